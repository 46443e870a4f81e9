/* The exact scene engine's run (rw_scene_exact.h): what it covers, the record's intervals (and the
 * output times) one after the other (rw_scene_exact_steps.c takes each), the scene's own event
 * update at each root (rw_scene_event_update: the walls' event rules and collapse) and the region
 * the motion goes into, the energy balance and the result. */
#include "rw_scene_exact_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_ROUNDS_PER_EVENT 100
#define MAX_EVENTS_PER_INSTANT 100

int rw_scene_exact_covers(const rw_scene_spec *spec, char *msg, size_t n)
{
    int i;
    if (!spec->rigid_in_plane && spec->building.storey_law != BD_ELASTIC)
        return snprintf(msg, n, "the exact engine takes linear in-plane walls only (storey law %d is hysteretic)",
                        spec->building.storey_law), RW_SCENE_UNSUPPORTED;
    for (i = 0; i < spec->n_storeys; i++) {
        const rw_hinge_law *law;
        if (!spec->has_wall[i]) continue;
        law = rw_hinge_law_of(spec->wall[i].hingeLaw);
        if (!law || !law->q_only)
            return snprintf(msg, n, "storey %d: the exact engine takes hinge laws whose moments are affine on a region "
                            "(semiRigidHinge, dohertyHinge), not %s", i + 1, law ? law->name : "this one"),
                   RW_SCENE_UNSUPPORTED;
    }
    return RW_SCENE_OK;
}

/* the record at t: linear between samples, the ends held */
double sx_ground(sx_run *R, double t)
{
    const rw_scene_record *rec = R->rec;
    size_t k = R->hint;
    if (t <= rec->t[0]) return rec->ag[0];
    if (t >= rec->t[rec->n - 1]) return rec->ag[rec->n - 1];
    while (k > 0 && rec->t[k] > t) k--;
    while (k + 2 < rec->n && rec->t[k + 1] <= t) k++;
    R->hint = k;
    if (t == rec->t[k]) return rec->ag[k]; /* (a sample: most calls, every interval's start and end) */
    return rec->ag[k] + (rec->ag[k + 1] - rec->ag[k]) * (t - rec->t[k]) / (rec->t[k + 1] - rec->t[k]);
}

static sx_region *current(sx_run *R) { return R->regions[R->cur]; }

static double energy(sx_run *R, double t);

/* the region's energy constant from the scene's own energy at the state it is entered at (R->e_event),
 * and its bilinear diaphragms' indicators */
static int entered(sx_run *R)
{
    sx_region *r = current(R);
    r->e_const = R->e_event - sx_region_energy(r, R->x);
    R->work_hysteretic = 0.0;
    sx_bilinear_entered(R);
    return RW_SCENE_OK;
}

/* a cached region (not slot `except`) whose key differs from key's in constants only, or NULL */
static const sx_region *sibling(const sx_run *R, const sx_key *key, int except)
{
    int k;
    for (k = 0; k < R->nregions; k++)
        if (k != except && R->regions[k]->Aa && sx_key_same_matrix(key, &R->regions[k]->key)) return R->regions[k];
    return NULL;
}

/* the region the motion at R->t goes into: kept, found among the cached ones, or built (dx: the
 * rates at R->x where the event update has them, else NULL) */
static int enter_region(sx_run *R, const double *dx)
{
    sx_key key;
    int k, slot = -1;
    sx_region_key(&R->sc, sx_ground(R, R->t), R->x, dx, &key);
    R->stamp++;
    if (R->cur >= 0 && sx_key_equal(&key, &current(R)->key)) return (current(R)->used = R->stamp), entered(R);
    for (k = 0; k < R->nregions; k++)
        if (sx_key_equal(&key, &R->regions[k]->key)) {
            R->cur = k;
            R->regions[k]->used = R->stamp;
            return entered(R);
        }
    if (R->nregions < R->capacity) { /* a slot's memory as it is first used (a region takes 127 KB,
                                        most of it for more storeys than this scene's: not zeroed, so
                                        what a region does not use stays untouched), from the memory
                                        the thread's last run left where it can */
        if (!(R->regions[R->nregions] = (sx_region *)sx_pool_alloc(sizeof(sx_region)))) {
            snprintf(R->res->message, sizeof R->res->message, "out of memory");
            return RW_SCENE_NO_MEMORY;
        }
        sx_region_blank(R->regions[R->nregions]);
        slot = R->nregions++;
    } else {
        for (k = 0; k < R->capacity; k++)
            if (slot < 0 || R->regions[k]->used < R->regions[slot]->used) slot = k;
        sx_settle_doubts(R, slot); /* their steps need the region's matrix */
    }
    R->cur = slot;
    R->regions[slot]->used = R->stamp;
    k = sx_region_build(&R->sc, &key, R->regions[slot], sibling(R, &key, slot));
    if (k == RW_SCENE_SOLVER) snprintf(R->res->message, sizeof R->res->message, "singular mass matrix at t = %.9g s", R->t);
    if (k == RW_SCENE_NO_MEMORY) snprintf(R->res->message, sizeof R->res->message, "out of memory");
    if (k) R->regions[slot]->key.standing[0] = -1; /* never matches */
    return k ? k : entered(R);
}

static double energy(sx_run *R, double t) { return rw_scene_energy(&R->sc, sx_ground(R, t), R->x); }

/* the peaks at the state after an event (a quiet step watches only its end: its start is the
 * end of the step before, or this state) */
static void peaks_now(sx_run *R)
{
    const sx_region *r = current(R);
    double xa[SX_MAX_NA];
    sx_gather(r, R->x, sx_ground(R, R->t), 0.0, xa); /* no functional has a term in the record's slope */
    sx_watch_peaks_at(R, r, xa);
}

/* the walls' event rules at t until nothing changes, then the new indicator lines and region */
int sx_handle_events(sx_run *R)
{
    const double ag = sx_ground(R, R->t);
    double before, dx[RW_SCENE_NX];
    int rounds = 0, flags, code;
    if (R->t == R->last_event_t && ++R->same_instant > MAX_EVENTS_PER_INSTANT) {
        snprintf(R->res->message, sizeof R->res->message, "more than %d events at t = %.9g s", MAX_EVENTS_PER_INSTANT, R->t);
        return RW_SCENE_ZENO;
    }
    if (R->t != R->last_event_t) R->same_instant = 0;
    R->last_event_t = R->t;
    sx_sync_hysteresis(R); /* the region left: its diaphragms' z and work */
    R->z_next_valid = 0;   /* the rates jump: the Bouc-Wen fits start afresh */
    before = energy(R, R->t);
    do { /* (the energy between two rounds is the same evaluation: the losses sum to the first's less the last's) */
        flags = rw_scene_event_update(&R->sc, R->t, ag, R->x, dx);
        R->res->events++;
        if (++rounds > MAX_ROUNDS_PER_EVENT) {
            snprintf(R->res->message, sizeof R->res->message,
                     "the walls' event iteration at t = %.9g s did not settle in %d rounds", R->t, MAX_ROUNDS_PER_EVENT);
            return RW_SCENE_ZENO;
        }
    } while (flags & 3);
    R->e_event = energy(R, R->t);
    R->losses += before - R->e_event;
    sx_watch_lines(R);
    /* a last round that changed nothing left the rates at x: the key takes them (evaluating them
     * again was 1.5 % of the house's run) */
    code = enter_region(R, flags ? NULL : dx);
    if (code == RW_SCENE_OK) peaks_now(R);
    return code;
}

static void track(double *peak, double v)
{
    if (fabs(v) > *peak) *peak = fabs(v);
}

/* the output row due at R->t: the state's own functions, and each base's acceleration from the
 * region's functional, the one its peak is taken from (the scene's rates, which the row took before,
 * were 40 % of a run that writes a row every millisecond, as the building's floors ask for) */
static void write_row(sx_run *R, const sx_region *r)
{
    rw_scene_result *res = R->res;
    double xa[SX_MAX_NA];
    int i;
    sx_gather(r, R->x, sx_ground(R, R->t), 0.0, xa); /* (no functional has a term in the record's slope) */
    for (i = 0; i < R->sc.S.n_storeys; i++) {
        const size_t row = R->next_out * RW_SCENE_MAX_STOREYS + (size_t)i;
        if (res->s1_out) res->s1_out[row] = rw_scene_s1(&R->sc, R->x, i);
        if (res->s2_out) res->s2_out[row] = rw_scene_s2(&R->sc, R->x, i);
        if (res->diaphragm_out) res->diaphragm_out[row] = rw_scene_diaphragm_deformation(&R->sc, R->x, i);
        if (res->base_acc_out) res->base_acc_out[row] = sx_functional(r, r->f_of[i][SX_BASE_ACC], xa);
        if (res->tie_out) res->tie_out[row] = rw_scene_tie_force(&R->sc, R->x, i);
    }
    R->next_out++;
}

/* the energy balance (the energy from the region's quadratic form) and the output row due at t */
static void observe(sx_run *R)
{
    const double t = R->t;
    rw_scene_result *res = R->res;
    const sx_region *r = current(R);
    const double e = sx_region_energy(r, R->x) + r->e_const + R->work_hysteretic;
    const double residual = e - res->energy_start - R->work_ground + R->work_damping + R->losses;
    track(&res->max_residual, residual);
    track(&res->max_work, R->work_ground);
    if (R->next_out < R->opt->n_out && t >= R->opt->t_out[R->next_out]) write_row(R, r);
}

/* where the interval from t ends: the next record sample, output time (the first not yet written
 * past the row due at t) or the end */
static double stop_after(sx_run *R, double t)
{
    const rw_scene_record *rec = R->rec;
    double stop = R->opt->t_end;
    size_t k = R->hint, out = R->next_out;
    while (k > 0 && rec->t[k - 1] > t) k--; /* (a window's samples may have moved the hint past t) */
    while (k < rec->n && rec->t[k] <= t) k++;
    if (k < rec->n && rec->t[k] < stop) stop = rec->t[k];
    if (t > R->t)
        while (out < R->opt->n_out && R->opt->t_out[out] <= t) out++;
    if (out < R->opt->n_out && R->opt->t_out[out] < stop) stop = R->opt->t_out[out];
    return stop;
}

static double next_stop(sx_run *R) { return stop_after(R, R->t); }

void sx_observe(sx_run *R)
{
    observe(R);
    R->res->t_reached = R->t;
}

static int integrate(sx_run *R)
{
    double t[SX_WINDOW + 1];
    while (R->t < R->opt->t_end) {
        int n = 1, taken;
        t[0] = R->t, t[1] = next_stop(R);
        while (n < SX_WINDOW && t[n] < R->opt->t_end) t[n + 1] = stop_after(R, t[n]), n++;
        taken = n > 1 ? sx_window(R, t, n) : 0;
        if (taken < 0 || (taken == 0 && sx_advance(R, t[1]))) return R->error;
        sx_observe(R);
    }
    return RW_SCENE_OK;
}

static void collect(sx_run *R)
{
    rw_scene_result *res = R->res;
    int i;
    for (i = 0; i < R->sc.S.n_storeys; i++) {
        res->collapsed[i] = R->sc.collapsed[i];
        res->collapse_reason[i] = R->sc.reason[i];
        res->t_collapse[i] = R->sc.t_collapse[i];
        res->impacts[i] = R->sc.impacts[i];
    }
    res->work_ground = R->work_ground;
    res->work_damping = R->work_damping;
    res->event_losses = R->losses;
    res->energy_end = energy(R, res->t_reached);
}

static void free_run(sx_run *R)
{
    int k;
    sx_free_doubts(R);
    for (k = 0; k < R->nregions; k++) {
        sx_region_free(R->regions[k]);
        sx_pool_free(R->regions[k]);
    }
    free(R->regions);
    free(R);
}

/* how many regions the cache holds: SX_REGIONS, fewer where the largest region's tables would
 * take more than SX_CACHE_BYTES (every storey with a wall, a floor and a z chain) */
static int region_capacity(const rw_scene_spec *spec)
{
    const double N = spec->n_storeys, n = 2.0 * 4.0 * N, na = n + 3.0 + 3.0 * N;
    const double rows = 4.0 * N * (SX_LO + 1) + N * SX_Z_NODES; /* the functionals' and z chains' */
    const double per = (double)sizeof(sx_region) + 8.0 * (2.0 * na * na + SX_STEPS * (4.0 * na * na + (n + 2.0 + rows) * na));
    const double fit = SX_CACHE_BYTES / per;
    return fit >= SX_REGIONS ? SX_REGIONS : (fit < 8.0 ? (SX_REGIONS < 8 ? SX_REGIONS : 8) : (int)fit);
}

static sx_run *new_run(const rw_scene_spec *spec, const rw_scene_record *rec, const rw_scene_options *opt,
                       rw_scene_result *res)
{
    sx_run *R = (sx_run *)calloc(1, sizeof *R);
    if (!R) return NULL;
    R->capacity = region_capacity(spec);
    R->regions = (sx_region **)calloc((size_t)R->capacity, sizeof(sx_region *));
    if (!R->regions) return free(R), NULL;
    R->rec = rec, R->opt = opt, R->res = res;
    R->cur = -1;
    R->t = rec->t[0];
    R->last_event_t = NAN;
    R->window_backoff = 1;
    rw_scene_start_state(spec, opt->x0, R->x);
    rw_scene_init(&R->sc, spec, rec->ag[0], R->x);
    return R;
}

int rw_scene_run_exact(const rw_scene_spec *spec, const rw_scene_record *rec, const rw_scene_options *opt,
                       rw_scene_result *res)
{
    sx_run *R;
    int code;
    if (!spec || !rec || !opt || !res) return RW_SCENE_BAD_ARGUMENT;
    rw_scene_result_start(res);
    if (rw_scene_check_arguments(rec, opt, res->message, sizeof res->message)) return RW_SCENE_BAD_ARGUMENT;
    if (rw_scene_validate(spec, res->message, sizeof res->message)) return RW_SCENE_BAD_SPEC;
    if (rw_scene_exact_covers(spec, res->message, sizeof res->message)) return RW_SCENE_UNSUPPORTED;
    R = new_run(spec, rec, opt, res);
    if (!R) return snprintf(res->message, sizeof res->message, "out of memory"), RW_SCENE_NO_MEMORY;
    res->energy_start = energy(R, R->t);
    res->t_reached = R->t;
    code = sx_handle_events(R);
    if (code == RW_SCENE_OK) {
        observe(R);
        code = integrate(R);
    }
    sx_settle_doubts(R, -1);
    sx_sync_hysteresis(R);
    collect(R);
    free_run(R);
    return code;
}

int rw_scene_exact_rates(const rw_scene *sc, double ag, const double x[], double dx[])
{
    sx_region r;
    sx_key key;
    double xa[SX_MAX_NA], d[SX_MAX_NA];
    int k, code;
    memset(&r, 0, sizeof r);
    sx_region_key(sc, ag, x, NULL, &key);
    code = sx_region_build(sc, &key, &r, NULL);
    if (code) return sx_region_free(&r), code;
    sx_gather(&r, x, ag, 0.0, xa);
    sx_matvec_cols(r.na, r.na, r.Aa_cols, xa, d);
    memset(dx, 0, sizeof(double) * RW_SCENE_NX);
    for (k = 0; k < r.ndof; k++) {
        dx[r.pos[k]] = d[k];
        dx[r.vel[k]] = d[r.ndof + k];
    }
    sx_region_free(&r);
    return RW_SCENE_OK;
}
