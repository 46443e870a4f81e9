/* An FMU on disk: a zip archive unpacked into a temporary folder, or a folder already unpacked.
 * Only what fmi2sim needs is extracted, each with a size limit: modelDescription.xml first
 * (fmu_unpack), then, once its modelIdentifier is known, the one binary and resources/
 * (fmu_extract_binary). sources/, documentation/ and anything else are never written. */
#ifndef FMI2SIM_FMU_ARCHIVE_H
#define FMI2SIM_FMU_ARCHIVE_H

#include <stddef.h>

#define FMU_MD_MAX_BYTES (64L << 20)         /* modelDescription.xml */
#define FMU_BINARY_MAX_BYTES (1L << 30)      /* binaries/linux64/<id>.so */
#define FMU_RESOURCES_MAX_BYTES (256L << 20) /* all of resources/ */
#define FMU_RESOURCES_MAX_FILES 1000

typedef struct {
    char dir[4096];  /* the unpacked FMU */
    int is_temp;     /* dir was made by fmu_unpack and is removed by fmu_cleanup */
    void *zip;       /* the open archive (zip_t *) while entries remain to be extracted */
    const char *path; /* the FMU as given, for messages */
} fmu_archive;

int fmu_unpack(const char *path, fmu_archive *a, char *err, size_t n);
/* Extract binaries/linux64/<model_identifier>.so and resources/ (nothing to do for a folder). */
int fmu_extract_binary(fmu_archive *a, const char *model_identifier, char *err, size_t n);
void fmu_cleanup(fmu_archive *a);

#endif
