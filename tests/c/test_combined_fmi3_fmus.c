/* Both FMUs' sources under the FMI 3.0 layer compiled into one shared object, each with its own
 * FMI3_FUNCTION_PREFIX (RockingWall_, Diaphragm_), as importers combine source-code FMUs
 * (fmu_src/fmu_package.cmake: combined_fmi3_fmus). Each FMU is simulated in Co-Simulation through the
 * combined object and through its own FMI 3.0 binary; the outputs must agree bitwise (same
 * sources, same compiler flags). The combined object must not export the unprefixed fmi3 names.
 *
 *     test_combined_fmi3_fmus COMBINED.so RockingWall.so Diaphragm.so */
#include "check.h"
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi3Functions.h"
#include "diaphragm_variables.h"
#include "model_variables.h"

static char last_message[1024];

static void logger(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category, fmi3String message)
{
    (void)env; (void)status; (void)category;
    snprintf(last_message, sizeof last_message, "%s", message ? message : "(null)");
}

/* the functions one Co-Simulation run needs, looked up with a prefix */
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
    a->instantiate = (fmi3InstantiateCoSimulationTYPE *)symbol(lib, prefix, "fmi3InstantiateCoSimulation");
    a->set = (fmi3SetFloat64TYPE *)symbol(lib, prefix, "fmi3SetFloat64");
    a->get = (fmi3GetFloat64TYPE *)symbol(lib, prefix, "fmi3GetFloat64");
    a->enter_init = (fmi3EnterInitializationModeTYPE *)symbol(lib, prefix, "fmi3EnterInitializationMode");
    a->exit_init = (fmi3ExitInitializationModeTYPE *)symbol(lib, prefix, "fmi3ExitInitializationMode");
    a->do_step = (fmi3DoStepTYPE *)symbol(lib, prefix, "fmi3DoStep");
    a->terminate = (fmi3TerminateTYPE *)symbol(lib, prefix, "fmi3Terminate");
    a->free_instance = (fmi3FreeInstanceTYPE *)symbol(lib, prefix, "fmi3FreeInstance");
    return a->instantiate && a->set && a->get && a->enter_init && a->exit_init && a->do_step && a->terminate &&
           a->free_instance;
}

typedef struct {
    const char *prefix, *guid;
    fmi3ValueReference start_vr, input_vr, output_vrs[2];
    double start, input;
} fmu_case;

#define N_STEPS 200
#define STEP 0.005

/* N_STEPS steps from a displaced start under a constant input; the two outputs after each step */
static int simulate(const cs_api *a, const fmu_case *f, double out[N_STEPS][2])
{
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

static void compare(void *combined, const char *own_path, const fmu_case *f)
{
    static double via_combined[N_STEPS][2], via_own[N_STEPS][2];
    cs_api a, b;
    void *own = dlopen(own_path, RTLD_NOW | RTLD_LOCAL);
    CHECK(own != NULL, "dlopen %s: %s", own_path, dlerror());
    if (!own || !load(combined, f->prefix, &a) || !load(own, "", &b)) return;
    CHECK(simulate(&a, f, via_combined), "%s: run through the combined object failed: %s", f->prefix, last_message);
    CHECK(simulate(&b, f, via_own), "%s: run through its own binary failed: %s", f->prefix, last_message);
    CHECK(memcmp(via_combined, via_own, sizeof via_own) == 0, "%s: the combined object's outputs differ from the own binary's",
          f->prefix);
    CHECK(via_own[N_STEPS - 1][0] != f->start, "%s: the run did not move (%g)", f->prefix, via_own[N_STEPS - 1][0]);
    printf("  %s through the combined FMI 3.0 object: output %.9g after %g s, bitwise equal to its own binary\n",
           f->prefix, via_combined[N_STEPS - 1][0], N_STEPS * STEP);
    dlclose(own);
}

int main(int argc, char **argv)
{
    const fmu_case rw = {"RockingWall_", RW_GUID, RW_VR_q1, RW_VR_ag, {RW_VR_s1, RW_VR_energy}, 0.02, 0.3};
    const fmu_case dg = {"Diaphragm_", DG_GUID, DG_VR_u, DG_VR_F_top, {DG_VR_u, DG_VR_energy}, 0.01, 50.0};
    void *combined;
    if (argc != 4) {
        fprintf(stderr, "usage: %s COMBINED.so RockingWall.so Diaphragm.so\n", argv[0]);
        return 2;
    }
    combined = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    CHECK(combined != NULL, "dlopen %s: %s", argv[1], dlerror());
    if (!combined) return 1;
    CHECK(dlsym(combined, "fmi3InstantiateCoSimulation") == NULL,
          "the combined object exports the unprefixed fmi3InstantiateCoSimulation");
    compare(combined, argv[2], &rw);
    compare(combined, argv[3], &dg);
    dlclose(combined);
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
