/* Loads a RockingWall FMU binary at run time (LoadLibrary on Windows, dlopen on Linux), the way an
 * importer does, and runs free rocking of the default wall from a tilt through it:
 *   me  Model Exchange, explicit Euler (step DT) with the state events handled at the step ends
 *   cs  Co-Simulation, the exact engine's steps of CS_STEP
 *   csfile  the same under a ground-motion record the FMU reads itself (agFile: a CSV the runner
 *       writes into the working directory, so the binary's own reader and C library read it)
 * and prints "peak_s1 peak_s2 impacts q1_end" on one line. The same source is built for Linux and
 * for Windows: tests/win64/compare_binaries.cmake runs both on the binaries of the packaged FMU
 * and compares what they print.
 * Usage: fmu_binary_runner <RockingWall.so | RockingWall.dll> me|cs|csfile
 *        fmu_binary_runner --compare A B REL_TOL   (exit 0 when |A - B| <= REL_TOL max(|A|, |B|)) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2FunctionTypes.h"
#include "model_variables.h"

#ifdef _WIN32
#include <windows.h>
typedef HMODULE library;
static library open_library(const char *path) { return LoadLibraryA(path); }
static void *symbol(library lib, const char *name) { return (void *)GetProcAddress(lib, name); }
static void close_library(library lib) { FreeLibrary(lib); }
#else
#include <dlfcn.h>
typedef void *library;
static library open_library(const char *path) { return dlopen(path, RTLD_NOW | RTLD_LOCAL); }
static void *symbol(library lib, const char *name) { return dlsym(lib, name); }
static void close_library(library lib) { dlclose(lib); }
#endif

#define T_END 2.0
#define DT 1e-4      /* explicit Euler */
#define CS_STEP 0.01 /* communication step */
#define NX RW_NUMBER_OF_STATES
#define NZ RW_NUMBER_OF_EVENT_INDICATORS

typedef struct {
    fmi2InstantiateTYPE *instantiate;
    fmi2FreeInstanceTYPE *free_instance;
    fmi2SetupExperimentTYPE *setup_experiment;
    fmi2EnterInitializationModeTYPE *enter_init;
    fmi2ExitInitializationModeTYPE *exit_init;
    fmi2SetRealTYPE *set_real;
    fmi2SetStringTYPE *set_string;
    fmi2GetRealTYPE *get_real;
    fmi2GetIntegerTYPE *get_integer;
    fmi2EnterEventModeTYPE *enter_event_mode;
    fmi2NewDiscreteStatesTYPE *new_discrete_states;
    fmi2EnterContinuousTimeModeTYPE *enter_continuous_time_mode;
    fmi2CompletedIntegratorStepTYPE *completed_integrator_step;
    fmi2SetTimeTYPE *set_time;
    fmi2SetContinuousStatesTYPE *set_states;
    fmi2GetContinuousStatesTYPE *get_states;
    fmi2GetDerivativesTYPE *get_derivatives;
    fmi2GetEventIndicatorsTYPE *get_event_indicators;
    fmi2DoStepTYPE *do_step;
} fmi2_api;

typedef struct {
    double peak_s1, peak_s2, q1_end;
    int impacts;
} run_result;

static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status, fmi2String category,
                   fmi2String message, ...)
{
    (void)env;
    if (status >= fmi2Error) fprintf(stderr, "%s [%s]: %s\n", name, category, message);
}

/* every function the runs need; 0 when one is missing */
static int load_api(library lib, fmi2_api *f)
{
#define LOAD(field, name) ok &= (*(void **)&f->field = symbol(lib, name)) != NULL
    int ok = 1;
    LOAD(instantiate, "fmi2Instantiate");
    LOAD(free_instance, "fmi2FreeInstance");
    LOAD(setup_experiment, "fmi2SetupExperiment");
    LOAD(enter_init, "fmi2EnterInitializationMode");
    LOAD(exit_init, "fmi2ExitInitializationMode");
    LOAD(set_real, "fmi2SetReal");
    LOAD(set_string, "fmi2SetString");
    LOAD(get_real, "fmi2GetReal");
    LOAD(get_integer, "fmi2GetInteger");
    LOAD(enter_event_mode, "fmi2EnterEventMode");
    LOAD(new_discrete_states, "fmi2NewDiscreteStates");
    LOAD(enter_continuous_time_mode, "fmi2EnterContinuousTimeMode");
    LOAD(completed_integrator_step, "fmi2CompletedIntegratorStep");
    LOAD(set_time, "fmi2SetTime");
    LOAD(set_states, "fmi2SetContinuousStates");
    LOAD(get_states, "fmi2GetContinuousStates");
    LOAD(get_derivatives, "fmi2GetDerivatives");
    LOAD(get_event_indicators, "fmi2GetEventIndicators");
    LOAD(do_step, "fmi2DoStep");
#undef LOAD
    return ok;
}

/* csfile's record: 1 s of a 2-Hz sine of 1 m/s2 at 0.005 s, as text the C library of each
 * platform writes (CRLF line ends on Windows) */
#define RECORD_FILE "runner_record.csv"
static int write_record(void)
{
    FILE *fp = fopen(RECORD_FILE, "w");
    int k;
    if (!fp) return 1;
    fprintf(fp, "time,ag\n");
    for (k = 0; k <= 200; k++) fprintf(fp, "%.17g,%.17g\n", k * 0.005, sin(2 * 3.14159265358979323846 * 2.0 * k * 0.005));
    return fclose(fp) != 0;
}

/* an initialized instance of the default wall tilted to q1 = 0.01, q2 = -0.01 rad (and the record
 * file as agFile, if one is given) */
static fmi2Component start(const fmi2_api *f, fmi2Type type, const fmi2CallbackFunctions *cb, const char *record)
{
    const fmi2ValueReference vr_q[2] = {RW_VR_q1, RW_VR_q2}, vr_file = RW_VR_agFile;
    const double q[2] = {0.01, -0.01};
    fmi2Component c = f->instantiate("runner", type, RW_GUID, "", cb, fmi2False, fmi2False);
    if (!c) return NULL;
    if ((record && f->set_string(c, &vr_file, 1, &record) != fmi2OK) || f->set_real(c, vr_q, 2, q) != fmi2OK || f->setup_experiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0) != fmi2OK ||
        f->enter_init(c) != fmi2OK || f->exit_init(c) != fmi2OK) {
        f->free_instance(c);
        return NULL;
    }
    return c;
}

static void track_peaks(const fmi2_api *f, fmi2Component c, run_result *r)
{
    const fmi2ValueReference vr_s[2] = {RW_VR_s1, RW_VR_s2};
    double s[2];
    f->get_real(c, vr_s, 2, s);
    r->peak_s1 = fmax(r->peak_s1, fabs(s[0]));
    r->peak_s2 = fmax(r->peak_s2, fabs(s[1]));
}

/* the event iteration of Model Exchange; 0 = go on, 1 = the model terminated, -1 = error */
static int event_iteration(const fmi2_api *f, fmi2Component c)
{
    fmi2EventInfo info;
    do {
        if (f->new_discrete_states(c, &info) != fmi2OK) return -1;
        if (info.terminateSimulation) return 1;
    } while (info.newDiscreteStatesNeeded);
    return f->enter_continuous_time_mode(c) == fmi2OK ? 0 : -1;
}

static int crossed(const double *z_before, const double *z_after)
{
    int i;
    for (i = 0; i < NZ; i++)
        if ((z_before[i] > 0) != (z_after[i] > 0)) return 1;
    return 0;
}

/* one explicit Euler step from t; 0 = go on, 1 = terminated, -1 = error */
static int euler_step(const fmi2_api *f, fmi2Component c, double t, double x[NX], double z[NZ])
{
    double dx[NX], z_new[NZ];
    fmi2Boolean enter_event = fmi2False, terminate = fmi2False;
    int i;
    if (f->get_derivatives(c, dx, NX) != fmi2OK) return -1;
    for (i = 0; i < NX; i++) x[i] += DT * dx[i];
    if (f->set_time(c, t + DT) != fmi2OK || f->set_states(c, x, NX) != fmi2OK ||
        f->get_event_indicators(c, z_new, NZ) != fmi2OK ||
        f->completed_integrator_step(c, fmi2True, &enter_event, &terminate) != fmi2OK)
        return -1;
    if (terminate) return 1;
    if (crossed(z, z_new) || enter_event) {
        int rc;
        if (f->enter_event_mode(c) != fmi2OK) return -1;
        rc = event_iteration(f, c);
        if (rc) return rc;
        if (f->get_states(c, x, NX) != fmi2OK || f->get_event_indicators(c, z_new, NZ) != fmi2OK) return -1;
    }
    memcpy(z, z_new, sizeof z_new);
    return 0;
}

static int run_me(const fmi2_api *f, fmi2Component c, run_result *r)
{
    double x[NX], z[NZ];
    const long n = (long)(T_END / DT + 0.5);
    long k;
    int rc = event_iteration(f, c);
    if (rc) return rc < 0 ? -1 : 0;
    if (f->get_states(c, x, NX) != fmi2OK || f->get_event_indicators(c, z, NZ) != fmi2OK) return -1;
    for (k = 0; k < n && rc == 0; k++) {
        rc = euler_step(f, c, k * DT, x, z);
        track_peaks(f, c, r);
    }
    return rc < 0 ? -1 : 0;
}

static int run_cs(const fmi2_api *f, fmi2Component c, run_result *r)
{
    const int n = (int)(T_END / CS_STEP + 0.5);
    int k;
    for (k = 0; k < n; k++) {
        if (f->do_step(c, k * CS_STEP, CS_STEP, fmi2True) != fmi2OK) return -1;
        track_peaks(f, c, r);
    }
    return 0;
}

/* for compare_binaries.cmake: CMake has no floating-point arithmetic */
static int compare(const char *a_text, const char *b_text, const char *tol_text)
{
    const double a = strtod(a_text, NULL), b = strtod(b_text, NULL), tol = strtod(tol_text, NULL);
    return isfinite(a) && isfinite(b) && fabs(a - b) <= tol * fmax(fabs(a), fabs(b)) ? 0 : 1;
}

int main(int argc, char **argv)
{
    const fmi2CallbackFunctions cb = {logger, calloc, free, NULL, NULL};
    const fmi2ValueReference vr_impacts = RW_VR_impacts, vr_q1 = RW_VR_q1;
    fmi2_api f;
    run_result r = {0.0, 0.0, 0.0, 0};
    fmi2Component c;
    library lib;
    int me, file, rc;
    if (argc == 5 && !strcmp(argv[1], "--compare")) return compare(argv[2], argv[3], argv[4]);
    if (argc != 3 || (strcmp(argv[2], "me") && strcmp(argv[2], "cs") && strcmp(argv[2], "csfile"))) {
        fprintf(stderr, "usage: %s <FMU binary> me|cs|csfile\n", argv[0]);
        return 2;
    }
    me = !strcmp(argv[2], "me");
    file = !strcmp(argv[2], "csfile");
    if (file && write_record()) {
        fprintf(stderr, "cannot write %s\n", RECORD_FILE);
        return 1;
    }
    lib = open_library(argv[1]);
    if (!lib) {
        fprintf(stderr, "cannot load %s\n", argv[1]);
        return 1;
    }
    if (!load_api(lib, &f) || !(c = start(&f, me ? fmi2ModelExchange : fmi2CoSimulation, &cb, file ? RECORD_FILE : NULL))) {
        fprintf(stderr, "%s: the fmi2 API is incomplete or the instance did not initialize\n", argv[1]);
        close_library(lib);
        return 1;
    }
    rc = me ? run_me(&f, c, &r) : run_cs(&f, c, &r);
    f.get_integer(c, &vr_impacts, 1, &r.impacts);
    f.get_real(c, &vr_q1, 1, &r.q1_end);
    f.free_instance(c);
    close_library(lib);
    if (rc) {
        fprintf(stderr, "the %s run failed\n", argv[2]);
        return 1;
    }
    printf("%.17g %.17g %d %.17g\n", r.peak_s1, r.peak_s2, r.impacts, r.q1_end);
    return 0;
}
