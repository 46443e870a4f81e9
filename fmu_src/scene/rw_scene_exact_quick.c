/* The quiet test of a step from its exact ends, and its first pass: the common case between events,
 * in few operations. Every functional's polynomial comes in one pass over the modes (the cubic
 * Hermite interpolant of the step's exact ends, bounded by rw_scene_exact_hermite.c, as arrays over
 * the functionals: cubics_of, which the full test's polynomials come from too); each standing
 * wall's lines are tested at once on the box of its rotations' ranges, and each peak quantity is
 * held against its peak by the bound its polynomial's coefficients give. A step that passes is
 * quiet, and its end's peaks are taken from the values the pass computed. The storeys it does not
 * clear (a line or a peak near, a collapse indicator in play, a bilinear diaphragm's indicators) are
 * given the full test (sx_watch_quiet_polys), which clears everything this pass does. */
#include "rw_scene_exact_internal.h"

#include <float.h>
#include <math.h>

/* every functional's cubic over a step as arrays over the functionals (two to a vector register, the
 * arrays' last entry a zero pair for an odd count): Bernstein coefficients b[0..3] (a band's free
 * motion taken out), tails, and the exact values at the step's start and end */
typedef struct {
    double b[4][SX_MAX_F + 1], tail[SX_MAX_F + 1], dtail[SX_MAX_F + 1], start[SX_MAX_F], end[SX_MAX_F];
    double bmax[SX_MAX_F]; /* the largest |b_k| (a NaN among them shows in the tails: abs_max) */
} cubics;

/* the modes' tails over the functionals: tail_f = sum_k |a_fk| err_k (and the rate's, and the sizes'),
 * the shares by columns (the modes) times the modes' bounds in one pass; each functional's sum runs
 * over the modes in order from zero, as a loop over them would */
static void tails_over(const sx_modes *m, const sx_mode_bounds *B, int nf, cubics *Q, double *size)
{
    const double *const by_mode[3] = {B->err, B->derr, B->size};
    double *const sums[3] = {Q->tail, Q->dtail, size};
    sx_matvec3_lead(nf, m->count, SX_MAX_F + 1, m->share_abs[0], by_mode, sums);
}

/* the bands' free motion taken out of the ends' data, over the functionals two at a time (the share
 * arrays hold zeros past the last functional, and the cubics' arrays room for them) */
static SX_ALWAYS_INLINE void bands_out(const sx_modes *m, const sx_mode_bounds *B, int nf, cubics *Q,
                                       double *d0, double *d1)
{
    int f, k;
    for (k = 0; k < m->count; k++) {
        const sx_mode_bound *mb = &B->mode[k];
        if (!mb->band) continue;
        for (f = 0; f < nf; f += 2) { /* Re(a w) in real arithmetic */
            const sx_v2 ar = sx_load2(m->share_re[k] + f), ai = sx_load2(m->share_im[k] + f);
            sx_store2(Q->b[0] + f, sx_load2(Q->b[0] + f) - (ar * mb->re[0] - ai * mb->im[0]));
            sx_store2(Q->b[3] + f, sx_load2(Q->b[3] + f) - (ar * mb->re[1] - ai * mb->im[1]));
            sx_store2(d0 + f, sx_load2(d0 + f) - (ar * mb->re[2] - ai * mb->im[2]));
            sx_store2(d1 + f, sx_load2(d1 + f) - (ar * mb->re[3] - ai * mb->im[3]));
        }
    }
}

/* the larger of m and |v|, without a branch (maxsd). A NaN may be dropped here: the coefficients come
 * from the ends' data b0, b3, d0 and d1, and a NaN among those makes the functional's tails NaN (their
 * rounding margin sums the data's sizes), so no bound that adds a tail clears the step. A test of
 * v != v here was a branch at every coefficient that the processor mispredicted: 10 % of the first
 * pass's time. */
static inline double abs_max(double m, double v)
{
    v = fabs(v);
    return v > m ? v : m;
}

/* every functional's cubic over the step from the modes' bounds over it and its exact ends (it runs
 * at every quiet test: inlined into both its callers, the first pass (sx_quiet_ends, the hot path)
 * and the full test's polynomials (sx_hermite_polys); out of line it cost the first pass 1.5 % of a
 * run's instructions) */
static SX_ALWAYS_INLINE void cubics_of(const sx_region *r, const sx_mode_bounds *B, const double xa0[],
                                       const double xa1[], cubics *Q)
{
    const sx_modes *m = &r->modes;
    const int nf = r->nf;
    const double h = B->h, margin = SX_MODES_MARGIN(m->cond);
    double d0[SX_MAX_F + 1], d1[SX_MAX_F + 1], size[SX_MAX_F + 1];
    int f;
    for (f = 0; f < nf; f++) {
        Q->start[f] = Q->b[0][f] = sx_functional(r, f, xa0);
        Q->end[f] = Q->b[3][f] = sx_functional(r, f, xa1);
        d0[f] = h * sx_functional_rate(r, f, xa0);
        d1[f] = h * sx_functional_rate(r, f, xa1);
    }
    if (B->modal) sx_ends_modal(r, B, xa0, xa1, Q->b[0], Q->b[3], d0, d1);
    Q->b[0][nf] = Q->b[3][nf] = d0[nf] = d1[nf] = Q->tail[nf] = Q->dtail[nf] = size[nf] = 0.0; /* (an odd count's pair) */
    tails_over(m, B, nf, Q, size);
    if (B->bands && !B->modal) bands_out(m, B, nf, Q, d0, d1);
    for (f = 0; f < nf; f++) { /* the Bernstein coefficients, and the rounding's margin on both tails */
        const double round =
            margin * (fabs(Q->b[0][f]) + fabs(Q->b[3][f]) + fabs(d0[f]) + fabs(d1[f]) + size[f]) + DBL_MIN;
        Q->b[1][f] = Q->b[0][f] + d0[f] * (1.0 / 3.0);
        Q->b[2][f] = Q->b[3][f] - d1[f] * (1.0 / 3.0);
        Q->tail[f] += round, Q->dtail[f] += round;
        Q->bmax[f] = abs_max(abs_max(abs_max(fabs(Q->b[0][f]), Q->b[1][f]), Q->b[2][f]), Q->b[3][f]);
    }
}

/* the same as the watch's polynomials (sx_lopoly) */
static void lopolys_of(const sx_region *r, const cubics *Q, sx_lopoly P[SX_MAX_F])
{
    int f, k;
    for (f = 0; f < r->nf; f++) {
        for (k = 0; k < 4; k++) P[f].coef[k] = Q->b[k][f];
        P[f].tail = Q->tail[f], P[f].dtail = Q->dtail[f], P[f].start = Q->start[f], P[f].deg = 3, P[f].bern = 1;
    }
}

int sx_hermite_polys(const sx_region *r, const sx_hermite_step *hs, const double xa0[], const double xa1[],
                     sx_lopoly P[SX_MAX_F])
{
    sx_mode_bounds B;
    cubics Q;
    if (!r->modes.valid) return 0;
    sx_mode_bounds_of(r, hs, xa0, &B);
    cubics_of(r, &B, xa0, xa1, &Q);
    lopolys_of(r, &Q, P);
    return 1;
}

/* the largest |b_k[f] + b_k[g]| over the coefficients */
static double sum_max(const cubics *Q, int f, int g)
{
    double m = 0.0;
    int k;
    for (k = 0; k < 4; k++) m = abs_max(m, Q->b[k][f] + Q->b[k][g]);
    return m;
}

/* a collapse indicator G(q) = q.A q - c.q whose region's A has a positive definite symmetric part
 * cannot vanish beyond the radius |c| / lam_min: clear where the box of the rotations is beyond it */
static int collapse_far(const sx_collapse *c, double c1, double r1, double c2, double r2)
{
    const double d1 = fabs(c1) - r1 > 0.0 ? fabs(c1) - r1 : 0.0, d2 = fabs(c2) - r2 > 0.0 ? fabs(c2) - r2 : 0.0;
    return c->lam_min > 0.0 && sqrt(d1 * d1 + d2 * d2) * c->lam_min > 1.000001 * hypot(c->c[0], c->c[1]);
}

/* storey i's wall: no line within reach of its box, no collapse indicator in play, s1 and s2 under
 * their peaks */
static int wall_clear(const sx_run *R, const sx_region *r, const cubics *Q, int i)
{
    const int f1 = r->f_of[i][SX_Q1], f2 = r->f_of[i][SX_Q2];
    const double h2 = 0.5 * R->sc.S.wall[i].h;
    double c1, r1, c2, r2;
    sx_cubic_box(Q->b[0][f1], Q->b[1][f1], Q->b[2][f1], Q->b[3][f1], Q->tail[f1], &c1, &r1);
    sx_cubic_box(Q->b[0][f2], Q->b[1][f2], Q->b[2][f2], Q->b[3][f2], Q->tail[f2], &c2, &r2);
    if (r->col[i].active && !collapse_far(&r->col[i], c1, r1, c2, r2)) return 0;
    if (sx_watch_box_lines(R, i, c1, r1, c2, r2, fabs(Q->b[0][f1]), fabs(Q->b[0][f2]))) return 0;
    return h2 * (Q->bmax[f1] + Q->tail[f1]) <= R->res->peak_s1[i] &&
           h2 * (sum_max(Q, f1, f2) + Q->tail[f1] + Q->tail[f2]) <= R->res->peak_s2[i];
}

/* can peak quantity f not rise over peak inside the step? (a quantity of the record alone is linear
 * over it: its ends hold its peak) */
static int under(const sx_region *r, const cubics *Q, int f, double peak)
{
    return r->modes.share_max[f] == 0.0 || Q->bmax[f] + Q->tail[f] <= peak;
}

/* the end's peaks, as sx_watch_peaks_at takes them, from the values the pass computed */
static void end_peaks(sx_run *R, const sx_region *r, const cubics *Q)
{
    rw_scene_result *res = R->res;
    int i;
    for (i = 0; i < R->sc.S.n_storeys; i++) {
        const int *f = r->f_of[i];
        if (f[SX_Q1] >= 0) {
            const double h2 = 0.5 * R->sc.S.wall[i].h, q1 = Q->end[f[SX_Q1]], q2 = Q->end[f[SX_Q2]];
            if (fabs(h2 * q1) > res->peak_s1[i]) res->peak_s1[i] = fabs(h2 * q1);
            if (fabs(h2 * (q1 + q2)) > res->peak_s2[i]) res->peak_s2[i] = fabs(h2 * (q1 + q2));
        }
        if (fabs(Q->end[f[SX_DEFORM]]) > res->peak_diaphragm[i]) res->peak_diaphragm[i] = fabs(Q->end[f[SX_DEFORM]]);
        if (fabs(Q->end[f[SX_BASE_ACC]]) > res->peak_base_acc[i]) res->peak_base_acc[i] = fabs(Q->end[f[SX_BASE_ACC]]);
    }
}

/* the first pass over every storey: the storeys it does not clear, whose say is the full test's (0:
 * quiet). A storey it clears is taken as clear, as it is where the pass clears every storey: the
 * full test's boxes are the same and its bounds no looser (but for the rounding of a peak's bound
 * times h/2, summed in another order), so that takes the others only: most steps that fail the
 * first pass fail it on one storey. */
static unsigned first_pass(sx_run *R, const sx_region *r, const cubics *Q)
{
    const rw_scene_result *res = R->res;
    unsigned unclear = 0;
    int i;
    for (i = 0; i < R->sc.S.n_storeys; i++) {
        const int *f = r->f_of[i];
        if (R->ndlines[i] || (f[SX_Q1] >= 0 && !wall_clear(R, r, Q, i)) ||
            !under(r, Q, f[SX_DEFORM], res->peak_diaphragm[i]) || !under(r, Q, f[SX_BASE_ACC], res->peak_base_acc[i]))
            unclear |= 1u << i;
    }
    return unclear;
}

int sx_quiet_ends(sx_run *R, const sx_region *r, const sx_hermite_step *hs, const double xa0[], const double xa1[])
{
    sx_mode_bounds B;
    cubics Q;
    sx_lopoly P[SX_MAX_F];
    unsigned unclear;
    int why;
    sx_mode_bounds_of(r, hs, xa0, &B);
    cubics_of(r, &B, xa0, xa1, &Q);
    if (!(unclear = first_pass(R, r, &Q))) {
        end_peaks(R, r, &Q);
        return 0;
    }
    lopolys_of(r, &Q, P);
    if ((why = sx_watch_quiet_polys(R, r, P, hs->h, xa0, unclear)) == 0) end_peaks(R, r, &Q);
    return why;
}

/* the peaks at a sample inside a window of the quantities of the record alone, which may peak at its
 * kink (the pass held every other under its peak over the whole window) */
static void kink_peaks(sx_run *R, const sx_region *r, const double xa[])
{
    static const int kinds[2][2] = {{SX_DEFORM, SX_PEAK_DEFORM}, {SX_BASE_ACC, SX_PEAK_ACC}};
    int i, k;
    for (i = 0; i < R->sc.S.n_storeys; i++)
        for (k = 0; k < 2; k++) {
            const int f = r->f_of[i][kinds[k][0]];
            double *peak = sx_peak_of(R->res, i, kinds[k][1]), v;
            if (f < 0 || r->modes.share_max[f] != 0.0) continue;
            if ((v = fabs(sx_functional(r, f, xa))) > *peak) *peak = v;
        }
}

int sx_quiet_window(sx_run *R, const sx_region *r, const sx_step *st, int n, double xa[][SX_MAX_NA], const double xe[])
{
    double modes = 0.0, record = 0.0;
    sx_mode_bounds B;
    cubics Q;
    int f, j;
    for (j = 1; j < n; j++) { /* the kinks' weights (a NaN slope leaves every tail NaN) */
        const double ds = fabs(xa[j][r->n + 1] - xa[j - 1][r->n + 1]);
        double value, rec;
        sx_window_kinks(n, j, &value, &rec);
        modes += ds * value, record += ds * rec;
    }
    sx_mode_bounds_of(r, &st->herm_w, xa[0], &B);
    cubics_of(r, &B, xa[0], xe, &Q);
    for (f = 0; f < r->nf; f++) Q.tail[f] += modes * st->kink_modes[f] + record * st->kink_record[f];
    if (first_pass(R, r, &Q)) return 1;
    for (j = 1; j < n; j++) kink_peaks(R, r, xa[j]);
    end_peaks(R, r, &Q);
    return 0;
}
