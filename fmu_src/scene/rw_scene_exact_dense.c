/* Small dense linear algebra for the exact scene engine (at most 43 x 43): an LU solve with
 * partial pivoting, Osborne's diagonal balancing, a matrix-vector product and the least eigenvalue
 * of a symmetric 2 x 2. Written here rather than taken from LAPACK: these are a few dozen lines and
 * the engine library stays free of a Fortran runtime. */
#include "rw_scene_exact_internal.h"

#include <math.h>
#include <string.h>

static void swap_rows(double *A, int cols, int i, int j)
{
    int k;
    for (k = 0; k < cols; k++) {
        const double v = A[i * cols + k];
        A[i * cols + k] = A[j * cols + k];
        A[j * cols + k] = v;
    }
}

int sx_lu_solve(int n, double *A, double *B, int nrhs)
{
    int i, j, k;
    for (k = 0; k < n; k++) {
        int p = k;
        for (i = k + 1; i < n; i++)
            if (fabs(A[i * n + k]) > fabs(A[p * n + k])) p = i;
        if (!(fabs(A[p * n + k]) > 0.0)) return 1;
        if (p != k) {
            swap_rows(A, n, p, k);
            swap_rows(B, nrhs, p, k);
        }
        for (i = k + 1; i < n; i++) {
            const double m = A[i * n + k] / A[k * n + k];
            if (m == 0.0) continue;
            for (j = k + 1; j < n; j++) A[i * n + j] -= m * A[k * n + j];
            for (j = 0; j < nrhs; j++) B[i * nrhs + j] -= m * B[k * nrhs + j];
        }
    }
    for (k = n - 1; k >= 0; k--)
        for (j = 0; j < nrhs; j++) {
            double v = B[k * nrhs + j];
            for (i = k + 1; i < n; i++) v -= A[k * n + i] * B[i * nrhs + j];
            B[k * nrhs + j] = v / A[k * n + k];
        }
    return 0;
}

/* off-diagonal absolute sums of row i and column i of B */
static void row_col_sums(int n, const double *B, int i, double *r, double *c)
{
    int j;
    *r = *c = 0.0;
    for (j = 0; j < n; j++) {
        if (j == i) continue;
        *r += fabs(B[i * n + j]);
        *c += fabs(B[j * n + i]);
    }
}

/* Osborne's iteration with powers of 2 (exact scaling): S^-1 A S with rows and columns of
 * comparable size, so that its infinity norm is near the spectral radius. */
void sx_balance(int n, const double *A, double *S, double *norm)
{
    double B[SX_MAX_N * SX_MAX_N];
    int i, j, sweep, changed = 1;
    memcpy(B, A, sizeof(double) * (size_t)(n * n));
    for (i = 0; i < n; i++) S[i] = 1.0;
    for (sweep = 0; sweep < 60 && changed; sweep++) {
        changed = 0;
        for (i = 0; i < n; i++) {
            double r, c, f;
            row_col_sums(n, B, i, &r, &c);
            if (!(r > 0.0 && c > 0.0)) continue;
            f = exp2(round(0.5 * log2(r / c)));
            if (f == 1.0 || !(c * f + r / f < 0.95 * (c + r))) continue;
            S[i] *= f;
            for (j = 0; j < n; j++) {
                B[i * n + j] /= f;
                B[j * n + i] *= f;
            }
            changed = 1;
        }
    }
    *norm = 0.0;
    for (i = 0; i < n; i++) {
        double r = 0.0;
        for (j = 0; j < n; j++) r += fabs(B[i * n + j]);
        if (r > *norm) *norm = r;
    }
}

/* rows 0..7 (or 0..3) of y = A x from A by columns (ld apart): their sums held in registers
 * while the columns pass, each one's terms added in the columns' order */
static void rows_8(int ld, int cols, const double *restrict At, const double *restrict x, double *restrict y)
{
    sx_v2 s0 = {0.0, 0.0}, s1 = s0, s2 = s0, s3 = s0;
    int j;
    for (j = 0; j < cols; j++) {
        const double *a = At + (size_t)j * (size_t)ld;
        const sx_v2 xj = {x[j], x[j]};
        s0 += sx_load2(a) * xj, s1 += sx_load2(a + 2) * xj, s2 += sx_load2(a + 4) * xj, s3 += sx_load2(a + 6) * xj;
    }
    sx_store2(y, s0), sx_store2(y + 2, s1), sx_store2(y + 4, s2), sx_store2(y + 6, s3);
}

static void rows_4(int ld, int cols, const double *restrict At, const double *restrict x, double *restrict y)
{
    sx_v2 s0 = {0.0, 0.0}, s1 = s0;
    int j;
    for (j = 0; j < cols; j++) {
        const double *a = At + (size_t)j * (size_t)ld;
        const sx_v2 xj = {x[j], x[j]};
        s0 += sx_load2(a) * xj, s1 += sx_load2(a + 2) * xj;
    }
    sx_store2(y, s0), sx_store2(y + 2, s1);
}

static void rows_2(int ld, int cols, const double *restrict At, const double *restrict x, double *restrict y)
{
    sx_v2 s0 = {0.0, 0.0};
    int j;
    for (j = 0; j < cols; j++) {
        const sx_v2 xj = {x[j], x[j]};
        s0 += sx_load2(At + (size_t)j * (size_t)ld) * xj;
    }
    sx_store2(y, s0);
}

static void rows_1(int ld, int cols, const double *restrict At, const double *restrict x, double *restrict y)
{
    double s0 = 0.0;
    int j;
    for (j = 0; j < cols; j++) s0 += At[(size_t)j * (size_t)ld] * x[j];
    *y = s0;
}

/* rows i..i+1 of three products A x0, A x1, A x2 at once (each column of A loaded once) */
static void rows_2x3(int ld, int cols, const double *restrict At, const double *const x[3], double *const y[3], int i)
{
    sx_v2 s0 = {0.0, 0.0}, s1 = s0, s2 = s0;
    int j;
    for (j = 0; j < cols; j++) {
        const sx_v2 a = sx_load2(At + (size_t)j * (size_t)ld + i);
        const sx_v2 x0 = {x[0][j], x[0][j]}, x1 = {x[1][j], x[1][j]}, x2 = {x[2][j], x[2][j]};
        s0 += a * x0, s1 += a * x1, s2 += a * x2;
    }
    sx_store2(y[0] + i, s0), sx_store2(y[1] + i, s1), sx_store2(y[2] + i, s2);
}

#if defined(__GNUC__) && defined(__x86_64__) && defined(__linux__)
/* The same blocks four doubles to a register where the processor has AVX2 (found once, as the library
 * loads). The same multiplications and additions in the same order, none fused (AVX2 without FMA):
 * the same bits (tests/c/test_scene_exact.c checks the products against row-wise sums). */
#define SX_AVX2 1
typedef double sx_v4 __attribute__((vector_size(32)));
static int has_avx2;
__attribute__((constructor)) static void find_avx2(void)
{
    __builtin_cpu_init(); /* (a constructor may run before libgcc's own) */
    has_avx2 = __builtin_cpu_supports("avx2");
}

__attribute__((target("avx2"))) static sx_v4 load4(const double *p)
{
    sx_v4 v;
    memcpy(&v, p, sizeof v);
    return v;
}

/* rows 0..11 and 0..15: more rows at once are more sums in flight (each sum's adds wait on each
 * other: a row's latency, not the processor's throughput, bounds a block of 8) */
__attribute__((target("avx2"))) static void rows_16_avx2(int ld, int cols, const double *restrict At,
                                                          const double *restrict x, double *restrict y)
{
    sx_v4 s0 = {0.0, 0.0, 0.0, 0.0}, s1 = s0, s2 = s0, s3 = s0;
    int j;
    for (j = 0; j < cols; j++) {
        const double *a = At + (size_t)j * (size_t)ld;
        const sx_v4 xj = {x[j], x[j], x[j], x[j]};
        s0 += load4(a) * xj, s1 += load4(a + 4) * xj, s2 += load4(a + 8) * xj, s3 += load4(a + 12) * xj;
    }
    memcpy(y, &s0, sizeof s0), memcpy(y + 4, &s1, sizeof s1), memcpy(y + 8, &s2, sizeof s2);
    memcpy(y + 12, &s3, sizeof s3);
}

__attribute__((target("avx2"))) static void rows_12_avx2(int ld, int cols, const double *restrict At,
                                                          const double *restrict x, double *restrict y)
{
    sx_v4 s0 = {0.0, 0.0, 0.0, 0.0}, s1 = s0, s2 = s0;
    int j;
    for (j = 0; j < cols; j++) {
        const double *a = At + (size_t)j * (size_t)ld;
        const sx_v4 xj = {x[j], x[j], x[j], x[j]};
        s0 += load4(a) * xj, s1 += load4(a + 4) * xj, s2 += load4(a + 8) * xj;
    }
    memcpy(y, &s0, sizeof s0), memcpy(y + 4, &s1, sizeof s1), memcpy(y + 8, &s2, sizeof s2);
}

__attribute__((target("avx2"))) static void rows_8_avx2(int ld, int cols, const double *restrict At,
                                                         const double *restrict x, double *restrict y)
{
    sx_v4 s0 = {0.0, 0.0, 0.0, 0.0}, s1 = s0;
    int j;
    for (j = 0; j < cols; j++) {
        const double *a = At + (size_t)j * (size_t)ld;
        const sx_v4 xj = {x[j], x[j], x[j], x[j]};
        s0 += load4(a) * xj, s1 += load4(a + 4) * xj;
    }
    memcpy(y, &s0, sizeof s0), memcpy(y + 4, &s1, sizeof s1);
}

/* rows 0..5 (a series' term: the velocities' rows of a scene with 6 degrees of freedom), both sums in
 * one pass */
__attribute__((target("avx2"))) static void rows_6_avx2(int ld, int cols, const double *restrict At,
                                                         const double *restrict x, double *restrict y)
{
    sx_v4 s0 = {0.0, 0.0, 0.0, 0.0};
    sx_v2 s1 = {0.0, 0.0};
    int j;
    for (j = 0; j < cols; j++) {
        const double *a = At + (size_t)j * (size_t)ld;
        const sx_v4 xj = {x[j], x[j], x[j], x[j]};
        const sx_v2 xj2 = {x[j], x[j]};
        s0 += load4(a) * xj, s1 += sx_load2(a + 4) * xj2;
    }
    memcpy(y, &s0, sizeof s0), sx_store2(y + 4, s1);
}

__attribute__((target("avx2"))) static void rows_4_avx2(int ld, int cols, const double *restrict At,
                                                         const double *restrict x, double *restrict y)
{
    sx_v4 s0 = {0.0, 0.0, 0.0, 0.0};
    int j;
    for (j = 0; j < cols; j++) {
        const sx_v4 xj = {x[j], x[j], x[j], x[j]};
        s0 += load4(At + (size_t)j * (size_t)ld) * xj;
    }
    memcpy(y, &s0, sizeof s0);
}

/* rows i..i+7 of three products at once */
__attribute__((target("avx2"))) static void rows_8x3_avx2(int ld, int cols, const double *restrict At,
                                                           const double *const x[3], double *const y[3], int i)
{
    sx_v4 s0 = {0.0, 0.0, 0.0, 0.0}, s1 = s0, t0 = s0, t1 = s0, u0 = s0, u1 = s0;
    int j;
    for (j = 0; j < cols; j++) {
        const double *a = At + (size_t)j * (size_t)ld + i;
        const sx_v4 a0 = load4(a), a1 = load4(a + 4);
        const sx_v4 x0 = {x[0][j], x[0][j], x[0][j], x[0][j]}, x1 = {x[1][j], x[1][j], x[1][j], x[1][j]},
                    x2 = {x[2][j], x[2][j], x[2][j], x[2][j]};
        s0 += a0 * x0, s1 += a1 * x0, t0 += a0 * x1, t1 += a1 * x1, u0 += a0 * x2, u1 += a1 * x2;
    }
    memcpy(y[0] + i, &s0, sizeof s0), memcpy(y[0] + i + 4, &s1, sizeof s1);
    memcpy(y[1] + i, &t0, sizeof t0), memcpy(y[1] + i + 4, &t1, sizeof t1);
    memcpy(y[2] + i, &u0, sizeof u0), memcpy(y[2] + i + 4, &u1, sizeof u1);
}
#endif

void sx_matvec_lead(int rows, int cols, int ld, const double *restrict At, const double *restrict x,
                    double *restrict y)
{
    int i = 0;
#ifdef SX_AVX2
    if (has_avx2) {
        for (; i + 16 <= rows; i += 16) rows_16_avx2(ld, cols, At + i, x, y + i);
        if (i + 12 <= rows) rows_12_avx2(ld, cols, At + i, x, y + i), i += 12;
        if (i + 8 <= rows) rows_8_avx2(ld, cols, At + i, x, y + i), i += 8;
        if (i + 6 <= rows) rows_6_avx2(ld, cols, At + i, x, y + i), i += 6;
        if (i + 4 <= rows) rows_4_avx2(ld, cols, At + i, x, y + i), i += 4;
    }
#endif
    for (; i + 8 <= rows; i += 8) rows_8(ld, cols, At + i, x, y + i);
    if (i + 4 <= rows) rows_4(ld, cols, At + i, x, y + i), i += 4;
    if (i + 2 <= rows) rows_2(ld, cols, At + i, x, y + i), i += 2;
    if (i < rows) rows_1(ld, cols, At + i, x, y + i);
}

void sx_matvec3_lead(int rows, int cols, int ld, const double *At, const double *const x[3], double *const y[3])
{
    int i = 0, k;
#ifdef SX_AVX2
    if (has_avx2)
        for (; i + 8 <= rows; i += 8) rows_8x3_avx2(ld, cols, At, x, y, i);
#endif
    for (; i + 2 <= rows; i += 2) rows_2x3(ld, cols, At, x, y, i);
    if (i < rows)
        for (k = 0; k < 3; k++) rows_1(ld, cols, At + i, x[k], y[k] + i);
}

void sx_matvec_cols(int rows, int cols, const double *restrict At, const double *restrict x, double *restrict y)
{
    sx_matvec_lead(rows, cols, rows, At, x, y);
}

void sx_transpose(int rows, int cols, const double *A, double *At)
{
    int i, j;
    for (i = 0; i < rows; i++)
        for (j = 0; j < cols; j++) At[(size_t)j * (size_t)rows + (size_t)i] = A[(size_t)i * (size_t)cols + (size_t)j];
}

void sx_sym2_eig(const double A[2][2], double mu[2], double e[2][2])
{
    const double a = A[0][0], d = A[1][1], b = 0.5 * (A[0][1] + A[1][0]);
    const double theta = 0.5 * atan2(2.0 * b, a - d), c = cos(theta), s = sin(theta);
    e[0][0] = c, e[0][1] = s;   /* the rotation that diagonalises [[a, b], [b, d]] */
    e[1][0] = -s, e[1][1] = c;
    mu[0] = a * c * c + 2.0 * b * c * s + d * s * s;
    mu[1] = a * s * s - 2.0 * b * c * s + d * c * c;
}

double sx_sym2_min_eig(const double A[2][2])
{
    const double a = A[0][0], d = A[1][1], b = 0.5 * (A[0][1] + A[1][0]);
    return 0.5 * (a + d) - sqrt(0.25 * (a - d) * (a - d) + b * b);
}
