/* RockingWall parameters: the one table every parameter is defined in.
 *
 * From this table come the C struct rw_params, the defaults, the range checks and the setters
 * (rw_parameters.c), the <ScalarVariable>s of the parameters in modelDescription.xml and the
 * parameter table of docs/model.md (both written by scripts/gen_model_description.py, which
 * parses the P(...) lines), and a test checks the reference solver's defaults and ranges against
 * it. Adding a parameter is one line here plus its use in the physics (docs/development.md).
 *
 * RW_PARAMETERS(P) lists one P(...) per line with the fields
 *   P(ID, VR, TYPE, UNIT, DEFAULT, MIN, MAX, DESCRIPTION)
 * TYPE: Real | Integer. [MIN, MAX] is the closed range a value must lie in; rules that tie
 * parameters together are in rw_params_validate(). Ranges are physical: each bound keeps the
 * model meaningful (a masonry wall, a diaphragm, a restitution coefficient), not just finite.
 * Keep one entry per line (the generator parses the lines). */
#ifndef RW_PARAMETERS_H
#define RW_PARAMETERS_H

#include <stddef.h>

#include "rw_symbols.h" /* the FMI2_FUNCTION_PREFIX of every external symbol */

/* clang-format off */
#define RW_PARAMETERS(P) \
P(h,           1, Real,    "m",     2.5,    0.3,   30.0, "Wall height") \
P(b,           2, Real,    "m",     0.15,   0.02,  3.0,  "Wall thickness (also < h)") \
P(W,           3, Real,    "N/m",   6622,   10.0,  1e6,  "Wall weight per metre of wall") \
P(psi,         4, Real,    "1",     0,      0.0,   20.0, "Overburden ratio Wd/W1: weight carried at the top over the weight of ONE body, W1 = W/2 (so psi = 2*overburden/W); the overburden moves with the top as mass") \
P(Kd,          5, Real,    "N/m2",  1e6,    0.0,   1e12, "Top spring stiffness, N/m per metre of wall (flexibleTop)") \
P(er,          6, Real,    "1",     0.86,   0.0,   1.0,  "Coefficient of restitution at base impacts") \
P(g,           7, Real,    "m/s2",  9.81,   1.0,   30.0, "Gravity") \
P(delta1Ratio, 8, Real,    "1",     0.05,   1e-4,  0.5,  "Delta_1/Delta_u (Eq. 5.1)") \
P(delta2A,     9, Real,    "1",     0.92,   0.0,   10.0, "Delta_2 = delta2A*Delta_1 + delta2B*Delta_u (Eq. 5.2)") \
P(delta2B,    10, Real,    "1",     0.21,   0.0,   1.0,  "See delta2A; together they must give Delta_1 < Delta_2 < Delta_u") \
P(hingeSat,   11, Real,    "1",     2.0,    0.1,   20.0, "semiRigidHinge, semiRigidPaper: hinge moments saturate at mid-height displacement hingeSat*Delta_1 (also < Delta_u)") \
P(restRate,   12, Real,    "rad/s", 1e-5,   1e-12, 0.1,  "Rigid hinges close when the relative rate after an impact or switch is below this") \
P(support,    13, Integer, "",      3,      1,     3,    "Top support: 1 free top (parapet), 2 pinned top (simplySupported), 3 spring Kd (flexibleTop)") \
P(hingeLaw,   14, Integer, "",      4,      1,     4,    "Hinge law: 1 rigid, 2 semiRigidPaper, 3 semiRigidHinge, 4 dohertyHinge (simplySupported: 2-4 all mean Doherty's trilinear)") \
P(pointing,   15, Real,    "m",     0,      0.0,   1.5,  "Depth of recessed mortar pointing on EACH face: the reactions' lever arms use the effective thickness t = b - 2*pointing (also < b/2)") \
P(eBaseRatio, 16, Real,    "1",     1,      0.0,   1.0,  "Base reaction's distance from the centreline over t/2: 1 on the face of the effective section (the paper), less when set in from it") \
P(eHingeRatio, 17, Real,   "1",     1,      0.0,   1.0,  "Mid-height hinge reaction's distance from the centreline over t/2 (1: the face)") \
P(eTop,       18, Real,    "m",     0,      -1.5,  1.5,  "Eccentricity of the overburden Wd (psi) from the centreline, positive toward +x, the inner face (joists bearing on it); also within b/2") \
P(psiWeightOnly, 19, Real, "1",     0,      0.0,   20.0, "Weight-only overburden Wo/W1 at the top's centreline: weight without mass (the walls above, whose mass their own equations carry)")
/* clang-format on */

#define RW_C_TYPE_Real double
#define RW_C_TYPE_Integer int
#define RW_PARAM_FIELD(ID, VR, TYPE, UNIT, DEF, LO, HI, DESC) RW_C_TYPE_##TYPE ID;
typedef struct {
    RW_PARAMETERS(RW_PARAM_FIELD)
} rw_params;
#undef RW_PARAM_FIELD

typedef struct {
    const char *name;
    unsigned vr;
    int is_integer;
    const char *unit;
    double def, lo, hi;
    size_t offset; /* of the field in rw_params */
    const char *description;
} rw_param_info;

extern const rw_param_info RW_PARAM_INFO[];
extern const size_t RW_NUMBER_OF_PARAMETERS;

const rw_param_info *rw_param_by_name(const char *name);
const rw_param_info *rw_param_by_vr(unsigned vr);

void rw_params_default(rw_params *p);
/* Range check of one value (NaN/inf, non-integers for Integer parameters and values outside
 * [lo, hi] rejected). 0 = ok, else msg filled with the name, the value and the range. */
int rw_param_check(const rw_param_info *info, double value, char *msg, size_t n);
double rw_param_get(const rw_params *p, const rw_param_info *info);
/* Checks, then stores. 0 = ok, else msg filled and p unchanged. */
int rw_param_set(rw_params *p, const rw_param_info *info, double value, char *msg, size_t n);
#endif
