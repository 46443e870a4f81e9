/* The interface between one model and the shared FMI 2.0 wrapper (fmi2Functions.c, cs_cvode.c):
 * the split of modelica/Reference-FMUs, model callbacks vs one shared API layer.
 *
 * A model (rw_model.c, diaphragm/diaphragm_model.c) defines the one object FMU_MODEL below. It
 * sees no FMI types: the wrapper checks the call sequence, NULL pointers, value references,
 * types, settability and finiteness, and turns the model's messages into fmi2Error + log. */
#ifndef FMU_MODEL_H
#define FMU_MODEL_H

#include <stddef.h>

#include "fmu_symbol.h"

typedef enum { FMU_REAL, FMU_INTEGER, FMU_BOOLEAN } fmu_type;

/* One row of the model's variable table. The wrapper derives from causality and initial when a
 * variable may be set (FMI 2.0 section 2.2.7): inputs always, parameters and variables with
 * initial="exact" (start values of states) until fmi2ExitInitializationMode, others never. */
typedef struct {
    unsigned vr;
    fmu_type type;
    const char *name;
    const char *causality;
    const char *initial;
} fmu_var;

/* The model logs through this (event messages; the wrapper prefixes nothing). */
typedef struct {
    void (*event)(void *ctx, const char *message);   /* category logEvents */
    void (*warning)(void *ctx, const char *message); /* category logStatusWarning */
    void *ctx;
} fmu_logger;

/* What one event-mode update did (fmi2EventInfo without the FMI types). */
typedef struct {
    int states_changed;    /* a continuous state jumped (valuesOfContinuousStatesChanged) */
    int more;              /* call again at the same instant (newDiscreteStatesNeeded) */
    int terminate;         /* the model asks to end the simulation */
    int next_time_defined; /* a time event is pending at next_time */
    double next_time;
} fmu_event_result;

/* The callbacks marked "optional" may be NULL: the FMI layer then uses a default that does what a
 * model without such variables or events needs (no Integer/Boolean variables, nothing settable
 * of that type, nothing to check at the end of initialization, no event indicators, no events,
 * nominal 1 for every state). The others are required. */
typedef struct {
    const char *identifier;
    const char *guid;
    int nx, nz;
    const fmu_var *vars;
    size_t nvars;
    const unsigned *z_vrs; /* value references of the nz event indicators as Real variables: FMI 3.0
                              names them by value reference (<EventIndicator>); NULL when nz = 0 */
    size_t data_size; /* bytes of model data the wrapper allocates per instance; plain data: the
                         FMU state (fmi2GetFMUstate) is a byte copy of it */
    /* Optional: more plain data after data_size bytes, whose size only a function knows (an opaque
       type: RockingWall's exact engine), allocated and copied into the FMU state with the rest */
    size_t (*data_tail_size)(void);

    /* start values of everything (fmi2Instantiate, fmi2Reset) */
    void (*reset)(void *M);
    /* Getters for a list of value references already checked to be of the right type.
     * `initializing` is 1 before fmi2ExitInitializationMode (discrete states not decided yet). */
    void (*get_real)(void *M, int initializing, double time, const unsigned vr[], size_t n, double v[]);
    void (*get_integer)(void *M, int initializing, const unsigned vr[], size_t n, int v[]); /* optional */
    void (*get_boolean)(void *M, const unsigned vr[], size_t n, int v[]);                   /* optional */
    /* Setters for one settable variable with a finite value: 0 = stored, else msg says why not. */
    int (*set_real)(void *M, unsigned vr, double v, char *msg, size_t n);   /* optional */
    int (*set_integer)(void *M, unsigned vr, int v, char *msg, size_t n);   /* optional */
    /* fmi2ExitInitializationMode: validate the parameters together, decide the discrete states.
     * 0 = ok, else msg says why not. Optional. */
    int (*exit_init)(void *M, double time, const fmu_logger *log, char *msg, size_t n);

    /* continuous-time evaluation (x has nx entries, z nz) */
    void (*get_states)(void *M, int initializing, double x[]);
    void (*set_states)(void *M, const double x[]);
    void (*derivatives)(void *M, double dx[]);
    void (*event_indicators)(void *M, int initializing, double z[]); /* optional when nz = 0 */
    void (*nominals)(double x[]);  /* optional: x holds 1 for every state on entry */
    /* one event-mode update at `time`; optional (no events: nothing changes) */
    void (*event_update)(void *M, double time, const fmu_logger *log, fmu_event_result *r);

    /* Optional (NULL, or FMU_NOT_EXACT returned: the CVODE step of cs_cvode.c). A Co-Simulation
     * step from t to t + h done exactly by the model over inputs linear in time: their values are
     * the ones set in the model, slope[i] the derivative the master gave for slope_vr[i] (0 if
     * none). Returns 0 (t + h reached), 1 (the model ended the run at *t_reached), -1 (msg says
     * why), or FMU_NOT_EXACT when these parameters need the general solver. */
    int (*exact_step)(void *M, double t, double h, const unsigned *slope_vr, const double *slope, size_t n_in,
                      const fmu_logger *log, double *t_reached, char *msg, size_t n);
} fmu_model;

#define FMU_NOT_EXACT 2

/* the model of this binary (FMU_SYMBOL: prefixed under FMI2_FUNCTION_PREFIX) */
#define FMU_MODEL FMU_SYMBOL(FMU_MODEL)
extern const fmu_model FMU_MODEL;

#endif
