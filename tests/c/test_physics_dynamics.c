/* Unit tests of the wall's parameters and dynamics (fmu_src/wall/rw_parameters.c, rw_dynamics.c):
 * defaults, ranges and rules, the matrices against scripts/derive_equations.py's sympy numbers,
 * Doherty's Table 5.1 and trilinear law.
 * Usage: test_physics_dynamics derive_equations.json  (written by scripts/derive_equations.py --json) */
#include "check.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "physics_check.h"
#include "rw_physics.h"

/* ---- tiny JSON number extractor: follows a path of keys, then reads the n next numbers ------ */
static char *read_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    long n;
    char *buf;
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = (char *)malloc((size_t)n + 1);
    if (buf && fread(buf, 1, (size_t)n, f) != (size_t)n) { free(buf); buf = NULL; }
    if (buf) buf[n] = '\0';
    fclose(f);
    return buf;
}

/* keys: NULL-terminated path, e.g. {"conditions", "1", "A", NULL}; returns count read */
/* keys: NULL-terminated path, e.g. {"conditions", "1", "A", NULL}; returns count read */
static int json_numbers(const char *text, const char *const *keys, double *out, int n)
{
    const char *p = text;
    int k = 0;
    char pat[64];
    for (; *keys; keys++) {
        snprintf(pat, sizeof pat, "\"%s\"", *keys);
        p = strstr(p, pat);
        if (!p) return 0;
        p += strlen(pat);
    }
    while (k < n && *p) {
        if (strchr("-+0123456789.", *p)) {
            char *end;
            out[k++] = strtod(p, &end);
            p = end;
        } else if (*p == '"' || *p == '}') {
            break; /* next key or end of object */
        } else {
            p++;
        }
    }
    return k;
}

static void test_defaults_valid(void)
{
    rw_params p;
    char msg[256];
    rw_params_default(&p);
    CHECK(rw_params_validate(&p, msg, sizeof msg) == 0, "defaults invalid: %s", msg);
    CHECK(p.support == RW_FLEXIBLE_TOP && p.h == 2.5 && p.W == 6622.0, "defaults not from the table");
}

/* every parameter's range: both bounds accepted, just beyond each refused with the range named */
static void test_ranges(void)
{
    size_t i;
    char msg[512];
    for (i = 0; i < RW_NUMBER_OF_PARAMETERS; i++) {
        const rw_param_info *q = &RW_PARAM_INFO[i];
        const double step = q->is_integer ? 1.0 : 1e-6 * fmax(fabs(q->hi), 1e-300);
        CHECK(rw_param_check(q, q->lo, msg, sizeof msg) == 0, "%s: lower bound refused: %s", q->name, msg);
        CHECK(rw_param_check(q, q->hi, msg, sizeof msg) == 0, "%s: upper bound refused: %s", q->name, msg);
        CHECK(rw_param_check(q, q->hi + step, msg, sizeof msg) && strstr(msg, q->name) && strstr(msg, "allowed ["),
              "%s: above range accepted: %s", q->name, msg);
        CHECK(rw_param_check(q, q->lo - (q->is_integer ? 1.0 : fmax(1e-6 * fabs(q->lo), 1e-300)), msg, sizeof msg),
              "%s: below range accepted", q->name);
        CHECK(rw_param_check(q, NAN, msg, sizeof msg), "%s: NaN accepted", q->name);
        CHECK(rw_param_by_vr(q->vr) == q && rw_param_by_name(q->name) == q, "%s: lookup", q->name);
    }
}

static void test_validation(void)
{
    rw_params p;
    char msg[256];
    CHECK(rw_param_check(rw_param_by_name("h"), -1.0, msg, sizeof msg) && strstr(msg, "h = -1"), "h=-1 accepted: %s", msg);
    CHECK(rw_param_check(rw_param_by_name("er"), 1.5, msg, sizeof msg), "er=1.5 accepted");
    CHECK(rw_param_check(rw_param_by_name("Kd"), 0.0, msg, sizeof msg) == 0, "Kd=0 rejected");
    CHECK(rw_param_check(rw_param_by_name("support"), 4, msg, sizeof msg), "support=4 accepted");
    CHECK(rw_param_check(rw_param_by_name("hingeLaw"), 2.5, msg, sizeof msg), "hingeLaw=2.5 accepted");
    CHECK(rw_param_check(rw_param_by_name("hingeSat"), 1e300, msg, sizeof msg), "hingeSat=1e300 accepted");
    CHECK(rw_param_by_name("model") == NULL, "a parameter called model remains");
    rw_params_default(&p);
    p.b = 2.9;
    p.h = 2.5;
    CHECK(rw_params_validate(&p, msg, sizeof msg) && strstr(msg, "b = 2.9"), "b >= h accepted: %s", msg);
    rw_params_default(&p);
    p.delta2B = 0.99;
    CHECK(rw_params_validate(&p, msg, sizeof msg) && strstr(msg, "delta"), "Delta_2 > Delta_u accepted");
    rw_params_default(&p);
    p.hingeSat = 19.0;
    p.delta1Ratio = 0.1;
    CHECK(rw_params_validate(&p, msg, sizeof msg) && strstr(msg, "hingeSat"), "saturation past Delta_u accepted");
}

/* json_numbers under an optional section (NULL: the top level) */
static int section_numbers(const char *json, const char *section, const char *const *keys, double *out, int n)
{
    const char *path[6];
    int k = 0;
    if (section) path[k++] = section;
    while (*keys && k < 5) path[k++] = *keys++;
    path[k] = NULL;
    return json_numbers(json, path, out, n);
}

/* The parameters of a section of the JSON: the paper's wall, the statics parameters as written */
static rw_params sympy_params(const char *json, const char *section)
{
    static const char *const names[] = {"pointing", "eBaseRatio", "eHingeRatio", "eTop", "psiWeightOnly"};
    rw_params p = paper_params();
    size_t i;
    for (i = 0; i < sizeof names / sizeof names[0]; i++) {
        const char *k[] = {"params", names[i], NULL};
        double v = NAN;
        char msg[512];
        CHECK(section_numbers(json, section, k, &v, 1) == 1, "%s: params.%s missing", section ? section : "top", names[i]);
        CHECK(rw_param_set(&p, rw_param_by_name(names[i]), v, msg, sizeof msg) == 0, "%s", msg);
    }
    return p;
}

/* The derived quantities of one section (the test's wall, or its eccentric variant) against sympy */
static void check_sympy_section(const char *json, const char *section)
{
    rw_params p = sympy_params(json, section);
    rw_derived d;
    double v[4];
    int i, j;
    static const int sides[5][2] = {{0, 0}, {1, -1}, {-1, 1}, {1, 1}, {-1, -1}}; /* condition: side_b, side_m */
    static const char *const side_keys[2] = {"+1", "-1"};
    rw_derive(&p, &d);
    {
        const char *k[] = {"params", "psi", NULL};
        CHECK(section_numbers(json, section, k, v, 1) == 1 && v[0] == p.psi, "JSON params differ from the test's");
    }
    {
        const char *k[] = {"M", NULL};
        CHECK(section_numbers(json, section, k, v, 4) == 4, "M not found");
        for (i = 0; i < 2; i++)
            for (j = 0; j < 2; j++) check_close("M", d.M[i][j], v[2 * i + j], 1e-12);
    }
    {
        const char *k[] = {"K", NULL};
        CHECK(section_numbers(json, section, k, v, 4) == 4, "K not found");
        for (i = 0; i < 2; i++)
            for (j = 0; j < 2; j++) check_close("K", d.K[i][j], v[2 * i + j], 1e-12);
    }
    {
        const char *k[] = {"p_per_ag", NULL};
        CHECK(section_numbers(json, section, k, v, 2) == 2, "p_per_ag not found");
        check_close("p1/ag", d.pa[0], v[0], 1e-12);
        check_close("p2/ag", d.pa[1], v[1], 1e-12);
    }
    {
        const char *k1[] = {"cap_b", NULL}, *k2[] = {"cap_m", NULL};
        CHECK(section_numbers(json, section, k1, v, 1) == 1, "cap_b not found");
        check_close("cap_b", d.cap_b, v[0], 1e-12);
        CHECK(section_numbers(json, section, k2, v, 1) == 1, "cap_m not found");
        check_close("cap_m", d.cap_m, v[0], 1e-12);
    }
    for (i = 0; i < 2; i++) { /* per side s = +1, -1 of a hinge, per direction d = +1, -1 */
        const char *kb[] = {"cap_b_side", side_keys[i], NULL}, *km[] = {"cap_m_side", side_keys[i], NULL};
        const char *ku[] = {"Delta_u", side_keys[i], NULL}, *kr[] = {"F_r", side_keys[i], NULL};
        const double s = i == 0 ? 1.0 : -1.0;
        CHECK(section_numbers(json, section, kb, v, 1) == 1, "cap_b_side not found");
        check_close("cap_b(s)", rw_cap_b_of(&d, s), v[0], 1e-12);
        CHECK(section_numbers(json, section, km, v, 1) == 1, "cap_m_side not found");
        check_close("cap_m(s)", rw_cap_m_of(&d, s), v[0], 1e-12);
        CHECK(section_numbers(json, section, ku, v, 1) == 1, "Delta_u not found");
        check_close("Delta_u(d)", d.dir[RW_SIDE(s)].Du, v[0], 1e-12);
        CHECK(section_numbers(json, section, kr, v, 1) == 1, "F_r not found");
        check_close("F_r(d)", d.dir[RW_SIDE(s)].Fr, v[0], 1e-12);
    }
    {   /* F_base = -base_mass*ag - base_per_qdd . q'' - F_top: each coefficient alone (q = 0, u_top = 0) */
        const char *km[] = {"base_mass", NULL}, *kc[] = {"base_per_qdd", NULL};
        const double x0[RW_NX] = {0, 0, 0, 0};
        double mass, c[2];
        rw_regime m = {.side_b = 1, .side_m = -1};
        rw_input in = {1.0, 0.0};
        double dx[RW_NX] = {0, 0, 0, 0};
        CHECK(section_numbers(json, section, km, &mass, 1) == 1 && section_numbers(json, section, kc, c, 2) == 2,
              "base force not found");
        check_close("F_base per ag", rw_F_base(&p, &d, &m, &in, x0, dx), -mass, 1e-12);
        in.ag = 0.0;
        for (i = 0; i < 2; i++) {
            dx[2] = i == 0 ? 1.0 : 0.0;
            dx[3] = i == 1 ? 1.0 : 0.0;
            check_close("F_base per q''", rw_F_base(&p, &d, &m, &in, x0, dx), -c[i], 1e-12);
        }
    }
    /* A_c, B_c: the rigid hinge terms Q with the sides of condition c */
    p.hingeLaw = RW_RIGID;
    for (i = 1; i <= 4; i++) {
        char cond[2] = {(char)('0' + i), 0};
        const char *ka[] = {"conditions", cond, "A", NULL}, *kb[] = {"conditions", cond, "B", NULL};
        rw_regime m = {.side_b = sides[i][0], .side_m = sides[i][1]};
        double q[RW_NX] = {0.01 * sides[i][0], 0.01 * sides[i][0] + 0.01 * sides[i][1], 0, 0}, Q[2], a, b;
        rw_hinge_Q(&p, &d, &m, q, Q);
        CHECK(section_numbers(json, section, ka, &a, 1) == 1 && section_numbers(json, section, kb, &b, 1) == 1,
              "condition %d missing", i);
        check_close("A_c", Q[0], a, 1e-12);
        check_close("B_c", Q[1], b, 1e-12);
        CHECK(rw_condition(&p, &m) == i, "condition from sides = %d, expected %d", rw_condition(&p, &m), i);
    }
}

static void test_against_sympy(const char *json_path)
{
    char *json = json_path ? read_file(json_path) : NULL;
    if (!json) {
        printf("FAIL: cannot read %s (run scripts/derive_equations.py --json)\n", json_path ? json_path : "(none)");
        failures++;
        return;
    }
    check_sympy_section(json, NULL);
    check_sympy_section(json, "eccentric");
    free(json);
}

static void test_table_5_1(void)
{
    /* Delta_u [m], R_el [kN/m], F0/W for psi = 0, 0.5, 1 */
    static const double want[3][4] = {{0.0, 0.150, 1.192, 0.180}, {0.5, 0.138, 1.639, 0.248}, {1.0, 0.131, 2.086, 0.315}};
    int i;
    for (i = 0; i < 3; i++) {
        rw_params p = paper_params();
        rw_derived d;
        p.psi = want[i][0];
        rw_derive(&p, &d);
        int k;
        for (k = 0; k < 2; k++) { /* both directions of the paper's wall */
            const rw_direction *r = &d.dir[k];
            CHECK(fabs(r->Du - want[i][1]) < 0.0006, "Delta_u(psi=%g) = %g", p.psi, r->Du);
            CHECK(fabs(r->Rel / 1000.0 - want[i][2]) < 0.0006, "R_el(psi=%g) = %g", p.psi, r->Rel);
            CHECK(fabs(r->Rel / p.W - want[i][3]) < 0.0006, "F0/W(psi=%g) = %g", p.psi, r->Rel / p.W);
        }
    }
}

/* Doherty's trilinear law of each direction, on the paper's wall and on an eccentric one (whose
 * directions differ) */
static void test_trilinear(void)
{
    int wall, k;
    for (wall = 0; wall < 2; wall++) {
        rw_params p = wall ? eccentric_params() : paper_params();
        rw_derived d;
        rw_regime m = {.side_b = 1, .side_m = 1};
        p.support = RW_SIMPLY_SUPPORTED;
        rw_derive(&p, &d);
        for (k = 0; k < 2; k++) {
            const rw_direction *r = &d.dir[k];
            const double s = k == 0 ? 1.0 : -1.0;
            check_close("F(D1/2)", rw_force_1dof(&p, &d, &m, s * r->D1 / 2), -s * r->Fi / 2, 1e-12);
            check_close("F(D1)", rw_force_1dof(&p, &d, &m, s * r->D1), -s * r->Fi, 1e-12);
            check_close("F((D1+D2)/2)", rw_force_1dof(&p, &d, &m, s * (r->D1 + r->D2) / 2), -s * r->Fi, 1e-12);
            check_close("F(D2)", rw_force_1dof(&p, &d, &m, s * r->D2), -s * r->Fi, 1e-12);
            check_close("F(D2+)", rw_force_1dof(&p, &d, &m, s * r->D2 * (1 + 1e-12)), -s * r->Fi, 1e-9);
            check_close("F(Du)", rw_force_1dof(&p, &d, &m, s * r->Du), 0.0, 1e-9);
            check_close("F_i", r->Fi, r->Fr * (1 - r->D2 / r->Du), 1e-12);
            check_close("Delta_1", r->D1, 0.05 * r->Du, 1e-12);
            check_close("Delta_2", r->D2, 0.92 * r->D1 + 0.21 * r->Du, 1e-12);
        }
        if (wall == 0)
            check_close("F(-0.1)", rw_force_1dof(&p, &d, &m, -0.1), -rw_force_1dof(&p, &d, &m, 0.1), 1e-12);
        else /* the eccentric top load makes the wall stronger toward +x, where it bears */
            CHECK(d.dir[0].Fr > d.dir[1].Fr * 1.01 && d.dir[0].Du > d.dir[1].Du * 1.01,
                  "eccentric wall: F_r %g, %g and Delta_u %g, %g not larger toward +x", d.dir[0].Fr, d.dir[1].Fr,
                  d.dir[0].Du, d.dir[1].Du);
    }
}

int main(int argc, char **argv)
{
    test_defaults_valid();
    test_ranges();
    test_validation();
    test_against_sympy(argc > 1 ? argv[1] : NULL);
    test_table_5_1();
    test_trilinear();
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
