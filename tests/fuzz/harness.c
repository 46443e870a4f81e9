/* The fuzzing harness of fmi2sim's input readers (host/input_table.c): the bytes become a file,
 * the reader reads it, and what it returns must keep the promises input_value() relies on:
 * at least one sample, times finite and increasing (a time at most twice in a row: a step),
 * values finite and not huge, and finite values between and beyond the samples. A broken
 * promise aborts, so a fuzzer finds wrong results as well as memory errors. Shared by the
 * libFuzzer targets (fuzz_csv.c, fuzz_at2.c) and the regression replay (replay.c). */
#include "harness.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "input_table.h"

static const char *scratch(void)
{
    static char path[64];
    if (!path[0]) snprintf(path, sizeof path, "/tmp/rw_fuzz_%ld.txt", (long)getpid());
    return path;
}

static void check_table(const input_table *tab)
{
    if (tab->n < 1 || tab->ncols < 1) abort();
    for (size_t i = 0; i < tab->n; i++) {
        if (!isfinite(tab->t[i]) || (i > 0 && !(tab->t[i] >= tab->t[i - 1]))) abort();
        if (i > 1 && tab->t[i] == tab->t[i - 2]) abort(); /* three rows of one time */
        for (size_t c = 0; c < tab->ncols; c++)
            if (!isfinite(tab->cols[c].values[i]) || fabs(tab->cols[c].values[i]) > 1e100) abort();
    }
    for (size_t c = 0; c < tab->ncols; c++) { /* interpolation inside, at and beyond the ends */
        double lo = tab->t[0], hi = tab->t[tab->n - 1];
        double probe[5] = {lo - 1.0, lo, 0.5 * lo + 0.5 * hi, hi, hi + 1.0};
        for (int k = 0; k < 5; k++)
            if (!isfinite(input_value(tab, c, probe[k])) || !isfinite(input_value_left(tab, c, probe[k])) ||
                !isfinite(input_value_held(tab, c, probe[k])) || !isfinite(input_value_held_left(tab, c, probe[k])))
                abort();
    }
}

static int run(const uint8_t *data, size_t size, int at2)
{
    const char *path = scratch();
    FILE *f = fopen(path, "wb");
    input_table tab;
    char err[512];
    int rc;
    if (!f) return 0;
    if (size && fwrite(data, 1, size, f) != size) { fclose(f); return 0; }
    fclose(f);
    rc = at2 ? input_read_at2(path, "ag", 9.81, 1.0, &tab, err, sizeof err)
             : input_read_csv(path, &tab, err, sizeof err);
    if (rc == 0) {
        check_table(&tab);
        input_free(&tab);
    } else if (!err[0]) {
        abort(); /* an error must come with a reason */
    }
    unlink(path);
    return 0;
}

int rw_fuzz_csv(const uint8_t *data, size_t size) { return run(data, size, 0); }
int rw_fuzz_at2(const uint8_t *data, size_t size) { return run(data, size, 1); }
