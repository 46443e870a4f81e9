/* A region's modes, which bound the motion between a step's exact ends (rw_scene_exact_hermite.c):
 * the eigen-decomposition of A (LAPACK's dgeev) with its basis balanced, each mode's modal forcing
 * by the record and the constant, and each functional's share of each mode. Where the basis is
 * too ill-conditioned to bound with, its nearly defective pairs are kept as blocks
 * (rw_scene_exact_blocks.c). The motion stays exp(Aa h)'s: the modes only bound it. */
#include "rw_scene_exact_internal.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* LAPACK: eigenvalues and right eigenvectors of a general real matrix (column-major) */
extern void dgeev_(const char *jobvl, const char *jobvr, const int *n, double *a, const int *lda, double *wr,
                   double *wi, double *vl, const int *ldvl, double *vr, const int *ldvr, double *work, const int *lwork,
                   int *info);

#define SX_MODES_COND 1e8 /* a decomposition worse conditioned than this bounds nothing */

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

/* the particular parts' sizes per unit of the record and its slope, from the modal forcing */
static void particular_sizes(sx_modes *m)
{
    int k;
    for (k = 0; k < m->count; k++) {
        const double il = m->abs_lam[k] > 0.0 && !m->block[k] ? 1.0 / m->abs_lam[k] : 0.0;
        m->pb0[k] = cabs(m->g0[k]) * il;
        m->pb1[k] = cabs(m->g1[k]) * il;
        m->pb2[k] = cabs(m->g1[k]) * il * il;
    }
}

static void shares(const sx_region *r, sx_modes *m, const double *Vr)
{
    const int n = r->n;
    int f, k, i;
    for (f = 0; f < r->nf; f++)
        for (m->share_max[f] = 0.0, k = 0; k < m->count; k++) {
            double re = 0.0, im = 0.0;
            for (i = 0; i < n; i++) {
                re += r->F[f][i] * Vr[i * n + m->first[k]];
                if (m->pair[k]) im += r->F[f][i] * Vr[i * n + m->first[k] + 1];
            }
            m->share_re[k][f] = re, m->share_im[k][f] = im, m->share_abs[k][f] = sqrt(re * re + im * im);
            m->share_re[k][r->nf] = m->share_im[k][r->nf] = m->share_abs[k][r->nf] = 0.0; /* (the pairs' pad) */
            m->share_max[f] = fmax(m->share_max[f], m->share_abs[k][f]);
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
    m->count = m->blocks = m->valid = 0; /* (the arrays are filled for the modes and functionals there are) */
    if (decompose(r, wr, wi, Vr) || inverse_basis(r, wi, blocked, Vr, Winv, &m->cond)) return;
    /* nearly defective pairs as blocks, the worst first, while the basis is too ill-conditioned */
    while (!(m->cond < SX_MODES_COND) && sx_block_worst_pair(r, wr, wi, blocked, Vr, Winv))
        if (inverse_basis(r, wi, blocked, Vr, Winv, &m->cond)) return;
    if (!(m->cond < SX_MODES_COND)) return;
    sx_transpose(n, n, Winv, m->Winv_cols);
    for (i = 0; i < n; i++) i = add_mode(r, m, i, wr, wi, blocked, Vr, Winv);
    modal_forcing(r, m, r->n + 2, m->g0);
    modal_forcing(r, m, r->n, m->g1);
    particular_sizes(m);
    shares(r, m, Vr);
    if (m->blocks) sx_block_coupling(r, Vr, Winv, m);
    m->valid = 1;
}

void sx_modes_adopt(sx_region *r, const sx_modes *of)
{
    r->modes = *of;
    modal_forcing(r, &r->modes, r->n + 2, r->modes.g0);
    particular_sizes(&r->modes);
}
