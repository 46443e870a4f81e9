/* One FMU instance whichever FMI version drives it: the version-free half of the FMI 2.0 and 3.0
 * layers (fmi2Functions.c, fmi3Functions.c), over its own status enum. It holds the instance
 * (name, call-sequence state, log categories, the model and its data in fmu_core), logs with
 * reasons, checks the call sequence, value references, types, settability, finiteness and array
 * sizes, and does the work of every function both versions have. A layer keeps only what is its
 * version's: the FMI types and signatures, the translation of fmu_status, its masks of allowed
 * states, how a message reaches its logger and the names its messages use (fmu_api). */
#ifndef FMU_INSTANCE_H
#define FMU_INSTANCE_H

#include <stddef.h>

#include "fmu_core.h"

typedef enum { FMU_OK, FMU_WARNING, FMU_DISCARD, FMU_ERROR, FMU_FATAL } fmu_status;

/* The call-sequence states: one bit per state of each interface type, so that one mask per
 * function says both in which states and for which interface type a call is allowed. FMI 2.0
 * never enters FMU_CS_EVENT (Co-Simulation's Event Mode is FMI 3.0's, with eventModeUsed). */
enum {
    FMU_ME_INSTANTIATED = 1 << 0,
    FMU_ME_INIT = 1 << 1,
    FMU_ME_EVENT = 1 << 2,
    FMU_ME_CONT = 1 << 3,
    FMU_ME_TERMINATED = 1 << 4,
    FMU_ME_ERROR = 1 << 5,
    FMU_CS_INSTANTIATED = 1 << 6,
    FMU_CS_INIT = 1 << 7,
    FMU_CS_EVENT = 1 << 8,
    FMU_CS_STEP = 1 << 9, /* initialized, between steps (FMI 2.0 stepComplete, FMI 3.0 Step Mode) */
    FMU_CS_TERMINATED = 1 << 10,
    FMU_CS_ERROR = 1 << 11
};
#define FMU_N_STATES 12
#define FMU_ME_ANY (FMU_ME_INSTANTIATED | FMU_ME_INIT | FMU_ME_EVENT | FMU_ME_CONT | FMU_ME_TERMINATED | FMU_ME_ERROR)
#define FMU_CS_ANY \
    (FMU_CS_INSTANTIATED | FMU_CS_INIT | FMU_CS_EVENT | FMU_CS_STEP | FMU_CS_TERMINATED | FMU_CS_ERROR)
#define FMU_ANY_STATE (FMU_ME_ANY | FMU_CS_ANY)
#define FMU_BEFORE_INIT_END (FMU_ME_INSTANTIATED | FMU_ME_INIT | FMU_CS_INSTANTIATED | FMU_CS_INIT)
#define FMU_READABLE (FMU_ANY_STATE & ~(FMU_ME_INSTANTIATED | FMU_CS_INSTANTIATED))
#define FMU_WRITABLE (FMU_ANY_STATE & ~(FMU_ME_TERMINATED | FMU_ME_ERROR | FMU_CS_TERMINATED | FMU_CS_ERROR))

/* log categories, as declared in modelDescription.xml */
enum { FMU_LOG_EVENTS = 1 << 0, FMU_LOG_WARNING = 1 << 1, FMU_LOG_ERROR = 1 << 2 };

/* The last time a Co-Simulation step may reach [s], about 32 years: a step ending later is refused
 * (doStep(0, 1e300) never returned), as is a step below the resolution of the time. */
#define FMU_MAX_TIME 1e9

/* the value reference of FMI 3.0's independent variable `time`; no model table uses it */
#define FMU_TIME_VR 0u

typedef struct fmu_instance fmu_instance;

/* What differs between the FMI versions in this half: the names in the messages, the variables
 * the version adds, and the importer's logger. */
typedef struct {
    const char *prefix;                        /* "fmi2", "fmi3": function names in the messages */
    const char *state_names[FMU_N_STATES];     /* by the bit of the state */
    const char *type_names[3];                 /* of FMU_REAL, FMU_INTEGER, FMU_BOOLEAN */
    const char *vr_argument, *values_argument; /* the getters' and setters' argument names */
    const char *nx_argument, *nz_argument;     /* the sizes of states and of event indicators */
    const char *fmu_state;                     /* "FMUstate" (FMI 2.0), "FMUState" (FMI 3.0) */
    int name_in_message;   /* FMI 3.0's logger has no instance name: the message starts with it */
    int time_and_indicators_are_variables; /* FMI 3.0: `time` and the event indicators are Float64s */
    /* hands one message to the importer's logger (the layer's instance begins with fmu_instance) */
    void (*emit)(fmu_instance *I, fmu_status status, const char *category, const char *message);
} fmu_api;

struct fmu_instance {
    const fmu_api *api;
    void *(*alloc)(size_t n, size_t size); /* calloc, or the importer's (FMI 2.0) */
    void (*release)(void *p);
    char *name;
    int state;
    const char *function; /* the FMI function running, for the messages */
    unsigned categories;
    int event_mode_used;  /* FMI 3.0 Co-Simulation: the importer enters Event Mode after initialization */
    int states_changed;   /* a state jumped in the current event iteration (fmu_update_discrete_states) */
    fmu_logger log;       /* the model's messages go here */
    fmu_core core;        /* the model, its data, time and Co-Simulation solver (fmu_core.h) */
};

/* external names (prefixed, see fmu_symbol.h) */
#define fmu_instantiate_arguments FMU_SYMBOL(fmu_instantiate_arguments)
#define fmu_instance_init FMU_SYMBOL(fmu_instance_init)
#define fmu_instance_free FMU_SYMBOL(fmu_instance_free)
#define fmu_defuse_percent FMU_SYMBOL(fmu_defuse_percent)
#define fmu_log_event FMU_SYMBOL(fmu_log_event)
#define fmu_fail FMU_SYMBOL(fmu_fail)
#define fmu_enter FMU_SYMBOL(fmu_enter)
#define fmu_leave FMU_SYMBOL(fmu_leave)
#define fmu_initializing FMU_SYMBOL(fmu_initializing)
#define fmu_check_vrs FMU_SYMBOL(fmu_check_vrs)
#define fmu_no_such_type FMU_SYMBOL(fmu_no_such_type)
#define fmu_get_reals FMU_SYMBOL(fmu_get_reals)
#define fmu_get_integer FMU_SYMBOL(fmu_get_integer)
#define fmu_get_boolean FMU_SYMBOL(fmu_get_boolean)
#define fmu_set_real FMU_SYMBOL(fmu_set_real)
#define fmu_set_integer FMU_SYMBOL(fmu_set_integer)
#define fmu_set_boolean FMU_SYMBOL(fmu_set_boolean)
#define fmu_set_debug_logging FMU_SYMBOL(fmu_set_debug_logging)
#define fmu_setup FMU_SYMBOL(fmu_setup)
#define fmu_exit_init FMU_SYMBOL(fmu_exit_init)
#define fmu_enter_event_mode FMU_SYMBOL(fmu_enter_event_mode)
#define fmu_leave_event_mode FMU_SYMBOL(fmu_leave_event_mode)
#define fmu_terminate FMU_SYMBOL(fmu_terminate)
#define fmu_reset FMU_SYMBOL(fmu_reset)
#define fmu_update_discrete_states FMU_SYMBOL(fmu_update_discrete_states)
#define fmu_set_time FMU_SYMBOL(fmu_set_time)
#define fmu_set_states FMU_SYMBOL(fmu_set_states)
#define fmu_get_derivatives FMU_SYMBOL(fmu_get_derivatives)
#define fmu_get_event_indicators FMU_SYMBOL(fmu_get_event_indicators)
#define fmu_get_states FMU_SYMBOL(fmu_get_states)
#define fmu_get_nominals FMU_SYMBOL(fmu_get_nominals)
#define fmu_do_step FMU_SYMBOL(fmu_do_step)
#define fmu_get_fmu_state FMU_SYMBOL(fmu_get_fmu_state)
#define fmu_set_fmu_state FMU_SYMBOL(fmu_set_fmu_state)
#define fmu_free_fmu_state FMU_SYMBOL(fmu_free_fmu_state)
#define fmu_serialized_size FMU_SYMBOL(fmu_serialized_size)
#define fmu_serialize FMU_SYMBOL(fmu_serialize)
#define fmu_deserialize FMU_SYMBOL(fmu_deserialize)

/* ---- instantiation ------------------------------------------------------------------------- */

/* The arguments of an instantiation, before there is an instance to log through: 0 = fine, else
 * msg (safe to log) says why not. `function` and `token_name` name them in the message. */
int fmu_instantiate_arguments(const char *function, const char *name, const char *token_name, const char *token,
                              char *msg, size_t n);
/* I is zeroed memory of the layer's instance, with api, alloc and release set: the rest of it,
 * the model's start values, state Instantiated. 0 = done, else out of memory (fmu_instance_free). */
int fmu_instance_init(fmu_instance *I, const char *name, int co_simulation, int logging_on);
/* everything of the instance, I itself included (by I->release) */
void fmu_instance_free(fmu_instance *I);

/* ---- logging ------------------------------------------------------------------------------- */

/* importers may treat a message as a format string: every % becomes _ */
void fmu_defuse_percent(char *s);
/* a message of category logEvents, prefixed with the running function's name */
void fmu_log_event(fmu_instance *I, const char *fmt, ...);
/* an error with its reason (logStatusError): the instance enters the error state */
fmu_status fmu_fail(fmu_instance *I, const char *fmt, ...);

/* ---- entry and exit of every function ------------------------------------------------------ */

/* Is the call allowed now (mask: its states)? If not, log why and enter the error state. */
int fmu_enter(fmu_instance *I, const char *function, int mask);
/* every error leaves the instance in the error state, whatever path produced it */
fmu_status fmu_leave(fmu_instance *I, fmu_status status);

/* The frame of every function of a layer whose instance argument is named `instance`: ENTER(F)
 * first (F's mask is MASK_F), LEAVE(status) for every return; the layer defines API_STATUS, the
 * translation of a fmu_status into its own status type. A NULL instance has no logger to reach:
 * an error without a message. */
#define ENTER_AS(F, MASK)                                  \
    fmu_instance *const S = (fmu_instance *)instance;      \
    if (!S) return API_STATUS(FMU_ERROR);                  \
    if (!fmu_enter(S, F, MASK)) LEAVE(FMU_ERROR)
#define ENTER(F) ENTER_AS(#F, MASK_##F)
#define LEAVE(status) return API_STATUS(fmu_leave(S, (status)))
#define REQUIRE(cond, ...) \
    do { if (!(cond)) LEAVE(fmu_fail(S, __VA_ARGS__)); } while (0)
#define REQUIRE_NOT_NULL(P) REQUIRE((P) != NULL, "argument %s must not be NULL", #P)
/* a shared operation's status, returned at once unless it is FMU_OK */
#define REQUIRE_OK(CALL) \
    do { const fmu_status rq_ = (CALL); if (rq_ != FMU_OK) LEAVE(rq_); } while (0)

/* ---- variables ----------------------------------------------------------------------------- */

/* 1 before initialization mode is left (start values, discrete states not decided yet) */
int fmu_initializing(const fmu_instance *I);
/* A getter's or setter's arguments: NULL arrays, every value reference known and of the type. */
fmu_status fmu_check_vrs(fmu_instance *I, const unsigned vr[], size_t nvr, const void *values, fmu_type type);
/* a getter or setter of a type (named `type`) no variable of the model has: why vr[0] is refused */
fmu_status fmu_no_such_type(fmu_instance *I, const char *type, const unsigned vr[], size_t nvr);
/* values of checked value references */
void fmu_get_reals(fmu_instance *I, const unsigned vr[], size_t n, double v[]);
int fmu_get_integer(fmu_instance *I, unsigned vr);
int fmu_get_boolean(fmu_instance *I, unsigned vr);
/* One value of a checked value reference: settable now, finite, accepted by the model. */
fmu_status fmu_set_real(fmu_instance *I, unsigned vr, double v);
fmu_status fmu_set_integer(fmu_instance *I, unsigned vr, int v);
fmu_status fmu_set_boolean(fmu_instance *I, unsigned vr);

/* ---- the functions both versions have ------------------------------------------------------ */

fmu_status fmu_set_debug_logging(fmu_instance *I, int logging_on, size_t n, const char *const categories[]);
/* start time and tolerance of the run (FMI 2.0 fmi2SetupExperiment, FMI 3.0 fmi3EnterInitializationMode) */
fmu_status fmu_setup(fmu_instance *I, int tolerance_defined, double tolerance, double start_time);
/* The model's checks at the end of initialization; then Event Mode (Model Exchange) or, in
 * Co-Simulation, the solver and Step Mode (Event Mode with eventModeUsed). */
fmu_status fmu_exit_init(fmu_instance *I);
fmu_status fmu_enter_event_mode(fmu_instance *I);
/* the event iteration ends: Continuous-Time Mode (Model Exchange) or Step Mode (Co-Simulation) */
void fmu_leave_event_mode(fmu_instance *I);
void fmu_terminate(fmu_instance *I);
void fmu_reset(fmu_instance *I);
/* One event update (Model Exchange; nothing to update in Co-Simulation). r->states_changed is
 * true in every call of an event iteration once a state jumped in it, so that an importer that
 * keeps only the last call's flags still re-reads the states. A state that is not finite after
 * the update is an error. */
fmu_status fmu_update_discrete_states(fmu_instance *I, fmu_event_result *r);

/* Model Exchange */
fmu_status fmu_set_time(fmu_instance *I, double time);
fmu_status fmu_set_states(fmu_instance *I, const double x[], size_t n);
fmu_status fmu_get_derivatives(fmu_instance *I, double dx[], size_t n);
fmu_status fmu_get_event_indicators(fmu_instance *I, double z[], size_t n);
fmu_status fmu_get_states(fmu_instance *I, double x[], size_t n);
fmu_status fmu_get_nominals(fmu_instance *I, double x[], size_t n);

/* A Co-Simulation step from t to t + h <= FMU_MAX_TIME. FMU_OK: done, *ended says whether the
 * model ended the run in it (at I->core.time); FMU_DISCARD: the run had ended before, nothing
 * done; FMU_ERROR, also when a state or a Real output is not finite after the step. */
fmu_status fmu_do_step(fmu_instance *I, double t, double h, int *ended);

/* FMU state (canGetAndSetFMUstate, canSerializeFMUstate; the blocks are fmu_core.c's) */
fmu_status fmu_get_fmu_state(fmu_instance *I, void **state);
fmu_status fmu_set_fmu_state(fmu_instance *I, void *state);
fmu_status fmu_free_fmu_state(fmu_instance *I, void **state);
fmu_status fmu_serialized_size(fmu_instance *I, void *state, size_t *size);
fmu_status fmu_serialize(fmu_instance *I, void *state, void *bytes, size_t size);
fmu_status fmu_deserialize(fmu_instance *I, const void *bytes, size_t size, void **state);

#endif
