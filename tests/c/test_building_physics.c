/* The Building's spring laws in building_physics.c, without the FMI layer: which laws a storey and
 * a diaphragm take (bd_law_allowed), and the bilinear law's rate (bd_hysteretic_rate): the elastic
 * slope du/Dy inside the elastic range and on unloading, exactly 0 while yielding, and held (not
 * drifting further) for a z a hair past 1; through bd_derivatives for a storey and a diaphragm. */
#include "check.h"
#include <math.h>
#include <string.h>

#include "building_physics.h"

static void test_laws_allowed(void)
{
    int law;
    for (law = -1; law <= 4; law++) {
        const int known = law >= BD_ELASTIC && law <= BD_BILINEAR;
        CHECK(bd_law_allowed(law, 0) == known, "diaphragm law %d: allowed %d", law, bd_law_allowed(law, 0));
        CHECK(bd_law_allowed(law, 1) == (known && law != BD_BOUC_WEN_PINCHED), "storey law %d: allowed %d", law,
              bd_law_allowed(law, 1));
    }
}

static void test_bilinear_rate(void)
{
    bd_params p;
    const bd_spring s = {2e5, 4e3, 0.1}; /* Dy = 0.02 m */
    const double dy = s.Fy / s.k, hair = 1.0 + 4.0 * 2.220446049250313e-16;
    const double z_inside[] = {0.0, 0.5, -0.999, 0.999999};
    size_t i;
    memset(&p, 0, sizeof p);
    p.n_bw = 1.0, p.beta = 0.5;
    for (i = 0; i < sizeof z_inside / sizeof z_inside[0]; i++) {
        CHECK(bd_hysteretic_rate(&p, BD_BILINEAR, &s, z_inside[i], 0.3) == 0.3 / dy, "z %g loading: rate %g",
              z_inside[i], bd_hysteretic_rate(&p, BD_BILINEAR, &s, z_inside[i], 0.3));
        CHECK(bd_hysteretic_rate(&p, BD_BILINEAR, &s, z_inside[i], -0.3) == -0.3 / dy, "z %g: rate %g", z_inside[i],
              bd_hysteretic_rate(&p, BD_BILINEAR, &s, z_inside[i], -0.3));
    }
    /* yielding: on the limit or a hair past it, loading on, the rate is exactly 0 */
    CHECK(bd_hysteretic_rate(&p, BD_BILINEAR, &s, 1.0, 0.3) == 0.0, "z 1 loading");
    CHECK(bd_hysteretic_rate(&p, BD_BILINEAR, &s, -1.0, -0.3) == 0.0, "z -1 loading");
    CHECK(bd_hysteretic_rate(&p, BD_BILINEAR, &s, hair, 0.3) == 0.0, "z a hair past 1, loading: drifts");
    CHECK(bd_hysteretic_rate(&p, BD_BILINEAR, &s, -hair, -0.3) == 0.0, "z a hair past -1, loading: drifts");
    CHECK(bd_hysteretic_rate(&p, BD_BILINEAR, &s, 1.2, 5.0) == 0.0, "z 1.2 loading: drifts");
    /* unloading leaves the limit at the elastic slope, from a hair past it too */
    CHECK(bd_hysteretic_rate(&p, BD_BILINEAR, &s, 1.0, -0.3) == -0.3 / dy, "z 1 unloading");
    CHECK(bd_hysteretic_rate(&p, BD_BILINEAR, &s, -hair, 0.3) == 0.3 / dy, "z a hair past -1 unloading");
    CHECK(bd_hysteretic_rate(&p, BD_BILINEAR, &s, 0.7, 0.0) == 0.0, "at rest");
    /* the other laws are unchanged by it: Bouc-Wen n = 1, beta 1/2 at z = 1/2 loading: (1 - 1/2) du/Dy */
    CHECK(fabs(bd_hysteretic_rate(&p, BD_BOUC_WEN, &s, 0.5, 0.3) - 0.5 * 0.3 / dy) < 1e-12 * 0.3 / dy, "Bouc-Wen");
    CHECK(bd_hysteretic_rate(&p, BD_ELASTIC, &s, 0.5, 0.3) == 0.0, "elastic");
}

/* through the building's rates: a storey's z and a diaphragm's z each follow the bilinear law, and
 * the force is alpha k u + (1 - alpha) Fy z */
static void test_bilinear_in_the_building(void)
{
    bd_params p;
    bd_input in;
    double x[BD_NX], dx[BD_NX];
    const double v_floor = 0.2, w_diaph = -0.1;
    memset(&p, 0, sizeof p);
    memset(&in, 0, sizeof in);
    memset(x, 0, sizeof x);
    p.n_storeys = 1, p.storey_law = p.diaphragm_law = BD_BILINEAR, p.n_bw = 1.0, p.beta = 0.5;
    p.m[0] = 3000.0, p.md[0] = 200.0;
    p.storey[0] = (bd_spring){3e7, 6e4, 0.05};  /* Dy = 2 mm */
    p.diaph[0] = (bd_spring){2e5, 4e3, 0.1};    /* Dy = 20 mm */
    x[BD_U] = 0.01, x[BD_V] = v_floor, x[BD_Z] = 1.0;  /* the storey yielding */
    x[BD_Y] = 0.015, x[BD_W] = w_diaph, x[BD_ZD] = 0.3; /* the diaphragm elastic, its deformation closing */
    bd_derivatives(&p, &in, x, dx);
    CHECK(dx[BD_Z] == 0.0, "yielding storey: dz %g", dx[BD_Z]);
    CHECK(fabs(dx[BD_ZD] - (w_diaph - v_floor) / 0.02) < 1e-12 * fabs(dx[BD_ZD]), "diaphragm dz %g", dx[BD_ZD]);
    CHECK(fabs(bd_storey_force(&p, x, 0) - (0.05 * 3e7 * 0.01 + 0.95 * 6e4)) < 1e-9 * 6e4, "storey force %g",
          bd_storey_force(&p, x, 0));
    CHECK(fabs(bd_diaphragm_force(&p, x, 0) - (0.1 * 2e5 * 0.005 + 0.9 * 4e3 * 0.3)) < 1e-9 * 4e3,
          "diaphragm force %g", bd_diaphragm_force(&p, x, 0));
}

int main(void)
{
    test_laws_allowed();
    test_bilinear_rate();
    test_bilinear_in_the_building();
    printf("%d checks, %d failures\n", checks, failures);
    return failures != 0;
}
