/* A scene (rw_scene.h) run over a ground-motion record with CVODE: Adams (fixed-point iteration, Newton
 * where the scene proves stiff) with root-finding on every wall's event indicators and the walls' own event rules at each root, one integration for the
 * whole scene. Works for every spring law of the building (linear, Bouc-Wen, pinched, bilinear). */
#ifndef RW_SCENE_RUN_H
#define RW_SCENE_RUN_H

#include <stddef.h>

#include "rw_scene.h"

/* error codes of rw_scene_run (0 = ok) */
enum {
    RW_SCENE_OK = 0,
    RW_SCENE_BAD_ARGUMENT = 1, /* NULL pointer, bad record, grid or option */
    RW_SCENE_BAD_SPEC = 2,     /* rw_scene_validate refused the scene */
    RW_SCENE_SOLVER = 3,       /* CVODE failed (message names the call and time) */
    RW_SCENE_ZENO = 4,         /* too many events at one instant */
    RW_SCENE_NO_MEMORY = 5,
    RW_SCENE_UNSUPPORTED = 6   /* the exact engine does not cover the scene (rw_scene_exact.h) */
};

/* the ground motion: n >= 2 samples at increasing times, linear between them, the ends held */
typedef struct {
    size_t n;
    const double *t, *ag; /* s, m/s2 (+ toward +x) */
} rw_scene_record;

typedef struct {
    double t_end;       /* the run is [t[0], t_end] */
    double rtol;        /* CVODE's relative tolerance; <= 0: 1e-8 */
    size_t n_out;       /* optional output grid, increasing times in [t[0], t_end] */
    const double *t_out;
    /* optional start state (RW_SCENE_NX values in the scene's layout, rw_scene.h), NULL = rest; the
     * floors' states are taken as zero when the in-plane walls are rigid */
    const double *x0;
    int bdf; /* 1: CVODE takes BDF with Newton throughout; 0: Adams, Newton from where the scene proves stiff */
} rw_scene_options;

typedef struct {
    /* per storey (0-based), the walls' displacements relative to their own base */
    double peak_s1[RW_SCENE_MAX_STOREYS], peak_s2[RW_SCENE_MAX_STOREYS];
    double peak_diaphragm[RW_SCENE_MAX_STOREYS]; /* |diaphragm - its floor| */
    double peak_base_acc[RW_SCENE_MAX_STOREYS];  /* |absolute acceleration of the wall's base| */
    int collapsed[RW_SCENE_MAX_STOREYS], collapse_reason[RW_SCENE_MAX_STOREYS];
    double t_collapse[RW_SCENE_MAX_STOREYS];     /* NaN if standing */
    long impacts[RW_SCENE_MAX_STOREYS];
    long steps, events;
    double t_reached;
    /* energy balance: E(t) - E(t0) = W_ground - W_damping - losses at events (impacts, walls that
     * collapsed and left the scene with their energy); residual = the difference of the two sides */
    double work_ground, work_damping, event_losses, energy_start, energy_end;
    double max_residual, max_work; /* max |residual| and max |W_ground| over the run */
    double t_newton; /* CVODE: when the run went on with Newton iteration (t0: from the start; NaN: never) */
    /* optional histories on the grid (caller-allocated, n_out * RW_SCENE_MAX_STOREYS each, row-major
     * [row][storey]) or NULL; tie_out: the tie's force on diaphragm i (+ toward +x; 0 once its wall
     * has collapsed and left the scene) */
    double *s1_out, *s2_out, *diaphragm_out, *base_acc_out, *tie_out;
    char message[256];
} rw_scene_result;

/* Runs the scene from rest (or opt->x0). Returns an error code (0 = ok) and fills res->message when not 0. */
int rw_scene_run(const rw_scene_spec *spec, const rw_scene_record *rec, const rw_scene_options *opt,
                 rw_scene_result *res);

/* The result's outputs set to nothing yet, its history pointers (the caller's) kept: both runners
 * start from it, so that a struct an earlier run filled says this run's numbers alone (its peaks
 * and maxima are kept as the larger of theirs and the motion's). */
void rw_scene_result_start(rw_scene_result *res);

/* The record, options and output grid checked (both runners): 0, or 1 with msg filled. */
int rw_scene_check_arguments(const rw_scene_record *rec, const rw_scene_options *opt, char *msg, size_t n);

/* sizeof rw_scene_spec, rw_scene_result and bd_params, for bindings that mirror them */
extern const size_t RW_SCENE_STRUCT_SIZES[3];

#endif
