"""The bilinear spring law (BD_BILINEAR = 3, `law = "bilinear"`: elastoplastic with kinematic
hardening, docs/building.md) for the Building's diaphragms and storeys:

- the Building FMU pushed cyclically (test_building.py's quasi-static push): the force against
  the deformation is the bilinear loop, the FMU's force equal to the play operator's (the law
  integrated exactly along the sampled deformation), elastic slope k, post-yield slope alpha k,
  yield at Fy, and the work per cycle the loop's area 4 (1 - alpha) Fy (u_max - Dy);
- a one-storey scene (the assessor's upper wall tied to a diaphragm that yields, El Centro at
  0.3 g: the wall collapses at 9.34 s, the diaphragm past 1.7 Dy before): the exact engine runs it
  by default, CVODES on the law's rate form converges to it with the tolerance at a linear
  diaphragm's step count, the energy balance closes in both; Bouc-Wen with a large n approaches it;
- the building file's `law = "bilinear"`: parsed, echoed, run by `rockingwall building`, carried
  to BuildingWithWalls.fmu and the co-simulated Building FMU;
- the laws' one table (Python's names and codes) and the FMUs' descriptions.
"""
import dataclasses
import json
import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from fmpy import simulate_fmu

import rockingwall
from rockingwall import cli, names, records
from rockingwall import scene_engine as se
from rockingwall.building import building_file, cosim, monolithic, with_walls
from test_building import cyclic_push, last_cycle, shoelace

# ---- the Building FMU pushed cyclically ------------------------------------------------------


def play(d, dy, z0=0.0):
    """The bilinear law's z along the sampled deformation d: z + (change of d)/Dy clipped to [-1, 1]
    at every sample, exact where d is monotone between samples (the law is rate-independent)."""
    z = np.empty_like(d)
    z[0] = z0
    for k in range(1, len(d)):
        z[k] = min(1.0, max(-1.0, z[k - 1] + (d[k] - d[k - 1]) / dy))
    return z


# (start values, deformation, force, work, k, Fy, alpha, push amplitude): a diaphragm pushed
# through its stiff floor, and a storey (test_building.py's) under a stiff diaphragm
SPRINGS = {
    "diaphragm": ({"storeyLaw": 0, "diaphragmLaw": 3, "kd_1": 7e5, "Fyd_1": 1e4, "alphad_1": 0.1, "k_1": 1e9},
                  "d_diaph_1", "F_diaph_1", "work_diaph_1", 7e5, 1e4, 0.1, 1.3e4),
    "storey": ({"storeyLaw": 3}, "drift_1", "V_storey_1", "work_storey_1", 2e7, 3e4, 0.05, 3.9e4),
}


@pytest.mark.parametrize("spring", sorted(SPRINGS))
def test_the_pushed_spring_draws_the_bilinear_loop(building_fmu, spring):
    """The force the FMU gives is alpha k d + (1 - alpha) Fy z with z the play operator's of its
    own deformation within 1e-3 Fy (measured: 3e-5 Fy for the diaphragm, 2e-4 for the storey, whose
    reversals fall between samples); the central-difference slope is k on the elastic branches and
    alpha k on the yielding ones within 1e-6 of k; the hysteretic force reaches (1 - alpha) Fy and
    stays there (|z| at most 1e-5 past 1: measured 7e-7, 1.4e-6); the work per cycle (the FMU's
    state) is the bilinear loop's area 4 (1 - alpha) Fy (u_max - Dy) within 0.1 % (measured 1e-5,
    2e-5). Bouc-Wen (n = 1, say) fails every one of these by percents."""
    extra, dn, fn, wn, k, fy, alpha, amplitude = SPRINGS[spring]
    r = cyclic_push(building_fmu, 1.0, amplitude, dt=0.02, extra=dict(extra, rayleighMass=2.0))
    d, F = r[dn], r[fn]
    dy = fy / k
    z = play(d, dy)
    analytic = alpha * k * d + (1 - alpha) * fy * z
    z_fmu = (F - alpha * k * d) / ((1 - alpha) * fy)
    c = last_cycle(r)
    first = len(r) - len(c)
    u_max = 0.5 * (c[dn].max() - c[dn].min())
    work = c[wn][-1] - c[wn][0]
    area = 4 * (1 - alpha) * fy * (u_max - dy)
    # slopes on the branches: the samples whose neighbours two either side move the same way
    step = np.diff(d)
    inner = np.arange(2, len(d) - 2)
    monotone = np.array([np.all(np.sign(step[i - 2:i + 2]) == np.sign(step[i])) and step[i] != 0 for i in inner])
    i = inner[monotone]
    slope = (F[i + 1] - F[i - 1]) / (d[i + 1] - d[i - 1])
    elastic = np.all([np.abs(z[i + j]) < 0.999 for j in (-1, 0, 1)], axis=0)
    # yielding since the sample before the last: the step that reaches the limit carries z past it
    # by the integrator's error (1e-6 here: a multistep method's history holds the elastic rate),
    # where it stays; that step's slope is neither branch's
    yielding = (np.abs(z[i - 2]) == 1.0) & (z[i - 2] == z[i + 1])
    print(f"{spring}: |F - play| {np.abs(F - analytic).max() / fy:.1e} Fy; slope error elastic "
          f"{np.abs(slope[elastic] / k - 1).max():.1e} ({elastic.sum()} samples), yielding "
          f"{np.abs(slope[yielding] / k - alpha).max():.1e} of k ({yielding.sum()}); max |z| - 1 "
          f"{np.abs(z_fmu).max() - 1:.1e}; u_max {u_max * 1e3:.2f} mm = {u_max / dy:.2f} Dy; work per cycle "
          f"{work:.3f} J/m, loop area {area:.3f} J/m (ratio {work / area:.6f}), shoelace {shoelace(c[dn], c[fn]):.3f}")
    assert u_max > 2 * dy, "the push does not yield the spring"
    assert elastic.sum() > 100 and yielding.sum() > 100
    assert np.abs(F - analytic).max() < 1e-3 * fy
    assert np.abs(slope[elastic] / k - 1).max() < 1e-6
    assert np.abs(slope[yielding] / k - alpha).max() < 1e-6
    assert z_fmu[first:].max() == pytest.approx(1.0, abs=1e-5) and z_fmu[first:].min() == pytest.approx(-1.0, abs=1e-5)
    assert np.abs(z_fmu).max() < 1.0 + 1e-5
    assert work == pytest.approx(area, rel=1e-3)


# ---- the one-storey scene under El Centro ----------------------------------------------------
WALL = dict(b=0.23, h=3.6, W=14904.0, psi=0.2013, hingeLaw=4, er=0.86, support=3, Kd=1e8)
KD, MD, FYD, ALPHAD = 2e5, 200.0, 0.02 * 2e5, 0.1  # Fyd: 2 % of kd x 1 m; Dy = 20 mm
DY = FYD / KD
PGA = 0.3
PEAKS = ("peak_s1", "peak_s2", "peak_diaphragm")  # (the base acceleration's is the ground's: rigid in-plane walls)


def scene(law, **shape):
    storey = se.StoreySpec(wall=WALL, md=MD, kd=KD, cd=2 * 0.05 * math.sqrt(KD * MD), Fyd=FYD, alphad=ALPHAD)
    return se.Spec(storeys=(storey,), diaphragm_law=law, **shape)


@pytest.fixture(scope="module")
def el_centro():
    return rockingwall.read_record("elcentro").to_pga(PGA)


@pytest.fixture(scope="module")
def bilinear_runs(el_centro):
    """The bilinear scene by CVODES at rtol 1e-10 and 1e-12, and by the default engine ('exact')."""
    runs = {rtol: se.run(scene("bilinear"), el_centro.t, el_centro.ag, rtol=rtol, engine="cvode")
            for rtol in (1e-10, 1e-12)}
    runs["exact"] = se.run(scene("bilinear"), el_centro.t, el_centro.ag)
    return runs


def peaks(r):
    return np.array([getattr(r, name)[0] for name in PEAKS])


def test_the_exact_engine_runs_the_law_and_cvodes_converges_to_it(bilinear_runs):
    """The exact engine takes bilinear diaphragms (each branch linear) and is the default; CVODES
    on the rate form comes to it as its tolerance tightens: within 1e-7 at rtol 1e-10, 1e-8 at
    1e-12 (measured 4e-8 and 6e-10), the collapse at the same time within 1e-6 s."""
    exact = bilinear_runs["exact"]
    assert se.exact_covers(scene("bilinear")) == (True, "") and exact.engine == "exact"
    for rtol, bound in ((1e-10, 1e-7), (1e-12, 1e-8)):
        cvode = bilinear_runs[rtol]
        assert np.all(np.abs(peaks(cvode) / peaks(exact) - 1) < bound), rtol
        assert cvode.collapsed[0] == exact.collapsed[0]
        assert abs(cvode.t_collapse[0] - exact.t_collapse[0]) < 1e-6


def test_cvodes_converges_on_the_yielding_scene(bilinear_runs, el_centro):
    """rtol 1e-10 against 1e-12: the peaks of s1, s2 and the diaphragm within 1e-6 (measured:
    4e-8 at most), the collapse time within 1e-6 s; the diaphragm yields
    (its peak past 1.5 Dy). CVODES steps over the yield kinks by its error control at no visible
    cost: no more steps a simulated second than with a linear diaphragm (the same scene at the
    same rtol), within 25 % (measured: 1 % fewer), and fixed-point iteration holds throughout."""
    fine, finer = bilinear_runs[1e-10], bilinear_runs[1e-12]
    rel = np.abs(peaks(fine) / peaks(finer) - 1)
    print("peaks (s1, s2, diaphragm) at 1e-10:", peaks(fine), "at 1e-12:", peaks(finer),
          f"relative differences {rel}; collapse at {fine.t_collapse[0]:.9f} s, {finer.t_collapse[0]:.9f} s; "
          f"steps {fine.steps}, {finer.steps}")
    assert peaks(finer)[2] > 1.5 * DY, "the diaphragm does not yield"
    assert np.all(rel < 1e-6)
    assert fine.collapsed[0] == finer.collapsed[0]
    if finer.collapsed[0]:
        assert abs(fine.t_collapse[0] - finer.t_collapse[0]) < 1e-6
    linear = se.run(scene("linear"), el_centro.t, el_centro.ag, rtol=1e-10, engine="cvode")
    rate, rate_linear = fine.steps / fine.t_reached, linear.steps / linear.t_reached
    print(f"steps a simulated second at 1e-10: bilinear {rate:.0f}, linear {rate_linear:.0f}; "
          f"t_newton {fine.t_newton}")
    assert rate < 1.25 * rate_linear
    assert math.isnan(fine.t_newton), "fixed-point iteration failed on the bilinear scene"


def test_the_energy_balance_closes(bilinear_runs):
    """The diaphragm's spring counted by the work done on it (its BD_WORK_D state): the balance's
    largest residual below 1e-6 of the largest work (measured 1e-8 at rtol 1e-10, 3e-10 at 1e-12,
    1e-12 on the exact engine)."""
    for run, r in bilinear_runs.items():
        print(f"{run}: max residual {r.max_residual:.2e} J/m, max work {r.max_work:.1f} J/m, "
              f"ratio {r.max_residual / r.max_work:.1e}")
        assert r.max_work > 100.0
        assert r.max_residual < (1e-10 if run == "exact" else 1e-6) * r.max_work


def test_bouc_wen_with_a_large_n_approaches_the_bilinear_law(bilinear_runs, el_centro):
    """Bouc-Wen with beta = gamma = 1/2 and n -> infinity is the bilinear law: at n = 25 the peaks
    lie within 2.5 % of the bilinear law's (measured: the diaphragm's 1.7 %, s1's 0.2 %), at
    n = 100 (the FMUs' largest) within 0.25 % (measured 0.07 %, 0.007 %), closer than at 25; the
    wall collapses in all three within 5 ms of each other. (Bouc-Wen on CVODES, bilinear on the
    exact engine: two formulations and two solvers.)"""
    bilinear = bilinear_runs["exact"]
    diff = {}
    for n in (25.0, 100.0):
        r = se.run(scene("boucWen", n_bw=n, beta=0.5), el_centro.t, el_centro.ag, rtol=1e-10, engine="cvode")
        diff[n] = np.abs(peaks(r) / peaks(bilinear) - 1)
        print(f"n = {n:g}: peaks {peaks(r)}, relative to the bilinear law's {diff[n]}; collapse "
              f"{r.t_collapse[0]:.4f} s against {bilinear.t_collapse[0]:.4f} s")
        assert r.collapsed[0] == bilinear.collapsed[0]
        if r.collapsed[0]:
            assert abs(r.t_collapse[0] - bilinear.t_collapse[0]) < 5e-3
    assert np.all(diff[25.0] < 2.5e-2)
    assert np.all(diff[100.0] < 2.5e-3)
    assert diff[100.0].max() < diff[25.0].max()


# ---- the building file ------------------------------------------------------------------------
ROOF = """\
[building]
name = "one storey, bilinear roof"

[[storey]]
height = "3.6 m"
wall = { b = "230 mm", unit_weight = "18 kN/m3", overburden = "1.5 kN/m" }
diaphragm = { stiffness = "200 kN/m/m", mass = "200 kg/m", damping = 0.05, law = "bilinear", yield_force = "4 kN/m", post_yield = 0.1 }
"""


@pytest.fixture(scope="module")
def roof(tmp_path_factory):
    path = tmp_path_factory.mktemp("roof") / "roof.toml"
    path.write_text(ROOF)
    return path


def test_the_file_reads_the_task_scene_and_echoes_the_law():
    """The file is the scene above (W = 18 kN/m3 x 0.23 m x 3.6 m, psi = 2 x 1.5/14.904): the
    solver's Spec carries the bilinear law, the yield force and the post-yield ratio; the echo says
    them as it does for Bouc-Wen."""
    b = building_file.parse(ROOF, "roof.toml")
    d = b.storeys[0].diaphragm
    assert d.law == "bilinear" and d.yield_force == pytest.approx(FYD) and d.post_yield == pytest.approx(ALPHAD)
    assert d.pinching is None
    spec = monolithic.building_spec(b)
    assert spec.diaphragm_law == "bilinear"
    s = spec.storeys[0]
    assert (s.kd, s.md, s.Fyd, s.alphad) == pytest.approx((KD, MD, FYD, ALPHAD))
    assert s.wall["W"] == pytest.approx(WALL["W"]) and s.wall["psi"] == pytest.approx(WALL["psi"], rel=1e-3)
    assert "5 % damping (bilinear, yield force 4 kN/m, post-yield 0.1; own period 0.199 s)" in b.describe()


@pytest.mark.parametrize("edit, words", [
    (lambda t: t.replace(', yield_force = "4 kN/m"', ''), "yield_force is given with a hysteretic law"),
    (lambda t: t.replace('post_yield = 0.1 }', 'post_yield = 0.1, pinch_size = 0.5 }'),
     'pinch_size is the pinching of law = "boucWenPinched" only'),
    (lambda t: t.replace('"bilinear"', '"biLinear"'), "known linear, boucWen, boucWenPinched, bilinear"),
])
def test_a_bad_bilinear_diaphragm_is_refused_on_its_line(edit, words):
    with pytest.raises(building_file.BuildingFileError) as err:
        building_file.parse(edit(ROOF), "roof.toml")
    assert str(err.value).startswith("roof.toml:7:") and words in str(err.value)


def test_rockingwall_building_runs_the_file(roof, capsys, el_centro):
    """`rockingwall building FILE elcentro --pga 0.3` echoes the law and runs it on the exact
    engine: the diaphragm's peak and the collapse time are those of CVODES's run (rtol 1e-12)
    within 1e-4."""
    assert cli.main(["building", str(roof), "elcentro", "--pga", "0.3", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    run, = data["runs"]
    storey, = run["storeys"]
    direct = se.run(scene("bilinear"), el_centro.t, el_centro.ag, rtol=1e-12, engine="cvode")
    print(f"rockingwall building: solver {run['solver']}, diaphragm {storey['diaphragm_peak_m']:.6f} m "
          f"(solver {direct.peak_diaphragm[0]:.6f}), collapse {storey['t_collapse_s']} s "
          f"(solver {direct.t_collapse[0]:.6f})")
    assert run["solver"] == "exact"
    assert storey["diaphragm_peak_m"] == pytest.approx(direct.peak_diaphragm[0], rel=1e-4)
    assert storey["collapsed"] == bool(direct.collapsed[0])
    if storey["collapsed"]:
        assert storey["t_collapse_s"] == pytest.approx(direct.t_collapse[0], abs=1e-4)
    assert cli.main(["building", str(roof), "elcentro", "--pga", "0.3", "--out", str(roof.parent / "out")]) == 0
    assert "(bilinear, yield force 4 kN/m, post-yield 0.1;" in capsys.readouterr().out


def test_the_file_reaches_the_fmus(roof, build_dir):
    """BuildingWithWalls.fmu's start values and the co-simulated Building FMU's carry
    diaphragmLaw 3 with the yield force and post-yield ratio; BuildingWithWalls.fmu through fmpy
    (Model Exchange, rtol 1e-8) runs the scene as the solver does: El Centro at 0.3 g over 6 s (the
    wall rocking, the diaphragm yielding), the peaks within 1 % (measured 0.05 %), z_diaph_1 at
    most 1e-4 past 1 (measured 3e-6)."""
    b = building_file.read(roof)
    v = with_walls.start_values(b)
    assert (v["diaphragmLaw"], v["Fyd_1"], v["alphad_1"]) == (3, pytest.approx(FYD), pytest.approx(ALPHAD))
    real, integer = cosim.building_start_values(b)
    assert integer["diaphragmLaw"] == 3 and (real["Fyd_1"], real["alphad_1"]) == pytest.approx((FYD, ALPHAD))
    rec = records.el_centro().to_pga(PGA)
    signal = np.array(list(zip(rec.t, rec.ag)), dtype=[("time", float), ("ag", float)])
    res = simulate_fmu(str(build_dir / "BuildingWithWalls.fmu"), fmi_type="ModelExchange", stop_time=6.0,
                       output_interval=1e-3, start_values=v, input=signal, relative_tolerance=1e-8,
                       output=["s1_1", "s2_1", "d_diaph_1", "z_diaph_1"])
    ref = se.run(monolithic.building_spec(b), rec.t, rec.ag, t_end=6.0, rtol=1e-10)
    got = [float(np.abs(res[n]).max()) for n in ("s1_1", "s2_1", "d_diaph_1")]
    want = [float(x) for x in peaks(ref)]
    print(f"BuildingWithWalls.fmu: peaks {got}, the solver's {want}; max |z_diaph_1| {np.abs(res['z_diaph_1']).max():.7f}")
    assert ref.peak_diaphragm[0] > DY and not ref.collapsed[0]
    assert got == pytest.approx(want, rel=1e-2)
    assert np.abs(res["z_diaph_1"]).max() < 1.0 + 1e-4


# ---- the laws' tables ---------------------------------------------------------------------------


def test_the_law_table_is_one():
    """One numbering everywhere (building_physics.h's codes): the scene solver, the building file
    and the FMUs' start values all read names.SPRING_LAWS, where each had its own copy."""
    assert names.SPRING_LAWS == {"linear": 0, "boucWen": 1, "boucWenPinched": 2, "bilinear": 3}
    for module in (se, building_file, cosim, with_walls):
        assert module.SPRING_LAWS is names.SPRING_LAWS, module.__name__


@pytest.mark.parametrize("model", ["Building", "BuildingWithWalls"])
@pytest.mark.parametrize("version", ["fmi2", "fmi3"])
def test_the_model_descriptions_name_the_law(repo, model, version):
    """storeyLaw and diaphragmLaw describe law 3 as bilinear, in both FMUs and both FMI versions;
    the storeys without the pinching (2)."""
    root = ET.parse(repo / "fmu_src" / "models" / model / version / "modelDescription.xml").getroot()
    tag = "ScalarVariable" if version == "fmi2" else "Int32"
    desc = {v.get("name"): v.get("description") for v in root.iter(tag)}
    assert "3 bilinear (elastoplastic, kinematic hardening)" in desc["diaphragmLaw"]
    assert "3 bilinear" in desc["storeyLaw"] and "2 " not in desc["storeyLaw"]


def test_the_scene_solver_refuses_a_pinched_storey(el_centro):
    """rw_scene_validate checks the laws as the FMUs do (it did not: an unknown law ran as
    Bouc-Wen): a pinched storey is refused with the law named, by both engines."""
    pinched_storey = dataclasses.replace(scene("bilinear"), storey_law="boucWenPinched")
    for engine in se.ENGINES:
        with pytest.raises(se.SceneError, match="storey law 2 is not one of 0 linear, 1 Bouc-Wen, 3 bilinear"):
            se.run(pinched_storey, el_centro.t, el_centro.ag, engine=engine)
