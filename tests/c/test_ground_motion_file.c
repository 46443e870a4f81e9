/* RockingWall reads its ground motion itself (agFile, agScale), through both FMI layers:
 *  - the acceleration it applies is the file's, linear between samples, times agScale (AT2: times
 *    g), 0 after the record: a wall held by rigid hinges has F_base = -W/g * ag(t), hand-computed;
 *  - Co-Simulation with agFile over coarse steps agrees with the input route given the record's
 *    exact slopes step by step from sample to sample;
 *  - a bad or missing file is fmi2Error / fmi3Error naming the file, the line and the problem;
 *  - an FMU state with the record: a step repeated after restoring it is bitwise the same, and an
 *    instance that read another record refuses it;
 *  - FMI 2.0 and FMI 3.0 give the same results. */
#include "check.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"
#include "fmi3Functions.h"
#include "model_variables.h"

static char last_error[2048];

static void logger2(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status, fmi2String category,
                    fmi2String message, ...)
{
    (void)env; (void)name; (void)category;
    if (status >= fmi2Error) snprintf(last_error, sizeof last_error, "%s", message ? message : "(null)");
}

static void logger3(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category, fmi3String message)
{
    (void)env; (void)category;
    if (status >= fmi3Error) snprintf(last_error, sizeof last_error, "%s", message ? message : "(null)");
}

static const fmi2CallbackFunctions CB = {logger2, calloc, free, NULL, NULL};

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (!f) { printf("cannot write %s\n", path); exit(2); }
    fputs(text, f);
    fclose(f);
}

/* a record that makes the default 2DOF wall rock: 2 s of a 1.5-Hz sine of 1.5 m/s2, sampled at 0.01 s */
#define PULSE_N 201
#define PULSE_DT 0.01
static double pulse(size_t k) { return 1.5 * sin(2 * 3.14159265358979323846 * 1.5 * k * PULSE_DT); }

static void write_pulse_csv(const char *path)
{
    FILE *f = fopen(path, "w");
    size_t k;
    if (!f) { printf("cannot write %s\n", path); exit(2); }
    fprintf(f, "# a test pulse\ntime,ag\n");
    for (k = 0; k < PULSE_N; k++) fprintf(f, "%.17g, %.17g\n", k * PULSE_DT, pulse(k));
    fclose(f);
}

/* ---- FMI 2.0 helpers ----------------------------------------------------------------------- */

static fmi2Component init2(int co_simulation, const char *file, double scale, int rigid, fmi2Status *exit_status)
{
    fmi2Component c = fmi2Instantiate("gm", co_simulation ? fmi2CoSimulation : fmi2ModelExchange, RW_GUID, "", &CB,
                                      fmi2False, fmi2False);
    const fmi2ValueReference vr_file = RW_VR_agFile, vr_scale = RW_VR_agScale, vr_law = RW_VR_hingeLaw;
    const fmi2Integer rigid_law = 1;
    fmi2Status st;
    if (file) fmi2SetString(c, &vr_file, 1, &file);
    fmi2SetReal(c, &vr_scale, 1, &scale);
    if (rigid) fmi2SetInteger(c, &vr_law, 1, &rigid_law);
    fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0);
    fmi2EnterInitializationMode(c);
    st = fmi2ExitInitializationMode(c);
    if (exit_status) *exit_status = st;
    return c;
}

static double real2(fmi2Component c, fmi2ValueReference vr)
{
    double v = NAN;
    fmi2GetReal(c, &vr, 1, &v);
    return v;
}

static const fmi2ValueReference RESULTS[] = {RW_VR_s1, RW_VR_s2, RW_VR_F_base, RW_VR_energy, RW_VR_dissipated,
                                             RW_VR_q1, RW_VR_q2, RW_VR_dq1, RW_VR_dq2};
#define N_RESULTS (sizeof RESULTS / sizeof RESULTS[0])

/* ---- the acceleration applied: F_base of a wall at rest ------------------------------------ */

static void applied_acceleration(void)
{
    /* W = 6622 N/m, g = 9.81 (defaults), psi = 0: F_base = -W/g * ag at rest */
    const double W_over_g = 6622.0 / 9.81;
    const double t_csv[] = {0.05, 0.2, 0.3, 0.35}, t_at2[] = {0.05, 0.15, 0.225, 0.35};
    /* CSV: 0 -> 0.5 m/s2 at 0.1 s -> -0.2 m/s2 at 0.3 s, agScale 0.5; 0 from the last sample on */
    const double csv_expected[] = {0.5 * 0.25, 0.5 * (0.5 - 0.7 / 2), 0.0, 0.0};
    /* AT2 with DT 0.1: 0, 0.02 g, 0.01 g, -0.01 g; agScale 2, g = 9.81 */
    const double at2_expected[] = {2 * 0.01 * 9.81, 2 * 0.015 * 9.81, 2 * 0.005 * 9.81, 0.0};
    size_t k;
    fmi2Component c;
    write_file("gm_rest.csv", "time;ag\n0 0\n0.1, 0.5\n0.3, -0.2\n");
    write_file("gm_rest.AT2", "PEER header\nsome record\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=    4, DT=   .1000 SEC\n"
                              "  0.0  0.02  0.01\n -0.01\n");
    c = init2(0, "gm_rest.csv", 0.5, 1, NULL);
    for (k = 0; k < 4; k++) {
        double ag;
        fmi2SetTime(c, t_csv[k]);
        ag = -real2(c, RW_VR_F_base) / W_over_g;
        CHECK(fabs(ag - csv_expected[k]) < 1e-12, "CSV: ag(%g) = %.17g, expected %.17g", t_csv[k], ag, csv_expected[k]);
    }
    CHECK(fabs(real2(c, RW_VR_s1)) == 0.0, "the rigid wall stays at rest");
    fmi2FreeInstance(c);
    c = init2(0, "gm_rest.AT2", 2.0, 1, NULL);
    for (k = 0; k < 4; k++) {
        double ag;
        fmi2SetTime(c, t_at2[k]);
        ag = -real2(c, RW_VR_F_base) / W_over_g;
        CHECK(fabs(ag - at2_expected[k]) < 1e-12, "AT2: ag(%g) = %.17g, expected %.17g", t_at2[k], ag, at2_expected[k]);
    }
    fmi2FreeInstance(c);
}

/* ---- coarse steps with the file = the input route with exact slopes sample by sample -------- */

static void file_agrees_with_exact_input(void)
{
    fmi2Component a, b;
    const fmi2ValueReference vr_ag = RW_VR_ag;
    const fmi2Integer order = 1;
    double ra[N_RESULTS], rb[N_RESULTS];
    size_t k, i;
    write_pulse_csv("gm_pulse.csv");
    a = init2(1, "gm_pulse.csv", 1.0, 0, NULL);
    b = init2(1, NULL, 1.0, 0, NULL);
    for (i = 0; i < 5; i++) fmi2DoStep(a, 0.5 * i, 0.5, fmi2True); /* 2.5 s in 5 steps */
    for (k = 0; k + 1 < PULSE_N; k++) {
        const double v = pulse(k), slope = (pulse(k + 1) - pulse(k)) / PULSE_DT;
        fmi2SetReal(b, &vr_ag, 1, &v);
        fmi2SetRealInputDerivatives(b, &vr_ag, 1, &order, &slope);
        fmi2DoStep(b, k * PULSE_DT, PULSE_DT, fmi2True);
    }
    {
        const double zero = 0.0;
        fmi2SetReal(b, &vr_ag, 1, &zero);
        fmi2DoStep(b, 2.0, 0.5, fmi2True);
    }
    fmi2GetReal(a, RESULTS, N_RESULTS, ra);
    fmi2GetReal(b, RESULTS, N_RESULTS, rb);
    CHECK(fabs(ra[0]) > 1e-4, "the pulse makes the wall rock (s1 = %g)", ra[0]);
    for (i = 0; i < N_RESULTS; i++)
        CHECK(fabs(ra[i] - rb[i]) <= 1e-9 * (1 + fabs(rb[i])), "result %u: agFile %.17g, input route %.17g",
              (unsigned)RESULTS[i], ra[i], rb[i]);
    fmi2FreeInstance(a);
    fmi2FreeInstance(b);
}

/* ---- bad and missing files ----------------------------------------------------------------- */

static void bad_file(const char *name, const char *text, const char *expect1, const char *expect2)
{
    fmi2Status st;
    fmi2Component c;
    fmi3Instance c3;
    const fmi3ValueReference vr = RW_VR_agFile;
    if (text) write_file(name, text);
    last_error[0] = '\0';
    c = init2(1, name, 1.0, 0, &st);
    CHECK(st == fmi2Error, "%s: fmi2ExitInitializationMode gave %d, expected fmi2Error", name, (int)st);
    CHECK(strstr(last_error, expect1) && strstr(last_error, expect2), "%s: message '%s' lacks '%s' or '%s'", name,
          last_error, expect1, expect2);
    fmi2FreeInstance(c);
    last_error[0] = '\0';
    c3 = fmi3InstantiateCoSimulation("gm3", RW_GUID, NULL, false, false, false, false, NULL, 0, NULL, logger3, NULL);
    fmi3SetString(c3, &vr, 1, &name, 1);
    fmi3EnterInitializationMode(c3, false, 0, 0, false, 0);
    CHECK(fmi3ExitInitializationMode(c3) == fmi3Error, "%s: fmi3ExitInitializationMode is not fmi3Error", name);
    CHECK(strstr(last_error, expect1) && strstr(last_error, expect2), "%s (FMI 3.0): message '%s' lacks '%s' or '%s'",
          name, last_error, expect1, expect2);
    fmi3FreeInstance(c3);
}

static void bad_files(void)
{
    remove("gm_missing.csv");
    bad_file("gm_missing.csv", NULL, "gm_missing.csv", "cannot open");
    bad_file("gm_word.csv", "time,ag\n0,0\n0.1,abc\n", "gm_word.csv:3:", "'abc' is not a number");
    bad_file("gm_back.csv", "0,0\n0.1,1\n0.05,2\n", "gm_back.csv:3:", "is not after the previous one");
    bad_file("gm_cols.csv", "0,0\n0.1,1,3\n", "gm_cols.csv:2:", "expected 2 columns");
    bad_file("gm_short.AT2", "a\nb\nUNITS OF G\nNPTS= 5, DT= 0.01 SEC\n0.1 0.2 0.3\n", "gm_short.AT2:5:",
             "3 values, the header says NPTS = 5");
    bad_file("gm_header.AT2", "a\nb\nUNITS OF G\nnothing here\n0.1\n", "gm_header.AT2:4:", "NPTS");
}

/* ---- FMU state with the record -------------------------------------------------------------- */

static void state_with_record(void)
{
    fmi2Component c = init2(1, "gm_pulse.csv", 1.0, 0, NULL), other;
    fmi2FMUstate s = NULL, s2 = NULL;
    double first[N_RESULTS], again[N_RESULTS];
    size_t i, size = 0;
    char *bytes;
    fmi2DoStep(c, 0.0, 0.6, fmi2True);
    CHECK(fmi2GetFMUstate(c, &s) == fmi2OK, "fmi2GetFMUstate");
    fmi2DoStep(c, 0.6, 0.45, fmi2True);
    fmi2GetReal(c, RESULTS, N_RESULTS, first);
    CHECK(fmi2SetFMUstate(c, s) == fmi2OK, "fmi2SetFMUstate: %s", last_error);
    fmi2DoStep(c, 0.6, 0.45, fmi2True);
    fmi2GetReal(c, RESULTS, N_RESULTS, again);
    CHECK(fabs(first[0]) > 1e-5, "the wall moves in the repeated step (s1 = %g)", first[0]);
    for (i = 0; i < N_RESULTS; i++)
        CHECK(memcmp(&first[i], &again[i], sizeof(double)) == 0, "result %u after restoring: %.17g, then %.17g",
              (unsigned)RESULTS[i], first[i], again[i]);
    /* the serialized state into an instance that read no record: refused, with the reason */
    fmi2SerializedFMUstateSize(c, s, &size);
    bytes = (char *)malloc(size);
    fmi2SerializeFMUstate(c, s, bytes, size);
    other = init2(1, NULL, 1.0, 0, NULL);
    fmi2DeSerializeFMUstate(other, bytes, size, &s2);
    last_error[0] = '\0';
    CHECK(fmi2SetFMUstate(other, s2) == fmi2Error, "a state with another record is refused");
    CHECK(strstr(last_error, "agFile") && strstr(last_error, "gm_pulse.csv"), "the reason names the record: '%s'",
          last_error);
    fmi2FreeFMUstate(other, &s2);
    fmi2FreeInstance(other);
    free(bytes);
    fmi2FreeFMUstate(c, &s);
    fmi2FreeInstance(c);
}

/* ---- FMI 3.0 gives what FMI 2.0 gives ------------------------------------------------------- */

static void fmi3_agrees(void)
{
    fmi2Component c2 = init2(1, "gm_pulse.csv", 0.8, 0, NULL);
    fmi3Instance c3 = fmi3InstantiateCoSimulation("gm3", RW_GUID, NULL, false, false, false, false, NULL, 0, NULL,
                                                  logger3, NULL);
    const fmi3ValueReference vr_file = RW_VR_agFile, vr_scale = RW_VR_agScale;
    const char *file = "gm_pulse.csv", *back = NULL;
    const double scale = 0.8;
    double r2[N_RESULTS], r3[N_RESULTS], t = 0, last;
    bool event, terminate, early;
    size_t i;
    CHECK(fmi3SetString(c3, &vr_file, 1, &file, 1) == fmi3OK, "fmi3SetString");
    fmi3SetFloat64(c3, &vr_scale, 1, &scale, 1);
    fmi3EnterInitializationMode(c3, false, 0, 0, false, 0);
    CHECK(fmi3ExitInitializationMode(c3) == fmi3OK, "fmi3ExitInitializationMode: %s", last_error);
    CHECK(fmi3GetString(c3, &vr_file, 1, &back, 1) == fmi3OK && back && !strcmp(back, file), "fmi3GetString");
    for (i = 0; i < 3; i++, t += 0.7) {
        fmi2DoStep(c2, t, 0.7, fmi2True);
        fmi3DoStep(c3, t, 0.7, true, &event, &terminate, &early, &last);
    }
    fmi2GetReal(c2, RESULTS, N_RESULTS, r2);
    fmi3GetFloat64(c3, RESULTS, N_RESULTS, r3, N_RESULTS);
    CHECK(fabs(r2[0]) > 1e-5, "the wall moves (s1 = %g)", r2[0]);
    for (i = 0; i < N_RESULTS; i++)
        CHECK(memcmp(&r2[i], &r3[i], sizeof(double)) == 0, "result %u: FMI 2.0 %.17g, FMI 3.0 %.17g", (unsigned)RESULTS[i],
              r2[i], r3[i]);
    {
        const char *s2 = NULL;
        const fmi2ValueReference vr = RW_VR_agFile;
        CHECK(fmi2GetString(c2, &vr, 1, &s2) == fmi2OK && s2 && !strcmp(s2, file), "fmi2GetString");
    }
    fmi2FreeInstance(c2);
    fmi3FreeInstance(c3);
}

int main(void)
{
    applied_acceleration();
    file_agrees_with_exact_input();
    bad_files();
    state_with_record();
    fmi3_agrees();
    printf("%d checks, %d failures\n", checks, failures);
    return failures != 0;
}
