/* Co-Simulation inside the FMU: one communication step of a model (fmu_model.h) integrated with
 * SUNDIALS CVODE (BDF, dense Newton), with its state events located by CVODE's root-finding and
 * its time events hit exactly. No FMI types: fmi2Functions.c's fmi2DoStep calls this. */
#ifndef CS_CVODE_H
#define CS_CVODE_H

#include <stddef.h>

#include "fmu_model.h"

typedef struct cs_solver cs_solver;

/* external names (prefixed under FMI2_FUNCTION_PREFIX, see fmu_symbol.h) */
#define cs_new FMU_SYMBOL(cs_new)
#define cs_free FMU_SYMBOL(cs_free)
#define cs_step FMU_SYMBOL(cs_step)
#define cs_state_size FMU_SYMBOL(cs_state_size)
#define cs_get_state FMU_SYMBOL(cs_get_state)
#define cs_set_state FMU_SYMBOL(cs_set_state)

/* A Real input over the step: value + slope * (t - t_start). slope is 0 unless the master gave a
 * first derivative (fmi2SetRealInputDerivatives); the value is the one set before the step. */
typedef struct {
    unsigned vr;
    double value, slope;
} cs_input;

/* After fmi2ExitInitializationMode: the event iteration at t_start, then CVODE set up from the
 * model's states. rtol <= 0 means 1e-6; absolute tolerances are rtol * nominal. NULL on failure
 * with msg filled. *terminated is set when the model ends the run already at t_start. */
cs_solver *cs_new(const fmu_model *model, void *M, double t_start, double rtol, const fmu_logger *log,
                  int *terminated, char *msg, size_t n);
void cs_free(cs_solver *s);

/* Integrate from t (the end of the previous step) to t + h with the inputs given.
 * Returns 0 when t + h was reached, 1 when the model asked to terminate at *t_reached (< t + h
 * or = t + h), -1 on failure (msg says why). */
int cs_step(cs_solver *s, double t, double h, const cs_input *in, size_t n_in, const fmu_logger *log,
            double *t_reached, char *msg, size_t n);

/* The integrator's part of an FMU state (fmi2GetFMUstate): what re-creates the integration
 * exactly, given the model's data of the same moment. CVODE's own history is not saved: the next
 * cs_step after cs_get_state or cs_set_state re-initialises CVODE from the model's states at the
 * saved time, so a step taken after a state was saved and the same step taken again after the
 * state was restored compute the same numbers, bit for bit. */
size_t cs_state_size(const cs_solver *s);
void cs_get_state(cs_solver *s, void *buf);
/* 0 = restored; else msg says why not and nothing changed */
int cs_set_state(cs_solver *s, const void *buf, size_t n, char *msg, size_t msg_n);

#endif
