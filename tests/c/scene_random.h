/* Random scenes for the exact scene engine's C tests: walls, diaphragms (linear, bilinear,
 * Bouc-Wen) and floors in plausible ranges, and states of a motion. */
#ifndef SCENE_RANDOM_H
#define SCENE_RANDOM_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "rw_scene.h"

static double uniform(double lo, double hi) { return lo + (hi - lo) * (rand() / (double)RAND_MAX); }
static int coin(void) { return rand() % 2; }

/* a wall in plausible ranges, tied to its diaphragm (support 3) */
static void random_wall(rw_params *p)
{
    rw_params_default(p);
    p->support = RW_FLEXIBLE_TOP;
    p->hingeLaw = coin() ? RW_DOHERTY_HINGE : RW_SEMI_RIGID_HINGE;
    p->b = uniform(0.1, 0.4);
    p->h = uniform(2.5, 4.5);
    p->W = uniform(15e3, 25e3) * p->b * p->h;
    p->psi = uniform(0.0, 1.0);
    p->Kd = pow(10.0, uniform(5.0, 9.0));
    p->er = uniform(0.6, 1.0);
}

static void random_spec(rw_scene_spec *s)
{
    int i;
    memset(s, 0, sizeof *s);
    s->n_storeys = 1 + rand() % 3;
    s->rigid_in_plane = coin();
    s->building.diaphragm_law = rand() % 3 == 0 ? BD_BOUC_WEN : (coin() ? BD_BILINEAR : BD_ELASTIC);
    s->building.n_bw = 1.0 + rand() % 2, s->building.beta = uniform(0.1, 0.9);
    s->building.a0 = coin() ? uniform(0.0, 0.5) : 0.0;
    s->building.a1 = coin() ? uniform(0.0, 1e-3) : 0.0;
    for (i = 0; i < s->n_storeys; i++) {
        bd_params *b = &s->building;
        b->md[i] = uniform(50.0, 500.0);
        b->diaph[i].k = pow(10.0, uniform(3.5, 6.0));
        b->cd[i] = uniform(0.0, 0.1) * 2.0 * sqrt(b->diaph[i].k * b->md[i]);
        b->diaph[i].Fy = b->diaph[i].k * uniform(0.002, 0.05), b->diaph[i].alpha = uniform(0.0, 0.5);
        b->m[i] = uniform(500.0, 3000.0);
        b->storey[i].k = pow(10.0, uniform(6.0, 8.0));
        b->cs[i] = uniform(0.0, 0.05) * 2.0 * sqrt(b->storey[i].k * b->m[i]);
        s->has_wall[i] = i == 0 || rand() % 4 != 0;
        if (s->has_wall[i]) random_wall(&s->wall[i]);
    }
}

/* a scene of walls in two storeys, both tied by `tie` (rigid in-plane walls, elastic diaphragms:
 * the assessor's house's kind, whose regions the exact engine takes in windows) */
static inline void random_house(rw_scene_spec *spec, double tie)
{
    int i;
    do random_spec(spec);
    while (spec->n_storeys < 2);
    spec->n_storeys = 2;
    spec->rigid_in_plane = 1;
    spec->building.diaphragm_law = BD_ELASTIC;
    for (i = 0; i < 2; i++) {
        spec->has_wall[i] = 1;
        random_wall(&spec->wall[i]);
        spec->wall[i].Kd = tie;
    }
}

/* a state of a motion: rotations up to the toppling limit, the building a few centimetres off, each
 * tie stretched by a force of at most a few kN per metre (random displacements of a 1e8 N/m per m
 * tie would make forces of MN, whose rates the scene's own arithmetic takes to 1e-10 only) */
static inline void random_state(const rw_scene *sc, double *x)
{
    const int N = sc->S.n_storeys;
    double y_below = 0.0, w_below = 0.0;
    int i, k;
    memset(x, 0, sizeof(double) * RW_SCENE_NX);
    for (i = 0; i < N; i++) {
        double *xi = RW_SCENE_WALL(x, i), *f = RW_SCENE_BUILDING(sc, x) + BD_STATES_PER_FLOOR * i;
        f[BD_Y] = uniform(-0.05, 0.05);
        f[BD_W] = uniform(-0.5, 0.5);
        if (sc->S.has_wall[i]) {
            const rw_params *p = &sc->S.wall[i];
            const double qt = sc->D[i].q_topple, stretch = uniform(-3e3, 3e3) / p->Kd;
            for (k = 0; k < 2; k++) xi[k] = uniform(-0.8, 0.8) * qt * (coin() ? 1.0 : 0.05);
            for (k = 2; k < 4; k++) xi[k] = uniform(-0.3, 0.3);
            f[BD_Y] = y_below + 0.5 * p->h * (xi[0] + xi[1]) - stretch;
            f[BD_W] = w_below + 0.5 * p->h * (xi[2] + xi[3]) - 100.0 * stretch;
        }
        if (!sc->S.rigid_in_plane) f[BD_U] = uniform(-0.02, 0.02), f[BD_V] = uniform(-0.2, 0.2);
        f[BD_ZD] = coin() ? uniform(-1.0, 1.0) : (coin() ? 1.0 : -1.0); /* a bilinear one: elastic, or at a limit */
        y_below = f[BD_Y], w_below = f[BD_W];
    }
}

#endif
