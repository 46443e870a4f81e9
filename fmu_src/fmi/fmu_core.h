/* What the FMI 2.0 and FMI 3.0 layers (fmi2Functions.c, fmi3Functions.c) share, without FMI types:
 * the model with defaults for the callbacks it leaves out, the variable table lookups, and the FMU
 * state (get/set/serialize) of an instance's simulation data. Each layer keeps its own call
 * sequence, status codes and logging; the parts here report problems as messages. */
#ifndef FMU_CORE_H
#define FMU_CORE_H

#include <stddef.h>

#include "cs_cvode.h"
#include "fmu_model.h"

/* external names (prefixed, see fmu_symbol.h) */
#define fmu_model_with_defaults FMU_SYMBOL(fmu_model_with_defaults)
#define fmu_find_var FMU_SYMBOL(fmu_find_var)
#define fmu_var_kind FMU_SYMBOL(fmu_var_kind)
#define fmu_core_inputs FMU_SYMBOL(fmu_core_inputs)
#define fmu_core_find_input FMU_SYMBOL(fmu_core_find_input)
#define fmu_core_nominals FMU_SYMBOL(fmu_core_nominals)
#define fmu_core_step FMU_SYMBOL(fmu_core_step)
#define fmu_state_size FMU_SYMBOL(fmu_state_size)
#define fmu_state_write FMU_SYMBOL(fmu_state_write)
#define fmu_state_check FMU_SYMBOL(fmu_state_check)
#define fmu_state_is_ours FMU_SYMBOL(fmu_state_is_ours)
#define fmu_state_bytes FMU_SYMBOL(fmu_state_bytes)
#define fmu_state_read FMU_SYMBOL(fmu_state_read)

/* The simulation data of one instance, whichever FMI version drives it. */
typedef struct {
    fmu_model model;      /* FMU_MODEL with defaults for the callbacks it leaves out */
    void *M;              /* the model's data (model.data_size bytes) */
    int co_simulation;    /* 1 = Co-Simulation instance, 0 = Model Exchange */
    double time;
    double rtol;          /* Co-Simulation: the tolerance of the master, 0 = none given */
    cs_solver *cs;        /* Co-Simulation after initialization: CVODE */
    cs_input *inputs;     /* every Real input, value refreshed before each step */
    size_t n_inputs;
    int terminated;       /* the model ended the run */
    int initialized;      /* initialization mode was left successfully (until a reset) */
    double last_successful_time;
} fmu_core;

/* *m = FMU_MODEL with the defaults for the optional callbacks it leaves NULL */
void fmu_model_with_defaults(fmu_model *m);
const fmu_var *fmu_find_var(const fmu_model *m, unsigned vr);

/* When may a variable be set (FMI 2.0 section 2.2.7, FMI 3.0 section 2.4.7.4 agree here)? */
enum { FMU_SET_ALWAYS, FMU_SET_BEFORE_INIT_END, FMU_SET_NEVER };
int fmu_var_kind(const fmu_var *v);

/* core->inputs from the model's table (every Real input); the array has nvars + 1 slots */
void fmu_core_inputs(fmu_core *core);
cs_input *fmu_core_find_input(fmu_core *core, unsigned vr);

/* the nominals of the continuous states (nx entries): the model's, or 1 where it gives none */
void fmu_core_nominals(const fmu_core *core, double x[]);

/* One Co-Simulation step from core->time to core->time + h: exactly where the model offers it
 * (exact_step), else with CVODE (cs_step); the inputs are the values set in the model, ramped
 * with the slopes given for this step only. Returns 0 (reached), 1 (the model ended the run at
 * core->time) or -1 (msg says why); time, last_successful_time and terminated follow. */
int fmu_core_step(fmu_core *core, double h, const fmu_logger *log, char *msg, size_t msg_n);

/* An FMU state is one block of bytes in its serialized form: a header, the model's data (a byte
 * copy: fmu_model.h asks for plain data), the Real inputs' slopes and, in Co-Simulation after
 * initialization, what re-creates the integrator exactly (cs_get_state). Serializing is a copy;
 * deserializing checks everything before copying. The call-sequence state of the instance is
 * not part of it: the importer is in charge of that. */
size_t fmu_state_size(const fmu_core *core);
void fmu_state_write(const fmu_core *core, void *block);
/* Is `block` (n bytes) a state of this FMU and this binary? 0 = yes, else msg says why not. */
int fmu_state_check(const fmu_core *core, const void *block, size_t n, char *msg, size_t msg_n);
/* a cheap test of a block the importer hands back (magic number); 0 = ours */
int fmu_state_is_ours(const void *block, char *msg, size_t msg_n);
/* the size recorded in a block that passed fmu_state_is_ours */
size_t fmu_state_bytes(const void *block);
/* A checked block into the instance; it must also fit the instance now (interface type, taken
 * before or after initialization). 0 = restored, else msg says why not and nothing changed. */
int fmu_state_read(fmu_core *core, const void *block, char *msg, size_t msg_n);

#endif
