/* The quiet test's polynomials over a step, from its exact ends. Each watched functional f (its row
 * F over the augmented state, and FA = F Aa for its rate) has exact values and rates at both ends
 * of the step, from xa0 and xa1 = exp(Aa h) xa0: their cubic Hermite interpolant H is the
 * polynomial, and the region's modes bound how far the motion departs from it (the tail).
 *
 * While the record is linear over the step, each mode is zeta(tau) = alpha + beta tau + C e^(lam tau):
 * its particular part is affine in time, which H reproduces exactly, so
 *     f - H[f] = sum_k Re(a_fk C_k (e^(lam_k tau) - H[e^(lam_k .)](tau))).
 * The Peano kernel of two-point cubic Hermite interpolation keeps its sign, so the remainder
 * |g - H[g]| <= max|g''''| u^2 (1 - u)^2 / 24 holds for complex g too: with mu = lam h and G the
 * growth e^(max(Re mu, 0)), |e^(mu u) - H| <= |mu|^4 G / 384 on [0, 1], and the rate's departure is
 * within |mu|^4 G sqrt(3) / 216. A mode that turns fast over the step (|mu|^4 > 384: a stiff tie
 * over a record interval) is a band instead: its free part is taken out of the ends' data and
 * bounded by its size |C| G, as docs/engine.md's band does for the single wall. A nearly defective
 * pair kept as a block (rw_scene_exact_blocks.c) moves as y' = B y + b0 + b1 tau, whose fourth
 * derivative B^2 y'' is within ||B||^2 e^(||B|| h) |y''(0)|.
 *
 * Every mode's size is its own coordinate at the step's start, all of them from one product
 * Winv x. The modes only bound: the polynomial is the motion's own ends, and the bounds carry a
 * margin for the decomposition's rounding (a few ulps times its condition, SX_MODES_MARGIN, times
 * each functional's own data and shares of the modes' sizes). The cubics themselves are assembled
 * from these bounds in rw_scene_exact_quick.c, for the first pass and the full test alike. */
#include "rw_scene_exact_internal.h"

#include <float.h>
#include <math.h>

#define SQRT3 1.7320508075688772
#define PEANO_VALUE (1.0 / 384.0)  /* max u^2 (1 - u)^2 / 24 */
#define PEANO_RATE (SQRT3 / 216.0) /* max over u of the rate's kernel */
#define BAND_POWER 384.0           /* |mu|^4 past which a band is tighter than the interpolant */


static double mag(double complex z) { return sqrt(creal(z) * creal(z) + cimag(z) * cimag(z)); }

static double growth_over(const sx_modes *m, int k, double h) { return m->growth[k] > 0.0 ? exp(m->growth[k] * h) : 1.0; }

void sx_hermite_step_of(const sx_region *r, double h, sx_hermite_step *hs)
{
    const sx_modes *m = &r->modes;
    int k;
    hs->h = h;
    hs->bands = hs->modal = hs->nfast = 0;
    for (k = 0; k < m->count; k++) {
        int band;
        hs->wh[k] = m->abs_lam[k] * h;
        hs->w4[k] = hs->wh[k] * hs->wh[k] * hs->wh[k] * hs->wh[k];
        hs->G[k] = growth_over(m, k, h);
        band = !m->block[k] && hs->w4[k] >= BAND_POWER; /* (fast_mode's: |mu|^4 past 384 is past |mu| = 1) */
        hs->emu[k] = band ? cexp(m->lam[k] * h) : 1.0;
        hs->bands += band;
        hs->modal |= band && hs->wh[k] > SX_BAND_MODAL_WH;
        if (!m->block[k] && hs->wh[k] >= 1.0) hs->fast[hs->nfast++] = k;
    }
}

/* A window of n steps of length h (L = n h) whose record's slope changes by ds_j at the sample t_j
 * inside it (u = s_j = j / n, to rounding) adds to mode k the motion kappa_j = g1 ds_j phi(t - t_j),
 * phi(v) = (e^(lam v) - 1 - lam v) / lam^2 past the kink and zero before it: C^1, with kappa_j'' =
 * g1 ds_j e^(lam (t - t_j)) past it. Every other part of the motion is as over one step. The cubic
 * Hermite interpolant's departure from a C^1 function g on [0, 1] is int_0^1 K(u, s) g''(s) ds with
 * the kernel K(u, s) = (u - s)_+ - H[(. - s)_+](u), so that |kappa_j - H kappa_j| <= L^2 |g1| |ds_j| G
 * max_u int_{s_j}^1 |K(u, s)| ds, the kernel's integral (sx_window_kinks). A functional's own term in
 * the record, F_ag ag, kinks there itself: its departure is L |F_ag| |ds_j| |K(u, s_j)|. Per table,
 * each functional's L^2 sum_k |a_fk| |g1_k| G_k (modes) and L |F_ag| (record). */
void sx_kink_of(const sx_region *r, const sx_hermite_step *hs, double modes[SX_MAX_F], double record[SX_MAX_F])
{
    const sx_modes *m = &r->modes;
    const double L = hs->h;
    int f, k;
    for (f = 0; f < r->nf; f++) {
        modes[f] = 0.0;
        record[f] = L * fabs(r->F[f][r->n]);
    }
    for (k = 0; k < m->count; k++) {
        const double c = L * L * mag(m->g1[k]) * hs->G[k];
        for (f = 0; f < r->nf; f++) modes[f] += m->share_abs[k][f] * c;
    }
}

/* The kernel's bounds for a kink at u = j / n, past s = j / n - 0.01 (rounding moves it by far less):
 * max_u int_s^1 |K(u, s')| ds' and max over s' within 0.01 of j / n and u of |K(u, s')|, rounded up
 * (tests/c/test_scene_window.c computes them again) */
#if SX_WINDOW > 4
#error "the kernel's bounds are tabled for windows of 4 steps at most"
#endif
void sx_window_kinks(int n, int j, double *value, double *record)
{
    static const double V[5][4] = {{0}, {0}, {0, 0.0375}, {0, 0.0470, 0.0230}, {0, 0.0480, 0.0375, 0.0168}};
    static const double E[5][4] = {{0}, {0}, {0, 0.126}, {0, 0.103, 0.103}, {0, 0.075, 0.126, 0.075}};
    *value = V[n][j];
    *record = E[n][j];
}

/* every mode's coordinates y = Winv x from the state, in one product (vectorised by columns) */
static void coordinates(const sx_region *r, const double x[], double y[])
{
    sx_matvec_cols(r->n, r->n, r->modes.Winv_cols, x, y);
}

/* mode k's coordinate from them (a pair's zeta = y_j - i y_j+1) */
static double complex coordinate(const sx_modes *m, int k, const double y[])
{
    const int j = m->first[k];
    return m->pair[k] ? y[j] - I * y[j + 1] : y[j];
}

/* a slow mode (|mu| < 1) over the step: its free part's size |C| <= |zeta| + |alpha| (the particular
 * part's from the record's) */
static void slow_mode(const sx_region *r, int k, const sx_hermite_step *hs, const double xa0[], const double y0[],
                      double slope, sx_mode_bounds *B)
{
    const sx_modes *m = &r->modes;
    const double w4G = hs->w4[k] * hs->G[k], z = mag(coordinate(m, k, y0));
    const double c = z + m->pb0[k] + m->pb1[k] * fabs(xa0[r->n]) + m->pb2[k] * fabs(slope);
    B->mode[k].band = 0;
    B->err[k] = c * w4G * PEANO_VALUE;
    B->derr[k] = c * w4G * PEANO_RATE;
    B->size[k] = z * hs->G[k]; /* the rounding of zeta moves C by as much, the departure by that times G at most */
}

/* every mode's bounds as a slow one's: slow_mode's arithmetic in arrays over the modes, in loops
 * without a branch that the compiler vectorises (the fast ones are then bounded again by fast_mode).
 * A loop over the modes that chose each mode's bound by a branch cost the house 2 % of its time. */
static void all_as_slow(const sx_modes *m, const sx_hermite_step *hs, double ag, double slope, const double y0[],
                        sx_mode_bounds *B)
{
    const double abs_ag = fabs(ag), abs_slope = fabs(slope);
    double re[SX_MAX_N], im[SX_MAX_N];
    int k;
    for (k = 0; k < m->count; k++) { /* (mag(coordinate) without the complex type: the same sums) */
        re[k] = y0[m->first[k]];
        im[k] = m->pair[k] ? y0[m->first[k] + 1] : 0.0;
    }
    for (k = 0; k < m->count; k++) {
        const double w4G = hs->w4[k] * hs->G[k], z = sqrt(re[k] * re[k] + im[k] * im[k]);
        const double c = z + m->pb0[k] + m->pb1[k] * abs_ag + m->pb2[k] * abs_slope;
        B->err[k] = c * w4G * PEANO_VALUE;
        B->derr[k] = c * w4G * PEANO_RATE;
        B->size[k] = z * hs->G[k];
    }
    if (hs->bands) /* (read only where the step holds bands) */
        for (k = 0; k < m->count; k++) B->mode[k].band = 0;
}

/* a mode that turns by a radian or more over the step: its coordinate, its free part C (zeta less
 * its particular part alpha = -(b0 + b1 / lam) / lam, b0 = g0 + g1 ag0, b1 = g1 slope) bounded
 * through the interpolant, or a band past |mu|^4 = 384 */
static SX_ALWAYS_INLINE void fast_mode(const sx_region *r, int k, const sx_hermite_step *hs, const double xa0[],
                                        const double y0[], double slope, sx_mode_bounds *B)
{
    sx_mode_bound *b = &B->mode[k];
    const sx_modes *m = &r->modes;
    const double wh = hs->wh[k], w4 = hs->w4[k], G = hs->G[k], h = hs->h;
    const double complex il = m->inv_lam[k], b1 = m->g1[k] * slope;
    const double complex alpha = -(m->g0[k] + m->g1[k] * xa0[r->n] + b1 * il) * il, zeta = coordinate(m, k, y0);
    const double complex C = zeta - alpha;
    const double c = mag(C);
    b->band = w4 >= BAND_POWER;
    if (!b->band) {
        B->err[k] = c * w4 * G * PEANO_VALUE;
        B->derr[k] = c * w4 * G * PEANO_RATE;
        B->size[k] = mag(zeta) * G;
    } else {
        const double complex e = hs->emu[k], mu = m->lam[k] * h;
        const double complex w[4] = {C, C * e, mu * C, mu * C * e};
        int j;
        B->err[k] = c * G;
        B->derr[k] = c * G * wh;
        B->size[k] = (mag(zeta) + mag(alpha) + mag(b1 * il) * h + c) * (1.0 + wh) * G;
        b->psize = mag(alpha) + mag(b1 * il) * h; /* its particular part alone (sx_ends_modal) */
        for (j = 0; j < 4; j++) b->re[j] = creal(w[j]), b->im[j] = cimag(w[j]);
    }
}

/* B applied to a block's coordinates (y_a, y_b), held as z = y_a - i y_b as a pair's */
static double complex apply_block(const double B[4], double complex z)
{
    const double a = creal(z), b = -cimag(z);
    return (B[0] * a + B[1] * b) - I * (B[2] * a + B[3] * b);
}

/* a block over the step; reach: what it adds to the largest size the blocks' coordinates take */
static void block_mode(const sx_region *r, int k, const double xa0[], const double y0[], double slope, double h,
                       sx_mode_bounds *B, double *reach)
{
    const sx_modes *m = &r->modes;
    const double complex b0 = m->g0[k] + m->g1[k] * xa0[r->n], b1 = m->g1[k] * slope;
    const double nb = m->abs_lam[k], g = exp(nb * h), h4 = h * h * h * h;
    const double complex z0 = coordinate(m, k, y0), d1 = apply_block(m->B[k], z0) + b0, d2 = apply_block(m->B[k], d1) + b1;
    B->mode[k].band = 0;
    B->err[k] = mag(d2) * nb * nb * g * h4 * PEANO_VALUE;
    B->derr[k] = mag(d2) * nb * nb * g * h4 * PEANO_RATE;
    B->size[k] = (mag(z0) + mag(d1) * h + mag(d2) * h * h) * g;
    *reach += B->size[k];
}

/* mode k driven by the blocks' rounding (a force of at most coupling x reach, the blocks' planes
 * being invariant to rounding only): the disturbance d (|d| <= F h G, |d'| <= F (1 + |lam| h) G)
 * departs from its own interpolant by at most |d| + |H[d]| */
static void driven(const sx_modes *m, int k, double reach, double h, sx_mode_bounds *B)
{
    const double F = m->coupling[k] * reach, G = growth_over(m, k, h), spread = F * h * G * (1.0 + m->abs_lam[k] * h);
    B->err[k] += 3.0 * spread;
    B->derr[k] += 8.0 * spread;
}

/* where the ends' data come from the modes' own coordinates (B->modal), the size behind mode k's part
 * of them, for the rounding's margin: a band's particular part, another's motion and rate (its
 * coordinate's size times 1 + |lam h|); elsewhere a mode's size stays its coordinate's (times its
 * rate's |lam h| for a band, whose free part the data give up) */
static void modal_sizes(const sx_modes *m, const sx_hermite_step *hs, sx_mode_bounds *B)
{
    int k;
    for (k = 0; k < m->count; k++)
        B->size[k] = B->mode[k].band ? B->mode[k].psize : B->size[k] * (1.0 + hs->wh[k]);
}

/* every mode's bounds, one mode at a time: a block's, a slow mode's or a fast one's */
static void each_mode(const sx_region *r, const sx_hermite_step *hs, const double xa0[], const double y0[],
                      sx_mode_bounds *B)
{
    const sx_modes *m = &r->modes;
    const double slope = xa0[r->n + 1];
    double reach = 0.0;
    int k;
    for (k = 0; k < m->count; k++) {
        if (m->block[k]) block_mode(r, k, xa0, y0, slope, hs->h, B, &reach);
        else if (hs->wh[k] < 1.0) slow_mode(r, k, hs, xa0, y0, slope, B);
        else fast_mode(r, k, hs, xa0, y0, slope, B);
    }
    if (m->blocks)
        for (k = 0; k < m->count; k++) driven(m, k, reach, hs->h, B);
}

/* the modes' bounds from the coordinates y0, each mode's (each_mode) or, without blocks, every
 * mode's as a slow one's at once and the fast ones' again */
static SX_ALWAYS_INLINE void bounds_of(const sx_region *r, const sx_hermite_step *hs, const double xa0[],
                                        const double y0[], int one_by_one, sx_mode_bounds *B)
{
    int k;
    B->h = hs->h;
    B->bands = hs->bands, B->modal = hs->modal;
    if (one_by_one || r->modes.blocks) each_mode(r, hs, xa0, y0, B);
    else {
        all_as_slow(&r->modes, hs, xa0[r->n], xa0[r->n + 1], y0, B);
        for (k = 0; k < hs->nfast; k++) fast_mode(r, hs->fast[k], hs, xa0, y0, xa0[r->n + 1], B);
    }
    if (B->modal) modal_sizes(&r->modes, hs, B);
}

void sx_mode_bounds_of(const sx_region *r, const sx_hermite_step *hs, const double xa0[], sx_mode_bounds *B)
{
    double y0[SX_MAX_N];
    coordinates(r, xa0, y0);
    bounds_of(r, hs, xa0, y0, 0, B);
}

void sx_mode_bounds_each(const sx_region *r, const sx_hermite_step *hs, const double xa0[], sx_mode_bounds *B)
{
    double y0[SX_MAX_N];
    coordinates(r, xa0, y0);
    bounds_of(r, hs, xa0, y0, 1, B);
}

/* mode k's part of the ends' data in the modes' own coordinates: a band's particular part only
 * (value alpha, alpha + beta h; rate beta), another's whole motion (zeta, and its rate lam zeta +
 * b0 + b1 t, a block's B zeta + b0 + b1 t) */
static void modal_part(const sx_region *r, int k, const sx_mode_bounds *B, const double xa0[], const double y0[],
                       const double y1[], double complex w[4])
{
    const sx_modes *m = &r->modes;
    const double h = B->h, slope = xa0[r->n + 1];
    const double complex b0 = m->g0[k] + m->g1[k] * xa0[r->n], b1 = m->g1[k] * slope;
    if (B->mode[k].band) {
        const double complex beta = -b1 * m->inv_lam[k], alpha = -(b0 - beta) * m->inv_lam[k];
        w[0] = alpha, w[1] = alpha + beta * h, w[2] = w[3] = beta * h;
    } else {
        const double complex z0 = coordinate(m, k, y0), z1 = coordinate(m, k, y1);
        w[0] = z0, w[1] = z1;
        w[2] = (m->block[k] ? apply_block(m->B[k], z0) : m->lam[k] * z0) + b0;
        w[3] = (m->block[k] ? apply_block(m->B[k], z1) : m->lam[k] * z1) + b0 + b1 * h;
        w[2] *= h, w[3] *= h;
    }
}

void sx_ends_modal(const sx_region *r, const sx_mode_bounds *B, const double xa0[], const double xa1[], double *v0,
                   double *v1, double *d0, double *d1)
{
    const sx_modes *m = &r->modes;
    const double h = B->h;
    double y0[SX_MAX_N], y1[SX_MAX_N];
    int f, k, j;
    coordinates(r, xa0, y0);
    coordinates(r, xa1, y1);
    for (f = 0; f < r->nf; f++) { /* the record's own terms (no functional holds its slope) */
        v0[f] = r->F[f][r->n] * xa0[r->n] + r->F[f][r->n + 2];
        v1[f] = r->F[f][r->n] * (xa0[r->n] + h * xa0[r->n + 1]) + r->F[f][r->n + 2];
        d0[f] = d1[f] = h * r->F[f][r->n] * xa0[r->n + 1];
    }
    for (k = 0; k < m->count; k++) {
        double complex w[4];
        double *out[4];
        modal_part(r, k, B, xa0, y0, y1, w);
        out[0] = v0, out[1] = v1, out[2] = d0, out[3] = d1;
        for (j = 0; j < 4; j++)
            for (f = 0; f < r->nf; f++) out[j][f] += m->share_re[k][f] * creal(w[j]) - m->share_im[k][f] * cimag(w[j]);
    }
}
