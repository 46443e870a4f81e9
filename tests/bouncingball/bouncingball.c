/* A bouncing ball, FMI 2.0 Model Exchange: the test FMU with an analytic answer for fmi2sim.
 *   h' = v, v' = -g; at h = 0 falling: v := -e v (a state event). Below v_rest it rests on the
 *   floor (no Zeno). At t_kick (>= 0) a time event adds `kick` to v.
 * Analytic bounce times: t1 = sqrt(2 h0/g), t_{k+1} = t_k + 2 e^k v1/g, v1 = sqrt(2 g h0). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"

#define GUID "{6f3d1f0e-2b1c-4c1a-9a55-b0c1d2e3f401}"
enum { VR_H, VR_DER_H, VR_V, VR_DER_V, VR_G, VR_E, VR_T_KICK, VR_KICK, VR_BOUNCES, NR };
#define V_REST 0.1 /* m/s: a hop of v^2/2g = 0.5 mm; smaller hops are below what the tolerances resolve */

typedef struct {
    double r[VR_KICK + 1];
    int bounces, resting, kicked;
    double time;
    const fmi2CallbackFunctions *cb;
    char name[64];
} ball;

static void logf_(ball *b, fmi2Status st, const char *msg)
{
    if (b->cb && b->cb->logger) b->cb->logger(b->cb->componentEnvironment, b->name, st, "logStatusError", "%s", msg);
}

static void derivatives(ball *b)
{
    b->r[VR_DER_H] = b->resting ? 0.0 : b->r[VR_V];
    b->r[VR_DER_V] = b->resting ? 0.0 : -b->r[VR_G];
}

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }
fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean on, size_t n, const fmi2String cat[])
{ (void)c; (void)on; (void)n; (void)cat; return fmi2OK; }

fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid, fmi2String res,
                              const fmi2CallbackFunctions *cb, fmi2Boolean vis, fmi2Boolean log)
{
    ball *b;
    (void)res; (void)vis; (void)log;
    if (!guid || strcmp(guid, GUID) != 0 || type != fmi2ModelExchange) {
        if (cb && cb->logger) cb->logger(cb->componentEnvironment, name, fmi2Error, "logStatusError",
                                         "wrong GUID '%s' (this binary is " GUID ") or not Model Exchange", guid ? guid : "");
        return NULL;
    }
    b = calloc(1, sizeof *b);
    if (!b) return NULL;
    b->cb = cb;
    snprintf(b->name, sizeof b->name, "%s", name ? name : "ball");
    b->r[VR_H] = 1.0; b->r[VR_G] = 9.81; b->r[VR_E] = 0.7; b->r[VR_T_KICK] = -1.0; b->r[VR_KICK] = 1.0;
    return b;
}

void fmi2FreeInstance(fmi2Component c) { free(c); }
fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean td, fmi2Real tol, fmi2Real t0, fmi2Boolean sd, fmi2Real t1)
{ (void)td; (void)tol; (void)sd; (void)t1; ((ball *)c)->time = t0; return fmi2OK; }
fmi2Status fmi2EnterInitializationMode(fmi2Component c) { (void)c; return fmi2OK; }
fmi2Status fmi2ExitInitializationMode(fmi2Component c) { derivatives(c); return fmi2OK; }
fmi2Status fmi2Terminate(fmi2Component c) { (void)c; return fmi2OK; }
fmi2Status fmi2Reset(fmi2Component c) { (void)c; return fmi2Error; }

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Real v[])
{
    ball *b = c;
    derivatives(b);
    for (size_t i = 0; i < n; i++) {
        if (vr[i] > VR_KICK) { logf_(b, fmi2Error, "fmi2GetReal: no such value reference"); return fmi2Error; }
        v[i] = b->r[vr[i]];
    }
    return fmi2OK;
}
fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Integer v[])
{
    for (size_t i = 0; i < n; i++) { if (vr[i] != VR_BOUNCES) return fmi2Error; v[i] = ((ball *)c)->bounces; }
    return fmi2OK;
}
fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Boolean v[])
{ (void)c; (void)vr; (void)v; return n ? fmi2Error : fmi2OK; }
fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2String v[])
{ (void)c; (void)vr; (void)v; return n ? fmi2Error : fmi2OK; }
fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Real v[])
{
    ball *b = c;
    for (size_t i = 0; i < n; i++) {
        if (vr[i] > VR_KICK || vr[i] == VR_DER_H || vr[i] == VR_DER_V || isnan(v[i])) {
            logf_(b, fmi2Error, "fmi2SetReal: not settable or NaN");
            return fmi2Error;
        }
        b->r[vr[i]] = v[i];
    }
    return fmi2OK;
}
fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer v[])
{ (void)c; (void)vr; (void)v; return n ? fmi2Error : fmi2OK; }
fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Boolean v[])
{ (void)c; (void)vr; (void)v; return n ? fmi2Error : fmi2OK; }
fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2String v[])
{ (void)c; (void)vr; (void)v; return n ? fmi2Error : fmi2OK; }

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *s) { (void)c; (void)s; return fmi2Error; }
fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate s) { (void)c; (void)s; return fmi2Error; }
fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *s) { (void)c; (void)s; return fmi2Error; }
fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate s, size_t *n) { (void)c; (void)s; (void)n; return fmi2Error; }
fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate s, fmi2Byte b[], size_t n) { (void)c; (void)s; (void)b; (void)n; return fmi2Error; }
fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte b[], size_t n, fmi2FMUstate *s) { (void)c; (void)b; (void)n; (void)s; return fmi2Error; }
fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference u[], size_t nu, const fmi2ValueReference z[],
                                        size_t nz, const fmi2Real dv[], fmi2Real df[])
{ (void)c; (void)u; (void)nu; (void)z; (void)nz; (void)dv; (void)df; return fmi2Error; }

fmi2Status fmi2EnterEventMode(fmi2Component c) { (void)c; return fmi2OK; }

/* The event map: bounce (state event) and kick (time event). */
fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo *info)
{
    ball *b = c;
    memset(info, 0, sizeof *info);
    if (b->r[VR_T_KICK] >= 0 && !b->kicked && b->time >= b->r[VR_T_KICK]) {
        b->kicked = 1;
        b->resting = 0;
        b->r[VR_V] += b->r[VR_KICK];
        info->valuesOfContinuousStatesChanged = fmi2True;
    }
    if (!b->resting && b->r[VR_H] <= 0.0 && b->r[VR_V] < 0.0) {
        b->bounces++;
        b->r[VR_H] = 0.0;
        b->r[VR_V] = -b->r[VR_E] * b->r[VR_V];
        if (b->r[VR_V] < V_REST) { b->r[VR_V] = 0.0; b->resting = 1; }
        info->valuesOfContinuousStatesChanged = fmi2True;
    }
    if (b->r[VR_T_KICK] >= 0 && !b->kicked) {
        info->nextEventTimeDefined = fmi2True;
        info->nextEventTime = b->r[VR_T_KICK];
    }
    derivatives(b);
    return fmi2OK;
}
fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c) { (void)c; return fmi2OK; }
fmi2Status fmi2CompletedIntegratorStep(fmi2Component c, fmi2Boolean ns, fmi2Boolean *ev, fmi2Boolean *term)
{ (void)c; (void)ns; *ev = fmi2False; *term = fmi2False; return fmi2OK; }
fmi2Status fmi2SetTime(fmi2Component c, fmi2Real t) { ((ball *)c)->time = t; return fmi2OK; }
fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[], size_t n)
{
    ball *b = c;
    if (n != 2) return fmi2Error;
    b->r[VR_H] = x[0];
    b->r[VR_V] = x[1];
    return fmi2OK;
}
fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real dx[], size_t n)
{
    ball *b = c;
    if (n != 2) return fmi2Error;
    derivatives(b);
    dx[0] = b->r[VR_DER_H];
    dx[1] = b->r[VR_DER_V];
    return fmi2OK;
}
fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real z[], size_t n)
{
    ball *b = c;
    if (n != 1) return fmi2Error;
    z[0] = b->resting ? 1.0 : b->r[VR_H];
    return fmi2OK;
}
fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t n)
{
    ball *b = c;
    if (n != 2) return fmi2Error;
    x[0] = b->r[VR_H];
    x[1] = b->r[VR_V];
    return fmi2OK;
}
fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real x[], size_t n)
{ (void)c; for (size_t i = 0; i < n; i++) x[i] = 1.0; return fmi2OK; }

/* Co-Simulation is not offered; the symbols exist so that importers can load the library. */
fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer o[], const fmi2Real v[])
{ (void)c; (void)vr; (void)n; (void)o; (void)v; return fmi2Error; }
fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer o[], fmi2Real v[])
{ (void)c; (void)vr; (void)n; (void)o; (void)v; return fmi2Error; }
fmi2Status fmi2DoStep(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean p) { (void)c; (void)t; (void)h; (void)p; return fmi2Error; }
fmi2Status fmi2CancelStep(fmi2Component c) { (void)c; return fmi2Error; }
fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind k, fmi2Status *v) { (void)c; (void)k; (void)v; return fmi2Error; }
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind k, fmi2Real *v) { (void)c; (void)k; (void)v; return fmi2Error; }
fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind k, fmi2Integer *v) { (void)c; (void)k; (void)v; return fmi2Error; }
fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind k, fmi2Boolean *v) { (void)c; (void)k; (void)v; return fmi2Error; }
fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind k, fmi2String *v) { (void)c; (void)k; (void)v; return fmi2Error; }
