/* Model-Exchange simulation of a loaded FMU with CVODE. */
#ifndef FMI2SIM_SIMULATE_ME_H
#define FMI2SIM_SIMULATE_ME_H

#include <stdio.h>
#include "fmu_binary.h"
#include "input_table.h"
#include "model_description.h"

typedef struct {
    const char *name, *value;
} start_value;

typedef struct {
    int adams;              /* 0: BDF, 1: Adams-Moulton */
    double rtol, atol;      /* atol <= 0: rtol * nominal of each state */
    double max_step;        /* <= 0: none */
    double start_time, stop_time, output_interval;
    const start_value *start_values;
    size_t n_start_values;
    const input_table *inputs;
    size_t n_inputs;
    int logging;            /* fmi2SetDebugLogging / logger verbosity */
    FILE *output;           /* CSV */
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
