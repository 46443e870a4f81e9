/* BuildingWithWalls through the FMI 2.0 API (linked statically; also under the sanitizers in
 * build-asan): parameters out of range refused with their names, a scene that cannot be made
 * refused when initialization ends, a Co-Simulation run whose energy balance closes and whose
 * storeys above nStoreys stay at rest, an FMU state that replays a step bitwise, and the
 * Model-Exchange calls of one step. */
#include "check.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bw_variables.h"
#include "fmi2Functions.h"
#include "fmi2_test_logger.h"

static fmi2Component instance(fmi2Type type)
{
    fmi2Component c = fmi2Instantiate("bw", type, BW_GUID, "", &CB, fmi2False, fmi2False);
    if (c) fmi2SetupExperiment(c, fmi2True, 1e-8, 0.0, fmi2False, 0.0);
    return c;
}

static void refused_real(fmi2ValueReference vr, double v, const char *name)
{
    fmi2Component c = instance(fmi2ModelExchange);
    n_logs = 0;
    CHECK(fmi2SetReal(c, &vr, 1, &v) == fmi2Error, "%s = %g accepted", name, v);
    CHECK(n_logs > 0 && strstr(last_message, name) != NULL, "%s: log '%s'", name, last_message);
    fmi2FreeInstance(c);
}

static void refused_integer(fmi2ValueReference vr, int v, const char *name)
{
    fmi2Component c = instance(fmi2ModelExchange);
    n_logs = 0;
    CHECK(fmi2SetInteger(c, &vr, 1, &v) == fmi2Error, "%s = %d accepted", name, v);
    CHECK(n_logs > 0 && strstr(last_message, name) != NULL, "%s: log '%s'", name, last_message);
    fmi2FreeInstance(c);
}

static void accepted_integer(fmi2ValueReference vr, int v, const char *name)
{
    fmi2Component c = instance(fmi2ModelExchange);
    fmi2Integer got = -1;
    n_logs = 0;
    CHECK(fmi2SetInteger(c, &vr, 1, &v) == fmi2OK, "%s = %d refused: %s", name, v, n_logs ? last_message : "");
    CHECK(fmi2EnterInitializationMode(c) == fmi2OK && fmi2GetInteger(c, &vr, 1, &got) == fmi2OK && got == v,
          "%s: read back %d, set %d", name, (int)got, v);
    fmi2FreeInstance(c);
}

static void test_bad_parameters(void)
{
    fmi2Component c;
    fmi2ValueReference vr[2] = {BW_VR_b_1, BW_VR_h_1};
    double v[2] = {2.0, 1.5};
    refused_real(BW_VR_h_2, 0.1, "h_2");
    refused_real(BW_VR_tie_3, -1.0, "tie_3");
    refused_real(BW_VR_md_1, 0.0, "md_1");
    refused_real(BW_VR_zetad_4, 3.0, "zetad_4");
    refused_real(BW_VR_kd_5, -1.0, "kd_5");
    refused_real(BW_VR_z_diaph_2, 1.5, "storey 2");
    refused_real(BW_VR_g, 0.0, "g");
    refused_integer(BW_VR_nStoreys, 6, "nStoreys");
    refused_integer(BW_VR_hingeLaw_2, 7, "hingeLaw_2");
    refused_integer(BW_VR_hasWall_1, 2, "hasWall_1");
    refused_integer(BW_VR_diaphragmLaw, 4, "diaphragmLaw"); /* one past bilinear, the last law */
    refused_integer(BW_VR_storeyLaw, 4, "storeyLaw");
    refused_integer(BW_VR_storeyLaw, 2, "storeyLaw"); /* the pinching is the diaphragms' */
    accepted_integer(BW_VR_diaphragmLaw, 3, "diaphragmLaw");
    accepted_integer(BW_VR_storeyLaw, 3, "storeyLaw");
    /* a wall thicker than it is high: each value in range, the scene refused */
    c = instance(fmi2ModelExchange);
    CHECK(fmi2SetReal(c, vr, 2, v) == fmi2OK, "b_1, h_1 in range");
    fmi2EnterInitializationMode(c);
    n_logs = 0;
    CHECK(fmi2ExitInitializationMode(c) == fmi2Error, "b_1 > h_1 accepted");
    CHECK(strstr(last_message, "storey 1 wall") != NULL, "log '%s'", last_message);
    fmi2FreeInstance(c);
}

/* ag = A sin(w t), ramped over each step with its secant slope */
static double ground(double t) { return 2.0 * sin(6.0 * t) * (t < 1.5); }

static double run_steps(fmi2Component c, double t0, double t1, double H)
{
    fmi2ValueReference ag = BW_VR_ag;
    fmi2Integer order = 1;
    double t;
    for (t = t0; t < t1 - 1e-12; t += H) {
        double a = ground(t), slope = (ground(t + H) - a) / H;
        fmi2SetReal(c, &ag, 1, &a);
        fmi2SetRealInputDerivatives(c, &ag, 1, &order, &slope);
        if (fmi2DoStep(c, t, H, fmi2True) != fmi2OK) return NAN;
    }
    return get_real(c, BW_VR_s1_2);
}

static void test_cosimulation(void)
{
    fmi2Component c = instance(fmi2CoSimulation);
    fmi2FMUstate state = NULL;
    double s1_end, s1_again, work, residual;
    CHECK(c != NULL, "instantiate");
    if (!c) return;
    fmi2EnterInitializationMode(c);
    CHECK(fmi2ExitInitializationMode(c) == fmi2OK, "exit initialization (defaults): %s", last_message);
    run_steps(c, 0.0, 1.0, 5e-3);
    CHECK(fmi2GetFMUstate(c, &state) == fmi2OK, "get FMU state");
    s1_end = run_steps(c, 1.0, 2.0, 5e-3);
    CHECK(isfinite(s1_end) && fabs(get_real(c, BW_VR_s1_1)) > 0.0, "a finite run that moves the walls");
    CHECK(fmi2SetFMUstate(c, state) == fmi2OK, "set FMU state");
    s1_again = run_steps(c, 1.0, 2.0, 5e-3);
    CHECK(s1_again == s1_end, "the replayed step: s1_2 %.17g against %.17g", s1_again, s1_end);
    work = get_real(c, BW_VR_work_ground);
    residual = get_real(c, BW_VR_energy_residual);
    CHECK(fabs(work) > 0.0 && fabs(residual) < 1e-4 * fabs(work), "energy residual %g of work %g", residual, work);
    CHECK(get_real(c, BW_VR_s1_3) == 0.0 && get_real(c, BW_VR_u_diaph_4) == 0.0, "storeys above nStoreys at rest");
    fmi2FreeFMUstate(c, &state);
    fmi2Terminate(c);
    fmi2FreeInstance(c);
}

static void test_model_exchange_calls(void)
{
    fmi2Component c = instance(fmi2ModelExchange);
    double x[BW_NUMBER_OF_STATES], dx[BW_NUMBER_OF_STATES], z[BW_NUMBER_OF_EVENT_INDICATORS], a = 1.0;
    fmi2ValueReference ag = BW_VR_ag;
    fmi2EventInfo info;
    int k, finite = 1;
    fmi2EnterInitializationMode(c);
    fmi2SetReal(c, &ag, 1, &a);
    CHECK(fmi2ExitInitializationMode(c) == fmi2OK, "exit initialization");
    memset(&info, 0, sizeof info);
    fmi2NewDiscreteStates(c, &info);
    CHECK(fmi2EnterContinuousTimeMode(c) == fmi2OK, "continuous-time mode");
    CHECK(fmi2GetContinuousStates(c, x, BW_NUMBER_OF_STATES) == fmi2OK, "states");
    CHECK(fmi2GetDerivatives(c, dx, BW_NUMBER_OF_STATES) == fmi2OK, "derivatives");
    CHECK(fmi2GetEventIndicators(c, z, BW_NUMBER_OF_EVENT_INDICATORS) == fmi2OK, "event indicators");
    for (k = 0; k < BW_NUMBER_OF_STATES; k++) finite &= isfinite(dx[k]);
    CHECK(finite, "finite derivatives");
    /* the ground pushes the walls and the diaphragms: the rotations and the diaphragm of storey 1 accelerate */
    CHECK(dx[2 + 2] != 0.0 && dx[2 + 4 + 4] != 0.0, "dq1_1' = %g, v_diaph_1' = %g", dx[4], dx[10]);
    CHECK(z[8 * 2] == 1.0, "storey 3 (above nStoreys) has no indicators: %g", z[16]);
    fmi2FreeInstance(c);
}

int main(void)
{
    test_bad_parameters();
    test_cosimulation();
    test_model_exchange_calls();
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
