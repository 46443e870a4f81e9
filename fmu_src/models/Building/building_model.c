/* Building as an FMU model: the callbacks of fmu_model.h over building_physics.c. Holds the
 * instance data (parameters, inputs, states); the FMI 2.0 API is the shared fmi2Functions.c and
 * Co-Simulation the shared CVODE stepper (cs_cvode.c). No events: the hysteretic variables (Bouc-Wen
 * and bilinear) are continuous states. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "building_physics.h"
#include "building_variables.h"
#include "fmu_model.h"

typedef char bd_check_nx[(BD_NUMBER_OF_STATES == BD_NX) ? 1 : -1];

typedef struct {
    bd_params P;
    bd_input in;
    double x[BD_NX];
} bd_data;

#define FMU_Real FMU_REAL
#define FMU_Integer FMU_INTEGER
#define BD_VAR(ID, VR, NAME, TYPE, CAUS, VARIAB, INIT, START, UNIT, NOM, DER, DESC) {VR, FMU_##TYPE, NAME, CAUS, INIT},
static const fmu_var VARS[] = {BD_VARIABLES(BD_VAR)};
#undef BD_VAR

/* slots of a floor's value references (BD_SLOT_OF): parameters, input, states, rates, outputs */
enum {
    SLOT_M = 1, SLOT_K, SLOT_FY, SLOT_ALPHA, SLOT_MD, SLOT_KD, SLOT_FYD, SLOT_ALPHAD,
    SLOT_F_WALL = 10, SLOT_F_ABOVE = 11, SLOT_CS = 12, SLOT_CD = 13,
    SLOT_STATE = 20, /* 20..27: the floor's states in the order of building_physics.h */
    SLOT_RATE = 30,  /* 31, 32, 34..37: rates of the states 21, 22, 24..27 */
    SLOT_A_DIAPH = 40, SLOT_U_TOP, SLOT_V_STOREY, SLOT_DRIFT, SLOT_F_DIAPH, SLOT_D_DIAPH
};

/* the parameter a floor slot stands for, NULL for the slots that are not parameters */
static double *floor_parameter(bd_params *P, int i, int slot)
{
    switch (slot) {
    case SLOT_M: return &P->m[i];
    case SLOT_K: return &P->storey[i].k;
    case SLOT_FY: return &P->storey[i].Fy;
    case SLOT_ALPHA: return &P->storey[i].alpha;
    case SLOT_MD: return &P->md[i];
    case SLOT_KD: return &P->diaph[i].k;
    case SLOT_FYD: return &P->diaph[i].Fy;
    case SLOT_ALPHAD: return &P->diaph[i].alpha;
    case SLOT_CS: return &P->cs[i];
    case SLOT_CD: return &P->cd[i];
    default: return NULL;
    }
}

static double *shared_parameter(bd_params *P, unsigned vr)
{
    switch (vr) {
    case BD_VR_nBW: return &P->n_bw;
    case BD_VR_betaBW: return &P->beta;
    case BD_VR_pinchSize: return &P->pinch_size;
    case BD_VR_pinchWidth: return &P->pinch_width;
    case BD_VR_pinchCentre: return &P->pinch_centre;
    case BD_VR_rayleighMass: return &P->a0;
    case BD_VR_rayleighStiffness: return &P->a1;
    default: return NULL;
    }
}

static int *integer_parameter(bd_params *P, unsigned vr)
{
    switch (vr) {
    case BD_VR_nStoreys: return &P->n_storeys;
    case BD_VR_storeyLaw: return &P->storey_law;
    case BD_VR_diaphragmLaw: return &P->diaphragm_law;
    default: return NULL;
    }
}

static void reset(void *M)
{
    bd_data *S = (bd_data *)M;
    memset(S, 0, sizeof *S);
#define BD_START(ID, VR, NAME, TYPE, CAUS, VARIAB, INIT, START, UNIT, NOM, DER, DESC)                              \
    if (strcmp(CAUS, "parameter") == 0) {                                                                        \
        double *r = BD_FLOOR_OF(VR) ? floor_parameter(&S->P, BD_FLOOR_OF(VR) - 1, BD_SLOT_OF(VR))                \
                                    : shared_parameter(&S->P, VR);                                               \
        int *k = integer_parameter(&S->P, VR);                                                                   \
        if (r) *r = START;                                                                                       \
        if (k) *k = (int)(START);                                                                                \
    }
    BD_VARIABLES(BD_START)
#undef BD_START
}

/* a Real of floor i (0-based) at slot, from the states x and their rates dx */
static double floor_real(bd_data *S, int i, int slot, const double dx[BD_NX])
{
    const double *xf = S->x + BD_STATES_PER_FLOOR * i;
    const int active = i < S->P.n_storeys;
    double *param = floor_parameter(&S->P, i, slot);
    if (param) return *param;
    if (slot >= SLOT_STATE && slot < SLOT_STATE + BD_STATES_PER_FLOOR) return xf[slot - SLOT_STATE];
    if (slot > SLOT_RATE && slot < SLOT_RATE + BD_STATES_PER_FLOOR) return dx[BD_STATES_PER_FLOOR * i + slot - SLOT_RATE];
    if (slot == SLOT_F_WALL) return S->in.F_wall[i];
    if (slot == SLOT_F_ABOVE) return S->in.F_above[i];
    /* a floor above nStoreys is not there: its outputs read 0, not the floor below's negative */
    if (!active) return 0.0;
    switch (slot) {
    case SLOT_A_DIAPH: return bd_diaphragm_acceleration(&S->P, &S->in, S->x, i);
    case SLOT_U_TOP: return xf[BD_Y] - (i > 0 ? S->x[BD_STATES_PER_FLOOR * (i - 1) + BD_Y] : 0.0);
    case SLOT_V_STOREY: return bd_storey_force(&S->P, S->x, i);
    case SLOT_DRIFT: return bd_drift(S->x, i);
    case SLOT_F_DIAPH: return bd_diaphragm_force(&S->P, S->x, i);
    default: return bd_diaphragm_deformation(S->x, i); /* SLOT_D_DIAPH, the last Real of a floor */
    }
}

static void get_real(void *M, int initializing, double time, const unsigned vr[], size_t n, double v[])
{
    bd_data *S = (bd_data *)M;
    double dx[BD_NX];
    size_t j;
    (void)initializing;
    (void)time;
    bd_derivatives(&S->P, &S->in, S->x, dx);
    for (j = 0; j < n; j++) {
        const int floor = BD_FLOOR_OF(vr[j]);
        if (floor) v[j] = floor_real(S, floor - 1, BD_SLOT_OF(vr[j]), dx);
        else if (vr[j] == BD_VR_ag) v[j] = S->in.ag;
        else v[j] = *shared_parameter(&S->P, vr[j]); /* the other Reals below 100 are parameters */
    }
}

static void get_integer(void *M, int initializing, const unsigned vr[], size_t n, int v[])
{
    size_t j;
    (void)initializing;
    for (j = 0; j < n; j++) v[j] = *integer_parameter(&((bd_data *)M)->P, vr[j]);
}

/* the range of every Real parameter; the names are the table's */
static int check_range(const char *name, double value, double lo, double hi, int lo_open, char *msg, size_t n)
{
    if ((lo_open ? value > lo : value >= lo) && value <= hi) return 0;
    snprintf(msg, n, "%s = %g is out of its range %s%g, %g]", name, value, lo_open ? "(" : "[", lo, hi);
    return 1;
}

static const char *name_of(unsigned vr)
{
    size_t j;
    for (j = 0; j < sizeof VARS / sizeof VARS[0]; j++)
        if (VARS[j].vr == vr) return VARS[j].name;
    return "?";
}

static int check_real(unsigned vr, double value, char *msg, size_t n)
{
    const char *name = name_of(vr);
    const int slot = BD_SLOT_OF(vr);
    if (BD_FLOOR_OF(vr) == 0) {
        switch (vr) {
        case BD_VR_nBW: return check_range(name, value, 1.0, 100.0, 0, msg, n);
        case BD_VR_betaBW: return check_range(name, value, 0.0, 1.0, 0, msg, n);
        case BD_VR_pinchSize:
        case BD_VR_pinchCentre: return check_range(name, value, 0.0, 0.99, 0, msg, n);
        case BD_VR_pinchWidth: return check_range(name, value, 0.01, 10.0, 0, msg, n);
        case BD_VR_rayleighMass: return check_range(name, value, 0.0, 1e3, 0, msg, n);
        case BD_VR_rayleighStiffness: return check_range(name, value, 0.0, 1.0, 0, msg, n);
        default: return 0; /* ag */
        }
    }
    switch (slot) {
    case SLOT_M:
    case SLOT_MD: return check_range(name, value, 0.0, 1e9, 1, msg, n);
    case SLOT_K:
    case SLOT_KD:
    case SLOT_FY:
    case SLOT_FYD: return check_range(name, value, 0.0, 1e15, 1, msg, n);
    case SLOT_ALPHA:
    case SLOT_ALPHAD: return check_range(name, value, 0.0, 1.0, 0, msg, n);
    case SLOT_CS:
    case SLOT_CD: return check_range(name, value, 0.0, 1e15, 0, msg, n);
    case SLOT_STATE + BD_Z:
    case SLOT_STATE + BD_ZD: return check_range(name, value, -1.0, 1.0, 0, msg, n); /* |z| <= z_u */
    default: return 0;
    }
}

static int set_real(void *M, unsigned vr, double value, char *msg, size_t n)
{
    bd_data *S = (bd_data *)M;
    const int floor = BD_FLOOR_OF(vr), slot = BD_SLOT_OF(vr);
    double *param;
    if (check_real(vr, value, msg, n)) return 1;
    if (floor == 0) {
        if (vr == BD_VR_ag) S->in.ag = value;
        else *shared_parameter(&S->P, vr) = value;
        return 0;
    }
    param = floor_parameter(&S->P, floor - 1, slot);
    if (param) *param = value;
    else if (slot == SLOT_F_WALL) S->in.F_wall[floor - 1] = value;
    else if (slot == SLOT_F_ABOVE) S->in.F_above[floor - 1] = value;
    else S->x[BD_STATES_PER_FLOOR * (floor - 1) + slot - SLOT_STATE] = value; /* a state's start value */
    return 0;
}

static int set_integer(void *M, unsigned vr, int value, char *msg, size_t n)
{
    bd_data *S = (bd_data *)M;
    if (vr == BD_VR_nStoreys && (value < 1 || value > BD_MAX_FLOORS)) {
        snprintf(msg, n, "%s = %d is out of its range [1, %d]", name_of(vr), value, BD_MAX_FLOORS);
        return 1;
    }
    if (vr != BD_VR_nStoreys && !bd_law_allowed(value, vr == BD_VR_storeyLaw)) {
        snprintf(msg, n, "%s = %d is not one of its laws (%s)", name_of(vr), value,
                 vr == BD_VR_storeyLaw ? BD_STOREY_LAWS_TEXT : BD_DIAPHRAGM_LAWS_TEXT);
        return 1;
    }
    *integer_parameter(&S->P, vr) = value;
    return 0;
}

/* the floors above nStoreys are not part of the building: at rest, whatever their start values */
static int exit_init(void *M, double time, const fmu_logger *log, char *msg, size_t n)
{
    bd_data *S = (bd_data *)M;
    const int first_unused = BD_STATES_PER_FLOOR * S->P.n_storeys;
    (void)time;
    (void)log;
    (void)msg;
    (void)n;
    memset(S->x + first_unused, 0, sizeof(double) * (size_t)(BD_NX - first_unused));
    return 0;
}

static void get_states(void *M, int initializing, double x[])
{
    (void)initializing;
    memcpy(x, ((bd_data *)M)->x, sizeof(double) * BD_NX);
}

static void set_states(void *M, const double x[]) { memcpy(((bd_data *)M)->x, x, sizeof(double) * BD_NX); }

static void derivatives(void *M, double dx[])
{
    bd_data *S = (bd_data *)M;
    bd_derivatives(&S->P, &S->in, S->x, dx);
}

static void nominals(double x[])
{
    int i;
    for (i = 0; i < BD_MAX_FLOORS; i++) {
        double *f = x + BD_STATES_PER_FLOOR * i;
        f[BD_U] = f[BD_Y] = 0.01; /* drifts of the order of 1 cm */
        f[BD_V] = f[BD_W] = 0.1;
        /* z (|z| <= 1) and the works keep nominal 1 */
    }
}

/* no events; every parameter checked when set */
const fmu_model FMU_MODEL = {
    .identifier = BD_MODEL_IDENTIFIER,
    .guid = BD_GUID,
    .nx = BD_NUMBER_OF_STATES,
    .nz = BD_NUMBER_OF_EVENT_INDICATORS,
    .vars = VARS,
    .nvars = sizeof VARS / sizeof VARS[0],
    .data_size = sizeof(bd_data),
    .reset = reset,
    .get_real = get_real,
    .get_integer = get_integer,
    .set_real = set_real,
    .set_integer = set_integer,
    .exit_init = exit_init,
    .get_states = get_states,
    .set_states = set_states,
    .derivatives = derivatives,
    .nominals = nominals,
};
