/* output_file.h: temporary file, checks, rename. */
#define _XOPEN_SOURCE 700
#include "output_file.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cleanup.h"

/* The file the output replaces: a symlink is followed, so the link stays and its target is
 * written, as a plain fopen would. 1: write in place (a device, a FIFO, /dev/stdout), 0: temp
 * file + rename, -1: error. */
static int resolve_target(output_file *o, const char *path, char *err, size_t n)
{
    struct stat st, lst;
    char real[PATH_MAX];
    snprintf(o->path, sizeof o->path, "%s", path);
    if (stat(path, &st) != 0) {
        if (lstat(path, &lst) == 0) { snprintf(err, n, "%s: a symbolic link to nothing", path); return -1; }
        return 0; /* a new file */
    }
    if (S_ISDIR(st.st_mode)) { snprintf(err, n, "%s: is a folder, not a file", path); return -1; }
    if (!S_ISREG(st.st_mode)) return 1;
    if (lstat(path, &lst) == 0 && S_ISLNK(lst.st_mode)) {
        if (!realpath(path, real)) { snprintf(err, n, "%s: %s", path, strerror(errno)); return -1; }
        snprintf(o->path, sizeof o->path, "%s", real);
    }
    return 0;
}

static int open_temp(output_file *o, char *err, size_t n)
{
    mode_t mask = umask(0);
    int fd;
    umask(mask);
    snprintf(o->tmp, sizeof o->tmp, "%s.fmi2sim-XXXXXX", o->path);
    if ((fd = mkstemp(o->tmp)) < 0) {
        snprintf(err, n, "%s: cannot create a temporary file beside it: %s", o->name, strerror(errno));
        o->tmp[0] = '\0';
        return -1;
    }
    cleanup_push(o->tmp, 0);
    fchmod(fd, 0666 & ~mask); /* the permissions a plain fopen would give */
    if (!(o->f = fdopen(fd, "w"))) {
        snprintf(err, n, "%s: %s", o->name, strerror(errno));
        close(fd);
        output_discard(o);
        return -1;
    }
    return 0;
}

int output_open(output_file *o, const char *path, char *err, size_t n)
{
    int in_place;
    memset(o, 0, sizeof *o);
    o->name = path ? path : "standard output";
    if (!path) { o->f = stdout; return 0; }
    if ((in_place = resolve_target(o, path, err, n)) < 0) return -1;
    if (!in_place) return open_temp(o, err, n);
    if (!(o->f = fopen(o->path, "w"))) { snprintf(err, n, "%s: %s", path, strerror(errno)); return -1; }
    return 0;
}

int output_printf(output_file *o, const char *fmt, ...)
{
    va_list ap;
    int rc;
    if (o->write_errno) return -1;
    errno = 0;
    va_start(ap, fmt);
    rc = vfprintf(o->f, fmt, ap);
    va_end(ap);
    if (rc < 0 || ferror(o->f)) o->write_errno = errno ? errno : EIO;
    return o->write_errno ? -1 : 0;
}

int output_commit(output_file *o, char *err, size_t n)
{
    int failed = o->write_errno != 0, saved = o->write_errno;
    if (!failed && (fflush(o->f) != 0 || ferror(o->f))) { failed = 1; saved = errno; }
    if (!failed && o->tmp[0] && fsync(fileno(o->f)) != 0) { failed = 1; saved = errno; }
    if (fclose(o->f) != 0 && !failed) { failed = 1; saved = errno; }
    o->f = NULL;
    if (!failed && o->tmp[0] && rename(o->tmp, o->path) != 0) { failed = 1; saved = errno; }
    if (failed) {
        snprintf(err, n, "%s: write failed: %s%s", o->name, strerror(saved ? saved : EIO),
                 o->tmp[0] ? " (the file was not written)" : "");
        output_discard(o);
        return -1;
    }
    if (o->tmp[0]) cleanup_forget(o->tmp);
    o->tmp[0] = '\0';
    return 0;
}

void output_discard(output_file *o)
{
    if (o->f && o->f != stdout) fclose(o->f);
    o->f = NULL;
    if (o->tmp[0]) {
        unlink(o->tmp);
        cleanup_forget(o->tmp);
        o->tmp[0] = '\0';
    }
}
