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

/* the doubt's peak on the exact series, over parts no longer than the region's limit */
static void resolve(sx_run *R, const sx_region *r, const sx_doubt *d)
{
    const int parts = sx_parts(r, d->h);
    double *peak = sx_peak_of(R->res, d->storey, d->kind), xa[SX_MAX_NA];
    sx_series s;
    int p;
    memcpy(xa, d->xa0, sizeof(double) * (size_t)r->na);
    for (p = 0; p < parts; p++) {
        sx_series_of(r, xa, d->h / parts, &s);
        *peak = sx_series_peak(R, r, &s, d->storey, d->kind, *peak);
        sx_series_at(r, &s, 1.0, xa); /* the next part's start */
    }
}

static int larger_bound_first(const void *a, const void *b)
{
    const double x = ((const sx_doubt *)a)->bound, y = ((const sx_doubt *)b)->bound;
    return (x < y) - (x > y);
}

void sx_settle_doubts(sx_run *R, int region)
{
    int k, kept = 0;
    if (region < 0) qsort(R->doubts, (size_t)R->ndoubts, sizeof *R->doubts, larger_bound_first);
    for (k = 0; k < R->ndoubts; k++) {
        const sx_doubt *d = &R->doubts[k];
        if (region >= 0 && d->region != region) {
            R->doubts[kept++] = *d;
            continue;
        }
        if (d->bound > *sx_peak_of(R->res, d->storey, d->kind)) resolve(R, &R->regions[d->region], d);
    }
    R->ndoubts = kept;
}

int sx_doubt_peak(sx_run *R, int storey, int kind, double bound, double h, const double xa0[])
{
    const sx_region *r = &R->regions[R->cur];
    sx_doubt *d;
    if (!R->doubts && !(R->doubts = (sx_doubt *)malloc(SX_DOUBTS * sizeof *R->doubts))) return 1;
    if (R->ndoubts == SX_DOUBTS) sx_settle_doubts(R, -1);
    d = &R->doubts[R->ndoubts++];
    d->bound = bound, d->h = h, d->storey = storey, d->kind = kind, d->region = R->cur;
    memcpy(d->xa0, xa0, sizeof(double) * (size_t)r->na);
    return 0;
}

void sx_free_doubts(sx_run *R)
{
    free(R->doubts);
    R->doubts = NULL;
    R->ndoubts = 0;
}
