/* Readers for input files (CSV and PEER NGA .AT2) and the inputs' values between samples: linear
 * for continuous inputs, held for discrete ones; two rows of one time are a step (the value
 * before it, then the value from it on). Every problem is reported as "FILE:LINE: what is wrong"
 * so a user can fix the file. */
#define _POSIX_C_SOURCE 200809L
#include "input_table.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static char *trim(char *s)
{
    char *e;
    while (*s == ' ' || *s == '\t') s++;
    e = s + strlen(s);
    while (e > s && (e[-1] == ' ' || e[-1] == '\t' || e[-1] == '\r' || e[-1] == '\n')) *--e = '\0';
    return s;
}

/* Larger magnitudes are no physical input but a corrupt file, and would overflow inside the
 * model (1e300 m/s2 gives infinite states) far from the line that caused it. */
#define INPUT_MAX_ABS 1e100
#define OUT_OF_RANGE "out of range (not a finite number of magnitude <= 1e100)"

/* A whole token as a double: 0, -1 (not a number), -2 (out of range). */
static int parse_number(const char *tok, double *out)
{
    char *end;
    if (!*tok) return -1;
    errno = 0;
    *out = strtod(tok, &end);
    if (end == tok || *end != '\0') return -1;
    if (errno == ERANGE && fabs(*out) > 1.0) return -2;
    if (!isfinite(*out) || fabs(*out) > INPUT_MAX_ABS) return -2;
    return 0;
}

/* The next comma-separated field of *s (NULL after the last). Unlike strtok, an empty field
 * stays a field, so "0.1,,2" is reported instead of silently read as "0.1,2". */
static char *next_field(char **s)
{
    char *f = *s, *comma;
    if (!f) return NULL;
    comma = strchr(f, ',');
    if (comma) { *comma = '\0'; *s = comma + 1; } else *s = NULL;
    return f;
}

static int grow(input_table *tab, size_t *cap)
{
    if (tab->n < *cap) return 0;
    *cap = *cap ? 2 * *cap : 1024;
    double *t = realloc(tab->t, *cap * sizeof *t);
    if (!t) return -1;
    tab->t = t;
    for (size_t c = 0; c < tab->ncols; c++) {
        double *v = realloc(tab->cols[c].values, *cap * sizeof *v);
        if (!v) return -1;
        tab->cols[c].values = v;
    }
    return 0;
}

static int check_time(const char *path, long line, const input_table *tab, double t, char *err, size_t n)
{
    if (tab->n > 1 && t == tab->t[tab->n - 1] && t == tab->t[tab->n - 2]) {
        snprintf(err, n, "%s:%ld: time %g is on a third row: a step takes two rows of one time (the value before "
                 "it, then the value from it on)", path, line, t);
        return -1;
    }
    if (tab->n > 0 && t < tab->t[tab->n - 1]) {
        snprintf(err, n, "%s:%ld: time %g is before the previous row's %g (times must increase)", path,
                 line, t, tab->t[tab->n - 1]);
        return -1;
    }
    return 0;
}

/* A line with a NUL or a control character other than white space is not text. */
static int has_nul(const char *s, ssize_t len)
{
    for (ssize_t i = 0; i < len; i++) {
        unsigned char c = (unsigned char)s[i];
        if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\f' && c != '\v') || c == 0x7f) return 1;
    }
    return 0;
}

/* The input file opened for reading; a folder is named as one (reading it would look empty). */
static FILE *open_input(const char *path, input_table *tab, char *err, size_t n)
{
    struct stat st;
    FILE *f = fopen(path, "r");
    if (!f) { snprintf(err, n, "%s: %s", path, strerror(errno)); return NULL; }
    if (fstat(fileno(f), &st) == 0 && S_ISDIR(st.st_mode)) {
        snprintf(err, n, "%s: is a folder, not an input file", path);
        fclose(f);
        return NULL;
    }
    if (!(tab->source = strdup(path))) { snprintf(err, n, "%s: out of memory", path); fclose(f); return NULL; }
    return f;
}

int input_read_csv(const char *path, input_table *tab, char *err, size_t n)
{
    FILE *f;
    char *line = NULL;
    size_t linecap = 0, cap = 0;
    ssize_t len;
    long lineno = 0;
    int rc = -1;
    memset(tab, 0, sizeof *tab);
    if (!(f = open_input(path, tab, err, n))) return -1;
    /* header */
    while ((len = getline(&line, &linecap, f)) >= 0) {
        lineno++;
        if (has_nul(line, len)) { snprintf(err, n, "%s:%ld: binary data, not a CSV text file", path, lineno); goto done; }
        if (*trim(line)) break;
    }
    if (len < 0) { snprintf(err, n, "%s: empty file: expected a header 'time,NAME,...'", path); goto done; }
    {
        char *rest = trim(line), *tok;
        size_t count = 0;
        for (tok = next_field(&rest); tok; tok = next_field(&rest), count++) {
            if (count == 0) continue; /* the time column, whatever its name */
            input_column *cols = realloc(tab->cols, (tab->ncols + 1) * sizeof *cols);
            if (!cols) goto oom;
            tab->cols = cols;
            tab->cols[tab->ncols].name = strdup(trim(tok));
            tab->cols[tab->ncols].values = NULL;
            if (!*tab->cols[tab->ncols].name) {
                tab->ncols++;
                snprintf(err, n, "%s:%ld: header column %zu has no name", path, lineno, count + 1);
                goto done;
            }
            tab->ncols++;
        }
        if (tab->ncols == 0) {
            snprintf(err, n, "%s:%ld: header names no input column (expected 'time,NAME,...')", path, lineno);
            goto done;
        }
    }
    /* rows */
    while ((len = getline(&line, &linecap, f)) >= 0) {
        char *row, *tok;
        size_t col = 0;
        double t = 0.0;
        lineno++;
        if (has_nul(line, len)) { snprintf(err, n, "%s:%ld: binary data, not a CSV text file", path, lineno); goto done; }
        row = trim(line);
        if (!*row) continue;
        if (grow(tab, &cap) != 0) goto oom;
        for (tok = next_field(&row); tok; tok = next_field(&row), col++) {
            double v;
            int bad;
            if (col > tab->ncols) continue; /* counted, reported below */
            bad = parse_number(trim(tok), &v);
            if (bad) {
                if (!*trim(tok)) snprintf(err, n, "%s:%ld: column %zu is empty", path, lineno, col + 1);
                else snprintf(err, n, "%s:%ld: column %zu: '%s' is %s", path, lineno, col + 1, trim(tok),
                              bad == -2 ? OUT_OF_RANGE : "not a number");
                goto done;
            }
            if (col == 0) t = v;
            else tab->cols[col - 1].values[tab->n] = v;
        }
        if (col != tab->ncols + 1) {
            snprintf(err, n, "%s:%ld: %zu columns, the header has %zu", path, lineno, col, tab->ncols + 1);
            goto done;
        }
        if (check_time(path, lineno, tab, t, err, n) != 0) goto done;
        tab->t[tab->n++] = t;
    }
    if (tab->n == 0) { snprintf(err, n, "%s:%ld: no data rows after the header", path, lineno); goto done; }
    rc = 0;
    goto done;
oom:
    snprintf(err, n, "%s:%ld: out of memory", path, lineno);
done:
    free(line);
    fclose(f);
    if (rc != 0) input_free(tab);
    return rc;
}

/* The 4th header line of an NGA file: "NPTS=  2688, DT=   .0100 SEC" (or "2688  .0100 NPTS, DT"). */
static int parse_at2_header(char *line, long *npts, double *dt)
{
    char *p = strstr(line, "NPTS"), *q = strstr(line, "DT");
    if (p && q && p < q && strchr(p, '=')) {
        p = strchr(p, '=') + 1;
        q = strchr(q, '=');
        if (!q) return -1;
        *npts = strtol(p, NULL, 10);
        *dt = strtod(q + 1, NULL);
    } else if (sscanf(line, "%ld %lf", npts, dt) != 2) {
        return -1;
    }
    return (*npts > 0 && *dt > 0 && isfinite(*dt)) ? 0 : -1;
}

int input_read_at2(const char *path, const char *name, double g, double scale, input_table *tab,
                   char *err, size_t n)
{
    FILE *f;
    char *line = NULL;
    size_t linecap = 0;
    size_t cap = 0;
    ssize_t len;
    long lineno = 0, npts = 0;
    double dt = 0.0;
    int rc = -1;
    memset(tab, 0, sizeof *tab);
    if (!(f = open_input(path, tab, err, n))) return -1;
    for (lineno = 1; lineno <= 4; lineno++) {
        if ((len = getline(&line, &linecap, f)) < 0) {
            snprintf(err, n, "%s:%ld: file ends inside the 4-line AT2 header", path, lineno);
            goto done;
        }
        if (has_nul(line, len)) { snprintf(err, n, "%s:%ld: binary data, not an AT2 text file", path, lineno); goto done; }
    }
    lineno = 4;
    if (parse_at2_header(line, &npts, &dt) != 0) {
        snprintf(err, n, "%s:4: expected 'NPTS= N, DT= dt SEC' in the header, found '%s'", path, trim(line));
        goto done;
    }
    if (npts > 100000000L) { snprintf(err, n, "%s:4: NPTS = %ld is too large (the limit is 100000000)", path, npts); goto done; }
    if (!isfinite((double)npts * dt) || (double)npts * dt > INPUT_MAX_ABS) {
        snprintf(err, n, "%s:4: NPTS * DT = %ld * %g is out of range", path, npts, dt);
        goto done;
    }
    /* the arrays grow with the values read: the header alone must not make us allocate */
    tab->cols = calloc(1, sizeof *tab->cols);
    if (!tab->cols) { snprintf(err, n, "%s: out of memory", path); goto done; }
    tab->ncols = 1;
    tab->cols[0].name = strdup(name);
    if (!tab->cols[0].name) { snprintf(err, n, "%s: out of memory", path); goto done; }
    while ((len = getline(&line, &linecap, f)) >= 0) {
        char *save = NULL, *tok;
        lineno++;
        if (has_nul(line, len)) { snprintf(err, n, "%s:%ld: binary data, not an AT2 text file", path, lineno); goto done; }
        for (tok = strtok_r(line, " \t\r\n,", &save); tok; tok = strtok_r(NULL, " \t\r\n,", &save)) {
            double v;
            int bad = parse_number(tok, &v);
            if (bad) {
                snprintf(err, n, "%s:%ld: '%s' is %s", path, lineno, tok, bad == -2 ? OUT_OF_RANGE : "not a number");
                goto done;
            }
            if ((long)tab->n >= npts) {
                snprintf(err, n, "%s:%ld: more values than NPTS = %ld", path, lineno, npts);
                goto done;
            }
            if (grow(tab, &cap) != 0) { snprintf(err, n, "%s:%ld: out of memory", path, lineno); goto done; }
            if (!isfinite(v * g * scale) || fabs(v * g * scale) > INPUT_MAX_ABS) {
                snprintf(err, n, "%s:%ld: '%s' times g = %g times the scale %g is out of range", path, lineno, tok, g, scale);
                goto done;
            }
            tab->t[tab->n] = (double)tab->n * dt;
            tab->cols[0].values[tab->n++] = v * g * scale;
        }
    }
    if ((long)tab->n != npts) {
        snprintf(err, n, "%s:%ld: %zu values, the header says NPTS = %ld", path, lineno, tab->n, npts);
        goto done;
    }
    rc = 0;
done:
    free(line);
    fclose(f);
    if (rc != 0) input_free(tab);
    return rc;
}

/* The last sample at or before t (after a step at t: its second row); 0 when t is before all. */
static size_t last_at_or_before(const input_table *tab, double t)
{
    size_t lo = 0, hi = tab->n; /* the first sample after t is in [lo, hi] */
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (tab->t[mid] <= t) lo = mid + 1; else hi = mid;
    }
    return lo ? lo - 1 : 0;
}

/* Linear between samples lo and lo + 1 (which are at different times), held beyond the ends. */
static double between(const input_table *tab, size_t col, size_t lo, double t)
{
    const double *v = tab->cols[col].values;
    if (t <= tab->t[lo] || lo + 1 >= tab->n) return v[lo];
    if (t >= tab->t[lo + 1]) return v[lo + 1];
    return v[lo] + (v[lo + 1] - v[lo]) * (t - tab->t[lo]) / (tab->t[lo + 1] - tab->t[lo]);
}

double input_value(const input_table *tab, size_t col, double t)
{
    if (t < tab->t[0]) return tab->cols[col].values[0];
    return between(tab, col, last_at_or_before(tab, t), t);
}

double input_value_left(const input_table *tab, size_t col, double t)
{
    size_t i;
    if (t <= tab->t[0]) return tab->cols[col].values[0];
    i = last_at_or_before(tab, t);
    while (i > 0 && tab->t[i] >= t) i--; /* the segment that ends at t, before any step there */
    return between(tab, col, i, t);
}

double input_value_held(const input_table *tab, size_t col, double t)
{
    return tab->cols[col].values[last_at_or_before(tab, t)];
}

int input_steps_at(const input_table *tab, size_t col, double t, int held)
{
    if (held) return input_value_held(tab, col, t) != input_value_held_left(tab, col, t);
    return input_value(tab, col, t) != input_value_left(tab, col, t);
}

double input_value_held_left(const input_table *tab, size_t col, double t)
{
    size_t i;
    if (t <= tab->t[0]) return tab->cols[col].values[0];
    i = last_at_or_before(tab, t);
    while (i > 0 && tab->t[i] >= t) i--;
    return tab->cols[col].values[i];
}

void input_free(input_table *tab)
{
    for (size_t c = 0; c < tab->ncols; c++) { free(tab->cols[c].name); free(tab->cols[c].values); }
    free(tab->cols);
    free(tab->t);
    free(tab->source);
    memset(tab, 0, sizeof *tab);
}
