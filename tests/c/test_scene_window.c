/* The exact scene engine's windows (sx_window): one quiet test over several record intervals, whose
 * slope kinks at the samples inside (rw_scene_exact_hermite.c, sx_kink_of). The kernel's bounds it
 * tables hold, computed again here; over windows of random regions under kinked records, the window's
 * cubic widened by its tails holds the exact motion at every point tried (and without the kinks'
 * share of the tails it does not); runs that take windows give the bits of runs that stop at every
 * sample for an output row. Run under ASan/UBSan by
 * scripts/run_tests.sh. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "scene_pulse.h"
#include "scene_random.h"
#include "scene_series.h"
#include "rw_scene_exact.h"
#include "rw_scene_exact_internal.h"

#define POINTS 16 /* the points tried in each step of a window, past its start */

/* the Peano kernel of two-point cubic Hermite interpolation on [0, 1] for the second derivative */
static double kernel(double u, double s)
{
    return (u > s ? u - s : 0.0) - (1.0 - s) * (3.0 * u * u - 2.0 * u * u * u) - (u * u * u - u * u);
}

/* max over u of int_lo^1 |K(u, s)| ds (Simpson's rule, fine grids), and max |K(u, s)| for s within
 * 0.01 of s0 */
static double kernel_integral(double lo)
{
    const int nu = 2000, ns = 4000;
    double best = 0.0;
    int a, b;
    for (a = 0; a <= nu; a++) {
        const double u = (double)a / nu, ds = (1.0 - lo) / ns;
        double sum = 0.0;
        for (b = 0; b <= ns; b++) sum += (b == 0 || b == ns ? 1.0 : (b % 2 ? 4.0 : 2.0)) * fabs(kernel(u, lo + b * ds));
        if (sum * ds / 3.0 > best) best = sum * ds / 3.0;
    }
    return best;
}

static double kernel_peak(double s0)
{
    double best = 0.0;
    int a, b;
    for (a = 0; a <= 2000; a++)
        for (b = 0; b <= 40; b++) {
            const double k = fabs(kernel(a / 2000.0, s0 - 0.01 + 0.02 * b / 40.0));
            if (k > best) best = k;
        }
    return best;
}

static void test_the_kernels_bounds_hold(void)
{
    int n, j;
    for (n = 2; n <= SX_WINDOW; n++)
        for (j = 1; j < n; j++) {
            double value, record;
            const double v = kernel_integral((double)j / n - 0.01), e = kernel_peak((double)j / n);
            sx_window_kinks(n, j, &value, &record);
            CHECK(value >= v * (1.0 + 1e-6) && value <= 1.05 * v, "a kink at %d/%d: the value's bound %.5f, the kernel's "
                  "integral %.5f", j, n, value, v);
            CHECK(record >= e && record <= 1.05 * e, "a kink at %d/%d: the record's bound %.5f, the kernel's peak %.5f", j,
                  n, record, e);
        }
}

/* the state at the start of each step of a window (the record continuous, its slope each step's),
 * and its end */
static void window_states(const sx_region *r, const double xa0[], double h, const double slope[],
                          double xa[][SX_MAX_NA], double xe[])
{
    int j;
    memcpy(xa[0], xa0, sizeof(double) * (size_t)r->na);
    xa[0][r->n + 1] = slope[0];
    for (j = 0; j < SX_WINDOW; j++) {
        double *to = j + 1 < SX_WINDOW ? xa[j + 1] : xe;
        exact_state(r, xa[j], h, to);
        to[r->n] = xa[j][r->n] + h * slope[j]; /* (the series' own ag is that to rounding) */
        if (j + 1 < SX_WINDOW) to[r->n + 1] = slope[j + 1];
    }
}

typedef struct {
    long tried, misses, misses_without_kinks;
} tally;

/* one window of SX_WINDOW steps of length h from xa0 under the slopes: the window's cubics and tails
 * (the kinks' share with and without) against the exact motion */
static void check_window(const sx_region *r, const double xa0[], double h, const double slope[], tally *t)
{
    double xa[SX_WINDOW][SX_MAX_NA], xe[SX_MAX_NA], x[SX_MAX_NA], modes[SX_MAX_F], record[SX_MAX_F];
    double wm = 0.0, wr = 0.0;
    sx_lopoly P[SX_MAX_F];
    sx_hermite_step hs;
    int j, k, f;
    window_states(r, xa0, h, slope, xa, xe);
    sx_hermite_step_of(r, SX_WINDOW * h, &hs);
    if (hs.modal) return;
    CHECK(sx_hermite_polys(r, &hs, xa[0], xe, P), "no polynomials");
    sx_kink_of(r, &hs, modes, record);
    for (j = 1; j < SX_WINDOW; j++) {
        double value, rec;
        sx_window_kinks(SX_WINDOW, j, &value, &rec);
        wm += fabs(slope[j] - slope[j - 1]) * value, wr += fabs(slope[j] - slope[j - 1]) * rec;
    }
    for (j = 0; j < SX_WINDOW; j++)
        for (k = 1; k <= POINTS; k++) {
            const double u = (j + (double)k / POINTS) / SX_WINDOW;
            exact_state(r, xa[j], h * k / POINTS, x);
            for (f = 0; f < r->nf; f++) {
                const double v = sx_functional(r, f, x);
                const double gap = fabs(v - sx_lopoly_at(&P[f], u)), kinks = wm * modes[f] + wr * record[f];
                t->tried++;
                t->misses += !(gap <= (P[f].tail + kinks) * (1.0 + 1e-9) + 1e-12 * fabs(v));
                t->misses_without_kinks += !(gap <= P[f].tail * (1.0 + 1e-9) + 1e-12 * fabs(v));
            }
        }
}

/* the region of a random state of the scene spec, its walls on random sides: 1 with valid modes
 * and no block (what a window takes), else 0 and nothing kept */
static int region_of(const rw_scene_spec *spec, rw_scene *sc, sx_region *r)
{
    sx_key key;
    double x[RW_SCENE_NX];
    int i;
    memset(x, 0, sizeof x);
    rw_scene_init(sc, spec, 0.0, x);
    for (i = 0; i < spec->n_storeys; i++)
        sc->regime[i].side_b = coin() ? 1 : -1, sc->regime[i].side_m = coin() ? 1 : -1;
    random_state(sc, x);
    sx_region_key(sc, uniform(-5.0, 5.0), x, NULL, &key);
    memset(r, 0, sizeof *r);
    CHECK(sx_region_build(sc, &key, r, NULL) == 0, "the region was not built");
    if (r->modes.valid && !r->modes.blocks) return 1;
    sx_region_free(r);
    return 0;
}

static void test_windows_bound_their_motion(void)
{
    tally t = {0, 0, 0};
    int n, regions = 0;
    for (n = 0; n < 60; n++) {
        rw_scene_spec spec;
        rw_scene sc;
        sx_region r;
        int w, j;
        random_spec(&spec);
        spec.building.diaphragm_law = BD_ELASTIC;
        if (!region_of(&spec, &sc, &r)) continue;
        regions++;
        for (w = 0; w < 6; w++) {
            const double h = w < 3 ? 5e-3 : uniform(1e-3, 1e-2);
            double x[RW_SCENE_NX], xa0[SX_MAX_NA], slope[SX_WINDOW];
            random_state(&sc, x);
            for (j = 0; j < SX_WINDOW; j++) slope[j] = uniform(-400.0, 400.0); /* up to 2 m/s2 over 5 ms */
            sx_gather(&r, x, uniform(-5.0, 5.0), slope[0], xa0);
            check_window(&r, xa0, h, slope, &t);
        }
        sx_region_free(&r);
    }
    printf("windows of %d steps: %d regions, %ld points: %ld outside their tails (%ld without the kinks' share)\n",
           SX_WINDOW, regions, t.tried, t.misses, t.misses_without_kinks);
    CHECK(regions >= 30, "too few regions tried (%d)", regions);
    CHECK(t.misses == 0, "the window's cubics missed the exact motion at %ld points", t.misses);
    CHECK(t.misses_without_kinks > 0, "the kinks' share of the tails was never needed: the test cannot tell");
}

/* Runs that take windows against runs that stop at every sample for an output row: the same windows,
 * to the bit (once a failed window's samples moved the record's hint past the interval that
 * followed, and a run without output rows took two intervals as one). */
static void test_windows_take_every_interval(void)
{
    static double t[801], ag[801], every[801], grid[801 * RW_SCENE_MAX_STOREYS];
    rw_scene_result a, b;
    int n, k, runs = 0;
    srand(20261209); /* (the same scenes whatever the tests before drew) */
    pulse(0.08, 801, t, ag);
    for (k = 0; k < 801; k++) every[k] = t[k];
    for (n = 0; n < 16; n++) {
        const rw_scene_record rec = {801, t, ag};
        rw_scene_options opt;
        rw_scene_spec spec;
        random_house(&spec, n % 2 ? 1e6 : 1e8);
        memset(&opt, 0, sizeof opt);
        opt.t_end = 4.0;
        memset(&a, 0, sizeof a), memset(&b, 0, sizeof b);
        if (rw_scene_run_exact(&spec, &rec, &opt, &a)) continue;
        opt.n_out = 801, opt.t_out = every, b.s1_out = grid;
        CHECK(rw_scene_run_exact(&spec, &rec, &opt, &b) == 0, "outputs at every sample: %s", b.message);
        runs++;
        CHECK(a.steps == b.steps && a.events == b.events && !memcmp(a.peak_s1, b.peak_s1, sizeof a.peak_s1) &&
              !memcmp(a.peak_s2, b.peak_s2, sizeof a.peak_s2) && !memcmp(a.peak_base_acc, b.peak_base_acc, sizeof
              a.peak_base_acc) && a.work_ground == b.work_ground && a.work_damping == b.work_damping,
              "scene %d: without outputs %ld steps, peak s1 %.17g; with one at every sample %ld, %.17g", n, a.steps,
              a.peak_s1[1], b.steps, b.peak_s1[1]);
    }
    CHECK(runs >= 12, "too few scenes ran (%d)", runs);
}

int main(void)
{
    srand(20261208);
    test_the_kernels_bounds_hold();
    test_windows_bound_their_motion();
    test_windows_take_every_interval();
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
