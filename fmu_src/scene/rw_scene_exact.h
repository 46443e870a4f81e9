/* The exact scene engine: a scene (rw_scene.h) over a record without a time-stepping solver.
 *
 * Between two events, inside one record interval (the record is linear between samples), a scene
 * whose building springs are linear and whose walls' hinge moments are affine on the region the
 * motion is in (Q = c + J q: semiRigidHinge, dohertyHinge) is a linear time-invariant system
 * M X'' + C X' + K X = f + b ag(t) in X = (each standing wall's q1, q2; the floors; the
 * diaphragms). Its motion is advanced exactly (to rounding) by the Taylor series of the augmented
 * state matrix over substeps short enough for the series to converge fast; the walls' event
 * indicators are located on that exact solution, and each wall's own event rules
 * (rw_scene_event_update) are applied at each root. docs/scenes.md says how.
 *
 * Same arguments and result as rw_scene_run (rw_scene_run.h, CVODES); what it does not cover
 * (Bouc-Wen springs, the rigid and semiRigidPaper hinge laws) is refused with
 * RW_SCENE_UNSUPPORTED and a message, and the caller runs CVODES instead. */
#ifndef RW_SCENE_EXACT_H
#define RW_SCENE_EXACT_H

#include <stddef.h>

#include "rw_scene_run.h"

/* 0 if rw_scene_run_exact covers the (validated) scene, else RW_SCENE_UNSUPPORTED with msg filled */
int rw_scene_exact_covers(const rw_scene_spec *spec, char *msg, size_t n);

/* Runs the scene from rest (or opt->x0) to opt->t_end; opt->rtol is not used (the motion is
 * exact). Returns an error code (rw_scene_run.h, 0 = ok) and fills res->message when not 0. */
int rw_scene_run_exact(const rw_scene_spec *spec, const rw_scene_record *rec, const rw_scene_options *opt,
                       rw_scene_result *res);

/* The rates of the scene's states from the engine's linear system on the region of x (for tests:
 * they equal rw_scene_derivatives' rates of the positions and velocities). The scene must be
 * covered and set up (rw_scene_init). 0, or an error code. */
int rw_scene_exact_rates(const rw_scene *sc, double ag, const double x[], double dx[]);

#endif
