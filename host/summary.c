/* Writes a sim_summary as one JSON object: end time, whether the model ended the run, solver
 * counters, and {"NAME": {"max_abs": x, "final": x}} for every output. JSON has no NaN or
 * infinity, so those are written as null. */
#include "summary.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void put_number(FILE *f, double x)
{
    if (isfinite(x)) fprintf(f, "%.17g", x);
    else fputs("null", f);
}

/* Variable names are free text in FMI: escape what JSON requires. */
static void put_string(FILE *f, const char *str)
{
    fputc('"', f);
    for (const unsigned char *p = (const unsigned char *)str; *p; p++) {
        if (*p == '"' || *p == '\\') fprintf(f, "\\%c", *p);
        else if (*p < 0x20) fprintf(f, "\\u%04x", *p);
        else fputc(*p, f);
    }
    fputc('"', f);
}

int summary_write_json(const char *path, const sim_summary *sum, const sim_stats *st, char *err, size_t n)
{
    FILE *f = fopen(path, "w");
    if (!f) { snprintf(err, n, "%s: %s", path, strerror(errno)); return -1; }
    fputs("{\"end_time\": ", f);
    put_number(f, st->end_time);
    fprintf(f, ", \"terminated_by_model\": %s, \"steps\": %ld, \"events\": %ld, \"cpu_seconds\": %.6f,\n \"outputs\": {",
            st->terminated_by_model ? "true" : "false", st->steps, st->events, st->cpu_seconds);
    for (size_t i = 0; i < sum->n; i++) {
        fputs(i ? ",\n  " : "\n  ", f);
        put_string(f, sum->vars[i]->name);
        fputs(": {\"max_abs\": ", f);
        put_number(f, sum->max_abs[i]);
        fputs(", \"final\": ", f);
        put_number(f, sum->final[i]);
        fputc('}', f);
    }
    fputs("}}\n", f);
    if (fclose(f) != 0) { snprintf(err, n, "%s: %s", path, strerror(errno)); return -1; }
    return 0;
}

void summary_free(sim_summary *sum)
{
    free(sum->vars);
    free(sum->max_abs);
    free(sum->final);
    memset(sum, 0, sizeof *sum);
}
