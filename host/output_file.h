/* An output file written safely: into a temporary file in the same folder, renamed into place
 * only when every write, the flush, fsync and close succeeded, so that a failed or interrupted
 * run never leaves a truncated or partial file in place of an existing one. Standard output and
 * existing files that are not regular (/dev/full, a FIFO) are written in place, with the same
 * checks. */
#ifndef FMI2SIM_OUTPUT_FILE_H
#define FMI2SIM_OUTPUT_FILE_H

#include <stddef.h>
#include <stdio.h>

typedef struct {
    FILE *f;
    char path[4096]; /* where the output ends up (symlinks resolved) */
    char tmp[4200];  /* the temporary file; "" when written in place */
    const char *name; /* as the user gave it, for messages */
    int write_errno;  /* errno of the first failed write, 0 while none failed */
} output_file;

/* path NULL: standard output. 0, or -1 with a message naming the file. */
int output_open(output_file *o, const char *path, char *err, size_t n);
/* fprintf into the output; 0, or -1 once any write failed (the first errno is kept). */
int output_printf(output_file *o, const char *fmt, ...);
/* Flush, check, close and rename into place; on failure the temporary file is removed. */
int output_commit(output_file *o, char *err, size_t n);
/* Close and remove the temporary file (nothing is renamed); safe to call twice. */
void output_discard(output_file *o);

#endif
