/* StepInputs, FMI 2.0 Model Exchange: fmi2sim's test FMU for inputs of every kind.
 *   x' = gain u           u: a continuous Real input, gain: a tunable parameter
 *   z' = d + k + b        d: a discrete Real input, k: an Integer input, b: a Boolean input (0/1)
 * It keeps FMI 2.0's rules on when an input may be set (section 3.2.3): u in Initialization,
 * Event and Continuous-Time Mode; d, k, b and gain only in Initialization and Event Mode. Any
 * other call is refused with fmi2Error and a message, as checking FMUs (the Reference FMUs) do.
 * With inputs given as tables, x and z have closed forms the tests compute independently.
 * Outputs: x, z, the discrete inputs as the model last saw them, and the number of times Event
 * Mode was entered. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"

#define GUID "{3b9e7c2a-51d4-4f0e-8a6b-2c7d9e1f0a35}"
enum { VR_U, VR_D, VR_K, VR_B, VR_GAIN, VR_X, VR_DER_X, VR_Z, VR_DER_Z, VR_D_SEEN, VR_K_SEEN, VR_B_SEEN, VR_EVENTS };
typedef enum { INSTANTIATED, INITIALIZATION, EVENT, CONTINUOUS } mode;

typedef struct {
    double u, d, gain, x, z, time;
    int k, b, events;
    mode m;
    const fmi2CallbackFunctions *cb;
    char name[64];
} model;

static fmi2Status refuse(model *M, const char *fmt, ...)
{
    char msg[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (M->cb && M->cb->logger) M->cb->logger(M->cb->componentEnvironment, M->name, fmi2Error, "logStatusError", "%s", msg);
    return fmi2Error;
}

/* Discrete inputs and tunable parameters: Initialization or Event Mode only (and before, as start values). */
static int discrete_settable(const model *M) { return M->m != CONTINUOUS; }

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }
fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean on, size_t n, const fmi2String cat[])
{ (void)c; (void)on; (void)n; (void)cat; return fmi2OK; }

fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid, fmi2String res,
                              const fmi2CallbackFunctions *cb, fmi2Boolean vis, fmi2Boolean log)
{
    model *M;
    (void)res; (void)vis; (void)log;
    if (!guid || strcmp(guid, GUID) != 0 || type != fmi2ModelExchange) return NULL;
    M = calloc(1, sizeof *M);
    if (!M) return NULL;
    M->cb = cb;
    M->gain = 1.0;
    snprintf(M->name, sizeof M->name, "%s", name ? name : "StepInputs");
    return M;
}

void fmi2FreeInstance(fmi2Component c) { free(c); }
fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean td, fmi2Real tol, fmi2Real t0, fmi2Boolean sd, fmi2Real t1)
{ (void)td; (void)tol; (void)sd; (void)t1; ((model *)c)->time = t0; return fmi2OK; }
fmi2Status fmi2EnterInitializationMode(fmi2Component c) { ((model *)c)->m = INITIALIZATION; return fmi2OK; }
fmi2Status fmi2ExitInitializationMode(fmi2Component c) { ((model *)c)->m = EVENT; return fmi2OK; }
fmi2Status fmi2EnterEventMode(fmi2Component c) { ((model *)c)->m = EVENT; ((model *)c)->events++; return fmi2OK; }
fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c) { ((model *)c)->m = CONTINUOUS; return fmi2OK; }
fmi2Status fmi2Terminate(fmi2Component c) { (void)c; return fmi2OK; }
fmi2Status fmi2Reset(fmi2Component c) { (void)c; return fmi2Error; }

fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo *info)
{
    (void)c;
    memset(info, 0, sizeof *info);
    return fmi2OK;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Real v[])
{
    model *M = c;
    for (size_t i = 0; i < n; i++)
        switch (vr[i]) {
        case VR_U: v[i] = M->u; break;
        case VR_D: case VR_D_SEEN: v[i] = M->d; break;
        case VR_GAIN: v[i] = M->gain; break;
        case VR_X: v[i] = M->x; break;
        case VR_DER_X: v[i] = M->gain * M->u; break;
        case VR_Z: v[i] = M->z; break;
        case VR_DER_Z: v[i] = M->d + M->k + M->b; break;
        default: return refuse(M, "fmi2GetReal: %u is not a Real", vr[i]);
        }
    return fmi2OK;
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Integer v[])
{
    model *M = c;
    for (size_t i = 0; i < n; i++)
        switch (vr[i]) {
        case VR_K: case VR_K_SEEN: v[i] = M->k; break;
        case VR_EVENTS: v[i] = M->events; break;
        default: return refuse(M, "fmi2GetInteger: %u is not an Integer", vr[i]);
        }
    return fmi2OK;
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Boolean v[])
{
    model *M = c;
    for (size_t i = 0; i < n; i++) {
        if (vr[i] != VR_B && vr[i] != VR_B_SEEN) return refuse(M, "fmi2GetBoolean: %u is not a Boolean", vr[i]);
        v[i] = M->b ? fmi2True : fmi2False;
    }
    return fmi2OK;
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2String v[])
{ (void)vr; (void)v; return n ? refuse(c, "fmi2GetString: no String variables") : fmi2OK; }

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Real v[])
{
    model *M = c;
    for (size_t i = 0; i < n; i++) {
        if (isnan(v[i])) return refuse(M, "fmi2SetReal: NaN");
        if (vr[i] == VR_U) M->u = v[i];
        else if ((vr[i] == VR_D || vr[i] == VR_GAIN) && !discrete_settable(M))
            return refuse(M, "fmi2SetReal: %s may be set only in Initialization or Event Mode, not in Continuous-Time "
                             "Mode", vr[i] == VR_D ? "the discrete input d" : "the tunable parameter gain");
        else if (vr[i] == VR_D) M->d = v[i];
        else if (vr[i] == VR_GAIN) M->gain = v[i];
        else return refuse(M, "fmi2SetReal: %u cannot be set", vr[i]);
    }
    return fmi2OK;
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer v[])
{
    model *M = c;
    for (size_t i = 0; i < n; i++) {
        if (vr[i] != VR_K) return refuse(M, "fmi2SetInteger: %u cannot be set", vr[i]);
        if (!discrete_settable(M)) return refuse(M, "fmi2SetInteger: the input k may be set only in Initialization or "
                                                    "Event Mode, not in Continuous-Time Mode");
        M->k = v[i];
    }
    return fmi2OK;
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Boolean v[])
{
    model *M = c;
    for (size_t i = 0; i < n; i++) {
        if (vr[i] != VR_B) return refuse(M, "fmi2SetBoolean: %u cannot be set", vr[i]);
        if (!discrete_settable(M)) return refuse(M, "fmi2SetBoolean: the input b may be set only in Initialization or "
                                                    "Event Mode, not in Continuous-Time Mode");
        M->b = v[i] ? 1 : 0;
    }
    return fmi2OK;
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2String v[])
{ (void)vr; (void)v; return n ? refuse(c, "fmi2SetString: no String variables") : fmi2OK; }

fmi2Status fmi2SetTime(fmi2Component c, fmi2Real t) { ((model *)c)->time = t; return fmi2OK; }

fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[], size_t n)
{
    model *M = c;
    if (n != 2) return refuse(M, "fmi2SetContinuousStates: 2 states, not %zu", n);
    M->x = x[0];
    M->z = x[1];
    return fmi2OK;
}

fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t n)
{
    model *M = c;
    if (n != 2) return refuse(M, "fmi2GetContinuousStates: 2 states, not %zu", n);
    x[0] = M->x;
    x[1] = M->z;
    return fmi2OK;
}

fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real dx[], size_t n)
{
    model *M = c;
    if (n != 2) return refuse(M, "fmi2GetDerivatives: 2 states, not %zu", n);
    dx[0] = M->gain * M->u;
    dx[1] = M->d + M->k + M->b;
    return fmi2OK;
}

fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real z[], size_t n)
{ (void)z; return n ? refuse(c, "fmi2GetEventIndicators: no event indicators") : fmi2OK; }
fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real x[], size_t n)
{ (void)c; for (size_t i = 0; i < n; i++) x[i] = 1.0; return fmi2OK; }
fmi2Status fmi2CompletedIntegratorStep(fmi2Component c, fmi2Boolean ns, fmi2Boolean *ev, fmi2Boolean *term)
{ (void)c; (void)ns; *ev = fmi2False; *term = fmi2False; return fmi2OK; }

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *s) { (void)c; (void)s; return fmi2Error; }
fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate s) { (void)c; (void)s; return fmi2Error; }
fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *s) { (void)c; (void)s; return fmi2Error; }
fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate s, size_t *n) { (void)c; (void)s; (void)n; return fmi2Error; }
fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate s, fmi2Byte b[], size_t n)
{ (void)c; (void)s; (void)b; (void)n; return fmi2Error; }
fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte b[], size_t n, fmi2FMUstate *s)
{ (void)c; (void)b; (void)n; (void)s; return fmi2Error; }
fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference u[], size_t nu, const fmi2ValueReference z[],
                                        size_t nz, const fmi2Real dv[], fmi2Real df[])
{ (void)c; (void)u; (void)nu; (void)z; (void)nz; (void)dv; (void)df; return fmi2Error; }

/* Co-Simulation is not offered; the symbols exist so that importers can load the library. */
fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer o[],
                                       const fmi2Real v[])
{ (void)c; (void)vr; (void)n; (void)o; (void)v; return fmi2Error; }
fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer o[],
                                        fmi2Real v[])
{ (void)c; (void)vr; (void)n; (void)o; (void)v; return fmi2Error; }
fmi2Status fmi2DoStep(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean p) { (void)c; (void)t; (void)h; (void)p; return fmi2Error; }
fmi2Status fmi2CancelStep(fmi2Component c) { (void)c; return fmi2Error; }
fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind k, fmi2Status *v) { (void)c; (void)k; (void)v; return fmi2Error; }
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind k, fmi2Real *v) { (void)c; (void)k; (void)v; return fmi2Error; }
fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind k, fmi2Integer *v) { (void)c; (void)k; (void)v; return fmi2Error; }
fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind k, fmi2Boolean *v) { (void)c; (void)k; (void)v; return fmi2Error; }
fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind k, fmi2String *v) { (void)c; (void)k; (void)v; return fmi2Error; }
