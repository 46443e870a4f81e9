/* Replays files through both input readers with the fuzzing harness's checks (harness.c): every
 * crashing input a fuzzer found (tests/fuzz/regressions/) and the seed corpus. Run by ctest, and
 * under ASan/UBSan in build-asan. Arguments: folders (or files). */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "harness.h"

static int replay_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    unsigned char *buf;
    long size;
    if (!f) { fprintf(stderr, "%s: cannot open\n", path); return 1; }
    fseek(f, 0, SEEK_END);
    size = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = malloc(size > 0 ? (size_t)size : 1);
    if (!buf || (size > 0 && fread(buf, 1, (size_t)size, f) != (size_t)size)) { fclose(f); free(buf); return 1; }
    fclose(f);
    rw_fuzz_csv(buf, (size_t)size); /* aborts if a promise is broken */
    rw_fuzz_at2(buf, (size_t)size);
    free(buf);
    return 0;
}

static int replay(const char *path, int *count)
{
    struct stat st;
    DIR *d;
    struct dirent *e;
    int bad = 0;
    if (stat(path, &st) != 0) { fprintf(stderr, "%s: missing\n", path); return 1; }
    if (!S_ISDIR(st.st_mode)) { (*count)++; return replay_file(path); }
    if (!(d = opendir(path))) return 1;
    while ((e = readdir(d)) != NULL) {
        char child[4096];
        if (e->d_name[0] == '.') continue; /* ., .. and hidden files such as .gitkeep */
        snprintf(child, sizeof child, "%s/%s", path, e->d_name);
        bad |= replay(child, count);
    }
    closedir(d);
    return bad;
}

int main(int argc, char **argv)
{
    int bad = 0, count = 0;
    for (int i = 1; i < argc; i++) bad |= replay(argv[i], &count);
    printf("%d inputs replayed through the CSV and AT2 readers\n", count);
    return bad || count == 0;
}
