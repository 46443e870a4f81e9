/* Writes a sim_summary as one JSON object: end time, whether the model ended the run, solver
 * counters, and {"NAME": {"max_abs": x, "final": x}} for every output. JSON has no NaN or
 * infinity, so those are written as null. */
#include "summary.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void put_number(output_file *f, double x)
{
    if (isfinite(x)) output_printf(f, "%.17g", x);
    else output_printf(f, "null");
}

/* Variable names are free text in FMI: escape what JSON requires. */
static void put_string(output_file *f, const char *str)
{
    output_printf(f, "\"");
    for (const unsigned char *p = (const unsigned char *)str; *p; p++) {
        if (*p == '"' || *p == '\\') output_printf(f, "\\%c", *p);
        else if (*p < 0x20) output_printf(f, "\\u%04x", *p);
        else output_printf(f, "%c", *p);
    }
    output_printf(f, "\"");
}

/* Written through output_file.h: a failed write is remembered there and reported by the commit,
 * and the file appears only complete. */
int summary_write_json(const char *path, const sim_summary *sum, const sim_stats *st, char *err, size_t n)
{
    output_file out, *f = &out;
    if (output_open(f, path, err, n) != 0) return -1;
    output_printf(f, "{\"end_time\": ");
    put_number(f, st->end_time);
    output_printf(f, ", \"terminated_by_model\": %s, \"steps\": %ld, \"events\": %ld, \"cpu_seconds\": %.6f,\n \"outputs\": {",
            st->terminated_by_model ? "true" : "false", st->steps, st->events, st->cpu_seconds);
    for (size_t i = 0; i < sum->n; i++) {
        output_printf(f, i ? ",\n  " : "\n  ");
        put_string(f, sum->vars[i]->name);
        output_printf(f, ": {\"max_abs\": ");
        put_number(f, sum->max_abs[i]);
        output_printf(f, ", \"final\": ");
        put_number(f, sum->final[i]);
        output_printf(f, "}");
    }
    output_printf(f, "}}\n");
    return output_commit(f, err, n);
}

void summary_free(sim_summary *sum)
{
    free(sum->vars);
    free(sum->max_abs);
    free(sum->final);
    memset(sum, 0, sizeof *sum);
}
