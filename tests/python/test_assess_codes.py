"""`rockingwall assess --code`: the code columns of a small case against the codes' procedures done
by hand here (each weight's rise per unit hinge displacement, the spectra's branches with their
numbers), a wall with the top load bearing eccentrically, bad option values refused, and the
report table showing the code columns.

The wall: b = 230 mm, h = 3.6 m, W = 14.904 kN/m, psi = 0.2 (top load P = psi W / 2 = 1490.4 N/m),
pinned at the top (the codes' stiff diaphragm), at ground level, under El Centro 1940 at 0.2 g
(stands, s1 = 52 mm) and 0.5 g (collapses)."""
import json
import math

import pandas as pd
import pytest

G = 9.81
WALL = ["--b", "230mm", "--h", "3.6", "--W", "14.904kN/m", "--psi", "0.2", "--support", "simplySupported"]
SITE = ["--nz-Z", "0.4", "--nz-soil", "C", "--ntc-ag", "0.25g", "--ntc-F0", "2.4", "--ntc-Tc", "0.3s",
        "--ntc-soil", "B", "--asce-SX1", "0.3g"]


def assess(tmp_path, *args):
    from rockingwall.cli import main
    return main(["assess", "elcentro", *WALL, "--pga", "0.2", "0.5", "--ensemble", "0",
                 "--out", str(tmp_path), *args])


def by_hand(e_top):
    """C8, the Circolare and ASCE 41 for the wall above at ground level, by hand. e_top: the top
    load's eccentricity toward the inner face; the wall moving outward (away from the floor) has
    the load's lever at the hinge shortened by e_top, which governs."""
    W, P, t, hb = 14904.0, 1490.4, 0.23, 1.8
    half = W / 2
    # gravity's work per unit D of the hinge displacement (rises to first order), and the drop to
    # second order: lower block's centroid e/hb and 1/(4 hb); hinge t/hb and 1/(2 hb); upper centroid
    # t/hb + (t/2)/hb and 1/(2 hb) + 1/(4 hb); top load t/hb + (t/2 - e)/hb and 1/(2 hb) + 1/(2 hb)
    A = (half * 0.115 + half * (0.23 + 0.115) + P * (0.23 + 0.115 - e_top)) / hb
    B = (half / 4 + half * 0.75 + P * 1.0) / hb
    delta_i = A / (2 * B)
    k_s = (A - 2 * B * 0.6 * delta_i) / (0.6 * delta_i)
    tp = 2 * math.pi * math.sqrt(W / (3 * G) / k_s)
    c0 = 1.33 * 0.4                       # soil C, Z = 0.4, R = N = 1
    c_i = 0.5 if tp >= 1.5 else 2 * (1.75 - tp)
    cp = c0 * 1.0 * c_i                   # C_Hi = 1 at the ground
    demand = 1.5 * (tp / (2 * math.pi)) ** 2 * cp * G
    nbs = 100 * 0.6 * delta_i / demand
    # NTC: both centroids move D/2, so M* = W/g, e* = 1, alpha0 = A / (W/2), d0* = Delta_i / 2
    a0 = A / half / 1.35
    s = min(1.2, max(1.0, 1.40 - 0.40 * 2.4 * 0.25))      # S_S of soil B, topography T1
    lin_demand = 0.25 * s / 2.0
    du = 0.4 * delta_i / 2
    ds = 0.4 * du
    ts = 2 * math.pi * math.sqrt(ds / (a0 * G * (1 - ds / (delta_i / 2))))
    tc = 1.10 * 0.3 ** -0.20 * 0.3
    assert tc < ts < 4 * 0.25 + 1.6       # the spectrum's 1/T branch
    sde = 0.25 * G * s * 2.4 * tc / ts * (ts / (2 * math.pi)) ** 2
    return dict(nzsee_delta_i_mm=delta_i * 1e3, nzsee_delta_m_mm=0.6 * delta_i * 1e3, nzsee_Tp_s=tp,
                nzsee_C_Hi=1.0, nzsee_Cp_g=cp, nzsee_demand_mm=demand * 1e3, nzsee_nbs=nbs,
                ntc_a0_star_g=a0, ntc_linear_demand_g=lin_demand, ntc_du_star_mm=du * 1e3, ntc_Ts_s=ts,
                ntc_SDe_mm=sde * 1e3, asce41_h_over_t=3.6 / 0.23, asce41_limit=16.0)


@pytest.mark.parametrize("e_top", [0.0, 0.05])
def test_code_columns_equal_the_procedures_by_hand(tmp_path, e_top):
    assert assess(tmp_path, "--code", "nzsee", "ntc", "asce41", *SITE, "--e-top", f"{e_top * 1e3:g}mm") == 0
    cases = pd.read_csv(tmp_path / "cases.csv")
    expected = by_hand(e_top)
    for row in cases.to_dict("records"):
        for name, value in expected.items():
            assert row[name] == pytest.approx(value, rel=1e-5), name
    row = cases.iloc[0]
    if e_top == 0.0:   # the load at mid-thickness: C8's Delta_i is Doherty's, the model's Delta_u
        assert row.nzsee_delta_i_mm == pytest.approx(230 * (1 + 0.75 * 0.2) / 1.2, rel=1e-5)
    else:              # eccentric toward the inner face: a smaller Delta_i outward
        assert row.nzsee_delta_i_mm < 230 * (1 + 0.75 * 0.2) / 1.2 - 3
    assert (row.nzsee_verdict, row.ntc_linear_verdict, row.asce41_verdict) == ("fail", "pass", "pass")
    assert row.ntc_nonlinear_verdict == ("pass" if expected["ntc_du_star_mm"] >= expected["ntc_SDe_mm"] else "fail")
    codes = json.loads((tmp_path / "codes.json").read_text())[0]
    assert codes["nzsee"]["direction"] == "outward"
    assert any(n.startswith("UNCONFIRMED") for n in codes["nzsee"]["notes"])


def test_a_code_passing_a_wall_that_collapses_is_flagged_unconservative(tmp_path, capsys):
    """ASCE 41's h/t passes this wall; El Centro at 0.5 g topples it: unconservative there only.
    A low hazard (Z = 0.13, soil A: C(0) = 0.13 g) makes C8 pass too."""
    assert assess(tmp_path, "--code", "nzsee", "asce41", "--nz-Z", "0.13", "--nz-soil", "A", "--table", "md") == 0
    cases = pd.read_csv(tmp_path / "cases.csv").sort_values("pga_g")
    assert list(cases.collapsed) == [False, True]
    assert cases.peak_s1_mm.iloc[0] < cases.nzsee_delta_m_mm.iloc[0]
    hand = by_hand(0.0)
    nbs = hand["nzsee_nbs"] * 0.532 / 0.13
    assert cases.nzsee_nbs.iloc[0] == pytest.approx(nbs, rel=1e-5) and nbs > 100
    assert list(cases.nzsee_unconservative) == [False, True]
    assert list(cases.asce41_unconservative) == [False, True]
    out = capsys.readouterr().out
    header = next(line for line in out.splitlines() if line.startswith("| record"))
    assert "C8 %NBS" in header and "ASCE 41 h/t" in header and "code unconservative" in header
    assert "NTC lin/nonlin" not in header
    rows = [line for line in out.splitlines() if line.startswith("| El Centro")]
    assert rows[0].endswith(f"| {nbs:.0f} pass | 15.7/16 pass | none |")
    assert rows[1].endswith(f"| {nbs:.0f} pass | 15.7/16 pass | C8, ASCE 41 |")


def test_the_hazard_of_each_case_is_its_pga(tmp_path, capsys):
    """--code-hazard pga: C8's C(0) and NTC's a_g S equal each case's PGA. By hand: D_ph scales with
    C(0), so %NBS = (the Z = 0.4, soil C value) x 0.532 / PGA; NTC's linear demand a_g S / q = PGA / 2
    whatever the soil; soil B at 0.2 g: S_S = 1.2 (1.40 - 0.40 F0 a_g >= 1.2 there), a_g = 0.2/1.2."""
    assert assess(tmp_path, "--code", "nzsee", "ntc", "--code-hazard", "pga", "--nz-soil", "C",
                  "--ntc-soil", "B") == 0
    cases = pd.read_csv(tmp_path / "cases.csv").sort_values("pga_g")
    hand = by_hand(0.0)
    for row, pga in zip(cases.to_dict("records"), (0.2, 0.5)):
        assert row["nzsee_C0_g"] == pytest.approx(pga, rel=1e-5)
        assert row["nzsee_nbs"] == pytest.approx(hand["nzsee_nbs"] * 0.532 / pga, rel=1e-5)
        assert row["ntc_linear_demand_g"] == pytest.approx(pga / 2, rel=1e-5)
    assert cases.ntc_ag_g.iloc[0] == pytest.approx(0.2 / 1.2, rel=1e-5)
    # at 0.2 g C8 passes (118 %NBS) and the wall stands; at 0.5 g C8 fails (47 %NBS) and it collapses
    assert list(cases.nzsee_verdict) == ["pass", "fail"] and list(cases.collapsed) == [False, True]
    assert list(cases.ntc_linear_verdict) == ["pass", "fail"]
    assert not cases.nzsee_unconservative.any() and not cases.ntc_unconservative.any()
    out = capsys.readouterr().out
    assert "code hazard at PGA 0.2 g (each case's):" in out and "code hazard at PGA 0.5 g (each case's):" in out
    codes = json.loads((tmp_path / "codes.json").read_text())
    assert [c["hazard_pga_g"] for c in codes] == [0.2, 0.5]


def test_without_code_the_table_has_no_code_columns(tmp_path, capsys):
    assert assess(tmp_path, "--table", "md") == 0
    assert "C8 %NBS" not in capsys.readouterr().out
    assert "nzsee_verdict" not in pd.read_csv(tmp_path / "cases.csv")


def test_the_codes_check_the_wall_the_time_histories_run(tmp_path):
    """Pointing and the weight of walls above are the model's statics (wall parameters), and the
    codes take them from the wall: C8's Delta_i equals the model's Delta_u of the same wall, and
    by hand: t = b - 2 p, the weight-only load Wo = psiWeightOnly W/2 at the centreline."""
    from rockingwall.wall import Wall
    extra = ["--pointing", "10mm", "--psi-weight-only", "0.5"]
    assert assess(tmp_path, "--code", "nzsee", *SITE, *extra) == 0
    row = pd.read_csv(tmp_path / "cases.csv").iloc[0]
    wall = Wall.make(b=0.23, h=3.6, W=14904.0, psi=0.2, support="simplySupported", pointing=0.01,
                     psiWeightOnly=0.5)
    assert row.nzsee_delta_i_mm == pytest.approx(wall.delta_u * 1e3, rel=1e-5)
    W, t, hb = 14904.0, 0.21, 1.8
    P = 0.2 * W / 2 + 0.5 * W / 2    # the overburden and the walls above, both at the centreline
    A = (W / 2 * t / 2 + W / 2 * (t + t / 2) + P * (t + t / 2)) / hb
    B = (W / 2 / 4 + W / 2 * 0.75 + P) / hb
    assert row.nzsee_delta_i_mm == pytest.approx(A / (2 * B) * 1e3, rel=1e-5)


@pytest.mark.parametrize("args, message", [
    (["--code", "nzsee", "--nz-Z", "0.9"], "--nz-Z: Z = 0.9"),
    (["--code", "nzsee", "--nz-soil", "X"], "--nz-soil: soil class = 'X'"),
    (["--code", "ntc", "--ntc-ag", "0.25kg"], "--ntc-ag: unit 'kg'"),
    (["--code", "ntc", "--ntc-FC", "2"], "--ntc-FC: FC = 2"),
    (["--code", "ntc", "--attachment-height", "3m", "--ntc-T1", "0s"], "--ntc-T1: T1 = 0 s"),
    (["--code", "asce41", "--asce-storey", "attic"], "--asce-storey: storey = 'attic'"),
    (["--code", "asce41", "--asce-SX1=-0.1g"], "--asce-SX1: S_X1 = -0.1 g"),
    (["--code", "nzsee", "--attachment-height", "10", "--building-height", "5"], "--attachment-height = 10 m"),
    (["--nz-Z", "0.3"], "--nz-Z is an input of the code checks: give --code too"),
    (["--code", "nzsee", "--code-hazard", "pga", "--nz-Z", "0.3"], "--nz-Z: with --code-hazard pga"),
    (["--code", "nzsee", "--code-hazard", "pgv"], "--code-hazard = 'pgv' is not one of site, pga"),
    (["--code", "nzsee", "--code-hazard", "pga", "--nz-soil", "A", "--nz-R", "0.5"],
     "--code-hazard pga: PGA 0.5 g on soil A needs Z = 1"),
])
def test_bad_code_options_are_refused_before_any_run(tmp_path, capsys, args, message):
    assert assess(tmp_path / "out", *args) == 2
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err
    assert not (tmp_path / "out" / "cases.csv").exists()


def test_unknown_code_is_refused(tmp_path, capsys):
    with pytest.raises(SystemExit) as exit_:
        assess(tmp_path, "--code", "eurocode8")
    assert exit_.value.code == 2 and "invalid choice: 'eurocode8'" in capsys.readouterr().err


def test_parapet_gets_c8s_parapet_check():
    """A 1.2-m parapet of 230-mm brick on a 6-m roof: Delta_TOP,ins = t = 230 mm, C_Hi = 2."""
    from rockingwall import Wall, assessment_codes as ac
    wall = Wall.make(b=0.23, h=1.2, W=4968.0, psi=0.0, support="parapet", warn=False)
    values = dict(ac.option_values(type("Args", (), {})()), attachment_height=6.0)
    checks = ac.check(wall, ["nzsee"], values)
    r = checks.results["nzsee"]
    # one block: A = W (t/2)/h, B = W/(4h) per unit top displacement; K_s at 0.6 Delta_i = 4B/3
    k_s = 4 / 3 * 4968 / (4 * 1.2)
    tp = 2 * math.pi * math.sqrt(4968 / (3 * G) / k_s)
    cp = 0.532 * 2.0 * (2.0 if tp <= 0.75 else 0.5 if tp >= 1.5 else 2 * (1.75 - tp))
    assert checks.element == "parapet" and r.element == "parapet"
    assert r.delta_i == pytest.approx(0.23, rel=1e-12) and r.Tp == pytest.approx(tp, rel=1e-9)
    assert r.nbs == pytest.approx(100 * 0.6 * 0.23 / (1.5 * (tp / (2 * math.pi)) ** 2 * cp * G), rel=1e-9)
    with pytest.raises(ValueError, match="parapet check is not implemented"):
        ac.check(wall, ["asce41"], values)


def test_parapet_from_the_command_line_is_flagged_where_it_topples(tmp_path):
    """A 1.2-m parapet of 230-mm brick on the ground at Z = 0.13, soil A: C8 passes it (by hand:
    Tp = 2 pi sqrt(M / (4B/3)), Cp = 0.13 x 0.5, D_ph = 1.5 (Tp/2 pi)^2 Cp g = 117 mm < Delta_m =
    138 mm); El Centro at 0.5 g topples it (fmi2sim: the exact engine does not run parapets)."""
    from rockingwall.cli import main
    args = ["assess", "elcentro", "--b", "230mm", "--h", "1.2", "--W", "4.968kN/m", "--psi", "0", "--support",
            "parapet", "--pga", "0.3", "0.5", "--ensemble", "0", "--engine", "fmi2sim", "--code", "nzsee",
            "--nz-Z", "0.13", "--nz-soil", "A", "--out", str(tmp_path)]
    assert main(args) == 0
    cases = pd.read_csv(tmp_path / "cases.csv").sort_values("pga_g")
    tp = 2 * math.pi * math.sqrt((4968 / (3 * G)) / (4 / 3 * 4968 / (4 * 1.2)))
    demand = 1.5 * (tp / (2 * math.pi)) ** 2 * 0.13 * 0.5 * G
    assert tp > 1.5 and cases.nzsee_delta_i_mm.iloc[0] == pytest.approx(230, rel=1e-6)
    assert cases.nzsee_demand_mm.iloc[0] == pytest.approx(demand * 1e3, rel=1e-5)
    assert list(cases.nzsee_verdict) == ["pass", "pass"] and list(cases.collapsed) == [False, True]
    assert list(cases.nzsee_unconservative) == [False, True]


def test_a_parapet_is_judged_by_its_top_and_a_wall_by_its_mid_height():
    """s2 = 150 mm, s1 = 75 mm standing: past C8's Delta_m = 0.6 t = 138 mm at a parapet's top,
    within Delta_m = 132 mm at a wall's hinge."""
    from rockingwall import Wall, assessment_codes as ac
    values = dict(ac.option_values(type("Args", (), {})()), nz_Z=0.13, nz_soil="A")
    cases = pd.DataFrame([dict(pga_g=0.3, peak_s1_mm=75.0, peak_s2_mm=150.0, collapsed=False)])
    parapet = Wall.make(b=0.23, h=1.2, W=4968.0, psi=0.0, support="parapet", warn=False)
    wall = Wall.make(b=0.23, h=3.6, W=14904.0, psi=0.2, support="simplySupported", warn=False)
    for element, flagged in ((parapet, True), (wall, False)):
        checks = ac.checks_by_hazard(element, ["nzsee"], values)
        assert checks[None].results["nzsee"].verdict == "pass"
        assert ac.add_to_cases(cases, checks).nzsee_unconservative.iloc[0] == flagged


def test_the_site_left_at_its_defaults_is_named(tmp_path, capsys):
    """The codes' hazard options have defaults (docs/codes.md's example site): a report that gave
    none printed 'Z = 0.4, soil C' as if they were the user's site. Each site line now names the
    options of its code's ground motion left at their defaults; the hazard 'pga' sets Z and a_g."""
    def site_lines(*args):
        assert assess(tmp_path / str(len(list(tmp_path.iterdir()))), "--code", "nzsee", "ntc", "asce41", *args) == 0
        return [line for line in capsys.readouterr().out.splitlines() if " site: " in line or "S_X1 =" in line]

    nz, it, us = site_lines()
    assert nz.endswith("(--nz-Z, --nz-soil not given: an example site's defaults, not yours)")
    assert it.endswith("(--ntc-ag, --ntc-F0, --ntc-Tc, --ntc-soil not given: an example site's defaults, not yours)")
    assert us.endswith("(--asce-SX1 not given: an example site's defaults, not yours)")
    assert not any("not given" in line for line in site_lines(*SITE))
    nz, it, us = site_lines("--code-hazard", "pga", "--nz-soil", "C")[:3]
    assert "not given" not in nz and "(--ntc-F0, --ntc-Tc, --ntc-soil not given" in it and "--asce-SX1" in us
