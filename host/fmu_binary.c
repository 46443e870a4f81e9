/* dlopen of the FMU binary and lookup of every FMI 2.0 Model-Exchange function. */
#include "fmu_binary.h"

#include <dlfcn.h>
#include <elf.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* The binary, symlinks resolved, must lie inside the FMU's folder: a modelIdentifier or a link
 * must not make fmi2sim run a shared object from elsewhere (its constructors run at dlopen). */
static int resolve_inside(const char *dir, const char *path, char *real, char *err, size_t n)
{
    char root[PATH_MAX];
    size_t len;
    if (!realpath(dir, root)) { snprintf(err, n, "%s: %s", dir, strerror(errno)); return -1; }
    if (!realpath(path, real)) { snprintf(err, n, "cannot load the FMU binary: %s: %s", path, strerror(errno)); return -1; }
    len = strlen(root);
    if (strncmp(real, root, len) != 0 || real[len] != '/') {
        snprintf(err, n, "the FMU binary %s resolves to %s, outside the FMU's folder %s", path, real, root);
        return -1;
    }
    return 0;
}

/* dlopen maps the segments the program headers name; a file cut short (a full disk, a truncated
 * archive) ends in SIGBUS when they are touched. Check that they lie inside the file first. */
static int check_elf_extent(const char *path, char *err, size_t n)
{
    FILE *f = fopen(path, "rb");
    Elf64_Ehdr eh;
    struct stat st;
    int rc = -1;
    if (!f) { snprintf(err, n, "cannot load the FMU binary: %s: %s", path, strerror(errno)); return -1; }
    if (fstat(fileno(f), &st) != 0 || fread(&eh, sizeof eh, 1, f) != 1 || memcmp(eh.e_ident, ELFMAG, SELFMAG) != 0 ||
        eh.e_ident[EI_CLASS] != ELFCLASS64 || eh.e_phentsize != sizeof(Elf64_Phdr)) {
        snprintf(err, n, "cannot load the FMU binary: %s is not a 64-bit ELF shared object", path);
        goto done;
    }
    for (unsigned i = 0; i < eh.e_phnum; i++) {
        Elf64_Phdr ph;
        if (fseek(f, (long)(eh.e_phoff + (Elf64_Off)i * sizeof ph), SEEK_SET) != 0 || fread(&ph, sizeof ph, 1, f) != 1) {
            snprintf(err, n, "cannot load the FMU binary: %s is cut short (its program headers end past the file's %lld bytes)",
                     path, (long long)st.st_size);
            goto done;
        }
        if (ph.p_type == PT_LOAD && (ph.p_offset > (Elf64_Off)st.st_size || ph.p_filesz > (Elf64_Off)st.st_size - ph.p_offset)) {
            snprintf(err, n, "cannot load the FMU binary: %s is cut short (a segment ends at byte %llu, the file has %lld)",
                     path, (unsigned long long)(ph.p_offset + ph.p_filesz), (long long)st.st_size);
            goto done;
        }
    }
    rc = 0;
done:
    fclose(f);
    return rc;
}

int fmu_binary_load(const char *dir, const char *model_identifier, fmu_binary *b, char *err, size_t n)
{
    char given[8192], path[PATH_MAX];
    memset(b, 0, sizeof *b);
    snprintf(given, sizeof given, "%s/binaries/linux64/%s.so", dir, model_identifier);
    if (resolve_inside(dir, given, path, err, n) != 0 || check_elf_extent(path, err, n) != 0) return -1;
    b->handle = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!b->handle) { snprintf(err, n, "cannot load the FMU binary: %s", dlerror()); return -1; }
    /* A function pointer is read out of dlsym's void* through memcpy, as POSIX intends. */
#define LOAD(field, name)                                                                      \
    do {                                                                                       \
        void *sym = dlsym(b->handle, name);                                                    \
        if (!sym) {                                                                            \
            snprintf(err, n, "%s does not export %s", path, name);                             \
            fmu_binary_unload(b);                                                              \
            return -1;                                                                         \
        }                                                                                      \
        memcpy(&b->field, &sym, sizeof sym);                                                   \
    } while (0)
    LOAD(instantiate, "fmi2Instantiate");
    LOAD(freeInstance, "fmi2FreeInstance");
    LOAD(setDebugLogging, "fmi2SetDebugLogging");
    LOAD(setupExperiment, "fmi2SetupExperiment");
    LOAD(enterInitializationMode, "fmi2EnterInitializationMode");
    LOAD(exitInitializationMode, "fmi2ExitInitializationMode");
    LOAD(terminate, "fmi2Terminate");
    LOAD(getReal, "fmi2GetReal");
    LOAD(getInteger, "fmi2GetInteger");
    LOAD(getBoolean, "fmi2GetBoolean");
    LOAD(getString, "fmi2GetString");
    LOAD(setReal, "fmi2SetReal");
    LOAD(setInteger, "fmi2SetInteger");
    LOAD(setBoolean, "fmi2SetBoolean");
    LOAD(setString, "fmi2SetString");
    LOAD(enterEventMode, "fmi2EnterEventMode");
    LOAD(newDiscreteStates, "fmi2NewDiscreteStates");
    LOAD(enterContinuousTimeMode, "fmi2EnterContinuousTimeMode");
    LOAD(completedIntegratorStep, "fmi2CompletedIntegratorStep");
    LOAD(setTime, "fmi2SetTime");
    LOAD(setContinuousStates, "fmi2SetContinuousStates");
    LOAD(getDerivatives, "fmi2GetDerivatives");
    LOAD(getEventIndicators, "fmi2GetEventIndicators");
    LOAD(getContinuousStates, "fmi2GetContinuousStates");
    LOAD(getNominalsOfContinuousStates, "fmi2GetNominalsOfContinuousStates");
#undef LOAD
    return 0;
}

void fmu_binary_unload(fmu_binary *b)
{
    if (b->handle) dlclose(b->handle);
    memset(b, 0, sizeof *b);
}
