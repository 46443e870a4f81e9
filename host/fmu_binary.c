/* dlopen of the FMU binary and lookup of every FMI 2.0 Model-Exchange function. */
#include "fmu_binary.h"

#include <dlfcn.h>
#include <stdio.h>
#include <string.h>

int fmu_binary_load(const char *dir, const char *model_identifier, fmu_binary *b, char *err, size_t n)
{
    char path[8192];
    memset(b, 0, sizeof *b);
    snprintf(path, sizeof path, "%s/binaries/linux64/%s.so", dir, model_identifier);
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
