/* Unpacking an FMU (a zip file) with libzip into a private temporary folder. */
#define _XOPEN_SOURCE 700
#include "fmu_archive.h"

#include <errno.h>
#include <ftw.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <zip.h>

/* mkdir -p for the folders of an entry */
static int make_parents(char *path)
{
    for (char *p = strchr(path + 1, '/'); p; p = strchr(p + 1, '/')) {
        *p = '\0';
        if (mkdir(path, 0700) != 0 && errno != EEXIST) { *p = '/'; return -1; }
        *p = '/';
    }
    return 0;
}

/* An entry may not escape the target folder ("zip slip"). */
static int safe_entry_name(const char *name)
{
    if (name[0] == '/' || strstr(name, "..")) return 0;
    return 1;
}

static int extract_entry(zip_t *zip, zip_int64_t i, const char *dir, char *err, size_t n)
{
    const char *name = zip_get_name(zip, (zip_uint64_t)i, 0);
    char path[8192];
    zip_file_t *zf;
    FILE *out;
    char buf[65536];
    zip_int64_t got;
    if (!name || !safe_entry_name(name)) {
        snprintf(err, n, "entry %lld has an unsafe name '%s'", (long long)i, name ? name : "?");
        return -1;
    }
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if (make_parents(path) != 0) { snprintf(err, n, "cannot create folders for %s", path); return -1; }
    if (name[strlen(name) - 1] == '/') return 0; /* folder entry */
    zf = zip_fopen_index(zip, (zip_uint64_t)i, 0);
    if (!zf) { snprintf(err, n, "cannot read entry '%s': %s", name, zip_strerror(zip)); return -1; }
    out = fopen(path, "wb");
    if (!out) { zip_fclose(zf); snprintf(err, n, "cannot write %s: %s", path, strerror(errno)); return -1; }
    while ((got = zip_fread(zf, buf, sizeof buf)) > 0) fwrite(buf, 1, (size_t)got, out);
    fclose(out);
    if (got < 0) {
        snprintf(err, n, "entry '%s' is corrupt: %s", name, zip_file_strerror(zf));
        zip_fclose(zf);
        return -1;
    }
    zip_fclose(zf);
    return 0;
}

int fmu_unpack(const char *path, fmu_archive *a, char *err, size_t n)
{
    struct stat st;
    int zerr = 0;
    zip_t *zip;
    memset(a, 0, sizeof *a);
    if (stat(path, &st) != 0) { snprintf(err, n, "%s: %s", path, strerror(errno)); return -1; }
    if (S_ISDIR(st.st_mode)) { /* already unpacked */
        snprintf(a->dir, sizeof a->dir, "%s", path);
        return 0;
    }
    zip = zip_open(path, ZIP_RDONLY, &zerr);
    if (!zip) {
        zip_error_t ze;
        zip_error_init_with_code(&ze, zerr);
        snprintf(err, n, "%s: not a valid FMU (zip archive): %s", path, zip_error_strerror(&ze));
        zip_error_fini(&ze);
        return -1;
    }
    snprintf(a->dir, sizeof a->dir, "%s/fmi2sim_XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
    if (!mkdtemp(a->dir)) {
        snprintf(err, n, "cannot create a temporary folder: %s", strerror(errno));
        zip_discard(zip);
        return -1;
    }
    a->is_temp = 1;
    for (zip_int64_t i = 0; i < zip_get_num_entries(zip, 0); i++) {
        char why[9000];
        if (extract_entry(zip, i, a->dir, why, sizeof why) != 0) {
            snprintf(err, n, "%s: %s", path, why);
            zip_discard(zip);
            fmu_cleanup(a);
            return -1;
        }
    }
    zip_discard(zip);
    return 0;
}

static int remove_one(const char *path, const struct stat *st, int flag, struct FTW *ftw)
{
    (void)st; (void)flag; (void)ftw;
    return remove(path);
}

void fmu_cleanup(fmu_archive *a)
{
    if (a->is_temp) nftw(a->dir, remove_one, 16, FTW_DEPTH | FTW_PHYS);
    a->is_temp = 0;
}
