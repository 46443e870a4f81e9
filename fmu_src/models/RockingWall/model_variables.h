/* RockingWall: the one source of truth for the FMU's variables other than the parameters (those
 * are the table of rw_parameters.h, listed first in modelDescription.xml).
 * scripts/gen_model_description.py generates modelDescription.xml from the two tables;
 * fmi2Functions.c uses the same tables for value references, types and settability.
 *
 * RW_VARIABLES(X) lists one X(...) per line with the fields
 *   X(ID, VR, NAME, TYPE, CAUSALITY, VARIABILITY, INITIAL, START, UNIT, NOMINAL, DERIVATIVE_OF, DESCRIPTION)
 * TYPE: Real | Integer | Boolean | String. INITIAL "" = not given (inputs). UNIT "" = none. NOMINAL 0 = none.
 * DERIVATIVE_OF: value reference of the state this variable is the derivative of, 0 = none.
 * Keep one entry per line (the generator parses the lines). */
#ifndef RW_MODEL_VARIABLES_H
#define RW_MODEL_VARIABLES_H

#include "rw_parameters.h"

#define RW_MODEL_IDENTIFIER "RockingWall"
#define RW_GUID "{1631bb30-f128-4b07-ae72-de0576cbb789}"
#define RW_NUMBER_OF_STATES 4
#define RW_NUMBER_OF_EVENT_INDICATORS 8

/* clang-format off */
#define RW_VARIABLES(X) \
X(ag,         20, "ag",          Real,    "input",     "continuous", "",           0,      "m/s2",   0,    0,  "Ground acceleration, positive toward +x") \
X(u_top,      21, "u_top",       Real,    "input",     "continuous", "",           0,      "m",      0,    0,  "Displacement of the diaphragm end of the top spring relative to the ground") \
X(agFile,     60, "agFile",      String,  "parameter", "fixed",      "exact",      "",     "",       0,    0,  "Ground-motion record the FMU reads itself at initialization, so that its answer does not depend on the importer's communication step: a PEER .AT2 file (values in g, times the parameter g) or a CSV of time [s] and acceleration [m/s2]; the input ag adds to it. Empty: none") \
X(agScale,    61, "agScale",     Real,    "parameter", "fixed",      "exact",      1,      "1",      0,    0,  "Factor on the accelerations of agFile") \
X(s1,         30, "s1",          Real,    "output",    "continuous", "calculated", 0,      "m",      0,    0,  "Mid-height displacement q1*h/2") \
X(s2,         31, "s2",          Real,    "output",    "continuous", "calculated", 0,      "m",      0,    0,  "Top displacement (q1+q2)*h/2 (simplySupported: 0)") \
X(F_top,      32, "F_top",       Real,    "output",    "continuous", "calculated", 0,      "N/m",    0,    0,  "Force of the top spring on the diaphragm, Kd*(s2 - u_top) (flexibleTop only)") \
X(energy,     33, "energy",      Real,    "output",    "continuous", "calculated", 0,      "J/m",    0,    0,  "Mechanical energy of the wall (kinetic + spring + gravity + hinges)") \
X(collapsed,  34, "collapsed",   Boolean, "output",    "discrete",   "calculated", 0,      "",       0,    0,  "True once the wall has passed its instability point") \
X(impacts,    35, "impacts",     Integer, "output",    "discrete",   "calculated", 0,      "",       0,    0,  "Number of base impacts: base crossings after an uplift (rigid hinges: every crossing; semi-rigid laws: only when the base passed its elastic range since the last crossing, docs/model.md)") \
X(condition,  36, "condition",   Integer, "output",    "discrete",   "calculated", 0,      "",       0,    0,  "Paper condition 1-4 from the hinge sides; 0 while a rigid hinge is closed") \
X(P_ground,   37, "P_ground",   Real,    "output",    "continuous", "calculated", 0,      "W/m",    0,    0,  "Power of the ground motion on the wall (energy bookkeeping: d(energy)/dt = P_ground - F_top*der(u_top) between impacts)") \
X(dissipated, 38, "dissipated", Real,    "output",    "discrete",   "calculated", 0,      "J/m",    0,    0,  "Energy lost so far in impacts and hinge closings (sum of the drops of energy at events)") \
X(F_base,     47, "F_base",      Real,    "output",    "continuous", "calculated", 0,      "N/m",    0,    0,  "Horizontal force of the wall on its base (with the overburden's inertia), positive toward +x: -(W+Wd)/g*ag - sum of body mass*horizontal acceleration relative to the ground - F_top (simplySupported: base and top support together)") \
X(q1,         40, "q1",          Real,    "local",     "continuous", "exact",      0,      "rad",    0.01, 0,  "Rotation of the lower body (state)") \
X(q2,         41, "q2",          Real,    "local",     "continuous", "exact",      0,      "rad",    0.01, 0,  "Rotation of the upper body (state)") \
X(dq1,        42, "dq1",         Real,    "local",     "continuous", "exact",      0,      "rad/s",  0.1,  40, "Rate of q1 (state, der(q1))") \
X(dq2,        43, "dq2",         Real,    "local",     "continuous", "exact",      0,      "rad/s",  0.1,  41, "Rate of q2 (state, der(q2))") \
X(der_dq1,    44, "der(dq1)",    Real,    "local",     "continuous", "calculated", 0,      "rad/s2", 0,    42, "Angular acceleration of the lower body") \
X(der_dq2,    45, "der(dq2)",    Real,    "local",     "continuous", "calculated", 0,      "rad/s2", 0,    43, "Angular acceleration of the upper body")
/* clang-format on */

/* The event indicators as variables, in the order of rw_event_indicators (RW_Z_* of rw_physics.h).
 * FMI 3.0 names the event indicators in <ModelStructure> by value reference, so the FMI 3.0
 * modelDescription.xml lists these as local Float64 variables; the FMI 2.0 one only counts them.
 * Z(ID, VR, DESCRIPTION), one per line. */
#define RW_EVENT_INDICATORS(Z) \
Z(z_base,     50, "Base hinge: opens to an impact (open) or to opening (closed); changes sign at the event") \
Z(z_mid,      51, "Mid-height hinge (flexibleTop): side switch (open) or opening (closed)") \
Z(z_break1,   52, "Hinge-law breakpoint 1 (base hinge, first kink of the moment-rotation law)") \
Z(z_break2,   53, "Hinge-law breakpoint 2 (base hinge, second kink)") \
Z(z_break3,   54, "Hinge-law breakpoint 3 (mid-height hinge, first kink)") \
Z(z_break4,   55, "Hinge-law breakpoint 4 (mid-height hinge, second kink)") \
Z(z_collapse, 56, "Stability margin, > 0 while the wall can still return (collapse at 0)") \
Z(z_topple,   57, "2DOF: 1 - max(|q1|, |q2|)/(2b/h), the geometric toppling limit of a body")

/* value references as an enum: RW_VR_h, RW_VR_q1, ... */
#define RW_VR_ENUM(ID, VR, NAME, TYPE, CAUS, VARIAB, INIT, START, UNIT, NOM, DER, DESC) RW_VR_##ID = VR,
#define RW_VR_PARAM_ENUM(ID, VR, TYPE, UNIT, DEF, LO, HI, DESC) RW_VR_##ID = VR,
enum { RW_PARAMETERS(RW_VR_PARAM_ENUM) RW_VARIABLES(RW_VR_ENUM) RW_VR_MAX_PLUS_ONE_DUMMY };
#undef RW_VR_ENUM
#undef RW_VR_PARAM_ENUM

/* Continuous states in the order of fmi2GetContinuousStates (x = q1, q2, dq1, dq2). */
#define RW_STATE_VRS {RW_VR_q1, RW_VR_q2, RW_VR_dq1, RW_VR_dq2}

/* ModelStructure: D(ID, "space-separated names of the states and inputs it depends on") for every
 * output and every state derivative (superset over all models and regimes). */
#define RW_DEPENDENCIES(D) \
D(s1,        "q1") \
D(s2,        "q1 q2") \
D(F_top,     "q1 q2 u_top") \
D(energy,    "q1 q2 dq1 dq2 u_top") \
D(collapsed, "") \
D(impacts,   "") \
D(condition, "") \
D(P_ground,  "q1 q2 dq1 dq2 ag") \
D(dissipated, "") \
D(F_base,    "q1 q2 dq1 ag u_top") \
D(dq1,       "dq1") \
D(dq2,       "dq1 dq2") \
D(der_dq1,   "q1 q2 ag u_top") \
D(der_dq2,   "q1 q2 ag u_top")

#endif
