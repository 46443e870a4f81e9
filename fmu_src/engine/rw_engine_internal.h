/* Internal to the exact engine (rw_engine.c, rw_engine_regions.c, rw_engine_batch.c): not part of
 * its C API (rw_engine.h). */
#ifndef RW_ENGINE_INTERNAL_H
#define RW_ENGINE_INTERNAL_H

#include "rw_engine.h"

/* min and max of finite values without libm's calls (fmin, fmax handle NaN, which never reaches here) */
static inline double rw_min2(double a, double b) { return a < b ? a : b; }
static inline double rw_max2(double a, double b) { return a > b ? a : b; }

/* ---- regions (rw_engine_regions.c) ---- */
/* The region the state x (moving along dq_sel) is in, under the regime m: its cache entry, the
 * modal forcing g0 of its constant terms and, where the law allows it, its affine hinge moments
 * aq. NULL if the engine cannot decompose it (e->msg filled). */
rw_cache_entry *rw_engine_region_of(rw_engine *e, const rw_regime *m, const double x[RW_NX], const double dq_sel[2],
                                    double g0[2], rw_affine_Q *aq);
/* The 2DOF with open hinges on the region of Jacobian J (stiffness K - J): 0, or -1 (complex or
 * repeated modes) */
int rw_engine_modes_open(const rw_engine *e, const double J[2][2], rw_modes2 *E);
/* the modal forcing of a generalised force vector F */
void rw_engine_modal_force(const rw_modes2 *E, const double F[2], double out[2]);

/* ---- the run (rw_engine.c), for rw_engine_batch.c ---- */
/* The start at t0 from x (regime, the initial event iteration, the collapse test): 0, 1 if
 * collapsed, or an error code + 1 */
int rw_engine_begin(rw_engine *e, rw_regime *m, double x[RW_NX], double t0, const rw_input *in);
/* Advance over [*t, t_end] with the input linear (in, given at t_in): 0, 1 on collapse, or an
 * error code + 1 */
int rw_engine_advance(rw_engine *e, rw_regime *m, double x[RW_NX], double *t, double t_end, const rw_linear_input *in,
                      double t_in);
/* The segment [*t, t_end] when it is quiet (rw_engine.c): 1 (x, *t at its end), else 0 with
 * nothing changed, for rw_engine_advance */
int rw_engine_quiet_segment(rw_engine *e, rw_regime *m, double x[RW_NX], double *t, double t_end,
                            const rw_linear_input *in, double t_in);
/* the output grid's rows past where the run stopped: NaN */
void rw_engine_fill_outputs(rw_engine *e);

#endif
