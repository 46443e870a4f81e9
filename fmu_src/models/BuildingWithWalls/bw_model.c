/* BuildingWithWalls as an FMU model: the callbacks of fmu_model.h over the scene (rw_scene.h): a
 * building's face-loaded walls, their ties, diaphragms and floors as the states of one model, each
 * wall with its own physics and event rules. Model Exchange gives the importer's solver the whole
 * scene; Co-Simulation integrates it inside with the shared CVODE stepper (cs_cvode.c), so there is
 * no exchange between walls and diaphragms that could go unstable (docs/building-coupling.md).
 *
 * The FMU's state vector has a fixed layout (bw_variables.h): work_ground, work_damping, then 12
 * states per storey; the scene's own layout depends on nStoreys (4 wall states per storey, then 8
 * per floor), so the states are packed into it for every evaluation. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "bw_params.h"
#include "bw_variables.h"
#include "fmu_model.h"

#define BW_PER_STOREY (RW_NX + BD_STATES_PER_FLOOR)
#define BW_SHARED_STATES 2 /* work_ground, work_damping */
#define BLOCK(x, i) ((x) + BW_SHARED_STATES + BW_PER_STOREY * (i))

typedef char bw_check_nx[(BW_NUMBER_OF_STATES == BW_SHARED_STATES + BW_PER_STOREY * RW_SCENE_MAX_STOREYS) ? 1 : -1];
typedef char bw_check_nz[(BW_NUMBER_OF_EVENT_INDICATORS == RW_SCENE_NZ) ? 1 : -1];

#define FMU_Real FMU_REAL
#define FMU_Integer FMU_INTEGER
#define FMU_Boolean FMU_BOOLEAN
#define BW_VAR(ID, VR, NAME, TYPE, CAUS, VARIAB, INIT, START, UNIT, NOM, DER, DESC) {VR, FMU_##TYPE, NAME, CAUS, INIT},
static const fmu_var VARS[] = {BW_VARIABLES(BW_VAR)};
#undef BW_VAR

#define BW_Z_VR(ID, VR, DESC) VR,
static const unsigned Z_VRS[] = {BW_EVENT_INDICATORS(BW_Z_VR)};
#undef BW_Z_VR
typedef char bw_check_z_vrs[(sizeof Z_VRS / sizeof Z_VRS[0] == RW_SCENE_NZ) ? 1 : -1];

/* slots of a storey's value references (BW_SLOT_OF) beyond its parameters (bw_params.c) */
enum {
    SLOT_STATE = 20, /* 20..31: the storey's states in their order */
    SLOT_RATE = 32,  /* 32..39: rates of dq1, dq2, v_floor, z_storey, v_diaph, z_diaph, work_storey, work_diaph */
    SLOT_S1 = 40, SLOT_S2, SLOT_COLLAPSED, SLOT_IMPACTS, SLOT_F_TOP, SLOT_F_BASE, SLOT_D_DIAPH, SLOT_A_DIAPH,
    SLOT_A_BASE,
    SLOT_Z = 50      /* 50..57: the wall's event indicators */
};
/* where each rate slot's value is in a storey's block of derivatives */
static const int RATE_INDEX[8] = {2, 3, 5, 6, 8, 9, 10, 11};

/* an instant of the scene: its states in the scene's layout, rates, forces and accelerations */
typedef struct {
    const rw_scene *sc;
    double xs[RW_SCENE_NX], dxs[RW_SCENE_NX];
    rw_scene_aux aux;
    double p_ground, p_damping;
} bw_instant;

static void pack(int n, const double x[], double xs[RW_SCENE_NX])
{
    int i;
    memset(xs, 0, sizeof(double) * RW_SCENE_NX);
    for (i = 0; i < n; i++) {
        memcpy(xs + RW_NX * i, BLOCK(x, i), sizeof(double) * RW_NX);
        memcpy(xs + RW_NX * n + BD_STATES_PER_FLOOR * i, BLOCK(x, i) + RW_NX, sizeof(double) * BD_STATES_PER_FLOOR);
    }
}

static void unpack(int n, const double xs[RW_SCENE_NX], double x[])
{
    int i;
    for (i = 0; i < RW_SCENE_MAX_STOREYS; i++) memset(BLOCK(x, i), 0, sizeof(double) * BW_PER_STOREY);
    for (i = 0; i < n; i++) {
        memcpy(BLOCK(x, i), xs + RW_NX * i, sizeof(double) * RW_NX);
        memcpy(BLOCK(x, i) + RW_NX, xs + RW_NX * n + BD_STATES_PER_FLOOR * i, sizeof(double) * BD_STATES_PER_FLOOR);
    }
}

static void reset(void *M)
{
    bw_params_reset((bw_data *)M);
}

/* The scene as it stands: set up at the end of initialization; before that, one made from the
 * current parameters and start values in *tmp (NULL while the parameters do not make a scene). */
static const rw_scene *scene_now(bw_data *S, rw_scene *tmp)
{
    rw_scene_spec spec;
    double xs[RW_SCENE_NX], start[RW_SCENE_NX];
    char why[8];
    if (S->ready) return &S->sc;
    bw_params_spec(S, &spec);
    if (rw_scene_validate(&spec, why, sizeof why)) return NULL;
    pack(spec.n_storeys, S->x, start);
    rw_scene_start_state(&spec, start, xs);
    rw_scene_init(tmp, &spec, S->ag, xs);
    return tmp;
}

/* the instant's rates and forces; 0 without a scene */
static int evaluate(bw_data *S, rw_scene *tmp, bw_instant *v)
{
    memset(v, 0, sizeof *v);
    v->sc = scene_now(S, tmp);
    if (!v->sc) return 0;
    pack(v->sc->S.n_storeys, S->x, v->xs);
    rw_scene_derivatives(v->sc, S->ag, v->xs, v->dxs, &v->aux);
    rw_scene_powers(v->sc, S->ag, v->xs, &v->p_ground, &v->p_damping);
    return 1;
}

static double energy_now(const bw_data *S, const bw_instant *v)
{
    return v->sc ? rw_scene_energy(v->sc, S->ag, v->xs) : 0.0;
}

/* a Real output or rate of storey i (0-based) at slot */
static double storey_real(bw_data *S, const bw_instant *v, int i, int slot)
{
    const int active = v->sc && i < v->sc->S.n_storeys;
    double z[RW_SCENE_NZ];
    if (slot >= SLOT_STATE && slot < SLOT_RATE) return BLOCK(S->x, i)[slot - SLOT_STATE];
    if (!active) return slot >= SLOT_Z ? 1.0 : 0.0;
    if (slot >= SLOT_RATE && slot < SLOT_S1) {
        double dx[BW_NUMBER_OF_STATES];
        unpack(v->sc->S.n_storeys, v->dxs, dx);
        return BLOCK(dx, i)[RATE_INDEX[slot - SLOT_RATE]];
    }
    switch (slot) {
    case SLOT_S1: return rw_scene_s1(v->sc, v->xs, i);
    case SLOT_S2: return rw_scene_s2(v->sc, v->xs, i);
    case SLOT_F_TOP: return v->aux.F_top[i];
    case SLOT_F_BASE: return v->aux.F_base[i];
    case SLOT_D_DIAPH: return rw_scene_diaphragm_deformation(v->sc, v->xs, i);
    case SLOT_A_DIAPH: return v->aux.a_diaph[i];
    case SLOT_A_BASE: return v->aux.a_base[i];
    default: /* SLOT_Z + k: the wall's event indicator k */
        rw_scene_indicators(v->sc, S->ag, v->xs, z);
        return z[RW_NZ * i + slot - SLOT_Z];
    }
}

static double shared_real(bw_data *S, const bw_instant *v, unsigned vr)
{
    switch (vr) {
    case BW_VR_ag: return S->ag;
    case BW_VR_energy: return energy_now(S, v);
    case BW_VR_work_ground: return S->x[0];
    case BW_VR_work_damping: return S->x[1];
    case BW_VR_der_work_ground: return v->p_ground;
    case BW_VR_der_work_damping: return v->p_damping;
    case BW_VR_event_losses: return S->losses;
    case BW_VR_energy_residual:
        return S->ready ? energy_now(S, v) - S->energy0 - (S->x[0] - S->x[1] - S->losses) : 0.0;
    default: return *bw_real_parameter(S, vr); /* the other shared Reals are parameters */
    }
}

static void get_real(void *M, int initializing, double time, const unsigned vr[], size_t n, double value[])
{
    bw_data *S = (bw_data *)M;
    rw_scene tmp;
    bw_instant v;
    size_t j;
    (void)initializing;
    (void)time;
    evaluate(S, &tmp, &v);
    for (j = 0; j < n; j++) {
        const int storey = BW_STOREY_OF(vr[j]), slot = BW_SLOT_OF(vr[j]);
        double *param = bw_real_parameter(S, vr[j]);
        if (storey && param) value[j] = *param;
        else if (storey) value[j] = storey_real(S, &v, storey - 1, slot);
        else value[j] = shared_real(S, &v, vr[j]);
    }
}

static void get_integer(void *M, int initializing, const unsigned vr[], size_t n, int value[])
{
    bw_data *S = (bw_data *)M;
    size_t j;
    (void)initializing;
    for (j = 0; j < n; j++) {
        int *param = bw_integer_parameter(S, vr[j]);
        const int i = BW_STOREY_OF(vr[j]) - 1;
        value[j] = param ? *param : (S->ready && i < S->sc.S.n_storeys ? (int)S->sc.impacts[i] : 0);
    }
}

static void get_boolean(void *M, const unsigned vr[], size_t n, int value[])
{
    bw_data *S = (bw_data *)M;
    size_t j;
    for (j = 0; j < n; j++) {
        const int i = BW_STOREY_OF(vr[j]) - 1; /* collapsed_i, the only Booleans */
        value[j] = S->ready && i < S->sc.S.n_storeys && S->sc.collapsed[i];
    }
}

static int set_real(void *M, unsigned vr, double value, char *msg, size_t n)
{
    bw_data *S = (bw_data *)M;
    const int storey = BW_STOREY_OF(vr), slot = BW_SLOT_OF(vr);
    if (vr == BW_VR_ag) {
        S->ag = value;
        return 0;
    }
    if (vr == BW_VR_work_ground || vr == BW_VR_work_damping) {
        S->x[vr == BW_VR_work_ground ? 0 : 1] = value;
        return 0;
    }
    if (storey && slot >= SLOT_STATE && slot < SLOT_RATE) { /* a state's start value */
        if ((slot == SLOT_STATE + RW_NX + BD_Z || slot == SLOT_STATE + RW_NX + BD_ZD) && !(fabs(value) <= 1.0)) {
            snprintf(msg, n, "the start value %g of a Bouc-Wen variable (storey %d) must lie in [-1, 1]", value, storey);
            return 1;
        }
        BLOCK(S->x, storey - 1)[slot - SLOT_STATE] = value;
        return 0;
    }
    return bw_set_real_parameter(S, vr, value, msg, n);
}

static int set_integer(void *M, unsigned vr, int value, char *msg, size_t n)
{
    return bw_set_integer_parameter((bw_data *)M, vr, value, msg, n);
}

static int exit_init(void *M, double time, const fmu_logger *log, char *msg, size_t n)
{
    bw_data *S = (bw_data *)M;
    rw_scene_spec spec;
    double xs[RW_SCENE_NX], start[RW_SCENE_NX];
    bw_instant v;
    S->log = log;
    S->time = time;
    bw_params_spec(S, &spec);
    if (rw_scene_validate(&spec, msg, n)) return 1;
    pack(spec.n_storeys, S->x, start);
    rw_scene_start_state(&spec, start, xs);
    rw_scene_init(&S->sc, &spec, S->ag, xs);
    unpack(spec.n_storeys, xs, S->x); /* the storeys above nStoreys at rest, the floors too if rigid */
    S->ready = 1;
    S->losses = 0.0;
    evaluate(S, NULL, &v);
    S->energy0 = energy_now(S, &v);
    return 0;
}

static void get_states(void *M, int initializing, double x[])
{
    (void)initializing;
    memcpy(x, ((bw_data *)M)->x, sizeof(double) * BW_NUMBER_OF_STATES);
}

static void set_states(void *M, const double x[]) { memcpy(((bw_data *)M)->x, x, sizeof(double) * BW_NUMBER_OF_STATES); }

static void derivatives(void *M, double dx[])
{
    bw_data *S = (bw_data *)M;
    rw_scene tmp;
    bw_instant v;
    memset(dx, 0, sizeof(double) * BW_NUMBER_OF_STATES);
    if (!evaluate(S, &tmp, &v)) return;
    unpack(v.sc->S.n_storeys, v.dxs, dx);
    dx[0] = v.p_ground;
    dx[1] = v.p_damping;
}

static void event_indicators(void *M, int initializing, double z[])
{
    bw_data *S = (bw_data *)M;
    rw_scene tmp;
    bw_instant v;
    int k;
    (void)initializing;
    for (k = 0; k < RW_SCENE_NZ; k++) z[k] = 1.0;
    if (evaluate(S, &tmp, &v)) rw_scene_indicators(v.sc, S->ag, v.xs, z);
}

static void nominals(double x[])
{
    int i;
    for (i = 0; i < RW_SCENE_MAX_STOREYS; i++) {
        double *b = BLOCK(x, i);
        b[0] = b[1] = 0.01; /* rotations of the order of 0.01 rad */
        b[2] = b[3] = 0.1;
        b[RW_NX + BD_U] = b[RW_NX + BD_Y] = 0.01;
        b[RW_NX + BD_V] = b[RW_NX + BD_W] = 0.1;
    }
}

static void log_collapse(bw_data *S, int i, double t)
{
    char buf[256];
    if (!S->log || !S->log->warning) return;
    snprintf(buf, sizeof buf, "the wall of storey %d collapsed at t = %.9g s (%s); it leaves the scene, the rest runs on",
             i + 1, t, S->sc.reason[i] == RW_PAST_INSTABILITY ? "past its instability point" : "past its toppling limit");
    S->log->warning(S->log->ctx, buf);
}

static void event_update(void *M, double time, const fmu_logger *log, fmu_event_result *r)
{
    bw_data *S = (bw_data *)M;
    int before[RW_SCENE_MAX_STOREYS], flags, i;
    bw_instant v;
    double energy_before;
    memset(r, 0, sizeof *r);
    S->log = log;
    S->time = time;
    if (!S->ready) return;
    evaluate(S, NULL, &v);
    energy_before = energy_now(S, &v);
    memcpy(before, S->sc.collapsed, sizeof before);
    flags = rw_scene_event_update(&S->sc, time, S->ag, v.xs, NULL);
    unpack(S->sc.S.n_storeys, v.xs, S->x);
    if (flags) {
        evaluate(S, NULL, &v);
        S->losses += energy_before - energy_now(S, &v);
    }
    for (i = 0; i < S->sc.S.n_storeys; i++)
        if (S->sc.collapsed[i] && !before[i]) log_collapse(S, i, time);
    r->states_changed = (flags & 1) != 0;
    r->more = (flags & 3) != 0; /* confirm at the same instant, as RockingWall does */
}

const fmu_model FMU_MODEL = {
    .identifier = BW_MODEL_IDENTIFIER,
    .guid = BW_GUID,
    .nx = BW_NUMBER_OF_STATES,
    .nz = BW_NUMBER_OF_EVENT_INDICATORS,
    .vars = VARS,
    .nvars = sizeof VARS / sizeof VARS[0],
    .z_vrs = Z_VRS,
    .data_size = sizeof(bw_data),
    .reset = reset,
    .get_real = get_real,
    .get_integer = get_integer,
    .get_boolean = get_boolean,
    .set_real = set_real,
    .set_integer = set_integer,
    .exit_init = exit_init,
    .get_states = get_states,
    .set_states = set_states,
    .derivatives = derivatives,
    .event_indicators = event_indicators,
    .nominals = nominals,
    .event_update = event_update,
};
