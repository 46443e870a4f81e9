/* Building physics: the equations of docs/building.md in plain C99 (no FMI types). */
#include "building_physics.h"

#include <math.h>
#include <string.h>

static double sgn(double v) { return (v > 0.0) - (v < 0.0); }

int bd_law_allowed(int law, int storey)
{
    if (law < BD_ELASTIC || law > BD_LAST_LAW) return 0;
    return !(storey && law == BD_BOUC_WEN_PINCHED);
}

static const double *floor_states(const double x[BD_NX], int i) { return x + BD_STATES_PER_FLOOR * i; }

double bd_drift(const double x[BD_NX], int i)
{
    const double below = i > 0 ? floor_states(x, i - 1)[BD_U] : 0.0; /* floor 0 is the ground */
    return floor_states(x, i)[BD_U] - below;
}

double bd_diaphragm_deformation(const double x[BD_NX], int i)
{
    return floor_states(x, i)[BD_Y] - floor_states(x, i)[BD_U];
}

/* linear: k u; Bouc-Wen and bilinear: alpha k u + (1 - alpha) Fy z with the normalised z (|z| <= 1) */
static double spring_force(int law, const bd_spring *s, double u, double z)
{
    if (law == BD_ELASTIC) return s->k * u;
    return s->alpha * s->k * u + (1.0 - s->alpha) * s->Fy * z;
}

double bd_storey_force(const bd_params *p, const double x[BD_NX], int i)
{
    return spring_force(p->storey_law, &p->storey[i], bd_drift(x, i), floor_states(x, i)[BD_Z]);
}

double bd_diaphragm_force(const bd_params *p, const double x[BD_NX], int i)
{
    return spring_force(p->diaphragm_law, &p->diaph[i], bd_diaphragm_deformation(x, i), floor_states(x, i)[BD_ZD]);
}

/* Foliente's pinching function with constant parameters (zeta1, zeta2, q), z_u = 1:
 * h = 1 - zeta1 exp(-((z sgn(du) - q)/zeta2)^2): the spring softens where the hysteretic force
 * passes through the pinched region after a reversal, the slack of nailed timber joints. */
static double pinching(const bd_params *p, double z, double du)
{
    const double r = (z * sgn(du) - p->pinch_centre) / p->pinch_width;
    return 1.0 - p->pinch_size * exp(-r * r);
}

/* |z|^n: the loop's usual shapes (n = 1, 2) without pow, which costs a few % of a hysteretic run
 * (the same value: pow is exact for these) */
static double power_of(double a, double n)
{
    if (n == 1.0) return a;
    if (n == 2.0) return a * a;
    return pow(a, n);
}

/* The bilinear law, Bouc-Wen's limit n -> infinity with beta = gamma = 1/2: z follows u at the
 * elastic slope (du/Dy) until |z| reaches 1, then stays while the spring loads on (yield, the force
 * growing at alpha k alone) and leaves 1 at the elastic slope as soon as it unloads (kinematic
 * hardening: the elastic range 2 Fy (1 - alpha) wide, wherever the loop stands).
 * The test is |z| >= 1, not |z| == 1, and a yielding z keeps a rate of exactly 0 rather than being
 * pulled back: the step that reaches the limit carries z past 1 by the integrator's error (a
 * multistep method's history still holds the elastic rate; about 1e-6 at rtol 1e-9), and rounding
 * leaves z a hair past; with the elastic rate there z would drift on past 1 for as long as the
 * spring loads, and a pull-back rate would be a stiff term the law does not have. Held where it
 * landed, z is off by that error only, and it rejoins the loop on the next unloading. */
static double bilinear_rate(double z, double du, double dy)
{
    return bd_bilinear_branch(z, du) ? 0.0 : du / dy; /* yielding (at rest the rate is 0 anyway) */
}

double bd_hysteretic_rate(const bd_params *p, int law, const bd_spring *s, double z, double du)
{
    const double gamma = 1.0 - p->beta, dy = s->Fy / s->k;
    double rate;
    if (law == BD_ELASTIC) return 0.0;
    if (law == BD_BILINEAR) return bilinear_rate(z, du, dy);
    rate = du / dy * (1.0 - power_of(fabs(z), p->n_bw) * (p->beta * sgn(du * z) + gamma));
    return law == BD_BOUC_WEN_PINCHED ? pinching(p, z, du) * rate : rate;
}

/* Damping force on floor i and on diaphragm i: Rayleigh a0 M v + a1 K0 v (K0 the initial
 * (elastic) stiffness matrix, v the velocities relative to the ground) and the dashpots */
static void damping_forces(const bd_params *p, const double x[BD_NX], int i, double *on_floor, double *on_diaph)
{
    const double *f = floor_states(x, i);
    const double v_below = i > 0 ? floor_states(x, i - 1)[BD_V] : 0.0;
    const double dv_diaph = f[BD_W] - f[BD_V];
    double k0v = p->storey[i].k * (f[BD_V] - v_below) - p->diaph[i].k * dv_diaph;
    if (i + 1 < p->n_storeys) k0v -= p->storey[i + 1].k * (floor_states(x, i + 1)[BD_V] - f[BD_V]);
    double dashpots = p->cs[i] * (f[BD_V] - v_below) - p->cd[i] * dv_diaph;
    if (i + 1 < p->n_storeys) dashpots -= p->cs[i + 1] * (floor_states(x, i + 1)[BD_V] - f[BD_V]);
    *on_floor = p->a0 * p->m[i] * f[BD_V] + p->a1 * k0v + dashpots;
    *on_diaph = p->a0 * p->md[i] * f[BD_W] + (p->a1 * p->diaph[i].k + p->cd[i]) * dv_diaph;
}

double bd_diaphragm_acceleration(const bd_params *p, const bd_input *in, const double x[BD_NX], int i)
{
    double c_floor, c_diaph;
    if (i >= p->n_storeys) return 0.0;
    damping_forces(p, x, i, &c_floor, &c_diaph);
    return (-bd_diaphragm_force(p, x, i) + in->F_wall[i] + in->F_above[i] - c_diaph) / p->md[i];
}

/* the 8 state rates of floor i */
static void floor_derivatives(const bd_params *p, const bd_input *in, const double x[BD_NX], int i, double *d)
{
    const double *f = floor_states(x, i);
    const double v_below = i > 0 ? floor_states(x, i - 1)[BD_V] : 0.0;
    const double V = bd_storey_force(p, x, i), Fd = bd_diaphragm_force(p, x, i);
    const double V_above = i + 1 < p->n_storeys ? bd_storey_force(p, x, i + 1) : 0.0;
    const double drift_rate = f[BD_V] - v_below, deform_rate = f[BD_W] - f[BD_V];
    double c_floor, c_diaph;
    damping_forces(p, x, i, &c_floor, &c_diaph);
    d[BD_U] = f[BD_V];
    d[BD_V] = (-V + V_above + Fd - c_floor) / p->m[i] - in->ag;
    d[BD_Z] = bd_hysteretic_rate(p, p->storey_law, &p->storey[i], f[BD_Z], drift_rate);
    d[BD_Y] = f[BD_W];
    d[BD_W] = bd_diaphragm_acceleration(p, in, x, i) - in->ag;
    d[BD_ZD] = bd_hysteretic_rate(p, p->diaphragm_law, &p->diaph[i], f[BD_ZD], deform_rate);
    d[BD_WORK_S] = V * drift_rate;
    d[BD_WORK_D] = Fd * deform_rate;
}

void bd_derivatives(const bd_params *p, const bd_input *in, const double x[BD_NX], double dx[BD_NX])
{
    int i;
    memset(dx, 0, sizeof(double) * BD_NX); /* floors above n_storeys stay at rest */
    for (i = 0; i < p->n_storeys; i++) floor_derivatives(p, in, x, i, dx + BD_STATES_PER_FLOOR * i);
}
