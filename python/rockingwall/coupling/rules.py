"""Safety rules of the wall-diaphragm coupling (`rockingwall couple`): the largest macro step the
tie K_d allows, and the check of the energy bookkeeping. Documented in docs/coupling.md.

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
import math

import numpy as np

ZETA_NUM_MAX = 5e-4       # the largest negative damping ratio the coupling may add to the tie mode
ENERGY_SHARE_MAX = 0.01   # the largest |energy residual| as a share of the peak |ground work|
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
