/* The exact scene engine's answer does not depend on where its output rows fall. A row inside a
 * record interval splits it, and its two pieces take other tables and other quiet tests than the
 * whole interval: the peaks and collapses must stay the same to rounding. Two defects that broke
 * this, each caught here:
 * - a window of three record intervals checked that the second and third share the first's table by
 *   asking for their tables, and a table built for another length could take the first's slot (the
 *   window then took all three on the wrong table: 78 of 200 random scenes moved, by up to 64 % of
 *   a peak, where the rows fell inside the intervals);
 * - the quiet test took a wall's side line as moving away from zero from the start of a Hermite
 *   cubic whose fast mode (a band) had been taken out, not from the line's exact start, and a wall's
 *   base went past the line with no event (one house in 16 moved by 2.3 %, rows halfway between the
 *   samples).
 * Elastic and bilinear diaphragms: a Bouc-Wen one's steps are fits to a tolerance, and its peaks move
 * by up to about 5e-5 with the rows (docs/scenes.md). Run under ASan/UBSan by scripts/run_tests.sh. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "scene_pulse.h"
#include "scene_random.h"
#include "rw_scene_exact.h"

#define SAMPLES 801

/* the largest relative difference of the peaks of two runs of a scene, and whether they collapsed
 * alike (the same walls, at the same times) */
static double peaks_apart(const rw_scene_spec *spec, const rw_scene_result *a, const rw_scene_result *b, int *alike)
{
    double worst = 0.0;
    int i, kind;
    *alike = 1;
    for (i = 0; i < spec->n_storeys; i++) {
        for (kind = 0; kind < 4; kind++) {
            const double *pa = kind == 0 ? a->peak_s1 : kind == 1 ? a->peak_s2 : kind == 2 ? a->peak_diaphragm : a->peak_base_acc;
            const double *pb = kind == 0 ? b->peak_s1 : kind == 1 ? b->peak_s2 : kind == 2 ? b->peak_diaphragm : b->peak_base_acc;
            worst = fmax(worst, fabs(pa[i] - pb[i]) / (fmax(fabs(pa[i]), fabs(pb[i])) + 1e-300));
        }
        *alike &= a->collapsed[i] == b->collapsed[i] && (!a->collapsed[i] || fabs(a->t_collapse[i] - b->t_collapse[i]) <= 1e-9);
    }
    return worst;
}

/* The run with rows at t_out against the run without: the same peaks and collapses, as far as the
 * scene's own sensitivity allows (a change of the record in its last digits: the sum of a scene's
 * rounding moves its peaks by about that much, and with many impacts more) */
static void compare(const char *what, int n, const rw_scene_spec *spec, const double *t, const double *ag,
                    const double *t_out)
{
    static double rows[(SAMPLES - 1) * RW_SCENE_MAX_STOREYS], nudged[SAMPLES];
    const rw_scene_record rec = {SAMPLES, t, ag}, rec_nudged = {SAMPLES, t, nudged};
    rw_scene_options opt;
    rw_scene_result a, b, c;
    double apart, sensitivity;
    int k, alike, alike_nudged;
    for (k = 0; k < SAMPLES; k++) nudged[k] = ag[k] * (1.0 + (k % 3 ? 4e-16 : -4e-16));
    memset(&opt, 0, sizeof opt);
    memset(&a, 0, sizeof a), memset(&b, 0, sizeof b), memset(&c, 0, sizeof c);
    opt.t_end = t[SAMPLES - 1];
    CHECK(rw_scene_run_exact(spec, &rec, &opt, &a) == 0, "%s %d: %s", what, n, a.message);
    CHECK(rw_scene_run_exact(spec, &rec_nudged, &opt, &c) == 0, "%s %d nudged: %s", what, n, c.message);
    opt.n_out = SAMPLES - 1, opt.t_out = t_out, b.s1_out = rows;
    CHECK(rw_scene_run_exact(spec, &rec, &opt, &b) == 0, "%s %d with rows: %s", what, n, b.message);
    apart = peaks_apart(spec, &a, &b, &alike);
    sensitivity = peaks_apart(spec, &a, &c, &alike_nudged);
    CHECK((alike || !alike_nudged) && apart <= 1e-9 + 1e3 * sensitivity && a.t_reached == b.t_reached,
          "%s %d: the rows move the peaks by %.2g (the record's last digits by %.2g); peak s1 %.12g, %.12g without "
          "rows, %.12g, %.12g with them (%ld and %ld events)", what, n, apart, sensitivity, a.peak_s1[0], a.peak_s1[1],
          b.peak_s1[0], b.peak_s1[1], a.events, b.events);
}

/* Random scenes of one to three storeys (elastic or bilinear diaphragms, rigid or linear in-plane walls) under
 * pulses of random strength, rows inside every other interval at random and beside the other
 * samples by one rounding step (as a grid of rows of its own makes them) */
static void test_rows_anywhere_change_nothing(void)
{
    static double t[SAMPLES], ag[SAMPLES], t_out[SAMPLES - 1];
    int n, k;
    for (n = 0; n < 60; n++) {
        rw_scene_spec spec;
        random_spec(&spec);
        if (spec.building.diaphragm_law != BD_BILINEAR) spec.building.diaphragm_law = BD_ELASTIC;
        pulse(uniform(0.03, 0.12), SAMPLES, t, ag);
        t_out[0] = 0.0;
        for (k = 1; k < SAMPLES - 1; k++)
            t_out[k] = k % 2 ? t[k] + uniform(0.0, 1.0) * (t[k + 1] - t[k]) : nextafter(t[k], k % 4 ? 1.0 : -1.0);
        compare("scene", n, &spec, t, ag, t_out);
    }
}

/* Two-storey houses, stiff and soft ties, rows halfway between the samples */
static void test_rows_halfway_change_nothing_in_houses(void)
{
    static double t[SAMPLES], ag[SAMPLES], t_out[SAMPLES - 1];
    int n, k;
    srand(20261209); /* (the houses of test_scene_window.c; the side line's case is the 15th) */
    pulse(0.08, SAMPLES, t, ag);
    for (k = 0; k < SAMPLES - 1; k++) t_out[k] = 0.5 * (t[k] + t[k + 1]);
    for (n = 0; n < 16; n++) {
        rw_scene_spec spec;
        random_house(&spec, n % 2 ? 1e6 : 1e8);
        compare("house", n, &spec, t, ag, t_out);
    }
}

int main(void)
{
    srand(20261210);
    test_rows_anywhere_change_nothing();
    test_rows_halfway_change_nothing_in_houses();
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
