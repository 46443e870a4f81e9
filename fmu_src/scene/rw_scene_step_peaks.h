/* The peaks of a wall's s1, s2 and its diaphragm's deformation inside a step of CVODE, found on the
 * cubic Hermite interpolant of the step's ends (values and rates). A step's ends alone miss the
 * top of a peak by about (w h)^2 / 8 of it (w the motion's frequency, h the step): 1e-5 of a wall's
 * peak at Adams's steps. The cubic's own error is about (w h)^4 / 384. */
#ifndef RW_SCENE_STEP_PEAKS_H
#define RW_SCENE_STEP_PEAKS_H

#include "rw_scene.h"

enum { RW_PEAK_S1, RW_PEAK_S2, RW_PEAK_DIAPHRAGM, RW_PEAK_KINDS };

/* the peak quantities' values and rates at one end of a step */
typedef struct {
    double t;
    double value[RW_PEAK_KINDS][RW_SCENE_MAX_STOREYS], rate[RW_PEAK_KINDS][RW_SCENE_MAX_STOREYS];
} rw_step_end;

/* the ends' values and rates at t from the state x and its derivative dx (the quantities are
 * linear in the state, so their rates are the same functionals of dx) */
void rw_step_end_at(const rw_scene *sc, double t, const double x[], const double dx[], rw_step_end *e);

/* raises peak[kind][storey] to the largest |value| inside the step from a to b */
void rw_step_peaks_inside(const rw_scene *sc, const rw_step_end *a, const rw_step_end *b,
                          double *peak[RW_PEAK_KINDS]);

#endif
