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
 * Only the modes that turn by a radian or more over the step need their coordinates (a row or two
 * of Winv each); a slower one's departure is |mu|^4 / 384 of its size or less, and the size is
 * bounded from the state's norm. The modes only bound: the polynomial is the motion's own ends,
 * and the bounds carry a margin for the decomposition's rounding (a few ulps times its condition,
 * SX_MODES_MARGIN). */
#include "rw_scene_exact_internal.h"

#include <float.h>
#include <math.h>

#define SQRT3 1.7320508075688772
#define PEANO_VALUE (1.0 / 384.0)  /* max u^2 (1 - u)^2 / 24 */
#define PEANO_RATE (SQRT3 / 216.0) /* max over u of the rate's kernel */
#define BAND_POWER 384.0           /* |mu|^4 past which a band is tighter than the interpolant */

/* one mode's share of the departure from H per unit of a functional's share |a|, for the value and
 * for its rate in u; the size behind it (for the rounding's margin); and a band's free part at the
 * ends (value at 0 and 1, rate in u at 0 and 1: real and imaginary parts), which the ends' data
 * give up */
typedef struct {
    double err, derr, size;
    int band;
    double re[4], im[4];
} mode_bound;

static double growth_over(const sx_modes *m, int k, double h) { return m->growth[k] > 0.0 ? exp(m->growth[k] * h) : 1.0; }

/* mode k's coordinate from the state (a pair's zeta = y_j - i y_j+1) */
static void coordinate(const sx_region *r, int k, const double x[], double *re, double *im)
{
    const sx_modes *m = &r->modes;
    const int n = r->n, j = m->first[k];
    const double *w = m->Winv + (size_t)j * (size_t)n;
    double a = 0.0, b = 0.0;
    int i;
    for (i = 0; i < n; i++) a += w[i] * x[i];
    if (m->pair[k])
        for (w += n, i = 0; i < n; i++) b -= w[i] * x[i];
    *re = a, *im = b;
}

/* the particular part's value at the step's start, alpha = -(b0 + b1 / lam) / lam, with
 * b0 = g0 + g1 ag0 and b1 = g1 slope */
static void particular(const sx_modes *m, int k, double ag0, double slope, double *ar, double *ai)
{
    const double lr = creal(m->inv_lam[k]), li = cimag(m->inv_lam[k]);
    const double g0r = creal(m->g0[k]), g0i = cimag(m->g0[k]), g1r = creal(m->g1[k]), g1i = cimag(m->g1[k]);
    const double b1r = g1r * slope, b1i = g1i * slope;
    const double sr = g0r + g1r * ag0 + (b1r * lr - b1i * li), si = g0i + g1i * ag0 + (b1r * li + b1i * lr);
    *ar = -(sr * lr - si * li), *ai = -(sr * li + si * lr);
}

/* a mode of its own (a real eigenvalue or a complex pair) over the step; xn: the state's balanced
 * norm, which bounds a slow mode's coordinate */
static void scalar_mode(const sx_region *r, int k, const double xa0[], double xn, double h, const double complex *emu,
                        mode_bound *b)
{
    const sx_modes *m = &r->modes;
    const double wh = m->abs_lam[k] * h, w4 = wh * wh * wh * wh, G = growth_over(m, k, h);
    const double ag0 = xa0[r->n], slope = xa0[r->n + 1];
    double zr, zi, ar, ai, cr = 0.0, ci = 0.0, c, z;
    b->band = 0;
    if (m->lam[k] == 0.0) { /* a polynomial of degree 2 in time: H holds it exactly */
        b->err = b->derr = 0.0;
        b->size = m->wnorm[k] * xn;
        return;
    }
    particular(m, k, ag0, slope, &ar, &ai);
    if (wh < 1.0) { /* |C| <= |zeta| + |alpha|, the coordinate's size from the state's */
        z = m->wnorm[k] * xn;
        c = z + sqrt(ar * ar + ai * ai);
    } else {
        coordinate(r, k, xa0, &zr, &zi);
        cr = zr - ar, ci = zi - ai;
        z = sqrt(zr * zr + zi * zi);
        c = sqrt(cr * cr + ci * ci);
    }
    if (w4 < BAND_POWER) {
        /* the rounding of zeta moves C by as much, and the departure by at most that times G */
        b->err = c * w4 * G * PEANO_VALUE;
        b->derr = c * w4 * G * PEANO_RATE;
        b->size = z * G;
        return;
    }
    {
        const double complex e = emu ? emu[k] : cexp(m->lam[k] * h), mu = m->lam[k] * h, C = cr + I * ci;
        const double complex w[4] = {C, C * e, mu * C, mu * C * e};
        int j;
        b->band = 1;
        b->err = c * G;
        b->derr = c * G * wh;
        b->size = (z + sqrt(ar * ar + ai * ai) + cabs(m->g1[k] * slope * m->inv_lam[k]) * h + c) * (1.0 + wh) * G;
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
static void block_mode(const sx_region *r, int k, const double xa0[], double h, mode_bound *b, double *reach)
{
    const sx_modes *m = &r->modes;
    const double complex b0 = m->g0[k] + m->g1[k] * xa0[r->n], b1 = m->g1[k] * xa0[r->n + 1];
    const double nb = m->abs_lam[k], g = exp(nb * h), h4 = h * h * h * h;
    double zr, zi;
    double complex z0, d1, d2;
    coordinate(r, k, xa0, &zr, &zi);
    z0 = zr + I * zi;
    d1 = apply_block(m->B[k], z0) + b0;
    d2 = apply_block(m->B[k], d1) + b1;
    b->band = 0;
    b->err = cabs(d2) * nb * nb * g * h4 * PEANO_VALUE;
    b->derr = cabs(d2) * nb * nb * g * h4 * PEANO_RATE;
    b->size = (cabs(z0) + cabs(d1) * h + cabs(d2) * h * h) * g;
    *reach += b->size;
}

/* mode k driven by the blocks' rounding (a force of at most coupling x reach, the blocks' planes
 * being invariant to rounding only): the disturbance d (|d| <= F h G, |d'| <= F (1 + |lam| h) G)
 * departs from its own interpolant by at most |d| + |H[d]| */
static void driven(const sx_modes *m, int k, double reach, double h, mode_bound *b)
{
    const double F = m->coupling[k] * reach, G = growth_over(m, k, h), spread = F * h * G * (1.0 + m->abs_lam[k] * h);
    b->err += 3.0 * spread;
    b->derr += 8.0 * spread;
}

/* the modes' bounds over the step */
static void mode_bounds(const sx_region *r, const double xa0[], double h, const double complex *emu, mode_bound *mb)
{
    const sx_modes *m = &r->modes;
    double reach = 0.0, xn = 0.0;
    int k, i;
    for (i = 0; i < r->n; i++) xn = fmax(xn, fabs(xa0[i]) / r->scale[i]);
    for (k = 0; k < m->count; k++) {
        if (m->block[k]) block_mode(r, k, xa0, h, &mb[k], &reach);
        else scalar_mode(r, k, xa0, xn, h, emu, &mb[k]);
    }
    if (m->blocks)
        for (k = 0; k < m->count; k++) driven(m, k, reach, h, &mb[k]);
}

int sx_hermite_polys(const sx_region *r, double h, const double complex *emu, const double xa0[], const double xa1[],
                     sx_lopoly P[SX_MAX_F])
{
    const sx_modes *m = &r->modes;
    const int nf = r->nf;
    double v0[SX_MAX_F], v1[SX_MAX_F], d0[SX_MAX_F], d1[SX_MAX_F];
    double tail[SX_MAX_F], dtail[SX_MAX_F], size[SX_MAX_F];
    mode_bound mb[SX_MAX_N];
    int f, k;
    if (!m->valid) return 0;
    mode_bounds(r, xa0, h, emu, mb);
    for (f = 0; f < nf; f++) {
        v0[f] = sx_functional(r, f, xa0);
        v1[f] = sx_functional(r, f, xa1);
        d0[f] = h * sx_functional_rate(r, f, xa0);
        d1[f] = h * sx_functional_rate(r, f, xa1);
        size[f] = fabs(v0[f]) + fabs(v1[f]) + fabs(d0[f]) + fabs(d1[f]);
        tail[f] = dtail[f] = 0.0;
    }
    for (k = 0; k < m->count; k++) {
        const double *ar = m->share_re[k], *ai = m->share_im[k], *abs_a = m->share_abs[k];
        const mode_bound *b = &mb[k];
        for (f = 0; f < nf; f++) {
            tail[f] += abs_a[f] * b->err;
            dtail[f] += abs_a[f] * b->derr;
            size[f] += abs_a[f] * b->size;
        }
        if (!b->band) continue;
        for (f = 0; f < nf; f++) { /* Re(a w) in real arithmetic */
            v0[f] -= ar[f] * b->re[0] - ai[f] * b->im[0];
            v1[f] -= ar[f] * b->re[1] - ai[f] * b->im[1];
            d0[f] -= ar[f] * b->re[2] - ai[f] * b->im[2];
            d1[f] -= ar[f] * b->re[3] - ai[f] * b->im[3];
        }
    }
    for (f = 0; f < nf; f++) {
        sx_lopoly *p = &P[f];
        const double margin = SX_MODES_MARGIN(m->cond) * size[f] + DBL_MIN;
        p->coef[0] = v0[f];
        p->coef[1] = v0[f] + d0[f] * (1.0 / 3.0);
        p->coef[2] = v1[f] - d1[f] * (1.0 / 3.0);
        p->coef[3] = v1[f];
        p->tail = tail[f] + margin;
        p->dtail = dtail[f] + margin;
        p->deg = 3;
        p->bern = 1;
    }
    return 1;
}
