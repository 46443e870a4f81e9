/* BuildingWithWalls: its parameters, bw_params.h. The walls' ranges are RockingWall's own
 * (rw_parameters.h), the building's the Building FMU's. */
#include "bw_params.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "bw_variables.h"

/* the RockingWall parameter a storey slot stands for (NULL: not a wall parameter) */
static const char *wall_parameter_name(int slot)
{
    switch (slot) {
    case 2: return "h";
    case 3: return "b";
    case 4: return "W";
    case 5: return "psi";
    case 6: return "Kd";
    case 7: return "er";
    case 8: return "hingeLaw";
    case 9: return "psiWeightOnly";
    case 49: return "eTop";
    default: return NULL;
    }
}

static const char *shared_wall_parameter_name(unsigned vr)
{
    switch (vr) {
    case BW_VR_g: return "g";
    case BW_VR_delta1Ratio: return "delta1Ratio";
    case BW_VR_delta2A: return "delta2A";
    case BW_VR_delta2B: return "delta2B";
    case BW_VR_hingeSat: return "hingeSat";
    case BW_VR_restRate: return "restRate";
    default: return NULL;
    }
}

static double *wall_field(rw_params *p, const char *name)
{
    const rw_param_info *info = rw_param_by_name(name);
    return info && !info->is_integer ? (double *)(void *)((char *)p + info->offset) : NULL;
}

double *bw_real_parameter(bw_data *S, unsigned vr)
{
    const int i = BW_STOREY_OF(vr) - 1, slot = BW_SLOT_OF(vr);
    bd_params *b = &S->spec.building;
    if (i < 0) {
        const char *name = shared_wall_parameter_name(vr);
        if (name) return wall_field(&S->shared, name);
        switch (vr) {
        case BW_VR_nBW: return &b->n_bw;
        case BW_VR_betaBW: return &b->beta;
        case BW_VR_pinchSize: return &b->pinch_size;
        case BW_VR_pinchWidth: return &b->pinch_width;
        case BW_VR_pinchCentre: return &b->pinch_centre;
        case BW_VR_rayleighMass: return &b->a0;
        case BW_VR_rayleighStiffness: return &b->a1;
        default: return NULL;
        }
    }
    if (i >= RW_SCENE_MAX_STOREYS) return NULL;
    if (slot != 8 && wall_parameter_name(slot)) return wall_field(&S->spec.wall[i], wall_parameter_name(slot));
    switch (slot) {
    case 10: return &b->md[i];
    case 11: return &b->diaph[i].k;
    case 12: return &S->zetad[i];
    case 13: return &b->diaph[i].Fy;
    case 14: return &b->diaph[i].alpha;
    case 15: return &b->m[i];
    case 16: return &b->storey[i].k;
    case 17: return &S->zetas[i];
    case 18: return &b->storey[i].Fy;
    case 19: return &b->storey[i].alpha;
    default: return NULL;
    }
}

int *bw_integer_parameter(bw_data *S, unsigned vr)
{
    const int i = BW_STOREY_OF(vr) - 1, slot = BW_SLOT_OF(vr);
    switch (vr) {
    case BW_VR_nStoreys: return &S->spec.n_storeys;
    case BW_VR_rigidInPlane: return &S->spec.rigid_in_plane;
    case BW_VR_storeyLaw: return &S->spec.building.storey_law;
    case BW_VR_diaphragmLaw: return &S->spec.building.diaphragm_law;
    default: break;
    }
    if (i < 0 || i >= RW_SCENE_MAX_STOREYS) return NULL;
    if (slot == 1) return &S->spec.has_wall[i];
    if (slot == 8) return &S->spec.wall[i].hingeLaw;
    return NULL;
}

static const char *name_of(unsigned vr)
{
#define BW_NAME(ID, VR, NAME, TYPE, CAUS, VARIAB, INIT, START, UNIT, NOM, DER, DESC) \
    if (vr == VR) return NAME;
    BW_VARIABLES(BW_NAME)
#undef BW_NAME
    return "?";
}

static int out_of(const char *name, double value, double lo, double hi, int lo_open, char *msg, size_t n)
{
    if ((lo_open ? value > lo : value >= lo) && value <= hi) return 0;
    snprintf(msg, n, "%s = %g is out of its range %s%g, %g]", name, value, lo_open ? "(" : "[", lo, hi);
    return 1;
}

/* the range of a building parameter (not a wall's): Building FMU's */
static int check_building(unsigned vr, double v, char *msg, size_t n)
{
    const char *name = name_of(vr);
    if (BW_STOREY_OF(vr) == 0) {
        switch (vr) {
        case BW_VR_nBW: return out_of(name, v, 1.0, 100.0, 0, msg, n);
        case BW_VR_betaBW: return out_of(name, v, 0.0, 1.0, 0, msg, n);
        case BW_VR_pinchSize:
        case BW_VR_pinchCentre: return out_of(name, v, 0.0, 0.99, 0, msg, n);
        case BW_VR_pinchWidth: return out_of(name, v, 0.01, 10.0, 0, msg, n);
        case BW_VR_rayleighMass: return out_of(name, v, 0.0, 1e3, 0, msg, n);
        default: return out_of(name, v, 0.0, 1.0, 0, msg, n); /* rayleighStiffness */
        }
    }
    switch (BW_SLOT_OF(vr)) {
    case 10:
    case 15: return out_of(name, v, 0.0, 1e9, 1, msg, n);  /* masses */
    case 11: return out_of(name, v, 0.0, 1e15, 0, msg, n); /* kd: 0 is a diaphragm held by its ties only */
    case 16:
    case 13:
    case 18: return out_of(name, v, 0.0, 1e15, 1, msg, n);
    case 12:
    case 17: return out_of(name, v, 0.0, 2.0, 0, msg, n);  /* damping ratios */
    default: return out_of(name, v, 0.0, 1.0, 0, msg, n);  /* post-yield ratios */
    }
}

int bw_set_real_parameter(bw_data *S, unsigned vr, double value, char *msg, size_t n)
{
    const int storey = BW_STOREY_OF(vr);
    const char *wall = storey ? wall_parameter_name(BW_SLOT_OF(vr)) : shared_wall_parameter_name(vr);
    double *field = bw_real_parameter(S, vr);
    if (!field) {
        snprintf(msg, n, "value reference %u is not a settable Real", vr);
        return 1;
    }
    if (wall) {
        char why[256];
        if (rw_param_check(rw_param_by_name(wall), value, why, sizeof why)) {
            snprintf(msg, n, "%s: %s", name_of(vr), why);
            return 1;
        }
    } else if (check_building(vr, value, msg, n)) {
        return 1;
    }
    *field = value;
    return 0;
}

int bw_set_integer_parameter(bw_data *S, unsigned vr, int value, char *msg, size_t n)
{
    int *field = bw_integer_parameter(S, vr), lo = 0, hi = 1;
    if (!field) {
        snprintf(msg, n, "value reference %u is not a settable Integer", vr);
        return 1;
    }
    if (vr == BW_VR_storeyLaw || vr == BW_VR_diaphragmLaw) {
        if (!bd_law_allowed(value, vr == BW_VR_storeyLaw)) {
            snprintf(msg, n, "%s = %d is not one of its laws (%s)", name_of(vr), value,
                     vr == BW_VR_storeyLaw ? BD_STOREY_LAWS_TEXT : BD_DIAPHRAGM_LAWS_TEXT);
            return 1;
        }
        *field = value;
        return 0;
    }
    if (vr == BW_VR_nStoreys) lo = 1, hi = RW_SCENE_MAX_STOREYS;
    else if (BW_SLOT_OF(vr) == 8 && BW_STOREY_OF(vr)) lo = RW_RIGID, hi = RW_DOHERTY_HINGE;
    if (value < lo || value > hi) {
        snprintf(msg, n, "%s = %d is out of its range [%d, %d]", name_of(vr), value, lo, hi);
        return 1;
    }
    *field = value;
    return 0;
}

void bw_params_reset(bw_data *S)
{
    int i;
    memset(S, 0, sizeof *S);
    rw_params_default(&S->shared);
    for (i = 0; i < RW_SCENE_MAX_STOREYS; i++) rw_params_default(&S->spec.wall[i]);
#define BW_START(ID, VR, NAME, TYPE, CAUS, VARIAB, INIT, START, UNIT, NOM, DER, DESC) \
    if (strcmp(CAUS, "parameter") == 0) {                                          \
        double *r = bw_real_parameter(S, VR);                                      \
        int *k = bw_integer_parameter(S, VR);                                      \
        if (r) *r = START;                                                         \
        if (k) *k = (int)(START);                                                  \
    }
    BW_VARIABLES(BW_START)
#undef BW_START
}

void bw_params_spec(const bw_data *S, rw_scene_spec *spec)
{
    int i;
    *spec = S->spec;
    spec->building.n_storeys = spec->n_storeys;
    for (i = 0; i < RW_SCENE_MAX_STOREYS; i++) {
        rw_params *w = &spec->wall[i];
        bd_params *b = &spec->building;
        w->support = RW_FLEXIBLE_TOP;
        w->g = S->shared.g;
        w->delta1Ratio = S->shared.delta1Ratio;
        w->delta2A = S->shared.delta2A;
        w->delta2B = S->shared.delta2B;
        w->hingeSat = S->shared.hingeSat;
        w->restRate = S->shared.restRate;
        b->cd[i] = 2.0 * S->zetad[i] * sqrt(b->diaph[i].k * b->md[i]);
        b->cs[i] = 2.0 * S->zetas[i] * sqrt(b->storey[i].k * b->m[i]);
        if (i >= spec->n_storeys) spec->has_wall[i] = 0;
    }
}
