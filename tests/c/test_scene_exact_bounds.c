/* The exact scene engine's quiet test bounds the motion it clears (rw_scene_exact_hermite.c): over a
 * step, each functional's cubic Hermite interpolant of its exact ends, widened by its tail, holds
 * the exact motion (the Taylor series, in parts) at every point tried, and the interpolant's rate,
 * widened by its rate's tail, the motion's rate. Random regions of random scenes (ties up to 1e9
 * N/m per m, whose modes turn by many radians over a record interval and are bands there), steps
 * from a fraction of the series' limit to 20 ms; and the free mechanism kept as a block. A step that
 * surely crosses a line is never cleared by the quiet test. The modes' bounds taken at once are each
 * mode's own, to the bit. Run under ASan/UBSan by scripts/run_tests.sh. */
#include <complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "scene_random.h"
#include "scene_series.h"
#include "rw_scene_exact.h"
#include "rw_scene_exact_internal.h"

#define POINTS 16 /* the points tried in a step, past its start */

/* a Bernstein cubic's rate in u */
static double bern_rate(const double *b, double u)
{
    const double v = 1.0 - u;
    return 3.0 * ((b[1] - b[0]) * v * v + 2.0 * (b[2] - b[1]) * u * v + (b[3] - b[2]) * u * u);
}

typedef struct {
    long tried, misses, rate_misses;
    double tightest; /* the smallest tail over the largest gap it held (how far from loose) */
} tally;

/* one step of length h from xa0: each functional's polynomial and tail against the exact motion */
static void check_step(const sx_region *r, const double xa0[], double h, const sx_hermite_step *table, tally *t)
{
    double xa1[SX_MAX_NA], xa[SX_MAX_NA], gap_max[SX_MAX_F] = {0.0};
    sx_lopoly P[SX_MAX_F];
    sx_hermite_step hs;
    int k, f;
    exact_state(r, xa0, h, xa1);
    sx_hermite_step_of(r, h, &hs);
    CHECK(sx_hermite_polys(r, table ? table : &hs, xa0, xa1, P), "no polynomials");
    for (k = 1; k < POINTS; k++) {
        const double u = (double)k / POINTS;
        exact_state(r, xa0, u * h, xa);
        for (f = 0; f < r->nf; f++) {
            const double value = sx_functional(r, f, xa), rate = h * sx_functional_rate(r, f, xa);
            const double gap = fabs(value - sx_lopoly_at(&P[f], u)), rate_gap = fabs(rate - bern_rate(P[f].coef, u));
            t->tried++;
            t->misses += !(gap <= P[f].tail * (1.0 + 1e-9) + 1e-12 * fabs(value));
            t->rate_misses += !(rate_gap <= P[f].dtail * (1.0 + 1e-9) + 1e-12 * fabs(rate));
            if (gap > gap_max[f]) gap_max[f] = gap;
        }
    }
    for (f = 0; f < r->nf; f++)
        if (gap_max[f] > 0.0 && P[f].tail / gap_max[f] < t->tightest) t->tightest = P[f].tail / gap_max[f];
}

/* a start state of the region: the scene's state with the record's value and slope */
static void start_state(const sx_region *r, const rw_scene *sc, double xa0[])
{
    double x[RW_SCENE_NX];
    random_state(sc, x);
    sx_gather(r, x, uniform(-5.0, 5.0), uniform(-200.0, 200.0), xa0);
}

/* the region of a random state of the scene spec (its walls on random sides if sides): 1 with valid
 * modes, else 0 and nothing kept */
static int region_of(const rw_scene_spec *spec, int sides, rw_scene *sc, sx_region *r)
{
    sx_key key;
    double x[RW_SCENE_NX];
    int i;
    memset(x, 0, sizeof x);
    rw_scene_init(sc, spec, 0.0, x);
    for (i = 0; sides && i < spec->n_storeys; i++)
        sc->regime[i].side_b = coin() ? 1 : -1, sc->regime[i].side_m = coin() ? 1 : -1;
    random_state(sc, x);
    sx_region_key(sc, uniform(-5.0, 5.0), x, NULL, &key);
    memset(r, 0, sizeof *r);
    CHECK(sx_region_build(sc, &key, r, NULL) == 0, "the region was not built");
    if (r->modes.valid) return 1;
    sx_region_free(r);
    return 0;
}

static void test_random_regions_bound_their_motion(void)
{
    tally t = {0, 0, 0, INFINITY};
    int n, regions = 0, bands = 0;
    for (n = 0; n < 60; n++) {
        rw_scene_spec spec;
        rw_scene sc;
        sx_region r;
        int s, k;
        random_spec(&spec);
        spec.building.diaphragm_law = coin() ? BD_BILINEAR : BD_ELASTIC; /* Bouc-Wen regions have no modes */
        if (!region_of(&spec, 1, &sc, &r)) continue;
        regions++;
        for (k = 0; k < r.modes.count; k++) bands += pow(r.modes.abs_lam[k] * 5e-3, 4) >= 384.0;
        for (s = 0; s < 12; s++) {
            const double h = s < 6 ? sx_hmax(&r) * uniform(0.05, 1.0) : (s < 9 ? 5e-3 : uniform(5e-3, 2e-2));
            double xa0[SX_MAX_NA];
            start_state(&r, &sc, xa0);
            if (s == 9) { /* a table's constants, as the run takes them */
                const sx_step *st = sx_step_of(&r, h, 0.0, 1);
                CHECK(st != NULL, "no table");
                if (st) check_step(&r, xa0, h, &st->herm, &t);
            } else check_step(&r, xa0, h, NULL, &t);
        }
        sx_region_free(&r);
    }
    printf("bounds: %d regions (%d modes bands over 5 ms), %ld points: %ld values and %ld rates outside their "
           "tails; the tightest tail %.3g times the largest gap\n", regions, bands, t.tried, t.misses, t.rate_misses,
           t.tightest);
    CHECK(regions >= 30 && bands > 0, "too few regions tried (%d, %d bands)", regions, bands);
    CHECK(t.misses == 0 && t.rate_misses == 0, "the polynomials missed the exact motion at %ld values and %ld rates",
          t.misses, t.rate_misses);
}

/* Diaphragms of grams per metre down to the building file's least (1e-6 kg/m) behind ties of 1e7
 * to 1e9 N/m per m: modes of up to 3e7 rad/s, which turn by hundreds of radians over a step of a
 * millisecond. There the ends' data come from the modes' own coordinates (SX_BAND_MODAL_WH), and
 * the polynomials with their tails still bound the exact motion at every point tried. */
static void test_light_diaphragms_bound_their_motion(void)
{
    tally t = {0, 0, 0, INFINITY};
    int n, regions = 0, modal = 0;
    for (n = 0; n < 16; n++) {
        rw_scene_spec spec;
        rw_scene sc;
        sx_region r;
        int i, s;
        random_spec(&spec);
        spec.building.diaphragm_law = BD_ELASTIC;
        for (i = 0; i < spec.n_storeys; i++) {
            spec.building.md[i] = pow(10.0, uniform(-6.0, -2.0));
            spec.building.cd[i] = uniform(0.0, 0.1) * 2.0 * sqrt(spec.building.diaph[i].k * spec.building.md[i]);
            if (spec.has_wall[i]) spec.wall[i].Kd = pow(10.0, uniform(7.0, 9.0));
        }
        if (!region_of(&spec, 0, &sc, &r)) continue;
        regions++;
        for (s = 0; s < 8; s++) {
            const double h = s < 3 ? sx_hmax(&r) * uniform(0.05, 1.0) : uniform(1e-4, 1e-3);
            double xa0[SX_MAX_NA];
            sx_hermite_step hs;
            sx_mode_bounds B;
            start_state(&r, &sc, xa0);
            sx_hermite_step_of(&r, h, &hs);
            sx_mode_bounds_of(&r, &hs, xa0, &B);
            modal += B.modal;
            check_step(&r, xa0, h, NULL, &t);
        }
        sx_region_free(&r);
    }
    printf("light diaphragms: %d regions, %d steps from the modes' own coordinates, %ld points: %ld values and "
           "%ld rates outside their tails\n", regions, modal, t.tried, t.misses, t.rate_misses);
    CHECK(regions >= 8 && modal >= 20, "too few light regions tried (%d, %d modal steps)", regions, modal);
    CHECK(t.misses == 0 && t.rate_misses == 0, "the light diaphragms' polynomials missed at %ld values and %ld rates",
          t.misses, t.rate_misses);
}

/* The paper's first wall (dohertyHinge) under a stiff tie to a light diaphragm, in the region the
 * 0.3-g Gaussian pulse takes it to where its mechanism has no stiffness: a double eigenvalue 0 with
 * one eigenvector, which the modes keep as a block (rw_scene_exact_blocks.c). The region's hinge
 * moments Q = c + J q are the run's (exact in binary). Its polynomials with their tails bound the
 * exact motion at every point tried, over steps from 1 ms to 20 ms from random states. */
static void test_a_free_mechanism_is_a_block_that_bounds(void)
{
    rw_scene_spec spec;
    rw_scene sc;
    sx_region r;
    sx_key key;
    double x[RW_SCENE_NX];
    tally t = {0, 0, 0, INFINITY};
    int trial;
    memset(&spec, 0, sizeof spec);
    spec.n_storeys = 1, spec.rigid_in_plane = 1, spec.has_wall[0] = 1;
    rw_params_default(&spec.wall[0]);
    spec.wall[0].support = RW_FLEXIBLE_TOP, spec.wall[0].hingeLaw = RW_DOHERTY_HINGE;
    spec.wall[0].b = 0.15, spec.wall[0].h = 2.5, spec.wall[0].W = 6622.0, spec.wall[0].psi = 0.0;
    spec.wall[0].Kd = 1e8, spec.wall[0].er = 0.86;
    spec.building.md[0] = 1e-2, spec.building.diaph[0].k = 5e4;
    spec.building.cd[0] = 0.1 * sqrt(spec.building.diaph[0].k * spec.building.md[0]);
    rw_scene_start_state(&spec, NULL, x);
    rw_scene_init(&sc, &spec, 0.0, x);
    memset(&key, 0, sizeof key);
    key.standing[0] = 1;
    key.J[0][0][0] = -5173.4375, key.J[0][0][1] = key.J[0][1][0] = 1034.6875, key.J[0][1][1] = -1034.6875;
    key.c[0][0] = -554.2614, key.c[0][1] = 184.7538;
    key.cap[0] = sc.D[0].cap_b + sc.D[0].cap_m;
    memset(&r, 0, sizeof r);
    CHECK(sx_region_build(&sc, &key, &r, NULL) == 0, "the mechanism's region was not built");
    CHECK(r.modes.valid && r.modes.blocks == 1, "the mechanism's modes: valid %d, %d blocks (cond %.3g)",
          r.modes.valid, r.modes.blocks, r.modes.cond);
    for (trial = 0; trial < 40 && r.modes.valid; trial++) {
        const double h = uniform(1e-3, 2e-2);
        double xa0[SX_MAX_NA];
        int k;
        for (k = 0; k < r.ndof; k++) {
            xa0[k] = uniform(-1e-2, 1e-2) * (k < 2 ? 1.0 : 0.1);
            xa0[r.ndof + k] = uniform(-0.1, 0.1);
        }
        xa0[r.n] = uniform(-2.0, 2.0), xa0[r.n + 1] = uniform(-50.0, 50.0), xa0[r.n + 2] = 1.0;
        check_step(&r, xa0, h, NULL, &t);
    }
    printf("the block: %ld points, %ld values and %ld rates outside their tails\n", t.tried, t.misses, t.rate_misses);
    CHECK(t.tried > 0 && t.misses == 0 && t.rate_misses == 0,
          "the block's bounds missed the exact motion at %ld values and %ld rates of %ld", t.misses, t.rate_misses,
          t.tried);
    sx_region_free(&r);
}

/* same bits: 1 if the doubles at a and b hold the same bits */
static int same_bits(const double *a, const double *b, int n) { return memcmp(a, b, sizeof(double) * (size_t)n) == 0; }

/* mode k's bounds in a and b, to the bit (where the step holds bands, which modes are bands and
 * their free parts too) */
static int same_mode(const sx_mode_bounds *a, const sx_mode_bounds *b, int k)
{
    const sx_mode_bound *x = &a->mode[k], *y = &b->mode[k];
    if (!same_bits(&a->err[k], &b->err[k], 1) || !same_bits(&a->derr[k], &b->derr[k], 1) ||
        !same_bits(&a->size[k], &b->size[k], 1) || a->bands != b->bands || a->modal != b->modal)
        return 0;
    if (!a->bands) return 1;
    if (x->band != y->band) return 0;
    return !x->band || (same_bits(&x->psize, &y->psize, 1) && same_bits(x->re, y->re, 4) && same_bits(x->im, y->im, 4));
}

/* Without blocks the modes' bounds come from one pass over the modes without a branch (every mode
 * as a slow one, then the fast ones again): the same bits as each mode's own bound, as a region with
 * blocks takes them. Random regions of random scenes, their slow modes, fast ones and bands, over
 * steps from a fraction of the series' limit to 20 ms. */
static void test_the_modes_bounds_at_once_are_each_modes(void)
{
    int n, s, k, regions = 0, slow = 0, fast = 0, bands = 0, differ = 0;
    for (n = 0; n < 60; n++) {
        rw_scene_spec spec;
        rw_scene sc;
        sx_region r;
        random_spec(&spec);
        spec.building.diaphragm_law = coin() ? BD_BILINEAR : BD_ELASTIC;
        if (!region_of(&spec, 1, &sc, &r)) continue;
        regions += !r.modes.blocks;
        for (s = 0; s < 12 && !r.modes.blocks; s++) {
            const double h = s < 4 ? sx_hmax(&r) * uniform(0.05, 1.0) : (s < 8 ? 5e-3 : uniform(5e-3, 2e-2));
            double xa0[SX_MAX_NA];
            sx_hermite_step hs;
            sx_mode_bounds at_once, each;
            start_state(&r, &sc, xa0);
            sx_hermite_step_of(&r, h, &hs);
            sx_mode_bounds_of(&r, &hs, xa0, &at_once);
            sx_mode_bounds_each(&r, &hs, xa0, &each);
            for (k = 0; k < r.modes.count; k++) {
                slow += hs.wh[k] < 1.0;
                fast += hs.wh[k] >= 1.0 && !(hs.bands && each.mode[k].band);
                bands += hs.bands && each.mode[k].band;
                differ += !same_mode(&at_once, &each, k);
            }
        }
        sx_region_free(&r);
    }
    printf("modes' bounds at once: %d regions, %d slow modes, %d fast, %d bands: %d not each mode's to the bit\n",
           regions, slow, fast, bands, differ);
    CHECK(regions >= 30 && slow > 0 && fast > 0 && bands > 0, "too few modes tried (%d regions: %d, %d, %d)", regions,
          slow, fast, bands);
    CHECK(differ == 0, "%d modes' bounds differ from each mode's own", differ);
}

/* A step whose exact ends put one of a wall's lines on opposite sides of zero surely holds a crossing
 * (sx_watch_sure_cross), and the run then skips the quiet test: that is sound only where the test
 * could never clear such a step. Random regions, states and steps (a record interval of 5 ms, its
 * halves and quarters, and pieces within the series' limit) with the scene's own lines; every peak
 * out of reach, so that only a crossing can fail the test. */
static void test_a_sure_crossing_is_never_cleared(void)
{
    int n, s, regions = 0, sure = 0, tried = 0, wrong = 0;
    for (n = 0; n < 60; n++) {
        sx_run *R = (sx_run *)calloc(1, sizeof *R);
        rw_scene_result res;
        rw_scene_spec spec;
        sx_region r;
        int i;
        CHECK(R != NULL, "no memory");
        if (!R) return;
        random_spec(&spec);
        spec.building.diaphragm_law = BD_ELASTIC;
        if (!region_of(&spec, 1, &R->sc, &r)) {
            free(R);
            continue;
        }
        regions++;
        memset(&res, 0, sizeof res);
        for (i = 0; i < RW_SCENE_MAX_STOREYS; i++)
            res.peak_s1[i] = res.peak_s2[i] = res.peak_diaphragm[i] = res.peak_base_acc[i] = HUGE_VAL;
        R->res = &res;
        sx_watch_lines(R);
        for (s = 0; s < 32; s++) {
            const double h = s < 24 ? 5e-3 / (1 << (s % 3)) : sx_hmax(&r) * uniform(0.05, 1.0);
            const sx_step *st = sx_step_of(&r, h, 0.0, 1);
            double xa0[SX_MAX_NA], xa1[SX_MAX_NA];
            CHECK(st != NULL, "no table");
            if (!st) break;
            start_state(&r, &R->sc, xa0);
            sx_step_propagate(&r, st, xa0, xa1);
            tried++;
            if (!sx_watch_sure_cross(R, &r, xa0, xa1)) continue;
            sure++;
            wrong += sx_quiet_ends(R, &r, &st->herm, xa0, xa1) != SX_MAY_CROSS;
        }
        sx_region_free(&r);
        free(R);
    }
    printf("sure crossings: %d regions, %d steps, %d sure to cross, %d of them not failed by the quiet test\n",
           regions, tried, sure, wrong);
    CHECK(regions >= 30 && sure >= 50, "too few sure crossings tried (%d regions, %d)", regions, sure);
    CHECK(wrong == 0, "the quiet test did not fail %d steps that surely cross", wrong);
}

int main(void)
{
    srand(20261207);
    test_random_regions_bound_their_motion();
    test_light_diaphragms_bound_their_motion();
    test_a_free_mechanism_is_a_block_that_bounds();
    test_a_sure_crossing_is_never_cleared();
    test_the_modes_bounds_at_once_are_each_modes();
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
