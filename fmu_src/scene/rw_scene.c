/* A scene of walls, diaphragms and floors as one model: rw_scene.h. */
#include "rw_scene.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* A standing wall's acceleration and base force, affine in its base's acceleration a_b:
 * dx = dx0 + beta a_b (beta nonzero in the rates only), F_base = phi + chi a_b. */
typedef struct {
    double dx0[RW_NX], beta[RW_NX];
    double phi, chi, F_top, u_top;
} wall_lin;

static int standing(const rw_scene *sc, int i) { return sc->S.has_wall[i] && !sc->collapsed[i]; }

/* the building's states copied into (and out of) the full-size block building_physics works on */
static void building_states(const rw_scene *sc, const double x[], double xb[BD_NX])
{
    memset(xb, 0, sizeof(double) * BD_NX);
    memcpy(xb, RW_SCENE_BUILDING(sc, x), sizeof(double) * BD_STATES_PER_FLOOR * sc->S.n_storeys);
}

static double diaphragm_displacement(const double xb[BD_NX], int i)
{
    return i < 0 ? 0.0 : xb[BD_STATES_PER_FLOOR * i + BD_Y];
}

static double diaphragm_velocity(const double xb[BD_NX], int i)
{
    return i < 0 ? 0.0 : xb[BD_STATES_PER_FLOOR * i + BD_W];
}

/* u_top of wall i: its diaphragm's displacement relative to the wall's base (diaphragm i - 1) */
static double wall_u_top(const double xb[BD_NX], int i)
{
    return diaphragm_displacement(xb, i) - diaphragm_displacement(xb, i - 1);
}

/* the inputs of wall i as its own model sees them, at the base acceleration a_base (0 for what
 * reads its top alone: the top spring's force, its energy) */
static rw_input wall_input(const double xb[BD_NX], int i, double a_base)
{
    rw_input in;
    in.ag = a_base;
    in.u_top = wall_u_top(xb, i);
    return in;
}

/* The wall's model evaluated at base accelerations 0 and 1: it is affine in a_b (rw_derivatives
 * and rw_F_base), whatever its regime, so two evaluations give the whole dependence. */
static void wall_linearised(const rw_scene *sc, int i, const double x[], const double xb[BD_NX], wall_lin *w)
{
    const rw_params *p = &sc->S.wall[i];
    const rw_derived *d = &sc->D[i];
    const rw_regime *m = &sc->regime[i];
    const double *xi = RW_SCENE_WALL(x, i);
    double dx1[RW_NX];
    const rw_input in0 = wall_input(xb, i, 0.0);
    rw_input in1 = in0;
    int k;
    in1.ag = 1.0;
    w->u_top = in0.u_top;
    rw_derivatives(p, d, m, &in0, xi, w->dx0);
    rw_derivatives(p, d, m, &in1, xi, dx1);
    for (k = 0; k < RW_NX; k++) w->beta[k] = dx1[k] - w->dx0[k];
    w->phi = rw_F_base(p, d, m, &in0, xi, w->dx0);
    w->chi = rw_F_base(p, d, m, &in1, xi, dx1) - w->phi;
    w->F_top = rw_F_top(p, &in0, xi);
}

int rw_scene_validate(const rw_scene_spec *spec, char *msg, size_t n)
{
    int i;
    if (spec->n_storeys < 1 || spec->n_storeys > RW_SCENE_MAX_STOREYS) {
        snprintf(msg, n, "a scene has 1 to %d storeys, not %d", RW_SCENE_MAX_STOREYS, spec->n_storeys);
        return 1;
    }
    if (!bd_law_allowed(spec->building.diaphragm_law, 0)) {
        snprintf(msg, n, "diaphragm law %d is not one of %s", spec->building.diaphragm_law, BD_DIAPHRAGM_LAWS_TEXT);
        return 1;
    }
    if (!bd_law_allowed(spec->building.storey_law, 1)) {
        snprintf(msg, n, "storey law %d is not one of %s", spec->building.storey_law, BD_STOREY_LAWS_TEXT);
        return 1;
    }
    for (i = 0; i < spec->n_storeys; i++) {
        const bd_params *b = &spec->building;
        char why[384];
        if (!(b->md[i] > 0.0 && isfinite(b->md[i]))) {
            snprintf(msg, n, "storey %d: the diaphragm's mass must be > 0 (got %g kg/m); a massless diaphragm is the "
                     "paper's scene with the tie and the diaphragm as springs in series", i + 1, b->md[i]);
            return 1;
        }
        if (!(b->diaph[i].k >= 0.0 && isfinite(b->diaph[i].k) && b->cd[i] >= 0.0 && isfinite(b->cd[i]))) {
            snprintf(msg, n, "storey %d: the diaphragm's stiffness and damping must be finite and >= 0", i + 1);
            return 1;
        }
        if (!spec->rigid_in_plane && !(b->m[i] > 0.0 && b->storey[i].k > 0.0 && isfinite(b->m[i] + b->storey[i].k))) {
            snprintf(msg, n, "storey %d: flexible in-plane walls need a floor mass and a storey stiffness > 0", i + 1);
            return 1;
        }
        if (!spec->has_wall[i]) continue;
        if (spec->wall[i].support != RW_FLEXIBLE_TOP) {
            snprintf(msg, n, "storey %d: a wall in a scene is tied to its diaphragm (support 3, flexibleTop)", i + 1);
            return 1;
        }
        if (rw_params_validate(&spec->wall[i], why, sizeof why)) {
            snprintf(msg, n, "storey %d wall: %s", i + 1, why);
            return 1;
        }
    }
    return 0;
}

void rw_scene_start_state(const rw_scene_spec *spec, const double *x0, double x[RW_SCENE_NX])
{
    int i;
    memset(x, 0, sizeof(double) * RW_SCENE_NX);
    if (!x0) return;
    memcpy(x, x0, sizeof(double) * (size_t)((RW_NX + BD_STATES_PER_FLOOR) * spec->n_storeys));
    if (!spec->rigid_in_plane) return;
    for (i = 0; i < spec->n_storeys; i++) {
        double *f = x + RW_NX * spec->n_storeys + BD_STATES_PER_FLOOR * i;
        f[BD_U] = f[BD_V] = 0.0;
    }
}

void rw_scene_init(rw_scene *sc, const rw_scene_spec *spec, double ag0, double x[RW_SCENE_NX])
{
    int i;
    double xb[BD_NX];
    memset(sc, 0, sizeof *sc);
    sc->S = *spec;
    sc->S.building.n_storeys = spec->n_storeys;
    sc->nx = (RW_NX + BD_STATES_PER_FLOOR) * spec->n_storeys;
    building_states(sc, x, xb);
    for (i = 0; i < spec->n_storeys; i++) {
        rw_input in;
        sc->regime[i].side_b = sc->regime[i].side_m = 1;
        sc->t_collapse[i] = NAN;
        if (!spec->has_wall[i]) {
            memset(RW_SCENE_WALL(x, i), 0, sizeof(double) * RW_NX);
            continue;
        }
        rw_derive(&sc->S.wall[i], &sc->D[i]);
        /* the initial regime: from the start states, or the start accelerations on the ground's */
        in = wall_input(xb, i, ag0);
        rw_init_regime(&sc->S.wall[i], &sc->D[i], &in, RW_SCENE_WALL(x, i), &sc->regime[i], NULL, NULL);
    }
}

/* The building's rates with the walls' forces, and each wall's base acceleration */
static void building_rates(const rw_scene *sc, double ag, const double xb[BD_NX], const wall_lin *w,
                           double db[BD_NX], rw_scene_aux *aux)
{
    const bd_params *b = &sc->S.building;
    const int N = sc->S.n_storeys;
    bd_input in;
    int i;
    memset(&in, 0, sizeof in);
    in.ag = ag;
    for (i = 0; i < N; i++) {
        if (standing(sc, i)) in.F_wall[i] = w[i].F_top;
        if (i + 1 < N && standing(sc, i + 1)) in.F_above[i] = w[i + 1].phi;
    }
    bd_derivatives(b, &in, xb, db);
    for (i = 0; i < N; i++) {
        double *f = db + BD_STATES_PER_FLOOR * i;
        /* the wall above as added mass on its diaphragm (rw_scene.h) */
        const double chi = (i + 1 < N && standing(sc, i + 1)) ? w[i + 1].chi : 0.0;
        const double a = b->md[i] * (f[BD_W] + ag) / (b->md[i] - chi);
        f[BD_W] = a - ag;
        aux->a_diaph[i] = a;
        aux->F_top[i] = standing(sc, i) ? w[i].F_top : 0.0;
        if (sc->S.rigid_in_plane) f[BD_U] = f[BD_V] = f[BD_Z] = f[BD_WORK_S] = 0.0;
    }
    for (i = 0; i < N; i++) aux->a_base[i] = i == 0 ? ag : aux->a_diaph[i - 1];
}

void rw_scene_derivatives(const rw_scene *sc, double ag, const double x[], double dx[], rw_scene_aux *aux)
{
    const int N = sc->S.n_storeys;
    wall_lin w[RW_SCENE_MAX_STOREYS];
    double xb[BD_NX], db[BD_NX];
    rw_scene_aux local;
    int i, k;
    if (!aux) aux = &local;
    memset(aux, 0, sizeof *aux);
    building_states(sc, x, xb);
    for (i = 0; i < N; i++)
        if (standing(sc, i)) wall_linearised(sc, i, x, xb, &w[i]);
    building_rates(sc, ag, xb, w, db, aux);
    memcpy(RW_SCENE_BUILDING(sc, dx), db, sizeof(double) * BD_STATES_PER_FLOOR * N);
    for (i = 0; i < N; i++) {
        double *di = RW_SCENE_WALL(dx, i);
        if (!standing(sc, i)) {
            memset(di, 0, sizeof(double) * RW_NX); /* no wall, or one that has left the scene */
            continue;
        }
        for (k = 0; k < RW_NX; k++) di[k] = w[i].dx0[k] + w[i].beta[k] * aux->a_base[i];
        aux->F_base[i] = w[i].phi + w[i].chi * aux->a_base[i];
    }
}

void rw_scene_indicators(const rw_scene *sc, double ag, const double x[], double z[])
{
    double dx[RW_SCENE_NX], xb[BD_NX];
    rw_scene_aux aux;
    int i, k;
    rw_scene_derivatives(sc, ag, x, dx, &aux);
    building_states(sc, x, xb);
    for (i = 0; i < sc->S.n_storeys; i++) {
        double *zi = z + RW_NZ * i;
        rw_input in;
        if (!standing(sc, i)) {
            for (k = 0; k < RW_NZ; k++) zi[k] = 1.0;
            continue;
        }
        in = wall_input(xb, i, aux.a_base[i]);
        rw_event_indicators(&sc->S.wall[i], &sc->D[i], &sc->regime[i], &in, RW_SCENE_WALL(x, i), zi);
        /* as in both exact engines: under a law of q alone the mid-height hinge's switch changes
         * nothing in the motion (rw_mid_switch_is_bookkeeping), so no solver need stop there; the
         * event update brings its side up to date at the next event */
        if (rw_mid_switch_is_bookkeeping(&sc->S.wall[i])) zi[RW_Z_MID] = 1.0;
    }
}

int rw_scene_event_update(rw_scene *sc, double t, double ag, double x[], double dx[])
{
    double own_dx[RW_SCENE_NX], xb[BD_NX];
    rw_scene_aux aux;
    int i, flags = 0;
    rw_scene_derivatives(sc, ag, x, dx ? dx : own_dx, &aux);
    building_states(sc, x, xb);
    for (i = 0; i < sc->S.n_storeys; i++) {
        const rw_params *p = &sc->S.wall[i];
        double *xi = RW_SCENE_WALL(x, i);
        rw_event_result r;
        rw_input in;
        if (!standing(sc, i)) continue;
        in = wall_input(xb, i, aux.a_base[i]);
        rw_event_update(p, &sc->D[i], &sc->regime[i], &in, xi, &r, NULL, NULL);
        sc->impacts[i] += r.impacts;
        if (r.states_changed) flags |= 1;
        if (r.regime_changed) flags |= 2;
        sc->reason[i] = rw_collapse_reason(p, &sc->D[i], &sc->regime[i], &in, xi);
        if (sc->reason[i] != RW_STANDING) {
            sc->collapsed[i] = 1;
            sc->t_collapse[i] = t;
            flags |= 4;
        }
    }
    return flags;
}

/* Wall i's mass (its bodies and the overburden it carries), and its momentum relative to its base
 * on the rotation rates (F_base = -m a_b + pa.q'' - F_top, rw_physics.c) */
static double wall_mass(const rw_scene *sc, int i)
{
    return (sc->S.wall[i].W + sc->D[i].Wd) / sc->S.wall[i].g;
}

static double wall_rocking_momentum(const rw_scene *sc, int i, const double xi[RW_NX])
{
    return -(sc->D[i].pa[0] * xi[2] + sc->D[i].pa[1] * xi[3]);
}

static double spring_energy(int law, const bd_spring *s, double u, double work)
{
    return law == BD_ELASTIC ? 0.5 * s->k * u * u : work; /* hysteretic: the work done on it */
}

static double building_energy(const rw_scene *sc, const double xb[BD_NX])
{
    const bd_params *b = &sc->S.building;
    double E = 0.0;
    int i;
    for (i = 0; i < sc->S.n_storeys; i++) {
        const double *f = xb + BD_STATES_PER_FLOOR * i;
        E += 0.5 * b->md[i] * f[BD_W] * f[BD_W];
        E += spring_energy(b->diaphragm_law, &b->diaph[i], bd_diaphragm_deformation(xb, i), f[BD_WORK_D]);
        if (sc->S.rigid_in_plane) continue;
        E += 0.5 * b->m[i] * f[BD_V] * f[BD_V];
        E += spring_energy(b->storey_law, &b->storey[i], bd_drift(xb, i), f[BD_WORK_S]);
    }
    return E;
}

double rw_scene_energy(const rw_scene *sc, double ag, const double x[])
{
    double xb[BD_NX];
    double E;
    int i;
    (void)ag; /* the energy of the motion relative to the ground does not depend on its acceleration */
    building_states(sc, x, xb);
    E = building_energy(sc, xb);
    for (i = 0; i < sc->S.n_storeys; i++) {
        const double *xi = RW_SCENE_WALL(x, i);
        const double vb = diaphragm_velocity(xb, i - 1);
        rw_input in;
        if (!standing(sc, i)) continue;
        /* a tied wall's energy reads its top's displacement only (rw_energy), not its base's
         * acceleration: the scene's rates are not needed here */
        in = wall_input(xb, i, 0.0);
        E += rw_energy(&sc->S.wall[i], &sc->D[i], &sc->regime[i], &in, xi) + 0.5 * wall_mass(sc, i) * vb * vb +
             vb * wall_rocking_momentum(sc, i, xi);
    }
    return E;
}

void rw_scene_powers(const rw_scene *sc, double ag, const double x[], double *p_ground, double *p_damping)
{
    const bd_params *b = &sc->S.building;
    double xb[BD_NX], momentum = 0.0, damping = 0.0;
    int i;
    building_states(sc, x, xb);
    for (i = 0; i < sc->S.n_storeys; i++) {
        const double *f = xb + BD_STATES_PER_FLOOR * i;
        const double v_below = i > 0 ? xb[BD_STATES_PER_FLOOR * (i - 1) + BD_V] : 0.0;
        const double drift_rate = f[BD_V] - v_below, deform_rate = f[BD_W] - f[BD_V];
        momentum += b->m[i] * f[BD_V] + b->md[i] * f[BD_W];
        damping += b->a0 * (b->m[i] * f[BD_V] * f[BD_V] + b->md[i] * f[BD_W] * f[BD_W]) +
                   (b->a1 * b->storey[i].k + b->cs[i]) * drift_rate * drift_rate +
                   (b->a1 * b->diaph[i].k + b->cd[i]) * deform_rate * deform_rate;
        if (standing(sc, i))
            momentum += wall_mass(sc, i) * diaphragm_velocity(xb, i - 1) +
                        wall_rocking_momentum(sc, i, RW_SCENE_WALL(x, i));
    }
    *p_ground = -ag * momentum;
    *p_damping = damping;
}

double rw_scene_s1(const rw_scene *sc, const double x[], int i)
{
    return sc->S.has_wall[i] ? rw_s1(&sc->S.wall[i], RW_SCENE_WALL(x, i)) : 0.0;
}

double rw_scene_s2(const rw_scene *sc, const double x[], int i)
{
    return sc->S.has_wall[i] ? rw_s2(&sc->S.wall[i], RW_SCENE_WALL(x, i)) : 0.0;
}

double rw_scene_diaphragm_deformation(const rw_scene *sc, const double x[], int i)
{
    double xb[BD_NX];
    building_states(sc, x, xb);
    return bd_diaphragm_deformation(xb, i);
}

double rw_scene_tie_force(const rw_scene *sc, const double x[], int i)
{
    double xb[BD_NX];
    rw_input in;
    if (!standing(sc, i)) return 0.0;
    building_states(sc, x, xb);
    in = wall_input(xb, i, 0.0);
    return rw_F_top(&sc->S.wall[i], &in, RW_SCENE_WALL(x, i));
}
