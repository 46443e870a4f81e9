/* Co-Simulation without CVODE: what fmi2DoStep has when the FMU is rebuilt from the sources its
 * modelDescription.xml lists for Model Exchange (an importer's build links no SUNDIALS). The
 * project's CMake build links cs_cvode.c instead; this file keeps the source FMU buildable. */
#include <stdio.h>

#include "cs_cvode.h"

cs_solver *cs_new(const fmu_model *model, void *M, double t_start, double rtol, const fmu_logger *log,
                  int *terminated, char *msg, size_t n)
{
    (void)model; (void)M; (void)t_start; (void)rtol; (void)log;
    *terminated = 0;
    snprintf(msg, n, "Co-Simulation is not available: this binary was built from the Model Exchange "
                     "sources without SUNDIALS CVODE (use the binary built by the project's CMake)");
    return NULL;
}

void cs_free(cs_solver *s) { (void)s; }

int cs_step(cs_solver *s, double t, double h, const cs_input *in, size_t n_in, const fmu_logger *log,
            double *t_reached, char *msg, size_t n)
{
    (void)s; (void)h; (void)in; (void)n_in; (void)log;
    *t_reached = t;
    snprintf(msg, n, "Co-Simulation is not available in this binary");
    return -1;
}

size_t cs_state_size(const cs_solver *s) { (void)s; return 0; }

void cs_get_state(cs_solver *s, void *buf) { (void)s; (void)buf; }

int cs_set_state(cs_solver *s, const void *buf, size_t n, char *msg, size_t msg_n)
{
    (void)s; (void)buf; (void)n;
    snprintf(msg, msg_n, "Co-Simulation is not available in this binary");
    return -1;
}
