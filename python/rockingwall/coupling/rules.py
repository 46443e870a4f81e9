"""Safety rules of the coupled scenes (`rockingwall couple`, `rockingwall couple-building`): the
largest macro step the tie K_d allows, the stability of a building's Jacobi exchange
(scene_stability), and the check of the energy bookkeeping. Documented in docs/coupling.md and
docs/building-coupling.md.

Macro-step rule
---------------
The tie K_d joins the top of the wall (effective mass m_w at the top, from the wall's Eq. 3.2 mass
matrix) to the diaphragm (mass m_d, stiffness k, damping c). The Jacobi scheme (coupling.jacobi) holds each
slave's input over the step: the wall integrates its own end of the spring exactly with u_top held,
the diaphragm receives the force F_top = K_d (s2(t+H) - u(t)) held over the next step. For the linear
tie (wall and diaphragm as the two masses) the exact step map of that scheme, z_{n+1} = A(H) z_n with
z = (s2, s2', u, u', F), has a spectral radius

    rho(H) = 1 + alpha (omega_t H)^2 + O(H^4),   omega_t = sqrt(K_d / m_r),  1/m_r = 1/m_w + 1/m_d,

with alpha > 0 for every H: the held force pumps energy into the tie mode at a rate that grows with
H (there is no sharp threshold as for an explicit central difference; the coupling acts as a
negative damping). Per unit time the amplitude grows by sigma = ln(rho)/H ~ alpha omega_t^2 H, a
negative damping ratio zeta_num = sigma/omega_t ~ alpha omega_t H. alpha depends on the mass ratio
only: measured from A(H) (tests/python/test_coupling_safety.py), alpha ~ 0.048 for m_w = m_d/10,
0.31 for m_w = m_d, 0.66 for m_w = 10 m_d, at most 0.75 (a light diaphragm, or a wall whose top
barely moves). The rule keeps zeta_num, without the physical damping, below ZETA_NUM_MAX = 0.05 %
of critical (1 % of the 5 % a structure's own damping usually has), so

    H <= c sqrt(m_r / K_d),   c = ZETA_NUM_MAX / alpha(m_w/m_d)
                              (c = 0.0016 for m_w = m_d, 0.00067 for a light diaphragm).

Calibrated on the stiff tie of docs/coupling.md (K_d = 1e6 N/m per m, diaphragm 400 kg/m on
30 kN/m per m, a 3.2 m wall, El Centro at 0.15 g, 15 s): against the monolithic run (one CVODE,
no macro step), H = 1 ms gives a false collapse with tie forces of 197 kN/m, H = 0.36 ms (zeta_num
0.5 %) tie forces 9 times too large, H = 0.1 ms (0.2 %) an energy residual of 7 % of the ground
work, H = 25 us (0.05 %, the rule's 23 us) 1.4 %, first-order convergence from there on.

max_macro_step() finds that H from the exact step map itself, with the diaphragm's own spring
included (a stiff diaphragm carries the force to the ground and allows a larger step), and without
its damping (the energy the scheme makes shows in the residual whether or not the physics later
damps it). Holding the force is the weak side: the diaphragm's mass m_d sets alpha, the wall's
mass acts only through m_r. A tie so stiff that the step is impractical is what --monolithic is for.
"""
import dataclasses
import math

import numpy as np

from . import linear_models, step_map

ZETA_NUM_MAX = 5e-4       # the largest negative damping ratio the coupling may add to the tie mode
ENERGY_SHARE_MAX = 0.01   # the largest |energy residual| as a share of the peak |ground work|
# A run whose energy residual exceeds this share of the peak input work ends with an error: no
# stable run at a usable step comes near it (the largest measured, held inputs at 8 ms, is 0.31 of
# it), while an unstable exchange passes it long before a wall it drives is declared collapsed.
ENERGY_STOP_SHARE = 0.5
H_SEARCH = (1e-8, 1e-2)   # s: the range max_macro_step searches


def wall_top_mass(W, psi, h, g=9.81):
    """Effective mass [kg/m] of the wall at its top, 1 / (J M^-1 J^T), with M the mass matrix of
    the wall's Eq. 3.2 (docs/model.md, support 3) and s2 = (h/2)(q1 + q2), J = (h/2)(1, 1): the mass a
    force at the top accelerates, the hinge free to move."""
    W1, Wd = W / 2.0, psi * W / 2.0
    hg = h * h / g
    M = hg * np.array([[W1 / 3.0 + Wd / 4.0, W1 / 8.0 + Wd / 4.0],
                       [W1 / 8.0 + Wd / 4.0, W1 / 12.0 + Wd / 4.0]])
    J = np.array([h / 2.0, h / 2.0])
    return 1.0 / float(J @ np.linalg.solve(M, J))


def jacobi_step_map(m_w, m_d, Kd, k, c, H):
    """The 5 x 5 map A(H) of one macro step of the Jacobi scheme on the linear tie, state
    (s2, s2', u, u', F): the wall's top (mass m_w) on the spring Kd to u held at u_n, the diaphragm
    (m_d, k, c) under the force F held, then F_{n+1} = Kd (s2_{n+1} - u_n)."""
    from scipy.linalg import expm
    # continuous system over the step on (s2, s2', u, u', F, u_held)
    A = np.zeros((6, 6))
    A[0, 1] = 1.0
    A[1, 0], A[1, 5] = -Kd / m_w, Kd / m_w
    A[2, 3] = 1.0
    A[3, 2], A[3, 3], A[3, 4] = -k / m_d, -c / m_d, 1.0 / m_d
    E = expm(A * H)
    lift = np.zeros((6, 5))
    lift[:5, :5] = np.eye(5)
    lift[5, 2] = 1.0                      # u_held = u at the start of the step
    after = E @ lift
    step = np.zeros((5, 5))
    step[:4] = after[:4]
    step[4] = Kd * (after[0] - lift[5])   # the wall's output F_top at the end of the step
    return step


def tie_frequency(m_w, m_d, Kd, k):
    """The highest natural frequency [rad/s] of the linear wall-tie-diaphragm system."""
    stiffness = np.array([[Kd, -Kd], [-Kd, Kd + k]])
    return float(np.sqrt(np.max(np.linalg.eigvals(stiffness / np.array([[m_w], [m_d]])).real)))


def numerical_damping(m_w, m_d, Kd, k, c, H):
    """The growth rate per unit time the scheme gives the linear tie, ln(rho(A(H)))/H, over the
    tie's frequency: a negative damping ratio when positive."""
    rho = max(abs(np.linalg.eigvals(jacobi_step_map(m_w, m_d, Kd, k, c, H))))
    return math.log(rho) / H / tie_frequency(m_w, m_d, Kd, k)


def max_macro_step(m_w, m_d, Kd, k, zeta_num_max=ZETA_NUM_MAX):
    """The largest macro step H [s] for which the coupling adds at most zeta_num_max of negative
    damping to the tie (see the module's docstring); H_SEARCH[1] when even that step is safe (no
    tie: Kd = 0). Scans H on a log grid from H_SEARCH[0] and stops at the first step that breaks
    the bound, then refines by bisection."""
    if Kd <= 0:
        return H_SEARCH[1]

    def ok(H):
        return numerical_damping(m_w, m_d, Kd, k, 0.0, H) <= zeta_num_max

    grid = np.geomspace(*H_SEARCH, 61)
    if not ok(grid[0]):
        return grid[0]
    for lo, hi in zip(grid[:-1], grid[1:]):
        if not ok(hi):
            for _ in range(30):
                mid = math.sqrt(lo * hi)
                lo, hi = (mid, hi) if ok(mid) else (lo, mid)
            return lo
    return H_SEARCH[1]


def work(t, power):
    """The work of a power history up to each time of t (trapezoidal rule, 0 at t[0]): the energy
    terms of the coupled scenes' bookkeeping."""
    return np.concatenate([[0.0], np.cumsum(0.5 * (power[1:] + power[:-1]) * np.diff(t))])


def energy_check(residual, ground_work, share_max=ENERGY_SHARE_MAX):
    """(share, ok): the largest |energy residual| as a share of the largest |ground work|, and
    whether it is within share_max. A run with no ground work has share 0 when its residual is 0."""
    peak_work = float(np.max(np.abs(ground_work))) if len(ground_work) else 0.0
    peak_res = float(np.max(np.abs(residual))) if len(residual) else 0.0
    if peak_work <= 0.0:
        share = 0.0 if peak_res == 0.0 else math.inf
    else:
        share = peak_res / peak_work
    return share, bool(share <= share_max)


# ---- the building's exchange: walls standing on diaphragms, walls tied to diaphragms ----------

BASE_RATIO_SEARCH = (1e-3, 1e2)   # the ratios m_b/m_d base_ratio_limit searches


def base_exchange_growth(wall_params, law, md, kd, cd, H, order):
    """The worst mode (step_map.Growth) of the Jacobi exchange of one wall standing on a diaphragm
    (mass md, stiffness kd, dashpot cd, its floor still), the wall's top free: the building reads
    the wall's F_base, the wall the diaphragm's absolute acceleration."""
    slaves, connections = linear_models.wall_on_diaphragm(wall_params, law, md, kd, cd)
    return step_map.worst_growth(step_map.jacobi_step_map(slaves, connections, H, order), H)


def base_ratio_limit(wall_params, law, kd, cd, H, order, zeta_num_max=ZETA_NUM_MAX):
    """The largest ratio m_b/m_d of the wall's effective mass on its base to the diaphragm's mass
    at which the base exchange (base_exchange_growth) adds at most zeta_num_max of negative
    damping; 0 if even BASE_RATIO_SEARCH[0] does not hold. Bisection on the ratio."""
    m_b = linear_models.base_mass(wall_params, law)

    def holds(ratio):
        return base_exchange_growth(wall_params, law, m_b / ratio, kd, cd, H, order).zeta_num <= zeta_num_max

    lo, hi = BASE_RATIO_SEARCH
    if not holds(lo):
        return 0.0
    if holds(hi):
        return hi
    for _ in range(40):
        mid = math.sqrt(lo * hi)
        lo, hi = (mid, hi) if holds(mid) else (lo, mid)
    return lo


def tie_step_limit(wall_params, law, md, kd, cd, order, zeta_num_max=ZETA_NUM_MAX):
    """The largest macro step [s] at which the tie's exchange (the wall, standing on the ground,
    tied by its K_d to a diaphragm md, kd, cd whose floor is still) adds at most zeta_num_max of
    negative damping: bisection on a log scale within H_SEARCH (its ends when it holds
    everywhere or nowhere)."""
    slaves, connections = linear_models.wall_tied_to_diaphragm(wall_params, law, md, kd, cd)

    def holds(H):
        return step_map.worst_growth(step_map.jacobi_step_map(slaves, connections, H, order), H).zeta_num <= zeta_num_max

    lo, hi = H_SEARCH
    if not holds(lo):
        return lo
    if holds(hi):
        return hi
    for _ in range(40):
        mid = math.sqrt(lo * hi)
        lo, hi = (mid, hi) if holds(mid) else (lo, mid)
    return lo


@dataclasses.dataclass(frozen=True)
class WallExchange:
    """One wall's exchanges in a co-simulated building: the wall's effective mass on its base m_b
    and the mass m_d of the diaphragm it stands on (None for the ground storey), the largest ratio
    m_b/m_d the base exchange takes at this step and order, and the tie's negative damping on the
    wall tied to its diaphragm alone (its floor still)."""
    storey: int
    m_b: float
    m_d_below: float
    ratio_limit: float
    tie_zeta_num: float

    @property
    def ratio(self):
        return None if self.m_d_below is None else self.m_b / self.m_d_below

    @property
    def base_holds(self):
        return self.ratio is None or self.ratio <= self.ratio_limit


@dataclasses.dataclass(frozen=True)
class SceneStability:
    """What the Jacobi scheme does to a co-simulated building about rest, at macro step H and
    order 1 (inputs held) or 2 (ramped): the worst mode of the whole scene's step map and each
    wall's exchanges. stable: that mode's negative damping is at most ZETA_NUM_MAX."""
    H: float
    order: int
    growth: step_map.Growth
    walls: tuple

    @property
    def stable(self):
        return self.growth.zeta_num <= ZETA_NUM_MAX

    def cause(self):
        """The likely cause of an instability, in words (empty when the scheme holds)."""
        inputs = "ramped" if self.order == 2 else "held"
        parts = []
        for w in self.walls:
            if not w.base_holds:
                parts.append(f"the wall of storey {w.storey} rides on diaphragm {w.storey - 1} with an effective "
                             f"mass on its base of {w.m_b:.0f} kg/m, {w.ratio:.2f} times the diaphragm's "
                             f"{w.m_d_below:.0f} kg/m; the exchange of its base force and the floor's acceleration "
                             f"with {inputs} inputs holds up to {w.ratio_limit:.3g} at H = {1e3 * self.H:g} ms"
                             + (", at any smaller step too" if self.order == 2 else ""))
            if w.tie_zeta_num > ZETA_NUM_MAX:
                parts.append(f"the tie of the wall of storey {w.storey} needs a smaller macro step than "
                             f"H = {1e3 * self.H:g} ms (negative damping {w.tie_zeta_num:.2g} of critical)")
        if not parts and not self.stable:
            parts.append(f"the macro step H = {1e3 * self.H:g} ms with {inputs} inputs: the exchange adds "
                         f"{self.growth.zeta_num:.2g} of negative damping to a mode at "
                         f"{self.growth.omega / (2 * math.pi):.3g} Hz")
        return "; ".join(parts)


def _diaphragm(values, i):
    return values[f"md_{i}"], values[f"kd_{i}"], values.get(f"cd_{i}", 0.0)


def scene_stability(scene, H, order):
    """Predicts whether the Jacobi master holds a co-simulated building (a
    rockingwall.building.scene.Scene) at macro step H and order 1 or 2: the exact step map of the
    whole scene about rest (its walls in their elastic range, its springs at their initial
    stiffness; step_map, linear_models), and for each wall its base and tie exchanges alone."""
    slaves, connections = linear_models.scene_slaves(scene)
    growth = step_map.worst_growth(step_map.jacobi_step_map(slaves, connections, H, order), H)
    values = dict(linear_models.fmu_start_values(scene.building_fmu), **scene.building_real)
    walls = []
    for w in scene.walls:
        law = int(w.integer.get("hingeLaw", 4))
        real = linear_models.wall_values(scene, w)
        m_b = linear_models.base_mass(real, law)
        md_below = ratio_limit = None
        if w.storey > 1:
            md_below, kd, cd = _diaphragm(values, w.storey - 1)
            ratio_limit = base_ratio_limit(real, law, kd, cd, H, order)
        tie = linear_models.wall_tied_to_diaphragm(real, law, *_diaphragm(values, w.storey))
        tie_growth = step_map.worst_growth(step_map.jacobi_step_map(*tie, H, order), H)
        walls.append(WallExchange(w.storey, m_b, md_below, ratio_limit, tie_growth.zeta_num))
    return SceneStability(H, order, growth, tuple(walls))
