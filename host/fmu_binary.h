/* The FMI 2.0 functions of an FMU's shared library, loaded with dlopen. */
#ifndef FMI2SIM_FMU_BINARY_H
#define FMI2SIM_FMU_BINARY_H

#include <stddef.h>
#include "fmi2Functions.h"

typedef struct {
    void *handle;
    fmi2InstantiateTYPE *instantiate;
    fmi2FreeInstanceTYPE *freeInstance;
    fmi2SetDebugLoggingTYPE *setDebugLogging;
    fmi2SetupExperimentTYPE *setupExperiment;
    fmi2EnterInitializationModeTYPE *enterInitializationMode;
    fmi2ExitInitializationModeTYPE *exitInitializationMode;
    fmi2TerminateTYPE *terminate;
    fmi2GetRealTYPE *getReal;
    fmi2GetIntegerTYPE *getInteger;
    fmi2GetBooleanTYPE *getBoolean;
    fmi2GetStringTYPE *getString;
    fmi2SetRealTYPE *setReal;
    fmi2SetIntegerTYPE *setInteger;
    fmi2SetBooleanTYPE *setBoolean;
    fmi2SetStringTYPE *setString;
    fmi2EnterEventModeTYPE *enterEventMode;
    fmi2NewDiscreteStatesTYPE *newDiscreteStates;
    fmi2EnterContinuousTimeModeTYPE *enterContinuousTimeMode;
    fmi2CompletedIntegratorStepTYPE *completedIntegratorStep;
    fmi2SetTimeTYPE *setTime;
    fmi2SetContinuousStatesTYPE *setContinuousStates;
    fmi2GetDerivativesTYPE *getDerivatives;
    fmi2GetEventIndicatorsTYPE *getEventIndicators;
    fmi2GetContinuousStatesTYPE *getContinuousStates;
    fmi2GetNominalsOfContinuousStatesTYPE *getNominalsOfContinuousStates;
} fmu_binary;

/* Load <dir>/binaries/linux64/<model_identifier>.so. */
int fmu_binary_load(const char *dir, const char *model_identifier, fmu_binary *b, char *err, size_t n);
void fmu_binary_unload(fmu_binary *b);

#endif
