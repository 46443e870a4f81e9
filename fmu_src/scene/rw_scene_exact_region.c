/* A scene's linear region for the exact engine: which region the motion is in (each standing
 * wall's hinge moments Q = c + J q), and the linear system M X'' + C X' + K X = f + b ag there,
 * assembled from each wall's derived data and the building's parameters exactly as
 * rw_scene_derivatives evaluates them (docs/scenes.md), as the augmented matrix Aa. */
#include "rw_scene_exact_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* the linear system in generalised coordinates, row-major ndof x ndof */
typedef struct {
    int nd;
    double M[SX_MAX_DOF * SX_MAX_DOF], C[SX_MAX_DOF * SX_MAX_DOF], K[SX_MAX_DOF * SX_MAX_DOF];
    double f[SX_MAX_DOF], b[SX_MAX_DOF];
    double fz[SX_MAX_Z][SX_MAX_DOF]; /* the force of each z chain's z (a Bouc-Wen diaphragm's hysteretic share) */
} lti;

static int standing(const rw_scene *sc, int i) { return sc->S.has_wall[i] && !sc->collapsed[i]; }

void sx_region_key(const rw_scene *sc, double ag, const double x[], const double *dx, sx_key *key)
{
    double own_dx[RW_SCENE_NX];
    int i;
    memset(key, 0, sizeof *key);
    if (!dx) rw_scene_derivatives(sc, ag, x, own_dx, NULL), dx = own_dx;
    for (i = 0; i < sc->S.n_storeys; i++) {
        const double *xi = RW_SCENE_WALL(x, i), *di = RW_SCENE_WALL(dx, i);
        /* on a breakpoint the motion a moment later picks the region (its acceleration decides a
         * grazing touch), as in the single wall's engine */
        const double dir[2] = {xi[2] + 1e-9 * di[2], xi[3] + 1e-9 * di[3]};
        double Q[2], J[2][2];
        if (!(key->standing[i] = standing(sc, i))) continue;
        rw_hinge_law_of(sc->S.wall[i].hingeLaw)->moments(&sc->D[i], sc->regime[i].side_b, sc->regime[i].side_m, xi, dir, Q, J);
        memcpy(key->J[i], J, sizeof J);
        key->c[i][0] = Q[0] - J[0][0] * xi[0] - J[0][1] * xi[1];
        key->c[i][1] = Q[1] - J[1][0] * xi[0] - J[1][1] * xi[1];
        key->cap[i] = sc->D[i].cap_b + sc->D[i].cap_m;
    }
    for (i = 0; i < sc->S.n_storeys; i++)
        if (sx_bilinear(sc, i)) sx_bilinear_key(sc, x, dx, i, key);
}

/* J selects the region exactly; c = Q - J q carries the rounding of the state it was taken at (of
 * J q, which may dwarf c), and differs between regions by a good part of a hinge's capacity */
int sx_key_equal(const sx_key *a, const sx_key *b)
{
    int i, k;
    for (i = 0; i < RW_SCENE_MAX_STOREYS; i++) {
        if (a->branch[i] != b->branch[i] || fabs(a->F0[i] - b->F0[i]) > 1e-9) return 0; /* F0: over its scale */
        if (a->standing[i] != b->standing[i]) return 0;
        if (!a->standing[i]) continue;
        if (memcmp(a->J[i], b->J[i], sizeof a->J[i]) != 0) return 0;
        for (k = 0; k < 2; k++)
            if (fabs(a->c[i][k] - b->c[i][k]) > 1e-9 * a->cap[i]) return 0;
    }
    return 1;
}

int sx_key_same_matrix(const sx_key *a, const sx_key *b)
{
    int i;
    for (i = 0; i < RW_SCENE_MAX_STOREYS; i++) {
        if (a->standing[i] != b->standing[i] || a->branch[i] != b->branch[i]) return 0;
        if (a->standing[i] && memcmp(a->J[i], b->J[i], sizeof a->J[i]) != 0) return 0;
    }
    return 1;
}

/* ---- layout: the generalised coordinates and where they live in the scene state ---- */

static int add_dof(sx_region *r, int pos, int vel)
{
    r->pos[r->ndof] = pos;
    r->vel[r->ndof] = vel;
    return r->ndof++;
}

static void layout(const rw_scene *sc, const sx_key *key, sx_region *r)
{
    const int N = sc->S.n_storeys;
    int i;
    r->ndof = 0;
    for (i = 0; i < N; i++) {
        const int fb = RW_NX * N + BD_STATES_PER_FLOOR * i;
        r->wall_dof[i] = r->floor_dof[i] = -1;
        if (key->standing[i]) {
            r->wall_dof[i] = add_dof(r, RW_NX * i, RW_NX * i + 2);
            add_dof(r, RW_NX * i + 1, RW_NX * i + 3);
        }
        if (!sc->S.rigid_in_plane) r->floor_dof[i] = add_dof(r, fb + BD_U, fb + BD_V);
        r->diaph_dof[i] = add_dof(r, fb + BD_Y, fb + BD_W);
    }
    r->nz = 0;
    for (i = 0; i < N; i++)
        if (sx_bouc_wen_chain(sc, i)) {
            r->z_pos[r->nz] = RW_NX * N + BD_STATES_PER_FLOOR * i + BD_ZD;
            r->z_storey[r->nz++] = i;
        }
    r->n = 2 * r->ndof;
    r->na = r->n + 3 + 3 * r->nz;
    r->hcap = r->nz ? SX_BW_HMAX : INFINITY;
}

/* ---- assembly ---- */

static void add(double *A, int nd, int i, int j, double v)
{
    if (i >= 0 && j >= 0) A[i * nd + j] += v;
}

static void add_b(lti *s, int i, double v)
{
    if (i >= 0) s->b[i] += v;
}

/* a spring k with a dashpot c between DOFs p and q (-1: a support that moves with the ground) */
static void spring(lti *s, int p, int q, double k, double c)
{
    add(s->K, s->nd, p, p, k), add(s->K, s->nd, q, q, k), add(s->K, s->nd, p, q, -k), add(s->K, s->nd, q, p, -k);
    add(s->C, s->nd, p, p, c), add(s->C, s->nd, q, q, c), add(s->C, s->nd, p, q, -c), add(s->C, s->nd, q, p, -c);
}

/* wall i: its bodies on the base (diaphragm i-1 or the ground), its hinge moments, its tie to
 * diaphragm i (spring Kd between s2 = (h/2)(q1+q2) and u_top = y_i - y_{i-1}) */
static void wall(const rw_scene *sc, const sx_region *r, const sx_key *key, int i, lti *s)
{
    const rw_derived *d = &sc->D[i];
    const int a = r->wall_dof[i], y = r->diaph_dof[i], yb = i > 0 ? r->diaph_dof[i - 1] : -1;
    const double m_wall = (sc->S.wall[i].W + d->Wd) / sc->S.wall[i].g;
    int p, q;
    for (p = 0; p < 2; p++) {
        for (q = 0; q < 2; q++) {
            add(s->M, s->nd, a + p, a + q, d->M[p][q]);
            add(s->K, s->nd, a + p, a + q, d->K[p][q] - key->J[i][p][q]); /* d->K holds the tie's Kd h^2/4 */
        }
        s->f[a + p] += key->c[i][p];
        s->b[a + p] += d->pa[p]; /* p = pa a_base, a_base = ag + y''_{i-1} */
        add(s->M, s->nd, a + p, yb, -d->pa[p]), add(s->M, s->nd, yb, a + p, -d->pa[p]);
        add(s->K, s->nd, a + p, y, -d->fu), add(s->K, s->nd, y, a + p, -d->fu);
        add(s->K, s->nd, a + p, yb, d->fu), add(s->K, s->nd, yb, a + p, d->fu);
    }
    spring(s, y, yb, sc->S.wall[i].Kd, 0.0);
    if (yb >= 0) { /* the wall rides on diaphragm i-1: its mass there, inertia force -m_wall ag */
        add(s->M, s->nd, yb, yb, m_wall);
        add_b(s, yb, -m_wall);
    }
}

/* a Bouc-Wen diaphragm's hysteretic force (1 - alpha) Fy z on DOF p (sign: -1 on the diaphragm,
 * +1 on its floor), from its z chain */
static void chain_force(const rw_scene *sc, const sx_region *r, lti *s, int i, int p, double sign)
{
    const bd_spring *d = &sc->S.building.diaph[i];
    int k;
    for (k = 0; k < r->nz; k++)
        if (r->z_storey[k] == i) s->fz[k][p] += sign * (1.0 - d->alpha) * d->Fy;
}

static void building(const rw_scene *sc, const sx_region *r, lti *s)
{
    const bd_params *b = &sc->S.building;
    int i;
    for (i = 0; i < sc->S.n_storeys; i++) {
        const int u = r->floor_dof[i], y = r->diaph_dof[i], ub = i > 0 ? r->floor_dof[i - 1] : -1;
        const bd_spring *d = &b->diaph[i];
        /* the diaphragm's spring on the region's branch, F = k_b (y - u) + F0 (a bilinear one's;
         * Rayleigh's a1 on the initial stiffness, as building_physics.c takes it) */
        const double k_b = sx_linear_stiffness(sc, &r->key, i);
        const double F0 = r->key.F0[i] * (1.0 - d->alpha) * d->Fy;
        add(s->M, s->nd, y, y, b->md[i]);
        add_b(s, y, -b->md[i]);
        add(s->C, s->nd, y, y, b->a0 * b->md[i]);
        spring(s, y, u, k_b, b->a1 * d->k + b->cd[i]);
        s->f[y] -= F0;
        chain_force(sc, r, s, i, y, -1.0);
        if (u < 0) continue;
        s->f[u] += F0;
        chain_force(sc, r, s, i, u, 1.0);
        add(s->M, s->nd, u, u, b->m[i]);
        add_b(s, u, -b->m[i]);
        add(s->C, s->nd, u, u, b->a0 * b->m[i]);
        spring(s, u, ub, b->storey[i].k, b->a1 * b->storey[i].k + b->cs[i]);
    }
}

/* Aa = [[0, I, 0, 0, 0, 0], [-M^-1 K, -M^-1 C, M^-1 b, 0, M^-1 f, M^-1 fz], [0.. 1 ..], 0, 0,
 * the z chains' shifts] */
static int augmented(const lti *s, sx_region *r)
{
    const int nd = s->nd, n = r->n, na = r->na, w = 2 * nd + 2 + r->nz;
    double Mc[SX_MAX_DOF * SX_MAX_DOF], B[SX_MAX_DOF * (2 * SX_MAX_DOF + 2 + SX_MAX_Z)];
    int i, j, k;
    memcpy(Mc, s->M, sizeof(double) * (size_t)(nd * nd));
    for (i = 0; i < nd; i++) {
        for (j = 0; j < nd; j++) {
            B[i * w + j] = -s->K[i * nd + j];
            B[i * w + nd + j] = -s->C[i * nd + j];
        }
        B[i * w + 2 * nd] = s->b[i];
        B[i * w + 2 * nd + 1] = s->f[i];
        for (k = 0; k < r->nz; k++) B[i * w + 2 * nd + 2 + k] = s->fz[k][i];
    }
    if (sx_lu_solve(nd, Mc, B, w)) return 1;
    memset(r->Aa, 0, sizeof(double) * (size_t)(na * na));
    for (i = 0; i < nd; i++) {
        double *row = r->Aa + (size_t)((nd + i) * na);
        r->Aa[i * na + nd + i] = 1.0;
        for (j = 0; j < 2 * nd; j++) row[j] = B[i * w + j];
        row[n] = B[i * w + 2 * nd];
        row[n + 2] = B[i * w + 2 * nd + 1];
        for (k = 0; k < r->nz; k++) row[sx_z_col(r, k)] = B[i * w + 2 * nd + 2 + k];
    }
    r->Aa[n * na + n + 1] = 1.0; /* ag' = slope */
    for (k = 0; k < r->nz; k++) { /* z' and z'' the chain's next entries */
        const int c = sx_z_col(r, k);
        r->Aa[c * na + c + 1] = 1.0;
        r->Aa[(c + 1) * na + c + 2] = 1.0;
    }
    return 0;
}

/* the energy's quadratic forms (1/2) V.M V + (1/2) X.K X as their nonzero entries on and above the
 * diagonal, over the scene state (symmetric: (K_ij + K_ji) / 2 for K's pair, whose antisymmetric
 * part adds nothing) */
static void energy_form(sx_region *r)
{
    const int nd = r->ndof;
    int i, j, m;
    r->eq_n = 0;
    for (m = 0; m < 2; m++) {
        const double *Q = m ? r->Mq : r->Kq;
        const int *at = m ? r->vel : r->pos;
        for (i = 0; i < nd; i++)
            for (j = i; j < nd; j++) {
                const double c = i == j ? 0.5 * Q[i * nd + i] : 0.5 * (Q[i * nd + j] + Q[j * nd + i]);
                if (c == 0.0) continue;
                r->eq_a[r->eq_n] = at[i], r->eq_b[r->eq_n] = at[j], r->eq_c[r->eq_n++] = c;
            }
    }
}

/* the rows of Aa outside the velocities' that hold a single 1 or nothing (the series' products
 * take them as copies: rw_scene_exact_series.c) */
static void find_hot_rows(sx_region *r)
{
    int i, j;
    r->one_hot = 1;
    for (i = 0; i < r->na; i++) {
        int count = 0;
        r->hot[i] = -1;
        if (i >= r->ndof && i < r->n) continue;
        for (j = 0; j < r->na; j++) {
            const double a = r->Aa[i * r->na + j];
            if (a == 0.0) continue;
            count++;
            r->hot[i] = j;
            if (a != 1.0) r->one_hot = 0;
        }
        if (count > 1 || (i < r->ndof && count != 1)) r->one_hot = 0;
    }
}

/* ---- what the engine watches and integrates ---- */

static void functional(sx_region *r, int kind, int storey)
{
    const int k = r->nf++;
    r->f_of[storey][kind] = k;
    memset(r->F[k], 0, sizeof r->F[k]);
    r->f_kind[k] = kind;
    r->f_storey[k] = storey;
}

/* a row's nonzero entries (in order), and inline where it holds two at most */
static void nonzeros(const double *row, int na, int *nz, int *at, sx_pair *pair)
{
    int j;
    *nz = 0;
    for (j = 0; j < na; j++)
        if (row[j] != 0.0) at[(*nz)++] = j;
    pair->i0 = *nz > 0 ? at[0] : 0, pair->c0 = *nz > 0 ? row[at[0]] : 0.0;
    pair->i1 = *nz > 1 ? at[1] : pair->i0, pair->c1 = *nz > 1 ? row[at[1]] : 0.0;
}

/* the functionals' rates along the motion, F Aa, with their nonzero entries */
static void rates(sx_region *r)
{
    const int na = r->na;
    int f, i, j;
    for (f = 0; f < r->nf; f++) {
        for (j = 0; j < na; j++) {
            double v = 0.0;
            for (i = 0; i < na; i++) v += r->F[f][i] * r->Aa[i * na + j];
            r->FA[f][j] = v;
        }
        nonzeros(r->FA[f], na, &r->fa_nz[f], r->fa_at[f], &r->fa_pair[f]);
    }
}

/* q1, q2 of each standing wall; each storey's diaphragm deformation and base acceleration */
static int functional_count(const rw_scene *sc, const sx_key *key)
{
    int i, n = 0;
    for (i = 0; i < sc->S.n_storeys; i++) n += 2 + (key->standing[i] ? 2 : 0) + (key->branch[i] != 0);
    return n;
}

static void functionals(const rw_scene *sc, sx_region *r)
{
    const int nd = r->ndof, na = r->na;
    int i, j;
    r->nf = 0;
    for (i = 0; i < RW_SCENE_MAX_STOREYS; i++)
        for (j = 0; j <= SX_DEFORM_RATE; j++) r->f_of[i][j] = -1;
    for (i = 0; i < sc->S.n_storeys; i++) {
        if (r->wall_dof[i] >= 0) {
            functional(r, SX_Q1, i);
            r->F[r->nf - 1][r->wall_dof[i]] = 1.0;
            functional(r, SX_Q2, i);
            r->F[r->nf - 1][r->wall_dof[i] + 1] = 1.0;
        }
        functional(r, SX_DEFORM, i);
        r->F[r->nf - 1][r->diaph_dof[i]] = 1.0;
        if (r->floor_dof[i] >= 0) r->F[r->nf - 1][r->floor_dof[i]] = -1.0;
        functional(r, SX_BASE_ACC, i); /* ag + y''_{i-1}: a row of Aa */
        r->F[r->nf - 1][r->n] = 1.0;
        if (i > 0)
            for (j = 0; j < na; j++) r->F[r->nf - 1][j] += r->Aa[(nd + r->diaph_dof[i - 1]) * na + j];
        if (r->key.branch[i]) { /* a yielding bilinear diaphragm unloads where this changes sign */
            functional(r, SX_DEFORM_RATE, i);
            r->F[r->nf - 1][nd + r->diaph_dof[i]] = 1.0;
            if (r->floor_dof[i] >= 0) r->F[r->nf - 1][nd + r->floor_dof[i]] = -1.0;
        }
    }
    rates(r);
    for (i = 0; i < r->nf; i++) {
        r->f_scale[i] = 0.0;
        for (j = 0; j < r->n; j++) r->f_scale[i] += fabs(r->F[i][j]) * r->scale[j];
        nonzeros(r->F[i], na, &r->f_nz[i], r->f_at[i], &r->f_pair[i]);
    }
}

/* a dashpot coef between the velocities of DOFs v1 and v2 (-1: the ground); dashpots between the
 * same two (a diaphragm's own and Rayleigh's share of its spring) are one term */
static void damping_term(sx_region *r, double coef, int v1, int v2)
{
    int k = r->nterms, t;
    if (!(coef != 0.0)) return;
    memset(r->dvec[k], 0, sizeof r->dvec[k]);
    r->dvec[k][r->ndof + v1] = 1.0;
    if (v2 >= 0) r->dvec[k][r->ndof + v2] = -1.0;
    for (t = 0; t < k; t++)
        if (memcmp(r->dvec[t], r->dvec[k], sizeof r->dvec[k]) == 0) {
            r->dcoef[t] += coef;
            return;
        }
    r->dcoef[k] = coef;
    {
        int at[SX_MAX_NA];
        nonzeros(r->dvec[k], r->n, &r->d_nz[k], at, &r->d_pair[k]);
    }
    r->nterms++;
}

/* the momentum and the dissipation rate of rw_scene_powers */
static void energy_rows(const rw_scene *sc, sx_region *r)
{
    const bd_params *b = &sc->S.building;
    const int nd = r->ndof;
    int i, p;
    memset(r->mom, 0, sizeof r->mom);
    r->nterms = 0;
    for (i = 0; i < sc->S.n_storeys; i++) {
        const int u = r->floor_dof[i], y = r->diaph_dof[i], a = r->wall_dof[i];
        r->mom[nd + y] += b->md[i];
        damping_term(r, b->a0 * b->md[i], y, -1);
        damping_term(r, b->a1 * b->diaph[i].k + b->cd[i], y, u);
        if (u >= 0) {
            r->mom[nd + u] += b->m[i];
            damping_term(r, b->a0 * b->m[i], u, -1);
            damping_term(r, b->a1 * b->storey[i].k + b->cs[i], u, i > 0 ? r->floor_dof[i - 1] : -1);
        }
        if (a < 0) continue;
        if (i > 0) r->mom[nd + r->diaph_dof[i - 1]] += (sc->S.wall[i].W + sc->D[i].Wd) / sc->S.wall[i].g;
        for (p = 0; p < 2; p++) r->mom[nd + a + p] -= sc->D[i].pa[p];
    }
}

static void collapse_forms(const rw_scene *sc, const sx_key *key, sx_region *r)
{
    int i, p, q;
    for (i = 0; i < sc->S.n_storeys; i++) {
        sx_collapse *c = &r->col[i];
        const rw_derived *d = &sc->D[i];
        memset(c, 0, sizeof *c);
        if (!key->standing[i]) continue;
        for (p = 0; p < 2; p++) {
            c->c[p] = key->c[i][p];
            for (q = 0; q < 2; q++) c->A[p][q] = d->K[p][q] - key->J[i][p][q];
        }
        c->lam_min = sx_sym2_min_eig((const double(*)[2])c->A);
        sx_sym2_eig((const double(*)[2])c->A, c->mu, c->e);
        /* the laws' elastic range is the region where Q = J q (c = 0): no collapse there */
        c->active = fabs(c->c[0]) + fabs(c->c[1]) > 1e-9 * (d->cap_b + d->cap_m);
    }
}

/* the region's matrix. Its step tables are allocated as each is first built (sx_step_of): a
 * region uses a few of its SX_STEPS lengths, and one allocation for all of them (188 KB for two
 * storeys) was mapped and faulted in anew at every build. */
static int allocate(sx_region *r)
{
    sx_region_free(r);
    r->blob = (double *)sx_pool_alloc(sizeof(double) * (size_t)(2 * r->na * r->na)); /* (set in full: augmented) */
    if (!r->blob) return 1;
    r->Aa = r->blob;
    r->Aa_cols = r->Aa + r->na * r->na;
    return 0;
}

/* is the first-order block of Aa the same, to the bit, in both regions? */
static int same_first_order(const sx_region *a, const sx_region *b)
{
    int i;
    if (a->n != b->n) return 0;
    for (i = 0; i < a->n; i++)
        if (memcmp(a->Aa + i * a->na, b->Aa + i * b->na, sizeof(double) * (size_t)a->n) != 0) return 0;
    return 1;
}

int sx_region_build(const rw_scene *sc, const sx_key *key, sx_region *r, const sx_region *sibling)
{
    lti *s = (lti *)calloc(1, sizeof(lti));
    int fail;
    if (!s) return RW_SCENE_NO_MEMORY;
    r->key = *key;
    layout(sc, key, r);
    r->nf = functional_count(sc, key); /* the tables' size; functionals() fills them */
    if (allocate(r)) {
        free(s);
        return RW_SCENE_NO_MEMORY;
    }
    s->nd = r->ndof;
    building(sc, r, s);
    {
        int i;
        for (i = 0; i < sc->S.n_storeys; i++)
            if (key->standing[i]) wall(sc, r, key, i, s);
    }
    memcpy(r->Mq, s->M, sizeof r->Mq);
    memcpy(r->Kq, s->K, sizeof r->Kq);
    memcpy(r->fq, s->f, sizeof r->fq);
    energy_form(r);
    fail = augmented(s, r);
    free(s);
    if (fail) return RW_SCENE_SOLVER;
    {
        double A[SX_MAX_N * SX_MAX_N];
        int i, j;
        for (i = 0; i < r->n; i++)
            for (j = 0; j < r->n; j++) A[i * r->n + j] = r->Aa[i * r->na + j];
        sx_balance(r->n, A, r->scale, &r->norm);
        for (i = 0; i < r->n; i++) r->inv_scale[i] = 1.0 / r->scale[i];
    }
    sx_transpose(r->na, r->na, r->Aa, r->Aa_cols);
    find_hot_rows(r);
    functionals(sc, r);
    energy_rows(sc, r);
    collapse_forms(sc, key, r);
    if (r->nz) r->modes.valid = 0; /* no slow steps: each step is the z fit's (their bounds do not
                                       take the chains' forcing) */
    else if (sibling && sibling->modes.valid && same_first_order(r, sibling)) sx_modes_adopt(r, &sibling->modes);
    else sx_modes_build(r);
    return RW_SCENE_OK;
}

void sx_region_blank(sx_region *r)
{
    int k;
    r->blob = NULL;
    r->Aa = r->Aa_cols = NULL;
    r->used = 0;
    r->last_step = 0;
    r->modes.valid = 0;
    for (k = 0; k < SX_STEPS; k++) r->step[k].mem = NULL, r->step[k].h = 0.0, r->step[k].used = 0;
}

void sx_region_free(sx_region *r)
{
    int k;
    sx_pool_free(r->blob);
    for (k = 0; k < SX_STEPS; k++) sx_pool_free(r->step[k].mem);
    sx_region_blank(r);
}

void sx_gather(const sx_region *r, const double x[], double ag, double slope, double xa[])
{
    int k;
    for (k = 0; k < r->ndof; k++) {
        xa[k] = x[r->pos[k]];
        xa[r->ndof + k] = x[r->vel[k]];
    }
    xa[r->n] = ag;
    xa[r->n + 1] = slope;
    xa[r->n + 2] = 1.0;
    for (k = 0; k < r->nz; k++) { /* z now, its rates unknown until fitted */
        const int c = sx_z_col(r, k);
        xa[c] = x[r->z_pos[k]];
        xa[c + 1] = xa[c + 2] = 0.0;
    }
}

/* (two partial sums: one sum's adds each wait on the one before, and the energy is taken at every
 * record interval; it feeds only the energy balance, never the motion) */
double sx_region_energy(const sx_region *r, const double x[])
{
    double e0 = 0.0, e1 = 0.0;
    int t, k;
    for (t = 0; t + 1 < r->eq_n; t += 2) {
        e0 += r->eq_c[t] * x[r->eq_a[t]] * x[r->eq_b[t]];
        e1 += r->eq_c[t + 1] * x[r->eq_a[t + 1]] * x[r->eq_b[t + 1]];
    }
    if (t < r->eq_n) e0 += r->eq_c[t] * x[r->eq_a[t]] * x[r->eq_b[t]];
    for (k = 0; k < r->ndof; k++) e1 -= r->fq[k] * x[r->pos[k]];
    return e0 + e1;
}

void sx_scatter(const sx_region *r, const double xa[], double x[])
{
    int k;
    for (k = 0; k < r->ndof; k++) {
        x[r->pos[k]] = xa[k];
        x[r->vel[k]] = xa[r->ndof + k];
    }
}
