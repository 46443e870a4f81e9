/* The exact motion of a region of the exact scene engine, for the tests that hold its bounds to it:
 * the Taylor series in parts no longer than the region's limit. */
#ifndef SCENE_SERIES_H
#define SCENE_SERIES_H

#include <string.h>

#include "rw_scene_exact_internal.h"

/* the exact motion over [0, L] from xa0 */
static void exact_state(const sx_region *r, const double xa0[], double L, double xa[])
{
    const int parts = sx_parts(r, L);
    sx_series s;
    int p;
    memcpy(xa, xa0, sizeof(double) * (size_t)r->na);
    for (p = 0; p < parts && L > 0.0; p++) {
        sx_series_of(r, xa, L / parts, &s);
        sx_series_at(r, &s, 1.0, xa);
    }
}

#endif
