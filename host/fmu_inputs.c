/* The inputs of a run, set into the FMU as FMI 2.0 allows (see fmu_inputs.h). FMUs that check the
 * calling sequence (the Reference FMUs' Feedthrough among them) refuse fmi2SetReal on a discrete
 * input in Continuous-Time Mode, and a discrete input that changed between two event instants
 * would be seen by the model at no event at all. */
#include "fmu_inputs.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int fmu_input_kind(const md_variable *v, const char **why)
{
    const int input = strcmp(v->causality, "input") == 0;
    const int tunable = strcmp(v->causality, "parameter") == 0 && strcmp(v->variability, "tunable") == 0;
    *why = NULL;
    if (!input && !tunable) {
        *why = "is not an input of the model (nor a tunable parameter)";
        return -1;
    }
    switch (v->type) {
    case MD_REAL:
        return input && strcmp(v->variability, "continuous") == 0 ? IN_CONTINUOUS : IN_DISCRETE_REAL;
    case MD_INTEGER:
    case MD_ENUMERATION:
        return IN_INTEGER;
    case MD_BOOLEAN:
        return IN_BOOLEAN;
    case MD_STRING:
        break;
    }
    *why = "is a String: only Real, Integer, Enumeration and Boolean inputs can be read from files";
    return -1;
}

int fmu_inputs_setup(fmu_inputs *ins, const model_description *md, const input_table *tabs, size_t ntab)
{
    size_t k = 0;
    const char *why;
    memset(ins, 0, sizeof *ins);
    ins->tabs = tabs;
    ins->ntab = ntab;
    for (size_t i = 0; i < ntab; i++) ins->n += tabs[i].ncols;
    ins->in = calloc(ins->n + 1, sizeof *ins->in);
    if (!ins->in) return -1;
    for (size_t i = 0; i < ntab; i++)
        for (size_t c = 0; c < tabs[i].ncols; c++, k++) {
            fmu_input *in = &ins->in[k];
            in->tab = &tabs[i];
            in->col = c;
            in->var = md_find(md, tabs[i].cols[c].name); /* existence and kind checked in main */
            in->kind = (input_kind)fmu_input_kind(in->var, &why);
        }
    return 0;
}

void fmu_inputs_free(fmu_inputs *ins)
{
    free(ins->in);
    memset(ins, 0, sizeof *ins);
}

static fmi2Status set_one(const fmu_input *in, const fmu_binary *fmu, fmi2Component c, double value,
                          const char **call)
{
    const fmi2ValueReference vr = in->var->vr;
    if (in->kind == IN_INTEGER) {
        const fmi2Integer k = (fmi2Integer)value; /* whole numbers in range: checked in main */
        *call = "fmi2SetInteger (input)";
        return fmu->setInteger(c, &vr, 1, &k);
    }
    if (in->kind == IN_BOOLEAN) {
        const fmi2Boolean b = value != 0.0 ? fmi2True : fmi2False;
        *call = "fmi2SetBoolean (input)";
        return fmu->setBoolean(c, &vr, 1, &b);
    }
    *call = "fmi2SetReal (input)";
    return fmu->setReal(c, &vr, 1, &value);
}

fmi2Status fmu_inputs_set_continuous(const fmu_inputs *ins, const fmu_binary *fmu, fmi2Component c, double t,
                                     const char **call)
{
    for (size_t i = 0; i < ins->n; i++) {
        const fmu_input *in = &ins->in[i];
        fmi2Status st;
        if (in->kind != IN_CONTINUOUS) continue;
        st = set_one(in, fmu, c, t <= ins->t_lo ? input_value(in->tab, in->col, t) : input_value_left(in->tab, in->col, t),
                     call);
        if (st > fmi2Warning) return st;
    }
    return fmi2OK;
}

fmi2Status fmu_inputs_set_all(fmu_inputs *ins, const fmu_binary *fmu, fmi2Component c, double t, const char **call)
{
    ins->t_lo = t;
    for (size_t i = 0; i < ins->n; i++) {
        const fmu_input *in = &ins->in[i];
        const double v = in->kind == IN_CONTINUOUS ? input_value(in->tab, in->col, t) : input_value_held(in->tab, in->col, t);
        const fmi2Status st = set_one(in, fmu, c, v, call);
        if (st > fmi2Warning) return st;
    }
    return fmi2OK;
}

double fmu_inputs_next_time(const fmu_inputs *ins, double t)
{
    double next = INFINITY;
    for (size_t i = 0; i < ins->ntab; i++) {
        const input_table *tab = &ins->tabs[i];
        size_t lo = 0, hi = tab->n;
        while (lo < hi) { /* first sample > t */
            size_t mid = (lo + hi) / 2;
            if (tab->t[mid] <= t) lo = mid + 1; else hi = mid;
        }
        if (lo < tab->n && tab->t[lo] < next) next = tab->t[lo];
    }
    return next;
}

int fmu_inputs_event_at(const fmu_inputs *ins, double t)
{
    for (size_t i = 0; i < ins->n; i++)
        if (input_steps_at(ins->in[i].tab, ins->in[i].col, t, ins->in[i].kind != IN_CONTINUOUS)) return 1;
    return 0;
}

const char *fmu_inputs_describe(const fmu_inputs *ins, double t, char *buf, size_t n)
{
    size_t used = 0;
    buf[0] = '\0';
    for (size_t i = 0; i < ins->n && used + 1 < n; i++) {
        const fmu_input *in = &ins->in[i];
        const int w = snprintf(buf + used, n - used, "%s%s = %g from %s", i ? ", " : " (the inputs there: ",
                               in->var->name, input_value_left(in->tab, in->col, t),
                               in->tab->source ? in->tab->source : "the inputs");
        if (w < 0) break;
        used += (size_t)w < n - used ? (size_t)w : n - used - 1;
    }
    if (ins->n && used + 2 < n) snprintf(buf + used, n - used, ")");
    return buf;
}
