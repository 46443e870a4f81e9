/* The FMUs' sources under the FMI 3.0 layer in one shared object, each with its own
 * FMI3_FUNCTION_PREFIX (RockingWall_, Diaphragm_), compared with their own FMI 3.0 binaries
 * (combined_fmus_check.h) through the FMI 3.0 adapter below.
 *
 *     test_combined_fmi3_fmus COMBINED.so RockingWall.so Diaphragm.so */
#include "combined_fmus_check.h"

#include "fmi3Functions.h"
#include "diaphragm_variables.h"
#include "model_variables.h"

static char last_message[1024];

static void logger(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category, fmi3String message)
{
    (void)env; (void)status; (void)category;
    snprintf(last_message, sizeof last_message, "%s", message ? message : "(null)");
}

/* the functions one Co-Simulation run needs */
typedef struct {
    fmi3InstantiateCoSimulationTYPE *instantiate;
    fmi3SetFloat64TYPE *set;
    fmi3GetFloat64TYPE *get;
    fmi3EnterInitializationModeTYPE *enter_init;
    fmi3ExitInitializationModeTYPE *exit_init;
    fmi3DoStepTYPE *do_step;
    fmi3TerminateTYPE *terminate;
    fmi3FreeInstanceTYPE *free_instance;
} cs_api;

static int load(void *lib, const char *prefix, void *api)
{
    cs_api *a = (cs_api *)api;
    a->instantiate = (fmi3InstantiateCoSimulationTYPE *)combined_symbol(lib, prefix, "fmi3InstantiateCoSimulation");
    a->set = (fmi3SetFloat64TYPE *)combined_symbol(lib, prefix, "fmi3SetFloat64");
    a->get = (fmi3GetFloat64TYPE *)combined_symbol(lib, prefix, "fmi3GetFloat64");
    a->enter_init = (fmi3EnterInitializationModeTYPE *)combined_symbol(lib, prefix, "fmi3EnterInitializationMode");
    a->exit_init = (fmi3ExitInitializationModeTYPE *)combined_symbol(lib, prefix, "fmi3ExitInitializationMode");
    a->do_step = (fmi3DoStepTYPE *)combined_symbol(lib, prefix, "fmi3DoStep");
    a->terminate = (fmi3TerminateTYPE *)combined_symbol(lib, prefix, "fmi3Terminate");
    a->free_instance = (fmi3FreeInstanceTYPE *)combined_symbol(lib, prefix, "fmi3FreeInstance");
    return a->instantiate && a->set && a->get && a->enter_init && a->exit_init && a->do_step && a->terminate &&
           a->free_instance;
}

static int simulate(const void *api, const fmu_case *f, double out[N_STEPS][2])
{
    const cs_api *a = (const cs_api *)api;
    fmi3Instance c = a->instantiate("combined", f->guid, NULL, false, false, false, false, NULL, 0, NULL, logger, NULL);
    fmi3Boolean event, terminate, early;
    double last;
    int k, ok = 1;
    if (!c) return 0;
    ok &= a->set(c, &f->start_vr, 1, &f->start, 1) == fmi3OK;
    ok &= a->enter_init(c, true, 1e-8, 0.0, false, 0.0) == fmi3OK && a->exit_init(c) == fmi3OK;
    ok &= a->set(c, &f->input_vr, 1, &f->input, 1) == fmi3OK;
    for (k = 0; ok && k < N_STEPS; k++) {
        ok &= a->do_step(c, k * STEP, STEP, true, &event, &terminate, &early, &last) == fmi3OK && !terminate;
        ok &= a->get(c, f->output_vrs, 2, out[k], 2) == fmi3OK;
    }
    a->terminate(c);
    a->free_instance(c);
    return ok;
}

static const char *message(void) { return last_message; }

int main(int argc, char **argv)
{
    static const combined_adapter FMI3 = {"FMI 3.0", "fmi3InstantiateCoSimulation", sizeof(cs_api), load, simulate,
                                          message};
    const fmu_case cases[] = {
        {"RockingWall_", RW_GUID, RW_VR_q1, RW_VR_ag, {RW_VR_s1, RW_VR_energy}, 0.02, 0.3},
        {"Diaphragm_", DG_GUID, DG_VR_u, DG_VR_F_top, {DG_VR_u, DG_VR_energy}, 0.01, 50.0},
    };
    return combined_main(&FMI3, cases, 2, argc, argv);
}
