/* Diaphragm: the one source of truth for the Diaphragm FMU's variables (same format as
 * fmu_src/models/RockingWall/model_variables.h; scripts/gen_model_description.py generates
 * fmu_src/models/Diaphragm/fmi2/modelDescription.xml from it).
 *
 * X(ID, VR, NAME, TYPE, CAUSALITY, VARIABILITY, INITIAL, START, UNIT, NOMINAL, DERIVATIVE_OF, DESCRIPTION) */
#ifndef DIAPHRAGM_VARIABLES_H
#define DIAPHRAGM_VARIABLES_H

#define DG_MODEL_IDENTIFIER "Diaphragm"
#define DG_GUID "{6f1f2a52-3c49-4a8e-9f0e-5d2b1c7a9e41}"
#define DG_NUMBER_OF_STATES 2
#define DG_NUMBER_OF_EVENT_INDICATORS 0

/* clang-format off */
#define DG_VARIABLES(X) \
X(m,          1, "m",          Real, "parameter", "fixed",      "exact",      2000,  "kg/m",  0,    0,  "Diaphragm mass per metre of wall (> 0)") \
X(k,          2, "k",          Real, "parameter", "fixed",      "exact",      7e5,   "N/m2",  0,    0,  "Diaphragm stiffness per metre of wall, N/m per m (> 0)") \
X(zeta,       3, "zeta",       Real, "parameter", "fixed",      "exact",      0.05,  "1",     0,    0,  "Damping ratio, in [0, 1]") \
X(ag,        20, "ag",         Real, "input",     "continuous", "",           0,     "m/s2",  0,    0,  "Ground acceleration, positive toward +x") \
X(F_top,     21, "F_top",      Real, "input",     "continuous", "",           0,     "N/m",   0,    0,  "Force of the wall on the diaphragm, positive toward +x (RockingWall.F_top)") \
X(u,         30, "u",          Real, "output",    "continuous", "exact",      0,     "m",     0.01, 0,  "Displacement relative to the ground (state; feeds RockingWall.u_top)") \
X(v,         31, "v",          Real, "output",    "continuous", "exact",      0,     "m/s",   0.1,  30, "Velocity relative to the ground (state, der(u))") \
X(der_v,     32, "der(v)",     Real, "local",     "continuous", "calculated", 0,     "m/s2",  0,    31, "Acceleration relative to the ground") \
X(energy,    33, "energy",     Real, "output",    "continuous", "calculated", 0,     "J/m",   0,    0,  "Kinetic + strain energy m v^2/2 + k u^2/2") \
X(P_ground,  34, "P_ground",   Real, "output",    "continuous", "calculated", 0,     "W/m",   0,    0,  "Power of the ground motion, -m ag v") \
X(P_damping, 35, "P_damping",  Real, "output",    "continuous", "calculated", 0,     "W/m",   0,    0,  "Power dissipated by damping, c v^2 (>= 0)") \
X(P_wall,    36, "P_wall",     Real, "output",    "continuous", "calculated", 0,     "W/m",   0,    0,  "Power of the wall force, F_top v")
/* clang-format on */

/* no event indicators (the format of RW_EVENT_INDICATORS in fmu_src/models/RockingWall/model_variables.h) */
#define DG_EVENT_INDICATORS(Z)

#define DG_VR_ENUM(ID, VR, NAME, TYPE, CAUS, VARIAB, INIT, START, UNIT, NOM, DER, DESC) DG_VR_##ID = VR,
enum { DG_VARIABLES(DG_VR_ENUM) DG_VR_MAX_PLUS_ONE_DUMMY };
#undef DG_VR_ENUM

/* ModelStructure: what each output and state derivative depends on. A state that is also an
 * output depends on itself (importers read "" as "depends on nothing");
 * tests/python/test_model_structure.py checks every entry by finite differences. */
#define DG_DEPENDENCIES(D) \
D(u,         "u") \
D(v,         "v") \
D(der_v,     "u v ag F_top") \
D(energy,    "u v") \
D(P_ground,  "v ag") \
D(P_damping, "v") \
D(P_wall,    "v F_top")

#endif
