#!/usr/bin/env python3
"""RockingWall coupled to a Diaphragm FMU through FMI 2.0 Co-Simulation.

The paper's top spring K_d is fixed to the ground at its far end; here its far end is a diaphragm
with mass, stiffness and damping (build/Diaphragm.fmu). Both FMUs are Co-Simulation slaves that
integrate themselves with CVODE; a master exchanges their values every macro step H:

    ground motion ag(t)  --> wall.ag,  diaphragm.ag          [m/s2, + toward +x]
    diaphragm.u          --> wall.u_top                      [m, relative to the ground]
    wall.F_top           --> diaphragm.F_top                 [N/m, force of the spring on the diaphragm]

Two independent masters run the same fixed-step Jacobi scheme (every slave steps from t to t+H
with the inputs set at t; after the step the outputs at t+H become the inputs of the next step):
fmpy (FMU2Slave, in this process) and libcosim (libcosimpy, run in a subprocess because it can
crash on a bad FMU). The ground motion is held over each step in both.

    scripts/couple.py                                  # wall 1, El Centro x 0.5, fmpy master
    scripts/couple.py --master both                    # fmpy and libcosim, and their difference
    scripts/couple.py --macro-step 0.005 --t-end 20 --Kd 1e5 --m 2000 --k 7e5 --zeta 0.05

Writes results/couple.csv (time, s1, s2, u, F_top and the energy terms) and results/couple.png.
"""
import argparse
import json
import pathlib
import subprocess
import sys

import numpy as np

REPO = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "reference"))

from rwref.inputs import el_centro, read_at2  # noqa: E402
from rwref.params import WALLS  # noqa: E402

WALL_OUT = ["s1", "s2", "F_top", "energy", "P_ground", "dissipated"]
DIA_OUT = ["u", "v", "energy", "P_ground", "P_damping"]
MODELS = {"parapet": 1, "simplySupported": 2, "flexibleTop": 3}
LAWS = {"rigid": 1, "semiRigidPaper": 2, "semiRigidHinge": 3, "dohertyHinge": 4}


def vrs(md):
    return {v.name: v.valueReference for v in md.modelVariables}


def wall_start_values(wall=1, Kd=1e5, hinge_law="dohertyHinge", er=0.86):
    """Real and Integer start values of RockingWall for one of the paper's walls."""
    real = dict(WALLS[wall], Kd=Kd, er=er)
    return real, {"support": MODELS["flexibleTop"], "hingeLaw": LAWS[hinge_law]}


def ground_motion(record="elcentro", scale=0.5):
    sig = el_centro(scale) if record == "elcentro" else read_at2(record, scale=scale)
    return np.asarray(sig.t, float), np.asarray(sig.a, float)


class CoupledResult(dict):
    """Arrays on the communication grid: time, wall_*, dia_* and the energy balance."""

    def energy_residual(self):
        """(E_wall + E_dia)(t) - E(0) - ground work + damping + impact losses: the energy the
        coupled system made or lost unaccounted for (trapezoidal work integrals)."""
        t = self["time"]
        stored = self["wall_energy"] + self["dia_energy"]
        power_in = self["wall_P_ground"] + self["dia_P_ground"] - self["dia_P_damping"]
        work = np.concatenate([[0.0], np.cumsum(0.5 * (power_in[1:] + power_in[:-1]) * np.diff(t))])
        return stored - stored[0] - work + self["wall_dissipated"]

    def _work(self, p):
        return np.concatenate([[0.0], np.cumsum(0.5 * (p[1:] + p[:-1]) * np.diff(self["time"]))])

    def ground_work(self):
        return self._work(self["wall_P_ground"] + self["dia_P_ground"])

    def damping_loss(self):
        return self._work(self["dia_P_damping"])


def _assemble(t, wall_rows, dia_rows):
    r = CoupledResult(time=np.asarray(t))
    w, d = np.asarray(wall_rows), np.asarray(dia_rows)
    for i, n in enumerate(WALL_OUT):
        r["wall_" + n] = w[:, i]
    for i, n in enumerate(DIA_OUT):
        r["dia_" + n] = d[:, i]
    return r


def run_fmpy(wall_fmu, dia_fmu, t_in, ag_in, t_end, H, wall=None, dia=None, rtol=1e-6, progress=False):
    """The fmpy master: fixed-step Jacobi over two Co-Simulation slaves."""
    from fmpy import extract, read_model_description
    from fmpy.fmi2 import FMU2Slave

    slaves = []
    for path, name, (real, integer) in [(wall_fmu, "wall", wall or wall_start_values()),
                                        (dia_fmu, "diaphragm", (dia or {}, {}))]:
        md = read_model_description(str(path))
        s = FMU2Slave(guid=md.guid, unzipDirectory=extract(str(path)),
                      modelIdentifier=md.coSimulation.modelIdentifier, instanceName=name)
        s.vr = vrs(md)
        s.instantiate()
        s.setupExperiment(tolerance=rtol, startTime=0.0)
        s.setReal([s.vr[k] for k in real], list(real.values()))
        s.setInteger([s.vr[k] for k in integer], list(integer.values()))
        s.enterInitializationMode()
        s.exitInitializationMode()
        slaves.append(s)
    w, d = slaves
    n = int(round(t_end / H))
    times, wall_rows, dia_rows = [], [], []
    u = d.getReal([d.vr["u"]])[0]
    w.setReal([w.vr["u_top"]], [u])
    F = w.getReal([w.vr["F_top"]])[0]
    steps = range(n)
    if progress:
        from tqdm import tqdm
        steps = tqdm(steps, desc="fmpy master", unit="step", mininterval=1.0)
    collapsed_at = None
    for k in steps:
        t = k * H
        ag = float(np.interp(t, t_in, ag_in, right=0.0))
        w.setReal([w.vr["ag"], w.vr["u_top"]], [ag, u])
        d.setReal([d.vr["ag"], d.vr["F_top"]], [ag, F])
        times.append(t)
        wall_rows.append(w.getReal([w.vr[x] for x in WALL_OUT]))
        dia_rows.append(d.getReal([d.vr[x] for x in DIA_OUT]))
        try:
            w.doStep(currentCommunicationPoint=t, communicationStepSize=H)
        except Exception:  # fmi2Discard: the wall collapsed and the FMU ended the run
            collapsed_at = t
            break
        d.doStep(currentCommunicationPoint=t, communicationStepSize=H)
        F = w.getReal([w.vr["F_top"]])[0]  # with the u_top of the step (Jacobi)
        u = d.getReal([d.vr["u"]])[0]
    else:
        times.append(n * H)
        w.setReal([w.vr["u_top"]], [u])
        d.setReal([d.vr["F_top"]], [F])
        wall_rows.append(w.getReal([w.vr[x] for x in WALL_OUT]))
        dia_rows.append(d.getReal([d.vr[x] for x in DIA_OUT]))
    for s in slaves:
        s.terminate()
        s.freeInstance()
    r = _assemble(times, wall_rows, dia_rows)
    r["collapsed_at"] = collapsed_at
    return r


def run_libcosim(wall_fmu, dia_fmu, t_in, ag_in, t_end, H, wall=None, dia=None):
    """The libcosim master (libcosimpy) with the same Jacobi scheme: call it in a subprocess
    (run_libcosim_subprocess), libcosim aborts the process on some FMU errors."""
    from fmpy import read_model_description
    from libcosimpy.CosimEnums import CosimVariableType
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimManipulator import CosimManipulator
    from libcosimpy.CosimObserver import CosimObserver
    from libcosimpy.CosimSlave import CosimLocalSlave

    real, integer = wall or wall_start_values()
    wv, dv = vrs(read_model_description(str(wall_fmu))), vrs(read_model_description(str(dia_fmu)))
    ex = CosimExecution.from_step_size(step_size=int(round(H * 1e9)))  # nanoseconds
    iw = ex.add_local_slave(CosimLocalSlave(fmu_path=str(pathlib.Path(wall_fmu).resolve()), instance_name="wall"))
    idia = ex.add_local_slave(CosimLocalSlave(fmu_path=str(pathlib.Path(dia_fmu).resolve()), instance_name="diaphragm"))
    for k, v in real.items():
        ex.real_initial_value(iw, wv[k], v)
    for k, v in integer.items():
        ex.integer_initial_value(iw, wv[k], v)
    for k, v in (dia or {}).items():
        ex.real_initial_value(idia, dv[k], v)
    ex.connect_real_variables(idia, dv["u"], iw, wv["u_top"])
    ex.connect_real_variables(iw, wv["F_top"], idia, dv["F_top"])
    override = CosimManipulator.create_override()
    ex.add_manipulator(manipulator=override)
    observer = CosimObserver.create_last_value()
    ex.add_observer(observer=observer)
    # libcosim initialises the slaves inside its first step and its observer has values only
    # after a step: row 0 is the state at rest both slaves start from (every output 0)
    n = int(round(t_end / H))
    times, wall_rows, dia_rows = [0.0], [[0.0] * len(WALL_OUT)], [[0.0] * len(DIA_OUT)]
    for k in range(n):
        ag = float(np.interp(k * H, t_in, ag_in, right=0.0))
        override.slave_real_values(iw, [wv["ag"]], [ag])  # held over the step, as in run_fmpy
        override.slave_real_values(idia, [dv["ag"]], [ag])
        if not ex.step():
            break
        times.append((k + 1) * H)
        wall_rows.append(observer.last_real_values(iw, [wv[x] for x in WALL_OUT]))
        dia_rows.append(observer.last_real_values(idia, [dv[x] for x in DIA_OUT]))
    return _assemble(times, wall_rows, dia_rows)


def run_libcosim_subprocess(args_list, out_json):
    """Run this script's libcosim master in a fresh process; returns the CompletedProcess."""
    cmd = [sys.executable, str(pathlib.Path(__file__).resolve()), "--master", "libcosim", "--json", str(out_json)]
    return subprocess.run(cmd + list(args_list), capture_output=True, text=True, timeout=1800)


def save_csv(r, path):
    cols = ["time", "wall_s1", "wall_s2", "dia_u", "wall_F_top", "wall_energy", "dia_energy",
            "wall_P_ground", "dia_P_ground", "dia_P_damping", "wall_dissipated"]
    data = np.column_stack([r[c] for c in cols] + [r.energy_residual()])
    np.savetxt(path, data, delimiter=",", header=",".join(cols + ["energy_residual"]), comments="")


def plot(r, path, title, other=None):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(3, 1, figsize=(9, 7), sharex=True)
    t = r["time"]
    ax[0].plot(t, 1e3 * r["wall_s1"], label="s1 (mid-height)")
    ax[0].plot(t, 1e3 * r["wall_s2"], label="s2 (top)")
    ax[0].plot(t, 1e3 * r["dia_u"], label="u (diaphragm)")
    if other is not None:
        ax[0].plot(other["time"], 1e3 * other["wall_s1"], "k:", lw=1, label="s1, libcosim master")
    ax[0].set_ylabel("displacement [mm]")
    ax[0].legend(loc="upper right", fontsize=8)
    ax[1].plot(t, r["wall_F_top"] / 1e3)
    ax[1].set_ylabel("F_top [kN/m]")
    ax[2].plot(t, r.ground_work(), label="ground work")
    ax[2].plot(t, r["wall_energy"] + r["dia_energy"], label="stored (wall + diaphragm)")
    ax[2].plot(t, r["wall_dissipated"], label="lost in impacts")
    ax[2].plot(t, r.damping_loss(), label="lost in diaphragm damping")
    ax[2].plot(t, r.energy_residual(), label="residual")
    ax[2].set_ylabel("energy [J/m]")
    ax[2].set_xlabel("time [s]")
    ax[2].legend(loc="upper left", fontsize=8)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--wall-fmu", default=str(REPO / "build" / "RockingWall.fmu"))
    ap.add_argument("--diaphragm-fmu", default=str(REPO / "build" / "Diaphragm.fmu"))
    ap.add_argument("--record", default="elcentro", help="'elcentro' (quakeio) or a PEER .AT2 file")
    ap.add_argument("--scale", type=float, default=0.5)
    ap.add_argument("--wall", type=int, default=1, choices=sorted(WALLS))
    ap.add_argument("--Kd", type=float, default=1e5, help="wall-to-diaphragm spring, N/m per m")
    ap.add_argument("--hinge-law", default="dohertyHinge", choices=list(LAWS))
    ap.add_argument("--m", type=float, default=2000.0, help="diaphragm mass, kg per m of wall")
    ap.add_argument("--k", type=float, default=7e5, help="diaphragm stiffness, N/m per m of wall")
    ap.add_argument("--zeta", type=float, default=0.05)
    ap.add_argument("--macro-step", type=float, default=1e-3)
    ap.add_argument("--t-end", type=float, default=30.0)
    ap.add_argument("--rtol", type=float, default=1e-6)
    ap.add_argument("--master", choices=["fmpy", "libcosim", "both"], default="fmpy")
    ap.add_argument("--out", default=str(REPO / "results" / "couple.csv"))
    ap.add_argument("--plot", default=str(REPO / "results" / "couple.png"))
    ap.add_argument("--json", help="write the result arrays as JSON (used for the libcosim subprocess)")
    a = ap.parse_args(argv)
    t_in, ag_in = ground_motion(a.record, a.scale)
    wall = wall_start_values(a.wall, a.Kd, a.hinge_law)
    dia = {"m": a.m, "k": a.k, "zeta": a.zeta}
    if a.master == "libcosim":
        r = run_libcosim(a.wall_fmu, a.diaphragm_fmu, t_in, ag_in, a.t_end, a.macro_step, wall, dia)
        if a.json:
            pathlib.Path(a.json).write_text(json.dumps({k: np.asarray(v).tolist() for k, v in r.items()}))
        print(f"libcosim: peak s1 {np.abs(r['wall_s1']).max():.5f} m, s2 {np.abs(r['wall_s2']).max():.5f} m, "
              f"u {np.abs(r['dia_u']).max():.5f} m")
        return 0
    r = run_fmpy(a.wall_fmu, a.diaphragm_fmu, t_in, ag_in, a.t_end, a.macro_step, wall, dia, a.rtol, progress=True)
    other = None
    if a.master == "both":
        out_json = pathlib.Path(a.out).with_suffix(".libcosim.json")
        passthrough = [f"--{k.replace('_', '-')}={v}" for k, v in vars(a).items()
                       if k not in ("master", "json", "out", "plot")]
        proc = run_libcosim_subprocess(passthrough, out_json)
        if proc.returncode != 0:
            print(f"couple: the libcosim master failed (exit {proc.returncode}):\n{proc.stderr[-2000:]}", file=sys.stderr)
            return 1
        other = CoupledResult({k: np.asarray(v) for k, v in json.loads(out_json.read_text()).items()})
    pathlib.Path(a.out).parent.mkdir(parents=True, exist_ok=True)
    save_csv(r, a.out)
    title = (f"Wall {a.wall} + diaphragm (m = {a.m:g} kg/m, k = {a.k:g} N/m2, zeta = {a.zeta:g}), "
             f"K_d = {a.Kd:g} N/m2, H = {a.macro_step:g} s")
    plot(r, a.plot, title, other)
    w_in = r.ground_work()
    print(f"fmpy master, H = {a.macro_step:g} s: peak s1 {np.abs(r['wall_s1']).max():.5f} m, "
          f"s2 {np.abs(r['wall_s2']).max():.5f} m, diaphragm u {np.abs(r['dia_u']).max():.5f} m"
          + (f", wall collapsed at t = {r['collapsed_at']:.3f} s" if r["collapsed_at"] is not None else ""))
    print(f"energy: max |residual| {np.abs(r.energy_residual()).max():.4g} J/m against "
          f"max |ground work| {np.abs(w_in).max():.4g} J/m")
    if other is not None:
        n = min(len(r["time"]), len(other["time"]))
        diff = np.abs(r["wall_s1"][:n] - other["wall_s1"][:n]).max()
        print(f"libcosim master: peak s1 {np.abs(other['wall_s1']).max():.5f} m; "
              f"max |s1 fmpy - s1 libcosim| = {diff:.3g} m")
    print(f"wrote {a.out} and {a.plot}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
