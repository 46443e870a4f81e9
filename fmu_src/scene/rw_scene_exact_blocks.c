/* Nearly defective pairs of a region's modes, kept as 2 x 2 blocks. Where both hinges of a wall
 * hold constant moments and its tie holds s2, the mechanism q1 = -q2 has no stiffness: the region's
 * matrix has a double eigenvalue 0 with one eigenvector, which dgeev returns as two real
 * eigenvalues +-sqrt(eps ||A||), or a complex pair, with eigenvectors parallel to 1e-8, and a basis
 * conditioned past anything it can bound with. The pair's invariant subspace itself is well conditioned: it is
 * taken from the two vectors by inverse iteration near the pair's eigenvalues, orthonormalised, and
 * the motion in it is a 2 x 2 system y' = B y + forcing, bounded as a slow mode is
 * (rw_scene_exact_modes.c). Only where the plain basis is too ill-conditioned to use. */
#include "rw_scene_exact_internal.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define REFINE_ITERATIONS 6
/* a mode is nearly defective when its own condition is past this (a sound one's is a few hundred:
 * blocking it would only take its band away) */
#define DEFECTIVE_CONDITION 1e4
/* the plane is taken as invariant when A moves it out of itself by at most this share of ||A||
 * (in the balanced norm): rounding (what is left couples the block to the other modes, and their
 * bounds take it, sx_block_coupling), against a plane that is part of a larger cluster (two walls'
 * mechanisms at once: four eigenvalues at 0) */
#define INVARIANCE_TOL 1e-9

/* columns j..last's largest entry in the balanced norm times rows j..last's of the inverse: the
 * mode's own condition (a pair's jointly: one column may hold the large part and the other row) */
static double own_condition(const sx_region *r, const double *Vr, const double *Winv, int j, int last)
{
    const int n = r->n;
    double col = 0.0, row = 0.0;
    int i, k;
    for (k = j; k <= last; k++)
        for (i = 0; i < n; i++) {
            col = fmax(col, fabs(Vr[i * n + k]) / r->scale[i]);
            row = fmax(row, fabs(Winv[k * n + i]) * r->scale[i]);
        }
    return col * row;
}

/* The mode (not a block yet) whose own condition is the worst: 0 if none, else its column with
 * its partner's. A complex pair is its own (the rounding of a double eigenvalue splits it into a
 * pair as often as into two real ones); a real one's is the nearest real eigenvalue. */
static int worst_pair(const sx_region *r, const double *wr, const double *wi, const int *blocked, const double *Vr,
                      const double *Winv, int *worst, int *partner)
{
    const int n = r->n;
    int j;
    double most = 0.0, nearest = INFINITY;
    *worst = *partner = -1;
    for (j = 0; j < n; j++) {
        const int pair = wi[j] != 0.0;
        const double c = own_condition(r, Vr, Winv, j, j + pair);
        if (!blocked[j] && c > most) most = c, *worst = j, *partner = pair ? j + 1 : -1;
        j += pair;
    }
    if (*worst < 0 || most < DEFECTIVE_CONDITION) return 0;
    if (*partner >= 0) return 1;
    for (j = 0; j < n; j++)
        if (j != *worst && wi[j] == 0.0 && !blocked[j] && fabs(wr[j] - wr[*worst]) < nearest)
            nearest = fabs(wr[j] - wr[*worst]), *partner = j;
    return *partner >= 0;
}

/* the columns a and b moved to the end (the others keep their order, a pair stays adjacent) */
static void move_to_end(int n, int a, int b, double *wr, double *wi, int *blocked, double *Vr)
{
    double V[SX_MAX_N * SX_MAX_N], w_r[SX_MAX_N], w_i[SX_MAX_N];
    int order[SX_MAX_N], bl[SX_MAX_N], i, j, k = 0;
    for (j = 0; j < n; j++)
        if (j != a && j != b) order[k++] = j;
    order[k++] = a, order[k] = b;
    for (j = 0; j < n; j++) {
        w_r[j] = wr[order[j]], w_i[j] = wi[order[j]], bl[j] = blocked[order[j]];
        for (i = 0; i < n; i++) V[i * n + j] = Vr[i * n + order[j]];
    }
    memcpy(wr, w_r, sizeof(double) * (size_t)n), memcpy(wi, w_i, sizeof(double) * (size_t)n);
    memcpy(blocked, bl, sizeof(int) * (size_t)n);
    memcpy(Vr, V, sizeof(double) * (size_t)(n * n));
}

/* the two columns (x, y: n values each) orthonormal in the balanced norm: 0, or 1 if they span
 * less than a plane */
static int orthonormalise(const sx_region *r, double *x, double *y)
{
    const int n = r->n;
    double nx = 0.0, dot = 0.0, ny = 0.0;
    int i;
    for (i = 0; i < n; i++) x[i] /= r->scale[i], y[i] /= r->scale[i];
    for (i = 0; i < n; i++) nx += x[i] * x[i];
    if (!(nx > 0.0)) return 1;
    nx = sqrt(nx);
    for (i = 0; i < n; i++) x[i] /= nx, dot += x[i] * y[i];
    for (i = 0; i < n; i++) y[i] -= dot * x[i], ny += y[i] * y[i];
    if (!(ny > 0.0)) return 1;
    ny = sqrt(ny);
    for (i = 0; i < n; i++) y[i] = y[i] / ny * r->scale[i], x[i] *= r->scale[i];
    return 0;
}

/* The plane of the pair (eigenvalue mean mu) cleared of the other modes: inverse iteration with
 * A - sigma I, sigma off mu by a thousandth of the gap to the nearest other eigenvalue, which
 * takes the pair's share up at least a thousand times against the others' each time */
static int refine(const sx_region *r, const double *wr, const double *wi, int a, double *x, double *y)
{
    const int n = r->n;
    const double mu = 0.5 * (wr[a] + wr[a + 1]);
    double gap = r->norm, sigma;
    int i, j, it;
    for (j = 0; j < n; j++)
        if (j != a && j != a + 1) gap = fmin(gap, hypot(wr[j] - mu, wi[j]));
    sigma = mu + 1e-3 * gap;
    if (orthonormalise(r, x, y)) return 1;
    for (it = 0; it < REFINE_ITERATIONS; it++) {
        double M[SX_MAX_N * SX_MAX_N], X[SX_MAX_N * 2];
        for (i = 0; i < n; i++) {
            for (j = 0; j < n; j++) M[i * n + j] = r->Aa[i * r->na + j] - (i == j ? sigma : 0.0);
            X[2 * i] = x[i], X[2 * i + 1] = y[i];
        }
        if (sx_lu_solve(n, M, X, 2)) return 1;
        for (i = 0; i < n; i++) x[i] = X[2 * i], y[i] = X[2 * i + 1];
        if (orthonormalise(r, x, y)) return 1;
    }
    return 0;
}

/* how far A takes the orthonormal plane (x, y) out of itself, over ||A||, in the balanced norm:
 * the largest entry of S^-1 (A X - X B) with B = X~^T S^-1 A X (X~ = S^-1 X orthonormal) */
static double invariance_residual(const sx_region *r, const double *x, const double *y)
{
    const int n = r->n;
    double AX[SX_MAX_N * 2], B[4] = {0.0, 0.0, 0.0, 0.0}, worst = 0.0;
    int i, j, c;
    for (i = 0; i < n; i++)
        for (c = 0; c < 2; c++) {
            const double *v = c ? y : x;
            double sum = 0.0;
            for (j = 0; j < n; j++) sum += r->Aa[i * r->na + j] * v[j];
            AX[2 * i + c] = sum / r->scale[i];
        }
    for (i = 0; i < n; i++)
        for (c = 0; c < 2; c++) {
            B[c] += x[i] / r->scale[i] * AX[2 * i + c];
            B[2 + c] += y[i] / r->scale[i] * AX[2 * i + c];
        }
    for (i = 0; i < n; i++)
        for (c = 0; c < 2; c++)
            worst = fmax(worst, fabs(AX[2 * i + c] - (x[i] * B[c] + y[i] * B[2 + c]) / r->scale[i]));
    return worst / r->norm;
}

int sx_block_worst_pair(const sx_region *r, double *wr, double *wi, int *blocked, double *Vr, const double *Winv)
{
    const int n = r->n;
    double x[SX_MAX_N], y[SX_MAX_N];
    int worst, partner, i;
    if (!worst_pair(r, wr, wi, blocked, Vr, Winv, &worst, &partner)) return 0;
    move_to_end(n, worst, partner, wr, wi, blocked, Vr);
    for (i = 0; i < n; i++) x[i] = Vr[i * n + n - 2], y[i] = Vr[i * n + n - 1];
    if (refine(r, wr, wi, n - 2, x, y) || !(invariance_residual(r, x, y) <= INVARIANCE_TOL)) return 0;
    for (i = 0; i < n; i++) Vr[i * n + n - 2] = x[i], Vr[i * n + n - 1] = y[i];
    blocked[n - 2] = 1, blocked[n - 1] = 2;
    return 1;
}

void sx_block_matrix(const sx_region *r, const double *Vr, const double *Winv, int a, double B[4])
{
    const int n = r->n;
    double AV[SX_MAX_N * 2];
    int i, j, c;
    for (i = 0; i < n; i++)
        for (c = 0; c < 2; c++) {
            AV[2 * i + c] = 0.0;
            for (j = 0; j < n; j++) AV[2 * i + c] += r->Aa[i * r->na + j] * Vr[j * n + a + c];
        }
    for (i = 0; i < 2; i++)
        for (c = 0; c < 2; c++) {
            B[2 * i + c] = 0.0;
            for (j = 0; j < n; j++) B[2 * i + c] += Winv[(a + i) * n + j] * AV[2 * j + c];
        }
}

void sx_block_coupling(const sx_region *r, const double *Vr, const double *Winv, sx_modes *m)
{
    const int n = r->n;
    int b, k, i, j, c;
    for (k = 0; k < m->count; k++) m->coupling[k] = 0.0;
    for (b = 0; b < m->count; b++) {
        double AX[SX_MAX_N * 2], E[SX_MAX_N * 2];
        if (!m->block[b]) continue;
        for (i = 0; i < n; i++)
            for (c = 0; c < 2; c++) {
                AX[2 * i + c] = 0.0;
                for (j = 0; j < n; j++) AX[2 * i + c] += r->Aa[i * r->na + j] * Vr[j * n + m->first[b] + c];
            }
        for (i = 0; i < n; i++)
            for (c = 0; c < 2; c++) {
                E[2 * i + c] = 0.0;
                for (j = 0; j < n; j++) E[2 * i + c] += Winv[i * n + j] * AX[2 * j + c];
            }
        for (k = 0; k < m->count; k++) {
            double sq = 0.0;
            if (k == b) continue;
            for (i = m->first[k]; i <= m->first[k] + m->pair[k]; i++) sq += E[2 * i] * E[2 * i] + E[2 * i + 1] * E[2 * i + 1];
            m->coupling[k] += sqrt(sq);
        }
    }
}
