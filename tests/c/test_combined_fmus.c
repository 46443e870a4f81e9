/* The FMUs' sources compiled into one shared object, each with its own
 * FMI2_FUNCTION_PREFIX (RockingWall_, Diaphragm_, Building_), as importers combine source-code FMUs. Each FMU
 * is simulated in Co-Simulation through the combined object and through its own binary; the
 * outputs must agree bitwise (same sources, same compiler flags). The combined object must not
 * export the unprefixed fmi2 names.
 *
 *     test_combined_fmus COMBINED.so RockingWall.so Diaphragm.so Building.so */
#include "check.h"
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"
#include "fmi2_test_logger.h"
#include "building_variables.h"
#include "diaphragm_variables.h"
#include "model_variables.h"

/* the functions one Co-Simulation run needs, looked up with a prefix */
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

static void *symbol(void *lib, const char *prefix, const char *name)
{
    char full[128];
    void *p;
    snprintf(full, sizeof full, "%s%s", prefix, name);
    p = dlsym(lib, full);
    CHECK(p != NULL, "%s not exported", full);
    return p;
}

static int load(void *lib, const char *prefix, cs_api *a)
{
    a->instantiate = (fmi2InstantiateTYPE *)symbol(lib, prefix, "fmi2Instantiate");
    a->set_real = (fmi2SetRealTYPE *)symbol(lib, prefix, "fmi2SetReal");
    a->get_real = (fmi2GetRealTYPE *)symbol(lib, prefix, "fmi2GetReal");
    a->setup = (fmi2SetupExperimentTYPE *)symbol(lib, prefix, "fmi2SetupExperiment");
    a->enter_init = (fmi2EnterInitializationModeTYPE *)symbol(lib, prefix, "fmi2EnterInitializationMode");
    a->exit_init = (fmi2ExitInitializationModeTYPE *)symbol(lib, prefix, "fmi2ExitInitializationMode");
    a->do_step = (fmi2DoStepTYPE *)symbol(lib, prefix, "fmi2DoStep");
    a->terminate = (fmi2TerminateTYPE *)symbol(lib, prefix, "fmi2Terminate");
    a->free_instance = (fmi2FreeInstanceTYPE *)symbol(lib, prefix, "fmi2FreeInstance");
    return a->instantiate && a->set_real && a->get_real && a->setup && a->enter_init && a->exit_init && a->do_step &&
           a->terminate && a->free_instance;
}

typedef struct {
    const char *prefix, *guid;
    fmi2ValueReference start_vr, input_vr, output_vrs[2];
    double start, input;
} fmu_case;

#define N_STEPS 200
#define STEP 0.005

/* N_STEPS steps from a displaced start under a constant input; the two outputs after each step */
static int simulate(const cs_api *a, const fmu_case *f, double out[N_STEPS][2])
{
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

static void compare(void *combined, const char *own_path, const fmu_case *f)
{
    static double via_combined[N_STEPS][2], via_own[N_STEPS][2];
    cs_api a, b;
    void *own = dlopen(own_path, RTLD_NOW | RTLD_LOCAL);
    CHECK(own != NULL, "dlopen %s: %s", own_path, dlerror());
    if (!own || !load(combined, f->prefix, &a) || !load(own, "", &b)) return;
    CHECK(simulate(&a, f, via_combined), "%s: run through the combined object failed: %s", f->prefix, last_log);
    CHECK(simulate(&b, f, via_own), "%s: run through its own binary failed: %s", f->prefix, last_log);
    CHECK(memcmp(via_combined, via_own, sizeof via_own) == 0, "%s: the combined object's outputs differ from the own binary's",
          f->prefix);
    CHECK(via_own[N_STEPS - 1][0] != f->start, "%s: the run did not move (%g)", f->prefix, via_own[N_STEPS - 1][0]);
    printf("  %s through the combined object: output %.9g after %g s, bitwise equal to its own binary\n", f->prefix,
           via_combined[N_STEPS - 1][0], N_STEPS * STEP);
    dlclose(own);
}

int main(int argc, char **argv)
{
    const fmu_case rw = {"RockingWall_", RW_GUID, RW_VR_q1, RW_VR_ag, {RW_VR_s1, RW_VR_energy}, 0.02, 0.3};
    const fmu_case dg = {"Diaphragm_", DG_GUID, DG_VR_u, DG_VR_F_top, {DG_VR_u, DG_VR_energy}, 0.01, 50.0};
    const fmu_case bd = {"Building_", BD_GUID, BD_VR_u_diaph_2, BD_VR_F_wall_1, {BD_VR_u_diaph_2, BD_VR_work_storey_1},
                         0.01, 5e3};
    void *combined;
    if (argc != 5) {
        fprintf(stderr, "usage: %s COMBINED.so RockingWall.so Diaphragm.so Building.so\n", argv[0]);
        return 2;
    }
    combined = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    CHECK(combined != NULL, "dlopen %s: %s", argv[1], dlerror());
    if (!combined) return 1;
    CHECK(dlsym(combined, "fmi2Instantiate") == NULL, "the combined object exports the unprefixed fmi2Instantiate");
    compare(combined, argv[2], &rw);
    compare(combined, argv[3], &dg);
    compare(combined, argv[4], &bd);
    dlclose(combined);
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
