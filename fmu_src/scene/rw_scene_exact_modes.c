/* A region's modes and the exact scene engine's slow steps. A stiff tie (or a stiff or light
 * diaphragm) is a mode far faster than the walls' rocking; over a step that turns it by many
 * radians its motion is its quasi-static part (affine in time while the record is linear) plus a
 * free oscillation whose size the mode's amplitude bounds: a band. The other modes are a quadratic
 * in time with a bounded remainder. So a step of the record's interval is cleared by one test on
 * these polynomials, as docs/engine.md's band does for the single wall; the motion over it is
 * still exp(Aa h)'s (the modes only bound it), and a step the test does not clear is halved down
 * to the exact steps. The eigen-decomposition is LAPACK's dgeev. */
#include "rw_scene_exact_internal.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* LAPACK: eigenvalues and right eigenvectors of a general real matrix (column-major) */
extern void dgeev_(const char *jobvl, const char *jobvr, const int *n, double *a, const int *lda, double *wr,
                   double *wi, double *vl, const int *ldvl, double *vr, const int *ldvr, double *work, const int *lwork,
                   int *info);

#define SX_MODES_COND 1e8 /* a decomposition worse conditioned than this bounds nothing */
/* the bounds' allowance for the decomposition's rounding: the modal values' error relative to
 * their size is a few ulps times the condition */
#define SX_MODES_MARGIN(cond) (256.0 * DBL_EPSILON * (cond) + 1e-12)

/* dgeev on A (the first-order block of Aa): eigenvalues and Vr (row-major, real form: a pair's
 * real and imaginary parts in two columns) */
static int decompose(const sx_region *r, double *wr, double *wi, double *Vr)
{
    const int n = r->n;
    double A[SX_MAX_N * SX_MAX_N], VR[SX_MAX_N * SX_MAX_N], work[8 * SX_MAX_N], dummy = 0.0;
    const int lwork = 8 * SX_MAX_N, one = 1;
    int i, j, info = 0;
    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++) A[i + j * n] = r->Aa[i * r->na + j];
    dgeev_("N", "V", &n, A, &n, wr, wi, &dummy, &one, VR, &n, work, &lwork, &info);
    if (info != 0) return 1;
    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++) Vr[i * n + j] = VR[i + j * n];
    return 0;
}

/* the balanced norms of Vr and Winv: their product bounds how far rounding in the coordinates goes */
static double condition(const sx_region *r, const double *Vr, const double *Winv)
{
    const int n = r->n;
    double nv = 0.0, nw = 0.0;
    int i, j;
    for (i = 0; i < n; i++) {
        double rv = 0.0, rw = 0.0;
        for (j = 0; j < n; j++) {
            rv += fabs(Vr[i * n + j]) / r->scale[i];
            rw += fabs(Winv[i * n + j]) * r->scale[j];
        }
        nv = fmax(nv, rv), nw = fmax(nw, rw);
    }
    return nv * nw;
}

/* An eigenvector's length is dgeev's choice (unit 2-norm), and with modes of far apart speeds (a
 * diaphragm of a few grams per metre: 1e7 rad/s beside the walls' 5) it leaves a slow mode's column
 * of Vr large and its row of Winv small, and their norms' product (the condition) a billion where
 * the basis is a few thousand. Each mode's column and row are scaled by the power of 2 that balances
 * them: the coordinates' arithmetic is the same to the bit, and the condition the basis's own. */
static void balance_modes(const sx_region *r, const double *wi, const int *blocked, double *Vr, double *Winv)
{
    const int n = r->n;
    int i, j, k;
    for (j = 0; j < n; j++) {
        const int last = j + (wi[j] != 0.0 || blocked[j] == 1); /* a pair's or block's columns take one scale */
        double col = 0.0, row = 0.0, d;
        for (k = j; k <= last; k++)
            for (i = 0; i < n; i++) {
                col = fmax(col, fabs(Vr[i * n + k]) / r->scale[i]);
                row = fmax(row, fabs(Winv[k * n + i]) * r->scale[i]);
            }
        d = col > 0.0 && row > 0.0 ? ldexp(1.0, (int)lround(0.5 * log2(row / col))) : 1.0;
        for (k = j; k <= last; k++)
            for (i = 0; i < n; i++) {
                Vr[i * n + k] *= d;
                Winv[k * n + i] /= d;
            }
        j = last;
    }
}

/* the modal forcing of a column of Aa (the constant's or ag's) */
static void modal_forcing(const sx_region *r, const sx_modes *m, int col, double complex *g)
{
    const int n = r->n;
    double y[SX_MAX_N], v[SX_MAX_N];
    int k;
    for (k = 0; k < n; k++) v[k] = r->Aa[k * r->na + col];
    sx_matvec_cols(n, n, m->Winv_cols, v, y);
    for (k = 0; k < m->count; k++)
        g[k] = m->pair[k] ? y[m->first[k]] - I * y[m->first[k] + 1] : y[m->first[k]];
}

static void shares(const sx_region *r, sx_modes *m, const double *Vr)
{
    const int n = r->n;
    int f, k, i;
    for (f = 0; f < r->nf; f++)
        for (k = 0; k < m->count; k++) {
            double re = 0.0, im = 0.0;
            for (i = 0; i < n; i++) {
                re += r->F[f][i] * Vr[i * n + m->first[k]];
                if (m->pair[k]) im += r->F[f][i] * Vr[i * n + m->first[k] + 1];
            }
            m->share_re[k][f] = re, m->share_im[k][f] = im, m->share_abs[k][f] = sqrt(re * re + im * im);
        }
}

/* Winv = Vr^-1, both balanced, and their condition: 0, or 1 if Vr is singular */
static int inverse_basis(const sx_region *r, const double *wi, const int *blocked, double *Vr, double *Winv,
                         double *cond)
{
    const int n = r->n;
    double LU[SX_MAX_N * SX_MAX_N];
    int i, j;
    memcpy(LU, Vr, sizeof(double) * (size_t)(n * n));
    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++) Winv[i * n + j] = i == j;
    if (sx_lu_solve(n, LU, Winv, n)) return 1;
    balance_modes(r, wi, blocked, Vr, Winv);
    *cond = condition(r, Vr, Winv);
    return 0;
}

/* mode k from column i (a real eigenvalue, a complex pair, or a block: its two columns as a
 * pair's): the column the next mode starts after */
static int add_mode(const sx_region *r, sx_modes *m, int i, const double *wr, const double *wi, const int *blocked,
                    const double *Vr, const double *Winv)
{
    const int k = m->count++;
    m->first[k] = i;
    m->pair[k] = wi[i] != 0.0 || blocked[i];
    m->block[k] = blocked[i] != 0;
    m->blocks += m->block[k];
    if (m->block[k]) {
        double *B = m->B[k];
        sx_block_matrix(r, Vr, Winv, i, B);
        m->lam[k] = m->inv_lam[k] = 0.0; /* bounded as a slow mode is, with ||B|| (Frobenius) for |lam| */
        m->abs_lam[k] = m->growth[k] = sqrt(B[0] * B[0] + B[1] * B[1] + B[2] * B[2] + B[3] * B[3]);
        return i + 1;
    }
    m->lam[k] = wr[i] + I * wi[i]; /* the first of a pair has the positive imaginary part */
    m->inv_lam[k] = m->lam[k] != 0.0 ? 1.0 / m->lam[k] : 0.0;
    m->abs_lam[k] = hypot(wr[i], wi[i]);
    m->growth[k] = wr[i] > 0.0 ? wr[i] : 0.0;
    return m->pair[k] ? i + 1 : i;
}

void sx_modes_build(sx_region *r)
{
    sx_modes *m = &r->modes;
    const int n = r->n;
    double wr[SX_MAX_N], wi[SX_MAX_N], Vr[SX_MAX_N * SX_MAX_N], Winv[SX_MAX_N * SX_MAX_N];
    int blocked[SX_MAX_N] = {0}, i;
    memset(m, 0, sizeof *m);
    if (decompose(r, wr, wi, Vr) || inverse_basis(r, wi, blocked, Vr, Winv, &m->cond)) return;
    /* nearly defective pairs as blocks, the worst first, while the basis is too ill-conditioned */
    while (!(m->cond < SX_MODES_COND) && sx_block_worst_pair(r, wr, wi, blocked, Vr, Winv))
        if (inverse_basis(r, wi, blocked, Vr, Winv, &m->cond)) return;
    if (!(m->cond < SX_MODES_COND)) return;
    sx_transpose(n, n, Winv, m->Winv_cols);
    for (i = 0; i < n; i++) i = add_mode(r, m, i, wr, wi, blocked, Vr, Winv);
    modal_forcing(r, m, r->n + 2, m->g0);
    modal_forcing(r, m, r->n, m->g1);
    shares(r, m, Vr);
    if (m->blocks) sx_block_coupling(r, Vr, Winv, m);
    m->valid = 1;
}

void sx_modes_adopt(sx_region *r, const sx_modes *of)
{
    r->modes = *of;
    modal_forcing(r, &r->modes, r->n + 2, r->modes.g0);
}

/* one mode over a step in u = tau/h: its part of a functional's polynomial (c[0..2], times the
 * share), and what bounds the rest (the slow mode's cubic remainder, or the fast mode's free
 * oscillation), for the value and for its rate */
typedef struct {
    double complex c[3];
    double bound, dbound;
} mode_step;

static double mag(double complex z) { return sqrt(creal(z) * creal(z) + cimag(z) * cimag(z)); }

/* |Re z| + |Im z| >= |z|: a size for the margins, without a square root */
static double size_of(double complex z) { return fabs(creal(z)) + fabs(cimag(z)); }

/* a slow mode's quadratic z0 + d1 tau + d2 tau^2/2 over the step and its remainder, from wh = the
 * mode's rate times h and grow = its growth over the step */
static mode_step quadratic(double complex z0, double complex d1, double complex d2, double wh, double grow, double h)
{
    const double r3 = wh * mag(d2) * grow * h * h;
    mode_step s;
    s.c[0] = z0;
    s.c[1] = d1 * h;
    s.c[2] = 0.5 * d2 * h * h;
    s.bound = r3 * (1.0 / 6.0);
    s.dbound = 0.5 * r3;
    return s;
}

/* The two ways to bound a mode over a step, whichever is tighter: a fast mode's quasi-static part
 * (exact while the input is linear) with its free oscillation, which keeps its size (times the
 * growth e^(Re lam h)) as a band; a slow mode's quadratic z0 + z'(0) tau + z''(0) tau^2/2 with the
 * remainder |lam| |z''(0)| e^(max(Re lam, 0) h) tau^3/6 (z''' = lam z'' while the input is linear). */
static mode_step mode_over(const sx_modes *m, int k, double complex z0, double ag0, double slope, double h)
{
    const double complex lam = m->lam[k], b0 = m->g0[k] + m->g1[k] * ag0, b1 = m->g1[k] * slope;
    const double grow = m->growth[k] > 0.0 ? exp(m->growth[k] * h) : 1.0, wh = m->abs_lam[k] * h;
    const double complex d1 = lam * z0 + b0, d2 = lam * d1 + b1;
    mode_step s = quadratic(z0, d1, d2, wh, grow, h);
    if (wh > 0.5) {
        const double complex il = m->inv_lam[k], qs = -(b0 + b1 * il) * il;
        const double band = mag(z0 - qs) * grow;
        if (band < s.bound) {
            s.c[0] = qs;
            s.c[1] = -b1 * il * h;
            s.c[2] = 0.0;
            s.bound = band;
            s.dbound = band * wh;
        }
    }
    return s;
}

/* a block over the step: y' = B y + b0 + b1 t in its two real coordinates (z = y_a - i y_b, as a
 * pair's), its quadratic in time with the remainder ||B|| ||y''(0)|| e^(||B|| h) tau^3/6 in the
 * 2-norm (y^(3) = B y'' while the input is linear), which bounds each functional's share through
 * the share's modulus as a pair's does */
static double complex apply_block(const double B[4], double complex z)
{
    const double a = creal(z), b = -cimag(z);
    return (B[0] * a + B[1] * b) - I * (B[2] * a + B[3] * b);
}

static mode_step block_over(const sx_modes *m, int k, double complex z0, double ag0, double slope, double h)
{
    const double complex b0 = m->g0[k] + m->g1[k] * ag0, b1 = m->g1[k] * slope;
    const double complex d1 = apply_block(m->B[k], z0) + b0, d2 = apply_block(m->B[k], d1) + b1;
    return quadratic(z0, d1, d2, m->abs_lam[k] * h, exp(m->abs_lam[k] * h), h);
}

/* the largest size the blocks' coordinates reach over the step, summed over the blocks */
static double blocks_reach(const sx_modes *m, const double y[], double ag0, double slope, double h)
{
    double reach = 0.0;
    int k;
    for (k = 0; k < m->count; k++)
        if (m->block[k]) {
            const mode_step s = block_over(m, k, y[m->first[k]] - I * y[m->first[k] + 1], ag0, slope, h);
            reach += size_of(s.c[0]) + size_of(s.c[1]) + size_of(s.c[2]) + s.bound;
        }
    return reach;
}

/* mode k driven by the blocks' rounding (a force of at most coupling x reach): what that adds to
 * its motion over the step, and to its rate */
static void driven(const sx_modes *m, int k, double reach, double h, mode_step *s)
{
    const double force = m->coupling[k] * reach, grow = m->growth[k] > 0.0 ? exp(m->growth[k] * h) : 1.0;
    s->bound += force * h * grow;
    s->dbound += force * (1.0 + m->abs_lam[k] * h) * grow;
}

int sx_modes_polys(const sx_region *r, double h, const double xa0[], sx_lopoly P[SX_MAX_F])
{
    const sx_modes *m = &r->modes;
    const double ag0 = xa0[r->n], slope = xa0[r->n + 1];
    double y[SX_MAX_N], size[SX_MAX_F], c0[SX_MAX_F], c1[SX_MAX_F], c2[SX_MAX_F], tail[SX_MAX_F], dtail[SX_MAX_F];
    const int nf = r->nf;
    double reach = 0.0;
    int f, k;
    if (!m->valid) return 0;
    sx_matvec_cols(r->n, r->n, m->Winv_cols, xa0, y);
    if (m->blocks) reach = blocks_reach(m, y, ag0, slope, h);
    for (f = 0; f < nf; f++) { /* the functionals' own terms in ag and the constant */
        c0[f] = r->F[f][r->n] * ag0 + r->F[f][r->n + 2];
        c1[f] = r->F[f][r->n] * slope * h;
        c2[f] = 0.0, tail[f] = 0.0, dtail[f] = 0.0;
        size[f] = fabs(c0[f]) + fabs(c1[f]);
    }
    for (k = 0; k < m->count; k++) {
        const double complex z0 = m->pair[k] ? y[m->first[k]] - I * y[m->first[k] + 1] : y[m->first[k]];
        mode_step s = m->block[k] ? block_over(m, k, z0, ag0, slope, h) : mode_over(m, k, z0, ag0, slope, h);
        if (m->blocks) driven(m, k, reach, h, &s);
        const double cr0 = creal(s.c[0]), cr1 = creal(s.c[1]), cr2 = creal(s.c[2]);
        const double ci0 = cimag(s.c[0]), ci1 = cimag(s.c[1]), ci2 = cimag(s.c[2]);
        const double mode_size = size_of(s.c[0]) + size_of(s.c[1]) + size_of(s.c[2]) + s.bound;
        const double *ar = m->share_re[k], *ai = m->share_im[k], *abs_a = m->share_abs[k];
        for (f = 0; f < nf; f++) { /* Re(a c) in real arithmetic: this loop runs for every step */
            c0[f] += ar[f] * cr0 - ai[f] * ci0;
            c1[f] += ar[f] * cr1 - ai[f] * ci1;
            c2[f] += ar[f] * cr2 - ai[f] * ci2;
            tail[f] += abs_a[f] * s.bound;
            dtail[f] += abs_a[f] * s.dbound;
            size[f] += abs_a[f] * mode_size;
        }
    }
    for (f = 0; f < nf; f++) {
        sx_lopoly *p = &P[f];
        p->coef[0] = c0[f], p->coef[1] = c1[f], p->coef[2] = c2[f];
        p->tail = tail[f] + (SX_MODES_MARGIN(m->cond) * size[f] + DBL_MIN);
        p->dtail = dtail[f] + (SX_MODES_MARGIN(m->cond) * size[f] + DBL_MIN);
        p->deg = 2;
    }
    return 1;
}
