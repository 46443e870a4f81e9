/* Bilinear diaphragms in the exact scene engine. The bilinear law (building_physics.h,
 * BD_BILINEAR: force alpha k d + (1 - alpha) Fy z, the hysteretic variable z following d / Dy on
 * the elastic branch and held at +-1 while yielding) is linear on each branch: on the elastic one
 * z = F0 + d / Dy and F = k d + F0 (1 - alpha) Fy (F0 fixed by where the branch was entered);
 * while yielding F = alpha k d +- (1 - alpha) Fy (F0 = +-1). So a branch is part of the region
 * (its key), and its ends are events: yield where z reaches +-1 on the elastic branch (indicators
 * 1 -+ z, affine in d), unloading where the deformation's rate changes sign while yielding. The
 * scene's state keeps z and the work done on the spring (which the scene's energy counts,
 * rw_scene_energy); a region does not advance them, so they are brought up to date from it before
 * the scene's own functions read the state. */
#include "rw_scene_exact_internal.h"

#include <math.h>

/* floor i's block of the scene state (its diaphragm's states among them) */
static const double *floor_states(const rw_scene *sc, const double x[], int i)
{
    return RW_SCENE_BUILDING(sc, x) + BD_STATES_PER_FLOOR * i;
}

static double *floor_states_to_set(const rw_scene *sc, double x[], int i)
{
    return RW_SCENE_BUILDING(sc, x) + BD_STATES_PER_FLOOR * i;
}

/* the hysteretic share of the yield force, (1 - alpha) Fy */
static double hysteretic_force(const bd_spring *s) { return (1.0 - s->alpha) * s->Fy; }

/* can the spring yield at all (alpha = 1 or no yield force: it is k d, as a linear one) */
static int yields(const bd_spring *s) { return hysteretic_force(s) > 0.0 && s->k > 0.0; }

int sx_bilinear(const rw_scene *sc, int i)
{
    (void)i; /* one law for every diaphragm */
    return sc->S.building.diaphragm_law == BD_BILINEAR;
}

void sx_bilinear_key(const rw_scene *sc, const double x[], const double dx[], int i, sx_key *key)
{
    const bd_spring *s = &sc->S.building.diaph[i];
    const double *f = floor_states(sc, x, i), *df = floor_states(sc, dx, i);
    const double d = f[BD_Y] - f[BD_U], du = f[BD_W] - f[BD_V], ddu = df[BD_W] - df[BD_V];
    const double z = f[BD_ZD];
    if (!yields(s)) return; /* the linear spring's key: the elastic branch, no constant */
    /* on a yield limit the motion a moment later picks the branch (as a wall's region) */
    key->branch[i] = bd_bilinear_branch(z, du + 1e-9 * ddu);
    key->F0[i] = key->branch[i] ? key->branch[i] : z - s->k * d / s->Fy; /* over (1 - alpha) Fy */
}

double sx_linear_stiffness(const rw_scene *sc, const sx_key *key, int i)
{
    const bd_spring *s = &sc->S.building.diaph[i];
    return key->branch[i] || sx_bouc_wen(sc, i) ? s->alpha * s->k : s->k;
}

void sx_sync_hysteresis(sx_run *R)
{
    const rw_scene *sc = &R->sc;
    const sx_key *key;
    int i;
    if (R->cur < 0) return;
    key = &R->regions[R->cur]->key;
    for (i = 0; i < sc->S.n_storeys; i++) {
        const bd_spring *s = &sc->S.building.diaph[i];
        double *f, d, d0, z;
        if (!sx_bilinear(sc, i) && !sx_bouc_wen(sc, i)) continue;
        f = floor_states_to_set(sc, R->x, i);
        d = f[BD_Y] - f[BD_U], d0 = R->d_synced[i];
        /* the work of F = k_b d + F0 (1 - alpha) Fy from d0 to d, without cancellation (the
         * scene's energy counts a hysteretic spring by it, whether or not it can yield) */
        f[BD_WORK_D] += (d - d0) * (0.5 * sx_linear_stiffness(sc, key, i) * (d + d0) + key->F0[i] * hysteretic_force(s));
        R->d_synced[i] = d;
        /* z does not enter its force; a Bouc-Wen spring's z and hysteretic work are its steps'
         * (rw_scene_exact_bouc_wen.c) */
        if (!sx_bilinear(sc, i) || !yields(s)) continue;
        z = key->branch[i] ? key->branch[i] : key->F0[i] + s->k * d / s->Fy;
        f[BD_ZD] = fmax(-1.0, fmin(1.0, z)); /* an event leaves z a rounding past its limit */
    }
}

void sx_bilinear_entered(sx_run *R)
{
    const rw_scene *sc = &R->sc;
    const sx_key *key = &R->regions[R->cur]->key;
    int i;
    for (i = 0; i < sc->S.n_storeys; i++) {
        const bd_spring *s = &sc->S.building.diaph[i];
        const double *f = floor_states(sc, R->x, i);
        sx_dline *L = R->dlines[i];
        R->ndlines[i] = 0;
        if (!sx_bilinear(sc, i) && !sx_bouc_wen(sc, i)) continue;
        R->d_synced[i] = f[BD_Y] - f[BD_U];
        if (!sx_bilinear(sc, i) || !yields(s)) continue;
        if (key->branch[i]) { /* yielding: until the deformation's rate changes sign */
            L[0] = (sx_dline){SX_DEFORM_RATE, 0.0, (double)key->branch[i]};
            R->ndlines[i] = 1;
            continue;
        }
        { /* elastic: 1 - z and 1 + z, z = F0 + d / Dy */
            const double z0 = key->F0[i], dz = s->k / s->Fy;
            L[0] = (sx_dline){SX_DEFORM, 1.0 - z0, -dz};
            L[1] = (sx_dline){SX_DEFORM, 1.0 + z0, dz};
            R->ndlines[i] = 2;
        }
    }
}
