/* BuildingWithWalls: the one source of truth for the FMU's variables (the format of
 * fmu_src/models/Building/building_variables.h; scripts/gen_model_description.py writes fmi2/ and
 * fmi3/ from it). A building's face-loaded walls, their ties, diaphragms and floors as one model
 * (the scene of fmu_src/scene/rw_scene.h), every quantity per metre of face-loaded wall.
 *
 * Value references: the shared parameters, the input and the energy terms below 100; storey i
 * (1..5) uses 100*i + k with the same k for every storey (BW_STOREY_OF, BW_SLOT_OF): 1-19 its
 * wall's, diaphragm's and in-plane walls' parameters, 20-31 its states, 32-39 their rates, 40-48
 * its outputs, 49 its wall's eTop (a parameter added after the outputs), 50-57 its wall's event
 * indicators.
 * The continuous states, in the order of the state vector: work_ground, work_damping, then per
 * storey q1, q2, dq1, dq2, u_floor, v_floor, z_storey, u_diaph, v_diaph, z_diaph, work_storey,
 * work_diaph (the order of their derivatives in the table below).
 *
 * X(ID, VR, NAME, TYPE, CAUSALITY, VARIABILITY, INITIAL, START, UNIT, NOMINAL, DERIVATIVE_OF, DESCRIPTION) */
#ifndef BW_VARIABLES_H
#define BW_VARIABLES_H

#define BW_MODEL_IDENTIFIER "BuildingWithWalls"
#define BW_GUID "{8d2f6a41-3c5e-4b9a-a7d0-5e1c9f26b4e8}"
#define BW_NUMBER_OF_STATES 62
#define BW_NUMBER_OF_EVENT_INDICATORS 40

#define BW_STOREY_OF(vr) ((vr) / 100)
#define BW_SLOT_OF(vr) ((vr) % 100)

/* clang-format off */
#define BW_VARIABLES(X) \
X(nStoreys, 1, "nStoreys", Integer, "parameter", "fixed", "exact", 2, "", 0, 0, "Number of storeys N, 1..5 (the storeys above N are not there: their states at rest, their outputs 0)") \
X(rigidInPlane, 2, "rigidInPlane", Integer, "parameter", "fixed", "exact", 1, "", 0, 0, "1: the in-plane walls are rigid, every floor moves with the ground (m_i, k_i, zetas_i unused); 0: floors of mass m_i on storey springs k_i") \
X(storeyLaw, 3, "storeyLaw", Integer, "parameter", "fixed", "exact", 0, "", 0, 0, "Storey springs (in-plane walls, rigidInPlane = 0): 0 linear, 1 Bouc-Wen, 3 bilinear (elastoplastic, kinematic hardening)") \
X(diaphragmLaw, 4, "diaphragmLaw", Integer, "parameter", "fixed", "exact", 0, "", 0, 0, "Diaphragm springs: 0 linear, 1 Bouc-Wen, 2 Bouc-Wen with Foliente's pinching (timber), 3 bilinear (elastoplastic, kinematic hardening)") \
X(nBW, 5, "nBW", Real, "parameter", "fixed", "exact", 1, "1", 0, 0, "Bouc-Wen exponent n, in [1, 100]") \
X(betaBW, 6, "betaBW", Real, "parameter", "fixed", "exact", 0.5, "1", 0, 0, "Bouc-Wen beta, in [0, 1] (gamma = 1 - beta)") \
X(pinchSize, 7, "pinchSize", Real, "parameter", "fixed", "exact", 0.8, "1", 0, 0, "Pinching zeta1, in [0, 0.99] (diaphragmLaw 2)") \
X(pinchWidth, 8, "pinchWidth", Real, "parameter", "fixed", "exact", 0.2, "1", 0, 0, "Pinching zeta2, in [0.01, 10] (diaphragmLaw 2)") \
X(pinchCentre, 9, "pinchCentre", Real, "parameter", "fixed", "exact", 0.1, "1", 0, 0, "Pinching q, in [0, 0.99] (diaphragmLaw 2)") \
X(rayleighMass, 10, "rayleighMass", Real, "parameter", "fixed", "exact", 0, "1/s", 0, 0, "Rayleigh a0 of C = a0 M + a1 K0 on the floors and diaphragms, in [0, 1000]") \
X(rayleighStiffness, 11, "rayleighStiffness", Real, "parameter", "fixed", "exact", 0, "s", 0, 0, "Rayleigh a1 of C = a0 M + a1 K0 (K0: initial stiffness), in [0, 1]") \
X(g, 12, "g", Real, "parameter", "fixed", "exact", 9.81, "m/s2", 0, 0, "Gravity (every wall)") \
X(delta1Ratio, 13, "delta1Ratio", Real, "parameter", "fixed", "exact", 0.05, "1", 0, 0, "Every wall's Delta_1/Delta_u (RockingWall's delta1Ratio)") \
X(delta2A, 14, "delta2A", Real, "parameter", "fixed", "exact", 0.92, "1", 0, 0, "Every wall's delta2A (RockingWall's)") \
X(delta2B, 15, "delta2B", Real, "parameter", "fixed", "exact", 0.21, "1", 0, 0, "Every wall's delta2B (RockingWall's)") \
X(hingeSat, 16, "hingeSat", Real, "parameter", "fixed", "exact", 2.0, "1", 0, 0, "Every wall's hingeSat (semiRigidHinge, semiRigidPaper)") \
X(restRate, 17, "restRate", Real, "parameter", "fixed", "exact", 1e-05, "rad/s", 0, 0, "Every wall's restRate (rigid hinges)") \
X(ag, 20, "ag", Real, "input", "continuous", "", 0, "m/s2", 0, 0, "Ground acceleration, positive toward +x") \
X(energy, 30, "energy", Real, "output", "continuous", "calculated", 0, "J/m", 0, 0, "Mechanical energy of the scene with velocities relative to the ground: standing walls with their ties, floors, diaphragms, the springs' work") \
X(work_ground, 31, "work_ground", Real, "output", "continuous", "exact", 0, "J/m", 0, 0, "Work of the ground motion on the scene (state: the integral of its power)") \
X(der_work_ground, 32, "der(work_ground)", Real, "local", "continuous", "calculated", 0, "W/m", 0, 31, "Power of the ground motion on the scene") \
X(work_damping, 33, "work_damping", Real, "output", "continuous", "exact", 0, "J/m", 0, 0, "Energy the dashpots and Rayleigh damping took (state: the integral of their power)") \
X(der_work_damping, 34, "der(work_damping)", Real, "local", "continuous", "calculated", 0, "W/m", 0, 33, "Power of the dashpots and Rayleigh damping") \
X(event_losses, 35, "event_losses", Real, "output", "discrete", "calculated", 0, "J/m", 0, 0, "Energy taken out at events: impacts, hinge closings, walls that collapsed and left the scene with their energy") \
X(energy_residual, 36, "energy_residual", Real, "output", "continuous", "calculated", 0, "J/m", 0, 0, "energy - energy at the start - (work_ground - work_damping - event_losses): what the integration made or lost, 0 to its tolerance") \
X(hasWall_1, 101, "hasWall_1", Integer, "parameter", "fixed", "exact", 1, "", 0, 0, "1: storey 1 has a face-loaded wall standing on diaphragm 0 (the ground for 1) and tied to diaphragm 1; 0: none") \
X(h_1, 102, "h_1", Real, "parameter", "fixed", "exact", 2.5, "m", 0, 0, "Height of the wall of storey 1, in [0.3, 30]") \
X(b_1, 103, "b_1", Real, "parameter", "fixed", "exact", 0.15, "m", 0, 0, "Thickness of the wall of storey 1, in [0.02, 3] (also < h_1)") \
X(W_1, 104, "W_1", Real, "parameter", "fixed", "exact", 6622, "N/m", 0, 0, "Weight of the wall of storey 1 per metre of wall, in [10, 1e6]") \
X(psi_1, 105, "psi_1", Real, "parameter", "fixed", "exact", 0, "1", 0, 0, "Overburden ratio of the wall of storey 1: 2 overburden/W_1, in [0, 20] (its mass moves with the top)") \
X(tie_1, 106, "tie_1", Real, "parameter", "fixed", "exact", 100000000.0, "N/m2", 0, 0, "Tie between the top of the wall of storey 1 and diaphragm 1, N/m per m, in [0, 1e12] (the wall's K_d)") \
X(er_1, 107, "er_1", Real, "parameter", "fixed", "exact", 0.86, "1", 0, 0, "Coefficient of restitution of the wall of storey 1, in [0, 1]") \
X(hingeLaw_1, 108, "hingeLaw_1", Integer, "parameter", "fixed", "exact", 4, "", 0, 0, "Hinge law of the wall of storey 1: 1 rigid, 2 semiRigidPaper, 3 semiRigidHinge, 4 dohertyHinge") \
X(psiWeightOnly_1, 109, "psiWeightOnly_1", Real, "parameter", "fixed", "exact", 0, "1", 0, 0, "Weight-only overburden ratio of the wall of storey 1: 2 (weight of the walls above)/W_1, in [0, 20] (weight without mass: the walls above carry their own)") \
X(eTop_1, 149, "eTop_1", Real, "parameter", "fixed", "exact", 0, "m", 0, 0, "Eccentricity of the overburden of the wall of storey 1 (psi_1) from its centreline, positive toward +x, the inner face (joists bearing on it); |eTop_1| <= b_1/2 (RockingWall's eTop; the walls above bear on the centreline)") \
X(md_1, 110, "md_1", Real, "parameter", "fixed", "exact", 600, "kg/m", 0, 0, "Mass of diaphragm 1 per metre of wall, in (0, 1e9]") \
X(kd_1, 111, "kd_1", Real, "parameter", "fixed", "exact", 60000.0, "N/m2", 0, 0, "Stiffness of diaphragm 1 relative to its floor (initial, hysteretic laws), N/m per m, in [0, 1e15]") \
X(zetad_1, 112, "zetad_1", Real, "parameter", "fixed", "exact", 0.05, "1", 0, 0, "Damping ratio of diaphragm 1 on its own mass and spring, a dashpot 2 zetad sqrt(kd md), in [0, 2]") \
X(Fyd_1, 113, "Fyd_1", Real, "parameter", "fixed", "exact", 10000.0, "N/m", 0, 0, "Yield force of diaphragm 1 (hysteretic laws: diaphragmLaw 1 to 3), in (0, 1e15]") \
X(alphad_1, 114, "alphad_1", Real, "parameter", "fixed", "exact", 0.1, "1", 0, 0, "Post-yield stiffness ratio of diaphragm 1 (hysteretic laws: diaphragmLaw 1 to 3), in [0, 1]") \
X(m_1, 115, "m_1", Real, "parameter", "fixed", "exact", 4000, "kg/m", 0, 0, "Mass of floor 1 at the in-plane walls (rigidInPlane = 0), in (0, 1e9]") \
X(k_1, 116, "k_1", Real, "parameter", "fixed", "exact", 20000000.0, "N/m2", 0, 0, "Stiffness of storey 1's in-plane walls (rigidInPlane = 0), N/m per m, in (0, 1e15]") \
X(zetas_1, 117, "zetas_1", Real, "parameter", "fixed", "exact", 0.05, "1", 0, 0, "Damping ratio of storey 1's in-plane walls on floor mass and spring, a dashpot 2 zetas sqrt(k m), in [0, 2]") \
X(Fy_1, 118, "Fy_1", Real, "parameter", "fixed", "exact", 30000.0, "N/m", 0, 0, "Yield force of storey 1 (storeyLaw 1, 3), in (0, 1e15]") \
X(alpha_1, 119, "alpha_1", Real, "parameter", "fixed", "exact", 0.05, "1", 0, 0, "Post-yield stiffness ratio of storey 1 (storeyLaw 1, 3), in [0, 1]") \
X(q1_1, 120, "q1_1", Real, "local", "continuous", "exact", 0, "rad", 0.01, 0, "Rotation of the lower body of the wall of storey 1 (state)") \
X(q2_1, 121, "q2_1", Real, "local", "continuous", "exact", 0, "rad", 0.01, 0, "Rotation of the upper body of the wall of storey 1 (state)") \
X(dq1_1, 122, "dq1_1", Real, "local", "continuous", "exact", 0, "rad/s", 0.1, 120, "Rate of q1_1 (state, der(q1_1))") \
X(dq2_1, 123, "dq2_1", Real, "local", "continuous", "exact", 0, "rad/s", 0.1, 121, "Rate of q2_1 (state, der(q2_1))") \
X(der_dq1_1, 132, "der(dq1_1)", Real, "local", "continuous", "calculated", 0, "rad/s2", 0, 122, "Angular acceleration of the lower body of the wall of storey 1") \
X(der_dq2_1, 133, "der(dq2_1)", Real, "local", "continuous", "calculated", 0, "rad/s2", 0, 123, "Angular acceleration of the upper body of the wall of storey 1") \
X(u_floor_1, 124, "u_floor_1", Real, "local", "continuous", "exact", 0, "m", 0.01, 0, "Displacement of floor 1 relative to the ground (state; 0 with rigid in-plane walls)") \
X(v_floor_1, 125, "v_floor_1", Real, "local", "continuous", "exact", 0, "m/s", 0.1, 124, "Velocity of floor 1 (state, der(u_floor_1))") \
X(der_v_floor_1, 134, "der(v_floor_1)", Real, "local", "continuous", "calculated", 0, "m/s2", 0, 125, "Acceleration of floor 1 relative to the ground") \
X(z_storey_1, 126, "z_storey_1", Real, "local", "continuous", "exact", 0, "1", 1, 0, "Hysteretic variable (Bouc-Wen, bilinear) of storey 1, in [-1, 1] (state)") \
X(der_z_storey_1, 135, "der(z_storey_1)", Real, "local", "continuous", "calculated", 0, "1/s", 0, 126, "Rate of z_storey_1") \
X(u_diaph_1, 127, "u_diaph_1", Real, "output", "continuous", "exact", 0, "m", 0.01, 0, "Displacement of diaphragm 1 relative to the ground (state)") \
X(v_diaph_1, 128, "v_diaph_1", Real, "local", "continuous", "exact", 0, "m/s", 0.1, 127, "Velocity of diaphragm 1 (state, der(u_diaph_1))") \
X(der_v_diaph_1, 136, "der(v_diaph_1)", Real, "local", "continuous", "calculated", 0, "m/s2", 0, 128, "Acceleration of diaphragm 1 relative to the ground") \
X(z_diaph_1, 129, "z_diaph_1", Real, "local", "continuous", "exact", 0, "1", 1, 0, "Hysteretic variable (Bouc-Wen, bilinear) of diaphragm 1, in [-1, 1] (state)") \
X(der_z_diaph_1, 137, "der(z_diaph_1)", Real, "local", "continuous", "calculated", 0, "1/s", 0, 129, "Rate of z_diaph_1") \
X(work_storey_1, 130, "work_storey_1", Real, "local", "continuous", "exact", 0, "J/m", 0, 0, "Work of storey 1's spring force on its drift (state)") \
X(der_work_storey_1, 138, "der(work_storey_1)", Real, "local", "continuous", "calculated", 0, "W/m", 0, 130, "Power of storey 1's spring") \
X(work_diaph_1, 131, "work_diaph_1", Real, "local", "continuous", "exact", 0, "J/m", 0, 0, "Work of diaphragm 1's spring force on its deformation (state)") \
X(der_work_diaph_1, 139, "der(work_diaph_1)", Real, "local", "continuous", "calculated", 0, "W/m", 0, 131, "Power of diaphragm 1's spring") \
X(s1_1, 140, "s1_1", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Mid-height displacement of the wall of storey 1 relative to its base, q1 h/2") \
X(s2_1, 141, "s2_1", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Top displacement of the wall of storey 1 relative to its base, (q1 + q2) h/2") \
X(collapsed_1, 142, "collapsed_1", Boolean, "output", "discrete", "calculated", 0, "", 0, 0, "True once the wall of storey 1 has collapsed; it then leaves the scene (no more forces, its states frozen) and the rest runs on") \
X(impacts_1, 143, "impacts_1", Integer, "output", "discrete", "calculated", 0, "", 0, 0, "Base impacts of the wall of storey 1 (RockingWall's count)") \
X(F_top_1, 144, "F_top_1", Real, "output", "continuous", "calculated", 0, "N/m", 0, 0, "Force of the tie of storey 1 on diaphragm 1, tie_1 (s2_1 - u_top), +x") \
X(F_base_1, 145, "F_base_1", Real, "output", "continuous", "calculated", 0, "N/m", 0, 0, "Force the wall of storey 1 puts on its base (diaphragm 0, the ground for 1), +x") \
X(d_diaph_1, 146, "d_diaph_1", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Displacement of diaphragm 1 relative to its floor (its supports)") \
X(a_diaph_1, 147, "a_diaph_1", Real, "output", "continuous", "calculated", 0, "m/s2", 0, 0, "Absolute acceleration of diaphragm 1: the floor the wall of storey 2 stands on") \
X(a_base_1, 148, "a_base_1", Real, "output", "continuous", "calculated", 0, "m/s2", 0, 0, "Absolute acceleration of the floor the wall of storey 1 stands on (ag for 1, a_diaph_0 above)") \
X(hasWall_2, 201, "hasWall_2", Integer, "parameter", "fixed", "exact", 1, "", 0, 0, "1: storey 2 has a face-loaded wall standing on diaphragm 1 (the ground for 1) and tied to diaphragm 2; 0: none") \
X(h_2, 202, "h_2", Real, "parameter", "fixed", "exact", 2.5, "m", 0, 0, "Height of the wall of storey 2, in [0.3, 30]") \
X(b_2, 203, "b_2", Real, "parameter", "fixed", "exact", 0.15, "m", 0, 0, "Thickness of the wall of storey 2, in [0.02, 3] (also < h_2)") \
X(W_2, 204, "W_2", Real, "parameter", "fixed", "exact", 6622, "N/m", 0, 0, "Weight of the wall of storey 2 per metre of wall, in [10, 1e6]") \
X(psi_2, 205, "psi_2", Real, "parameter", "fixed", "exact", 0, "1", 0, 0, "Overburden ratio of the wall of storey 2: 2 overburden/W_2, in [0, 20] (its mass moves with the top)") \
X(tie_2, 206, "tie_2", Real, "parameter", "fixed", "exact", 100000000.0, "N/m2", 0, 0, "Tie between the top of the wall of storey 2 and diaphragm 2, N/m per m, in [0, 1e12] (the wall's K_d)") \
X(er_2, 207, "er_2", Real, "parameter", "fixed", "exact", 0.86, "1", 0, 0, "Coefficient of restitution of the wall of storey 2, in [0, 1]") \
X(hingeLaw_2, 208, "hingeLaw_2", Integer, "parameter", "fixed", "exact", 4, "", 0, 0, "Hinge law of the wall of storey 2: 1 rigid, 2 semiRigidPaper, 3 semiRigidHinge, 4 dohertyHinge") \
X(psiWeightOnly_2, 209, "psiWeightOnly_2", Real, "parameter", "fixed", "exact", 0, "1", 0, 0, "Weight-only overburden ratio of the wall of storey 2: 2 (weight of the walls above)/W_2, in [0, 20] (weight without mass: the walls above carry their own)") \
X(eTop_2, 249, "eTop_2", Real, "parameter", "fixed", "exact", 0, "m", 0, 0, "Eccentricity of the overburden of the wall of storey 2 (psi_2) from its centreline, positive toward +x, the inner face (joists bearing on it); |eTop_2| <= b_2/2 (RockingWall's eTop; the walls above bear on the centreline)") \
X(md_2, 210, "md_2", Real, "parameter", "fixed", "exact", 600, "kg/m", 0, 0, "Mass of diaphragm 2 per metre of wall, in (0, 1e9]") \
X(kd_2, 211, "kd_2", Real, "parameter", "fixed", "exact", 60000.0, "N/m2", 0, 0, "Stiffness of diaphragm 2 relative to its floor (initial, hysteretic laws), N/m per m, in [0, 1e15]") \
X(zetad_2, 212, "zetad_2", Real, "parameter", "fixed", "exact", 0.05, "1", 0, 0, "Damping ratio of diaphragm 2 on its own mass and spring, a dashpot 2 zetad sqrt(kd md), in [0, 2]") \
X(Fyd_2, 213, "Fyd_2", Real, "parameter", "fixed", "exact", 10000.0, "N/m", 0, 0, "Yield force of diaphragm 2 (hysteretic laws: diaphragmLaw 1 to 3), in (0, 1e15]") \
X(alphad_2, 214, "alphad_2", Real, "parameter", "fixed", "exact", 0.1, "1", 0, 0, "Post-yield stiffness ratio of diaphragm 2 (hysteretic laws: diaphragmLaw 1 to 3), in [0, 1]") \
X(m_2, 215, "m_2", Real, "parameter", "fixed", "exact", 4000, "kg/m", 0, 0, "Mass of floor 2 at the in-plane walls (rigidInPlane = 0), in (0, 1e9]") \
X(k_2, 216, "k_2", Real, "parameter", "fixed", "exact", 20000000.0, "N/m2", 0, 0, "Stiffness of storey 2's in-plane walls (rigidInPlane = 0), N/m per m, in (0, 1e15]") \
X(zetas_2, 217, "zetas_2", Real, "parameter", "fixed", "exact", 0.05, "1", 0, 0, "Damping ratio of storey 2's in-plane walls on floor mass and spring, a dashpot 2 zetas sqrt(k m), in [0, 2]") \
X(Fy_2, 218, "Fy_2", Real, "parameter", "fixed", "exact", 30000.0, "N/m", 0, 0, "Yield force of storey 2 (storeyLaw 1, 3), in (0, 1e15]") \
X(alpha_2, 219, "alpha_2", Real, "parameter", "fixed", "exact", 0.05, "1", 0, 0, "Post-yield stiffness ratio of storey 2 (storeyLaw 1, 3), in [0, 1]") \
X(q1_2, 220, "q1_2", Real, "local", "continuous", "exact", 0, "rad", 0.01, 0, "Rotation of the lower body of the wall of storey 2 (state)") \
X(q2_2, 221, "q2_2", Real, "local", "continuous", "exact", 0, "rad", 0.01, 0, "Rotation of the upper body of the wall of storey 2 (state)") \
X(dq1_2, 222, "dq1_2", Real, "local", "continuous", "exact", 0, "rad/s", 0.1, 220, "Rate of q1_2 (state, der(q1_2))") \
X(dq2_2, 223, "dq2_2", Real, "local", "continuous", "exact", 0, "rad/s", 0.1, 221, "Rate of q2_2 (state, der(q2_2))") \
X(der_dq1_2, 232, "der(dq1_2)", Real, "local", "continuous", "calculated", 0, "rad/s2", 0, 222, "Angular acceleration of the lower body of the wall of storey 2") \
X(der_dq2_2, 233, "der(dq2_2)", Real, "local", "continuous", "calculated", 0, "rad/s2", 0, 223, "Angular acceleration of the upper body of the wall of storey 2") \
X(u_floor_2, 224, "u_floor_2", Real, "local", "continuous", "exact", 0, "m", 0.01, 0, "Displacement of floor 2 relative to the ground (state; 0 with rigid in-plane walls)") \
X(v_floor_2, 225, "v_floor_2", Real, "local", "continuous", "exact", 0, "m/s", 0.1, 224, "Velocity of floor 2 (state, der(u_floor_2))") \
X(der_v_floor_2, 234, "der(v_floor_2)", Real, "local", "continuous", "calculated", 0, "m/s2", 0, 225, "Acceleration of floor 2 relative to the ground") \
X(z_storey_2, 226, "z_storey_2", Real, "local", "continuous", "exact", 0, "1", 1, 0, "Hysteretic variable (Bouc-Wen, bilinear) of storey 2, in [-1, 1] (state)") \
X(der_z_storey_2, 235, "der(z_storey_2)", Real, "local", "continuous", "calculated", 0, "1/s", 0, 226, "Rate of z_storey_2") \
X(u_diaph_2, 227, "u_diaph_2", Real, "output", "continuous", "exact", 0, "m", 0.01, 0, "Displacement of diaphragm 2 relative to the ground (state)") \
X(v_diaph_2, 228, "v_diaph_2", Real, "local", "continuous", "exact", 0, "m/s", 0.1, 227, "Velocity of diaphragm 2 (state, der(u_diaph_2))") \
X(der_v_diaph_2, 236, "der(v_diaph_2)", Real, "local", "continuous", "calculated", 0, "m/s2", 0, 228, "Acceleration of diaphragm 2 relative to the ground") \
X(z_diaph_2, 229, "z_diaph_2", Real, "local", "continuous", "exact", 0, "1", 1, 0, "Hysteretic variable (Bouc-Wen, bilinear) of diaphragm 2, in [-1, 1] (state)") \
X(der_z_diaph_2, 237, "der(z_diaph_2)", Real, "local", "continuous", "calculated", 0, "1/s", 0, 229, "Rate of z_diaph_2") \
X(work_storey_2, 230, "work_storey_2", Real, "local", "continuous", "exact", 0, "J/m", 0, 0, "Work of storey 2's spring force on its drift (state)") \
X(der_work_storey_2, 238, "der(work_storey_2)", Real, "local", "continuous", "calculated", 0, "W/m", 0, 230, "Power of storey 2's spring") \
X(work_diaph_2, 231, "work_diaph_2", Real, "local", "continuous", "exact", 0, "J/m", 0, 0, "Work of diaphragm 2's spring force on its deformation (state)") \
X(der_work_diaph_2, 239, "der(work_diaph_2)", Real, "local", "continuous", "calculated", 0, "W/m", 0, 231, "Power of diaphragm 2's spring") \
X(s1_2, 240, "s1_2", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Mid-height displacement of the wall of storey 2 relative to its base, q1 h/2") \
X(s2_2, 241, "s2_2", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Top displacement of the wall of storey 2 relative to its base, (q1 + q2) h/2") \
X(collapsed_2, 242, "collapsed_2", Boolean, "output", "discrete", "calculated", 0, "", 0, 0, "True once the wall of storey 2 has collapsed; it then leaves the scene (no more forces, its states frozen) and the rest runs on") \
X(impacts_2, 243, "impacts_2", Integer, "output", "discrete", "calculated", 0, "", 0, 0, "Base impacts of the wall of storey 2 (RockingWall's count)") \
X(F_top_2, 244, "F_top_2", Real, "output", "continuous", "calculated", 0, "N/m", 0, 0, "Force of the tie of storey 2 on diaphragm 2, tie_2 (s2_2 - u_top), +x") \
X(F_base_2, 245, "F_base_2", Real, "output", "continuous", "calculated", 0, "N/m", 0, 0, "Force the wall of storey 2 puts on its base (diaphragm 1, the ground for 1), +x") \
X(d_diaph_2, 246, "d_diaph_2", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Displacement of diaphragm 2 relative to its floor (its supports)") \
X(a_diaph_2, 247, "a_diaph_2", Real, "output", "continuous", "calculated", 0, "m/s2", 0, 0, "Absolute acceleration of diaphragm 2: the floor the wall of storey 3 stands on") \
X(a_base_2, 248, "a_base_2", Real, "output", "continuous", "calculated", 0, "m/s2", 0, 0, "Absolute acceleration of the floor the wall of storey 2 stands on (ag for 1, a_diaph_1 above)") \
X(hasWall_3, 301, "hasWall_3", Integer, "parameter", "fixed", "exact", 1, "", 0, 0, "1: storey 3 has a face-loaded wall standing on diaphragm 2 (the ground for 1) and tied to diaphragm 3; 0: none") \
X(h_3, 302, "h_3", Real, "parameter", "fixed", "exact", 2.5, "m", 0, 0, "Height of the wall of storey 3, in [0.3, 30]") \
X(b_3, 303, "b_3", Real, "parameter", "fixed", "exact", 0.15, "m", 0, 0, "Thickness of the wall of storey 3, in [0.02, 3] (also < h_3)") \
X(W_3, 304, "W_3", Real, "parameter", "fixed", "exact", 6622, "N/m", 0, 0, "Weight of the wall of storey 3 per metre of wall, in [10, 1e6]") \
X(psi_3, 305, "psi_3", Real, "parameter", "fixed", "exact", 0, "1", 0, 0, "Overburden ratio of the wall of storey 3: 2 overburden/W_3, in [0, 20] (its mass moves with the top)") \
X(tie_3, 306, "tie_3", Real, "parameter", "fixed", "exact", 100000000.0, "N/m2", 0, 0, "Tie between the top of the wall of storey 3 and diaphragm 3, N/m per m, in [0, 1e12] (the wall's K_d)") \
X(er_3, 307, "er_3", Real, "parameter", "fixed", "exact", 0.86, "1", 0, 0, "Coefficient of restitution of the wall of storey 3, in [0, 1]") \
X(hingeLaw_3, 308, "hingeLaw_3", Integer, "parameter", "fixed", "exact", 4, "", 0, 0, "Hinge law of the wall of storey 3: 1 rigid, 2 semiRigidPaper, 3 semiRigidHinge, 4 dohertyHinge") \
X(psiWeightOnly_3, 309, "psiWeightOnly_3", Real, "parameter", "fixed", "exact", 0, "1", 0, 0, "Weight-only overburden ratio of the wall of storey 3: 2 (weight of the walls above)/W_3, in [0, 20] (weight without mass: the walls above carry their own)") \
X(eTop_3, 349, "eTop_3", Real, "parameter", "fixed", "exact", 0, "m", 0, 0, "Eccentricity of the overburden of the wall of storey 3 (psi_3) from its centreline, positive toward +x, the inner face (joists bearing on it); |eTop_3| <= b_3/2 (RockingWall's eTop; the walls above bear on the centreline)") \
X(md_3, 310, "md_3", Real, "parameter", "fixed", "exact", 600, "kg/m", 0, 0, "Mass of diaphragm 3 per metre of wall, in (0, 1e9]") \
X(kd_3, 311, "kd_3", Real, "parameter", "fixed", "exact", 60000.0, "N/m2", 0, 0, "Stiffness of diaphragm 3 relative to its floor (initial, hysteretic laws), N/m per m, in [0, 1e15]") \
X(zetad_3, 312, "zetad_3", Real, "parameter", "fixed", "exact", 0.05, "1", 0, 0, "Damping ratio of diaphragm 3 on its own mass and spring, a dashpot 2 zetad sqrt(kd md), in [0, 2]") \
X(Fyd_3, 313, "Fyd_3", Real, "parameter", "fixed", "exact", 10000.0, "N/m", 0, 0, "Yield force of diaphragm 3 (hysteretic laws: diaphragmLaw 1 to 3), in (0, 1e15]") \
X(alphad_3, 314, "alphad_3", Real, "parameter", "fixed", "exact", 0.1, "1", 0, 0, "Post-yield stiffness ratio of diaphragm 3 (hysteretic laws: diaphragmLaw 1 to 3), in [0, 1]") \
X(m_3, 315, "m_3", Real, "parameter", "fixed", "exact", 4000, "kg/m", 0, 0, "Mass of floor 3 at the in-plane walls (rigidInPlane = 0), in (0, 1e9]") \
X(k_3, 316, "k_3", Real, "parameter", "fixed", "exact", 20000000.0, "N/m2", 0, 0, "Stiffness of storey 3's in-plane walls (rigidInPlane = 0), N/m per m, in (0, 1e15]") \
X(zetas_3, 317, "zetas_3", Real, "parameter", "fixed", "exact", 0.05, "1", 0, 0, "Damping ratio of storey 3's in-plane walls on floor mass and spring, a dashpot 2 zetas sqrt(k m), in [0, 2]") \
X(Fy_3, 318, "Fy_3", Real, "parameter", "fixed", "exact", 30000.0, "N/m", 0, 0, "Yield force of storey 3 (storeyLaw 1, 3), in (0, 1e15]") \
X(alpha_3, 319, "alpha_3", Real, "parameter", "fixed", "exact", 0.05, "1", 0, 0, "Post-yield stiffness ratio of storey 3 (storeyLaw 1, 3), in [0, 1]") \
X(q1_3, 320, "q1_3", Real, "local", "continuous", "exact", 0, "rad", 0.01, 0, "Rotation of the lower body of the wall of storey 3 (state)") \
X(q2_3, 321, "q2_3", Real, "local", "continuous", "exact", 0, "rad", 0.01, 0, "Rotation of the upper body of the wall of storey 3 (state)") \
X(dq1_3, 322, "dq1_3", Real, "local", "continuous", "exact", 0, "rad/s", 0.1, 320, "Rate of q1_3 (state, der(q1_3))") \
X(dq2_3, 323, "dq2_3", Real, "local", "continuous", "exact", 0, "rad/s", 0.1, 321, "Rate of q2_3 (state, der(q2_3))") \
X(der_dq1_3, 332, "der(dq1_3)", Real, "local", "continuous", "calculated", 0, "rad/s2", 0, 322, "Angular acceleration of the lower body of the wall of storey 3") \
X(der_dq2_3, 333, "der(dq2_3)", Real, "local", "continuous", "calculated", 0, "rad/s2", 0, 323, "Angular acceleration of the upper body of the wall of storey 3") \
X(u_floor_3, 324, "u_floor_3", Real, "local", "continuous", "exact", 0, "m", 0.01, 0, "Displacement of floor 3 relative to the ground (state; 0 with rigid in-plane walls)") \
X(v_floor_3, 325, "v_floor_3", Real, "local", "continuous", "exact", 0, "m/s", 0.1, 324, "Velocity of floor 3 (state, der(u_floor_3))") \
X(der_v_floor_3, 334, "der(v_floor_3)", Real, "local", "continuous", "calculated", 0, "m/s2", 0, 325, "Acceleration of floor 3 relative to the ground") \
X(z_storey_3, 326, "z_storey_3", Real, "local", "continuous", "exact", 0, "1", 1, 0, "Hysteretic variable (Bouc-Wen, bilinear) of storey 3, in [-1, 1] (state)") \
X(der_z_storey_3, 335, "der(z_storey_3)", Real, "local", "continuous", "calculated", 0, "1/s", 0, 326, "Rate of z_storey_3") \
X(u_diaph_3, 327, "u_diaph_3", Real, "output", "continuous", "exact", 0, "m", 0.01, 0, "Displacement of diaphragm 3 relative to the ground (state)") \
X(v_diaph_3, 328, "v_diaph_3", Real, "local", "continuous", "exact", 0, "m/s", 0.1, 327, "Velocity of diaphragm 3 (state, der(u_diaph_3))") \
X(der_v_diaph_3, 336, "der(v_diaph_3)", Real, "local", "continuous", "calculated", 0, "m/s2", 0, 328, "Acceleration of diaphragm 3 relative to the ground") \
X(z_diaph_3, 329, "z_diaph_3", Real, "local", "continuous", "exact", 0, "1", 1, 0, "Hysteretic variable (Bouc-Wen, bilinear) of diaphragm 3, in [-1, 1] (state)") \
X(der_z_diaph_3, 337, "der(z_diaph_3)", Real, "local", "continuous", "calculated", 0, "1/s", 0, 329, "Rate of z_diaph_3") \
X(work_storey_3, 330, "work_storey_3", Real, "local", "continuous", "exact", 0, "J/m", 0, 0, "Work of storey 3's spring force on its drift (state)") \
X(der_work_storey_3, 338, "der(work_storey_3)", Real, "local", "continuous", "calculated", 0, "W/m", 0, 330, "Power of storey 3's spring") \
X(work_diaph_3, 331, "work_diaph_3", Real, "local", "continuous", "exact", 0, "J/m", 0, 0, "Work of diaphragm 3's spring force on its deformation (state)") \
X(der_work_diaph_3, 339, "der(work_diaph_3)", Real, "local", "continuous", "calculated", 0, "W/m", 0, 331, "Power of diaphragm 3's spring") \
X(s1_3, 340, "s1_3", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Mid-height displacement of the wall of storey 3 relative to its base, q1 h/2") \
X(s2_3, 341, "s2_3", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Top displacement of the wall of storey 3 relative to its base, (q1 + q2) h/2") \
X(collapsed_3, 342, "collapsed_3", Boolean, "output", "discrete", "calculated", 0, "", 0, 0, "True once the wall of storey 3 has collapsed; it then leaves the scene (no more forces, its states frozen) and the rest runs on") \
X(impacts_3, 343, "impacts_3", Integer, "output", "discrete", "calculated", 0, "", 0, 0, "Base impacts of the wall of storey 3 (RockingWall's count)") \
X(F_top_3, 344, "F_top_3", Real, "output", "continuous", "calculated", 0, "N/m", 0, 0, "Force of the tie of storey 3 on diaphragm 3, tie_3 (s2_3 - u_top), +x") \
X(F_base_3, 345, "F_base_3", Real, "output", "continuous", "calculated", 0, "N/m", 0, 0, "Force the wall of storey 3 puts on its base (diaphragm 2, the ground for 1), +x") \
X(d_diaph_3, 346, "d_diaph_3", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Displacement of diaphragm 3 relative to its floor (its supports)") \
X(a_diaph_3, 347, "a_diaph_3", Real, "output", "continuous", "calculated", 0, "m/s2", 0, 0, "Absolute acceleration of diaphragm 3: the floor the wall of storey 4 stands on") \
X(a_base_3, 348, "a_base_3", Real, "output", "continuous", "calculated", 0, "m/s2", 0, 0, "Absolute acceleration of the floor the wall of storey 3 stands on (ag for 1, a_diaph_2 above)") \
X(hasWall_4, 401, "hasWall_4", Integer, "parameter", "fixed", "exact", 1, "", 0, 0, "1: storey 4 has a face-loaded wall standing on diaphragm 3 (the ground for 1) and tied to diaphragm 4; 0: none") \
X(h_4, 402, "h_4", Real, "parameter", "fixed", "exact", 2.5, "m", 0, 0, "Height of the wall of storey 4, in [0.3, 30]") \
X(b_4, 403, "b_4", Real, "parameter", "fixed", "exact", 0.15, "m", 0, 0, "Thickness of the wall of storey 4, in [0.02, 3] (also < h_4)") \
X(W_4, 404, "W_4", Real, "parameter", "fixed", "exact", 6622, "N/m", 0, 0, "Weight of the wall of storey 4 per metre of wall, in [10, 1e6]") \
X(psi_4, 405, "psi_4", Real, "parameter", "fixed", "exact", 0, "1", 0, 0, "Overburden ratio of the wall of storey 4: 2 overburden/W_4, in [0, 20] (its mass moves with the top)") \
X(tie_4, 406, "tie_4", Real, "parameter", "fixed", "exact", 100000000.0, "N/m2", 0, 0, "Tie between the top of the wall of storey 4 and diaphragm 4, N/m per m, in [0, 1e12] (the wall's K_d)") \
X(er_4, 407, "er_4", Real, "parameter", "fixed", "exact", 0.86, "1", 0, 0, "Coefficient of restitution of the wall of storey 4, in [0, 1]") \
X(hingeLaw_4, 408, "hingeLaw_4", Integer, "parameter", "fixed", "exact", 4, "", 0, 0, "Hinge law of the wall of storey 4: 1 rigid, 2 semiRigidPaper, 3 semiRigidHinge, 4 dohertyHinge") \
X(psiWeightOnly_4, 409, "psiWeightOnly_4", Real, "parameter", "fixed", "exact", 0, "1", 0, 0, "Weight-only overburden ratio of the wall of storey 4: 2 (weight of the walls above)/W_4, in [0, 20] (weight without mass: the walls above carry their own)") \
X(eTop_4, 449, "eTop_4", Real, "parameter", "fixed", "exact", 0, "m", 0, 0, "Eccentricity of the overburden of the wall of storey 4 (psi_4) from its centreline, positive toward +x, the inner face (joists bearing on it); |eTop_4| <= b_4/2 (RockingWall's eTop; the walls above bear on the centreline)") \
X(md_4, 410, "md_4", Real, "parameter", "fixed", "exact", 600, "kg/m", 0, 0, "Mass of diaphragm 4 per metre of wall, in (0, 1e9]") \
X(kd_4, 411, "kd_4", Real, "parameter", "fixed", "exact", 60000.0, "N/m2", 0, 0, "Stiffness of diaphragm 4 relative to its floor (initial, hysteretic laws), N/m per m, in [0, 1e15]") \
X(zetad_4, 412, "zetad_4", Real, "parameter", "fixed", "exact", 0.05, "1", 0, 0, "Damping ratio of diaphragm 4 on its own mass and spring, a dashpot 2 zetad sqrt(kd md), in [0, 2]") \
X(Fyd_4, 413, "Fyd_4", Real, "parameter", "fixed", "exact", 10000.0, "N/m", 0, 0, "Yield force of diaphragm 4 (hysteretic laws: diaphragmLaw 1 to 3), in (0, 1e15]") \
X(alphad_4, 414, "alphad_4", Real, "parameter", "fixed", "exact", 0.1, "1", 0, 0, "Post-yield stiffness ratio of diaphragm 4 (hysteretic laws: diaphragmLaw 1 to 3), in [0, 1]") \
X(m_4, 415, "m_4", Real, "parameter", "fixed", "exact", 4000, "kg/m", 0, 0, "Mass of floor 4 at the in-plane walls (rigidInPlane = 0), in (0, 1e9]") \
X(k_4, 416, "k_4", Real, "parameter", "fixed", "exact", 20000000.0, "N/m2", 0, 0, "Stiffness of storey 4's in-plane walls (rigidInPlane = 0), N/m per m, in (0, 1e15]") \
X(zetas_4, 417, "zetas_4", Real, "parameter", "fixed", "exact", 0.05, "1", 0, 0, "Damping ratio of storey 4's in-plane walls on floor mass and spring, a dashpot 2 zetas sqrt(k m), in [0, 2]") \
X(Fy_4, 418, "Fy_4", Real, "parameter", "fixed", "exact", 30000.0, "N/m", 0, 0, "Yield force of storey 4 (storeyLaw 1, 3), in (0, 1e15]") \
X(alpha_4, 419, "alpha_4", Real, "parameter", "fixed", "exact", 0.05, "1", 0, 0, "Post-yield stiffness ratio of storey 4 (storeyLaw 1, 3), in [0, 1]") \
X(q1_4, 420, "q1_4", Real, "local", "continuous", "exact", 0, "rad", 0.01, 0, "Rotation of the lower body of the wall of storey 4 (state)") \
X(q2_4, 421, "q2_4", Real, "local", "continuous", "exact", 0, "rad", 0.01, 0, "Rotation of the upper body of the wall of storey 4 (state)") \
X(dq1_4, 422, "dq1_4", Real, "local", "continuous", "exact", 0, "rad/s", 0.1, 420, "Rate of q1_4 (state, der(q1_4))") \
X(dq2_4, 423, "dq2_4", Real, "local", "continuous", "exact", 0, "rad/s", 0.1, 421, "Rate of q2_4 (state, der(q2_4))") \
X(der_dq1_4, 432, "der(dq1_4)", Real, "local", "continuous", "calculated", 0, "rad/s2", 0, 422, "Angular acceleration of the lower body of the wall of storey 4") \
X(der_dq2_4, 433, "der(dq2_4)", Real, "local", "continuous", "calculated", 0, "rad/s2", 0, 423, "Angular acceleration of the upper body of the wall of storey 4") \
X(u_floor_4, 424, "u_floor_4", Real, "local", "continuous", "exact", 0, "m", 0.01, 0, "Displacement of floor 4 relative to the ground (state; 0 with rigid in-plane walls)") \
X(v_floor_4, 425, "v_floor_4", Real, "local", "continuous", "exact", 0, "m/s", 0.1, 424, "Velocity of floor 4 (state, der(u_floor_4))") \
X(der_v_floor_4, 434, "der(v_floor_4)", Real, "local", "continuous", "calculated", 0, "m/s2", 0, 425, "Acceleration of floor 4 relative to the ground") \
X(z_storey_4, 426, "z_storey_4", Real, "local", "continuous", "exact", 0, "1", 1, 0, "Hysteretic variable (Bouc-Wen, bilinear) of storey 4, in [-1, 1] (state)") \
X(der_z_storey_4, 435, "der(z_storey_4)", Real, "local", "continuous", "calculated", 0, "1/s", 0, 426, "Rate of z_storey_4") \
X(u_diaph_4, 427, "u_diaph_4", Real, "output", "continuous", "exact", 0, "m", 0.01, 0, "Displacement of diaphragm 4 relative to the ground (state)") \
X(v_diaph_4, 428, "v_diaph_4", Real, "local", "continuous", "exact", 0, "m/s", 0.1, 427, "Velocity of diaphragm 4 (state, der(u_diaph_4))") \
X(der_v_diaph_4, 436, "der(v_diaph_4)", Real, "local", "continuous", "calculated", 0, "m/s2", 0, 428, "Acceleration of diaphragm 4 relative to the ground") \
X(z_diaph_4, 429, "z_diaph_4", Real, "local", "continuous", "exact", 0, "1", 1, 0, "Hysteretic variable (Bouc-Wen, bilinear) of diaphragm 4, in [-1, 1] (state)") \
X(der_z_diaph_4, 437, "der(z_diaph_4)", Real, "local", "continuous", "calculated", 0, "1/s", 0, 429, "Rate of z_diaph_4") \
X(work_storey_4, 430, "work_storey_4", Real, "local", "continuous", "exact", 0, "J/m", 0, 0, "Work of storey 4's spring force on its drift (state)") \
X(der_work_storey_4, 438, "der(work_storey_4)", Real, "local", "continuous", "calculated", 0, "W/m", 0, 430, "Power of storey 4's spring") \
X(work_diaph_4, 431, "work_diaph_4", Real, "local", "continuous", "exact", 0, "J/m", 0, 0, "Work of diaphragm 4's spring force on its deformation (state)") \
X(der_work_diaph_4, 439, "der(work_diaph_4)", Real, "local", "continuous", "calculated", 0, "W/m", 0, 431, "Power of diaphragm 4's spring") \
X(s1_4, 440, "s1_4", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Mid-height displacement of the wall of storey 4 relative to its base, q1 h/2") \
X(s2_4, 441, "s2_4", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Top displacement of the wall of storey 4 relative to its base, (q1 + q2) h/2") \
X(collapsed_4, 442, "collapsed_4", Boolean, "output", "discrete", "calculated", 0, "", 0, 0, "True once the wall of storey 4 has collapsed; it then leaves the scene (no more forces, its states frozen) and the rest runs on") \
X(impacts_4, 443, "impacts_4", Integer, "output", "discrete", "calculated", 0, "", 0, 0, "Base impacts of the wall of storey 4 (RockingWall's count)") \
X(F_top_4, 444, "F_top_4", Real, "output", "continuous", "calculated", 0, "N/m", 0, 0, "Force of the tie of storey 4 on diaphragm 4, tie_4 (s2_4 - u_top), +x") \
X(F_base_4, 445, "F_base_4", Real, "output", "continuous", "calculated", 0, "N/m", 0, 0, "Force the wall of storey 4 puts on its base (diaphragm 3, the ground for 1), +x") \
X(d_diaph_4, 446, "d_diaph_4", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Displacement of diaphragm 4 relative to its floor (its supports)") \
X(a_diaph_4, 447, "a_diaph_4", Real, "output", "continuous", "calculated", 0, "m/s2", 0, 0, "Absolute acceleration of diaphragm 4: the floor the wall of storey 5 stands on") \
X(a_base_4, 448, "a_base_4", Real, "output", "continuous", "calculated", 0, "m/s2", 0, 0, "Absolute acceleration of the floor the wall of storey 4 stands on (ag for 1, a_diaph_3 above)") \
X(hasWall_5, 501, "hasWall_5", Integer, "parameter", "fixed", "exact", 1, "", 0, 0, "1: storey 5 has a face-loaded wall standing on diaphragm 4 (the ground for 1) and tied to diaphragm 5; 0: none") \
X(h_5, 502, "h_5", Real, "parameter", "fixed", "exact", 2.5, "m", 0, 0, "Height of the wall of storey 5, in [0.3, 30]") \
X(b_5, 503, "b_5", Real, "parameter", "fixed", "exact", 0.15, "m", 0, 0, "Thickness of the wall of storey 5, in [0.02, 3] (also < h_5)") \
X(W_5, 504, "W_5", Real, "parameter", "fixed", "exact", 6622, "N/m", 0, 0, "Weight of the wall of storey 5 per metre of wall, in [10, 1e6]") \
X(psi_5, 505, "psi_5", Real, "parameter", "fixed", "exact", 0, "1", 0, 0, "Overburden ratio of the wall of storey 5: 2 overburden/W_5, in [0, 20] (its mass moves with the top)") \
X(tie_5, 506, "tie_5", Real, "parameter", "fixed", "exact", 100000000.0, "N/m2", 0, 0, "Tie between the top of the wall of storey 5 and diaphragm 5, N/m per m, in [0, 1e12] (the wall's K_d)") \
X(er_5, 507, "er_5", Real, "parameter", "fixed", "exact", 0.86, "1", 0, 0, "Coefficient of restitution of the wall of storey 5, in [0, 1]") \
X(hingeLaw_5, 508, "hingeLaw_5", Integer, "parameter", "fixed", "exact", 4, "", 0, 0, "Hinge law of the wall of storey 5: 1 rigid, 2 semiRigidPaper, 3 semiRigidHinge, 4 dohertyHinge") \
X(psiWeightOnly_5, 509, "psiWeightOnly_5", Real, "parameter", "fixed", "exact", 0, "1", 0, 0, "Weight-only overburden ratio of the wall of storey 5: 2 (weight of the walls above)/W_5, in [0, 20] (weight without mass: the walls above carry their own)") \
X(eTop_5, 549, "eTop_5", Real, "parameter", "fixed", "exact", 0, "m", 0, 0, "Eccentricity of the overburden of the wall of storey 5 (psi_5) from its centreline, positive toward +x, the inner face (joists bearing on it); |eTop_5| <= b_5/2 (RockingWall's eTop; the walls above bear on the centreline)") \
X(md_5, 510, "md_5", Real, "parameter", "fixed", "exact", 600, "kg/m", 0, 0, "Mass of diaphragm 5 per metre of wall, in (0, 1e9]") \
X(kd_5, 511, "kd_5", Real, "parameter", "fixed", "exact", 60000.0, "N/m2", 0, 0, "Stiffness of diaphragm 5 relative to its floor (initial, hysteretic laws), N/m per m, in [0, 1e15]") \
X(zetad_5, 512, "zetad_5", Real, "parameter", "fixed", "exact", 0.05, "1", 0, 0, "Damping ratio of diaphragm 5 on its own mass and spring, a dashpot 2 zetad sqrt(kd md), in [0, 2]") \
X(Fyd_5, 513, "Fyd_5", Real, "parameter", "fixed", "exact", 10000.0, "N/m", 0, 0, "Yield force of diaphragm 5 (hysteretic laws: diaphragmLaw 1 to 3), in (0, 1e15]") \
X(alphad_5, 514, "alphad_5", Real, "parameter", "fixed", "exact", 0.1, "1", 0, 0, "Post-yield stiffness ratio of diaphragm 5 (hysteretic laws: diaphragmLaw 1 to 3), in [0, 1]") \
X(m_5, 515, "m_5", Real, "parameter", "fixed", "exact", 4000, "kg/m", 0, 0, "Mass of floor 5 at the in-plane walls (rigidInPlane = 0), in (0, 1e9]") \
X(k_5, 516, "k_5", Real, "parameter", "fixed", "exact", 20000000.0, "N/m2", 0, 0, "Stiffness of storey 5's in-plane walls (rigidInPlane = 0), N/m per m, in (0, 1e15]") \
X(zetas_5, 517, "zetas_5", Real, "parameter", "fixed", "exact", 0.05, "1", 0, 0, "Damping ratio of storey 5's in-plane walls on floor mass and spring, a dashpot 2 zetas sqrt(k m), in [0, 2]") \
X(Fy_5, 518, "Fy_5", Real, "parameter", "fixed", "exact", 30000.0, "N/m", 0, 0, "Yield force of storey 5 (storeyLaw 1, 3), in (0, 1e15]") \
X(alpha_5, 519, "alpha_5", Real, "parameter", "fixed", "exact", 0.05, "1", 0, 0, "Post-yield stiffness ratio of storey 5 (storeyLaw 1, 3), in [0, 1]") \
X(q1_5, 520, "q1_5", Real, "local", "continuous", "exact", 0, "rad", 0.01, 0, "Rotation of the lower body of the wall of storey 5 (state)") \
X(q2_5, 521, "q2_5", Real, "local", "continuous", "exact", 0, "rad", 0.01, 0, "Rotation of the upper body of the wall of storey 5 (state)") \
X(dq1_5, 522, "dq1_5", Real, "local", "continuous", "exact", 0, "rad/s", 0.1, 520, "Rate of q1_5 (state, der(q1_5))") \
X(dq2_5, 523, "dq2_5", Real, "local", "continuous", "exact", 0, "rad/s", 0.1, 521, "Rate of q2_5 (state, der(q2_5))") \
X(der_dq1_5, 532, "der(dq1_5)", Real, "local", "continuous", "calculated", 0, "rad/s2", 0, 522, "Angular acceleration of the lower body of the wall of storey 5") \
X(der_dq2_5, 533, "der(dq2_5)", Real, "local", "continuous", "calculated", 0, "rad/s2", 0, 523, "Angular acceleration of the upper body of the wall of storey 5") \
X(u_floor_5, 524, "u_floor_5", Real, "local", "continuous", "exact", 0, "m", 0.01, 0, "Displacement of floor 5 relative to the ground (state; 0 with rigid in-plane walls)") \
X(v_floor_5, 525, "v_floor_5", Real, "local", "continuous", "exact", 0, "m/s", 0.1, 524, "Velocity of floor 5 (state, der(u_floor_5))") \
X(der_v_floor_5, 534, "der(v_floor_5)", Real, "local", "continuous", "calculated", 0, "m/s2", 0, 525, "Acceleration of floor 5 relative to the ground") \
X(z_storey_5, 526, "z_storey_5", Real, "local", "continuous", "exact", 0, "1", 1, 0, "Hysteretic variable (Bouc-Wen, bilinear) of storey 5, in [-1, 1] (state)") \
X(der_z_storey_5, 535, "der(z_storey_5)", Real, "local", "continuous", "calculated", 0, "1/s", 0, 526, "Rate of z_storey_5") \
X(u_diaph_5, 527, "u_diaph_5", Real, "output", "continuous", "exact", 0, "m", 0.01, 0, "Displacement of diaphragm 5 relative to the ground (state)") \
X(v_diaph_5, 528, "v_diaph_5", Real, "local", "continuous", "exact", 0, "m/s", 0.1, 527, "Velocity of diaphragm 5 (state, der(u_diaph_5))") \
X(der_v_diaph_5, 536, "der(v_diaph_5)", Real, "local", "continuous", "calculated", 0, "m/s2", 0, 528, "Acceleration of diaphragm 5 relative to the ground") \
X(z_diaph_5, 529, "z_diaph_5", Real, "local", "continuous", "exact", 0, "1", 1, 0, "Hysteretic variable (Bouc-Wen, bilinear) of diaphragm 5, in [-1, 1] (state)") \
X(der_z_diaph_5, 537, "der(z_diaph_5)", Real, "local", "continuous", "calculated", 0, "1/s", 0, 529, "Rate of z_diaph_5") \
X(work_storey_5, 530, "work_storey_5", Real, "local", "continuous", "exact", 0, "J/m", 0, 0, "Work of storey 5's spring force on its drift (state)") \
X(der_work_storey_5, 538, "der(work_storey_5)", Real, "local", "continuous", "calculated", 0, "W/m", 0, 530, "Power of storey 5's spring") \
X(work_diaph_5, 531, "work_diaph_5", Real, "local", "continuous", "exact", 0, "J/m", 0, 0, "Work of diaphragm 5's spring force on its deformation (state)") \
X(der_work_diaph_5, 539, "der(work_diaph_5)", Real, "local", "continuous", "calculated", 0, "W/m", 0, 531, "Power of diaphragm 5's spring") \
X(s1_5, 540, "s1_5", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Mid-height displacement of the wall of storey 5 relative to its base, q1 h/2") \
X(s2_5, 541, "s2_5", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Top displacement of the wall of storey 5 relative to its base, (q1 + q2) h/2") \
X(collapsed_5, 542, "collapsed_5", Boolean, "output", "discrete", "calculated", 0, "", 0, 0, "True once the wall of storey 5 has collapsed; it then leaves the scene (no more forces, its states frozen) and the rest runs on") \
X(impacts_5, 543, "impacts_5", Integer, "output", "discrete", "calculated", 0, "", 0, 0, "Base impacts of the wall of storey 5 (RockingWall's count)") \
X(F_top_5, 544, "F_top_5", Real, "output", "continuous", "calculated", 0, "N/m", 0, 0, "Force of the tie of storey 5 on diaphragm 5, tie_5 (s2_5 - u_top), +x") \
X(F_base_5, 545, "F_base_5", Real, "output", "continuous", "calculated", 0, "N/m", 0, 0, "Force the wall of storey 5 puts on its base (diaphragm 4, the ground for 1), +x") \
X(d_diaph_5, 546, "d_diaph_5", Real, "output", "continuous", "calculated", 0, "m", 0, 0, "Displacement of diaphragm 5 relative to its floor (its supports)") \
X(a_diaph_5, 547, "a_diaph_5", Real, "output", "continuous", "calculated", 0, "m/s2", 0, 0, "Absolute acceleration of diaphragm 5: the floor the wall of storey 6 stands on") \
X(a_base_5, 548, "a_base_5", Real, "output", "continuous", "calculated", 0, "m/s2", 0, 0, "Absolute acceleration of the floor the wall of storey 5 stands on (ag for 1, a_diaph_4 above)")
/* clang-format on */

/* The event indicators as variables, in the order of rw_scene_indicators: RW_NZ per storey (the
 * wall's own, RW_Z_* of rw_physics.h). Z(ID, VR, DESCRIPTION), one per line. */
#define BW_EVENT_INDICATORS(Z) \
Z(z_base_1, 150, "Wall of storey 1: base hinge (impact or opening); 1 without a standing wall") \
Z(z_mid_1, 151, "Wall of storey 1: mid-height hinge (switch or opening); 1 without a standing wall") \
Z(z_break1_1, 152, "Wall of storey 1: hinge-law breakpoint 1; 1 without a standing wall") \
Z(z_break2_1, 153, "Wall of storey 1: hinge-law breakpoint 2; 1 without a standing wall") \
Z(z_break3_1, 154, "Wall of storey 1: hinge-law breakpoint 3; 1 without a standing wall") \
Z(z_break4_1, 155, "Wall of storey 1: hinge-law breakpoint 4; 1 without a standing wall") \
Z(z_collapse_1, 156, "Wall of storey 1: stability margin (collapse at 0); 1 without a standing wall") \
Z(z_topple_1, 157, "Wall of storey 1: toppling limit of a body; 1 without a standing wall") \
Z(z_base_2, 250, "Wall of storey 2: base hinge (impact or opening); 1 without a standing wall") \
Z(z_mid_2, 251, "Wall of storey 2: mid-height hinge (switch or opening); 1 without a standing wall") \
Z(z_break1_2, 252, "Wall of storey 2: hinge-law breakpoint 1; 1 without a standing wall") \
Z(z_break2_2, 253, "Wall of storey 2: hinge-law breakpoint 2; 1 without a standing wall") \
Z(z_break3_2, 254, "Wall of storey 2: hinge-law breakpoint 3; 1 without a standing wall") \
Z(z_break4_2, 255, "Wall of storey 2: hinge-law breakpoint 4; 1 without a standing wall") \
Z(z_collapse_2, 256, "Wall of storey 2: stability margin (collapse at 0); 1 without a standing wall") \
Z(z_topple_2, 257, "Wall of storey 2: toppling limit of a body; 1 without a standing wall") \
Z(z_base_3, 350, "Wall of storey 3: base hinge (impact or opening); 1 without a standing wall") \
Z(z_mid_3, 351, "Wall of storey 3: mid-height hinge (switch or opening); 1 without a standing wall") \
Z(z_break1_3, 352, "Wall of storey 3: hinge-law breakpoint 1; 1 without a standing wall") \
Z(z_break2_3, 353, "Wall of storey 3: hinge-law breakpoint 2; 1 without a standing wall") \
Z(z_break3_3, 354, "Wall of storey 3: hinge-law breakpoint 3; 1 without a standing wall") \
Z(z_break4_3, 355, "Wall of storey 3: hinge-law breakpoint 4; 1 without a standing wall") \
Z(z_collapse_3, 356, "Wall of storey 3: stability margin (collapse at 0); 1 without a standing wall") \
Z(z_topple_3, 357, "Wall of storey 3: toppling limit of a body; 1 without a standing wall") \
Z(z_base_4, 450, "Wall of storey 4: base hinge (impact or opening); 1 without a standing wall") \
Z(z_mid_4, 451, "Wall of storey 4: mid-height hinge (switch or opening); 1 without a standing wall") \
Z(z_break1_4, 452, "Wall of storey 4: hinge-law breakpoint 1; 1 without a standing wall") \
Z(z_break2_4, 453, "Wall of storey 4: hinge-law breakpoint 2; 1 without a standing wall") \
Z(z_break3_4, 454, "Wall of storey 4: hinge-law breakpoint 3; 1 without a standing wall") \
Z(z_break4_4, 455, "Wall of storey 4: hinge-law breakpoint 4; 1 without a standing wall") \
Z(z_collapse_4, 456, "Wall of storey 4: stability margin (collapse at 0); 1 without a standing wall") \
Z(z_topple_4, 457, "Wall of storey 4: toppling limit of a body; 1 without a standing wall") \
Z(z_base_5, 550, "Wall of storey 5: base hinge (impact or opening); 1 without a standing wall") \
Z(z_mid_5, 551, "Wall of storey 5: mid-height hinge (switch or opening); 1 without a standing wall") \
Z(z_break1_5, 552, "Wall of storey 5: hinge-law breakpoint 1; 1 without a standing wall") \
Z(z_break2_5, 553, "Wall of storey 5: hinge-law breakpoint 2; 1 without a standing wall") \
Z(z_break3_5, 554, "Wall of storey 5: hinge-law breakpoint 3; 1 without a standing wall") \
Z(z_break4_5, 555, "Wall of storey 5: hinge-law breakpoint 4; 1 without a standing wall") \
Z(z_collapse_5, 556, "Wall of storey 5: stability margin (collapse at 0); 1 without a standing wall") \
Z(z_topple_5, 557, "Wall of storey 5: toppling limit of a body; 1 without a standing wall")

#define BW_VR_ENUM(ID, VR, NAME, TYPE, CAUS, VARIAB, INIT, START, UNIT, NOM, DER, DESC) BW_VR_##ID = VR,
enum { BW_VARIABLES(BW_VR_ENUM) BW_VR_MAX_PLUS_ONE_DUMMY };
#undef BW_VR_ENUM

#endif
