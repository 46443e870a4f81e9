/* Unpacking an FMU (a zip file) with libzip into a private temporary folder (fmu_archive.h).
 * Every file and folder made here is registered with cleanup.h, so that a signal removes them. */
#define _XOPEN_SOURCE 700
#include "fmu_archive.h"

#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zip.h>

#include "cleanup.h"

/* mkdir -p for the folders of an entry below dir (dir itself exists) */
static int make_parents(const char *dir, char *path)
{
    for (char *p = strchr(path + strlen(dir) + 1, '/'); p; p = strchr(p + 1, '/')) {
        *p = '\0';
        if (mkdir(path, 0700) == 0) {
            if (cleanup_push(path, 1) != 0) { *p = '/'; errno = ENOMEM; return -1; }
        } else if (errno != EEXIST) {
            *p = '/';
            return -1;
        }
        *p = '/';
    }
    return 0;
}

/* A relative name whose every component is a plain file name: no "", ".", ".." component, no
 * backslash. "release..notes.txt" is a legal name; "a/../b" is not. */
static int safe_entry_name(const char *name)
{
    const char *p = name;
    if (!*name || name[0] == '/' || strchr(name, '\\')) return 0;
    while (*p) {
        size_t len = strcspn(p, "/");
        if (len == 0 || (len == 1 && p[0] == '.') || (len == 2 && p[0] == '.' && p[1] == '.')) return 0;
        p += len;
        if (*p == '/') p++;
    }
    return 1;
}

/* Write all of buf to fd; -1 with errno on failure (a short write on a full disk included). */
static int write_all(int fd, const char *buf, size_t len)
{
    while (len > 0) {
        ssize_t w = write(fd, buf, len);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) { if (w == 0) errno = ENOSPC; return -1; }
        buf += w;
        len -= (size_t)w;
    }
    return 0;
}

/* Copy the open entry zf into fd, at most `limit` bytes; *total gets the count. 0, -1 (write
 * failed, errno set), -2 (entry corrupt), -3 (over the limit). */
static int copy_entry(zip_file_t *zf, int fd, long limit, long *total)
{
    char buf[65536];
    zip_int64_t got;
    *total = 0;
    while ((got = zip_fread(zf, buf, sizeof buf)) > 0) {
        if (*total + got > limit) return -3;
        if (write_all(fd, buf, (size_t)got) != 0) return -1;
        *total += got;
    }
    return got < 0 ? -2 : 0;
}

/* Extract entry `name` as dir/name (made new: a name twice in the archive is refused). */
static int extract_entry(fmu_archive *a, zip_int64_t i, const char *name, long limit, long *size,
                         char *err, size_t n)
{
    zip_t *zip = a->zip;
    char path[8192];
    zip_file_t *zf;
    zip_stat_t zs;
    int fd, rc;
    /* the declared size refuses a bomb before a byte is written; copy_entry's count catches a
     * header that lies */
    if (zip_stat_index(zip, (zip_uint64_t)i, 0, &zs) == 0 && (zs.valid & ZIP_STAT_SIZE) && zs.size > (zip_uint64_t)limit) {
        snprintf(err, n, "%s: entry '%s' is larger than the limit of %ld MiB", a->path, name, limit >> 20);
        return -1;
    }
    snprintf(path, sizeof path, "%s/%s", a->dir, name);
    if (make_parents(a->dir, path) != 0) {
        snprintf(err, n, "%s: cannot create the folders for %s: %s", a->path, path, strerror(errno));
        return -1;
    }
    zf = zip_fopen_index(zip, (zip_uint64_t)i, 0);
    if (!zf) { snprintf(err, n, "%s: cannot read entry '%s': %s", a->path, name, zip_strerror(zip)); return -1; }
    fd = open(path, O_WRONLY | O_CREAT | O_EXCL, 0600);
    if (fd < 0) {
        snprintf(err, n, "%s: cannot write %s: %s%s", a->path, path, strerror(errno),
                 errno == EEXIST ? " (the archive holds this entry twice)" : "");
        zip_fclose(zf);
        return -1;
    }
    cleanup_push(path, 0);
    rc = copy_entry(zf, fd, limit, size);
    if (rc == -1) snprintf(err, n, "%s: cannot write %s: %s", a->path, path, strerror(errno));
    if (rc == -2) snprintf(err, n, "%s: entry '%s' is corrupt: %s", a->path, name, zip_file_strerror(zf));
    if (rc == -3) snprintf(err, n, "%s: entry '%s' is larger than the limit of %ld MiB", a->path, name, limit >> 20);
    if (close(fd) != 0 && rc == 0) {
        snprintf(err, n, "%s: cannot write %s: %s", a->path, path, strerror(errno));
        rc = -1;
    }
    zip_fclose(zf);
    return rc == 0 ? 0 : -1;
}

/* Extract the entry called exactly `name`; a missing one is reported with `missing`. */
static int extract_named(fmu_archive *a, const char *name, long limit, const char *missing, char *err, size_t n)
{
    zip_int64_t i = zip_name_locate(a->zip, name, 0);
    long size;
    if (i < 0) { snprintf(err, n, "%s: %s", a->path, missing); return -1; }
    return extract_entry(a, i, name, limit, &size, err, n);
}

/* Every file under resources/, within FMU_RESOURCES_MAX_FILES and FMU_RESOURCES_MAX_BYTES. */
static int extract_resources(fmu_archive *a, char *err, size_t n)
{
    zip_int64_t count = zip_get_num_entries(a->zip, 0);
    long files = 0, bytes = 0;
    for (zip_int64_t i = 0; i < count; i++) {
        const char *name = zip_get_name(a->zip, (zip_uint64_t)i, 0);
        long size;
        if (!name || strncmp(name, "resources/", 10) != 0 || name[strlen(name) - 1] == '/') continue;
        if (!safe_entry_name(name)) {
            snprintf(err, n, "%s: entry '%s' has an unsafe name (an absolute path or a '..' component)", a->path, name);
            return -1;
        }
        if (++files > FMU_RESOURCES_MAX_FILES) {
            snprintf(err, n, "%s: resources/ holds more than %d files", a->path, FMU_RESOURCES_MAX_FILES);
            return -1;
        }
        if (extract_entry(a, i, name, FMU_RESOURCES_MAX_BYTES - bytes, &size, err, n) != 0) {
            if (strstr(err, "larger than the limit"))
                snprintf(err, n, "%s: resources/ is larger than the limit of %ld MiB (at entry '%s')", a->path,
                         FMU_RESOURCES_MAX_BYTES >> 20, name);
            return -1;
        }
        bytes += size;
    }
    return 0;
}

static int make_temp_dir(fmu_archive *a, char *err, size_t n)
{
    const char *tmp = getenv("TMPDIR");
    snprintf(a->dir, sizeof a->dir, "%s/fmi2sim_XXXXXX", tmp && *tmp ? tmp : "/tmp");
    if (!mkdtemp(a->dir)) {
        snprintf(err, n, "%s: cannot create a temporary folder in %s: %s", a->path, tmp && *tmp ? tmp : "/tmp", strerror(errno));
        return -1;
    }
    a->is_temp = 1;
    if (cleanup_push(a->dir, 1) != 0) { snprintf(err, n, "out of memory"); return -1; }
    return 0;
}

int fmu_unpack(const char *path, fmu_archive *a, char *err, size_t n)
{
    struct stat st;
    int zerr = 0;
    memset(a, 0, sizeof *a);
    a->path = path;
    if (stat(path, &st) != 0) { snprintf(err, n, "%s: %s", path, strerror(errno)); return -1; }
    if (S_ISDIR(st.st_mode)) { /* already unpacked */
        snprintf(a->dir, sizeof a->dir, "%s", path);
        return 0;
    }
    a->zip = zip_open(path, ZIP_RDONLY, &zerr);
    if (!a->zip) {
        zip_error_t ze;
        zip_error_init_with_code(&ze, zerr);
        snprintf(err, n, "%s: not a valid FMU (zip archive): %s", path, zip_error_strerror(&ze));
        zip_error_fini(&ze);
        return -1;
    }
    if (make_temp_dir(a, err, n) != 0 ||
        extract_named(a, "modelDescription.xml", FMU_MD_MAX_BYTES,
                      "the archive has no modelDescription.xml (an FMU must contain one)", err, n) != 0) {
        fmu_cleanup(a);
        return -1;
    }
    return 0;
}

int fmu_extract_binary(fmu_archive *a, const char *model_identifier, char *err, size_t n)
{
    char name[4200], missing[4300];
    int rc;
    if (!a->zip) return 0;
    snprintf(name, sizeof name, "binaries/linux64/%s.so", model_identifier);
    snprintf(missing, sizeof missing, "cannot load the FMU binary: the archive has no %s", name);
    rc = extract_named(a, name, FMU_BINARY_MAX_BYTES, missing, err, n);
    if (rc == 0) rc = extract_resources(a, err, n);
    zip_discard(a->zip);
    a->zip = NULL;
    return rc;
}

static int remove_one(const char *path, const struct stat *st, int flag, struct FTW *ftw)
{
    (void)st; (void)flag; (void)ftw;
    return remove(path);
}

void fmu_cleanup(fmu_archive *a)
{
    if (a->zip) zip_discard(a->zip);
    a->zip = NULL;
    /* what the FMU may have written into its folder besides what was extracted */
    if (a->is_temp) nftw(a->dir, remove_one, 16, FTW_DEPTH | FTW_PHYS);
    a->is_temp = 0;
}
