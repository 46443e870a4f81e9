/* An FMU on disk: a zip archive unpacked into a temporary folder, or a folder already unpacked. */
#ifndef FMI2SIM_FMU_ARCHIVE_H
#define FMI2SIM_FMU_ARCHIVE_H

#include <stddef.h>

typedef struct {
    char dir[4096]; /* the unpacked FMU */
    int is_temp;    /* dir was made by fmu_unpack and is removed by fmu_cleanup */
} fmu_archive;

int fmu_unpack(const char *path, fmu_archive *a, char *err, size_t n);
void fmu_cleanup(fmu_archive *a);

#endif
