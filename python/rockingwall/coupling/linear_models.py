"""The slaves of the co-simulated scenes as linear systems (step_map.LinearSlave), about rest:
RockingWall in its first, elastic range and the Building with its springs' initial stiffnesses.
What rockingwall.coupling.rules needs to predict whether the Jacobi scheme holds (docs/model.md
and docs/building.md have the equations; nothing here is read from the C).

The wall (support 3, flexibleTop), states (q1, q2, q1', q2'), inputs (ag, u_top), outputs
(F_top, F_base):

    M q'' + (K - J) q = -c ag + (K_d h/2) (1, 1) u_top
    F_top = K_d (s2 - u_top),   F_base = -m ag - c.q'' - F_top

with M, K of Eq. 3.2, 3.3, c = -p/ag of Eq. 3.4, m = (W + Wd)/g and J the hinge moments' Jacobian
in the law's first linear range (dohertyHinge, semiRigidHinge). The rigid law and semiRigidPaper
have no linear range at rest (their moments jump or kink at zero rotation): the wall is taken as
one rigid body there, q = 0, which is what closed rigid hinges do.

The wall's effective mass on its base, m_b = m - c.M^-1 c, is how much of F_base follows the base
acceleration at once (-dF_base/d ag): the part of the wall that a floor feels as added mass at the
instant (m itself for a rigid wall)."""
import functools

import numpy as np

from .step_map import LinearSlave

G_DEFAULT = 9.81
RIGID_LAWS = (1, 2)   # rigid, semiRigidPaper: no linear range at rest
WALL_DEFAULTS = dict(psi=0.0, Kd=1e6, g=G_DEFAULT, delta1Ratio=0.05, delta2A=0.92, delta2B=0.21, hingeSat=2.0)


def _wall(params):
    p = dict(WALL_DEFAULTS, **params)
    return p, p["W"] / 2.0, p["psi"] * p["W"] / 2.0


def wall_matrices(params):
    """(M, K, c, m) of a wall given by the FMU's parameter names (h, b, W, psi, Kd, g)."""
    p, W1, Wd = _wall(params)
    h, g, Kd = p["h"], p["g"], p["Kd"]
    hg = h * h / g
    M = hg * np.array([[W1 / 3 + Wd / 4, W1 / 8 + Wd / 4], [W1 / 8 + Wd / 4, W1 / 12 + Wd / 4]])
    K = np.array([[Kd * h * h / 4 - 0.75 * W1 * h - Wd * h / 2, Kd * h * h / 4],
                  [Kd * h * h / 4, Kd * h * h / 4 - W1 * h / 4 - Wd * h / 2]])
    c = np.array([(3 * W1 + 2 * Wd) * h / (4 * g), (W1 + 2 * Wd) * h / (4 * g)])
    return M, K, c, (p["W"] + Wd) / g


def hinge_jacobian(params, law):
    """dQ/dq in the first linear range of the hinge law (docs/model.md, "Hinge laws")."""
    p, W1, Wd = _wall(params)
    h, b, W, psi = p["h"], p["b"], p["W"], p["psi"]
    cap_b, cap_m = (2 * W1 + Wd) * b / 2, (W1 + Wd) * b / 2
    Du = b * (1 + 0.75 * psi) / (1 + psi)
    D1 = p["delta1Ratio"] * Du
    if law == 4:   # dohertyHinge: mu = (F_i/D1 + F_r/Du)/F_r D, D_b = h q1/2, D_m = h (q2 - q1)/4
        Fr = 2 * b / h * W * (1 + 0.75 * psi)
        D2 = p["delta2A"] * D1 + p["delta2B"] * Du
        slope = (Fr * (1 - D2 / Du) / D1 + Fr / Du) / Fr
        kb, km = cap_b * slope * h / 2, cap_m * slope * h / 4
    elif law == 3:  # semiRigidHinge: mu = rotation / theta_y
        theta_y = 2 * p["hingeSat"] * D1 / h
        kb, km = cap_b / theta_y, cap_m / theta_y
    else:
        raise ValueError(f"hinge law {law} has no linear range at rest")
    return np.array([[-kb - km, km], [km, -km]])


def base_mass(params, law=4):
    """The wall's effective mass on its base m_b [kg/m] (the module's docstring)."""
    M, _, c, m = wall_matrices(params)
    return m if law in RIGID_LAWS else m - float(c @ np.linalg.solve(M, c))


def top_mass(params, law=4):
    """The wall's mass at its top [kg/m] as the tie sees it, 1/(J M^-1 J^T) with s2 = (h/2)(q1 + q2)
    (rules.wall_top_mass); a rigid wall's top does not move (inf)."""
    if law in RIGID_LAWS:
        return np.inf
    M, _, _, _ = wall_matrices(params)
    e = np.full(2, dict(WALL_DEFAULTS, **params)["h"] / 2.0)
    return 1.0 / float(e @ np.linalg.solve(M, e))


def wall_slave(name, params, law=4):
    """RockingWall (flexibleTop) about rest: inputs ag, u_top; outputs F_top, F_base."""
    M, K, c, m = wall_matrices(params)
    p = dict(WALL_DEFAULTS, **params)
    Kd, h = p["Kd"], p["h"]
    if law in RIGID_LAWS:  # one rigid body: F_top = -K_d u_top, F_base = -m ag + K_d u_top
        return LinearSlave(name, np.zeros((0, 0)), np.zeros((0, 2)), np.zeros((2, 0)),
                           np.array([[0.0, -Kd], [-m, Kd]]), ["ag", "u_top"], ["F_top", "F_base"])
    Minv = np.linalg.inv(M)
    stiff = K - hinge_jacobian(params, law)
    e = np.ones(2)
    A = np.zeros((4, 4))
    A[:2, 2:] = np.eye(2)
    A[2:, :2] = -Minv @ stiff
    B = np.zeros((4, 2))
    B[2:, 0] = -Minv @ c
    B[2:, 1] = Minv @ e * (Kd * h / 2)
    C = np.zeros((2, 4))
    C[0, :2] = Kd * h / 2
    C[1, :2] = c @ Minv @ stiff - Kd * h / 2
    D = np.array([[0.0, -Kd],
                  [-m + float(c @ Minv @ c), -float(c @ Minv @ e) * Kd * h / 2 + Kd]])
    return LinearSlave(name, A, B, C, D, ["ag", "u_top"], ["F_top", "F_base"])


@functools.cache
def fmu_start_values(path):
    """{name: start value} of an FMU's parameters (its modelDescription.xml)."""
    from fmpy import read_model_description
    md = read_model_description(str(path))
    return {v.name: float(v.start) for v in md.modelVariables if v.causality == "parameter" and v.start is not None}


def building_matrices(values, n, rigid=False):
    """(M, K, C) of the Building (docs/building.md) over (u_1, y_1, ..., u_n, y_n), or over
    (y_1, ..., y_n) with rigid in-plane walls (the floors move with the ground): floors on the
    storeys' springs, diaphragms on theirs relative to their floors, the springs' initial
    stiffness, Rayleigh a0 M + a1 K0 and the dashpots cs_i, cd_i beside the springs. values: the
    FMU's names."""
    per = 1 if rigid else 2
    N = per * n
    M, K, Cd = np.zeros((N, N)), np.zeros((N, N)), np.zeros((N, N))

    def spring(mat, a, b, k):  # a spring k between DOF a and DOF b (None: the ground)
        mat[a, a] += k
        if b is not None:
            mat[b, b] += k
            mat[a, b] -= k
            mat[b, a] -= k

    for i in range(n):
        y = per * i + per - 1
        M[y, y] = values[f"md_{i + 1}"]
        u = None if rigid else 2 * i
        spring(K, y, u, values[f"kd_{i + 1}"])
        spring(Cd, y, u, values.get(f"cd_{i + 1}", 0.0))
        if rigid:
            continue
        below = 2 * (i - 1) if i > 0 else None
        M[u, u] = values[f"m_{i + 1}"]
        spring(K, u, below, values[f"k_{i + 1}"])
        spring(Cd, u, below, values.get(f"cs_{i + 1}", 0.0))
    C = values.get("rayleighMass", 0.0) * M + values.get("rayleighStiffness", 0.0) * K + Cd
    return M, K, C


def building_slave(name, values, n, rigid=False):
    """The Building about rest: inputs F_wall_i, F_above_i; outputs a_diaph_i (ag = 0), u_top_i."""
    M, K, C = building_matrices(values, n, rigid)
    N, per = M.shape[0], (1 if rigid else 2)
    Minv = np.linalg.inv(M)
    A = np.zeros((2 * N, 2 * N))
    A[:N, N:] = np.eye(N)
    A[N:, :N], A[N:, N:] = -Minv @ K, -Minv @ C
    inputs = [f"{q}_{i + 1}" for i in range(n) for q in ("F_wall", "F_above")]
    F = np.zeros((N, 2 * n))  # the force inputs act on the diaphragms
    for i in range(n):
        F[per * i + per - 1, 2 * i] = F[per * i + per - 1, 2 * i + 1] = 1.0
    B = np.vstack([np.zeros((N, 2 * n)), Minv @ F])
    outputs, Crows, Drows = [], [], []
    for i in range(n):
        y = per * i + per - 1
        outputs.append(f"a_diaph_{i + 1}")
        Crows.append(A[N + y])
        Drows.append(B[N + y])
        row = np.zeros(2 * N)
        row[y] = 1.0
        if i > 0:
            row[y - per] = -1.0
        outputs.append(f"u_top_{i + 1}")
        Crows.append(row)
        Drows.append(np.zeros(2 * n))
    return LinearSlave(name, A, B, np.array(Crows), np.array(Drows), inputs, outputs)


def wall_values(scene, wall):
    """A wall's Real parameters: its start values over its FMU's defaults."""
    return dict(fmu_start_values(scene.wall_fmu), **wall.real)


def scene_slaves(scene):
    """(slaves, connections) of a co-simulated building scene (rockingwall.building.scene.Scene)
    about rest: the Building with its FMU's start values under the scene's, and every wall."""
    values = dict(fmu_start_values(scene.building_fmu))
    values.update(scene.building_real)
    slaves = [building_slave("building", values, scene.n_storeys)]
    for w in scene.walls:
        slaves.append(wall_slave(w.name, wall_values(scene, w), int(w.integer.get("hingeLaw", 4))))
    return slaves, [c for c in scene.connections()]


def wall_on_diaphragm(wall_params, law, md, kd, cd):
    """(slaves, connections) of one wall standing on a diaphragm (md, kd, dashpot cd) whose floor
    does not move, the wall's top free (K_d = 0): the base exchange alone."""
    values = {"md_1": md, "kd_1": kd, "cd_1": cd}
    slaves = [building_slave("building", values, 1, rigid=True), wall_slave("wall", dict(wall_params, Kd=0.0), law)]
    return slaves, [("building", "a_diaph_1", "wall", "ag"), ("wall", "F_base", "building", "F_above_1")]


def wall_tied_to_diaphragm(wall_params, law, md, kd, cd):
    """(slaves, connections) of one wall standing on the ground, tied to a diaphragm (md, kd, cd)
    whose floor does not move: the tie's exchange alone."""
    values = {"md_1": md, "kd_1": kd, "cd_1": cd}
    slaves = [building_slave("building", values, 1, rigid=True), wall_slave("wall", wall_params, law)]
    return slaves, [("building", "u_top_1", "wall", "u_top"), ("wall", "F_top", "building", "F_wall_1")]
