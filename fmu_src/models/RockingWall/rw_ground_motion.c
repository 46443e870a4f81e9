/* Reads a ground-motion record (AT2 or two-column CSV) and interpolates it: see rw_ground_motion.h.
 * Plain C99 with fgets, so the win64 cross-build compiles it; every problem names FILE:LINE. */
#include "rw_ground_motion.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define LINE_MAX_CHARS 4096
/* larger magnitudes are a corrupt file, not a ground motion (and would overflow the model) */
#define VALUE_MAX_ABS 1e100
#define MAX_SAMPLES 100000000L

typedef struct {
    FILE *f;
    const char *path;
    long lineno;
    char line[LINE_MAX_CHARS];
    size_t cap;
} reader;

/* the next line into r->line: 1 = read, 0 = end of file, -1 = problem in err */
static int next_line(reader *r, char *err, size_t n)
{
    const unsigned char *p;
    size_t len;
    if (!fgets(r->line, sizeof r->line, r->f)) {
        if (!ferror(r->f)) return 0;
        return snprintf(err, n, "%s:%ld: cannot read: %s", r->path, r->lineno + 1, strerror(errno)), -1;
    }
    r->lineno++;
    len = strlen(r->line);
    if (len + 1 == sizeof r->line && r->line[len - 1] != '\n' && !feof(r->f))
        return snprintf(err, n, "%s:%ld: line longer than %d characters", r->path, r->lineno, LINE_MAX_CHARS - 2), -1;
    for (p = (const unsigned char *)r->line; *p; p++)
        if ((*p < 0x20 && !isspace(*p)) || *p == 0x7f)
            return snprintf(err, n, "%s:%ld: binary data, not a text file", r->path, r->lineno), -1;
    return 1;
}

/* a whole token as a finite number of sane magnitude: 0, else -1 (not a number) or -2 (range) */
static int number(const char *tok, double *v)
{
    char *end;
    errno = 0;
    *v = strtod(tok, &end);
    if (end == tok || *end != '\0') return -1;
    if (!isfinite(*v) || fabs(*v) > VALUE_MAX_ABS || (errno == ERANGE && fabs(*v) > 1.0)) return -2;
    return 0;
}

static int bad_number(const reader *r, const char *tok, int why, char *err, size_t n)
{
    return snprintf(err, n, "%s:%ld: '%.40s' is %s", r->path, r->lineno, tok,
                    why == -2 ? "out of range (not a finite number of magnitude <= 1e100)" : "not a number"), -1;
}

/* splits s in place at commas, semicolons and blanks: up to max tokens, returns how many there are */
static int tokens(char *s, char *tok[], int max)
{
    int k = 0;
    char *p = s;
    for (;;) {
        while (*p && (strchr(",;", *p) || isspace((unsigned char)*p))) p++;
        if (!*p) return k;
        if (k < max) tok[k] = p;
        k++;
        while (*p && !strchr(",;", *p) && !isspace((unsigned char)*p)) p++;
        if (*p) *p++ = '\0';
    }
}

static int append(rw_ground_motion *gm, reader *r, double t, double a, char *err, size_t n)
{
    if (gm->n == r->cap) {
        const size_t cap = r->cap ? 2 * r->cap : 4096;
        double *tt = (double *)realloc(gm->t, cap * sizeof *tt), *aa;
        if (tt) gm->t = tt;
        aa = tt ? (double *)realloc(gm->a, cap * sizeof *aa) : NULL;
        if (!aa) return snprintf(err, n, "%s:%ld: out of memory", r->path, r->lineno), -1;
        gm->a = aa;
        r->cap = cap;
    }
    gm->t[gm->n] = t;
    gm->a[gm->n++] = a;
    return 0;
}

static int read_csv(reader *r, double scale, rw_ground_motion *gm, char *err, size_t n)
{
    int rc, header_seen = 0;
    while ((rc = next_line(r, err, n)) == 1) {
        char *tok[3];
        double t, a;
        int k = tokens(r->line, tok, 3), why;
        if (k == 0 || tok[0][0] == '#') continue;
        if (gm->n == 0 && !header_seen && number(tok[0], &t) == -1) { header_seen = 1; continue; }
        if (k != 2)
            return snprintf(err, n, "%s:%ld: expected 2 columns (time [s], acceleration [m/s2]), found %d", r->path,
                            r->lineno, k), -1;
        if ((why = number(tok[0], &t)) != 0) return bad_number(r, tok[0], why, err, n);
        if ((why = number(tok[1], &a)) != 0) return bad_number(r, tok[1], why, err, n);
        if (gm->n > 0 && !(t > gm->t[gm->n - 1]))
            return snprintf(err, n, "%s:%ld: time %.17g is not after the previous one (%.17g)", r->path, r->lineno, t,
                            gm->t[gm->n - 1]), -1;
        if (append(gm, r, t, a * scale, err, n)) return -1;
    }
    if (rc < 0) return -1;
    if (gm->n < 2) return snprintf(err, n, "%s: need at least 2 rows of numbers, found %lu", r->path, (unsigned long)gm->n), -1;
    return 0;
}

/* NPTS and DT from the 4th line of an AT2 file: "NPTS=  2688, DT=   .0100 SEC" or "2688  .0100 ..." */
static int at2_header(const char *line, long *npts, double *dt)
{
    const char *p = strstr(line, "NPTS"), *q = strstr(line, "DT");
    char *end;
    if (p && q && strchr(p, '=') && strchr(q, '=')) {
        *npts = strtol(strchr(p, '=') + 1, &end, 10);
        *dt = strtod(strchr(q, '=') + 1, &end);
    } else if (sscanf(line, "%ld %lf", npts, dt) != 2) {
        return -1;
    }
    return (*npts > 0 && *npts <= MAX_SAMPLES && *dt > 0 && isfinite(*dt) && *npts * *dt < VALUE_MAX_ABS) ? 0 : -1;
}

static int upper_has_g(const char *line)
{
    const char *p;
    for (p = line; *p; p++)
        if (toupper((unsigned char)*p) == 'G' && (p == line || !isalpha((unsigned char)p[-1])) &&
            !isalpha((unsigned char)p[1]))
            return 1;
    return 0;
}

static int read_at2(reader *r, double g, double scale, rw_ground_motion *gm, char *err, size_t n)
{
    long npts = 0;
    double dt = 0.0;
    int rc;
    while (r->lineno < 4) {
        if ((rc = next_line(r, err, n)) < 0) return -1;
        if (rc == 0) return snprintf(err, n, "%s:%ld: file ends inside the 4-line AT2 header", r->path, r->lineno + 1), -1;
        if (r->lineno == 3 && !upper_has_g(r->line))
            return snprintf(err, n, "%s:3: the 3rd header line does not say the values are in G", r->path), -1;
    }
    if (at2_header(r->line, &npts, &dt))
        return snprintf(err, n, "%s:4: expected 'NPTS= N, DT= dt SEC' with N > 0 and dt > 0", r->path), -1;
    while ((rc = next_line(r, err, n)) == 1) {
        char *tok[64];
        int k = tokens(r->line, tok, 64), i, why;
        if (k > 64) return snprintf(err, n, "%s:%ld: more than 64 values on a line", r->path, r->lineno), -1;
        for (i = 0; i < k; i++) {
            double v;
            if ((why = number(tok[i], &v)) != 0) return bad_number(r, tok[i], why, err, n);
            if ((long)gm->n >= npts)
                return snprintf(err, n, "%s:%ld: more values than NPTS = %ld", r->path, r->lineno, npts), -1;
            if (append(gm, r, (double)gm->n * dt, v * g * scale, err, n)) return -1;
        }
    }
    if (rc < 0) return -1;
    if ((long)gm->n != npts)
        return snprintf(err, n, "%s:%ld: %lu values, the header says NPTS = %ld", r->path, r->lineno,
                        (unsigned long)gm->n, npts), -1;
    if (npts < 2) return snprintf(err, n, "%s:4: NPTS = %ld, a record needs at least 2 samples", r->path, npts), -1;
    return 0;
}

static int is_at2(const char *path)
{
    const size_t len = strlen(path);
    const char *ext = path + (len >= 4 ? len - 4 : 0);
    return len >= 4 && ext[0] == '.' && toupper((unsigned char)ext[1]) == 'A' && toupper((unsigned char)ext[2]) == 'T' &&
           ext[3] == '2';
}

int rw_gm_read(const char *path, double g, double scale, rw_ground_motion *gm, char *err, size_t n)
{
    reader r;
    int rc;
    memset(gm, 0, sizeof *gm);
    memset(&r, 0, sizeof r);
    r.path = path;
    r.f = fopen(path, "r");
    if (!r.f) return snprintf(err, n, "%s: cannot open: %s", path, strerror(errno)), -1;
    rc = is_at2(path) ? read_at2(&r, g, scale, gm, err, n) : read_csv(&r, scale, gm, err, n);
    fclose(r.f);
    if (rc) rw_gm_free(gm);
    return rc;
}

void rw_gm_free(rw_ground_motion *gm)
{
    free(gm->t);
    free(gm->a);
    memset(gm, 0, sizeof *gm);
}

double rw_gm_at(const rw_ground_motion *gm, double t, double *slope, double *t_next)
{
    size_t lo = 0, hi = gm->n - 1;
    *slope = 0.0;
    if (t < gm->t[0]) return *t_next = gm->t[0], 0.0;
    if (t >= gm->t[hi]) return *t_next = HUGE_VAL, 0.0;
    while (hi - lo > 1) { /* t[lo] <= t < t[hi] */
        const size_t mid = lo + (hi - lo) / 2;
        if (gm->t[mid] <= t) lo = mid;
        else hi = mid;
    }
    *slope = (gm->a[hi] - gm->a[lo]) / (gm->t[hi] - gm->t[lo]);
    *t_next = gm->t[hi];
    return gm->a[lo] + *slope * (t - gm->t[lo]);
}
