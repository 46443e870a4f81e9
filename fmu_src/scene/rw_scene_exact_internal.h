/* The exact scene engine's shared pieces (rw_scene_exact*.c): a scene's linear region, its exact
 * propagators over a step length, polynomial tools and the run's state. Internal, not installed.
 *
 * Augmented state xa = (x, ag, ag', 1, z chains) of length na = n + 3 + 3 nz, x = (X, X') the
 * region's n = 2 ndof first-order states: xa' = Aa xa exactly while the record is linear, so the
 * motion over a step of length h is xa(u h) = sum_k X_k u^k with X_{k+1} = h/(k+1) Aa X_k (u in
 * [0, 1]). A Bouc-Wen diaphragm's hysteretic variable enters as a quadratic over each step, the
 * chain (z, z', z'') with z''' = 0, fitted to the law along the exact motion
 * (rw_scene_exact_bouc_wen.c). */
#ifndef RW_SCENE_EXACT_INTERNAL_H
#define RW_SCENE_EXACT_INTERNAL_H

#include <complex.h>
#include <float.h>
#include <math.h>
#include <string.h>

#include "rw_scene_exact.h"

#define SX_MAX_DOF (4 * RW_SCENE_MAX_STOREYS) /* per storey: a wall's q1, q2, the floor, the diaphragm */
#define SX_MAX_N (2 * SX_MAX_DOF)
#define SX_MAX_Z RW_SCENE_MAX_STOREYS /* Bouc-Wen diaphragms: each a chain of 3 inputs (z, z', z'') */
#define SX_MAX_NA (SX_MAX_N + 3 + 3 * SX_MAX_Z)
#ifndef SX_BW_HMAX
#define SX_BW_HMAX 1e-3 /* the longest step a Bouc-Wen diaphragm's fit takes [s] */
#endif
#define SX_BW_HMIN 1e-9 /* the shortest step it halves to where its rounds do not settle [s] */
#define SX_Z_NODES 4 /* a Bouc-Wen fit's nodes past the step's start: u = 1/4, 1/2, 3/4, 1 */
#define SX_MAX_F (5 * RW_SCENE_MAX_STOREYS)     /* watched linear functionals of the state */
#define SX_MAX_TERMS (4 * RW_SCENE_MAX_STOREYS) /* rank-one terms of the viscous dissipation */
#define SX_LO 6          /* degree of the quiet test's polynomials */
#define SX_MAX_DEG 40    /* cap of a series' degree (reached only for rho > 1) */
#define SX_RHO 1.0       /* a step's ||A h|| in the balanced norm */
#define SX_STEPS 8       /* step lengths cached per region */
#ifndef SX_WINDOW
#define SX_WINDOW 3      /* record intervals a quiet test takes at once (sx_window) */
#endif
#ifndef SX_REGIONS /* (the C tests build the scenes with the least memory too) */
#define SX_REGIONS 96    /* regions cached per run (two walls visit about 50) ... */
#endif
#define SX_CACHE_BYTES 64e6 /* ... within this much memory (five storeys: about 100) */
#define SX_MAX_LINES (RW_NZ + 2) /* a wall's indicator lines (+ the toppling limit's two) */
#define SX_LINE_SLOTS ((SX_MAX_LINES + 3) & ~3) /* ... as arrays, in blocks of four (sx_line_set) */

/* kinds of functionals (the deformation's rate only where a bilinear diaphragm yields: its
 * unloading is where the rate changes sign) */
enum { SX_Q1 = 0, SX_Q2, SX_DEFORM, SX_BASE_ACC, SX_DEFORM_RATE };
/* a storey's peak quantities: s1 = (h/2) q1, s2 = (h/2)(q1 + q2), the diaphragm's deformation and
 * the base acceleration */
enum { SX_PEAK_S1 = 0, SX_PEAK_S2, SX_PEAK_DEFORM, SX_PEAK_ACC, SX_PEAK_KINDS };

/* a function inlined into each of its callers in the quiet test's hot path */
#if defined(__GNUC__)
#define SX_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define SX_ALWAYS_INLINE
#endif

/* a . b over n entries, in two running sums (even and odd entries: not a row's order) held as one
 * vector register (GCC's vector extension: SSE2 on x86-64) */
typedef double sx_v2 __attribute__((vector_size(16)));
static inline double sx_dot(const double *a, const double *b, int n)
{
    sx_v2 s = {0.0, 0.0};
    double sum;
    int i = 0;
    for (; i + 2 <= n; i += 2) {
        sx_v2 x, y;
        memcpy(&x, a + i, sizeof x), memcpy(&y, b + i, sizeof y);
        s += x * y;
    }
    sum = s[0] + s[1];
    return i < n ? sum + a[i] * b[i] : sum;
}

/* two doubles in a vector register, loaded from and stored to any address */
static inline sx_v2 sx_load2(const double *p)
{
    sx_v2 v;
    memcpy(&v, p, sizeof v);
    return v;
}

static inline void sx_store2(double *p, sx_v2 v) { memcpy(p, &v, sizeof v); }

/* a row's nonzero entries when it holds two at most (c1 = 0 where it holds one, c0 = 0 too where
 * none) */
typedef struct {
    int i0, i1;
    double c0, c1;
} sx_pair;

/* what selects a region: which walls stand and their hinge moments Q = c + J q, and each bilinear
 * diaphragm's branch, its spring force F = k_branch d + F0 (1 - alpha) Fy (d its deformation) */
typedef struct {
    int standing[RW_SCENE_MAX_STOREYS];
    double c[RW_SCENE_MAX_STOREYS][2], J[RW_SCENE_MAX_STOREYS][2][2];
    double cap[RW_SCENE_MAX_STOREYS]; /* the wall's hinge capacities cap_b + cap_m: the scale of c */
    int branch[RW_SCENE_MAX_STOREYS]; /* bilinear diaphragm: 0 elastic, +1 or -1 yielding that way */
    double F0[RW_SCENE_MAX_STOREYS];  /* its spring force's constant over (1 - alpha) Fy (0: linear) */
} sx_key;

/* a standing wall's collapse indicator on the region: G(q) = q.A q - c.q (rw_collapse_form) */
typedef struct {
    int active;          /* outside the law's elastic range: the collapse test can fire */
    double A[2][2], c[2];
    double lam_min;      /* least eigenvalue of A's symmetric part */
    double mu[2], e[2][2]; /* A's symmetric part = sum_k mu_k e_k e_k^T (G without the rounding of a
                              stiff tie's large entries: q.A q = sum_k mu_k (e_k.q)^2) */
} sx_collapse;

/* A region's modes (the eigen-decomposition of A, LAPACK's dgeev), for the slow steps' quiet test:
 * x = Vr y, y = Winv x; a mode is a real eigenvalue (coordinate y_j) or a complex pair lambda =
 * sigma + i omega (zeta = y_j - i y_{j+1}), with zeta' = lambda zeta + g0 + g1 ag, and functional
 * f's share of it Re(a[f] zeta). The motion stays exp(Aa h)'s: the modes only bound it. */
typedef struct {
    int valid;       /* decomposed, and well enough conditioned to bound with */
    int count;
    int first[SX_MAX_N], pair[SX_MAX_N];
    /* a nearly defective real pair kept as a block (rw_scene_exact_blocks.c): its two columns as a
     * pair's, its motion y' = B y + forcing in them (B row-major), abs_lam and growth its ||B|| */
    int block[SX_MAX_N], blocks;
    double B[SX_MAX_N][4];
    double coupling[SX_MAX_N]; /* how hard the blocks' motion drives mode k (sx_block_coupling) */
    double complex lam[SX_MAX_N], inv_lam[SX_MAX_N], g0[SX_MAX_N], g1[SX_MAX_N];
    double abs_lam[SX_MAX_N], growth[SX_MAX_N]; /* |lam|, max(Re lam, 0) */
    /* functional f's share a of mode k by mode, the functionals contiguous (Re a, Im a, |a|): the
     * slow steps' loop over the functionals runs on these, which the compiler vectorises */
    double share_re[SX_MAX_N][SX_MAX_F + 1], share_im[SX_MAX_N][SX_MAX_F + 1], share_abs[SX_MAX_N][SX_MAX_F + 1];
    /* (each zero past the last functional: the loops take the functionals two at a time) */
    double cond;     /* the product of Vr's and Winv's balanced norms */
    double Winv_cols[SX_MAX_N * SX_MAX_N]; /* Winv by columns (sx_matvec_cols: every coordinate at once) */
    /* |alpha_k| <= pb0 + pb1 |ag| + pb2 |slope|, its particular part's size (|g0|/|lam|, |g1|/|lam|,
     * |g1|/|lam|^2), and each functional's largest share of any mode */
    double pb0[SX_MAX_N], pb1[SX_MAX_N], pb2[SX_MAX_N], share_max[SX_MAX_F];
} sx_modes;

/* a functional's low-degree polynomial over a step (u in [0, 1]): its range is within the
 * coefficients' and `tail`, its derivative's within theirs and `dtail`; `start` its exact value at
 * the step's start (a Hermite cubic's coef[0] is not that where a band's free motion was taken out
 * of it) */
typedef struct {
    double coef[SX_LO + 1], tail, dtail, start;
    int deg;  /* the coefficients in use */
    int bern; /* 1: coef[0..3] are the Bernstein coefficients of a cubic (sx_hermite_polys), else
                 the monomial ones (the Taylor rows of a step's table) */
} sx_lopoly;

/* a step length's constants for the quiet test's bounds (rw_scene_exact_hermite.c), per mode of the
 * region: |lam h|, |lam h|^4, its growth G = e^(max(Re lam, 0) h) and, for a band (|lam h|^4 past
 * 384), e^(lam h) */
typedef struct {
    double h;
    double wh[SX_MAX_N], w4[SX_MAX_N], G[SX_MAX_N];
    double complex emu[SX_MAX_N];
    int bands, modal; /* how many modes are bands over the step, and whether one turns past
                         SX_BAND_MODAL_WH (sx_mode_bounds' own fields, which the length alone sets) */
    int nfast, fast[SX_MAX_N]; /* the modes (not blocks) that turn by a radian or more over it */
} sx_hermite_step;

/* the exact propagators of a region over one step length h */
typedef struct {
    double h;
    long used;
    int is_long;  /* longer than the series converges over: E, Wd and wg by squaring, no T or rows */
    int deg;      /* degree of the matrix series */
    double rho;   /* ||A_s|| h */
    double *E;    /* na x na: exp(Aa h) */
    double *T;    /* n x na by columns: x part of (Aa h)^(SX_LO+1)/(SX_LO+1)!, the quiet test's tail */
    double *Wd;   /* na x na: the viscous dissipation over the step as a quadratic form of xa */
    double *Et;   /* E by columns, for the quiet steps' products (sx_step_propagate) */
    double *Wdp;  /* Wd by columns, each padded with zeros to a multiple of 4 rows (sx_step_dissipation) */
    double *wg;   /* 2 x na: the momentum's integrals over the step of E(tau) and tau E(tau) */
    double *rows; /* (nf (SX_LO+1)) x na by columns: functional f's Taylor coefficients l.(Aa h)^k/k!
                     in row f (SX_LO+1) + k */
    double *zrows; /* (nz SX_Z_NODES) x na: Bouc-Wen diaphragm k's deformation rate at u = (j+1)/4
                      in row k SX_Z_NODES + j, e_k.exp(Aa u h) */
    double *zwork; /* (nz 3) x na: its integrals over the step of tau^m e_k.exp(Aa tau), m = 0, 1, 2,
                      in row 3 k + m (the hysteretic force's work, exactly) */
    double *mem;  /* all of the above, allocated when the slot is first built (NULL before) */
    sx_hermite_step herm; /* the quiet test's constants (the region's modes valid) */
    /* a window of SX_WINDOW such steps (sx_window): the quiet test's constants over its length, and
       each functional's bounds on what kinks of the record inside it add to the departure from the
       window's cubic (sx_kink_of) */
    sx_hermite_step herm_w;
    double kink_modes[SX_MAX_F], kink_record[SX_MAX_F];
} sx_step;

typedef struct {
    sx_key key;
    long used;
    int ndof, n, na, nf;
    int pos[SX_MAX_DOF], vel[SX_MAX_DOF]; /* each DOF's displacement and velocity in the scene state */
    int wall_dof[RW_SCENE_MAX_STOREYS], floor_dof[RW_SCENE_MAX_STOREYS], diaph_dof[RW_SCENE_MAX_STOREYS];
    int nz, z_storey[SX_MAX_Z];  /* the Bouc-Wen diaphragms' z chains: chain k at columns sx_z_col */
    int z_pos[SX_MAX_Z];         /* chain k's z in the scene state */
    double hcap;                 /* the longest step a Bouc-Wen fit takes (INFINITY: none), halved
                                    where its rounds did not settle */
    double *Aa;                /* na x na, row-major */
    double *Aa_cols;           /* the same by columns, for the series' products */
    int one_hot;               /* every row of Aa but the velocities' holds one 1 or nothing ... */
    int hot[SX_MAX_NA];        /* ... at this column (-1: nothing) */
    double scale[SX_MAX_N];    /* balancing: A_s = S^-1 A S */
    double inv_scale[SX_MAX_N];
    double norm;               /* ||A_s||_inf */
    double F[SX_MAX_F][SX_MAX_NA]; /* functional rows over xa */
    int f_nz[SX_MAX_F], f_at[SX_MAX_F][SX_MAX_NA]; /* their nonzero entries, in order (most hold one
                                                      or two: sx_functional) */
    int f_kind[SX_MAX_F], f_storey[SX_MAX_F];
    int f_of[RW_SCENE_MAX_STOREYS][SX_DEFORM_RATE + 1]; /* storey i's functional of each kind (-1: none) */
    double f_scale[SX_MAX_F];  /* sum_i |l_i| S_i over x: a functional's share of a tail in the S norm */
    double FA[SX_MAX_F][SX_MAX_NA];   /* their rates along the motion, F Aa, rows over xa ... */
    int fa_nz[SX_MAX_F], fa_at[SX_MAX_F][SX_MAX_NA]; /* ... and their nonzero entries (most hold one or
                                                      two: a velocity, or a difference of two) */
    sx_pair f_pair[SX_MAX_F], fa_pair[SX_MAX_F]; /* the rows' entries inline where they hold two at most */
    double mom[SX_MAX_NA];     /* the horizontal momentum relative to the ground, a row over xa */
    /* the scene's energy on the region, (1/2) V.M V + (1/2) X.K X - f.X + e_const (M, K: its
     * Hessians; e_const: from rw_scene_energy at a state of the region) */
    double Mq[SX_MAX_DOF * SX_MAX_DOF], Kq[SX_MAX_DOF * SX_MAX_DOF], fq[SX_MAX_DOF], e_const;
    /* ... as sum_t eq_c[t] x[eq_a[t]] x[eq_b[t]] - sum_k fq[k] x[pos[k]] + e_const over the scene
     * state x itself: the forms' nonzero entries on and above their diagonals */
    int eq_n, eq_a[SX_MAX_N * (SX_MAX_N + 1) / 2], eq_b[SX_MAX_N * (SX_MAX_N + 1) / 2];
    double eq_c[SX_MAX_N * (SX_MAX_N + 1) / 2];
    int nterms;                /* viscous dissipation rate = sum_t dcoef_t (dvec_t . xa)^2 */
    double dcoef[SX_MAX_TERMS], dvec[SX_MAX_TERMS][SX_MAX_NA];
    int d_nz[SX_MAX_TERMS];    /* dvec_t's nonzero entries (one or two: a dashpot's velocities) */
    sx_pair d_pair[SX_MAX_TERMS];
    sx_collapse col[RW_SCENE_MAX_STOREYS];
    sx_modes modes;
    sx_step step[SX_STEPS];
    int last_step;             /* the slot sx_step_of found last */
    double *blob;              /* Aa and Aa_cols (the step tables have their own) */
} sx_region;

/* a step's Taylor series of the augmented state (X[k*na + i]) and its tail bound in the S norm */
typedef struct {
    int deg;
    double L;        /* step length */
    double X[(SX_MAX_DEG + 1) * SX_MAX_NA];
    double tail;     /* max_i |sum_{k>deg} X_k,i| / S_i */
} sx_series;

/* one indicator of a wall: z = c + s|w| + t w with w = a.(q1, q2) (rw_indicator_line), or the
 * collapse indicator's G */
typedef struct {
    double a0, a1, s, t, c;
} sx_line;

/* a wall's lines as arrays, each line's coefficients with what the quiet test's first pass takes of
 * them: |a0|, |a1|, |c| and s + |t|, the most z moves per unit of |w|; past the last line, up to a
 * multiple of four, lines that never come near zero (z = 1), so that the box test runs in whole
 * blocks of four */
typedef struct {
    double a0[SX_LINE_SLOTS], a1[SX_LINE_SLOTS], abs_a0[SX_LINE_SLOTS], abs_a1[SX_LINE_SLOTS];
    double s[SX_LINE_SLOTS], t[SX_LINE_SLOTS], c[SX_LINE_SLOTS], abs_c[SX_LINE_SLOTS], slope[SX_LINE_SLOTS];
} sx_line_set;

/* one indicator of a bilinear diaphragm on its region: z = c + a v, v the functional of `kind`
 * (the deformation on the elastic branch: z = 1 -+ the normalised hysteretic force; its rate while
 * yielding) */
typedef struct {
    int kind;
    double c, a;
} sx_dline;

/* a step whose quiet test left a peak in doubt: the step was taken, and the peak of `kind` of
 * `storey` inside it is bounded by `bound`; it is resolved on the exact series only if the peak
 * reached elsewhere stays under that bound (rw_scene_exact_peaks.c) */
typedef struct {
    double bound, h, t1; /* t1: where the step ends (the rounding its halves' tables share) */
    int storey, kind, region;
    double xa0[SX_MAX_NA];
} sx_doubt;

typedef struct {
    rw_scene sc;
    const rw_scene_record *rec;
    const rw_scene_options *opt;
    rw_scene_result *res;
    double x[RW_SCENE_NX];
    double t;
    sx_region **regions;     /* the cached regions, each allocated as its slot is first used */
    int nregions, cur, capacity;
    long stamp;              /* a clock: every region entry and every request for a step table ticks it,
                                so that the region and the table used least recently go first */
    int nlines[RW_SCENE_MAX_STOREYS];
    sx_line lines[RW_SCENE_MAX_STOREYS][SX_MAX_LINES];
    sx_line_set line_set[RW_SCENE_MAX_STOREYS]; /* the same, as arrays for the quiet test's first pass */
    int ndlines[RW_SCENE_MAX_STOREYS];  /* the bilinear diaphragms' indicators on the region */
    sx_dline dlines[RW_SCENE_MAX_STOREYS][2];
    double d_synced[RW_SCENE_MAX_STOREYS]; /* a bilinear diaphragm's deformation where its work and
                                              z were last brought up to date (sx_sync_hysteresis) */
    double work_ground, work_damping, losses;
    double e_event;          /* the scene's energy after the last event's update (sx_handle_events) */
    double z_next[SX_MAX_Z][2]; /* z' and z'' where the last fitted step ended: the next fit's guess */
    int z_next_valid;           /* ... unless an event came between */
    double work_hysteretic; /* the Bouc-Wen diaphragms' hysteretic work since the region was entered
                               (the region's quadratic energy holds their alpha k part only) */
    size_t hint, next_out;
    double last_event_t;
    int same_instant;
    int error;               /* an event's error code (Zeno, no memory, a singular mass matrix) */
    sx_doubt *doubts;        /* the steps whose peaks are in doubt, in the order taken */
    int ndoubts;
    int window_wait;         /* record intervals to take one by one before a window is tried again */
    int window_backoff;      /* ... after the next failure, in units of WINDOW_WAIT (doubled at each) */
} sx_run;

/* row . v (na entries, nz of them not zero). Most rows hold one or two (a displacement, a velocity,
 * a difference of two), which pair holds inline. */
static inline double sx_row_dot(const double *row, int nz, int na, const sx_pair *pair, const double *v)
{
    return nz <= 2 ? pair->c0 * v[pair->i0] + pair->c1 * v[pair->i1] : sx_dot(row, v, na);
}

/* functional f of the region at v (an augmented state, or a series' coefficient) */
static inline double sx_functional(const sx_region *r, int f, const double *v)
{
    return sx_row_dot(r->F[f], r->f_nz[f], r->na, &r->f_pair[f], v);
}

/* functional f's rate along the region's motion at xa: F Aa xa */
static inline double sx_functional_rate(const sx_region *r, int f, const double *v)
{
    return sx_row_dot(r->FA[f], r->fa_nz[f], r->na, &r->fa_pair[f], v);
}

/* ---- the run (rw_scene_exact.c) and its steps (rw_scene_exact_steps.c) ---- */
double sx_ground(sx_run *R, double t);  /* the record at t */
int sx_handle_events(sx_run *R);        /* the event update at R->t, then the region: 0 or an error code */
int sx_advance(sx_run *R, double tb);   /* the interval [R->t, tb]: 0, or 1 with R->error set */
/* the record intervals [t[0] = R->t, t[1]], ..., [t[n-1], t[n]] at once, where the quiet test clears
 * them over the window they make (each observed at its end by sx_observe but the last): the
 * intervals taken (n; 1 where the window failed and the first was taken alone, as sx_advance takes
 * it; 0 if no window was tried), or -1 with R->error set */
int sx_window(sx_run *R, const double t[], int n);
void sx_observe(sx_run *R); /* the output row due at R->t and the energy balance there */

/* ---- bilinear diaphragms (rw_scene_exact_bilinear.c) ---- */
/* is diaphragm i bilinear (its z and the work done on it are states the engine keeps)? */
int sx_bilinear(const rw_scene *sc, int i);
/* the branch and force constant of bilinear diaphragm i at the scene state x (rates dx) */
void sx_bilinear_key(const rw_scene *sc, const double x[], const double dx[], int i, sx_key *key);
/* the hysteretic variable z and the work done on each bilinear diaphragm, and the alpha k work
 * done on each Bouc-Wen one, brought up to R->x from the current region (before the scene's own
 * functions read x) */
void sx_sync_hysteresis(sx_run *R);
/* the indicators of the current region's bilinear diaphragms, and where their work (and Bouc-Wen
 * diaphragms' alpha k work) starts */
void sx_bilinear_entered(sx_run *R);
/* diaphragm i's spring stiffness in the region's linear system: k, or alpha k on a yielding
 * bilinear branch and for Bouc-Wen (whose hysteretic share is the z chain's input) */
double sx_linear_stiffness(const rw_scene *sc, const sx_key *key, int i);

/* ---- Bouc-Wen diaphragms (rw_scene_exact_bouc_wen.c) ---- */
/* is diaphragm i a smooth hysteresis (Bouc-Wen, pinched or not), whose force (1 - alpha) Fy z
 * enters the region as the z chain's input? */
int sx_bouc_wen(const rw_scene *sc, int i);
/* does it yield (a z chain: its hysteretic force not zero)? */
int sx_bouc_wen_chain(const rw_scene *sc, int i);
/* the first column of chain k */
static inline int sx_z_col(const sx_region *r, int k) { return r->n + 3 + 3 * k; }
/* the law's z over a step of length h from xa0 (its z chains' values set, their rates a guess):
 * the chains' quadratics fitted by Picard rounds along the exact motion from the table of h (st)
 * or, for st NULL, the exact series; 0, or 1 if the rounds did not settle */
int sx_bouc_wen_fit(const sx_run *R, const sx_region *r, const sx_step *st, double h, double xa0[]);
/* the Bouc-Wen diaphragms' z and hysteretic work brought to u in (0, 1] of the fitted step from xa0:
 * on its series s, or for s NULL (u = 1) on its table st */
void sx_bouc_wen_advance(sx_run *R, const sx_region *r, const double xa0[], double u, const sx_step *st,
                         const sx_series *s);

/* ---- memory kept for the next run on the thread (rw_scene_exact_pool.c) ---- */
void *sx_pool_alloc(size_t size); /* a block of at least size bytes, not zeroed (NULL: no memory) */
void sx_pool_free(void *p);       /* a block of sx_pool_alloc back (NULL: nothing) */

/* ---- dense pieces (rw_scene_exact_dense.c) ---- */
int sx_lu_solve(int n, double *A, double *B, int nrhs); /* A X = B in place (B n x nrhs); 0 ok, 1 singular */
void sx_balance(int n, const double *A, double *S, double *norm); /* diagonal S (powers of 2), ||S^-1 A S||_inf */
/* y = A x from A stored by columns (At: cols x rows), vectorised; each sum in a row's order */
void sx_matvec_cols(int rows, int cols, const double *restrict At, const double *restrict x, double *restrict y);
/* the same with A's columns ld apart (its first `rows` rows) */
void sx_matvec_lead(int rows, int cols, int ld, const double *restrict At, const double *restrict x, double *restrict y);
/* y[k] = the leading rows of A x[k] for three vectors at once, each entry's sum as sx_matvec_lead's */
void sx_matvec3_lead(int rows, int cols, int ld, const double *At, const double *const x[3], double *const y[3]);
void sx_transpose(int rows, int cols, const double *A, double *At); /* At (cols x rows) = A^T */
double sx_sym2_min_eig(const double A[2][2]);
void sx_sym2_eig(const double A[2][2], double mu[2], double e[2][2]); /* A's symmetric part: mu_k, rows e_k */

/* ---- the region (rw_scene_exact_region.c) ---- */
/* the key of the region the motion at x goes into; dx: the scene's rates at x where the caller has
 * them (the event update's), NULL to have them evaluated here */
void sx_region_key(const rw_scene *sc, double ag, const double x[], const double *dx, sx_key *key);
int sx_key_equal(const sx_key *a, const sx_key *b);
/* builds region r for key (allocates; frees an old build first): 0 or RW_SCENE_NO_MEMORY. A
 * sibling (NULL: none) is a built region whose key differs from this one's in constants only (the
 * hinge moments' c, a bilinear diaphragm's F0): where its first-order matrix is this one's to the
 * bit, its modes are taken over rather than decomposed again (sx_modes_adopt) */
int sx_region_build(const rw_scene *sc, const sx_key *key, sx_region *r, const sx_region *sibling);
/* do two keys select the same first-order matrix (the same standing walls, J and branches)? */
int sx_key_same_matrix(const sx_key *a, const sx_key *b);
void sx_region_free(sx_region *r);
/* a region's fields that say it holds nothing (no matrix, tables or modes), the rest left as it is */
void sx_region_blank(sx_region *r);
/* the scene state's (x, ag, slope) as the region's augmented state, and back */
void sx_gather(const sx_region *r, const double x[], double ag, double slope, double xa[]);
void sx_scatter(const sx_region *r, const double xa[], double x[]);
/* the region's quadratic energy at the scene state x, without e_const */
double sx_region_energy(const sx_region *r, const double x[]);

/* ---- propagators (rw_scene_exact_series.c) ---- */
/* the step table of length h (cached, built if missing; lengths within tol share one: the
 * rounding of the record's times); NULL if its memory could not be had (the caller takes the
 * step on the exact series instead) */
sx_step *sx_step_of(sx_region *r, double h, double tol, long stamp);
/* is st the table of a step of length h (within tol, the rounding of the record's times)? */
int sx_step_fits(const sx_step *st, double h, double tol);
/* exp(Aa h / 2^k) by columns for k = 0..levels, each na x na in Et in turn: the shortest from its
 * table, the others by squaring it as sx_step_of squares a long table's; 0, or 1 if that table
 * could not be had */
int sx_halves_of(sx_region *r, double h, int levels, double tol, long stamp, double *Et);
/* that rounding at time t */
#define SX_TIME_TOL(t) (16.0 * DBL_EPSILON * fmax(fabs(t), 1.0))
/* xa1 = exp(Aa h) xa0 over a step's table (the record's rows are exact: ag + h slope, slope, 1) */
void sx_step_propagate(const sx_region *r, const sx_step *st, const double xa0[], double xa1[]);
/* the viscous dissipation over the step from xa0, xa0.Wd xa0 */
double sx_step_dissipation(const sx_region *r, const sx_step *st, const double xa0[]);
/* the Taylor series of the augmented state over a step of length L <= the region's limit */
void sx_series_of(const sx_region *r, const double xa0[], double L, sx_series *s);
/* the longest step the series is built for */
double sx_hmax(const sx_region *r);
/* the parts, no longer than that, a length is taken in (at least 1) */
int sx_parts(const sx_region *r, double length);
/* the augmented state at u in [0, 1] of a series */
void sx_series_at(const sx_region *r, const sx_series *s, double u, double xa[]);

/* ---- polynomials on [0, 1] (rw_scene_exact_poly.c) ---- */
double sx_poly_eval(const double *p, int deg, double u);
/* a quiet test's polynomial at u (either basis) */
double sx_lopoly_at(const sx_lopoly *p, double u);
/* sum_k |p_k|: a bound on |p| over [0, 1] (0 for deg < 0) */
double sx_poly_abs_sum(const double *p, int deg);
double sx_poly_deriv(const double *p, int deg, double u);
/* the first u in (0, 1] where g = p + r changes sign from g(0) > 0 (p within `err` of the function),
 * or 2 if none */
double sx_poly_first_root(const double *p, int deg, double err);
/* max |p| over [0, b] if it exceeds best (else best) */
double sx_poly_max_abs(const double *p, int deg, double err, double b, double best);
/* integral over [0, b] of p */
double sx_poly_integral(const double *p, int deg, double b);
/* the square of p (degree 2 deg) */
void sx_poly_square(const double *p, int deg, double *sq);
/* the integral over [0, u] of p(v)^2 (p of degree deg) */
double sx_poly_square_integral(const double *p, int deg, double u);
void sx_poly_product(const double *p, const double *q, int deg, double *pq);

/* ---- modes (rw_scene_exact_modes.c) ---- */
void sx_modes_build(sx_region *r);
/* the modes of a region whose first-order matrix is r's: all but the constant's modal forcing */
void sx_modes_adopt(sx_region *r, const sx_modes *of);
/* the bounds' allowance for the decomposition's rounding: the modal values' error relative to
 * their size is a few ulps times the condition */
#define SX_MODES_MARGIN(cond) (256.0 * DBL_EPSILON * (cond) + 1e-12)

/* ---- the quiet test's polynomials from a step's exact ends: the modes' bounds
 * (rw_scene_exact_hermite.c), the cubics from them (sx_hermite_polys: rw_scene_exact_quick.c) ---- */
/* a mode over a step besides its tails and size (sx_mode_bounds' arrays): whether it is a band, and a
 * band's free part at the step's ends (value at 0 and 1, rate in u at 0 and 1: real and imaginary
 * parts), which the ends' data give up */
typedef struct {
    double psize; /* a band's particular part's size */
    int band;
    double re[4], im[4];
} sx_mode_bound;

/* the modes' bounds over a step from its start xa0 */
typedef struct {
    double h;        /* the step's length */
    int bands;       /* how many modes are bands */
    int modal;       /* a band turns so fast over the step (SX_BAND_MODAL_WH) that the ends' data come from
                        the modes' own coordinates (sx_ends_modal) */
    sx_mode_bound mode[SX_MAX_N]; /* (set where the step holds bands: read only there) */
    /* each mode's share of the departure from a functional's interpolant per unit of the functional's
     * share |a| of it, for the value and for its rate in u, and the size behind its part of the ends'
     * data (for the rounding's margin): one array each, which the quiet test sums over the
     * functionals' shares in one product */
    double err[SX_MAX_N], derr[SX_MAX_N], size[SX_MAX_N];
} sx_mode_bounds;

/* the constants of a step of length h (the region's modes valid) */
void sx_hermite_step_of(const sx_region *r, double h, sx_hermite_step *hs);
/* each functional's bounds on the departure from its cubic over a window of steps (its constants hs)
 * that kinks of the record inside it add, per unit of a slope's change and of the kernel's bound:
 * through the modes and through its own term in the record */
void sx_kink_of(const sx_region *r, const sx_hermite_step *hs, double modes[SX_MAX_F], double record[SX_MAX_F]);
/* the kernel's bounds for a kink at the j-th of n steps' ends inside a window (0 < j < n <= SX_WINDOW) */
void sx_window_kinks(int n, int j, double *value, double *record);
/* The data of the interpolant (each functional's values and rates at a step's ends) are the motion's
 * own less each band's free part. Where a band turns past this many radians over the step (a
 * diaphragm of grams per metre: 1e7 rad/s), its rate at the ends is so large that taking it out of
 * the physical rate leaves the rounding of its coordinate times |lam h| in the slow part's; there
 * the data are summed from the modes' own coordinates instead, which the band's rate never enters. */
#define SX_BAND_MODAL_WH 32.0
/* the ends' data (values and rates in u) from the modes' own coordinates, the bands' free parts out */
void sx_ends_modal(const sx_region *r, const sx_mode_bounds *B, const double xa0[], const double xa1[], double *v0,
                   double *v1, double *d0, double *d1);
/* the modes' bounds over a step (its constants hs) from its start xa0 (the region's modes valid) */
void sx_mode_bounds_of(const sx_region *r, const sx_hermite_step *hs, const double xa0[], sx_mode_bounds *B);
/* the same, each mode's bounds taken one mode at a time as a region with blocks takes them (the
 * tests hold sx_mode_bounds_of's vectorised pass to it, to the bit) */
void sx_mode_bounds_each(const sx_region *r, const sx_hermite_step *hs, const double xa0[], sx_mode_bounds *B);
/* a cubic's range over a step as the centre and half-width of its Bernstein coefficients' hull,
 * widened by its tail (a NaN leaves both NaN: nothing is clear of it) */
static inline void sx_cubic_box(double b0, double b1, double b2, double b3, double tail, double *centre,
                                double *radius)
{
    const double lo01 = b0 < b1 ? b0 : b1, lo23 = b2 < b3 ? b2 : b3, hi01 = b0 > b1 ? b0 : b1, hi23 = b2 > b3 ? b2 : b3;
    const double lo = lo01 < lo23 ? lo01 : lo23, hi = hi01 > hi23 ? hi01 : hi23;
    *centre = 0.5 * (lo + hi);
    *radius = lo == lo && hi == hi ? 0.5 * (hi - lo) + tail : NAN;
}
/* each functional's cubic Hermite interpolant over a step (its constants hs) from its values and
 * rates at the exact ends xa0 and xa1 = exp(Aa h) xa0 (Bernstein coefficients), with the modes'
 * bound on the motion's departure from it as the tail; 0 if the region has no usable modes */
int sx_hermite_polys(const sx_region *r, const sx_hermite_step *hs, const double xa0[], const double xa1[],
                     sx_lopoly P[SX_MAX_F]);

/* ---- nearly defective pairs of modes (rw_scene_exact_blocks.c) ---- */
/* dgeev's basis Vr (row-major; eigenvalues wr + i wi) with its balanced inverse Winv: the real
 * pair whose own condition is the worst made a block (blocked: 1 and 2 at its columns, moved to
 * the end); 1 if one was, 0 if none can be */
int sx_block_worst_pair(const sx_region *r, double *wr, double *wi, int *blocked, double *Vr, const double *Winv);
/* the block at columns a, a + 1: B = Winv(rows a, a + 1) A Vr(columns a, a + 1), row-major */
void sx_block_matrix(const sx_region *r, const double *Vr, const double *Winv, int a, double B[4]);
/* each mode's coupling to the blocks: the 2-norm of its rows of Winv A Vr(a block's columns),
 * summed over the blocks (the blocks' planes are invariant to rounding only) */
void sx_block_coupling(const sx_region *r, const double *Vr, const double *Winv, sx_modes *m);

/* ---- watching a step (rw_scene_exact_watch.c) ---- */
/* the quiet test on given polynomials of the functionals over a step of length h from xa0 in the
 * current region, on the storeys in the bit set storeys (SX_ALL_STOREYS: every one; a storey left
 * out must be clear by other means): 0 (quiet: then the peaks are those of the step's ends,
 * sx_watch_peaks_at, and of the doubts it left, sx_doubt_peak), or the first reason why not it
 * found (SX_MAY_PEAK only where no doubt could be kept) */
enum { SX_MAY_CROSS = 1, SX_MAY_PEAK = 2 };
#define SX_ALL_STOREYS (~0u)
int sx_watch_quiet_polys(sx_run *R, const sx_region *r, sx_lopoly P[SX_MAX_F], double h, const double xa0[],
                         unsigned storeys);
/* what the quiet test could not clear over a step, per storey: bits of the wall's lines (bit 31: its
 * collapse indicator), of its bilinear diaphragm's indicators, and of its peak quantities */
typedef struct {
    unsigned wall[RW_SCENE_MAX_STOREYS], diaphragm[RW_SCENE_MAX_STOREYS], peaks[RW_SCENE_MAX_STOREYS];
} sx_suspects;
#define SX_COLLAPSE_BIT (1u << 31) /* a wall's suspect collapse indicator (its lines: bits 0..SX_MAX_LINES-1) */
/* the quiet test's suspects on given polynomials (no doubt kept): 0 if none */
int sx_watch_suspects(sx_run *R, const sx_region *r, sx_lopoly P[SX_MAX_F], sx_suspects *sus);
/* the centre and half-width of a polynomial's range over its step */
void sx_watch_box(const sx_lopoly *p, double *centre, double *radius);
/* the lines of storey i's wall the box of q1's and q2's ranges (centres c, half-widths r; Q: |q|
 * at the start, for the lines' rounding) does not clear at once: bit k for line k */
unsigned sx_watch_box_lines(const sx_run *R, int i, double c1, double r1, double c2, double r2, double Q1, double Q2);

/* ---- the quiet test from a step's exact ends (rw_scene_exact_quick.c) ---- */
/* the quiet test of a step from xa0 to its exact end xa1 (the region's modes valid; the step's
 * constants hs): a first pass on every functional's polynomial at once, then, on the storeys it does
 * not clear, the full test (sx_watch_quiet_polys) on the same polynomials; quiet (0), the end's
 * peaks are taken */
int sx_quiet_ends(sx_run *R, const sx_region *r, const sx_hermite_step *hs, const double xa0[], const double xa1[]);
/* the first pass over a window of n steps of table st from xa[0] over xa[1..n-1] (each the start of
 * a step, the record's sample in it) to its end xe: 0 if it clears every storey (the peaks at the
 * samples inside and at the end are then taken), else 1 */
int sx_quiet_window(sx_run *R, const sx_region *r, const sx_step *st, int n, double xa[][SX_MAX_NA], const double xe[]);

/* 1 if a standing wall's indicator line surely changes sign between a step's exact ends xa0 and xa1
 * (then the quiet test cannot clear the step, and need not run), else 0 */
int sx_watch_sure_cross(const sx_run *R, const sx_region *r, const double xa0[], const double xa1[]);
/* the peaks at a state of the region (a quiet step's exact end, the state after an event) */
void sx_watch_peaks_at(sx_run *R, const sx_region *r, const double xa[]);
/* the walls' indicator lines under the current modes (after every event) */
void sx_watch_lines(sx_run *R);
/* the quiet test of a step from its start state with its table: 1 when no indicator can change
 * sign and no peak can rise over it unnoticed (then xa1 = exp(Aa h) xa0, the end, and the peaks
 * are those of the ends and of the doubts it left), else 0 (xa1 not set) */
int sx_watch_quiet(sx_run *R, const sx_region *r, const sx_step *st, const double xa0[], double xa1[]);
/* the first root over a step's series (u in (0, 1], or 2 if none), with the peaks up to it: of the
 * suspects only (the others cleared over the whole step), or of everything (sus NULL) */
double sx_watch_step(sx_run *R, const sx_region *r, const sx_series *s, const sx_suspects *sus);
/* the modes' bound on |storey i's peak quantity `kind`| over a step of length h from xa0 to its
 * exact end xa1 if it may rise over that quantity's peak inside the step, else 0 (INFINITY: the
 * region has no usable modes) */
double sx_watch_peak_bound(sx_run *R, const sx_region *r, double h, const double xa0[], const double xa1[], int storey,
                           int kind);
/* the largest |value| of storey i's peak quantity `kind` over [0, 1] of a series, if over best */
double sx_series_peak(const sx_run *R, const sx_region *r, const sx_series *s, int storey, int kind, double best);
/* the work of the ground and of the dashpots over [0, u] of a series */
void sx_series_work(const sx_region *r, const sx_series *s, double u, double *w_ground, double *w_damping);

/* ---- peaks left in doubt by quiet steps (rw_scene_exact_peaks.c) ---- */
/* the running peak of storey i's quantity `kind` */
double *sx_peak_of(rw_scene_result *res, int storey, int kind);
/* keeps a doubt on the current region's step [0, h] from xa0: 0, or 1 if it cannot be kept (no
 * memory: the caller resolves the step instead) */
int sx_doubt_peak(sx_run *R, int storey, int kind, double bound, double h, const double xa0[]);
/* resolves the doubts on region slot `region` (-1: all of them, the largest bounds first, each
 * only while its bound is over its quantity's peak) and forgets them: before the region is
 * rebuilt for another key, and at the run's end */
void sx_settle_doubts(sx_run *R, int region);
void sx_free_doubts(sx_run *R);

#endif
