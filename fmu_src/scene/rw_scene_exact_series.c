/* The exact propagators of a region: the Taylor series of the augmented state over a step, and a
 * step length's tables (exp(Aa h), the quiet test's polynomial rows and tail, the work integrals)
 * built once per region and length. A step is at most SX_RHO / ||A_s|| long (A_s the balanced
 * first-order matrix), so that the series' terms fall at least as fast as rho^k / k! in the
 * balanced norm: no cancellation, and a tail bounded by its first term (docs/scenes.md). */
#include "rw_scene_exact_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define SX_SERIES_REL 1e-19 /* the series stops where its terms are this small against the largest */

double sx_hmax(const sx_region *r)
{
    return fmin(r->norm > 0.0 ? SX_RHO / r->norm : INFINITY, r->hcap);
}

/* max_i |v_i| / S_i over the first-order states */
static double scaled_norm(const sx_region *r, const double *v)
{
    double m = 0.0;
    int i;
    for (i = 0; i < r->n; i++) { /* (the scales are powers of 2: their inverses are exact) */
        const double a = fabs(v[i]) * r->inv_scale[i];
        m = a > m ? a : m;
    }
    return m;
}

/* the degree at which rho^(k+1)/(k+1)! (the matrix series' tail in the S norm) is negligible */
static int matrix_degree(double rho)
{
    double term = rho;
    int k = 0;
    while (k < SX_MAX_DEG && term > SX_SERIES_REL) {
        k++;
        term *= rho / (k + 1);
    }
    return k < SX_LO + 1 ? SX_LO + 1 : k;
}

int sx_parts(const sx_region *r, double length)
{
    const int n = (int)ceil(length / sx_hmax(r) * (1.0 - 1e-12));
    return n > 1 ? n : 1;
}

void sx_series_at(const sx_region *r, const sx_series *s, double u, double xa[])
{
    const int na = r->na;
    int k, j;
    for (k = 0; k < na; k++) xa[k] = 0.0;
    for (j = s->deg; j >= 0; j--) { /* Horner's rule, every entry at once */
        const double *X = s->X + (size_t)j * (size_t)na;
        for (k = 0; k < na; k++) xa[k] = xa[k] * u + X[k];
    }
}

/* y = Aa x: the velocities' rows in full, the others one entry of x each (the displacements' rates
 * are the velocities, ag's is its slope, a z chain's each the next; the slope's and the constant's
 * rows are zero), the same sums as the whole product's */
static void aa_times(const sx_region *r, const double *x, double *y)
{
    int i;
    if (!r->one_hot) {
        sx_matvec_cols(r->na, r->na, r->Aa_cols, x, y);
        return;
    }
    sx_matvec_lead(r->ndof, r->na, r->na, r->Aa_cols + r->ndof, x, y + r->ndof);
    for (i = 0; i < r->ndof; i++) y[i] = x[r->hot[i]];
    for (i = r->n; i < r->na; i++) y[i] = r->hot[i] >= 0 ? x[r->hot[i]] : 0.0;
}

void sx_series_of(const sx_region *r, const double xa0[], double L, sx_series *s)
{
    const int na = r->na;
    const double rho = r->norm * L;
    double biggest = scaled_norm(r, xa0), nk = 0.0;
    int k;
    memcpy(s->X, xa0, sizeof(double) * (size_t)na);
    s->L = L;
    for (k = 0; k < SX_MAX_DEG; k++) {
        double *next = s->X + (size_t)(k + 1) * (size_t)na;
        int i;
        aa_times(r, s->X + (size_t)k * (size_t)na, next);
        for (i = 0; i < na; i++) next[i] *= L / (k + 1);
        nk = scaled_norm(r, next);
        if (nk > biggest) biggest = nk;
        /* from degree 2 on the inputs' entries are zero: the rest of the series is A's alone */
        if (k + 1 >= 3 && nk <= SX_SERIES_REL * biggest && rho < k + 2) break;
    }
    s->deg = k; /* X_{k+1} is the tail's first term, not part of the polynomial */
    s->tail = rho < s->deg + 2 ? nk / (1.0 - rho / (s->deg + 2)) : INFINITY;
}

/* rows r_{k+1} = h/(k+1) r_k Aa of a row vector r_0 over xa */
static void row_step(const sx_region *r, const double *rk, int k, double h, double *next)
{
    const int na = r->na;
    int i, j;
    for (j = 0; j < na; j++) next[j] = 0.0;
    for (i = 0; i < na; i++) {
        const double v = rk[i];
        if (v == 0.0) continue;
        for (j = 0; j < na; j++) next[j] += v * r->Aa[i * na + j];
    }
    for (j = 0; j < na; j++) next[j] *= h / (k + 1);
}

/* C = A B (na x na), a row of C at a time as a sum of B's rows: each entry's sum runs over l in
 * order as a dot product would, and the inner loop runs along rows (the compiler vectorises it).
 * A zero of A adds nothing and is skipped: half of Aa's rows (x's displacements) hold one 1. */
static void matmul(int na, const double *A, const double *B, double *C)
{
    int i, j, l;
    for (i = 0; i < na; i++) {
        double *c = C + i * na;
        for (j = 0; j < na; j++) c[j] = 0.0;
        for (l = 0; l < na; l++) {
            const double a = A[i * na + l], *b = B + l * na;
            if (a == 0.0) continue;
            for (j = 0; j < na; j++) c[j] += a * b[j];
        }
    }
}

/* C = A B (add: C += A B) for a dense A given by columns (At, na x na), a column of C at a time
 * through the products' kernels (sx_matvec_cols): each entry's sum runs over l in order, as in
 * matmul (whose skipped zeros add nothing), so the bits are matmul's, in about a quarter of its
 * instructions where A has few zeros (4 000 against 17 600 for the house's doublings) */
static void dense_product(int na, const double *At, const double *B, double *C, int add)
{
    double b[SX_MAX_NA], c[SX_MAX_NA];
    int i, j;
    for (j = 0; j < na; j++) {
        for (i = 0; i < na; i++) b[i] = B[i * na + j];
        sx_matvec_cols(na, na, At, b, c);
        for (i = 0; i < na; i++) C[i * na + j] = add ? C[i * na + j] + c[i] : c[i];
    }
}

/* the square of a dense E (na x na) into E2 */
static void square(int na, const double *E, double *E2)
{
    double Et[SX_MAX_NA * SX_MAX_NA];
    sx_transpose(na, na, E, Et);
    dense_product(na, Et, E, E2, 0);
}

/* E = sum_k (Aa h)^k/k!, and T = the x rows of the term SX_LO+1 */
static void exponential(const sx_region *r, sx_step *st)
{
    const int na = r->na;
    double B[SX_MAX_NA * SX_MAX_NA], Bn[SX_MAX_NA * SX_MAX_NA];
    int i, k;
    memset(B, 0, sizeof(double) * (size_t)(na * na));
    for (i = 0; i < na; i++) B[i * na + i] = 1.0;
    memcpy(st->E, B, sizeof(double) * (size_t)(na * na));
    for (k = 0; k < st->deg; k++) {
        matmul(na, r->Aa, B, Bn);
        for (i = 0; i < na * na; i++) B[i] = Bn[i] * st->h / (k + 1);
        for (i = 0; i < na * na; i++) st->E[i] += B[i];
        if (k + 1 == SX_LO + 1) sx_transpose(r->n, na, B, st->T);
    }
}

/* chain k's rate row e_k (its diaphragm's deformation rate over xa) */
static void rate_row(const sx_region *r, int k, double *row)
{
    const int i = r->z_storey[k], nd = r->ndof;
    memset(row, 0, sizeof(double) * (size_t)r->na);
    row[nd + r->diaph_dof[i]] = 1.0;
    if (r->floor_dof[i] >= 0) row[nd + r->floor_dof[i]] = -1.0;
}

/* the integrals of tau^m e_k.exp(Aa tau) over [0, h], m = 0, 1, 2: sum over the series' terms
 * r_n = e_k.(Aa h)^n/n! of r_n h^(m+1) / (n + m + 1) */
static void z_work_rows(const sx_region *r, sx_step *st, int k)
{
    const int na = r->na;
    const double hp[3] = {st->h, st->h * st->h, st->h * st->h * st->h};
    double cur[SX_MAX_NA], next[SX_MAX_NA], *w = st->zwork + (size_t)(3 * k * na);
    int n, m, c;
    rate_row(r, k, cur);
    memset(w, 0, sizeof(double) * (size_t)(3 * na));
    for (n = 0; n <= st->deg; n++) {
        for (m = 0; m < 3; m++)
            for (c = 0; c < na; c++) w[m * na + c] += cur[c] * hp[m] / (n + m + 1);
        row_step(r, cur, n, st->h, next);
        memcpy(cur, next, sizeof(double) * (size_t)na);
    }
}

/* each z chain's diaphragm deformation rate at the nodes u = (j+1)/4, its row times exp(Aa u h)
 * summed to the table's degree (u h is no longer than h), and its work rows */
static void z_rows(const sx_region *r, sx_step *st)
{
    const int na = r->na;
    double cur[SX_MAX_NA], next[SX_MAX_NA];
    int k, j, m, c;
    for (k = 0; k < r->nz; k++) {
        z_work_rows(r, st, k);
        for (j = 0; j < SX_Z_NODES; j++) {
            double *out = st->zrows + (size_t)((k * SX_Z_NODES + j) * na);
            const double uh = st->h * (j + 1) / SX_Z_NODES;
            rate_row(r, k, cur);
            memcpy(out, cur, sizeof(double) * (size_t)na);
            for (m = 0; m < st->deg; m++) {
                row_step(r, cur, m, uh, next);
                for (c = 0; c < na; c++) out[c] += next[c];
                memcpy(cur, next, sizeof(double) * (size_t)na);
            }
        }
    }
}

/* the functionals' rows l.(Aa h)^k/k! for k <= SX_LO (the quiet test's polynomials where the region
 * has no modes to bound with: low_polys), and the momentum's work integrals */
static void rows(const sx_region *r, sx_step *st)
{
    const int na = r->na, D = SX_LO + 1;
    double cur[SX_MAX_NA], next[SX_MAX_NA], by_rows[SX_MAX_F * (SX_LO + 1) * SX_MAX_NA];
    int f, k, j;
    for (f = 0; f < r->nf && !r->modes.valid; f++) { /* (the Taylor rows of regions without modes only) */
        double *out = by_rows + (size_t)f * (size_t)(D * na);
        memcpy(out, r->F[f], sizeof(double) * (size_t)na);
        for (k = 0; k < SX_LO; k++) row_step(r, out + k * na, k, st->h, out + (k + 1) * na);
    }
    if (!r->modes.valid) sx_transpose(r->nf * D, na, by_rows, st->rows);
    z_rows(r, st);
    memcpy(cur, r->mom, sizeof(double) * (size_t)na);
    memset(st->wg, 0, sizeof(double) * (size_t)(2 * na));
    for (k = 0; k <= st->deg; k++) {
        for (j = 0; j < na; j++) {
            st->wg[j] += st->h * cur[j] / (k + 1);
            st->wg[na + j] += st->h * st->h * cur[j] / (k + 2);
        }
        row_step(r, cur, k, st->h, next);
        memcpy(cur, next, sizeof(double) * (size_t)na);
    }
}

/* Wd = h sum_t c_t sum_{j,k} r_tj r_tk^T / (j+k+1), r_tk = d_t.(Aa h)^k/k!: the integral over the
 * step of the dissipation rate sum_t c_t (d_t . xa)^2 along xa(tau) = E(tau) xa0 */
static void dissipation(const sx_region *r, sx_step *st)
{
    const int na = r->na, D = st->deg + 1;
    double R[(SX_MAX_DEG + 1) * SX_MAX_NA], P[SX_MAX_NA], inv[2 * (SX_MAX_DEG + 1)];
    int t, j, k, a, b;
    for (k = 0; k < 2 * D; k++) inv[k] = 1.0 / (k + 1); /* 1/(j+k+1): a product, not a division, per entry */
    memset(st->Wd, 0, sizeof(double) * (size_t)(na * na));
    for (t = 0; t < r->nterms; t++) {
        memcpy(R, r->dvec[t], sizeof(double) * (size_t)na);
        for (k = 0; k + 1 < D; k++) row_step(r, R + k * na, k, st->h, R + (k + 1) * na);
        for (k = 0; k < D; k++) {
            const double *rk = R + k * na;
            for (a = 0; a < na; a++) P[a] = 0.0;
            for (j = 0; j < D; j++)
                for (a = 0; a < na; a++) P[a] += R[j * na + a] * inv[j + k];
            for (a = 0; a < na; a++) {
                const double v = r->dcoef[t] * st->h * rk[a];
                if (v == 0.0) continue;
                for (b = 0; b < na; b++) st->Wd[a * na + b] += v * P[b];
            }
        }
    }
}

/* the table of 2h from that of h: E(2h) = E E, Wd(2h) = Wd + E^T Wd E, and the momentum's
 * integrals w0(2h) = w0 + w0 E, w1(2h) = w1 + (w1 + h w0) E (the semigroup E(tau + h) = E(tau) E(h)) */
static void doubled(const sx_region *r, sx_step *st)
{
    const int na = r->na;
    double T1[SX_MAX_NA * SX_MAX_NA], T2[SX_MAX_NA * SX_MAX_NA], w[SX_MAX_NA];
    int i, j;
    sx_transpose(na, na, st->Wd, T2);
    dense_product(na, T2, st->E, T1, 0);      /* T1 = Wd E */
    dense_product(na, st->E, T1, st->Wd, 1); /* Wd += E^T T1 (E by rows is E^T by columns) */
    for (j = 0; j < na; j++) w[j] = st->wg[na + j] + st->h * st->wg[j];
    for (j = 0; j < na; j++) {
        double v0 = 0.0, v1 = 0.0;
        for (i = 0; i < na; i++) v0 += st->wg[i] * st->E[i * na + j], v1 += w[i] * st->E[i * na + j];
        T1[j] = v0, T2[j] = v1;
    }
    for (j = 0; j < na; j++) st->wg[j] += T1[j], st->wg[na + j] += T2[j];
    square(na, st->E, T1);
    memcpy(st->E, T1, sizeof(double) * (size_t)(na * na));
    st->h *= 2.0;
}

int sx_step_fits(const sx_step *st, double h, double tol)
{
    return st->h > 0.0 && fabs(st->h - h) <= (1e-12 * h > tol ? 1e-12 * h : tol);
}

/* the slot of length h, the one found last first (most steps are a record interval's) */
static sx_step *cached(sx_region *r, double h, double tol)
{
    int k;
    if (sx_step_fits(&r->step[r->last_step], h, tol)) return &r->step[r->last_step];
    for (k = 0; k < SX_STEPS; k++)
        if (sx_step_fits(&r->step[k], h, tol)) return &r->step[r->last_step = k];
    return NULL;
}

/* a copy of the table of h/2 doubled (E, Wd, wg: what a long table holds) */
static void from_half(const sx_region *r, const sx_step *half, sx_step *st)
{
    const size_t nn = (size_t)(r->na * r->na);
    memcpy(st->E, half->E, sizeof(double) * nn);
    memcpy(st->Wd, half->Wd, sizeof(double) * nn);
    memcpy(st->wg, half->wg, sizeof(double) * (size_t)(2 * r->na));
    st->h = half->h;
    st->rho = half->rho;
    st->deg = half->deg;
    st->is_long = 1;
    doubled(r, st);
}

/* a slot's memory, the first time it is built: E, Wd, Et (na x na), Wdp (na columns of padded(na)),
 * T (n x na), wg (2 x na), rows (nf (SX_LO+1) x na), zrows (nz SX_Z_NODES x na), zwork (3 nz x na);
 * 0, or 1 if none could be had */
static int table_memory(const sx_region *r, sx_step *st)
{
    const size_t nn = (size_t)(r->na * r->na);
    if (st->mem) return 0;
    st->mem = (double *)sx_pool_alloc(sizeof(double) *
                               (4 * nn + (size_t)((r->n + 2 + r->nf * (SX_LO + 1) + r->nz * (SX_Z_NODES + 3) + 3) * r->na)));
    if (!st->mem) return 1;
    st->E = st->mem, st->Wd = st->E + nn, st->Et = st->Wd + nn, st->Wdp = st->Et + nn;
    st->T = st->Wdp + nn + 3 * r->na; /* Wdp's rows padded to a multiple of 4 */
    st->wg = st->T + r->n * r->na;
    st->rows = st->wg + 2 * r->na;
    st->zrows = st->rows + r->nf * (SX_LO + 1) * r->na;
    st->zwork = st->zrows + r->nz * SX_Z_NODES * r->na;
    return 0;
}

/* the rows a matrix by columns is padded to (a multiple of 4, for sx_matvec_lead's blocks) */
static int padded(int n) { return (n + 3) & ~3; }

/* W by columns, each padded with zeros to padded(n) rows */
static void padded_cols(int n, const double *W, double *Wc)
{
    const int ld = padded(n);
    int i, j;
    for (j = 0; j < n; j++)
        for (i = 0; i < ld; i++) Wc[j * ld + i] = i < n ? W[i * n + j] : 0.0;
}

void sx_step_propagate(const sx_region *r, const sx_step *st, const double xa0[], double xa1[])
{
    const int n = r->n;
    if (r->nz) {
        sx_matvec_cols(r->na, r->na, st->Et, xa0, xa1);
        return;
    }
    sx_matvec_lead(n, r->na, r->na, st->Et, xa0, xa1); /* E's first n rows */
    xa1[n] = xa0[n] + st->h * xa0[n + 1];
    xa1[n + 1] = xa0[n + 1];
    xa1[n + 2] = xa0[n + 2];
}

double sx_step_dissipation(const sx_region *r, const sx_step *st, const double xa0[])
{
    double Wx[SX_MAX_NA + 3];
    sx_matvec_lead(padded(r->na), r->na, padded(r->na), st->Wdp, xa0, Wx);
    return sx_dot(xa0, Wx, r->na);
}

/* The table of length h: cached (a length within tol, the rounding of the record's times, is the
 * same), or built. A step longer than the series converge over is the table of h/2 doubled (itself
 * cached, so that the halves of a slow step find theirs ready). */
sx_step *sx_step_of(sx_region *r, double h, double tol, long stamp)
{
    sx_step *st = cached(r, h, tol), *half = NULL;
    int k;
    if (st) return (st->used = stamp), st;
    if (r->norm * h > SX_RHO * (1.0 + 1e-12)) {
        if (!(half = sx_step_of(r, 0.5 * h, 0.5 * tol, stamp))) return NULL;
        half->used = stamp + 1; /* not the slot this one takes */
    }
    for (k = 0; k < SX_STEPS; k++)
        if (!st || r->step[k].used < st->used) st = &r->step[k];
    if (table_memory(r, st)) return NULL;
    if (half) {
        half->used = stamp;
        from_half(r, half, st);
    } else {
        st->h = h;
        st->is_long = 0;
        st->rho = r->norm * h;
        st->deg = matrix_degree(st->rho);
        exponential(r, st);
        rows(r, st);
        dissipation(r, st);
    }
    sx_transpose(r->na, r->na, st->E, st->Et);
    padded_cols(r->na, st->Wd, st->Wdp);
    if (r->modes.valid) {
        sx_hermite_step_of(r, h, &st->herm);
        sx_hermite_step_of(r, SX_WINDOW * h, &st->herm_w);
        sx_kink_of(r, &st->herm_w, st->kink_modes, st->kink_record);
    }
    st->used = stamp;
    st->h = h;
    return st;
}

int sx_halves_of(sx_region *r, double h, int levels, double tol, long stamp, double *Et)
{
    const int na = r->na;
    const size_t nn = (size_t)(na * na);
    double E[SX_MAX_NA * SX_MAX_NA], E2[SX_MAX_NA * SX_MAX_NA];
    const sx_step *st = sx_step_of(r, ldexp(h, -levels), ldexp(tol, -levels), stamp);
    int k;
    if (!st) return 1;
    memcpy(E, st->E, sizeof(double) * nn);
    sx_transpose(na, na, E, Et + (size_t)levels * nn);
    for (k = levels - 1; k >= 0; k--) { /* squared as a long table's E is (doubled) */
        square(na, E, E2);
        memcpy(E, E2, sizeof(double) * nn);
        sx_transpose(na, na, E, Et + (size_t)k * nn);
    }
    return 0;
}
