/* Bouc-Wen diaphragms in the exact scene engine. The law's force alpha k d + (1 - alpha) Fy z
 * (building_physics.h) is split: alpha k d is part of the region's linear system, and the
 * hysteretic share (1 - alpha) Fy z(t) is an input, a quadratic in time over each step held in the
 * augmented state as the chain (z, z', z'') with z''' = 0. Over a step the motion is then exact
 * (exp(Aa h) or the exact series), and the quadratic is fitted to the law by Picard rounds:
 *
 *   the deformation rate d'(t) along the exact motion under the current quadratic, at the nodes
 *   u = 0, 1/4, ..., 1 of the step, and the quartic through them; z' = rate(z, d')
 *   (bd_hysteretic_rate, pinching included) by RK4 over the quarters, a quarter split where d'
 *   reverses (z's rate has a kink there); the quadratic through z(0), z(1/2) and z(1); until it
 *   settles.
 *
 * A round contracts by about (1 - alpha) k h^2 / m_d, the diaphragm's own (omega h)^2: the steps
 * the series converge over keep it under 1, and the fit's cap on the step (SX_BW_HMAX) far under.
 * The error is the quadratic's and RK4's, of high order in h (measured in docs/scenes.md). The work done
 * on the spring, which the scene's energy counts, is kept exactly: alpha k's part, a function of the
 * deformation alone, where the bilinear law's work is brought up to date (sx_sync_hysteresis); the
 * hysteretic part with each step, as the integral of z's quadratic times the exact deformation rate
 * (the table's work rows, or the series' polynomial). */
#include "rw_scene_exact_internal.h"

#include <math.h>
#include <string.h>

#define SX_BW_ROUNDS 30     /* Picard rounds before a fit is given up (2 to 4 settle it) */
#define SX_BW_SETTLED 1e-13 /* z changes less than this between rounds (|z| <= 1) */

static double *floor_states(const rw_scene *sc, double x[], int i)
{
    return RW_SCENE_BUILDING(sc, x) + BD_STATES_PER_FLOOR * i;
}

int sx_bouc_wen(const rw_scene *sc, int i)
{
    const int law = sc->S.building.diaphragm_law;
    (void)i; /* one law for every diaphragm */
    return law == BD_BOUC_WEN || law == BD_BOUC_WEN_PINCHED;
}

int sx_bouc_wen_chain(const rw_scene *sc, int i)
{
    const bd_spring *s = &sc->S.building.diaph[i];
    return sx_bouc_wen(sc, i) && (1.0 - s->alpha) * s->Fy > 0.0 && s->k > 0.0;
}

/* storey i's diaphragm deformation rate at an augmented state */
static double deformation_rate(const sx_region *r, int i, const double xa[])
{
    const int nd = r->ndof;
    return xa[nd + r->diaph_dof[i]] - (r->floor_dof[i] >= 0 ? xa[nd + r->floor_dof[i]] : 0.0);
}

/* the deformation rates at the nodes u = j/4 of the step from xa0: by the table's rows, or on
 * the series of xa0 */
static void rates_at_nodes(const sx_region *r, const sx_step *st, double h, const double xa0[],
                           double d[SX_MAX_Z][SX_Z_NODES + 1])
{
    double xa[SX_MAX_NA];
    sx_series s;
    int k, j;
    for (k = 0; k < r->nz; k++) d[k][0] = deformation_rate(r, r->z_storey[k], xa0);
    if (st) {
        for (k = 0; k < r->nz; k++)
            for (j = 0; j < SX_Z_NODES; j++) {
                const double *row = st->zrows + (size_t)((k * SX_Z_NODES + j) * r->na);
                double v = 0.0;
                int c;
                for (c = 0; c < r->na; c++) v += row[c] * xa0[c];
                d[k][j + 1] = v;
            }
        return;
    }
    sx_series_of(r, xa0, h, &s);
    for (j = 1; j <= SX_Z_NODES; j++) {
        sx_series_at(r, &s, (double)j / SX_Z_NODES, xa);
        for (k = 0; k < r->nz; k++) d[k][j] = deformation_rate(r, r->z_storey[k], xa);
    }
}

/* the law's z' at z and the deformation rate du */
static double z_rate(const sx_run *R, int i, double z, double du)
{
    const bd_params *p = &R->sc.S.building;
    return bd_hysteretic_rate(p, p->diaphragm_law, &p->diaph[i], z, du);
}

/* the quartic through the deformation rates d at the nodes x = 0, 1, ..., 4 (x = 4 u), in Newton's
 * form: its forward differences (the exact motion's rate is smooth over the step; only z's law has
 * kinks) */
static void newton_form(const double d[SX_Z_NODES + 1], double c[SX_Z_NODES + 1])
{
    int j, m;
    memcpy(c, d, sizeof(double) * (SX_Z_NODES + 1));
    for (m = 1; m <= SX_Z_NODES; m++)
        for (j = SX_Z_NODES; j >= m; j--) c[j] = (c[j] - c[j - 1]) / m;
}

/* the quartic at u in [0, 1] */
static double rate_at(const double c[SX_Z_NODES + 1], double u)
{
    const double x = u * SX_Z_NODES;
    double v = c[SX_Z_NODES];
    int j;
    for (j = SX_Z_NODES - 1; j >= 0; j--) v = v * (x - j) + c[j];
    return v;
}

/* one RK4 step of z of length dt, the deformation rate d0, dm and d1 at its start, middle and end */
static double rk4(const sx_run *R, int i, double z, double d0, double dm, double d1, double dt)
{
    const double k1 = z_rate(R, i, z, d0), k2 = z_rate(R, i, z + 0.5 * dt * k1, dm);
    const double k3 = z_rate(R, i, z + 0.5 * dt * k2, dm), k4 = z_rate(R, i, z + dt * k3, d1);
    return z + dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

/* where the rate changes sign in [u0, u1] (its ends' signs differ), by bisection */
static double reversal(const double c[], double u0, double u1, int positive_at_u0)
{
    int k;
    for (k = 0; k < 40; k++) {
        const double um = 0.5 * (u0 + u1);
        if ((rate_at(c, um) > 0.0) == positive_at_u0) u0 = um;
        else u1 = um;
    }
    return 0.5 * (u0 + u1);
}

/* z over the quarter [j/4, (j+1)/4] of a step of length h: RK4, split where the deformation rate
 * reverses (z's rate has a kink there); d the rates at the nodes, c their quartic */
static double z_quarter(const sx_run *R, int i, const double d[], const double c[], double z, int j, double h)
{
    const double u0 = (double)j / SX_Z_NODES, u1 = (double)(j + 1) / SX_Z_NODES, a = d[j], b = d[j + 1];
    if ((a > 0.0 && b < 0.0) || (a < 0.0 && b > 0.0)) {
        const double ur = reversal(c, u0, u1, a > 0.0);
        z = rk4(R, i, z, a, rate_at(c, 0.5 * (u0 + ur)), 0.0, (ur - u0) * h);
        return rk4(R, i, z, 0.0, rate_at(c, 0.5 * (ur + u1)), b, (u1 - ur) * h);
    }
    return rk4(R, i, z, a, rate_at(c, 0.5 * (u0 + u1)), b, (u1 - u0) * h);
}

/* chain k's quadratic through z0, zh and z1 at u = 0, 1/2 and 1 of a step of length h; the
 * largest change of z's coefficients in u */
static double set_chain(const sx_region *r, int k, double h, double z0, double zh, double z1, double xa[])
{
    double *c = xa + sx_z_col(r, k);
    const double a = 2.0 * (z1 - 2.0 * zh + z0), b = z1 - z0 - a;
    const double change = fmax(fabs(b - c[1] * h), fabs(a - 0.5 * c[2] * h * h));
    c[0] = z0;
    c[1] = b / h;
    c[2] = 2.0 * a / (h * h);
    return change;
}

int sx_bouc_wen_fit(const sx_run *R, const sx_region *r, const sx_step *st, double h, double xa0[])
{
    double nodes[SX_MAX_Z][SX_Z_NODES + 1], last;
    int k, round;
    for (k = 0; k < r->nz; k++) { /* a first guess: the last step's quadratic carried on, or after an
                                      event the law's rate at the start, held */
        const int i = r->z_storey[k];
        double *c = xa0 + sx_z_col(r, k);
        c[1] = R->z_next_valid ? R->z_next[k][0] : z_rate(R, i, c[0], deformation_rate(r, i, xa0));
        c[2] = R->z_next_valid ? R->z_next[k][1] : 0.0;
    }
    for (round = 0, last = INFINITY; round < SX_BW_ROUNDS; round++) {
        double change = 0.0;
        rates_at_nodes(r, st, h, xa0, nodes);
        for (k = 0; k < r->nz; k++) {
            const int i = r->z_storey[k];
            const double *d = nodes[k], z0 = xa0[sx_z_col(r, k)];
            double c[SX_Z_NODES + 1], zh, z1;
            newton_form(d, c);
            zh = z_quarter(R, i, d, c, z_quarter(R, i, d, c, z0, 0, h), 1, h);
            z1 = z_quarter(R, i, d, c, z_quarter(R, i, d, c, zh, 2, h), 3, h);
            change = fmax(change, set_chain(r, k, h, z0, zh, z1, xa0));
        }
        if (change <= SX_BW_SETTLED) return 0;
        if (round >= 2 && change > 0.5 * last) return 1; /* not contracting: a shorter step will */
        last = change;
    }
    return 1;
}

/* the chain's z at u of the step (c: its columns; h: the step's length) */
static double chain_at(const double *c, double u, double h)
{
    const double tau = u * h;
    return c[0] + tau * (c[1] + 0.5 * tau * c[2]);
}

/* the integral over [0, u] of the step of the chain's z times the deformation rate [m]: on the
 * series, the product of z's quadratic in u with the rate's polynomial; on the table, its work rows */
static double z_times_rate(const sx_region *r, int k, const double xa0[], double u, const sx_step *st,
                           const sx_series *s)
{
    const double *c = xa0 + sx_z_col(r, k);
    double sum = 0.0;
    int j;
    if (s) {
        double z[SX_MAX_DEG + 1], d[SX_MAX_DEG + 1], zd[2 * SX_MAX_DEG + 2];
        for (j = 0; j <= s->deg; j++) {
            z[j] = j == 0 ? c[0] : (j == 1 ? c[1] * s->L : (j == 2 ? 0.5 * c[2] * s->L * s->L : 0.0));
            d[j] = deformation_rate(r, r->z_storey[k], s->X + (size_t)j * (size_t)r->na);
        }
        sx_poly_product(z, d, s->deg, zd);
        return s->L * sx_poly_integral(zd, 2 * s->deg, u);
    }
    {
        const double *w = st->zwork + (size_t)(3 * k * r->na);
        for (j = 0; j < r->na; j++) sum += (c[0] * w[j] + c[1] * w[r->na + j] + 0.5 * c[2] * w[2 * r->na + j]) * xa0[j];
    }
    return sum;
}

void sx_bouc_wen_advance(sx_run *R, const sx_region *r, const double xa0[], double u, const sx_step *st,
                         const sx_series *s)
{
    const double h = s ? s->L : st->h;
    int k;
    for (k = 0; k < r->nz; k++) {
        const int i = r->z_storey[k];
        const bd_spring *sp = &R->sc.S.building.diaph[i];
        const double *c = xa0 + sx_z_col(r, k);
        const double work = (1.0 - sp->alpha) * sp->Fy * z_times_rate(r, k, xa0, u, st, s);
        double *f_states = floor_states(&R->sc, R->x, i);
        f_states[BD_WORK_D] += work;
        f_states[BD_ZD] = fmax(-1.0, fmin(1.0, chain_at(c, u, h)));
        R->work_hysteretic += work;
        R->z_next[k][0] = c[1] + u * h * c[2]; /* the next step's first guess */
        R->z_next[k][1] = c[2];
    }
    R->z_next_valid = 1;
}
