/* The exact engine's batch runs (rw_engine.h: rw_engine_run, rw_engine_run_many): argument
 * checks, the record as linear input segments, one engine per run over them. */
#include "rw_engine_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- the batch run ---------------------------------------------------------------------------- */
static int check_increasing(const double *v, size_t n, const char *what, char *msg, size_t len)
{
    size_t i;
    for (i = 0; i < n; i++) {
        if (!isfinite(v[i])) {
            snprintf(msg, len, "%s[%zu] is not finite", what, i);
            return 1;
        }
        if (i > 0 && !(v[i] > v[i - 1])) {
            snprintf(msg, len, "%s must be strictly increasing (%s[%zu] = %.17g after %.17g)", what, what, i, v[i],
                     v[i - 1]);
            return 1;
        }
    }
    return 0;
}

static int check_finite(const double *v, size_t n, const char *what, char *msg, size_t len)
{
    size_t i;
    for (i = 0; v && i < n; i++)
        if (!isfinite(v[i])) {
            snprintf(msg, len, "%s[%zu] is not finite", what, i);
            return 1;
        }
    return 0;
}

static int check_run_arguments(const rw_params *p, const rw_record *rec, const rw_engine_options *o, char *msg,
                               size_t n)
{
    if (!p || !rec || !o) {
        snprintf(msg, n, "rw_engine_run: params, record and options must not be NULL");
        return RW_ENGINE_BAD_ARGUMENT;
    }
    if (rec->n < 1 || !rec->t || !rec->ag) {
        snprintf(msg, n, "the record needs n >= 1 samples with times t and accelerations ag");
        return RW_ENGINE_BAD_ARGUMENT;
    }
    if (check_increasing(rec->t, rec->n, "t", msg, n) || check_finite(rec->ag, rec->n, "ag", msg, n) ||
        check_finite(rec->u_top, rec->n, "u_top", msg, n))
        return RW_ENGINE_BAD_ARGUMENT;
    if (!isfinite(o->t_start) || !isfinite(o->t_end) || !(o->t_end > o->t_start)) {
        snprintf(msg, n, "need finite t_start < t_end, got %g, %g", o->t_start, o->t_end);
        return RW_ENGINE_BAD_ARGUMENT;
    }
    if (check_finite(o->x0, o->x0 ? RW_NX : 0, "x0", msg, n)) return RW_ENGINE_BAD_ARGUMENT;
    if (o->n_out > 0) {
        if (!o->t_out || check_increasing(o->t_out, o->n_out, "t_out", msg, n)) {
            if (!o->t_out) snprintf(msg, n, "n_out > 0 needs the output times t_out");
            return RW_ENGINE_BAD_ARGUMENT;
        }
        if (o->t_out[0] < o->t_start || o->t_out[o->n_out - 1] > o->t_end) {
            snprintf(msg, n, "output times must lie in [t_start, t_end]");
            return RW_ENGINE_BAD_ARGUMENT;
        }
    }
    return 0;
}

/* the input of the record on the segment starting at sample i (i = -1: before the first sample,
 * i = n - 1: after the last; both held) */
static rw_linear_input record_segment(const rw_record *rec, ptrdiff_t i)
{
    rw_linear_input in;
    memset(&in, 0, sizeof in);
    if (i < 0 || (size_t)i >= rec->n - 1) {
        const size_t k = i < 0 ? 0 : rec->n - 1;
        in.ag = rec->ag[k];
        in.u_top = rec->u_top ? rec->u_top[k] : 0.0;
        return in;
    }
    {
        const double dt = rec->t[i + 1] - rec->t[i];
        in.ag = rec->ag[i];
        in.ag_slope = (rec->ag[i + 1] - rec->ag[i]) / dt;
        if (rec->u_top) {
            in.u_top = rec->u_top[i];
            in.u_slope = (rec->u_top[i + 1] - rec->u_top[i]) / dt;
        }
    }
    return in;
}

/* the segment index whose interval [t_i, t_i+1) holds t (-1 before the first sample); ptrdiff_t, not
 * long: long has 32 bits on Windows */
static ptrdiff_t segment_of(const rw_record *rec, double t)
{
    size_t lo = 0, hi = rec->n;
    if (t < rec->t[0]) return -1;
    while (hi - lo > 1) { /* rec->t[lo] <= t < rec->t[hi] */
        const size_t mid = (lo + hi) / 2;
        if (rec->t[mid] <= t) lo = mid;
        else hi = mid;
    }
    return (ptrdiff_t)lo;
}

static void result_init(rw_engine_result *res)
{
    double *x_out = res->x_out, *s1 = res->s1_out, *s2 = res->s2_out;
    double *it = res->impact_t, *ie = res->impact_energy;
    const size_t cap = res->impact_cap;
    memset(res, 0, sizeof *res);
    res->impact_t = it;
    res->impact_energy = ie;
    res->impact_cap = cap;
    res->x_out = x_out;
    res->s1_out = s1;
    res->s2_out = s2;
    res->t_collapse = NAN;
}

/* Start: the state at t_start (x0 or rest) and the input there, then rwe_begin. */
static int run_start(rw_engine *e, const rw_record *rec, const rw_engine_options *o, rw_regime *m, double x[RW_NX])
{
    const ptrdiff_t seg = segment_of(rec, o->t_start);
    const rw_linear_input li = record_segment(rec, seg);
    rw_input in;
    in.ag = li.ag + li.ag_slope * (o->t_start - (seg >= 0 ? rec->t[seg] : o->t_start));
    in.u_top = li.u_top + li.u_slope * (o->t_start - (seg >= 0 ? rec->t[seg] : o->t_start));
    if (o->x0) memcpy(x, o->x0, sizeof(double) * RW_NX);
    else memset(x, 0, sizeof(double) * RW_NX);
    return rwe_begin(e, m, x, o->t_start, &in);
}

int rw_engine_run(const rw_params *p, const rw_record *rec, const rw_engine_options *o, rw_engine_result *res)
{
    rw_engine *e;
    rw_regime m;
    double x[RW_NX], t;
    ptrdiff_t seg;
    int rc;
    if (!res) return RW_ENGINE_BAD_ARGUMENT;
    result_init(res);
    rc = check_run_arguments(p, rec, o, res->message, sizeof res->message);
    if (rc) return rc;
    e = rw_engine_new(p, res->message, sizeof res->message);
    if (!e) {
        if (!rw_params_validate(p, res->message, sizeof res->message) &&
            rwe_parapet_beyond_small_rotation(p, res->message, sizeof res->message))
            return RW_ENGINE_UNSUPPORTED;
        return strstr(res->message, "memory") ? RW_ENGINE_NO_MEMORY : RW_ENGINE_BAD_PARAMETERS;
    }
    if (o->max_events_per_instant > 0) e->max_same_instant = o->max_events_per_instant;
    e->t_out = o->t_out;
    e->n_out = o->n_out;
    e->x_out = res->x_out;
    e->s1_out = res->s1_out;
    e->s2_out = res->s2_out;
    if (res->impact_t && res->impact_energy) {
        e->impact_t = res->impact_t;
        e->impact_energy = res->impact_energy;
        e->impact_cap = res->impact_cap;
    }
    rc = run_start(e, rec, o, &m, x);
    t = o->t_start;
    seg = segment_of(rec, t);
    while (rc == 0 && t < o->t_end) {
        const rw_linear_input in = record_segment(rec, seg);
        const double t_in = seg >= 0 ? rec->t[seg] : t;
        double t_next = (seg + 1 < (ptrdiff_t)rec->n) ? rec->t[seg + 1] : o->t_end;
        if (t_next > o->t_end) t_next = o->t_end;
        if (t_next > t && !rwe_quiet_segment(e, &m, x, &t, t_next, &in, t_in))
            rc = rwe_advance(e, &m, x, &t, t_next, &in, t_in);
        seg++;
    }
    rwe_fill_outputs(e);
    res->peak_s1 = e->peak_s1;
    res->peak_s2 = e->peak_s2;
    res->collapsed = e->collapsed;
    res->collapse_reason = e->reason;
    res->t_collapse = e->t_collapse;
    res->impacts = e->impacts;
    res->events = e->events;
    res->steps = e->steps;
    res->t_reached = t;
    memcpy(res->x_end, x, sizeof x);
    if (rc > 1) snprintf(res->message, sizeof res->message, "%s", e->msg);
    rw_engine_free(e);
    return rc > 1 ? rc - 1 : 0;
}

/* ---- sweeps ----------------------------------------------------------------------------------- */
static int check_many_arguments(size_t n, const rw_params *params, const double *scale, const rw_record *rec,
                                const rw_engine_options *opt, const rw_engine_batch *out, char *msg, size_t len)
{
    size_t i;
    if (!params || !rec || !opt || !out || (n > 0 && !rec->ag)) {
        snprintf(msg, len, "rw_engine_run_many: params, record, options and outputs must not be NULL");
        return RW_ENGINE_BAD_ARGUMENT;
    }
    if (opt->n_out > 0) {
        snprintf(msg, len, "rw_engine_run_many gives peaks only: no output grid (n_out = 0)");
        return RW_ENGINE_BAD_ARGUMENT;
    }
    for (i = 0; scale && i < n; i++)
        if (!isfinite(scale[i])) {
            snprintf(msg, len, "scale[%zu] is not finite", i);
            return RW_ENGINE_BAD_ARGUMENT;
        }
    return 0;
}

static void store_summary(const rw_engine_batch *out, size_t i, int code, const rw_engine_result *r)
{
    const int ran = code == 0 || code == RW_ENGINE_ZENO;
    if (out->peak_s1) out->peak_s1[i] = ran ? r->peak_s1 : NAN;
    if (out->peak_s2) out->peak_s2[i] = ran ? r->peak_s2 : NAN;
    if (out->collapsed) out->collapsed[i] = r->collapsed;
    if (out->t_collapse) out->t_collapse[i] = r->collapsed ? r->t_collapse : NAN;
    if (out->impacts) out->impacts[i] = r->impacts;
    if (out->code) out->code[i] = code;
}

int rw_engine_run_many(size_t n, const rw_params *params, int params_each, const double *scale, const rw_record *rec,
                       const rw_engine_options *opt, const rw_engine_batch *out, char *msg, size_t msg_len)
{
    double *ag = NULL;
    rw_record scaled;
    size_t i, j;
    int rc = check_many_arguments(n, params, scale, rec, opt, out, msg, msg_len);
    if (rc || n == 0) return rc;
    if (scale) { /* one buffer for the scaled record, reused by every run */
        ag = (double *)malloc(sizeof(double) * (rec->n > 0 ? rec->n : 1));
        if (!ag) {
            snprintf(msg, msg_len, "out of memory");
            return RW_ENGINE_NO_MEMORY;
        }
    }
    scaled = *rec;
    for (i = 0; i < n; i++) {
        rw_engine_result r;
        int code;
        memset(&r, 0, sizeof r);
        if (scale) {
            for (j = 0; j < rec->n; j++) ag[j] = scale[i] * rec->ag[j];
            scaled.ag = ag;
        }
        code = rw_engine_run(&params[params_each ? i : 0], &scaled, opt, &r);
        store_summary(out, i, code, &r);
    }
    free(ag);
    return 0;
}
