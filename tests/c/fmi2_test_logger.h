/* The logger and callbacks the C tests of the FMI 2.0 API give the FMU: they keep the last message
 * (raw, and formatted with its category and instance) and its status, and count the calls. */
#ifndef RW_FMI2_TEST_LOGGER_H
#define RW_FMI2_TEST_LOGGER_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "fmi2Functions.h"

static char last_message[2048];  /* the message as the FMU passed it */
static char last_log[4096];      /* "[category] instance: message" */
static fmi2Status last_status;
static int n_logs = 0;
static int print_errors = 0;     /* set to echo every error message to stdout */

static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status, fmi2String category,
                   fmi2String message, ...)
{
    (void)env;
    snprintf(last_message, sizeof last_message, "%s", message ? message : "(null)");
    snprintf(last_log, sizeof last_log, "[%s] %s: %s", category, name, last_message);
    last_status = status;
    n_logs++;
    if (print_errors && status >= fmi2Error) printf("  log: %s\n", last_log);
}

static const fmi2CallbackFunctions CB = {logger, calloc, free, NULL, NULL};

/* one Real of an instance, NaN when the call fails */
static inline double get_real(fmi2Component c, fmi2ValueReference vr)
{
    double v = NAN;
    fmi2GetReal(c, &vr, 1, &v);
    return v;
}

#endif
