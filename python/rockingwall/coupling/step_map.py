"""The exact step map of the package's Jacobi master (rockingwall.coupling.jacobi) over linear
slaves: what one macro step does to the coupled system, for its stability (rockingwall.coupling.rules).

Each slave is linear, x' = A x + B u, y = C x + D u, and integrates its step exactly: over
[t_k, t_k + H] its inputs are u_k (held, order 1) or u_k + s_k (t - t_k) (ramped, order 2). The
master does what jacobi.exchange does: at t_k every coupled input is its source's output read at
the end of the previous step (with the inputs then in force, u_(k-1) + s_(k-1) H), the slope is
(u_k - u_(k-1))/H with order 2 and 0 with order 1, and every slave steps from the same point.
The inputs that take the record are 0 here (the homogeneous scheme: its growth is the
instability). So with z_k = (x_k, u_(k-1), s_(k-1)) the step is linear, z_(k+1) = S(H) z_k, and
the scheme is stable when the spectral radius of S is at most 1.

Over a step, (x, u, s) with u' = s, s' = 0 is one linear system, so exp of its matrix over H gives
the state map Phi, the held input's Gamma0 and the slope's Gamma1 at once."""
import dataclasses
import math

import numpy as np


@dataclasses.dataclass
class LinearSlave:
    """One slave: x' = A x + B u, y = C x + D u, its inputs and outputs named."""
    name: str
    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    D: np.ndarray
    inputs: list
    outputs: list

    def step_matrices(self, H):
        """(Phi, Gamma0, Gamma1): x(t + H) = Phi x + Gamma0 u + Gamma1 s for the input u + s t."""
        from scipy.linalg import expm
        n, m = self.A.shape[0], len(self.inputs)
        big = np.zeros((n + 2 * m, n + 2 * m))
        big[:n, :n], big[:n, n:n + m] = self.A, self.B
        big[n:n + m, n + m:] = np.eye(m)
        E = expm(big * H)
        return E[:n, :n], E[:n, n:n + m], E[:n, n + m:]


def jacobi_step_map(slaves, connections, H, order):
    """The matrix S(H) of one macro step (the module's docstring). connections: (from slave,
    output, to slave, input) for every coupled input; an input no connection feeds is 0."""
    if order not in (1, 2):
        raise ValueError(f"order {order!r}: 1 (inputs held) or 2 (inputs ramped)")
    nx = [s.A.shape[0] for s in slaves]
    nu = [len(s.inputs) for s in slaves]
    ox, ou = np.cumsum([0] + nx), np.cumsum([0] + nu)
    NX, NU = ox[-1], ou[-1]
    index = {s.name: k for k, s in enumerate(slaves)}
    # outputs at the start of the step, y = Cx x + Cu (u_prev + H s_prev), stacked over the slaves
    ny = [len(s.outputs) for s in slaves]
    oy = np.cumsum([0] + ny)
    Cx, Cu = np.zeros((oy[-1], NX)), np.zeros((oy[-1], NU))
    for k, s in enumerate(slaves):
        Cx[oy[k]:oy[k + 1], ox[k]:ox[k + 1]] = s.C
        Cu[oy[k]:oy[k + 1], ou[k]:ou[k + 1]] = s.D
    L = np.zeros((NU, oy[-1]))  # the inputs from the outputs
    for src, out, dst, inp in connections:
        a, b = index[src], index[dst]
        L[ou[b] + slaves[b].inputs.index(inp), oy[a] + slaves[a].outputs.index(out)] = 1.0
    # z = (x, u_prev, s_prev) -> u = L y
    Y = np.hstack([Cx, Cu, H * Cu])
    U = L @ Y
    Sl = (U - np.hstack([np.zeros((NU, NX)), np.eye(NU), np.zeros((NU, NU))])) / H if order == 2 else np.zeros_like(U)
    X = np.zeros((NX, NX + 2 * NU))
    for k, s in enumerate(slaves):
        Phi, G0, G1 = s.step_matrices(H)
        rows = slice(ox[k], ox[k + 1])
        X[rows, ox[k]:ox[k + 1]] += Phi
        X[rows] += G0 @ U[ou[k]:ou[k + 1]] + G1 @ Sl[ou[k]:ou[k + 1]]
    return np.vstack([X, U, Sl])


@dataclasses.dataclass(frozen=True)
class Growth:
    """One eigenvalue of a step map: its modulus rho (per step), the growth rate
    sigma = ln(rho)/H [1/s], its frequency omega = |arg|/H [rad/s], and the scheme's negative
    damping ratio on that mode, sigma/omega (inf for a real positive eigenvalue above 1)."""
    rho: float
    sigma: float
    omega: float
    zeta_num: float


def worst_growth(S, H):
    """The mode of the step map S (over a step H) the scheme drives hardest: among the eigenvalues
    outside the unit circle the one with the largest negative damping ratio sigma/omega (a real
    eigenvalue above 1 counts as infinite), else the largest eigenvalue."""
    modes = []
    for lam in np.linalg.eigvals(S):
        rho = float(abs(lam))
        sigma = math.log(rho) / H if rho > 0 else -math.inf
        omega = abs(float(np.angle(lam))) / H
        zeta = sigma / omega if omega > 0 else (math.inf if sigma > 0 else 0.0)
        modes.append(Growth(rho, sigma, omega, zeta))
    growing = [m for m in modes if m.rho > 1.0]
    if growing:
        return max(growing, key=lambda m: m.zeta_num)
    return max(modes, key=lambda m: m.rho)
