/* A scene: the rocking walls of a building with their diaphragms and floors, as one model (no FMI
 * types, no solver). docs/scenes.md states the equations.
 *
 * Storey i (0-based) holds an out-of-plane wall (optional) that stands on diaphragm i-1 (the ground
 * for i = 0) and is tied to diaphragm i by its top spring (the wall's parameter Kd is the tie's
 * stiffness, u_top the diaphragm's displacement relative to the wall's base). The diaphragms and
 * floors are the Building's physics (building_physics.h): floor i on the in-plane walls of storey
 * i, diaphragm i on its spring relative to floor i; with rigid in-plane walls the floors move with
 * the ground. Each wall keeps its own physics and event rules (rw_physics.h): the scene only
 * assembles them.
 *
 * The coupling through a wall's base is the one algebraic loop: the wall's rocking acceleration
 * depends on its base's acceleration, and the force it puts on its base on both. Both are affine
 * in the base acceleration a_b (q'' = q''_0 + beta a_b, F_base = phi + chi a_b), so the diaphragm
 * it stands on takes it as an added mass -chi: (md - chi) a_diaph = md a_diaph(F_above = phi). */
#ifndef RW_SCENE_H
#define RW_SCENE_H

#include "building_physics.h"
#include "rw_physics.h"

#define RW_SCENE_MAX_STOREYS BD_MAX_FLOORS
#define RW_SCENE_NX (RW_SCENE_MAX_STOREYS * (RW_NX + BD_STATES_PER_FLOOR))
#define RW_SCENE_NZ (RW_SCENE_MAX_STOREYS * RW_NZ)

typedef struct {
    int n_storeys;          /* 1..RW_SCENE_MAX_STOREYS */
    int rigid_in_plane;     /* the in-plane walls are rigid: every floor moves with the ground */
    bd_params building;     /* floors and diaphragms (its n_storeys is set from the scene's) */
    int has_wall[RW_SCENE_MAX_STOREYS];
    rw_params wall[RW_SCENE_MAX_STOREYS]; /* flexibleTop walls; Kd = the tie's stiffness */
} rw_scene_spec;

/* What the scene's walls are doing (the discrete state): each wall's regime and whether it has
 * collapsed; a collapsed wall leaves the scene (no more forces on the building, its states frozen). */
typedef struct {
    rw_scene_spec S;
    rw_derived D[RW_SCENE_MAX_STOREYS];
    rw_regime regime[RW_SCENE_MAX_STOREYS];
    int collapsed[RW_SCENE_MAX_STOREYS];
    int reason[RW_SCENE_MAX_STOREYS];
    double t_collapse[RW_SCENE_MAX_STOREYS];
    long impacts[RW_SCENE_MAX_STOREYS];
    int nx; /* states in use: 4 per storey (the wall's, zero without one) + the floor's 8 */
} rw_scene;

/* Quantities of one instant that outputs and the energy balance need, from rw_scene_derivatives. */
typedef struct {
    double a_base[RW_SCENE_MAX_STOREYS];  /* absolute acceleration of each wall's base */
    double a_diaph[RW_SCENE_MAX_STOREYS]; /* absolute acceleration of each diaphragm */
    double F_top[RW_SCENE_MAX_STOREYS];   /* tie force on diaphragm i, + toward +x */
    double F_base[RW_SCENE_MAX_STOREYS];  /* force wall i puts on its base, + toward +x */
} rw_scene_aux;

/* the wall states of storey i and the building's states inside the scene's state vector */
#define RW_SCENE_WALL(x, i) ((x) + RW_NX * (i))
#define RW_SCENE_BUILDING(sc, x) ((x) + RW_NX * (sc)->S.n_storeys)

/* Checks the spec (storey count, every wall's parameters, masses and springs): 0, or 1 with msg. */
int rw_scene_validate(const rw_scene_spec *spec, char *msg, size_t n);
/* The start state: x0 (NULL = rest) with the floors' displacements and velocities zero when the
 * in-plane walls are rigid (the floors move with the ground) */
void rw_scene_start_state(const rw_scene_spec *spec, const double *x0, double x[RW_SCENE_NX]);
/* Sets up the scene from a validated spec with the walls' start states in x (the rest zero):
 * derived data, the walls' initial regimes (from the start accelerations, at ag0). */
void rw_scene_init(rw_scene *sc, const rw_scene_spec *spec, double ag0, double x[RW_SCENE_NX]);

/* dx = f(x) under the ground acceleration ag; aux (may be NULL) the instant's forces and accelerations */
void rw_scene_derivatives(const rw_scene *sc, double ag, const double x[], double dx[], rw_scene_aux *aux);
/* The event indicators: RW_NZ per storey (1 for a storey without a standing wall, and for a
 * mid-height switch that is bookkeeping only) */
void rw_scene_indicators(const rw_scene *sc, double ag, const double x[], double z[]);
/* One event-mode update of every standing wall at time t: impacts, switches, collapse. Returns a
 * bit set: 1 states changed, 2 a regime changed, 4 a wall collapsed. dx (may be NULL): the rates
 * at the state it started from, which are the rates at the state it leaves where it returns 0. */
int rw_scene_event_update(rw_scene *sc, double t, double ag, double x[], double dx[]);

/* Energy of the scene with velocities relative to the ground (walls, their ties, floors,
 * diaphragms, the springs' work), and the powers that change it: the ground's work rate and the
 * viscous dissipation rate. */
double rw_scene_energy(const rw_scene *sc, double ag, const double x[]);
void rw_scene_powers(const rw_scene *sc, double ag, const double x[], double *p_ground, double *p_damping);

/* outputs of storey i */
double rw_scene_s1(const rw_scene *sc, const double x[], int i);
double rw_scene_s2(const rw_scene *sc, const double x[], int i);
double rw_scene_diaphragm_deformation(const rw_scene *sc, const double x[], int i);
/* the tie's force on diaphragm i, + toward +x (0 without a standing wall): the wall's top spring at
 * the state, as rw_scene_derivatives's aux.F_top */
double rw_scene_tie_force(const rw_scene *sc, const double x[], int i);

#endif
