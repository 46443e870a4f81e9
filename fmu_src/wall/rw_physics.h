/* RockingWall physics: the equations of motion of docs/model.md in plain C99 (no FMI types), the
 * wall's one public header. Implemented by job: rw_dynamics.c (derived quantities, equations of
 * motion), rw_indicators.c (event indicators, collapse), rw_outputs.c (outputs, energy),
 * rw_events.c (event rules), rw_hinge_laws.c (one entry per hinge law).
 *
 * State vector x = (q1, q2, dq1, dq2): absolute rotations of the lower and upper body (clockwise
 * positive) and their rates. Models 1 (parapet) and 2 (simplySupported) keep q2 slaved to q1
 * (q2 = q1, resp. q2 = -q1). The discrete state, the contact regime (sides and closed flags of the
 * hinges), lives in rw_regime and changes only in rw_event_update() (event mode of the FMU);
 * everything else is a pure function of (parameters, regime, inputs, x). "Modes" are the
 * eigenmodes of the exact engine's regions (rw_engine.h), nothing else.
 */
#ifndef RW_PHYSICS_H
#define RW_PHYSICS_H

#include <math.h>
#include <stddef.h>

#include "rw_parameters.h"
#include "rw_symbols.h" /* the FMI2_FUNCTION_PREFIX of every external function */

/* values of the parameter `support` (rw_parameters.h) */
enum { RW_PARAPET = 1, RW_SIMPLY_SUPPORTED = 2, RW_FLEXIBLE_TOP = 3 };
/* values of the parameter `hingeLaw`; each law is one entry of rw_hinge_laws.c */
enum { RW_RIGID = 1, RW_SEMI_RIGID_PAPER = 2, RW_SEMI_RIGID_HINGE = 3, RW_DOHERTY_HINGE = 4 };

#define RW_NX 4     /* q1, q2, dq1, dq2 */
#define RW_NBREAK 4 /* breakpoint indicators of a hinge law: base 1, base 2, mid 1, mid 2 */

/* Event indicator layout (continuous functions in continuous-time mode; values 1 = unused). */
enum {
    RW_Z_BASE = 0,     /* base hinge open: side_b*q1 + eps (impact); closed: 1 - |f_b|/cap + eps (opening) */
    RW_Z_MID = 1,      /* flexibleTop mid open: side_m*(q2-q1) + eps (switch); closed: 1 - |f_m|/cap_m + eps */
    RW_Z_BREAK = 2,    /* RW_NBREAK breakpoints of the hinge law (kinks of Q(q)), see rw_hinge_law */
    RW_Z_COLLAPSE = RW_Z_BREAK + RW_NBREAK, /* > 0 while stable: parapet 1-|theta|/alpha, 1DOF 1-|D|/Delta_u, 2DOF G(q)/|q|^2 */
    RW_Z_TOPPLE,       /* 2DOF: 1 - max(|q1|, |q2|)/(2b/h), the geometric toppling limit of a body */
    RW_NZ
};

/* why a wall is taken as collapsed (rw_collapse_reason) */
enum { RW_STANDING = 0, RW_PAST_INSTABILITY = 1, RW_PAST_TOPPLING_LIMIT = 2 };

/* An event indicator that is a function of the rotations alone, as data, so that the exact engine
 * evaluates it along a motion without a call: z = c + s |w| + t w with w = a.q (a line t = 1,
 * s = 0, or a breakpoint |w| = -c/s with t = 0); `none`: not of this form (the collapse and
 * toppling indicators, a closed hinge's). rw_line_value is the one evaluation, for the FMU's
 * indicators and the engine. */
typedef struct {
    double a[2], s, t, c;
    int none;
} rw_indicator_line;

/* The breakpoint where w = a0 q1 + a1 q2 reaches lim_p (w > 0) or -lim_n (w < 0), as a line:
 * z = c + |w| + t w with t = (lim_n - lim_p)/(lim_p + lim_n), c = -(1 + t) lim_p, zero at both
 * (|w| = lim_p, resp. -c/(1 - t) = lim_n); |w| - lim when both limits are lim. */
static inline rw_indicator_line rw_kink_line(double a0, double a1, double lim_p, double lim_n)
{
    const double t = (lim_n - lim_p) / (lim_p + lim_n);
    const rw_indicator_line line = {{a0, a1}, 1.0, t, -(1.0 + t) * lim_p, 0};
    return line;
}

/* z of the line at the rotations q = (x[0], x[1]) and its rate *dz along the rotation rates
 * (xd[0], xd[1]) (xd, dz may be NULL); no branch, so that the engine's loop over all lines stays
 * short */
static inline double rw_line_value(const rw_indicator_line *L, const double *x, const double *xd, double *dz)
{
    const double w = L->a[0] * x[0] + L->a[1] * x[1];
    if (dz) *dz = (L->s * ((w > 0.0) - (w < 0.0)) + L->t) * (L->a[0] * xd[0] + L->a[1] * xd[1]);
    return L->c + L->s * fabs(w) + L->t * w;
}

/* The quantities of one direction d of the mid-height's motion (docs/model.md "Derived"; +1 toward
 * +x, the inner face): they differ between the directions when the top load is eccentric. */
typedef struct {
    double Du, Fr, F0, Rel;    /* Delta_u(d), F_r(d), F0(d), R_el(d) (Table 5.1; C8's Delta_i) */
    double D1, D2, Fi;         /* Delta_1, Delta_2 (Eq. 5.1, 5.2), plateau F_i */
    double theta_y;            /* 2*hingeSat*Delta_1/h */
} rw_direction;

/* index of a side or a direction (+1 -> 0, -1 -> 1; 0 counts as +1) in the arrays below */
#define RW_SIDE(s) ((s) < 0)

typedef struct {
    double h;                  /* wall height (for the laws written in mid-height displacements) */
    double W1, Wd, Wo;         /* W1 = W2 = W/2, Wd = psi*W1 (weight and mass), Wo = psiWeightOnly*W1 (weight) */
    double e_b, e_m, Et;       /* the reactions' lever arms (eBaseRatio, eHingeRatio of t/2), Et = Wd*eTop */
    rw_direction dir[2];       /* per direction d of the mid-height's motion, [RW_SIDE(d)] */
    double cap_b, cap_m;       /* the hinge capacities' means over both sides: (2 W1 + Wd + Wo) e_b, (W1 + Wd + Wo) e_m */
    double cap_bs[2], cap_ms[2]; /* the capacities on a hinge's side s, [RW_SIDE(s)]: cap - s*Et */
    double M[2][2], K[2][2];   /* Eq. 3.2, 3.3 */
    double pa[2];              /* p = pa*ag (Eq. 3.4, sign per convention) */
    double fu;                 /* f_u = fu*u_top*(1,1), fu = Kd*h/2 */
    double Bp, Hp, R, alpha, p2; /* parapet (Housner): pivot's lever arm e_b, h/2, pivot to centroid, ... */
    double Ir;                 /* parapet: (4/3) R^2 over its inertia about the pivot per mass (1 with the pivot on the face) */
    double zscale;             /* normalisation of the 2DOF collapse indicator (W*h) */
    double q_topple;           /* 2b/h: rotation at which a body's centre of gravity passes over its pivot */
    double inv_q_topple;       /* its inverse */
    double tiny;               /* rotation below which the direction of motion decides a side */
    rw_indicator_line breaks[RW_NBREAK]; /* the hinge law's breakpoints (rw_hinge_law.breakpoints), fixed by the wall */
} rw_derived;

/* The 2DOF collapse indicator z = G(q)/(|q|^2 zscale), clipped at RW_COLLAPSE_ZMAX, on a region
 * whose hinge moments are Q = c + J q: G = q.(K q - Q) = q.A q - c.q with A = K - J (docs/model.md
 * "Collapse"), as data for the exact engine (rw_collapse_form_of); its rate along dq is
 * dG = q.(A + A^T) dq - c.dq. The FMU's own value comes from rw_collapse_G_of with the law's Q. */
#define RW_COLLAPSE_ZMAX 1e3
typedef struct {
    double A[2][2], c[2], zscale, inv_zscale;
} rw_collapse_form;

static inline double rw_collapse_form_value(const rw_collapse_form *f, const double *x, const double *xd, double *dz)
{
    const double q1 = x[0], q2 = x[1], n2 = q1 * q1 + q2 * q2;
    const double Aq1 = f->A[0][0] * q1 + f->A[0][1] * q2, Aq2 = f->A[1][0] * q1 + f->A[1][1] * q2;
    double v;
    if (dz) *dz = 0.0;
    if (!(n2 > 0.0)) return RW_COLLAPSE_ZMAX;
    const double inv_n2 = 1.0 / n2; /* one division: the engine evaluates this at every substep */
    v = (q1 * Aq1 + q2 * Aq2 - (f->c[0] * q1 + f->c[1] * q2)) * (inv_n2 * f->inv_zscale);
    if (v > RW_COLLAPSE_ZMAX) return RW_COLLAPSE_ZMAX;
    if (dz) {
        const double dq1 = xd[0], dq2 = xd[1];
        const double ATq1 = f->A[0][0] * q1 + f->A[1][0] * q2, ATq2 = f->A[0][1] * q1 + f->A[1][1] * q2;
        const double dG = (Aq1 + ATq1 - f->c[0]) * dq1 + (Aq2 + ATq2 - f->c[1]) * dq2;
        *dz = (dG * f->inv_zscale - 2.0 * v * (q1 * dq1 + q2 * dq2)) * inv_n2;
    }
    return v;
}

/* The 2DOF toppling indicator 1 - max(|q1|, |q2|)/q_topple and its rate (xd, dz may be NULL), with
 * d->inv_q_topple = 1/q_topple: no division, as the engine evaluates it at every substep */
static inline double rw_topple_value(const rw_derived *d, const double *x, const double *xd, double *dz)
{
    const int i = fabs(x[0]) >= fabs(x[1]) ? 0 : 1;
    if (dz) *dz = -((x[i] > 0.0) - (x[i] < 0.0)) * xd[i] * d->inv_q_topple;
    return 1.0 - fabs(x[i]) * d->inv_q_topple;
}

/* A 2DOF hinge law: everything that differs between laws, in one place (rw_hinge_laws.c).
 * Generalised hinge moments Q = (-cap_b*mu_b + cap_m*mu_m, -cap_m*mu_m) for the laws that come
 * from a potential; every law's Q(q) is piecewise affine between its breakpoints. */
typedef struct {
    int id;
    const char *name;
    int set_valued; /* mu = sign at zero rotation: rigid hinges, with rest and closed-hinge states */
    /* Q(q) and its Jacobian J = dQ/dq (constant between breakpoints). side_b, side_m: the active
     * sides (they decide the set-valued laws and the paper's conditions); dq decides the region
     * when q sits on a breakpoint (the one the motion goes into). */
    void (*moments)(const rw_derived *d, int side_b, int side_m, const double q[2], const double dq[2],
                    double Q[2], double J[2][2]);
    /* V_h(q) with Q = -grad V_h (semiRigidPaper has none: its value is a measure, not conserved) */
    double (*potential)(const rw_derived *d, const double q[2]);
    /* RW_NBREAK indicators crossing zero where Q(q) has a kink, as lines (the constant 1 = unused) */
    void (*breakpoints)(const rw_derived *d, rw_indicator_line lines[RW_NBREAK]);
    /* 1 inside the first linear range of every hinge (collapse is not tested there); on its end
     * itself (to rounding, as at the event there) the direction of motion dq decides */
    int (*elastic)(const rw_derived *d, const double q[2], const double dq[2]);
    /* 1 if Q depends on q alone (not on the sides, no kink at zero rotation), so that Q = c + J q
     * holds on the whole linear region the motion is in (the exact engine evaluates it so), on a
     * symmetric wall: rw_moments_of_q_alone says it for a wall */
    int q_only;
} rw_hinge_law;

/* The law of a hingeLaw value, NULL if none. */
const rw_hinge_law *rw_hinge_law_of(int id);

/* The capacity of a hinge turning to side s (the base: q1, the mid-height hinge: q2 - q1) */
static inline double rw_cap_b_of(const rw_derived *d, double s) { return d->cap_bs[RW_SIDE(s)]; }
static inline double rw_cap_m_of(const rw_derived *d, double s) { return d->cap_ms[RW_SIDE(s)]; }

/* offsets of the hinge event indicators (rotation, relative force margin) */
#define RW_EPS_Q(d) (0.1 * (d)->tiny)
#define RW_EPS_F 1e-12

typedef struct {
    int closed_b, closed_m; /* rigid hinges: 1 = closed (rest / closed-hinge state) */
    int side_b, side_m;     /* active side of each hinge, +1 / -1 */
    double zoff_b, zoff_m;  /* offsets of the open-hinge event indicators side*rotation + zoff, set at
                               each event so that the indicator is >= eps_q > 0 when integration restarts */
    int uplifted_b;         /* semi-rigid laws: the base has passed the end of its elastic range (the
                               law's first base breakpoint) since the last base crossing, so the next
                               crossing is a base impact that is counted (docs/model.md "Impacts") */
    int tie_held;           /* flexibleTop: the top spring is held rigid (rw_rigid_tie.c; Model Exchange
                               sets it after rw_init_regime, which clears it): q2 = -q1, and a
                               rigid law's hinges rest and open together */
} rw_regime;

typedef struct {
    double ag;    /* ground acceleration, + toward +x [m/s2] */
    double u_top; /* diaphragm displacement [m] */
} rw_input;

/* Parameters and derived quantities (rw_dynamics.c; the table, defaults and per-value checks:
 * rw_parameters.h) ------------------------------------------------------------------------------ */
/* Every range, then the rules that tie parameters together. 0 = ok, else msg filled. */
int rw_params_validate(const rw_params *p, char *msg, size_t n);
void rw_derive(const rw_params *p, rw_derived *d);

/* The wall's statics as a user reads them (the package's Wall): per direction d of the
 * mid-height's motion, [RW_SIDE(d)], Delta_u(d) (NZSEE C8's Delta_i) and F_r(d); per side s of a
 * hinge, [RW_SIDE(s)], its capacity. */
typedef struct {
    double Du[2], Fr[2], cap_b[2], cap_m[2];
} rw_statics;
/* Checks the parameters (rw_params_validate), then fills s. 0 = ok, else msg filled. */
int rw_wall_statics(const rw_params *p, rw_statics *s, char *msg, size_t n);

/* Is the hinge law set-valued (rest / closed-hinge states)? */
int rw_is_rigid(const rw_params *p);
/* 1 when the hinge moments are a function of q alone, affine on the whole region between the law's
 * breakpoints (rw_hinge_law.q_only), on this wall: not where an eccentric top load (psi and eTop
 * not 0) gives each side its own capacity and breakpoints, whose slopes differ at zero rotation. */
int rw_moments_of_q_alone(const rw_params *p);
/* 1 when the mid-height hinge's switch changes the `condition` output and nothing else: flexibleTop
 * with moments of q alone (rw_moments_of_q_alone: semiRigidHinge, dohertyHinge on a symmetric wall;
 * the rigid law's and semiRigidPaper's moments take the sides). The exact engine does not stop
 * there, and brings the side up to date (rw_sync_mid_side) at its events and where it reports. */
int rw_mid_switch_is_bookkeeping(const rw_params *p);

/* Dynamics (rw_dynamics.c) --------------------------------------------------------------------- */
/* Hinge terms Q(q) of the 2DOF for the open-hinge case (rigid: mu = sides), from the law. */
void rw_hinge_Q(const rw_params *p, const rw_derived *d, const rw_regime *m, const double x[RW_NX], double Q[2]);
/* Trilinear / rigid resisting force F(D) of the 1DOF (Doherty), rigid uses side for sign(D). */
double rw_force_1dof(const rw_params *p, const rw_derived *d, const rw_regime *m, double D);
/* For the exact engine: the same force as F0 + F1*D on the region the motion (dD) goes into. */
void rw_force_1dof_affine(const rw_params *p, const rw_derived *d, const rw_regime *m, double D, double dD,
                          double *F0, double *F1);
void rw_derivatives(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                    const double x[RW_NX], double dx[RW_NX]);
/* Generalised moments a closed rigid hinge must resist (spec "Opening tendency"), less the
 * asymmetry delta = (cap(+1) - cap(-1))/2 of its capacities: the hinge opens where |f| exceeds
 * rw_caps' mean capacity, on side sign(f) (docs/model.md "Rigid hinges"). */
void rw_closed_forces(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                      const double x[RW_NX], double *f_b, double *f_m);
/* The moments rw_closed_forces gives under m, (f_b, f_m) = c + G q + g_ag ag + g_u u_top, with the
 * inverses of the capacities, as data for the exact engine (rw_closed_force_form) */
typedef struct {
    double c[2], G[2][2], g_ag[2], g_u[2], inv_cap[2];
} rw_closed_form;
void rw_closed_force_form(const rw_params *p, const rw_derived *d, const rw_regime *m, rw_closed_form *f);
/* Capacities matching rw_closed_forces, their means over both sides (parapet: g tan(alpha),
 * simplySupported: (F_r(+1) + F_r(-1))/2, 2DOF: cap_b, cap_m). */
void rw_caps(const rw_params *p, const rw_derived *d, double *cap_b, double *cap_m);

/* Event indicators (rw_indicators.c) ----------------------------------------------------------- */
void rw_event_indicators(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                         const double x[RW_NX], double z[RW_NZ]);
/* The same indicators, those of `mask` (bit k = indicator k; the others are left), with
 * the hinge moments Q(q) at x given by the caller (NULL: from the law). One definition of the rules
 * for the FMU and the exact engine: the engine asks only for what it needs (one indicator while it
 * refines a root) and passes the affine Q of its current linear region where the law's Q depends
 * on q alone (rw_hinge_law.q_only), which spares the law's case analysis at every evaluation. */
#define RW_Z_ALL ((1u << RW_NZ) - 1u)
void rw_event_indicators_some(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                              const double x[RW_NX], const double *Q, unsigned mask, double z[RW_NZ]);
/* The indicators of the rigid hinges that are closed under m (bit k = indicator k): not lines but
 * 1 - |f|/cap + eps_f, with f affine in the inputs and one rotation */
unsigned rw_closed_hinge_mask(const rw_params *p, const rw_regime *m);
/* The indicators that are lines of the rotations under the regime m (rw_indicator_line; the others
 * marked none): they change only with the regime, so the exact engine takes them once per region. */
void rw_indicator_lines(const rw_params *p, const rw_derived *d, const rw_regime *m, rw_indicator_line lines[RW_NZ]);
/* The same indicators of `mask` (the others left) with their rates dz = dz/dt along a motion: the state moving at
 * xd = dx/dt and the inputs at in_rate (d ag/dt, d u_top/dt). Q, J: the hinge moments at x and
 * their Jacobian dQ/dq, both given or both NULL (from the law). The exact engine's bracketing and
 * root refinement use the rates (docs/engine.md). */
void rw_event_indicator_rates(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                              const rw_input *in_rate, const double x[RW_NX], const double xd[RW_NX],
                              const double *Q, const double (*J)[2], unsigned mask, double z[RW_NZ],
                              double dz[RW_NZ]);
/* The collapse indicator's form on the region Q = c + J q (rw_collapse_form) */
void rw_collapse_form_of(const rw_derived *d, const double c[2], const double J[2][2], rw_collapse_form *f);
/* G(q) = q.(K q - f_u - Q(q)) of the 2DOF (collapse when <= 0 outside the elastic range). */
double rw_collapse_G(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                     const double x[RW_NX]);
/* The same G with the hinge moments Q at x given (one formula for both). */
double rw_collapse_G_of(const rw_derived *d, const double x[RW_NX], const double Q[2]);
/* RW_STANDING, or why x is taken as collapsed (spec "Collapse"). */
int rw_collapse_reason(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                    const double x[RW_NX]);

/* Outputs and energy (rw_outputs.c) ------------------------------------------------------------ */
double rw_energy(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                 const double x[RW_NX]);
/* Rate of work of the ground motion on the wall (energy bookkeeping). */
double rw_ground_power(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                       const double x[RW_NX]);
double rw_s1(const rw_params *p, const double x[RW_NX]);
double rw_s2(const rw_params *p, const double x[RW_NX]);
double rw_F_top(const rw_params *p, const rw_input *in, const double x[RW_NX]);
/* Horizontal force of the wall on its base, + toward +x, from the horizontal momentum balance of
 * the bodies and the overburden (docs/model.md "Base force"); dx = rw_derivatives(x). */
double rw_F_base(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                 const double x[RW_NX], const double dx[RW_NX]);
/* The same with the top's force F_top given (the rigid tie's reaction, rw_rigid_tie_motion) */
double rw_F_base_given_top(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                           const double x[RW_NX], const double dx[RW_NX], double F_top);
int rw_condition(const rw_params *p, const rw_regime *m);

/* A stiff tie held rigid (rw_rigid_tie.c) ---------------------------------------------------------
 * omega^2 of the wall's stiffest mode without the spring over that of the tie's own mode. */
double rw_tie_stiffness_ratio(const rw_params *p, const rw_derived *d);
/* Below this ratio the tie is held rigid: the answers differ by about the ratio (relative), less
 * than the tolerance integrators are run at (fmi2sim's default rtol is 1e-8) */
#define RW_RIGID_TIE_RATIO 1e-5
/* The rigid law's hinges have no elastic range: its answer converges this many times more slowly
 * in the ratio (measured: docs/model.md "A stiff tie held rigid"), so its ratio counts so much more */
#define RW_RIGID_LAW_TIE_FACTOR 100.0
/* 1 if a flexible-top wall in regime m may move with its tie held rigid from x on: the ratio (times
 * RW_RIGID_LAW_TIE_FACTOR for the rigid law) at most RW_RIGID_TIE_RATIO, the far end still
 * (u_top = 0), the top at rest there (q1 + q2 = 0, dq1 + dq2 = 0), and a rigid law's hinges both
 * open or both closed */
int rw_tie_holds_rigid(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                       const double x[RW_NX]);
/* 1 if the Model Exchange FMU holds the tie of wall p started at rest with u_top = 0 (for hosts
 * that compare it with the exact engine, which never holds it) */
int rw_tie_held_from_rest(const rw_params *p);
/* The derivatives with the tie held rigid (q2 = -q1), and the tie's force F_top (the reaction; 0
 * at rest, where the closed hinges carry everything) */
void rw_rigid_tie_motion(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                         const double x[RW_NX], double dx[RW_NX], double *F_top);
/* A held tie's rigid hinges at rest: the force the mechanism q = theta (1, -1) must resist, as
 * rw_closed_forces gives a closed base's (scaled to the base's mean capacity, less the asymmetry),
 * and 0 for the mid-height hinge, which opens with the base */
void rw_rigid_tie_closed_forces(const rw_params *p, const rw_derived *d, const rw_input *in, double *f_b,
                                double *f_m);
/* The tie's force F_top in regime m: the held tie's reaction, else the spring's rw_F_top */
double rw_tie_force(const rw_params *p, const rw_derived *d, const rw_regime *m, const rw_input *in,
                    const double x[RW_NX]);

/* Event rules (rw_events.c) -------------------------------------------------------------------- */
typedef void (*rw_log_fn)(void *ctx, const char *message);

typedef struct {
    int impacts;        /* base impacts applied */
    int states_changed; /* a continuous state jumped */
    int regime_changed; /* the contact regime changed */
} rw_event_result;

/* Initial regime from the start states (spec "Initial state"); slaves q2 for models 1, 2. */
void rw_init_regime(const rw_params *p, const rw_derived *d, const rw_input *in, double x[RW_NX],
                    rw_regime *m, rw_log_fn log, void *ctx);
/* After rw_init_regime: hold the tie from here on if rw_tie_holds_rigid allows (a rigid law at
 * rest is first closed at both hinges and opened by the held tie's rule, whatever the free top's
 * test did). 1 if held. (rw_events.c) */
int rw_hold_tie(const rw_params *p, const rw_derived *d, rw_regime *m, const rw_input *in, double x[RW_NX],
                rw_log_fn log, void *ctx);
/* Event-mode update: impacts, mid-hinge switches, closing and opening of rigid hinges. */
void rw_event_update(const rw_params *p, const rw_derived *d, rw_regime *m, const rw_input *in,
                     double x[RW_NX], rw_event_result *r, rw_log_fn log, void *ctx);
/* The mid-height hinge's side brought up to date with x by rw_event_update's own rule, for a
 * caller that did not stop at its switch (rw_mid_switch_is_bookkeeping). Returns 1 if it switched. */
int rw_sync_mid_side(const rw_params *p, const rw_derived *d, rw_regime *m, const double x[RW_NX]);
/* Opening test of closed rigid hinges only (part of rw_event_update). Returns 1 if a hinge opened. */
int rw_open_hinges(const rw_params *p, const rw_derived *d, rw_regime *m, const rw_input *in,
                   const double x[RW_NX], rw_log_fn log, void *ctx);

#endif
