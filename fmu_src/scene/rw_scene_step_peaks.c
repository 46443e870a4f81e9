/* The peaks inside a CVODE step on the cubic Hermite interpolant of its ends (rw_scene_step_peaks.h). */
#include "rw_scene_step_peaks.h"

#include <math.h>

typedef double (*functional)(const rw_scene *sc, const double x[], int i);

static const functional FUNCTIONALS[RW_PEAK_KINDS] = {rw_scene_s1, rw_scene_s2, rw_scene_diaphragm_deformation};

void rw_step_end_at(const rw_scene *sc, double t, const double x[], const double dx[], rw_step_end *e)
{
    int k, i;
    e->t = t;
    for (k = 0; k < RW_PEAK_KINDS; k++)
        for (i = 0; i < sc->S.n_storeys; i++) {
            e->value[k][i] = FUNCTIONALS[k](sc, x, i);
            e->rate[k][i] = FUNCTIONALS[k](sc, dx, i);
        }
}

/* the cubic p(s), s in [0, 1], with p(0) = p0, p(1) = p1, p'(0) = m0, p'(1) = m1 */
static double hermite(double p0, double p1, double m0, double m1, double s)
{
    const double s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (3 * s2 - 2 * s3) * p1 + (s3 - s2) * m1;
}

/* the largest |p| at the cubic's turning points inside (0, 1): roots of a s^2 + b s + c = p'(s) */
static double largest_inside(double p0, double p1, double m0, double m1)
{
    const double a = 6 * p0 + 3 * m0 - 6 * p1 + 3 * m1, b = -6 * p0 - 4 * m0 + 6 * p1 - 2 * m1, c = m0;
    double roots[2], largest = 0.0;
    int n = 0, k;
    if (fabs(a) <= 1e-14 * (fabs(b) + fabs(c))) {
        if (b != 0.0) roots[n++] = -c / b;
    } else {
        const double disc = b * b - 4 * a * c;
        if (disc >= 0.0) { /* the stable pair of roots */
            const double q = -0.5 * (b + copysign(sqrt(disc), b));
            if (q != 0.0) roots[n++] = q / a, roots[n++] = c / q;
        }
    }
    for (k = 0; k < n; k++)
        if (roots[k] > 0.0 && roots[k] < 1.0) largest = fmax(largest, fabs(hermite(p0, p1, m0, m1, roots[k])));
    return largest;
}

void rw_step_peaks_inside(const rw_scene *sc, const rw_step_end *a, const rw_step_end *b,
                          double *peak[RW_PEAK_KINDS])
{
    const double h = b->t - a->t;
    int k, i;
    if (!(h > 0.0)) return;
    for (k = 0; k < RW_PEAK_KINDS; k++)
        for (i = 0; i < sc->S.n_storeys; i++)
            peak[k][i] = fmax(peak[k][i], largest_inside(a->value[k][i], b->value[k][i], h * a->rate[k][i],
                                                          h * b->rate[k][i]));
}
