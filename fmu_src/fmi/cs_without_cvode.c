/* Co-Simulation without CVODE: what fmi2DoStep has in a binary built without SUNDIALS, i.e. the
 * Windows binaries (there is no SUNDIALS for the cross compiler) and an importer's build from the
 * sources the modelDescription.xml lists for Model Exchange. The project's Linux build links
 * cs_cvode.c instead.
 *
 * A step the model takes exactly (fmu_model.exact_step: RockingWall's event-driven engine for
 * supports 2 and 3) never reaches this file's cs_step; any other step is refused with an error
 * that says why. cs_new runs the initial event iteration, as cs_cvode.c does, because the exact
 * step starts from its result (a wall that collapses at t_start). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_cvode.h"

#define CS_MAX_EVENT_ROUNDS 1000

struct cs_solver {
    int unused; /* nothing to keep between steps: the exact step keeps its state in the model */
};

/* The event iteration a Model-Exchange master runs after initialization: 0 = done (*terminated
 * set when the model ended the run), -1 = it did not converge (msg says so). */
static int initial_event_iteration(const fmu_model *model, void *M, double t_start, const fmu_logger *log,
                                   int *terminated, char *msg, size_t n)
{
    fmu_event_result r;
    int rounds = 0;
    if (!model->event_update) return 0;
    do {
        memset(&r, 0, sizeof r);
        model->event_update(M, t_start, log, &r);
        if (r.terminate) {
            *terminated = 1;
            return 0;
        }
        if (++rounds > CS_MAX_EVENT_ROUNDS) {
            snprintf(msg, n, "the event iteration at t = %.17g did not converge in %d rounds", t_start,
                     CS_MAX_EVENT_ROUNDS);
            return -1;
        }
    } while (r.more);
    return 0;
}

cs_solver *cs_new(const fmu_model *model, void *M, double t_start, double rtol, const fmu_logger *log,
                  int *terminated, char *msg, size_t n)
{
    cs_solver *s;
    (void)rtol; /* the exact step does not depend on a tolerance */
    *terminated = 0;
    if (initial_event_iteration(model, M, t_start, log, terminated, msg, n) != 0) return NULL;
    s = (cs_solver *)calloc(1, sizeof *s);
    if (!s) snprintf(msg, n, "out of memory setting up Co-Simulation");
    return s;
}

void cs_free(cs_solver *s) { free(s); }

/* Reached only when the model has no exact step for its parameters. msg may hold the model's
 * reason already (fmi2DoStep clears it before the exact step); it is kept in the message. */
int cs_step(cs_solver *s, double t, double h, const cs_input *in, size_t n_in, const fmu_logger *log,
            double *t_reached, char *msg, size_t n)
{
    char reason[512];
    (void)s; (void)h; (void)in; (void)n_in; (void)log;
    *t_reached = t;
    snprintf(reason, sizeof reason, "%s", msg && msg[0] ? msg : "the model has no exact step for these parameters");
    snprintf(msg, n, "Co-Simulation of these parameters is not available in this binary: %s; the general "
                     "solver (SUNDIALS CVODE) is not built in (a Windows binary, or one built from the FMU's "
                     "sources). Use Model Exchange instead",
             reason);
    return -1;
}

size_t cs_state_size(const cs_solver *s) { (void)s; return 0; }

void cs_get_state(cs_solver *s, void *buf) { (void)s; (void)buf; }

int cs_set_state(cs_solver *s, const void *buf, size_t n, char *msg, size_t msg_n)
{
    (void)s; (void)buf;
    if (n != 0) {
        snprintf(msg, msg_n, "the integrator part of the FMU state has %u bytes, expected 0", (unsigned)n);
        return -1;
    }
    return 0;
}
