/* The exact scene engine (fmu_src/scene/rw_scene_exact*.c): its linear system against the scene's
 * own rates (rw_scene_derivatives) at random states of random scenes (linear and bilinear
 * diaphragms), the event update's rates where it changes nothing (the region's key takes them),
 * short runs against CVODES, what it refuses, its two matrix-vector products giving the same bits,
 * and a run after another giving the same bits. Run under ASan/UBSan by scripts/run_tests.sh. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "scene_pulse.h"
#include "scene_random.h"
#include "rw_scene_exact.h"
#include "rw_scene_exact_internal.h"

/* the largest |d_i - e_i| over the positions' and velocities' rates, against the largest term of
 * each rate (the sums cancel: a stiff tie's force is a large difference) */
static double rates_error(const rw_scene *sc, double ag, double *x)
{
    double dx[RW_SCENE_NX], ex[RW_SCENE_NX], scale[RW_SCENE_NX], d2[RW_SCENE_NX], worst = 0.0;
    int k, b;
    rw_scene_derivatives(sc, ag, x, dx, NULL);
    if (rw_scene_exact_rates(sc, ag, x, ex) != 0) return INFINITY;
    /* each rate's scale: its largest change when any one state or the input doubles (the terms it sums) */
    rw_scene_derivatives(sc, 2.0 * ag, x, d2, NULL);
    for (k = 0; k < RW_SCENE_NX; k++) scale[k] = fmax(fabs(dx[k]), fabs(d2[k] - dx[k]));
    for (b = 0; b < sc->nx; b++) {
        const double keep = x[b];
        x[b] = 2.0 * keep;
        rw_scene_derivatives(sc, ag, x, d2, NULL);
        x[b] = keep;
        for (k = 0; k < RW_SCENE_NX; k++) scale[k] = fmax(scale[k], fabs(d2[k] - dx[k]));
    }
    for (k = 0; k < sc->nx; k++) {
        const int floor_block = k >= RW_NX * sc->S.n_storeys;
        const int off = (k - RW_NX * sc->S.n_storeys) % BD_STATES_PER_FLOOR;
        if (floor_block && (off == BD_Z || off == BD_ZD || off == BD_WORK_S || off == BD_WORK_D)) continue;
        if (scale[k] > 0.0) worst = fmax(worst, fabs(dx[k] - ex[k]) / scale[k]);
    }
    return worst;
}

static void test_rates_match_the_scene(void)
{
    int n, worst_case = -1;
    double worst = 0.0;
    for (n = 0; n < 400; n++) {
        rw_scene_spec spec;
        rw_scene sc;
        double x[RW_SCENE_NX];
        char msg[256];
        int i;
        random_spec(&spec);
        CHECK(rw_scene_validate(&spec, msg, sizeof msg) == 0, "scene %d refused: %s", n, msg);
        memset(x, 0, sizeof x);
        rw_scene_init(&sc, &spec, 0.0, x);
        for (i = 0; i < spec.n_storeys; i++) {
            sc.regime[i].side_b = coin() ? 1 : -1;
            sc.regime[i].side_m = coin() ? 1 : -1;
            sc.collapsed[i] = spec.has_wall[i] && rand() % 6 == 0;
        }
        random_state(&sc, x);
        {
            const double e = rates_error(&sc, uniform(-5.0, 5.0), x);
            if (e > worst) worst = e, worst_case = n;
        }
    }
    printf("rates: worst relative difference %.3g (scene %d) over 400 random scenes and states\n", worst, worst_case);
    CHECK(worst <= 1e-12, "the linear system's rates differ from rw_scene_derivatives by %.3g (scene %d)", worst,
          worst_case);
}

/* the event update's rates (rw_scene_event_update's dx) where its last round changed nothing are the
 * rates at the state it leaves, to the bit, and so is the region's key the engine takes from them
 * (sx_handle_events hands them to sx_region_key, which then skips its own evaluation) */
static void test_a_quiet_update_leaves_the_rates_at_its_state(void)
{
    int n, quiet = 0, after_change = 0;
    for (n = 0; n < 400; n++) {
        rw_scene_spec spec;
        rw_scene sc;
        sx_key given, own;
        double x[RW_SCENE_NX], dx[RW_SCENE_NX], fresh[RW_SCENE_NX];
        const double ag = uniform(-5.0, 5.0);
        int i, rounds = 0, flags;
        random_spec(&spec);
        memset(x, 0, sizeof x);
        rw_scene_init(&sc, &spec, 0.0, x);
        for (i = 0; i < spec.n_storeys; i++)
            sc.regime[i].side_b = coin() ? 1 : -1, sc.regime[i].side_m = coin() ? 1 : -1;
        random_state(&sc, x);
        for (i = 0; i < spec.n_storeys; i++) /* some walls at rest on their base, where impacts and lifts happen */
            if (spec.has_wall[i] && coin()) RW_SCENE_WALL(x, i)[0] = RW_SCENE_WALL(x, i)[1] = 0.0;
        do flags = rw_scene_event_update(&sc, 0.0, ag, x, dx);
        while ((flags & 3) && ++rounds < 100);
        if (flags) continue;
        quiet++, after_change += rounds > 0;
        rw_scene_derivatives(&sc, ag, x, fresh, NULL);
        CHECK(memcmp(dx, fresh, sizeof dx) == 0, "scene %d: the update's rates are not the state's", n);
        sx_region_key(&sc, ag, x, dx, &given);
        sx_region_key(&sc, ag, x, NULL, &own);
        CHECK(memcmp(&given, &own, sizeof given) == 0, "scene %d: the key from the update's rates differs", n);
    }
    printf("event update's rates: %d quiet updates (%d after rounds that changed the state) of 400\n", quiet,
           after_change);
    CHECK(quiet >= 100 && after_change >= 10, "too few cases tried (%d quiet, %d after a change)", quiet, after_change);
}

/* the exact engine against CVODES at rtol 1e-10 (Adams, or BDF with bdf): peaks within 1e-4, the
 * same impacts and collapses; stiff: Adams goes on with Newton iteration */
static void compare_with_cvodes(const char *what, const rw_scene_spec *spec, double D, int bdf, int stiff)
{
    rw_scene_result a, b;
    rw_scene_options opt;
    rw_scene_record rec;
    double t[401], ag[401];
    int i, ca, cb;
    pulse(D, 401, t, ag);
    rec.n = 401, rec.t = t, rec.ag = ag;
    memset(&opt, 0, sizeof opt);
    opt.t_end = 2.0, opt.rtol = 1e-10, opt.bdf = bdf;
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    ca = rw_scene_run_exact(spec, &rec, &opt, &a);
    cb = rw_scene_run(spec, &rec, &opt, &b);
    CHECK(ca == 0 && cb == 0, "%s: runs failed: %d %s / %d %s", what, ca, a.message, cb, b.message);
    CHECK(bdf || stiff ? b.t_newton < 1.0 : isnan(b.t_newton), "%s, bdf %d: Newton from t = %g", what, bdf, b.t_newton);
    for (i = 0; i < spec->n_storeys; i++) {
        CHECK(fabs(a.peak_s1[i] - b.peak_s1[i]) <= 1e-4 * b.peak_s1[i], "%s, storey %d: peak s1 %.9g against %.9g",
              what, i, a.peak_s1[i], b.peak_s1[i]);
        CHECK(fabs(a.peak_s2[i] - b.peak_s2[i]) <= 1e-4 * b.peak_s2[i], "%s, storey %d: peak s2 %.9g against %.9g",
              what, i, a.peak_s2[i], b.peak_s2[i]);
        CHECK(a.impacts[i] == b.impacts[i] && a.collapsed[i] == b.collapsed[i], "%s, storey %d: %ld impacts, collapse %d "
              "against %ld, %d", what, i, a.impacts[i], a.collapsed[i], b.impacts[i], b.collapsed[i]);
    }
    CHECK(a.impacts[0] > 0, "%s: the ground storey's wall does not rock (a comparison of little worth)", what);
    CHECK(a.max_residual <= 1e-9 * fmax(a.max_work, 1e-3), "%s: energy residual %.3g of work %.3g", what,
          a.max_residual, a.max_work);
}

/* two storeys on flexible in-plane walls (soft ties), one storey with a stiff tie (its mode a band
 * over the record's intervals, halved near events), and one with a stiff dashpot (300 times
 * critical), each with Adams and with BDF */
static void test_runs_against_cvodes(void)
{
    rw_scene_spec spec;
    int i, bdf;
    srand(7);
    memset(&spec, 0, sizeof spec);
    spec.n_storeys = 2;
    spec.rigid_in_plane = 0;
    for (i = 0; i < 2; i++) {
        spec.has_wall[i] = 1;
        random_wall(&spec.wall[i]);
        spec.wall[i].Kd = 1e6;
        spec.building.md[i] = 200.0, spec.building.diaph[i].k = 5e4, spec.building.cd[i] = 300.0;
        spec.building.m[i] = 2000.0, spec.building.storey[i].k = 5e7, spec.building.cs[i] = 1e4;
    }
    for (bdf = 0; bdf < 2; bdf++) compare_with_cvodes("two storeys", &spec, 0.05, bdf, 0);
    spec.n_storeys = 1;
    spec.rigid_in_plane = 1;
    spec.wall[0].Kd = 1e8;
    for (bdf = 0; bdf < 2; bdf++) compare_with_cvodes("stiff tie", &spec, 0.06, bdf, 0);
    spec.building.cd[0] = 600.0 * sqrt(spec.building.diaph[0].k * spec.building.md[0]);
    for (bdf = 0; bdf < 2; bdf++) compare_with_cvodes("stiff dashpot", &spec, 0.06, bdf, 1);
}

/* two storeys whose diaphragms follow `law` and yield at 200 N/m (alpha 0.1): walls drawn from seed,
 * tied by 1e6 (and by `upper_tie` above), flexible in-plane walls unless rigid */
static void yielding_storeys(rw_scene_spec *spec, int law, unsigned seed, int rigid, double upper_tie)
{
    int i;
    srand(seed);
    memset(spec, 0, sizeof *spec);
    spec->n_storeys = 2;
    spec->rigid_in_plane = rigid;
    spec->building.diaphragm_law = law;
    spec->building.n_bw = 1.0, spec->building.beta = 0.5;
    spec->building.pinch_size = 0.5, spec->building.pinch_width = 0.3, spec->building.pinch_centre = 0.0;
    for (i = 0; i < 2; i++) {
        spec->has_wall[i] = 1;
        random_wall(&spec->wall[i]);
        spec->wall[i].Kd = i ? upper_tie : 1e6;
        spec->building.md[i] = 200.0, spec->building.diaph[i].k = 5e4, spec->building.cd[i] = 100.0;
        spec->building.diaph[i].Fy = 200.0, spec->building.diaph[i].alpha = 0.1;
        spec->building.m[i] = 2000.0, spec->building.storey[i].k = 5e7, spec->building.cs[i] = 1e4;
    }
}

/* the scene against CVODES (compare_with_cvodes), and its ground diaphragm past twice its yield
 * displacement on the exact engine (else the comparison is of little worth) */
static void compare_yielding(const char *what, const rw_scene_spec *spec)
{
    rw_scene_result r;
    rw_scene_options opt;
    rw_scene_record rec;
    double t[401], ag[401];
    compare_with_cvodes(what, spec, 0.08, 0, 0);
    pulse(0.08, 401, t, ag);
    rec.n = 401, rec.t = t, rec.ag = ag;
    memset(&opt, 0, sizeof opt);
    opt.t_end = 2.0;
    memset(&r, 0, sizeof r);
    CHECK(rw_scene_run_exact(spec, &rec, &opt, &r) == 0, "%s: %s", what, r.message);
    CHECK(r.peak_diaphragm[0] > 2.0 * spec->building.diaph[0].Fy / spec->building.diaph[0].k,
          "%s: the diaphragm does not yield (peak %g m): a comparison of little worth", what, r.peak_diaphragm[0]);
}

/* bilinear diaphragms that yield and unload: the exact engine's branches against CVODES's rate
 * form, which steps over the kinks by its error control */
static void test_bilinear_against_cvodes(void)
{
    rw_scene_spec spec;
    yielding_storeys(&spec, BD_BILINEAR, 11, 1, 1e6);
    compare_yielding("bilinear diaphragms", &spec);
}

/* Bouc-Wen diaphragms (and pinched ones) that yield, one under a stiff tie (its steps the series',
 * not the fit's): the exact engine's fitted z against CVODES's rate form */
static void test_bouc_wen_against_cvodes(void)
{
    rw_scene_spec spec;
    yielding_storeys(&spec, BD_BOUC_WEN, 13, 0, 1e8);
    compare_yielding("Bouc-Wen diaphragms", &spec);
    yielding_storeys(&spec, BD_BOUC_WEN_PINCHED, 13, 0, 1e8);
    compare_yielding("pinched Bouc-Wen diaphragms", &spec);
}

/* the two scenes the reuse tests run, one after the other, under the pulse (0.08, 2 s): bilinear
 * diaphragms on rigid in-plane walls under a soft tie, and linear ones on flexible walls under a
 * stiff tie (the record points into the struct: not to be copied) */
typedef struct {
    rw_scene_spec first, other;
    rw_scene_options opt;
    rw_scene_record rec;
    double t[401], ag[401];
} two_scenes;

static void two_scenes_of(two_scenes *s)
{
    yielding_storeys(&s->first, BD_BILINEAR, 11, 1, 1e6);
    yielding_storeys(&s->other, BD_ELASTIC, 17, 0, 1e8);
    pulse(0.08, 401, s->t, s->ag);
    s->rec.n = 401, s->rec.t = s->t, s->rec.ag = s->ag;
    memset(&s->opt, 0, sizeof s->opt);
    s->opt.t_end = 2.0;
}

/* A run's memory is kept for the next run on the thread (rw_scene_exact_pool.c), so a run must set
 * all it reads: bilinear diaphragms, then a stiff-tied linear scene on flexible in-plane walls, then
 * the first again give the first run's result to the bit (in the sanitizer build the reused
 * blocks come filled with NaNs) */
static void test_reused_memory_gives_the_same_bits(void)
{
    two_scenes s;
    rw_scene_result r[3];
    int k;
    two_scenes_of(&s);
    for (k = 0; k < 3; k++) {
        memset(&r[k], 0, sizeof r[k]);
        CHECK(rw_scene_run_exact(k == 1 ? &s.other : &s.first, &s.rec, &s.opt, &r[k]) == 0, "run %d: %s", k,
              r[k].message);
    }
    CHECK(r[0].steps > 0 && r[0].events > 0, "the first scene did not move (%ld steps, %ld events)", r[0].steps,
          r[0].events);
    CHECK(memcmp(&r[0], &r[2], sizeof r[0]) == 0, "the first scene run again after another: peak s1 %.17g, %.17g "
          "(steps %ld, %ld)", r[0].peak_s1[0], r[2].peak_s1[0], r[0].steps, r[2].steps);
}

/* A result struct handed to a run is its output, whatever it held: the bilinear scene into a struct
 * the stiff-tied one filled (whose peaks are larger) gives its own numbers, the same to the bit as
 * into a zeroed one, from either runner (the peaks and the energy's maxima were once kept as the
 * larger of the old and the new) */
static void test_a_reused_result_holds_this_run_alone(void)
{
    typedef int (*runner)(const rw_scene_spec *, const rw_scene_record *, const rw_scene_options *,
                          rw_scene_result *);
    const runner runners[2] = {rw_scene_run_exact, rw_scene_run};
    const char *names[2] = {"exact", "CVODES"};
    two_scenes s;
    rw_scene_result reused, fresh;
    int k;
    two_scenes_of(&s);
    for (k = 0; k < 2; k++) {
        memset(&reused, 0, sizeof reused);
        memset(&fresh, 0, sizeof fresh);
        CHECK(runners[k](&s.other, &s.rec, &s.opt, &reused) == 0, "%s: the first scene: %s", names[k], reused.message);
        CHECK(runners[k](&s.first, &s.rec, &s.opt, &reused) == 0 && runners[k](&s.first, &s.rec, &s.opt, &fresh) == 0,
              "%s: the second scene: %s", names[k], reused.message);
        CHECK(fresh.steps > 0 && fresh.peak_s1[0] > 0.0, "%s: the second scene did not move", names[k]);
        CHECK(memcmp(&reused, &fresh, sizeof fresh) == 0,
              "%s: a reused result: peak s1 %.17g against %.17g, max residual %.3g against %.3g", names[k],
              reused.peak_s1[0], fresh.peak_s1[0], reused.max_residual, fresh.max_residual);
    }
}

static void test_refusals(void)
{
    rw_scene_spec spec;
    char msg[256];
    memset(&spec, 0, sizeof spec);
    spec.n_storeys = 1;
    spec.rigid_in_plane = 1;
    spec.has_wall[0] = 1;
    random_wall(&spec.wall[0]);
    spec.building.md[0] = 100.0, spec.building.diaph[0].k = 1e4;
    CHECK(rw_scene_exact_covers(&spec, msg, sizeof msg) == 0, "a dohertyHinge scene refused: %s", msg);
    spec.wall[0].hingeLaw = RW_RIGID;
    CHECK(rw_scene_exact_covers(&spec, msg, sizeof msg) == RW_SCENE_UNSUPPORTED && strstr(msg, "rigid"),
          "the rigid law: %s", msg);
    spec.wall[0].hingeLaw = RW_DOHERTY_HINGE;
    spec.building.diaphragm_law = BD_BOUC_WEN;
    CHECK(rw_scene_exact_covers(&spec, msg, sizeof msg) == 0, "Bouc-Wen diaphragms refused: %s", msg);
    spec.rigid_in_plane = 0;
    spec.building.storey_law = BD_BOUC_WEN;
    CHECK(rw_scene_exact_covers(&spec, msg, sizeof msg) == RW_SCENE_UNSUPPORTED && strstr(msg, "in-plane"),
          "Bouc-Wen in-plane walls: %s", msg);
    spec.rigid_in_plane = 1;
    spec.building.storey_law = BD_ELASTIC;
    spec.building.diaphragm_law = BD_BILINEAR;
    CHECK(rw_scene_exact_covers(&spec, msg, sizeof msg) == 0, "bilinear diaphragms refused: %s", msg);
}

/* the three products at once (sx_matvec3_lead: x, -x and 2x, the leading rows of A) against the
 * row-wise sums y of A x: 1 if any entry's bits differ */
static int three_at_once_differ(int rows, int cols, const double *At, const double *x, const double *y)
{
    double x1[SX_MAX_NA], x2[SX_MAX_NA], z[3][SX_MAX_NA];
    const double *xs[3] = {x, x1, x2};
    double *zs[3] = {z[0], z[1], z[2]};
    int k, lead;
    for (k = 0; k < cols; k++) x1[k] = -x[k], x2[k] = 2.0 * x[k]; /* (exact: each sum scales exactly) */
    for (lead = 1; lead <= rows; lead += 4) {
        sx_matvec3_lead(lead, cols, rows, At, xs, zs);
        for (k = 0; k < lead; k++)
            if (memcmp(&z[0][k], &y[k], sizeof(double)) || z[1][k] != -y[k] || z[2][k] != 2.0 * y[k]) return 1;
    }
    return 0;
}

/* the engine's product from a matrix stored by columns keeps each sum's order: the very bits of a
 * row's dot product taken in order, so that the layout changes no motion */
static void test_products_agree_bitwise(void)
{
    static double A[SX_MAX_NA * SX_MAX_NA], At[SX_MAX_NA * SX_MAX_NA];
    double x[SX_MAX_NA], y_rows[SX_MAX_NA], y_cols[SX_MAX_NA];
    int rows, cols, k, differ = 0;
    for (rows = 1; rows <= SX_MAX_NA; rows += 3)
        for (cols = 1; cols <= SX_MAX_NA; cols += 2) {
            for (k = 0; k < rows * cols; k++) A[k] = uniform(-1.0, 1.0) * pow(10.0, uniform(-8.0, 8.0));
            for (k = 0; k < cols; k++) x[k] = uniform(-1.0, 1.0) * pow(10.0, uniform(-8.0, 8.0));
            sx_transpose(rows, cols, A, At);
            for (k = 0; k < rows; k++) { /* each row's dot product, in order */
                int j;
                y_rows[k] = 0.0;
                for (j = 0; j < cols; j++) y_rows[k] += A[k * cols + j] * x[j];
            }
            sx_matvec_cols(rows, cols, At, x, y_cols);
            differ += memcmp(y_rows, y_cols, sizeof(double) * (size_t)rows) != 0;
            differ += three_at_once_differ(rows, cols, At, x, y_rows);
        }
    CHECK(differ == 0, "%d of the products by columns differ from the row-wise ones", differ);
}

int main(void)
{
    srand(12345);
    test_rates_match_the_scene();
    test_a_quiet_update_leaves_the_rates_at_its_state();
    test_runs_against_cvodes();
    test_bilinear_against_cvodes();
    test_bouc_wen_against_cvodes();
    test_refusals();
    test_products_agree_bitwise();
    test_reused_memory_gives_the_same_bits();
    test_a_reused_result_holds_this_run_alone();
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
