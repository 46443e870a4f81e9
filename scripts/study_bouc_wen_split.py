"""Bouc-Wen diaphragms with the linear part exact and z fitted: a study on a reduced scene.

The method that could bring Bouc-Wen diaphragms onto the exact engine: the scene's
linear part propagated exactly (exp(Aa h), as the exact engine does), the hysteretic force
(1 - alpha) Fy z(t) taken over each step as a polynomial input in the augmented state, and z fitted
by Picard iteration along the exact motion. It is measured here on a reduced scene, not built into
the engine (docs/scenes.md, "Bouc-Wen on the exact engine").

The reduced scene: a wall's mass (1 500 kg/m on a spring of 100 kN/m per m, standing in for the
wall) tied by the tie (1e8 or 1e6 N/m per m) to a diaphragm of 200 kg/m with a Bouc-Wen spring
(200 kN/m per m, yield force 2 % of that times 1 m, post-yield ratio 0.1, n = 1, beta = 0.5: the
benchmark's law) and 5 % damping, its supports on the ground. The record: FEMA P695 ff19a from
30 s for 12 s, scaled to PGA 0.3 g (the strong part). Every 0.25 s the wall's velocity is
multiplied by 0.86, as at a rocking wall's impacts: those jumps set the tie ringing, which is what
makes CVODES take 380 000 steps over the benchmark's record.

Each step of length h: the input z is z0 + z1 tau (a line) or z0 + z1 tau + z2 tau^2 (a quadratic);
the diaphragm's velocity at 2 sub + 1 equally spaced points of the step comes from the exact
propagators to those points; z is integrated along it (RK4 on the sub steps) and the polynomial
refitted through z's values (the line through the end, the quadratic through the middle and the
end) until the fit moves by less than 1e-13. The oracle: DOP853 at rtol 1e-12 on each interval
between the record's samples and the jumps. Printed per step length: the steps, the Picard
iterations per step, the largest error of the diaphragm's deformation on the record's 5-ms grid
relative to its peak, and the error of the end state relative to its size.

    .venv/bin/python scripts/study_bouc_wen_split.py [--tie 1e8] [--sub 4]
"""
import argparse
import pathlib
import sys

import numpy as np
from scipy.integrate import solve_ivp
from scipy.linalg import expm

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))  # run by path: the benchmark's record
import bench_scenes  # noqa: E402

WALL_MASS, WALL_K = 1500.0, 1e5
MASS, K, ALPHA, DAMPING = 200.0, 2e5, 0.1, 0.05
FY = 0.02 * K
UY = FY / K
DASHPOT = 2.0 * DAMPING * np.sqrt(K * MASS)
N_BW, BETA = 1.0, 0.5
GAMMA = 1.0 - BETA
START, LENGTH, PGA = 30.0, 12.0, 0.3
JUMP_EVERY, RESTITUTION = 0.25, 0.86
STEPS = (0.005, 0.0025, 0.00125, 0.000625)


def z_rate(z, v):
    return v / UY * (1.0 - abs(z) ** N_BW * (BETA * np.sign(v * z) + GAMMA))


def the_record():
    """ff19a's strong part, from START for LENGTH s, at PGA g"""
    t, ag = bench_scenes.record(PGA, START + LENGTH)
    keep = t >= START - 1e-9
    return np.round(t[keep] - START, 9), ag[keep]


def stops(t_rec):
    """the record's samples and the jumps"""
    return np.unique(np.concatenate([t_rec, np.arange(JUMP_EVERY, t_rec[-1], JUMP_EVERY)]))


def is_jump(t):
    return t > 0.0 and abs(t / JUMP_EVERY - round(t / JUMP_EVERY)) < 1e-9


def oracle(tie, t_rec, ag_rec):
    """DOP853 at rtol 1e-12: the state (uw, vw, ud, vd, z) at the end and ud on the record's grid"""
    def rhs(t, y, a0, slope, t0):
        uw, vw, ud, vd, z = y
        ag = a0 + slope * (t - t0)
        aw = (-WALL_K * uw - tie * (uw - ud)) / WALL_MASS - ag
        ad = (-tie * (ud - uw) - ALPHA * K * ud - (1.0 - ALPHA) * FY * z - DASHPOT * vd) / MASS - ag
        return [vw, aw, vd, ad, z_rate(z, vd)]

    y, grid = np.zeros(5), {}
    ts = stops(t_rec)
    for t0, t1 in zip(ts[:-1], ts[1:]):
        if is_jump(t0):
            y[1] *= RESTITUTION
        a0, a1 = np.interp([t0, t1], t_rec, ag_rec)
        y = solve_ivp(rhs, (t0, t1), y, method="DOP853", rtol=1e-12, atol=1e-15,
                      args=(a0, (a1 - a0) / (t1 - t0), t0)).y[:, -1]
        grid[round(t1, 9)] = y[2]
    return y, grid


def augmented(tie, degree):
    """the first-order matrix over (uw, vw, ud, vd, ag, ag', z's chain): z = s0, s0' = s1, s1' = 2 s2"""
    n = 6 + degree + 1
    A = np.zeros((n, n))
    A[0, 1] = A[2, 3] = A[4, 5] = 1.0
    A[1, 0], A[1, 2], A[1, 4] = (-WALL_K - tie) / WALL_MASS, tie / WALL_MASS, -1.0
    A[3, 0], A[3, 2], A[3, 3], A[3, 4] = tie / MASS, (-tie - ALPHA * K) / MASS, -DASHPOT / MASS, -1.0
    A[3, 6] = -(1.0 - ALPHA) * FY / MASS
    for k in range(degree):
        A[6 + k, 7 + k] = k + 1.0
    return A


def refit(z0, z_mid, z_end, h, degree):
    """the chain's rates: the line through the end, or the quadratic through the middle and the end"""
    if degree == 1:
        return [(z_end - z0) / h]
    z2 = 2.0 * ((z_end - z0) - 2.0 * (z_mid - z0)) / h ** 2
    return [(z_end - z0 - z2 * h * h) / h, z2]


def split(tie, t_rec, ag_rec, h, degree, sub=4):
    """the method at steps of h (dividing the record's intervals): the end state, the deformation
    on the record's grid, the steps and the Picard rounds"""
    props = [expm(augmented(tie, degree) * tau) for tau in np.arange(2 * sub + 1) * h / (2 * sub)]
    y, z, iterations, steps, grid = np.zeros(4), 0.0, 0, 0, {}
    ts = stops(t_rec)
    for t0, t1 in zip(ts[:-1], ts[1:]):
        if is_jump(t0):
            y[1] *= RESTITUTION
        a0, a1 = np.interp([t0, t1], t_rec, ag_rec)
        slope, parts = (a1 - a0) / (t1 - t0), int(round((t1 - t0) / h))
        for j in range(parts):
            rates = [z_rate(z, y[3])] + [0.0] * (degree - 1)
            for _ in range(50):
                iterations += 1
                X = [P @ np.concatenate([y, [a0 + slope * j * h, slope, z], rates]) for P in props]
                zs, zz, dt = [z], z, h / sub
                for q in range(sub):
                    v0, vm, v1 = X[2 * q][3], X[2 * q + 1][3], X[2 * q + 2][3]
                    k1 = z_rate(zz, v0)
                    k2 = z_rate(zz + 0.5 * dt * k1, vm)
                    k3 = z_rate(zz + 0.5 * dt * k2, vm)
                    zz += dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + z_rate(zz + dt * k3, v1))
                    zs.append(zz)
                new = refit(z, zs[sub // 2], zz, h, degree)
                moved = max(abs(a - b) * h ** (k + 1) for k, (a, b) in enumerate(zip(new, rates)))
                rates = new
                if moved < 1e-13:
                    break
            y, z = X[-1][:4], zz
            steps += 1
        grid[round(t1, 9)] = y[2]
    return np.concatenate([y, [z]]), grid, steps, iterations


def errors(tie, t_rec, ag_rec, h, degree, sub=4, truth=None):
    """the method's errors against the oracle (given, or computed): the deformation's history's
    relative to its peak, the end state's relative to its size; the steps and Picard rounds a step"""
    end, grid = truth or oracle(tie, t_rec, ag_rec)
    y, g, steps, iterations = split(tie, t_rec, ag_rec, h, degree, sub)
    peak = max(abs(v) for v in grid.values())
    return (max(abs(g[t] - grid[t]) for t in grid) / peak, np.max(np.abs(y - end)) / np.max(np.abs(end)),
            steps, iterations / steps)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tie", type=float, default=1e8, help="the tie's stiffness, N/m per m (default 1e8)")
    ap.add_argument("--sub", type=int, default=4, help="RK4 sub steps of z per step (default 4)")
    args = ap.parse_args(argv)
    t_rec, ag_rec = the_record()
    truth = oracle(args.tie, t_rec, ag_rec)
    peak = max(abs(v) for v in truth[1].values())
    print(f"tie {args.tie:.0e} N/m per m: the diaphragm's peak deformation {peak * 1e3:.3f} mm (DOP853, rtol 1e-12)")
    print(f"{'z over a step':>13} {'h ms':>6} {'steps':>6} {'Picard/step':>11} {'history err':>11} {'end err':>8}")
    for degree, name in ((1, "line"), (2, "quadratic")):
        for h in STEPS:
            history, end_err, steps, rounds = errors(args.tie, t_rec, ag_rec, h, degree, args.sub, truth)
            print(f"{name:>13} {h * 1e3:6.3f} {steps:6d} {rounds:11.2f} {history:11.2e} {end_err:8.1e}", flush=True)


if __name__ == "__main__":
    main()
