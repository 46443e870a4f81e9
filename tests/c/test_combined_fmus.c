/* The FMUs' sources under the FMI 2.0 layer in one shared object, each with its own
 * FMI2_FUNCTION_PREFIX (RockingWall_, Diaphragm_, Building_), compared with their own binaries
 * (combined_fmus_check.h) through the FMI 2.0 adapter below.
 *
 *     test_combined_fmus COMBINED.so RockingWall.so Diaphragm.so Building.so */
#include "combined_fmus_check.h"

#include "fmi2Functions.h"
#include "fmi2_test_logger.h"
#include "building_variables.h"
#include "diaphragm_variables.h"
#include "model_variables.h"

/* the functions one Co-Simulation run needs */
typedef struct {
    fmi2InstantiateTYPE *instantiate;
    fmi2SetRealTYPE *set_real;
    fmi2GetRealTYPE *get_real;
    fmi2SetupExperimentTYPE *setup;
    fmi2EnterInitializationModeTYPE *enter_init;
    fmi2ExitInitializationModeTYPE *exit_init;
    fmi2DoStepTYPE *do_step;
    fmi2TerminateTYPE *terminate;
    fmi2FreeInstanceTYPE *free_instance;
} cs_api;

static int load(void *lib, const char *prefix, void *api)
{
    cs_api *a = (cs_api *)api;
    a->instantiate = (fmi2InstantiateTYPE *)combined_symbol(lib, prefix, "fmi2Instantiate");
    a->set_real = (fmi2SetRealTYPE *)combined_symbol(lib, prefix, "fmi2SetReal");
    a->get_real = (fmi2GetRealTYPE *)combined_symbol(lib, prefix, "fmi2GetReal");
    a->setup = (fmi2SetupExperimentTYPE *)combined_symbol(lib, prefix, "fmi2SetupExperiment");
    a->enter_init = (fmi2EnterInitializationModeTYPE *)combined_symbol(lib, prefix, "fmi2EnterInitializationMode");
    a->exit_init = (fmi2ExitInitializationModeTYPE *)combined_symbol(lib, prefix, "fmi2ExitInitializationMode");
    a->do_step = (fmi2DoStepTYPE *)combined_symbol(lib, prefix, "fmi2DoStep");
    a->terminate = (fmi2TerminateTYPE *)combined_symbol(lib, prefix, "fmi2Terminate");
    a->free_instance = (fmi2FreeInstanceTYPE *)combined_symbol(lib, prefix, "fmi2FreeInstance");
    return a->instantiate && a->set_real && a->get_real && a->setup && a->enter_init && a->exit_init && a->do_step &&
           a->terminate && a->free_instance;
}

static int simulate(const void *api, const fmu_case *f, double out[N_STEPS][2])
{
    const cs_api *a = (const cs_api *)api;
    fmi2Component c = a->instantiate("combined", fmi2CoSimulation, f->guid, "", &CB, fmi2False, fmi2False);
    int k, ok = 1;
    if (!c) return 0;
    ok &= a->set_real(c, &f->start_vr, 1, &f->start) == fmi2OK;
    ok &= a->setup(c, fmi2True, 1e-8, 0.0, fmi2False, 0.0) == fmi2OK;
    ok &= a->enter_init(c) == fmi2OK && a->exit_init(c) == fmi2OK;
    ok &= a->set_real(c, &f->input_vr, 1, &f->input) == fmi2OK;
    for (k = 0; ok && k < N_STEPS; k++) {
        ok &= a->do_step(c, k * STEP, STEP, fmi2True) == fmi2OK;
        ok &= a->get_real(c, f->output_vrs, 2, out[k]) == fmi2OK;
    }
    a->terminate(c);
    a->free_instance(c);
    return ok;
}

static const char *message(void) { return last_log; }

int main(int argc, char **argv)
{
    static const combined_adapter FMI2 = {"FMI 2.0", "fmi2Instantiate", sizeof(cs_api), load, simulate, message};
    const fmu_case cases[] = {
        {"RockingWall_", RW_GUID, RW_VR_q1, RW_VR_ag, {RW_VR_s1, RW_VR_energy}, 0.02, 0.3},
        {"Diaphragm_", DG_GUID, DG_VR_u, DG_VR_F_top, {DG_VR_u, DG_VR_energy}, 0.01, 50.0},
        {"Building_", BD_GUID, BD_VR_u_diaph_2, BD_VR_F_wall_1, {BD_VR_u_diaph_2, BD_VR_work_storey_1}, 0.01, 5e3},
    };
    return combined_main(&FMI2, cases, 3, argc, argv);
}
