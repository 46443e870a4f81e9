/* fmi2sim: simulate any FMI 2.0 Model-Exchange FMU with SUNDIALS CVODE.
 * This file is the command line: options, checks of names and types against the model
 * description, input files, and the report. The simulation itself is in simulate_me.c. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmu_archive.h"
#include "fmu_binary.h"
#include "input_table.h"
#include "model_description.h"
#include "simulate_me.h"
#include "summary.h"

#define FMI2SIM_VERSION "0.1.0"

static const char *usage =
    "usage: fmi2sim MODEL.fmu|FOLDER [options]\n"
    "Simulates an FMI 2.0 Model-Exchange FMU with SUNDIALS CVODE and writes a CSV of its outputs.\n"
    "\n"
    "  --solver bdf|adams|erk   CVODE BDF or Adams, or ARKODE's explicit Runge-Kutta (ERKStep)\n"
    "                           (default bdf)\n"
    "  --rtol R                 relative tolerance (default 1e-6)\n"
    "  --atol A                 absolute tolerance (default rtol * nominal of each state)\n"
    "  --max-step H             largest CVODE step (default none)\n"
    "  --start-time T           default: DefaultExperiment startTime, else 0\n"
    "  --stop-time T            default: DefaultExperiment stopTime, else 1\n"
    "  --output-interval H      regular output grid (default (stop-start)/500)\n"
    "  --set NAME=VALUE         start value by variable name (repeatable; type-checked)\n"
    "  --input FILE.csv         inputs: header 'time,NAME,...', rows of numbers, times increasing;\n"
    "                           linearly interpolated, ends held\n"
    "  --ag FILE.AT2            PEER NGA acceleration record (in g) for the input 'ag' [m/s2]\n"
    "  --ag-scale S             factor on the record (default 1)\n"
    "  --g G                    gravity used to convert g to m/s2 (default 9.81)\n"
    "  --output FILE.csv        time and every output, plus a row before and after each event\n"
    "                           (default: standard output)\n"
    "  --summary FILE.json      max |value| and final value of every output (over output rows\n"
    "                           and solver steps); without --output no time history is written\n"
    "  --stats                  steps, evaluations, events and CPU time to standard error\n"
    "  --log                    switch the FMU's debug logging on\n"
    "  --help, --version\n"
    "Errors are reported as one line 'fmi2sim: error: ...' and a non-zero exit status.\n";

static int die(const char *fmt, ...)
{
    va_list ap;
    fputs("fmi2sim: error: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return 2;
}

static int parse_double(const char *opt, const char *text, double *out)
{
    char *end;
    errno = 0;
    *out = strtod(text, &end);
    if (end == text || *end || errno == ERANGE || !isfinite(*out)) {
        die("%s: '%s' is not a finite number", opt, text);
        return -1;
    }
    return 0;
}

/* Is "--set NAME=VALUE" allowed for this variable, and does VALUE fit its type? */
static int check_start_value(const model_description *md, const char *name, const char *value)
{
    const md_variable *v = md_find(md, name);
    char *end;
    if (!v) return die("--set %s: the model has no variable '%s'", name, name);
    if (strcmp(v->variability, "constant") == 0 || strcmp(v->causality, "independent") == 0 ||
        (v->initial && strcmp(v->initial, "calculated") == 0) ||
        (strcmp(v->causality, "parameter") != 0 && strcmp(v->causality, "input") != 0 && !v->start))
        return die("--set %s: '%s' (%s, %s) cannot be set", name, name, v->causality, v->variability);
    errno = 0;
    switch (v->type) {
    case MD_REAL: {
        double r = strtod(value, &end);
        if (end == value || *end || errno == ERANGE || isnan(r))
            return die("--set %s=%s: '%s' is not a Real", name, value, value);
        break;
    }
    case MD_INTEGER:
    case MD_ENUMERATION: {
        long k = strtol(value, &end, 10);
        if (end == value || *end || errno == ERANGE || k < -2147483647L - 1 || k > 2147483647L)
            return die("--set %s=%s: '%s' is not an Integer", name, value, value);
        break;
    }
    case MD_BOOLEAN:
        if (strcmp(value, "true") && strcmp(value, "false") && strcmp(value, "1") && strcmp(value, "0"))
            return die("--set %s=%s: '%s' is not a Boolean (true, false, 1, 0)", name, value, value);
        break;
    case MD_STRING:
        break;
    }
    return 0;
}

static int check_inputs(const model_description *md, const input_table *tabs, size_t ntab, const char *const *files)
{
    for (size_t i = 0; i < ntab; i++)
        for (size_t c = 0; c < tabs[i].ncols; c++) {
            const char *name = tabs[i].cols[c].name;
            const md_variable *v = md_find(md, name);
            if (!v) return die("%s:1: column '%s' is not a variable of the model", files[i], name);
            if (strcmp(v->causality, "input") != 0) return die("%s:1: '%s' is not an input of the model (causality %s)", files[i], name, v->causality);
            if (v->type != MD_REAL) return die("%s:1: input '%s' is a %s; only Real inputs can be read from files", files[i], name, md_type_name(v->type));
            for (size_t j = 0; j <= i; j++)
                for (size_t d = 0; d < tabs[j].ncols; d++)
                    if ((j < i || d < c) && strcmp(tabs[j].cols[d].name, name) == 0)
                        return die("%s:1: input '%s' is given twice", files[i], name);
        }
    return 0;
}

int main(int argc, char **argv)
{
    const char *fmu_path = NULL, *csv_path = NULL, *at2_path = NULL, *out_path = NULL;
    const char *summary_path = NULL;
    sim_summary summary = {0};
    double ag_scale = 1.0, g = 9.81;
    int stats_on = 0, status = 1;
    start_value *sets = calloc((size_t)argc, sizeof *sets);
    size_t nsets = 0;
    sim_options opt;
    double start = NAN, stop = NAN, interval = NAN;
    model_description md;
    fmu_archive archive;
    fmu_binary bin;
    input_table tabs[2];
    const char *tab_files[2];
    size_t ntab = 0;
    char err[2048], uri[8300], mdpath[8200];
    sim_stats st;

    memset(&opt, 0, sizeof opt);
    memset(&md, 0, sizeof md);
    memset(&archive, 0, sizeof archive);
    memset(&bin, 0, sizeof bin);
    opt.rtol = 1e-6;
    if (!sets) return die("out of memory");
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *val = (i + 1 < argc) ? argv[i + 1] : NULL;
#define NEED_VALUE() do { if (!val) { status = die("%s needs a value", a); goto out; } i++; } while (0)
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) { fputs(usage, stdout); status = 0; goto out; }
        else if (!strcmp(a, "--version")) { printf("fmi2sim " FMI2SIM_VERSION "\n"); status = 0; goto out; }
        else if (!strcmp(a, "--solver")) {
            NEED_VALUE();
            if (!strcmp(val, "bdf")) opt.adams = opt.erk = 0;
            else if (!strcmp(val, "adams")) opt.adams = 1, opt.erk = 0;
            else if (!strcmp(val, "erk")) opt.erk = 1, opt.adams = 0;
            else { status = die("--solver: '%s' is not bdf, adams or erk", val); goto out; }
        }
        else if (!strcmp(a, "--rtol")) { NEED_VALUE(); if (parse_double(a, val, &opt.rtol) || opt.rtol <= 0) { status = die("--rtol must be > 0"); goto out; } }
        else if (!strcmp(a, "--atol")) { NEED_VALUE(); if (parse_double(a, val, &opt.atol) || opt.atol <= 0) { status = die("--atol must be > 0"); goto out; } }
        else if (!strcmp(a, "--max-step")) { NEED_VALUE(); if (parse_double(a, val, &opt.max_step) || opt.max_step <= 0) { status = die("--max-step must be > 0"); goto out; } }
        else if (!strcmp(a, "--start-time")) { NEED_VALUE(); if (parse_double(a, val, &start)) goto out; }
        else if (!strcmp(a, "--stop-time")) { NEED_VALUE(); if (parse_double(a, val, &stop)) goto out; }
        else if (!strcmp(a, "--output-interval")) { NEED_VALUE(); if (parse_double(a, val, &interval) || interval <= 0) { status = die("--output-interval must be > 0"); goto out; } }
        else if (!strcmp(a, "--ag-scale")) { NEED_VALUE(); if (parse_double(a, val, &ag_scale)) goto out; }
        else if (!strcmp(a, "--g")) { NEED_VALUE(); if (parse_double(a, val, &g) || g <= 0) { status = die("--g must be > 0"); goto out; } }
        else if (!strcmp(a, "--input")) { NEED_VALUE(); csv_path = val; }
        else if (!strcmp(a, "--ag")) { NEED_VALUE(); at2_path = val; }
        else if (!strcmp(a, "--output")) { NEED_VALUE(); out_path = val; }
        else if (!strcmp(a, "--summary")) { NEED_VALUE(); summary_path = val; }
        else if (!strcmp(a, "--stats")) stats_on = 1;
        else if (!strcmp(a, "--log")) opt.logging = 1;
        else if (!strcmp(a, "--set")) {
            char *eq;
            NEED_VALUE();
            eq = strchr(val, '=');
            if (!eq || eq == val) { status = die("--set '%s': expected NAME=VALUE", val); goto out; }
            sets[nsets].name = strndup(val, (size_t)(eq - val));
            sets[nsets++].value = eq + 1;
        }
        else if (a[0] == '-' && a[1]) { status = die("unknown option '%s' (see --help)", a); goto out; }
        else if (!fmu_path) fmu_path = a;
        else { status = die("more than one FMU given: '%s' and '%s'", fmu_path, a); goto out; }
#undef NEED_VALUE
    }
    if (!fmu_path) { fputs(usage, stderr); status = 2; goto out; }

    if (fmu_unpack(fmu_path, &archive, err, sizeof err) != 0) { status = die("%s", err); goto out; }
    snprintf(mdpath, sizeof mdpath, "%s/modelDescription.xml", archive.dir);
    if (md_parse(mdpath, &md, err, sizeof err) != 0) { status = die("%s: %s", fmu_path, err); goto out; }
    for (size_t i = 0; i < nsets; i++)
        if ((status = check_start_value(&md, sets[i].name, sets[i].value)) != 0) goto out;
    if (csv_path) {
        if (input_read_csv(csv_path, &tabs[ntab], err, sizeof err) != 0) { status = die("%s", err); goto out; }
        tab_files[ntab++] = csv_path;
    }
    if (at2_path) {
        if (input_read_at2(at2_path, "ag", g, ag_scale, &tabs[ntab], err, sizeof err) != 0) { status = die("%s", err); goto out; }
        tab_files[ntab++] = at2_path;
    }
    if ((status = check_inputs(&md, tabs, ntab, tab_files)) != 0) goto out;
    status = 1;

    opt.start_time = !isnan(start) ? start : (md.has_start_time ? md.start_time : 0.0);
    opt.stop_time = !isnan(stop) ? stop : (md.has_stop_time ? md.stop_time : 1.0);
    if (!(opt.stop_time > opt.start_time)) { status = die("stop time %g is not after start time %g", opt.stop_time, opt.start_time); goto out; }
    opt.output_interval = !isnan(interval) ? interval : (opt.stop_time - opt.start_time) / 500.0;
    opt.start_values = sets;
    opt.n_start_values = nsets;
    opt.inputs = tabs;
    opt.n_inputs = ntab;
    snprintf(uri, sizeof uri, "file://%s/resources", archive.dir);
    opt.resource_uri = uri;
    opt.summary = summary_path ? &summary : NULL;
    /* a summary alone skips the time history: printing it is a good part of a short run */
    opt.output = out_path ? fopen(out_path, "w") : (summary_path ? NULL : stdout);
    if (out_path && !opt.output) { status = die("%s: %s", out_path, strerror(errno)); goto out; }

    if (fmu_binary_load(archive.dir, md.model_identifier, &bin, err, sizeof err) != 0) { status = die("%s: %s", fmu_path, err); goto out; }
    if (simulate_me(&md, &bin, &opt, &st, err, sizeof err) != 0) {
        status = die("%s: %s", fmu_path, err);
    } else {
        status = 0;
        if (st.terminated_by_model) fprintf(stderr, "fmi2sim: the model terminated the simulation at t = %.10g\n", st.end_time);
        if (summary_path && summary_write_json(summary_path, &summary, &st, err, sizeof err) != 0) status = die("%s", err);
    }
    if (stats_on)
        fprintf(stderr, "fmi2sim: stats: steps %ld, rhs evaluations %ld, root-function evaluations %ld, "
                        "events %ld (state %ld, time %ld, step %ld), CVODE re-initialisations %ld, cpu %.6f s\n",
                st.steps, st.rhs_evals, st.root_evals, st.events, st.state_events, st.time_events,
                st.step_events, st.reinits, st.cpu_seconds);

out:
    if (opt.output && opt.output != stdout) fclose(opt.output);
    summary_free(&summary);
    fmu_binary_unload(&bin);
    md_free(&md);
    fmu_cleanup(&archive);
    for (size_t i = 0; i < ntab; i++) input_free(&tabs[i]);
    for (size_t i = 0; i < nsets; i++) free((char *)sets[i].name);
    free(sets);
    return status;
}
