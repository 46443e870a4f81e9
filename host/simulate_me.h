/* Model-Exchange simulation of a loaded FMU with CVODE. */
#ifndef FMI2SIM_SIMULATE_ME_H
#define FMI2SIM_SIMULATE_ME_H

#include <stdio.h>
#include "fmu_binary.h"
#include "input_table.h"
#include "model_description.h"
#include "output_file.h"

typedef struct {
    const char *name, *value;
} start_value;

/* Peaks without a time history: for every output, max |value| and the last value, taken over the
 * output rows and every accepted solver step (so a peak between grid points is not missed).
 * simulate_me allocates the arrays; summary_free (summary.h) releases them. */
typedef struct {
    const md_variable **vars; /* outputs, XML order */
    double *max_abs, *final;  /* NAN for String outputs */
    size_t n;
} sim_summary;

typedef struct {
    int adams;              /* 0: BDF, 1: Adams-Moulton (CVODE) */
    int erk;                /* 1: ARKODE ERKStep (explicit Runge-Kutta) instead of CVODE */
    double rtol, atol;      /* atol <= 0: rtol * nominal of each state */
    double max_step;        /* <= 0: none */
    double start_time, stop_time, output_interval;
    const start_value *start_values;
    size_t n_start_values;
    const input_table *inputs;
    size_t n_inputs;
    int logging;            /* fmi2SetDebugLogging / logger verbosity */
    output_file *output;    /* CSV; NULL: no time history */
    sim_summary *summary;   /* NULL: none */
    const char *resource_uri;
} sim_options;

typedef struct {
    long steps, rhs_evals, root_evals, events, state_events, time_events, step_events, reinits;
    double cpu_seconds, end_time;
    int terminated_by_model;
} sim_stats;

/* 0 on success; -1 with a one-line reason in err. */
int simulate_me(const model_description *md, const fmu_binary *fmu, const sim_options *opt,
                sim_stats *stats, char *err, size_t n);

#endif
