/* rwengine: one run of the exact event-driven engine (fmu_src/engine/rw_engine.h) from the command line,
 * in fmi2sim's form (--set, --input/--ag, --stop-time), printing the peaks, the collapse and the
 * counters as one JSON object. For whole-process timing and shell pipelines; the batch C API and
 * the Python binding (rockingwall.engine) are the main ways in. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "input_table.h"
#include "rw_engine.h"

static const char usage[] =
    "usage: rwengine [options]\n"
    "Runs the RockingWall model with the exact event-driven engine (not the parapet) and prints\n"
    "{peak_s1, peak_s2, collapsed, t_collapse, impacts, events, steps, cpu_seconds} as JSON.\n\n"
    "  --set NAME=VALUE     a parameter of the FMU by name (repeatable; range-checked)\n"
    "  --input FILE.csv     header 'time,ag[,u_top]', rows of numbers; linear, ends held\n"
    "  --ag FILE.AT2        PEER NGA record (in g) for ag [m/s2]; --ag-scale S, --g G\n"
    "  --start-time T       default 0\n"
    "  --stop-time T        default: the last input sample\n"
    "  --help\n";

static int die(const char *msg, const char *arg)
{
    fprintf(stderr, "rwengine: error: %s%s\n", msg, arg ? arg : "");
    return 2;
}

static int parse_number(const char *s, double *v)
{
    char *end;
    *v = strtod(s, &end);
    return end == s || *end != '\0' || !isfinite(*v);
}

static int set_parameter(rw_params *p, const char *assign)
{
    char name[64], msg[256];
    const char *eq = strchr(assign, '=');
    const rw_param_info *info;
    double v;
    if (!eq || (size_t)(eq - assign) >= sizeof name) return die("--set needs NAME=VALUE, got ", assign);
    memcpy(name, assign, (size_t)(eq - assign));
    name[eq - assign] = '\0';
    info = rw_param_by_name(name);
    if (!info) return die("unknown parameter ", name);
    if (parse_number(eq + 1, &v)) return die("not a number: ", eq + 1);
    if (rw_param_set(p, info, v, msg, sizeof msg)) return die(msg, NULL);
    return 0;
}

static const double *column(const input_table *tab, const char *name)
{
    size_t i;
    for (i = 0; i < tab->ncols; i++)
        if (strcmp(tab->cols[i].name, name) == 0) return tab->cols[i].values;
    return NULL;
}

int main(int argc, char **argv)
{
    rw_params p;
    input_table tab;
    rw_engine_options o;
    rw_engine_result r;
    rw_record rec;
    const char *csv = NULL, *at2 = NULL;
    double scale = 1.0, g = 9.81, stop = NAN;
    char err[512];
    clock_t c0 = clock();
    int i, rc;
    rw_params_default(&p);
    memset(&o, 0, sizeof o);
    memset(&r, 0, sizeof r);
    memset(&tab, 0, sizeof tab);
    for (i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--help")) { fputs(usage, stdout); return 0; }
        if (!v) return die("missing value after ", a);
        i++;
        if (!strcmp(a, "--set")) { if (set_parameter(&p, v)) return 2; }
        else if (!strcmp(a, "--input")) csv = v;
        else if (!strcmp(a, "--ag")) at2 = v;
        else if (!strcmp(a, "--ag-scale")) { if (parse_number(v, &scale)) return die("--ag-scale: ", v); }
        else if (!strcmp(a, "--g")) { if (parse_number(v, &g) || g <= 0) return die("--g: ", v); }
        else if (!strcmp(a, "--start-time")) { if (parse_number(v, &o.t_start)) return die("--start-time: ", v); }
        else if (!strcmp(a, "--stop-time")) { if (parse_number(v, &stop)) return die("--stop-time: ", v); }
        else return die("unknown option ", a);
    }
    if (!csv == !at2) return die("give one of --input FILE.csv or --ag FILE.AT2", NULL);
    if ((csv ? input_read_csv(csv, &tab, err, sizeof err) : input_read_at2(at2, "ag", g, scale, &tab, err, sizeof err)) != 0)
        return die(err, NULL);
    rec.n = tab.n;
    rec.t = tab.t;
    rec.ag = column(&tab, "ag");
    rec.u_top = column(&tab, "u_top");
    if (!rec.ag) { input_free(&tab); return die("the input has no column 'ag'", NULL); }
    o.t_end = isnan(stop) ? tab.t[tab.n - 1] : stop;
    rc = rw_engine_run(&p, &rec, &o, &r);
    input_free(&tab);
    if (rc) return die(r.message, NULL);
    printf("{\"peak_s1\": %.17g, \"peak_s2\": %.17g, \"collapsed\": %s, \"t_collapse\": ", r.peak_s1, r.peak_s2,
           r.collapsed ? "true" : "false");
    if (r.collapsed) printf("%.17g", r.t_collapse);
    else fputs("null", stdout);
    printf(", \"impacts\": %ld, \"events\": %ld, \"steps\": %ld, \"cpu_seconds\": %.6f}\n", r.impacts, r.events, r.steps,
           (double)(clock() - c0) / CLOCKS_PER_SEC);
    return 0;
}
