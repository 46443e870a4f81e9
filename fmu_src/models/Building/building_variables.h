/* Building: the one source of truth for the Building FMU's variables (same format as
 * fmu_src/models/RockingWall/model_variables.h; scripts/gen_model_description.py generates
 * fmu_src/models/Building/fmi2/modelDescription.xml from it). Every quantity is per metre of out-of-plane wall,
 * as RockingWall's: masses kg/m, stiffnesses N/m per m, forces N/m.
 *
 * Value references: the shared parameters and ag below 100; floor i (1..5) uses 100*i + k with the
 * same k for every floor (BD_FLOOR_OF, BD_SLOT_OF), so the model decodes floor and quantity.
 * The states of floor i, in the order of the state vector: u_floor, v_floor, z_storey, u_diaph,
 * v_diaph, z_diaph, work_storey, work_diaph (slots 20..27; their derivatives 21, 31, 32, 24, 34,
 * 35, 36, 37).
 *
 * X(ID, VR, NAME, TYPE, CAUSALITY, VARIABILITY, INITIAL, START, UNIT, NOMINAL, DERIVATIVE_OF, DESCRIPTION) */
#ifndef BUILDING_VARIABLES_H
#define BUILDING_VARIABLES_H

#define BD_MODEL_IDENTIFIER "Building"
#define BD_GUID "{3b7c1e2d-9a4f-4c6b-8e15-2f0d7a9c4b63}"
#define BD_NUMBER_OF_STATES 40
#define BD_NUMBER_OF_EVENT_INDICATORS 0

#define BD_FLOOR_OF(vr) ((vr) / 100)
#define BD_SLOT_OF(vr) ((vr) % 100)

/* clang-format off */
#define BD_VARIABLES(X) \
X(nStoreys, 1, "nStoreys", Integer, "parameter", "fixed", "exact", 2, "", 0, 0, "Number of storeys N, 1..5 (floors above N are held at rest, their outputs 0)") \
X(storeyLaw, 2, "storeyLaw", Integer, "parameter", "fixed", "exact", 1, "", 0, 0, "Storey shear springs (in-plane walls): 0 linear elastic, 1 Bouc-Wen, 3 bilinear (elastoplastic, kinematic hardening)") \
X(diaphragmLaw, 3, "diaphragmLaw", Integer, "parameter", "fixed", "exact", 1, "", 0, 0, "Diaphragm springs: 0 linear elastic, 1 Bouc-Wen, 2 Bouc-Wen with Foliente's pinching (timber), 3 bilinear (elastoplastic, kinematic hardening)") \
X(nBW, 4, "nBW", Real, "parameter", "fixed", "exact", 2, "1", 0, 0, "Bouc-Wen exponent n, in [1, 100] (large n: sharp, elastoplastic-like yield)") \
X(betaBW, 5, "betaBW", Real, "parameter", "fixed", "exact", 0.5, "1", 0, 0, "Bouc-Wen beta, in [0, 1]; gamma = 1 - beta so that the hysteretic force saturates at the yield force") \
X(pinchSize, 6, "pinchSize", Real, "parameter", "fixed", "exact", 0.8, "1", 0, 0, "Pinching: zeta1 of Foliente's pinching function, in [0, 0.99] (diaphragmLaw 2)") \
X(pinchWidth, 7, "pinchWidth", Real, "parameter", "fixed", "exact", 0.2, "1", 0, 0, "Pinching: zeta2, the spread of the pinched region in z/z_u, in [0.01, 10] (diaphragmLaw 2)") \
X(pinchCentre, 8, "pinchCentre", Real, "parameter", "fixed", "exact", 0.1, "1", 0, 0, "Pinching: q, the centre of the pinched region in z/z_u, in [0, 0.99] (diaphragmLaw 2)") \
X(rayleighMass, 9, "rayleighMass", Real, "parameter", "fixed", "exact", 1.0, "1/s", 0, 0, "Rayleigh damping coefficient a0 of C = a0 M + a1 K0, >= 0 (damping ratio a0/(2 omega) + a1 omega/2)") \
X(rayleighStiffness, 10, "rayleighStiffness", Real, "parameter", "fixed", "exact", 0.001, "s", 0, 0, "Rayleigh damping coefficient a1 of C = a0 M + a1 K0 (K0: initial stiffness), >= 0") \
X(ag, 20, "ag", Real, "input", "continuous", "", 0, "m/s2", 0, 0, "Ground acceleration, positive toward +x") \
X(m_1, 101, "m_1", Real, "parameter", "fixed", "exact", 4000, "kg/m", 0, 0, "Mass of floor 1 at the in-plane walls per metre of out-of-plane wall (> 0)") \
X(k_1, 102, "k_1", Real, "parameter", "fixed", "exact", 20000000.0, "N/m2", 0, 0, "Initial stiffness of storey 1 (its in-plane walls), N/m per m (> 0)") \
X(Fy_1, 103, "Fy_1", Real, "parameter", "fixed", "exact", 30000.0, "N/m", 0, 0, "Yield force of storey 1 (> 0)") \
X(alpha_1, 104, "alpha_1", Real, "parameter", "fixed", "exact", 0.05, "1", 0, 0, "Post-yield stiffness ratio of storey 1, in [0, 1]") \
X(md_1, 105, "md_1", Real, "parameter", "fixed", "exact", 2000, "kg/m", 0, 0, "Mass of diaphragm 1 per metre of out-of-plane wall (> 0)") \
X(kd_1, 106, "kd_1", Real, "parameter", "fixed", "exact", 700000.0, "N/m2", 0, 0, "Initial stiffness of diaphragm 1 relative to its floor, N/m per m (> 0)") \
X(Fyd_1, 107, "Fyd_1", Real, "parameter", "fixed", "exact", 10000.0, "N/m", 0, 0, "Yield force of diaphragm 1 (> 0)") \
X(alphad_1, 108, "alphad_1", Real, "parameter", "fixed", "exact", 0.1, "1", 0, 0, "Post-yield stiffness ratio of diaphragm 1, in [0, 1]") \
X(cs_1, 112, "cs_1", Real, "parameter", "fixed", "exact", 0, "N.s/m2", 0, 0, "Dashpot beside storey 1's spring (in-plane walls), N s/m per m (>= 0; 0: Rayleigh damping only)") \
X(cd_1, 113, "cd_1", Real, "parameter", "fixed", "exact", 0, "N.s/m2", 0, 0, "Dashpot beside diaphragm 1's spring, N s/m per m (>= 0; a damping ratio zeta on its own spring and mass: 2 zeta sqrt(kd md))") \
X(F_wall_1, 110, "F_wall_1", Real, "input", "continuous", "", 0, "N/m", 0, 0, "Horizontal force on diaphragm 1 of the top spring of the out-of-plane wall below it, +x (RockingWall F_top)") \
X(F_above_1, 111, "F_above_1", Real, "input", "continuous", "", 0, "N/m", 0, 0, "Horizontal force on diaphragm 1 of the base of the out-of-plane wall standing on floor 1, +x (RockingWall F_base)") \
X(u_floor_1, 120, "u_floor_1", Real, "local", "continuous", "exact", 0, "m", 0.01, 0, "Displacement of floor 1 (in-plane walls' level) relative to the ground (state)") \
X(v_floor_1, 121, "v_floor_1", Real, "local", "continuous", "exact", 0, "m/s", 0.1, 120, "Velocity of floor 1 relative to the ground (state, der(u_floor_1))") \
X(der_v_floor_1, 131, "der(v_floor_1)", Real, "local", "continuous", "calculated", 0, "m/s2", 0, 121, "Acceleration of floor 1 relative to the ground") \
X(z_storey_1, 122, "z_storey_1", Real, "local", "continuous", "exact", 0, "1", 1, 0, "Hysteretic variable (Bouc-Wen, bilinear) of storey 1, z/z_u in [-1, 1] (state)") \
X(der_z_storey_1, 132, "der(z_storey_1)", Real, "local", "continuous", "calculated", 0, "1/s", 0, 122, "Rate of z_storey_1") \
X(u_diaph_1, 123, "u_diaph_1", Real, "output", "continuous", "exact", 0, "m", 0.01, 0, "Displacement of diaphragm 1 relative to the ground (state)") \
X(v_diaph_1, 124, "v_diaph_1", Real, "local", "continuous", "exact", 0, "m/s", 0.1, 123, "Velocity of diaphragm 1 relative to the ground (state, der(u_diaph_1))") \
X(der_v_diaph_1, 134, "der(v_diaph_1)", Real, "local", "continuous", "calculated", 0, "m/s2", 0, 124, "Acceleration of diaphragm 1 relative to the ground") \
X(z_diaph_1, 125, "z_diaph_1", Real, "local", "continuous", "exact", 0, "1", 1, 0, "Hysteretic variable (Bouc-Wen, bilinear) of diaphragm 1, z/z_u in [-1, 1] (state)") \
X(der_z_diaph_1, 135, "der(z_diaph_1)", Real, "local", "continuous", "calculated", 0, "1/s", 0, 125, "Rate of z_diaph_1") \
X(work_storey_1, 126, "work_storey_1", Real, "output", "continuous", "exact", 0, "J/m", 0, 0, "Work of storey 1's spring force on its drift, integral of V_storey_1 d(drift_1) (state; per closed cycle: the energy dissipated by hysteresis)") \
X(der_work_storey_1, 136, "der(work_storey_1)", Real, "local", "continuous", "calculated", 0, "W/m", 0, 126, "Power V_storey_1 * der(drift_1)") \
X(work_diaph_1, 127, "work_diaph_1", Real, "output", "continuous", "exact", 0, "J/m", 0, 0, "Work of diaphragm 1's spring force on its deformation, integral of F_diaph_1 d(d_diaph_1) (state)") \
X(der_work_diaph_1, 137, "der(work_diaph_1)", Real, "local", "continuous", "calculated", 0, "W/m", 0, 127, "Power F_diaph_1 * der(d_diaph_1)") \
X(a_diaph_1, 140, "a_diaph_1", Real, "output", "continuous", "calculated", 0, "m/s2", 0, 0, "Absolute acceleration of diaphragm 1 (ag + der(v_diaph_1)): the ground motion of a wall standing on floor 1") \
X(u_top_1, 141, "u_top_1", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Displacement of diaphragm 1 relative to diaphragm 0 (the ground for 1): u_top of a wall in storey 1") \
X(V_storey_1, 142, "V_storey_1", Real, "output", "continuous", "calculated", 0, "N/m", 0, 0, "Spring (hysteretic) shear force of storey 1, without damping: positive for positive drift, it pulls floor 1 toward -x and the floor below toward +x") \
X(drift_1, 143, "drift_1", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Storey drift u_floor_1 - u_floor_0") \
X(F_diaph_1, 144, "F_diaph_1", Real, "output", "continuous", "calculated", 0, "N/m", 0, 0, "Spring force of diaphragm 1 (without damping) for its deformation d_diaph_1") \
X(d_diaph_1, 145, "d_diaph_1", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Deformation of diaphragm 1: u_diaph_1 - u_floor_1") \
X(m_2, 201, "m_2", Real, "parameter", "fixed", "exact", 4000, "kg/m", 0, 0, "Mass of floor 2 at the in-plane walls per metre of out-of-plane wall (> 0)") \
X(k_2, 202, "k_2", Real, "parameter", "fixed", "exact", 20000000.0, "N/m2", 0, 0, "Initial stiffness of storey 2 (its in-plane walls), N/m per m (> 0)") \
X(Fy_2, 203, "Fy_2", Real, "parameter", "fixed", "exact", 30000.0, "N/m", 0, 0, "Yield force of storey 2 (> 0)") \
X(alpha_2, 204, "alpha_2", Real, "parameter", "fixed", "exact", 0.05, "1", 0, 0, "Post-yield stiffness ratio of storey 2, in [0, 1]") \
X(md_2, 205, "md_2", Real, "parameter", "fixed", "exact", 2000, "kg/m", 0, 0, "Mass of diaphragm 2 per metre of out-of-plane wall (> 0)") \
X(kd_2, 206, "kd_2", Real, "parameter", "fixed", "exact", 700000.0, "N/m2", 0, 0, "Initial stiffness of diaphragm 2 relative to its floor, N/m per m (> 0)") \
X(Fyd_2, 207, "Fyd_2", Real, "parameter", "fixed", "exact", 10000.0, "N/m", 0, 0, "Yield force of diaphragm 2 (> 0)") \
X(alphad_2, 208, "alphad_2", Real, "parameter", "fixed", "exact", 0.1, "1", 0, 0, "Post-yield stiffness ratio of diaphragm 2, in [0, 1]") \
X(cs_2, 212, "cs_2", Real, "parameter", "fixed", "exact", 0, "N.s/m2", 0, 0, "Dashpot beside storey 2's spring (in-plane walls), N s/m per m (>= 0; 0: Rayleigh damping only)") \
X(cd_2, 213, "cd_2", Real, "parameter", "fixed", "exact", 0, "N.s/m2", 0, 0, "Dashpot beside diaphragm 2's spring, N s/m per m (>= 0; a damping ratio zeta on its own spring and mass: 2 zeta sqrt(kd md))") \
X(F_wall_2, 210, "F_wall_2", Real, "input", "continuous", "", 0, "N/m", 0, 0, "Horizontal force on diaphragm 2 of the top spring of the out-of-plane wall below it, +x (RockingWall F_top)") \
X(F_above_2, 211, "F_above_2", Real, "input", "continuous", "", 0, "N/m", 0, 0, "Horizontal force on diaphragm 2 of the base of the out-of-plane wall standing on floor 2, +x (RockingWall F_base)") \
X(u_floor_2, 220, "u_floor_2", Real, "local", "continuous", "exact", 0, "m", 0.01, 0, "Displacement of floor 2 (in-plane walls' level) relative to the ground (state)") \
X(v_floor_2, 221, "v_floor_2", Real, "local", "continuous", "exact", 0, "m/s", 0.1, 220, "Velocity of floor 2 relative to the ground (state, der(u_floor_2))") \
X(der_v_floor_2, 231, "der(v_floor_2)", Real, "local", "continuous", "calculated", 0, "m/s2", 0, 221, "Acceleration of floor 2 relative to the ground") \
X(z_storey_2, 222, "z_storey_2", Real, "local", "continuous", "exact", 0, "1", 1, 0, "Hysteretic variable (Bouc-Wen, bilinear) of storey 2, z/z_u in [-1, 1] (state)") \
X(der_z_storey_2, 232, "der(z_storey_2)", Real, "local", "continuous", "calculated", 0, "1/s", 0, 222, "Rate of z_storey_2") \
X(u_diaph_2, 223, "u_diaph_2", Real, "output", "continuous", "exact", 0, "m", 0.01, 0, "Displacement of diaphragm 2 relative to the ground (state)") \
X(v_diaph_2, 224, "v_diaph_2", Real, "local", "continuous", "exact", 0, "m/s", 0.1, 223, "Velocity of diaphragm 2 relative to the ground (state, der(u_diaph_2))") \
X(der_v_diaph_2, 234, "der(v_diaph_2)", Real, "local", "continuous", "calculated", 0, "m/s2", 0, 224, "Acceleration of diaphragm 2 relative to the ground") \
X(z_diaph_2, 225, "z_diaph_2", Real, "local", "continuous", "exact", 0, "1", 1, 0, "Hysteretic variable (Bouc-Wen, bilinear) of diaphragm 2, z/z_u in [-1, 1] (state)") \
X(der_z_diaph_2, 235, "der(z_diaph_2)", Real, "local", "continuous", "calculated", 0, "1/s", 0, 225, "Rate of z_diaph_2") \
X(work_storey_2, 226, "work_storey_2", Real, "output", "continuous", "exact", 0, "J/m", 0, 0, "Work of storey 2's spring force on its drift, integral of V_storey_2 d(drift_2) (state; per closed cycle: the energy dissipated by hysteresis)") \
X(der_work_storey_2, 236, "der(work_storey_2)", Real, "local", "continuous", "calculated", 0, "W/m", 0, 226, "Power V_storey_2 * der(drift_2)") \
X(work_diaph_2, 227, "work_diaph_2", Real, "output", "continuous", "exact", 0, "J/m", 0, 0, "Work of diaphragm 2's spring force on its deformation, integral of F_diaph_2 d(d_diaph_2) (state)") \
X(der_work_diaph_2, 237, "der(work_diaph_2)", Real, "local", "continuous", "calculated", 0, "W/m", 0, 227, "Power F_diaph_2 * der(d_diaph_2)") \
X(a_diaph_2, 240, "a_diaph_2", Real, "output", "continuous", "calculated", 0, "m/s2", 0, 0, "Absolute acceleration of diaphragm 2 (ag + der(v_diaph_2)): the ground motion of a wall standing on floor 2") \
X(u_top_2, 241, "u_top_2", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Displacement of diaphragm 2 relative to diaphragm 1 (the ground for 1): u_top of a wall in storey 2") \
X(V_storey_2, 242, "V_storey_2", Real, "output", "continuous", "calculated", 0, "N/m", 0, 0, "Spring (hysteretic) shear force of storey 2, without damping: positive for positive drift, it pulls floor 2 toward -x and the floor below toward +x") \
X(drift_2, 243, "drift_2", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Storey drift u_floor_2 - u_floor_1") \
X(F_diaph_2, 244, "F_diaph_2", Real, "output", "continuous", "calculated", 0, "N/m", 0, 0, "Spring force of diaphragm 2 (without damping) for its deformation d_diaph_2") \
X(d_diaph_2, 245, "d_diaph_2", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Deformation of diaphragm 2: u_diaph_2 - u_floor_2") \
X(m_3, 301, "m_3", Real, "parameter", "fixed", "exact", 4000, "kg/m", 0, 0, "Mass of floor 3 at the in-plane walls per metre of out-of-plane wall (> 0)") \
X(k_3, 302, "k_3", Real, "parameter", "fixed", "exact", 20000000.0, "N/m2", 0, 0, "Initial stiffness of storey 3 (its in-plane walls), N/m per m (> 0)") \
X(Fy_3, 303, "Fy_3", Real, "parameter", "fixed", "exact", 30000.0, "N/m", 0, 0, "Yield force of storey 3 (> 0)") \
X(alpha_3, 304, "alpha_3", Real, "parameter", "fixed", "exact", 0.05, "1", 0, 0, "Post-yield stiffness ratio of storey 3, in [0, 1]") \
X(md_3, 305, "md_3", Real, "parameter", "fixed", "exact", 2000, "kg/m", 0, 0, "Mass of diaphragm 3 per metre of out-of-plane wall (> 0)") \
X(kd_3, 306, "kd_3", Real, "parameter", "fixed", "exact", 700000.0, "N/m2", 0, 0, "Initial stiffness of diaphragm 3 relative to its floor, N/m per m (> 0)") \
X(Fyd_3, 307, "Fyd_3", Real, "parameter", "fixed", "exact", 10000.0, "N/m", 0, 0, "Yield force of diaphragm 3 (> 0)") \
X(alphad_3, 308, "alphad_3", Real, "parameter", "fixed", "exact", 0.1, "1", 0, 0, "Post-yield stiffness ratio of diaphragm 3, in [0, 1]") \
X(cs_3, 312, "cs_3", Real, "parameter", "fixed", "exact", 0, "N.s/m2", 0, 0, "Dashpot beside storey 3's spring (in-plane walls), N s/m per m (>= 0; 0: Rayleigh damping only)") \
X(cd_3, 313, "cd_3", Real, "parameter", "fixed", "exact", 0, "N.s/m2", 0, 0, "Dashpot beside diaphragm 3's spring, N s/m per m (>= 0; a damping ratio zeta on its own spring and mass: 2 zeta sqrt(kd md))") \
X(F_wall_3, 310, "F_wall_3", Real, "input", "continuous", "", 0, "N/m", 0, 0, "Horizontal force on diaphragm 3 of the top spring of the out-of-plane wall below it, +x (RockingWall F_top)") \
X(F_above_3, 311, "F_above_3", Real, "input", "continuous", "", 0, "N/m", 0, 0, "Horizontal force on diaphragm 3 of the base of the out-of-plane wall standing on floor 3, +x (RockingWall F_base)") \
X(u_floor_3, 320, "u_floor_3", Real, "local", "continuous", "exact", 0, "m", 0.01, 0, "Displacement of floor 3 (in-plane walls' level) relative to the ground (state)") \
X(v_floor_3, 321, "v_floor_3", Real, "local", "continuous", "exact", 0, "m/s", 0.1, 320, "Velocity of floor 3 relative to the ground (state, der(u_floor_3))") \
X(der_v_floor_3, 331, "der(v_floor_3)", Real, "local", "continuous", "calculated", 0, "m/s2", 0, 321, "Acceleration of floor 3 relative to the ground") \
X(z_storey_3, 322, "z_storey_3", Real, "local", "continuous", "exact", 0, "1", 1, 0, "Hysteretic variable (Bouc-Wen, bilinear) of storey 3, z/z_u in [-1, 1] (state)") \
X(der_z_storey_3, 332, "der(z_storey_3)", Real, "local", "continuous", "calculated", 0, "1/s", 0, 322, "Rate of z_storey_3") \
X(u_diaph_3, 323, "u_diaph_3", Real, "output", "continuous", "exact", 0, "m", 0.01, 0, "Displacement of diaphragm 3 relative to the ground (state)") \
X(v_diaph_3, 324, "v_diaph_3", Real, "local", "continuous", "exact", 0, "m/s", 0.1, 323, "Velocity of diaphragm 3 relative to the ground (state, der(u_diaph_3))") \
X(der_v_diaph_3, 334, "der(v_diaph_3)", Real, "local", "continuous", "calculated", 0, "m/s2", 0, 324, "Acceleration of diaphragm 3 relative to the ground") \
X(z_diaph_3, 325, "z_diaph_3", Real, "local", "continuous", "exact", 0, "1", 1, 0, "Hysteretic variable (Bouc-Wen, bilinear) of diaphragm 3, z/z_u in [-1, 1] (state)") \
X(der_z_diaph_3, 335, "der(z_diaph_3)", Real, "local", "continuous", "calculated", 0, "1/s", 0, 325, "Rate of z_diaph_3") \
X(work_storey_3, 326, "work_storey_3", Real, "output", "continuous", "exact", 0, "J/m", 0, 0, "Work of storey 3's spring force on its drift, integral of V_storey_3 d(drift_3) (state; per closed cycle: the energy dissipated by hysteresis)") \
X(der_work_storey_3, 336, "der(work_storey_3)", Real, "local", "continuous", "calculated", 0, "W/m", 0, 326, "Power V_storey_3 * der(drift_3)") \
X(work_diaph_3, 327, "work_diaph_3", Real, "output", "continuous", "exact", 0, "J/m", 0, 0, "Work of diaphragm 3's spring force on its deformation, integral of F_diaph_3 d(d_diaph_3) (state)") \
X(der_work_diaph_3, 337, "der(work_diaph_3)", Real, "local", "continuous", "calculated", 0, "W/m", 0, 327, "Power F_diaph_3 * der(d_diaph_3)") \
X(a_diaph_3, 340, "a_diaph_3", Real, "output", "continuous", "calculated", 0, "m/s2", 0, 0, "Absolute acceleration of diaphragm 3 (ag + der(v_diaph_3)): the ground motion of a wall standing on floor 3") \
X(u_top_3, 341, "u_top_3", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Displacement of diaphragm 3 relative to diaphragm 2 (the ground for 1): u_top of a wall in storey 3") \
X(V_storey_3, 342, "V_storey_3", Real, "output", "continuous", "calculated", 0, "N/m", 0, 0, "Spring (hysteretic) shear force of storey 3, without damping: positive for positive drift, it pulls floor 3 toward -x and the floor below toward +x") \
X(drift_3, 343, "drift_3", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Storey drift u_floor_3 - u_floor_2") \
X(F_diaph_3, 344, "F_diaph_3", Real, "output", "continuous", "calculated", 0, "N/m", 0, 0, "Spring force of diaphragm 3 (without damping) for its deformation d_diaph_3") \
X(d_diaph_3, 345, "d_diaph_3", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Deformation of diaphragm 3: u_diaph_3 - u_floor_3") \
X(m_4, 401, "m_4", Real, "parameter", "fixed", "exact", 4000, "kg/m", 0, 0, "Mass of floor 4 at the in-plane walls per metre of out-of-plane wall (> 0)") \
X(k_4, 402, "k_4", Real, "parameter", "fixed", "exact", 20000000.0, "N/m2", 0, 0, "Initial stiffness of storey 4 (its in-plane walls), N/m per m (> 0)") \
X(Fy_4, 403, "Fy_4", Real, "parameter", "fixed", "exact", 30000.0, "N/m", 0, 0, "Yield force of storey 4 (> 0)") \
X(alpha_4, 404, "alpha_4", Real, "parameter", "fixed", "exact", 0.05, "1", 0, 0, "Post-yield stiffness ratio of storey 4, in [0, 1]") \
X(md_4, 405, "md_4", Real, "parameter", "fixed", "exact", 2000, "kg/m", 0, 0, "Mass of diaphragm 4 per metre of out-of-plane wall (> 0)") \
X(kd_4, 406, "kd_4", Real, "parameter", "fixed", "exact", 700000.0, "N/m2", 0, 0, "Initial stiffness of diaphragm 4 relative to its floor, N/m per m (> 0)") \
X(Fyd_4, 407, "Fyd_4", Real, "parameter", "fixed", "exact", 10000.0, "N/m", 0, 0, "Yield force of diaphragm 4 (> 0)") \
X(alphad_4, 408, "alphad_4", Real, "parameter", "fixed", "exact", 0.1, "1", 0, 0, "Post-yield stiffness ratio of diaphragm 4, in [0, 1]") \
X(cs_4, 412, "cs_4", Real, "parameter", "fixed", "exact", 0, "N.s/m2", 0, 0, "Dashpot beside storey 4's spring (in-plane walls), N s/m per m (>= 0; 0: Rayleigh damping only)") \
X(cd_4, 413, "cd_4", Real, "parameter", "fixed", "exact", 0, "N.s/m2", 0, 0, "Dashpot beside diaphragm 4's spring, N s/m per m (>= 0; a damping ratio zeta on its own spring and mass: 2 zeta sqrt(kd md))") \
X(F_wall_4, 410, "F_wall_4", Real, "input", "continuous", "", 0, "N/m", 0, 0, "Horizontal force on diaphragm 4 of the top spring of the out-of-plane wall below it, +x (RockingWall F_top)") \
X(F_above_4, 411, "F_above_4", Real, "input", "continuous", "", 0, "N/m", 0, 0, "Horizontal force on diaphragm 4 of the base of the out-of-plane wall standing on floor 4, +x (RockingWall F_base)") \
X(u_floor_4, 420, "u_floor_4", Real, "local", "continuous", "exact", 0, "m", 0.01, 0, "Displacement of floor 4 (in-plane walls' level) relative to the ground (state)") \
X(v_floor_4, 421, "v_floor_4", Real, "local", "continuous", "exact", 0, "m/s", 0.1, 420, "Velocity of floor 4 relative to the ground (state, der(u_floor_4))") \
X(der_v_floor_4, 431, "der(v_floor_4)", Real, "local", "continuous", "calculated", 0, "m/s2", 0, 421, "Acceleration of floor 4 relative to the ground") \
X(z_storey_4, 422, "z_storey_4", Real, "local", "continuous", "exact", 0, "1", 1, 0, "Hysteretic variable (Bouc-Wen, bilinear) of storey 4, z/z_u in [-1, 1] (state)") \
X(der_z_storey_4, 432, "der(z_storey_4)", Real, "local", "continuous", "calculated", 0, "1/s", 0, 422, "Rate of z_storey_4") \
X(u_diaph_4, 423, "u_diaph_4", Real, "output", "continuous", "exact", 0, "m", 0.01, 0, "Displacement of diaphragm 4 relative to the ground (state)") \
X(v_diaph_4, 424, "v_diaph_4", Real, "local", "continuous", "exact", 0, "m/s", 0.1, 423, "Velocity of diaphragm 4 relative to the ground (state, der(u_diaph_4))") \
X(der_v_diaph_4, 434, "der(v_diaph_4)", Real, "local", "continuous", "calculated", 0, "m/s2", 0, 424, "Acceleration of diaphragm 4 relative to the ground") \
X(z_diaph_4, 425, "z_diaph_4", Real, "local", "continuous", "exact", 0, "1", 1, 0, "Hysteretic variable (Bouc-Wen, bilinear) of diaphragm 4, z/z_u in [-1, 1] (state)") \
X(der_z_diaph_4, 435, "der(z_diaph_4)", Real, "local", "continuous", "calculated", 0, "1/s", 0, 425, "Rate of z_diaph_4") \
X(work_storey_4, 426, "work_storey_4", Real, "output", "continuous", "exact", 0, "J/m", 0, 0, "Work of storey 4's spring force on its drift, integral of V_storey_4 d(drift_4) (state; per closed cycle: the energy dissipated by hysteresis)") \
X(der_work_storey_4, 436, "der(work_storey_4)", Real, "local", "continuous", "calculated", 0, "W/m", 0, 426, "Power V_storey_4 * der(drift_4)") \
X(work_diaph_4, 427, "work_diaph_4", Real, "output", "continuous", "exact", 0, "J/m", 0, 0, "Work of diaphragm 4's spring force on its deformation, integral of F_diaph_4 d(d_diaph_4) (state)") \
X(der_work_diaph_4, 437, "der(work_diaph_4)", Real, "local", "continuous", "calculated", 0, "W/m", 0, 427, "Power F_diaph_4 * der(d_diaph_4)") \
X(a_diaph_4, 440, "a_diaph_4", Real, "output", "continuous", "calculated", 0, "m/s2", 0, 0, "Absolute acceleration of diaphragm 4 (ag + der(v_diaph_4)): the ground motion of a wall standing on floor 4") \
X(u_top_4, 441, "u_top_4", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Displacement of diaphragm 4 relative to diaphragm 3 (the ground for 1): u_top of a wall in storey 4") \
X(V_storey_4, 442, "V_storey_4", Real, "output", "continuous", "calculated", 0, "N/m", 0, 0, "Spring (hysteretic) shear force of storey 4, without damping: positive for positive drift, it pulls floor 4 toward -x and the floor below toward +x") \
X(drift_4, 443, "drift_4", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Storey drift u_floor_4 - u_floor_3") \
X(F_diaph_4, 444, "F_diaph_4", Real, "output", "continuous", "calculated", 0, "N/m", 0, 0, "Spring force of diaphragm 4 (without damping) for its deformation d_diaph_4") \
X(d_diaph_4, 445, "d_diaph_4", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Deformation of diaphragm 4: u_diaph_4 - u_floor_4") \
X(m_5, 501, "m_5", Real, "parameter", "fixed", "exact", 4000, "kg/m", 0, 0, "Mass of floor 5 at the in-plane walls per metre of out-of-plane wall (> 0)") \
X(k_5, 502, "k_5", Real, "parameter", "fixed", "exact", 20000000.0, "N/m2", 0, 0, "Initial stiffness of storey 5 (its in-plane walls), N/m per m (> 0)") \
X(Fy_5, 503, "Fy_5", Real, "parameter", "fixed", "exact", 30000.0, "N/m", 0, 0, "Yield force of storey 5 (> 0)") \
X(alpha_5, 504, "alpha_5", Real, "parameter", "fixed", "exact", 0.05, "1", 0, 0, "Post-yield stiffness ratio of storey 5, in [0, 1]") \
X(md_5, 505, "md_5", Real, "parameter", "fixed", "exact", 2000, "kg/m", 0, 0, "Mass of diaphragm 5 per metre of out-of-plane wall (> 0)") \
X(kd_5, 506, "kd_5", Real, "parameter", "fixed", "exact", 700000.0, "N/m2", 0, 0, "Initial stiffness of diaphragm 5 relative to its floor, N/m per m (> 0)") \
X(Fyd_5, 507, "Fyd_5", Real, "parameter", "fixed", "exact", 10000.0, "N/m", 0, 0, "Yield force of diaphragm 5 (> 0)") \
X(alphad_5, 508, "alphad_5", Real, "parameter", "fixed", "exact", 0.1, "1", 0, 0, "Post-yield stiffness ratio of diaphragm 5, in [0, 1]") \
X(cs_5, 512, "cs_5", Real, "parameter", "fixed", "exact", 0, "N.s/m2", 0, 0, "Dashpot beside storey 5's spring (in-plane walls), N s/m per m (>= 0; 0: Rayleigh damping only)") \
X(cd_5, 513, "cd_5", Real, "parameter", "fixed", "exact", 0, "N.s/m2", 0, 0, "Dashpot beside diaphragm 5's spring, N s/m per m (>= 0; a damping ratio zeta on its own spring and mass: 2 zeta sqrt(kd md))") \
X(F_wall_5, 510, "F_wall_5", Real, "input", "continuous", "", 0, "N/m", 0, 0, "Horizontal force on diaphragm 5 of the top spring of the out-of-plane wall below it, +x (RockingWall F_top)") \
X(F_above_5, 511, "F_above_5", Real, "input", "continuous", "", 0, "N/m", 0, 0, "Horizontal force on diaphragm 5 of the base of the out-of-plane wall standing on floor 5, +x (RockingWall F_base)") \
X(u_floor_5, 520, "u_floor_5", Real, "local", "continuous", "exact", 0, "m", 0.01, 0, "Displacement of floor 5 (in-plane walls' level) relative to the ground (state)") \
X(v_floor_5, 521, "v_floor_5", Real, "local", "continuous", "exact", 0, "m/s", 0.1, 520, "Velocity of floor 5 relative to the ground (state, der(u_floor_5))") \
X(der_v_floor_5, 531, "der(v_floor_5)", Real, "local", "continuous", "calculated", 0, "m/s2", 0, 521, "Acceleration of floor 5 relative to the ground") \
X(z_storey_5, 522, "z_storey_5", Real, "local", "continuous", "exact", 0, "1", 1, 0, "Hysteretic variable (Bouc-Wen, bilinear) of storey 5, z/z_u in [-1, 1] (state)") \
X(der_z_storey_5, 532, "der(z_storey_5)", Real, "local", "continuous", "calculated", 0, "1/s", 0, 522, "Rate of z_storey_5") \
X(u_diaph_5, 523, "u_diaph_5", Real, "output", "continuous", "exact", 0, "m", 0.01, 0, "Displacement of diaphragm 5 relative to the ground (state)") \
X(v_diaph_5, 524, "v_diaph_5", Real, "local", "continuous", "exact", 0, "m/s", 0.1, 523, "Velocity of diaphragm 5 relative to the ground (state, der(u_diaph_5))") \
X(der_v_diaph_5, 534, "der(v_diaph_5)", Real, "local", "continuous", "calculated", 0, "m/s2", 0, 524, "Acceleration of diaphragm 5 relative to the ground") \
X(z_diaph_5, 525, "z_diaph_5", Real, "local", "continuous", "exact", 0, "1", 1, 0, "Hysteretic variable (Bouc-Wen, bilinear) of diaphragm 5, z/z_u in [-1, 1] (state)") \
X(der_z_diaph_5, 535, "der(z_diaph_5)", Real, "local", "continuous", "calculated", 0, "1/s", 0, 525, "Rate of z_diaph_5") \
X(work_storey_5, 526, "work_storey_5", Real, "output", "continuous", "exact", 0, "J/m", 0, 0, "Work of storey 5's spring force on its drift, integral of V_storey_5 d(drift_5) (state; per closed cycle: the energy dissipated by hysteresis)") \
X(der_work_storey_5, 536, "der(work_storey_5)", Real, "local", "continuous", "calculated", 0, "W/m", 0, 526, "Power V_storey_5 * der(drift_5)") \
X(work_diaph_5, 527, "work_diaph_5", Real, "output", "continuous", "exact", 0, "J/m", 0, 0, "Work of diaphragm 5's spring force on its deformation, integral of F_diaph_5 d(d_diaph_5) (state)") \
X(der_work_diaph_5, 537, "der(work_diaph_5)", Real, "local", "continuous", "calculated", 0, "W/m", 0, 527, "Power F_diaph_5 * der(d_diaph_5)") \
X(a_diaph_5, 540, "a_diaph_5", Real, "output", "continuous", "calculated", 0, "m/s2", 0, 0, "Absolute acceleration of diaphragm 5 (ag + der(v_diaph_5)): the ground motion of a wall standing on floor 5") \
X(u_top_5, 541, "u_top_5", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Displacement of diaphragm 5 relative to diaphragm 4 (the ground for 1): u_top of a wall in storey 5") \
X(V_storey_5, 542, "V_storey_5", Real, "output", "continuous", "calculated", 0, "N/m", 0, 0, "Spring (hysteretic) shear force of storey 5, without damping: positive for positive drift, it pulls floor 5 toward -x and the floor below toward +x") \
X(drift_5, 543, "drift_5", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Storey drift u_floor_5 - u_floor_4") \
X(F_diaph_5, 544, "F_diaph_5", Real, "output", "continuous", "calculated", 0, "N/m", 0, 0, "Spring force of diaphragm 5 (without damping) for its deformation d_diaph_5") \
X(d_diaph_5, 545, "d_diaph_5", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Deformation of diaphragm 5: u_diaph_5 - u_floor_5")
/* clang-format on */

/* no event indicators (the format of RW_EVENT_INDICATORS in fmu_src/models/RockingWall/model_variables.h) */
#define BD_EVENT_INDICATORS(Z)

#define BD_VR_ENUM(ID, VR, NAME, TYPE, CAUS, VARIAB, INIT, START, UNIT, NOM, DER, DESC) BD_VR_##ID = VR,
enum { BD_VARIABLES(BD_VR_ENUM) BD_VR_MAX_PLUS_ONE_DUMMY };
#undef BD_VR_ENUM

/* ModelStructure: what each output and state derivative depends on (superset over the laws and
 * nStoreys). A state that is also an output depends on itself. tests/python/
 * test_building_model_structure.py checks every entry by finite differences. */
#define BD_DEPENDENCIES(D) \
D(v_floor_1, "v_floor_1") \
D(der_v_floor_1, "ag u_floor_1 u_floor_2 z_storey_1 z_storey_2 u_diaph_1 z_diaph_1 v_floor_1 v_floor_2 v_diaph_1") \
D(der_z_storey_1, "v_floor_1 z_storey_1") \
D(u_diaph_1, "u_diaph_1") \
D(v_diaph_1, "v_diaph_1") \
D(der_v_diaph_1, "ag u_floor_1 u_diaph_1 z_diaph_1 v_floor_1 v_diaph_1 F_wall_1 F_above_1") \
D(der_z_diaph_1, "v_floor_1 v_diaph_1 z_diaph_1") \
D(work_storey_1, "work_storey_1") \
D(der_work_storey_1, "u_floor_1 z_storey_1 v_floor_1") \
D(work_diaph_1, "work_diaph_1") \
D(der_work_diaph_1, "u_floor_1 u_diaph_1 z_diaph_1 v_floor_1 v_diaph_1") \
D(a_diaph_1, "u_floor_1 u_diaph_1 z_diaph_1 v_floor_1 v_diaph_1 F_wall_1 F_above_1") \
D(u_top_1, "u_diaph_1") \
D(V_storey_1, "u_floor_1 z_storey_1") \
D(drift_1, "u_floor_1") \
D(F_diaph_1, "u_floor_1 u_diaph_1 z_diaph_1") \
D(d_diaph_1, "u_floor_1 u_diaph_1") \
D(v_floor_2, "v_floor_2") \
D(der_v_floor_2, "ag u_floor_1 u_floor_2 u_floor_3 z_storey_2 z_storey_3 u_diaph_2 z_diaph_2 v_floor_1 v_floor_2 v_floor_3 v_diaph_2") \
D(der_z_storey_2, "v_floor_1 v_floor_2 z_storey_2") \
D(u_diaph_2, "u_diaph_2") \
D(v_diaph_2, "v_diaph_2") \
D(der_v_diaph_2, "ag u_floor_2 u_diaph_2 z_diaph_2 v_floor_2 v_diaph_2 F_wall_2 F_above_2") \
D(der_z_diaph_2, "v_floor_2 v_diaph_2 z_diaph_2") \
D(work_storey_2, "work_storey_2") \
D(der_work_storey_2, "u_floor_1 u_floor_2 z_storey_2 v_floor_1 v_floor_2") \
D(work_diaph_2, "work_diaph_2") \
D(der_work_diaph_2, "u_floor_2 u_diaph_2 z_diaph_2 v_floor_2 v_diaph_2") \
D(a_diaph_2, "u_floor_2 u_diaph_2 z_diaph_2 v_floor_2 v_diaph_2 F_wall_2 F_above_2") \
D(u_top_2, "u_diaph_1 u_diaph_2") \
D(V_storey_2, "u_floor_1 u_floor_2 z_storey_2") \
D(drift_2, "u_floor_1 u_floor_2") \
D(F_diaph_2, "u_floor_2 u_diaph_2 z_diaph_2") \
D(d_diaph_2, "u_floor_2 u_diaph_2") \
D(v_floor_3, "v_floor_3") \
D(der_v_floor_3, "ag u_floor_2 u_floor_3 u_floor_4 z_storey_3 z_storey_4 u_diaph_3 z_diaph_3 v_floor_2 v_floor_3 v_floor_4 v_diaph_3") \
D(der_z_storey_3, "v_floor_2 v_floor_3 z_storey_3") \
D(u_diaph_3, "u_diaph_3") \
D(v_diaph_3, "v_diaph_3") \
D(der_v_diaph_3, "ag u_floor_3 u_diaph_3 z_diaph_3 v_floor_3 v_diaph_3 F_wall_3 F_above_3") \
D(der_z_diaph_3, "v_floor_3 v_diaph_3 z_diaph_3") \
D(work_storey_3, "work_storey_3") \
D(der_work_storey_3, "u_floor_2 u_floor_3 z_storey_3 v_floor_2 v_floor_3") \
D(work_diaph_3, "work_diaph_3") \
D(der_work_diaph_3, "u_floor_3 u_diaph_3 z_diaph_3 v_floor_3 v_diaph_3") \
D(a_diaph_3, "u_floor_3 u_diaph_3 z_diaph_3 v_floor_3 v_diaph_3 F_wall_3 F_above_3") \
D(u_top_3, "u_diaph_2 u_diaph_3") \
D(V_storey_3, "u_floor_2 u_floor_3 z_storey_3") \
D(drift_3, "u_floor_2 u_floor_3") \
D(F_diaph_3, "u_floor_3 u_diaph_3 z_diaph_3") \
D(d_diaph_3, "u_floor_3 u_diaph_3") \
D(v_floor_4, "v_floor_4") \
D(der_v_floor_4, "ag u_floor_3 u_floor_4 u_floor_5 z_storey_4 z_storey_5 u_diaph_4 z_diaph_4 v_floor_3 v_floor_4 v_floor_5 v_diaph_4") \
D(der_z_storey_4, "v_floor_3 v_floor_4 z_storey_4") \
D(u_diaph_4, "u_diaph_4") \
D(v_diaph_4, "v_diaph_4") \
D(der_v_diaph_4, "ag u_floor_4 u_diaph_4 z_diaph_4 v_floor_4 v_diaph_4 F_wall_4 F_above_4") \
D(der_z_diaph_4, "v_floor_4 v_diaph_4 z_diaph_4") \
D(work_storey_4, "work_storey_4") \
D(der_work_storey_4, "u_floor_3 u_floor_4 z_storey_4 v_floor_3 v_floor_4") \
D(work_diaph_4, "work_diaph_4") \
D(der_work_diaph_4, "u_floor_4 u_diaph_4 z_diaph_4 v_floor_4 v_diaph_4") \
D(a_diaph_4, "u_floor_4 u_diaph_4 z_diaph_4 v_floor_4 v_diaph_4 F_wall_4 F_above_4") \
D(u_top_4, "u_diaph_3 u_diaph_4") \
D(V_storey_4, "u_floor_3 u_floor_4 z_storey_4") \
D(drift_4, "u_floor_3 u_floor_4") \
D(F_diaph_4, "u_floor_4 u_diaph_4 z_diaph_4") \
D(d_diaph_4, "u_floor_4 u_diaph_4") \
D(v_floor_5, "v_floor_5") \
D(der_v_floor_5, "ag u_floor_4 u_floor_5 z_storey_5 u_diaph_5 z_diaph_5 v_floor_4 v_floor_5 v_diaph_5") \
D(der_z_storey_5, "v_floor_4 v_floor_5 z_storey_5") \
D(u_diaph_5, "u_diaph_5") \
D(v_diaph_5, "v_diaph_5") \
D(der_v_diaph_5, "ag u_floor_5 u_diaph_5 z_diaph_5 v_floor_5 v_diaph_5 F_wall_5 F_above_5") \
D(der_z_diaph_5, "v_floor_5 v_diaph_5 z_diaph_5") \
D(work_storey_5, "work_storey_5") \
D(der_work_storey_5, "u_floor_4 u_floor_5 z_storey_5 v_floor_4 v_floor_5") \
D(work_diaph_5, "work_diaph_5") \
D(der_work_diaph_5, "u_floor_5 u_diaph_5 z_diaph_5 v_floor_5 v_diaph_5") \
D(a_diaph_5, "u_floor_5 u_diaph_5 z_diaph_5 v_floor_5 v_diaph_5 F_wall_5 F_above_5") \
D(u_top_5, "u_diaph_4 u_diaph_5") \
D(V_storey_5, "u_floor_4 u_floor_5 z_storey_5") \
D(drift_5, "u_floor_4 u_floor_5") \
D(F_diaph_5, "u_floor_5 u_diaph_5 z_diaph_5") \
D(d_diaph_5, "u_floor_5 u_diaph_5")

#endif
