/* The RockingWall FMU's instance data, shared by rw_model.c (the model callbacks) and cs_exact.c
 * (its Co-Simulation step through the exact engine). */
#ifndef RW_MODEL_DATA_H
#define RW_MODEL_DATA_H

#include "fmu_model.h"
#include "rw_engine.h"
#include "rw_physics.h"

/* time between the collapse event (where `collapsed` becomes true and is recorded) and the
 * time event that requests terminateSimulation */
#define RW_TERMINATE_DELAY 1e-6

typedef struct {
    rw_params P;
    rw_derived D;
    rw_regime regime;
    rw_input in;
    double x[RW_NX];
    int impacts;
    int collapsed;
    double terminate_time;
    double dissipated;
    /* for messages from the physics: the logger and the time of the current event */
    const fmu_logger *log;
    double time;
    /* Co-Simulation through the exact engine (cs_exact.c): set up at the first step */
    int engine_state; /* 0 not yet decided, 1 in use, -1 not available (CVODE) */
    /* The engine itself (rw_engine.h: opaque, rw_engine_size() bytes) follows these fields in the
     * same allocation (fmu_model.data_tail_size), so the FMU state, a byte copy of the data, holds
     * it as it is: restoring a state restores the engine's caches, tracked indicator states and
     * peaks, and the steps after it repeat bit for bit. */
    double engine_space[];
} rw_data;

static inline rw_engine *rw_engine_of(rw_data *S)
{
    return (rw_engine *)S->engine_space;
}

/* fmu_model.exact_step of RockingWall (cs_exact.c) */
int rw_exact_step(void *M, double t, double h, const unsigned *slope_vr, const double *slope, size_t n_in,
                  const fmu_logger *log, double *t_reached, char *msg, size_t n);

#endif
