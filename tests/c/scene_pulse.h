/* The ground motion the scene tests run under: the pulse D exp(-(t-1)^2/(2 s^2)) as acceleration
 * (the second derivative of a Gaussian displacement), s = 0.15 s, n samples 5 ms apart. */
#ifndef SCENE_PULSE_H
#define SCENE_PULSE_H

#include <math.h>

static void pulse(double D, int n, double *t, double *ag)
{
    int i;
    for (i = 0; i < n; i++) {
        const double s = 0.15, tt = 0.005 * i - 1.0;
        t[i] = 0.005 * i;
        ag[i] = D * (tt * tt / (s * s) - 1.0) / (s * s) * exp(-tt * tt / (2.0 * s * s));
    }
}

#endif
