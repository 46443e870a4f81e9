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

#endif
