/* Helpers shared by the wall's unit tests (test_physics_*.c): a relative check, the paper's wall,
 * the initial regime, a reproducible random number. */
#ifndef RW_PHYSICS_CHECK_H
#define RW_PHYSICS_CHECK_H

#include <math.h>

#include "check.h"
#include "rw_physics.h"

static inline void check_close(const char *what, double got, double want, double rtol)
{
    const double tol = rtol * fmax(1.0, fabs(want));
    CHECK(fabs(got - want) <= tol, "%s = %.12g, expected %.12g", what, got, want);
}

static inline rw_params paper_params(void)
{
    rw_params p;
    rw_params_default(&p);
    p.h = 2.5; p.b = 0.15; p.W = 6622.0; p.psi = 0.5; p.Kd = 1e5; p.g = 9.81;
    return p;
}

/* the paper's wall with the statics parameters away from their defaults: pointing 7.5 mm on each
 * face, the reactions set in from the faces, the top load 40 mm toward +x, weight-only overburden */
static inline rw_params eccentric_params(void)
{
    rw_params p = paper_params();
    p.pointing = 0.0075; p.eBaseRatio = 0.8; p.eHingeRatio = 0.9; p.eTop = 0.04; p.psiWeightOnly = 0.6;
    return p;
}

static inline void init(const rw_params *p, rw_derived *d, rw_regime *m, const rw_input *in, double x[RW_NX])
{
    rw_derive(p, d);
    rw_init_regime(p, d, in, x, m, NULL, NULL);
}

/* a reproducible uniform number in [lo, hi) */
static inline double uniform(unsigned long *state, double lo, double hi)
{
    *state = *state * 6364136223846793005UL + 1442695040888963407UL;
    return lo + (hi - lo) * (double)(*state >> 11) / 9007199254740992.0;
}

#endif
