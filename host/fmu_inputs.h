/* The inputs of a run, set into the FMU as FMI 2.0 allows: continuous Real inputs at any time
 * (linear between samples), discrete ones (Real discrete, Integer, Enumeration, Boolean inputs,
 * tunable parameters) only in Initialization and Event Mode, held between samples; a sample time
 * where a discrete input changes, or where a continuous one steps (two rows of one time), is an
 * event of the run. */
#ifndef FMI2SIM_FMU_INPUTS_H
#define FMI2SIM_FMU_INPUTS_H

#include <stddef.h>

#include "fmu_binary.h"
#include "input_table.h"
#include "model_description.h"

typedef enum { IN_CONTINUOUS, IN_DISCRETE_REAL, IN_INTEGER, IN_BOOLEAN } input_kind;

typedef struct {
    const input_table *tab; /* the table and column it comes from */
    size_t col;
    const md_variable *var; /* the FMU variable it drives */
    input_kind kind;
} fmu_input;

typedef struct {
    fmu_input *in;
    size_t n;
    const input_table *tabs;
    size_t ntab;
    double t_lo; /* start of the current stretch of continuous time: continuous inputs take their value
                    from a step there, and the limit from the left at later times */
} fmu_inputs;

/* The kind of input a variable can be from a file (-1: none; *why says why). */
int fmu_input_kind(const md_variable *v, const char **why);
/* The columns of every table, matched to the FMU's variables (checked by the caller). */
int fmu_inputs_setup(fmu_inputs *ins, const model_description *md, const input_table *tabs, size_t ntab);
void fmu_inputs_free(fmu_inputs *ins);
/* fmi2Set* of the continuous inputs at time t (Continuous-Time Mode); the failing call's name in *call. */
fmi2Status fmu_inputs_set_continuous(const fmu_inputs *ins, const fmu_binary *fmu, fmi2Component c, double t,
                                     const char **call);
/* fmi2Set* of every input at t, the value from t on (Initialization and Event Mode); t becomes t_lo. */
fmi2Status fmu_inputs_set_all(fmu_inputs *ins, const fmu_binary *fmu, fmi2Component c, double t, const char **call);
/* The first sample time after t (INFINITY when none): the solver stops there. */
double fmu_inputs_next_time(const fmu_inputs *ins, double t);
/* Is t an event of the inputs: a discrete input changes there, or a continuous one steps? */
int fmu_inputs_event_at(const fmu_inputs *ins, double t);
/* " (the inputs there: ag = 1e+99 from rec.csv, ...)" into buf, for a solver's failure at t. */
const char *fmu_inputs_describe(const fmu_inputs *ins, double t, char *buf, size_t n);

#endif
