/* fmi2sim: simulate any FMI 2.0 Model-Exchange FMU with SUNDIALS CVODE.
 * This file is the command line: options, checks of names and types against the model
 * description, input files, and the report. The simulation itself is in simulate_me.c. */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cleanup.h"
#include "fmu_archive.h"
#include "fmu_binary.h"
#include "fmu_inputs.h"
#include "input_table.h"
#include "model_description.h"
#include "output_file.h"
#include "simulate_me.h"
#include "summary.h"

#define FMI2SIM_VERSION "0.1.0"

static const char *usage =
    "usage: fmi2sim MODEL.fmu|FOLDER [options]\n"
    "Simulates an FMI 2.0 Model-Exchange FMU with SUNDIALS CVODE and writes a CSV of its outputs.\n"
    "\n"
    "  --solver bdf|adams|erk   CVODE BDF or Adams, or ARKODE's explicit Runge-Kutta (ERKStep)\n"
    "                           (default bdf)\n"
    "  --rtol R                 relative tolerance in [1e-12, 0.01] (default 1e-8: free rocking\n"
    "                           then loses < 0.2 % of its energy per 100 s; 2.6 % at 1e-6)\n"
    "  --atol A                 absolute tolerance in [1e-16, 0.01] x the nominal of every state\n"
    "                           (default rtol * nominal of each state)\n"
    "  --max-step H             largest CVODE step, >= (stop - start) x 1e-8 (default none)\n"
    "  --start-time T           in [-1e9, 1e9] s; default: DefaultExperiment startTime, else 0\n"
    "  --stop-time T            in [-1e9, 1e9] s, stop - start >= 1e-6 x max(1, |start|, |stop|);\n"
    "                           default with --input/--ag: the time of the inputs' last sample\n"
    "                           (the whole record, no tail; a note says when --stop-time ends the\n"
    "                           run before it); without inputs: DefaultExperiment stopTime, else 1\n"
    "  --output-interval H      regular output grid in [(stop - start) x 1e-7, stop - start]\n"
    "                           (default (stop - start)/500)\n"
    "  --set NAME=VALUE         start value by variable name (repeatable; type-checked)\n"
    "  --input FILE.csv         inputs: header 'time,NAME,...', rows of numbers, times increasing;\n"
    "                           Real continuous inputs linear between rows, discrete ones (Real\n"
    "                           discrete, Integer, Boolean 0/1, tunable parameters) held and set\n"
    "                           at events; two rows of one time are a step; ends held\n"
    "  --ag FILE.AT2            PEER NGA acceleration record (in g) for the input 'ag' [m/s2]\n"
    "  --ag-scale S             factor on the record (default 1)\n"
    "  --g G                    gravity used to convert g to m/s2, in [0.1, 100] (default 9.81)\n"
    "  --output FILE.csv        time and every output, plus a row before and after each event\n"
    "                           (default: standard output); written to a temporary file beside it\n"
    "                           and renamed into place only when the run succeeded; never an input\n"
    "  --summary FILE.json      max |value| and final value of every output (over output rows\n"
    "                           and solver steps); without --output no time history is written\n"
    "  --stats                  steps, evaluations, events and CPU time to standard error\n"
    "  --log                    switch the FMU's debug logging on\n"
    "  --help, --version\n"
    "Errors are reported as one line 'fmi2sim: error: ...' and a non-zero exit status. On SIGINT,\n"
    "SIGTERM, SIGHUP and SIGPIPE the unpacked FMU and temporary files are removed first.\n";

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

/* The values of an Integer or Boolean column: whole numbers in range, 0 or 1. */
static int check_column_values(const input_table *tab, size_t c, input_kind kind, const char *file)
{
    const char *name = tab->cols[c].name;
    for (size_t r = 0; r < tab->n; r++) {
        const double v = tab->cols[c].values[r];
        if (kind == IN_INTEGER && !(v == floor(v) && v >= -2147483648.0 && v <= 2147483647.0))
            return die("%s: the row at time %g: input '%s' is an Integer: %g is not a whole number in [-2^31, 2^31 - 1]",
                       file, tab->t[r], name, v);
        if (kind == IN_BOOLEAN && v != 0.0 && v != 1.0)
            return die("%s: the row at time %g: input '%s' is a Boolean: %g is not 0 or 1", file, tab->t[r], name, v);
    }
    return 0;
}

static int check_inputs(const model_description *md, const input_table *tabs, size_t ntab, const char *const *files)
{
    for (size_t i = 0; i < ntab; i++)
        for (size_t c = 0; c < tabs[i].ncols; c++) {
            const char *name = tabs[i].cols[c].name, *why;
            const md_variable *v = md_find(md, name);
            int kind;
            if (!v) return die("%s:1: column '%s' is not a variable of the model", files[i], name);
            if ((kind = fmu_input_kind(v, &why)) < 0)
                return die("%s:1: '%s' %s (a %s of causality %s)", files[i], name, why, md_type_name(v->type),
                           v->causality);
            if (check_column_values(&tabs[i], c, (input_kind)kind, files[i]) != 0) return 2;
            for (size_t j = 0; j <= i; j++)
                for (size_t d = 0; d < tabs[j].ncols; d++)
                    if ((j < i || d < c) && strcmp(tabs[j].cols[d].name, name) == 0)
                        return die("%s:1: input '%s' is given twice", files[i], name);
        }
    return 0;
}

/* ---- ranges of the options (stated in the usage text) ---------------------------------------- */
#define RTOL_MIN 1e-12
#define RTOL_MAX 1e-2
#define TIME_MAX 1e9              /* |start|, |stop| [s]: 30 years */
#define SPAN_MIN_REL 1e-6         /* stop - start against the times' magnitude: resolvable steps */
#define MAX_STEP_MIN_REL 1e-8     /* --max-step forces at most 1e8 steps */
#define INTERVAL_MIN_REL 1e-7     /* the output grid has at most 1e7 rows */
#define G_MIN 0.1
#define G_MAX 100.0

static int in_range(const char *opt, double x, double lo, double hi)
{
    if (x >= lo && x <= hi) return 0;
    die("%s %g is out of range: it must lie in [%g, %g]", opt, x, lo, hi);
    return -1;
}

/* The options that depend on the start and stop times, once those are known; the times' labels
 * say where each came from (an option, the inputs, the model description). */
static int check_times(const sim_options *o, const char *start_label, const char *stop_label, double max_step,
                       double interval)
{
    const double span = o->stop_time - o->start_time;
    const double scale = fmax(1.0, fmax(fabs(o->start_time), fabs(o->stop_time)));
    if (in_range(start_label, o->start_time, -TIME_MAX, TIME_MAX) || in_range(stop_label, o->stop_time, -TIME_MAX, TIME_MAX))
        return -1;
    if (!(span >= SPAN_MIN_REL * scale)) {
        die("stop time %.17g - start time %.17g = %g is out of range: it must be >= 1e-6 x max(1, |start|, |stop|) = %g",
            o->stop_time, o->start_time, span, SPAN_MIN_REL * scale);
        return -1;
    }
    if (max_step > 0 && max_step < MAX_STEP_MIN_REL * span) {
        die("--max-step %g is out of range: it must be >= (stop - start) x 1e-8 = %g", max_step, MAX_STEP_MIN_REL * span);
        return -1;
    }
    if (!isnan(interval)) return in_range("--output-interval", interval, INTERVAL_MIN_REL * span, span);
    return 0;
}

/* "/tmp/fmi2sim_XXXXXX/modelDescription.xml:7: ..." as "modelDescription.xml:7: ...": the
 * temporary folder is gone when the user reads the message, the FMU's name is given with it. */
static const char *without_temp_dir(const char *msg, const fmu_archive *a)
{
    size_t len = strlen(a->dir);
    return a->is_temp && strncmp(msg, a->dir, len) == 0 && msg[len] == '/' ? msg + len + 1 : msg;
}

/* ---- outputs are never inputs -------------------------------------------------------------- */
typedef struct {
    const char *path, *what;
} named_path;

/* Does path lie inside folder (both resolved)? A folder FMU's files are inputs too. */
static int inside_folder(const char *path, const char *folder)
{
    char dir[PATH_MAX], root[PATH_MAX], copy[PATH_MAX];
    char *slash;
    size_t len;
    snprintf(copy, sizeof copy, "%s", path);
    slash = strrchr(copy, '/');
    if (slash) *slash = '\0'; else snprintf(copy, sizeof copy, ".");
    if (!realpath(copy[0] ? copy : "/", dir) || !realpath(folder, root)) return 0;
    len = strlen(root);
    return strncmp(dir, root, len) == 0 && (dir[len] == '/' || dir[len] == '\0');
}

/* Are a and b the same existing regular file (device and inode, symlinks followed)? */
static int same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    return stat(a, &sa) == 0 && stat(b, &sb) == 0 && S_ISREG(sa.st_mode) && sa.st_dev == sb.st_dev &&
           sa.st_ino == sb.st_ino;
}

/* Refuse an output that is one of the inputs, lies inside a folder FMU, or is the other output:
 * writing it would destroy what the run reads (or the other result). */
static int check_outputs(const named_path *outs, size_t nout, const named_path *ins, size_t nin)
{
    for (size_t i = 0; i < nout; i++) {
        if (!outs[i].path) continue;
        for (size_t j = 0; j < nin; j++) {
            struct stat st;
            if (!ins[j].path || stat(ins[j].path, &st) != 0) continue;
            if (S_ISDIR(st.st_mode) && inside_folder(outs[i].path, ins[j].path))
                return die("%s %s lies inside the FMU folder %s: refusing to write into an input", outs[i].what,
                           outs[i].path, ins[j].path);
            if (same_file(outs[i].path, ins[j].path))
                return die("%s %s is the same file as %s %s: refusing to overwrite an input", outs[i].what,
                           outs[i].path, ins[j].what, ins[j].path);
        }
        for (size_t j = 0; j < i; j++)
            if (outs[j].path && (strcmp(outs[i].path, outs[j].path) == 0 || same_file(outs[i].path, outs[j].path)))
                return die("%s and %s are both %s", outs[j].what, outs[i].what, outs[i].path);
    }
    return 0;
}

/* With a standard stream closed, the next open file would take its number and the CSV would end
 * up on stderr (or the stats inside the CSV): give each closed one /dev/null. Returns a bit per
 * stream that was closed. */
static int reopen_closed_std_streams(void)
{
    int closed = 0;
    for (int fd = 0; fd <= 2; fd++)
        if (fcntl(fd, F_GETFD) == -1 && errno == EBADF) {
            closed |= 1 << fd;
            if (open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY) != fd) return closed; /* cannot happen */
        }
    return closed;
}

/* The time of the last sample of any input table: where the record given ends. */
static double inputs_end_time(const input_table *tabs, size_t ntab)
{
    double end = -INFINITY;
    for (size_t i = 0; i < ntab; i++)
        if (tabs[i].n > 0 && tabs[i].t[tabs[i].n - 1] > end) end = tabs[i].t[tabs[i].n - 1];
    return end;
}

#define FROM_MD(attribute) "DefaultExperiment " attribute " of the FMU's modelDescription.xml"

/* The stop time: --stop-time if given; else the end of the inputs, so that a record is run to its
 * end rather than cut at the FMU's DefaultExperiment (RockingWall's 10 s of a 40-s record); else
 * DefaultExperiment stopTime, else 1. A given stop time before the inputs' end gets a note.
 * *label says where it came from. */
static double choose_stop_time(double requested, const model_description *md, const input_table *tabs, size_t ntab,
                               const char **label)
{
    const double inputs_end = inputs_end_time(tabs, ntab);
    if (!isnan(requested)) {
        if (ntab > 0 && requested < inputs_end)
            fprintf(stderr, "fmi2sim: note: the run stops at t = %.10g s (--stop-time), before the inputs end at "
                            "t = %.10g s\n", requested, inputs_end);
        *label = "--stop-time";
        return requested;
    }
    if (ntab > 0) {
        *label = "stop time (the inputs' last sample)";
        return inputs_end;
    }
    *label = md->has_stop_time ? "stop time (" FROM_MD("stopTime") ")" : "stop time (the default)";
    return md->has_stop_time ? md->stop_time : 1.0;
}

int main(int argc, char **argv)
{
    const char *fmu_path = NULL, *csv_path = NULL, *at2_path = NULL, *out_path = NULL;
    const char *summary_path = NULL, *start_label, *stop_label;
    sim_summary summary = {0};
    double ag_scale = 1.0, g = 9.81;
    int stats_on = 0, status = 1;
    const int closed_streams = reopen_closed_std_streams();
    start_value *sets = calloc((size_t)argc, sizeof *sets);
    size_t nsets = 0;
    sim_options opt;
    double start = NAN, stop = NAN, interval = NAN;
    model_description md;
    fmu_archive archive;
    fmu_binary bin;
    output_file csv;
    input_table tabs[2];
    const char *tab_files[2];
    size_t ntab = 0;
    char err[2048], uri[8300], mdpath[8200];
    sim_stats st;

    memset(&opt, 0, sizeof opt);
    memset(&md, 0, sizeof md);
    memset(&archive, 0, sizeof archive);
    memset(&bin, 0, sizeof bin);
    memset(&csv, 0, sizeof csv);
    opt.rtol = 1e-8; /* free rocking loses < 0.2 % of its energy per 100 s (scripts/stability_cases.py) */
    cleanup_install_signal_handlers();
    if (!sets) return die("out of memory");
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *val = (i + 1 < argc) ? argv[i + 1] : NULL;
#define NEED_VALUE() do { if (!val) { status = die("%s needs a value", a); goto out; } i++; } while (0)
#define NUMBER(target) do { NEED_VALUE(); if (parse_double(a, val, (target))) { status = 2; goto out; } } while (0)
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) { fputs(usage, stdout); status = 0; goto out; }
        else if (!strcmp(a, "--version")) { printf("fmi2sim " FMI2SIM_VERSION "\n"); status = 0; goto out; }
        else if (!strcmp(a, "--solver")) {
            NEED_VALUE();
            if (!strcmp(val, "bdf")) opt.adams = opt.erk = 0;
            else if (!strcmp(val, "adams")) opt.adams = 1, opt.erk = 0;
            else if (!strcmp(val, "erk")) opt.erk = 1, opt.adams = 0;
            else { status = die("--solver: '%s' is not bdf, adams or erk", val); goto out; }
        }
        else if (!strcmp(a, "--rtol")) { NUMBER(&opt.rtol); if (in_range(a, opt.rtol, RTOL_MIN, RTOL_MAX)) { status = 2; goto out; } }
        else if (!strcmp(a, "--atol")) { NUMBER(&opt.atol); if (opt.atol <= 0) { status = die("--atol must be > 0"); goto out; } }
        else if (!strcmp(a, "--max-step")) { NUMBER(&opt.max_step); if (opt.max_step <= 0) { status = die("--max-step must be > 0"); goto out; } }
        else if (!strcmp(a, "--start-time")) NUMBER(&start);
        else if (!strcmp(a, "--stop-time")) NUMBER(&stop);
        else if (!strcmp(a, "--output-interval")) { NUMBER(&interval); if (interval <= 0) { status = die("--output-interval must be > 0"); goto out; } }
        else if (!strcmp(a, "--ag-scale")) NUMBER(&ag_scale);
        else if (!strcmp(a, "--g")) { NUMBER(&g); if (in_range(a, g, G_MIN, G_MAX)) { status = 2; goto out; } }
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
#undef NUMBER
#undef NEED_VALUE
    }
    if (!fmu_path) { fputs(usage, stderr); status = 2; goto out; }
    if (!out_path && !summary_path && (closed_streams & 2)) {
        status = die("standard output is closed: give --output FILE.csv (or --summary FILE.json)");
        goto out;
    }
    {
        const named_path outs[] = {{out_path, "--output"}, {summary_path, "--summary"}};
        const named_path ins[] = {{fmu_path, "the FMU"}, {csv_path, "--input"}, {at2_path, "--ag"}};
        if ((status = check_outputs(outs, 2, ins, 3)) != 0) goto out;
        status = 1;
    }

    if (fmu_unpack(fmu_path, &archive, err, sizeof err) != 0) { status = die("%s", err); goto out; }
    snprintf(mdpath, sizeof mdpath, "%s/modelDescription.xml", archive.dir);
    if (md_parse(mdpath, &md, err, sizeof err) != 0) { status = die("%s: %s", fmu_path, without_temp_dir(err, &archive)); goto out; }
    for (size_t i = 0; i < nsets; i++) {
        for (size_t j = 0; j < i; j++)
            if (strcmp(sets[i].name, sets[j].name) == 0) {
                status = die("--set %s is given twice (%s and %s): give each variable once", sets[i].name,
                             sets[j].value, sets[i].value);
                goto out;
            }
        if ((status = check_start_value(&md, sets[i].name, sets[i].value)) != 0) goto out;
    }
    if (csv_path) {
        if (input_read_csv(csv_path, &tabs[ntab], err, sizeof err) != 0) { status = die("%s", err); goto out; }
        tab_files[ntab++] = csv_path;
    }
    if (at2_path) {
        if (input_read_at2(at2_path, "ag", g, ag_scale, &tabs[ntab], err, sizeof err) != 0) { status = die("%s", err); goto out; }
        tab_files[ntab++] = at2_path;
    }
    if ((status = check_inputs(&md, tabs, ntab, tab_files)) != 0) goto out;
    status = 2;

    opt.start_time = !isnan(start) ? start : (md.has_start_time ? md.start_time : 0.0);
    start_label = !isnan(start) ? "--start-time" : md.has_start_time ? "start time (" FROM_MD("startTime") ")"
                                                                      : "start time (the default)";
    opt.stop_time = choose_stop_time(stop, &md, tabs, ntab, &stop_label);
    if (!(opt.stop_time > opt.start_time)) {
        die("%s %g is not after %s %g", stop_label, opt.stop_time, start_label, opt.start_time);
        goto out;
    }
    if (check_times(&opt, start_label, stop_label, opt.max_step, interval) != 0) goto out;
    opt.output_interval = !isnan(interval) ? interval : (opt.stop_time - opt.start_time) / 500.0;
    opt.start_values = sets;
    opt.n_start_values = nsets;
    opt.inputs = tabs;
    opt.n_inputs = ntab;
    snprintf(uri, sizeof uri, "file://%s/resources", archive.dir);
    opt.resource_uri = uri;
    opt.summary = summary_path ? &summary : NULL;

    if (fmu_extract_binary(&archive, md.model_identifier, err, sizeof err) != 0) { die("%s", err); goto out; }
    if (fmu_binary_load(archive.dir, md.model_identifier, &bin, err, sizeof err) != 0) { die("%s: %s", fmu_path, err); goto out; }
    /* a summary alone skips the time history: printing it is a good part of a short run */
    if ((out_path || !summary_path) && output_open(&csv, out_path, err, sizeof err) != 0) { die("%s", err); goto out; }
    opt.output = csv.f ? &csv : NULL;
    if (simulate_me(&md, &bin, &opt, &st, err, sizeof err) != 0) {
        die("%s: %s", fmu_path, err);
    } else if (csv.f && output_commit(&csv, err, sizeof err) != 0) {
        die("%s", err);
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
    output_discard(&csv);
    summary_free(&summary);
    fmu_binary_unload(&bin);
    md_free(&md);
    fmu_cleanup(&archive);
    cleanup_all();
    for (size_t i = 0; i < ntab; i++) input_free(&tabs[i]);
    for (size_t i = 0; i < nsets; i++) free((char *)sets[i].name);
    free(sets);
    return status;
}
