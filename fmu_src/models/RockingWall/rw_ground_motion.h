/* A ground-motion record the RockingWall FMU reads itself (parameter agFile): a PEER NGA .AT2
 * file or a two-column CSV, read once at initialization, then the acceleration at any time,
 * linear between samples. No FMI types and no physics: the model (rw_model.c, cs_exact.c) uses it. */
#ifndef RW_GROUND_MOTION_H
#define RW_GROUND_MOTION_H

#include <stddef.h>

#include "fmu_symbol.h" /* the FMI2_FUNCTION_PREFIX of every external symbol */

#define rw_gm_read FMU_SYMBOL(rw_gm_read)
#define rw_gm_free FMU_SYMBOL(rw_gm_free)
#define rw_gm_at FMU_SYMBOL(rw_gm_at)

typedef struct {
    double *t;  /* sample times [s], strictly increasing */
    double *a;  /* accelerations [m/s2], scale applied */
    size_t n;   /* samples, at least 2 */
} rw_ground_motion;

/* Reads `path`: a name ending in .AT2 (any case) is an AT2 file (4 header lines, the 4th with NPTS
 * and DT, then the values in g, times g), anything else a CSV of two columns, time [s] and
 * acceleration [m/s2] (separated by commas, semicolons or blanks; '#' lines and one header line
 * skipped). Every value is multiplied by scale. 0 = read; else err says "FILE:LINE: problem" (or
 * "FILE: problem") and gm holds nothing. */
int rw_gm_read(const char *path, double g, double scale, rw_ground_motion *gm, char *err, size_t n);
void rw_gm_free(rw_ground_motion *gm);

/* The acceleration at t: linear between samples, 0 before the first and from the last on. *slope
 * gets its rate up to *t_next, the next time after t where the rate changes (a sample time, or
 * HUGE_VAL after the record). */
double rw_gm_at(const rw_ground_motion *gm, double t, double *slope, double *t_next);

#endif
