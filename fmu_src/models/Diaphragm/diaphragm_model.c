/* Diaphragm: a floor or roof diaphragm as one degree of freedom per metre of wall, the far end of
 * RockingWall's top spring. In the frame of the ground (u relative to the ground):
 *
 *     m (u'' + ag) = F_top - c u' - k u,     c = 2 zeta sqrt(k m)
 *
 * where F_top is the force of the wall's spring on the diaphragm (RockingWall.F_top). Energy
 * bookkeeping: d/dt (m u'^2/2 + k u^2/2) = P_ground + P_wall - P_damping. No events.
 *
 * A Co-Simulation step is exact (exact_step): over a step the inputs are linear in time (held, or
 * ramped with the derivatives the master gave), and so is the forcing of this linear oscillator,
 * whose response is then known in closed form. No CVODE is needed (the Windows binary has none). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "diaphragm_variables.h"
#include "fmu_model.h"

typedef struct {
    double m, k, zeta;
    double ag, F_top;
    double x[2]; /* u, v */
} dg_data;

#define FMU_Real FMU_REAL
#define DG_VAR(ID, VR, NAME, TYPE, CAUS, VARIAB, INIT, START, UNIT, NOM, DER, DESC) \
    {VR, FMU_##TYPE, NAME, CAUS, INIT},
static const fmu_var VARS[] = {DG_VARIABLES(DG_VAR)};
#undef DG_VAR

static double damping(const dg_data *S) { return 2.0 * S->zeta * sqrt(S->k * S->m); }

static double acceleration(const dg_data *S)
{
    return (S->F_top - damping(S) * S->x[1] - S->k * S->x[0]) / S->m - S->ag;
}

/* The free response of y'' + 2 sigma y' + w2 y = 0 after a time t, from (y, y'), with
 * wd2 = w2 - sigma^2 >= 0 (the damping ratio is at most 1): e^(-sigma t) (p C + q S) with
 * p = y(0), q = y'(0) + sigma p, C = cos(wd t), S = sin(wd t) / wd (C = 1, S = t when critically
 * damped), and its derivative e^(-sigma t) ((q - sigma p) C - (sigma q + wd2 p) S). */
static void free_response(double sigma, double wd2, double t, double *y, double *dy)
{
    const double e = exp(-sigma * t), p = *y, q = *dy + sigma * p;
    double C = 1.0, S = t;
    if (wd2 > 0) {
        const double wd = sqrt(wd2);
        C = cos(wd * t);
        S = sin(wd * t) / wd;
    }
    *y = e * (p * C + q * S);
    *dy = e * ((q - sigma * p) * C - (sigma * q + wd2 * p) * S);
}

static double slope_of(unsigned vr, const unsigned *slope_vr, const double *slope, size_t n_in)
{
    size_t i;
    for (i = 0; i < n_in; i++)
        if (slope_vr[i] == vr) return slope[i];
    return 0.0;
}

/* u'' + 2 sigma u' + w2 u = g0 + g1 s over the step (s = time into it), g = F_top / m - ag: the
 * particular solution A + B s plus the free response of what is left. Always exact: returns 0. */
static int exact_step(void *M, double t, double h, const unsigned *slope_vr, const double *slope, size_t n_in,
                      const fmu_logger *log, double *t_reached, char *msg, size_t n)
{
    dg_data *S = (dg_data *)M;
    const double ag_slope = slope_of(DG_VR_ag, slope_vr, slope, n_in);
    const double F_slope = slope_of(DG_VR_F_top, slope_vr, slope, n_in);
    const double w2 = S->k / S->m, sigma = S->zeta * sqrt(w2);
    const double g0 = S->F_top / S->m - S->ag, g1 = F_slope / S->m - ag_slope;
    const double B = g1 / w2, A = (g0 - 2.0 * sigma * B) / w2;
    double y = S->x[0] - A, dy = S->x[1] - B;
    (void)log; (void)msg; (void)n;
    free_response(sigma, w2 * (1.0 - S->zeta * S->zeta), h, &y, &dy);
    S->x[0] = A + B * h + y;
    S->x[1] = B + dy;
    /* the inputs where the step ended, as the CVODE step leaves them */
    S->ag += ag_slope * h;
    S->F_top += F_slope * h;
    *t_reached = t + h;
    return 0;
}

static void reset(void *M)
{
    dg_data *S = (dg_data *)M;
    memset(S, 0, sizeof *S);
#define DG_START(ID, VR, NAME, TYPE, CAUS, VARIAB, INIT, START, UNIT, NOM, DER, DESC) \
    if (VR == DG_VR_m) S->m = START; \
    if (VR == DG_VR_k) S->k = START; \
    if (VR == DG_VR_zeta) S->zeta = START;
    DG_VARIABLES(DG_START)
#undef DG_START
}

static void get_real(void *M, int initializing, double time, const unsigned vr[], size_t n, double v[])
{
    const dg_data *S = (const dg_data *)M;
    const double u = S->x[0], vel = S->x[1];
    size_t i;
    (void)initializing;
    (void)time;
    for (i = 0; i < n; i++) {
        switch (vr[i]) {
        case DG_VR_m: v[i] = S->m; break;
        case DG_VR_k: v[i] = S->k; break;
        case DG_VR_zeta: v[i] = S->zeta; break;
        case DG_VR_ag: v[i] = S->ag; break;
        case DG_VR_F_top: v[i] = S->F_top; break;
        case DG_VR_u: v[i] = u; break;
        case DG_VR_v: v[i] = vel; break;
        case DG_VR_der_v: v[i] = acceleration(S); break;
        case DG_VR_energy: v[i] = 0.5 * S->m * vel * vel + 0.5 * S->k * u * u; break;
        case DG_VR_P_ground: v[i] = -S->m * S->ag * vel; break;
        case DG_VR_P_damping: v[i] = damping(S) * vel * vel; break;
        default: v[i] = S->F_top * vel; break; /* DG_VR_P_wall */
        }
    }
}

static int set_real(void *M, unsigned vr, double value, char *msg, size_t n)
{
    dg_data *S = (dg_data *)M;
    switch (vr) {
    case DG_VR_m:
    case DG_VR_k:
        if (!(value > 0)) {
            snprintf(msg, n, "%s = %g must be > 0", vr == DG_VR_m ? "m" : "k", value);
            return 1;
        }
        if (vr == DG_VR_m) S->m = value;
        else S->k = value;
        return 0;
    case DG_VR_zeta:
        if (!(value >= 0 && value <= 1)) {
            snprintf(msg, n, "zeta = %g must be in [0, 1]", value);
            return 1;
        }
        S->zeta = value;
        return 0;
    case DG_VR_ag: S->ag = value; return 0;
    case DG_VR_F_top: S->F_top = value; return 0;
    case DG_VR_u: S->x[0] = value; return 0;
    default: S->x[1] = value; return 0; /* DG_VR_v */
    }
}

static void get_states(void *M, int initializing, double x[])
{
    (void)initializing;
    memcpy(x, ((dg_data *)M)->x, sizeof(double) * 2);
}

static void set_states(void *M, const double x[]) { memcpy(((dg_data *)M)->x, x, sizeof(double) * 2); }

static void derivatives(void *M, double dx[])
{
    const dg_data *S = (const dg_data *)M;
    dx[0] = S->x[1];
    dx[1] = acceleration(S);
}

static void nominals(double x[])
{
    x[0] = 0.01; /* diaphragm drifts of the order of 1 cm */
    x[1] = 0.1;
}

/* no Integer or Boolean variables, no events, each parameter checked when set: the FMI layer's
 * defaults stand for the callbacks left out */
const fmu_model FMU_MODEL = {
    .identifier = DG_MODEL_IDENTIFIER,
    .guid = DG_GUID,
    .nx = DG_NUMBER_OF_STATES,
    .nz = DG_NUMBER_OF_EVENT_INDICATORS,
    .vars = VARS,
    .nvars = sizeof VARS / sizeof VARS[0],
    .data_size = sizeof(dg_data),
    .reset = reset,
    .get_real = get_real,
    .set_real = set_real,
    .get_states = get_states,
    .set_states = set_states,
    .derivatives = derivatives,
    .nominals = nominals,
    .exact_step = exact_step,
};
