/* What test_combined_fmus.c (FMI 2.0) and test_combined_fmi3_fmus.c (FMI 3.0) share: the FMUs'
 * sources compiled into one shared object, each under its own function prefix (RockingWall_, ...),
 * as importers combine source-code FMUs. Each FMU is simulated in Co-Simulation through the
 * combined object and through its own binary, by a small per-version adapter; the outputs must
 * agree bitwise (same sources, same compiler flags), and the combined object must not export the
 * unprefixed names. */
#ifndef COMBINED_FMUS_CHECK_H
#define COMBINED_FMUS_CHECK_H

#include <dlfcn.h>
#include <stdio.h>
#include <string.h>

#include "check.h"

/* one FMU's run: N_STEPS steps from a displaced start under a constant input, two outputs read */
typedef struct {
    const char *prefix, *guid;
    unsigned start_vr, input_vr, output_vrs[2];
    double start, input;
} fmu_case;

#define N_STEPS 200
#define STEP 0.005

typedef struct {
    const char *version;     /* "FMI 2.0", "FMI 3.0" */
    const char *unprefixed;  /* a function the combined object must not export unprefixed */
    size_t api_size;         /* bytes of the adapter's table of functions */
    /* the functions of a run, looked up in lib with the prefix into api: 0 if one is missing */
    int (*load)(void *lib, const char *prefix, void *api);
    /* the run: 1 if every call succeeded, the outputs after each step in out */
    int (*simulate)(const void *api, const fmu_case *f, double out[N_STEPS][2]);
    const char *(*last_message)(void);
} combined_adapter;

static void *combined_symbol(void *lib, const char *prefix, const char *name)
{
    char full[128];
    void *p;
    snprintf(full, sizeof full, "%s%s", prefix, name);
    p = dlsym(lib, full);
    CHECK(p != NULL, "%s not exported", full);
    return p;
}

static void compare_with_own_binary(const combined_adapter *A, void *combined, const char *own_path, const fmu_case *f)
{
    static double via_combined[N_STEPS][2], via_own[N_STEPS][2];
    void *a[64], *b[64]; /* the adapter's tables of functions */
    void *own = dlopen(own_path, RTLD_NOW | RTLD_LOCAL);
    CHECK(own != NULL, "dlopen %s: %s", own_path, dlerror());
    CHECK(A->api_size <= sizeof a, "the adapter's table has %u bytes", (unsigned)A->api_size);
    if (!own || A->api_size > sizeof a || !A->load(combined, f->prefix, a) || !A->load(own, "", b)) return;
    CHECK(A->simulate(a, f, via_combined), "%s: run through the combined object failed: %s", f->prefix, A->last_message());
    CHECK(A->simulate(b, f, via_own), "%s: run through its own binary failed: %s", f->prefix, A->last_message());
    CHECK(memcmp(via_combined, via_own, sizeof via_own) == 0, "%s: the combined object's outputs differ from the own binary's",
          f->prefix);
    CHECK(via_own[N_STEPS - 1][0] != f->start, "%s: the run did not move (%g)", f->prefix, via_own[N_STEPS - 1][0]);
    printf("  %s through the combined %s object: output %.9g after %g s, bitwise equal to its own binary\n", f->prefix,
           A->version, via_combined[N_STEPS - 1][0], N_STEPS * STEP);
    dlclose(own);
}

/* argv: COMBINED.so, then each case's own binary */
static int combined_main(const combined_adapter *A, const fmu_case *cases, int n_cases, int argc, char **argv)
{
    void *combined;
    int k;
    if (argc != n_cases + 2) {
        fprintf(stderr, "usage: %s COMBINED.so", argv[0]);
        for (k = 0; k < n_cases; k++) fprintf(stderr, " %.*s.so", (int)strlen(cases[k].prefix) - 1, cases[k].prefix);
        fprintf(stderr, "\n");
        return 2;
    }
    combined = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    CHECK(combined != NULL, "dlopen %s: %s", argv[1], dlerror());
    if (!combined) return 1;
    CHECK(dlsym(combined, A->unprefixed) == NULL, "the combined object exports the unprefixed %s", A->unprefixed);
    for (k = 0; k < n_cases; k++) compare_with_own_binary(A, combined, argv[2 + k], &cases[k]);
    dlclose(combined);
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}

#endif
