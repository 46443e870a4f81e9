/* The RockingWall FMU's instance data, shared by rw_model.c (the model callbacks) and cs_exact.c
 * (its Co-Simulation step through the exact engine). */
#ifndef RW_MODEL_DATA_H
#define RW_MODEL_DATA_H

#include "fmu_model.h"
#include "rw_engine.h"
#include "rw_ground_motion.h"
#include "rw_physics.h"

/* time between the collapse event (where `collapsed` becomes true and is recorded) and the
 * time event that requests terminateSimulation */
#define RW_TERMINATE_DELAY 1e-6

/* A master that holds a changing ag over communication steps longer than this [s] gets a warning
 * (once): an accelerogram held over coarse steps loses its peaks. The DefaultExperiment's stepSize. */
#define RW_HELD_AG_STEP 0.005

/* the longest agFile this FMU takes, with its terminating zero */
#define RW_AG_FILE_MAX 1024

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
    /* The ground motion the FMU reads itself (agFile, agScale; rw_ground_motion.h), so that its
     * answer does not depend on how an importer holds the input: the input `ag` (ag_input) adds
     * to it, and in.ag is their sum at `time`. */
    char ag_file[RW_AG_FILE_MAX];
    double ag_scale;
    double ag_input;
    int initialized; /* exit_init read the record (if any): an FMU state must then fit it */
    /* Co-Simulation without agFile: ag where the last step left it, and whether the warning about
     * a changing ag held over long steps was given (cs_exact.c) */
    int stepped, held_ag_warned;
    double ag_step_end;
    rw_ground_motion *record; /* NULL without agFile; the instance's, not an FMU state's (rw_model.c) */
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
