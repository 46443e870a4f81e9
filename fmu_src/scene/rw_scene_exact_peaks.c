/* Peaks left in doubt by the exact scene engine's quiet steps. A step whose indicators cannot
 * change sign is taken whether or not a peak may rise inside it; where one may, the step is kept
 * as a doubt (its start, its length, the polynomial bound on the quantity over it) instead of
 * being halved down to the exact series there and then. Most doubts are settled by the peak
 * reached later: a quantity's peak over the record is far above what its bound was early in the
 * record, and a doubt whose bound is not over the peak cannot change it. Only the others are
 * resolved on the exact series, the largest bounds first, which is the same answer the eager
 * resolution gives (to rounding). A tie's ringing keeps a floor's raw acceleration near its peak
 * so far for much of a record: it is what halved most intervals (docs/scenes.md). */
#include "rw_scene_exact_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifndef SX_DOUBTS
#define SX_DOUBTS 4096 /* kept at most at once (1.5 MB): when full, they are settled as at the end */
#endif

double *sx_peak_of(rw_scene_result *res, int storey, int kind)
{
    switch (kind) {
    case SX_PEAK_S1: return &res->peak_s1[storey];
    case SX_PEAK_S2: return &res->peak_s2[storey];
    case SX_PEAK_DEFORM: return &res->peak_diaphragm[storey];
    default: return &res->peak_base_acc[storey];
    }
}

/* the peak over [0, h] from xa0 on the exact series, over parts no longer than the region's limit */
static void on_series(sx_run *R, const sx_region *r, const sx_doubt *d, const double xa0[], double h)
{
    const int parts = sx_parts(r, h);
    double *peak = sx_peak_of(R->res, d->storey, d->kind), xa[SX_MAX_NA];
    sx_series s;
    int p;
    memcpy(xa, xa0, sizeof(double) * (size_t)r->na);
    for (p = 0; p < parts; p++) {
        sx_series_of(r, xa, h / parts, &s);
        *peak = sx_series_peak(R, r, &s, d->storey, d->kind, *peak);
        sx_series_at(r, &s, 1.0, xa); /* the next part's start */
    }
}

/* the propagators over a doubt's halves, exp(Aa h / 2^k) for k = 0..levels (by columns), of the
 * last doubt's region and length: the next doubts, mostly of the same record intervals, take them
 * as they are. Built for them rather than as step tables: a doubt goes down some twenty halvings
 * under a fast mode, which the tables' few slots would build again at every doubt. */
typedef struct {
    int region, levels;
    double h;
    double *Et;
} halves;

/* the halvings a piece of length h takes before the exact series' steps take it */
static int levels_of(const sx_region *r, double h)
{
    int k = 0;
    while (k < 40 && ldexp(h, -k) > 2.0 * sx_hmax(r)) k++;
    return k;
}

/* the chain for doubt d: kept, or built (0: none could be) */
static const halves *chain_for(sx_run *R, halves *c, const sx_doubt *d)
{
    sx_region *r = R->regions[d->region];
    const size_t nn = (size_t)(r->na * r->na);
    const int levels = levels_of(r, d->h);
    double *Et;
    if (c->region == d->region && c->levels == levels && fabs(c->h - d->h) <= SX_TIME_TOL(d->t1)) return c;
    c->region = -1;
    if (!(Et = (double *)realloc(c->Et, (size_t)(levels + 1) * nn * sizeof(double)))) return NULL;
    c->Et = Et;
    if (sx_halves_of(r, d->h, levels, SX_TIME_TOL(d->t1), ++R->stamp, c->Et)) return NULL;
    c->region = d->region, c->levels = levels, c->h = d->h;
    return c;
}

/* The doubt's piece `level` [0, h] from xa0 to its exact end xa1, whose bound is over the peak:
 * halved while it is longer than the exact series' steps, each half's exact ends taken as peaks and
 * the half dropped where the modes' bound over it no longer rises over the peak. A fast mode (a
 * diaphragm of a few grams per metre) makes the series' steps a ten-thousandth of the record's:
 * the halves find the peak in a few dozen bounds where the series would take that many steps per
 * interval. */
static void resolve_piece(sx_run *R, const halves *c, const sx_doubt *d, const double xa0[], const double xa1[],
                          double h, int level)
{
    const sx_region *r = R->regions[d->region];
    double mid[SX_MAX_NA];
    const double half = 0.5 * h;
    if (!c || level >= c->levels || !r->modes.valid) return on_series(R, r, d, xa0, h);
    sx_matvec_cols(r->na, r->na, c->Et + (size_t)(level + 1) * (size_t)(r->na * r->na), xa0, mid);
    sx_watch_peaks_at(R, r, mid); /* the motion's own values: they may settle the halves */
    if (sx_watch_peak_bound(R, r, half, xa0, mid, d->storey, d->kind) > 0.0) resolve_piece(R, c, d, xa0, mid, half, level + 1);
    if (sx_watch_peak_bound(R, r, half, mid, xa1, d->storey, d->kind) > 0.0) resolve_piece(R, c, d, mid, xa1, half, level + 1);
}

/* doubt d resolved: halved on its chain of propagators (NULL: none could be had), else on the series */
static void resolve(sx_run *R, const halves *c, const sx_doubt *d)
{
    const sx_region *r = R->regions[d->region];
    double end[SX_MAX_NA];
    if (!c || !r->modes.valid) return on_series(R, r, d, d->xa0, d->h);
    sx_matvec_cols(r->na, r->na, c->Et, d->xa0, end);
    resolve_piece(R, c, d, d->xa0, end, d->h, 0);
}

static int larger_bound_first(const void *a, const void *b)
{
    const double x = ((const sx_doubt *)a)->bound, y = ((const sx_doubt *)b)->bound;
    return (x < y) - (x > y);
}

void sx_settle_doubts(sx_run *R, int region)
{
    halves chain = {-1, 0, 0.0, NULL};
    int k, kept = 0;
    if (region < 0) qsort(R->doubts, (size_t)R->ndoubts, sizeof *R->doubts, larger_bound_first);
    for (k = 0; k < R->ndoubts; k++) {
        const sx_doubt *d = &R->doubts[k];
        if (region >= 0 && d->region != region) {
            R->doubts[kept++] = *d;
            continue;
        }
        if (d->bound > *sx_peak_of(R->res, d->storey, d->kind)) resolve(R, chain_for(R, &chain, d), d);
    }
    free(chain.Et);
    R->ndoubts = kept;
}

int sx_doubt_peak(sx_run *R, int storey, int kind, double bound, double h, const double xa0[])
{
    const sx_region *r = R->regions[R->cur];
    sx_doubt *d;
    if (!R->doubts && !(R->doubts = (sx_doubt *)sx_pool_alloc(SX_DOUBTS * sizeof *R->doubts))) return 1;
    if (R->ndoubts == SX_DOUBTS) sx_settle_doubts(R, -1);
    d = &R->doubts[R->ndoubts++];
    d->bound = bound, d->h = h, d->t1 = R->t + h, d->storey = storey, d->kind = kind, d->region = R->cur;
    memcpy(d->xa0, xa0, sizeof(double) * (size_t)r->na);
    return 0;
}

void sx_free_doubts(sx_run *R)
{
    sx_pool_free(R->doubts);
    R->doubts = NULL;
    R->ndoubts = 0;
}
