/* The RockingWall FMU's record reader (rw_ground_motion.c) on its own:
 *  - on the seed corpus it reads what fmi2sim's readers (host/input_table.c) read, bit for bit;
 *  - hostile files (a long line, binary data, too few rows, huge or non-finite numbers, impossible
 *    AT2 headers) are refused with FILE:LINE and the problem, never read;
 *  - the interpolation: linear between samples, 0 before the first and from the last on, and the
 *    next time the rate changes. Arguments: the corpus folder (tests/fuzz/corpus). */
#include "check.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "input_table.h"
#include "rw_ground_motion.h"

static char corpus[1024];

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (!f) { printf("cannot write %s\n", path); exit(2); }
    fputs(text, f);
    fclose(f);
}

/* the record both readers give for one corpus file */
static void same_as_host(const char *name, int at2)
{
    char path[1200], err[1024], err2[1024];
    rw_ground_motion gm;
    input_table tab;
    size_t k;
    int rc, rc2;
    snprintf(path, sizeof path, "%s/%s", corpus, name);
    rc = rw_gm_read(path, 9.81, 0.5, &gm, err, sizeof err);
    rc2 = at2 ? input_read_at2(path, "ag", 9.81, 0.5, &tab, err2, sizeof err2) : input_read_csv(path, &tab, err2, sizeof err2);
    CHECK(rc == 0 && rc2 == 0, "%s: FMU reader '%s', host reader '%s'", name, rc ? err : "", rc2 ? err2 : "");
    if (rc || rc2) return;
    CHECK(gm.n == tab.n, "%s: %lu samples, the host reads %lu", name, (unsigned long)gm.n, (unsigned long)tab.n);
    for (k = 0; k < gm.n && k < tab.n; k++) {
        const double host = at2 ? tab.cols[0].values[k] : 0.5 * tab.cols[0].values[k];
        CHECK(gm.t[k] == tab.t[k] && gm.a[k] == host, "%s sample %lu: (%.17g, %.17g), host (%.17g, %.17g)", name,
              (unsigned long)k, gm.t[k], gm.a[k], tab.t[k], host);
    }
    rw_gm_free(&gm);
    input_free(&tab);
}

static void refused(const char *name, const char *text, const char *where, const char *what)
{
    rw_ground_motion gm;
    char err[1024] = "";
    if (text) write_file(name, text);
    CHECK(rw_gm_read(name, 9.81, 1.0, &gm, err, sizeof err) != 0, "%s was read", name);
    CHECK(strstr(err, where) && strstr(err, what), "%s: '%s' lacks '%s' or '%s'", name, err, where, what);
    CHECK(gm.n == 0 && gm.t == NULL && gm.a == NULL, "%s: a refused file leaves nothing", name);
}

static void hostile_files(void)
{
    char *long_line = (char *)malloc(6000);
    memset(long_line, '1', 5000);
    strcpy(long_line + 5000, ",2\n");
    refused("gmr_long.csv", long_line, "gmr_long.csv:1:", "line longer than");
    free(long_line);
    refused("gmr_binary.csv", "0,0\n0.1,\001\002\n", "gmr_binary.csv:2:", "binary data");
    refused("gmr_one.csv", "time,ag\n0,1\n", "gmr_one.csv:", "at least 2 rows");
    refused("gmr_empty.csv", "", "gmr_empty.csv:", "at least 2 rows");
    refused("gmr_huge.csv", "0,0\n0.1,1e999\n", "gmr_huge.csv:2:", "out of range");
    refused("gmr_nan.csv", "0,0\n0.1,nan\n", "gmr_nan.csv:2:", "out of range");
    refused("gmr_two_headers.csv", "time,ag\nseconds,m/s2\n0,0\n", "gmr_two_headers.csv:2:", "'seconds' is not a number");
    refused("gmr_npts.AT2", "a\nb\nG\nNPTS= 1000000000000, DT= 0.01\n0\n", "gmr_npts.AT2:4:", "NPTS");
    refused("gmr_dt.AT2", "a\nb\nG\nNPTS= 3, DT= 0\n0 0 0\n", "gmr_dt.AT2:4:", "NPTS");
    refused("gmr_units.AT2", "a\nb\nCM/S/S\nNPTS= 3, DT= 0.01\n0 0 0\n", "gmr_units.AT2:3:", "in G");
    refused("gmr_more.AT2", "a\nb\nG\nNPTS= 2, DT= 0.01\n0 0 0\n", "gmr_more.AT2:5:", "more values than NPTS = 2");
    refused("gmr_absent.csv", NULL, "gmr_absent.csv", "cannot open");
    refused(".", NULL, ".:1:", "cannot read"); /* a folder: fopen succeeds, reading fails */
}

static void interpolation(void)
{
    const double t[] = {1.0, 2.0, 4.0}, a[] = {2.0, -2.0, 1.0};
    rw_ground_motion gm = {(double *)t, (double *)a, 3};
    double slope, next, v;
    v = rw_gm_at(&gm, 0.5, &slope, &next);
    CHECK(v == 0.0 && slope == 0.0 && next == 1.0, "before the record: %g %g %g", v, slope, next);
    v = rw_gm_at(&gm, 1.0, &slope, &next);
    CHECK(v == 2.0 && slope == -4.0 && next == 2.0, "at the first sample: %g %g %g", v, slope, next);
    v = rw_gm_at(&gm, 1.25, &slope, &next);
    CHECK(v == 1.0 && slope == -4.0 && next == 2.0, "between: %g %g %g", v, slope, next);
    v = rw_gm_at(&gm, 3.0, &slope, &next);
    CHECK(v == -0.5 && slope == 1.5 && next == 4.0, "in the second interval: %g %g %g", v, slope, next);
    v = rw_gm_at(&gm, 4.0, &slope, &next);
    CHECK(v == 0.0 && slope == 0.0 && next == HUGE_VAL, "from the last sample on: %g %g %g", v, slope, next);
}

int main(int argc, char **argv)
{
    if (argc != 2) { printf("usage: test_ground_motion_reader CORPUS\n"); return 2; }
    snprintf(corpus, sizeof corpus, "%s", argv[1]);
    same_as_host("at2/nga_new.AT2", 1);
    same_as_host("at2/nga_old.AT2", 1);
    same_as_host("csv/simple.csv", 0);
    hostile_files();
    interpolation();
    printf("%d checks, %d failures\n", checks, failures);
    return failures != 0;
}
