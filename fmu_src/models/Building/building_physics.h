/* Building physics (no FMI types): an in-plane building of N storeys, per metre of out-of-plane
 * wall, as a chain of masses (docs/building.md):
 *
 *   floor i (the in-plane walls' level, mass m_i) on the storey spring i (the in-plane walls of
 *   storey i, between floor i-1 and floor i; floor 0 is the ground), and
 *   diaphragm i (mass md_i) on a spring relative to floor i; the out-of-plane walls' forces act
 *   on diaphragm i: F_wall_i (the top spring of the wall below) and F_above_i (the base of the
 *   wall standing on floor i), two inputs so that each takes one connection (SSP).
 *
 * Displacements relative to the ground; the ground acceleration ag enters as -m ag. Each spring is
 * linear, Bouc-Wen or bilinear (the hysteretic variable a continuous state, no events), the
 * diaphragms optionally Bouc-Wen with Foliente's pinching function; Rayleigh damping
 * C = a0 M + a1 K0, and a dashpot beside each spring (cs, cd: the scenes' damping ratios; the
 * Building FMU leaves them 0). */
#ifndef BUILDING_PHYSICS_H
#define BUILDING_PHYSICS_H

#include <stddef.h>

#include "fmu_symbol.h"

#define BD_MAX_FLOORS 5
#define BD_STATES_PER_FLOOR 8
#define BD_NX (BD_MAX_FLOORS * BD_STATES_PER_FLOOR)

/* offsets of a floor's states in its block of the state vector */
enum { BD_U = 0, BD_V, BD_Z, BD_Y, BD_W, BD_ZD, BD_WORK_S, BD_WORK_D };

/* spring laws (BD_BILINEAR: elastoplastic with kinematic hardening, docs/building.md) */
enum { BD_ELASTIC = 0, BD_BOUC_WEN = 1, BD_BOUC_WEN_PINCHED = 2, BD_BILINEAR = 3 };
/* the laws a diaphragm takes (all of them) and a storey takes (all but the pinching, a timber
 * diaphragm's), as the messages that refuse a law list them */
#define BD_LAST_LAW BD_BILINEAR
#define BD_DIAPHRAGM_LAWS_TEXT "0 linear, 1 Bouc-Wen, 2 Bouc-Wen with pinching, 3 bilinear"
#define BD_STOREY_LAWS_TEXT "0 linear, 1 Bouc-Wen, 3 bilinear"

/* The bilinear law's branch at the normalised hysteretic variable z and the deformation rate du:
 * +1 or -1 yielding (|z| at 1 and loading on: z stays), 0 elastic (z follows du / Dy; at du = 0 z
 * stays either way). The law's rate (bd_hysteretic_rate) and the exact scene engine's regions
 * (its branches) both take it from here. */
static inline int bd_bilinear_branch(double z, double du)
{
    if (z >= 1.0 && du > 0.0) return 1;
    if (z <= -1.0 && du < 0.0) return -1;
    return 0;
}

/* one spring: initial stiffness k, yield force Fy, post-yield ratio alpha */
typedef struct {
    double k, Fy, alpha;
} bd_spring;

typedef struct {
    int n_storeys, storey_law, diaphragm_law;
    double n_bw, beta;                                /* Bouc-Wen exponent and beta (gamma = 1 - beta) */
    double pinch_size, pinch_width, pinch_centre;     /* Foliente's zeta1, zeta2, q */
    double a0, a1;                                    /* Rayleigh: C = a0 M + a1 K0 */
    double cs[BD_MAX_FLOORS], cd[BD_MAX_FLOORS];      /* dashpots beside the storey and diaphragm springs */
    double m[BD_MAX_FLOORS], md[BD_MAX_FLOORS];       /* floor and diaphragm masses */
    bd_spring storey[BD_MAX_FLOORS], diaph[BD_MAX_FLOORS];
} bd_params;

typedef struct {
    double ag;
    double F_wall[BD_MAX_FLOORS];  /* the wall below's F_top */
    double F_above[BD_MAX_FLOORS]; /* the wall above's F_base */
} bd_input;

/* external names (prefixed under FMI2_FUNCTION_PREFIX, see fmu_symbol.h) */
#define bd_derivatives FMU_SYMBOL(bd_derivatives)
#define bd_storey_force FMU_SYMBOL(bd_storey_force)
#define bd_diaphragm_force FMU_SYMBOL(bd_diaphragm_force)
#define bd_drift FMU_SYMBOL(bd_drift)
#define bd_diaphragm_deformation FMU_SYMBOL(bd_diaphragm_deformation)
#define bd_hysteretic_rate FMU_SYMBOL(bd_hysteretic_rate)
#define bd_diaphragm_acceleration FMU_SYMBOL(bd_diaphragm_acceleration)
#define bd_law_allowed FMU_SYMBOL(bd_law_allowed)

/* 1 if a storey's spring (storey = 1) or a diaphragm's (storey = 0) takes the law, else 0 */
int bd_law_allowed(int law, int storey);

/* dx = f(x) for the whole state vector; the floors above n_storeys stay at rest (dx = 0) */
void bd_derivatives(const bd_params *p, const bd_input *in, const double x[BD_NX], double dx[BD_NX]);

/* storey i (0-based): drift u_i - u_{i-1} and spring force (without damping) */
double bd_drift(const double x[BD_NX], int i);
double bd_storey_force(const bd_params *p, const double x[BD_NX], int i);
/* diaphragm i: deformation y_i - u_i and spring force (without damping) */
double bd_diaphragm_deformation(const double x[BD_NX], int i);
double bd_diaphragm_force(const bd_params *p, const double x[BD_NX], int i);

/* absolute acceleration of diaphragm i (ag + its acceleration relative to the ground) */
double bd_diaphragm_acceleration(const bd_params *p, const bd_input *in, const double x[BD_NX], int i);

/* Rate of the normalised hysteretic variable z (|z| <= 1) of a spring under deformation rate du,
 * Dy = Fy/k. Bouc-Wen: dz/dt = h(z, du) du/Dy [1 - |z|^n (beta sgn(du z) + gamma)], h = 1 or
 * Foliente's pinching function. Bilinear: du/Dy while elastic (|z| < 1, or unloading, z du < 0),
 * 0 while yielding (|z| >= 1, z du >= 0: bd_bilinear_branch). 0 for the elastic law. */
double bd_hysteretic_rate(const bd_params *p, int law, const bd_spring *s, double z, double du);

#endif
