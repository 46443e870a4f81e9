"""Building.fmu against independent results.

Elastic (storeyLaw = diaphragmLaw = 0): the building is the linear system M x'' + C x' + K x = 0
with x = (u_floor_1, u_diaph_1, u_floor_2, ...), M, K written here from the springs and masses
(docs/building.md), and C = a0 M + a1 K classical, so a free vibration started in one mode shape
stays in it: x(t) = phi exp(-zeta w t) (cos(w_d t) + zeta/sqrt(1 - zeta^2) sin(w_d t)), with w and
phi from scipy's generalised symmetric eigenproblem K phi = w^2 M phi and zeta = a0/(2w) + a1 w/2.

Bouc-Wen: a quasi-static cyclic push (a slow force on diaphragm 1 of a one-storey building): the
work the FMU integrates (work_storey_1, a state) over one cycle against the loop area from the
sampled (drift_1, V_storey_1) outputs by the shoelace formula; with a large exponent n the law is
elastoplastic: the hysteretic part of the shear reaches the yield force (1 - alpha) Fy within 1 %
and the loop area that of the bilinear loop 4 (1 - alpha) Fy (d_max - Dy).
"""
import numpy as np
import pytest
import scipy.linalg
from fmpy import simulate_fmu

N = 3
M_FLOOR = [5000.0, 4500.0, 3000.0]
K_STOREY = [3e7, 2.5e7, 1.5e7]
M_DIAPH = [2000.0, 1800.0, 1500.0]
K_DIAPH = [8e5, 6e5, 4e5]


def elastic_start(a0, a1):
    start = {"nStoreys": N, "storeyLaw": 0, "diaphragmLaw": 0, "rayleighMass": a0, "rayleighStiffness": a1}
    for i in range(N):
        start.update({f"m_{i + 1}": M_FLOOR[i], f"k_{i + 1}": K_STOREY[i], f"md_{i + 1}": M_DIAPH[i],
                      f"kd_{i + 1}": K_DIAPH[i]})
    return start


def matrices():
    """M, K of the 2N degrees of freedom (u_floor_i, u_diaph_i), from the springs."""
    n = 2 * N
    M, K = np.zeros((n, n)), np.zeros((n, n))

    def spring(a, b, k):  # between dof a and dof b (None: the ground)
        for p, sp in ((a, 1), (b, -1)):
            for q, sq in ((a, 1), (b, -1)):
                if p is not None and q is not None:
                    K[p, q] += sp * sq * k

    for i in range(N):
        f, d = 2 * i, 2 * i + 1
        M[f, f], M[d, d] = M_FLOOR[i], M_DIAPH[i]
        spring(f, 2 * (i - 1) if i > 0 else None, K_STOREY[i])
        spring(d, f, K_DIAPH[i])
    return M, K


def modal_solution(w, zeta, phi, t):
    wd = w * np.sqrt(1 - zeta ** 2)
    return np.outer(np.exp(-zeta * w * t) * (np.cos(wd * t) + zeta / np.sqrt(1 - zeta ** 2) * np.sin(wd * t)), phi)


def free_vibration(fmu, start, phi, stop, dt):
    names = [f"{kind}_{i + 1}" for i in range(N) for kind in ("u_floor", "u_diaph")]
    start = dict(start, **{name: value for name, value in zip(names, phi)})
    r = simulate_fmu(str(fmu), fmi_type="ModelExchange", start_values=start, stop_time=stop, output_interval=dt,
                     relative_tolerance=1e-10, output=names)
    return r["time"], np.column_stack([r[n] for n in names])


def frequency_from_crossings(t, y):
    """Mean frequency [rad/s] from the first and last upward zero crossings (linear interpolation)."""
    s = np.where((y[:-1] < 0) & (y[1:] >= 0))[0]
    tc = t[s] - y[s] * (t[s + 1] - t[s]) / (y[s + 1] - y[s])
    return 2 * np.pi * (len(tc) - 1) / (tc[-1] - tc[0])


@pytest.mark.parametrize("mode", range(2 * N))
def test_undamped_free_vibration_is_the_modal_solution(building_fmu, mode):
    M, K = matrices()
    w2, phis = scipy.linalg.eigh(K, M)
    w, phi = np.sqrt(w2[mode]), phis[:, mode]
    phi = 0.01 * phi / np.max(np.abs(phi))
    periods = 40
    t, x = free_vibration(building_fmu, elastic_start(0.0, 0.0), phi, periods * 2 * np.pi / w, 2 * np.pi / w / 200)
    w_fmu = frequency_from_crossings(t, x[:, np.argmax(np.abs(phi))])
    err = np.max(np.abs(x - modal_solution(w, 0.0, phi, t))) / 0.01
    print(f"mode {mode + 1}: f = {w / 2 / np.pi:.4f} Hz (eigenproblem), {w_fmu / 2 / np.pi:.4f} Hz (FMU), "
          f"relative difference {abs(w_fmu / w - 1):.1e}; max deviation from the modal solution {err:.1e} of the amplitude")
    assert abs(w_fmu / w - 1) < 1e-3
    assert err < 1e-3


@pytest.mark.parametrize("mode", [0, 2, 5])
def test_rayleigh_damped_free_vibration_decays_as_the_modal_solution(building_fmu, mode):
    a0, a1 = 0.8, 4e-4
    M, K = matrices()
    w2, phis = scipy.linalg.eigh(K, M)
    w, phi = np.sqrt(w2[mode]), phis[:, mode]
    phi = 0.01 * phi / np.max(np.abs(phi))
    zeta = a0 / (2 * w) + a1 * w / 2
    stop = min(3 / (zeta * w), 60 * 2 * np.pi / w)  # down to exp(-3) or 60 periods
    t, x = free_vibration(building_fmu, elastic_start(a0, a1), phi, stop, 2 * np.pi / w / 200)
    err = np.max(np.abs(x - modal_solution(w, zeta, phi, t))) / 0.01
    # decay per period, the logarithmic decrement, from the peaks of the largest dof
    y = x[:, np.argmax(np.abs(phi))] * np.sign(phi[np.argmax(np.abs(phi))])
    peaks = np.where((y[1:-1] > y[:-2]) & (y[1:-1] >= y[2:]))[0] + 1
    decrement = np.log(y[peaks[0]] / y[peaks[-1]]) / (len(peaks) - 1)
    expected = 2 * np.pi * zeta / np.sqrt(1 - zeta ** 2)
    print(f"mode {mode + 1}: zeta = {zeta:.4f}, logarithmic decrement {decrement:.5f} (FMU) vs {expected:.5f}; "
          f"max deviation from the damped modal solution {err:.1e} of the amplitude")
    assert abs(decrement / expected - 1) < 1e-2
    assert err < 1e-3


# ---- Bouc-Wen: quasi-static cyclic push --------------------------------------------------------
K1, FY1, ALPHA1 = 2e7, 3e4, 0.05
PERIOD = 20.0  # s, against the building's ~0.1 s: quasi-static


def cyclic_push(fmu, n_bw, amplitude, cycles=2, dt=0.005, extra=None):
    t = np.arange(0.0, cycles * PERIOD + dt / 2, dt / 2)
    force = amplitude * np.sin(2 * np.pi * t / PERIOD)
    signal = np.array(list(zip(t, force)), dtype=[("time", float), ("F_wall_1", float)])
    start = {"nStoreys": 1, "storeyLaw": 1, "diaphragmLaw": 0, "kd_1": 1e9, "k_1": K1, "Fy_1": FY1,
             "alpha_1": ALPHA1, "nBW": n_bw, "rayleighMass": 2.0, "rayleighStiffness": 0.0}
    start.update(extra or {})
    return simulate_fmu(str(fmu), fmi_type="ModelExchange", start_values=start, stop_time=cycles * PERIOD,
                        output_interval=dt, relative_tolerance=1e-9, input=signal,
                        output=["drift_1", "V_storey_1", "work_storey_1", "d_diaph_1", "F_diaph_1", "work_diaph_1"])


def last_cycle(r):
    return r[r["time"] >= r["time"][-1] - PERIOD - 1e-9]


def shoelace(x, y):
    return 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


@pytest.mark.parametrize("n_bw", [2.0, 40.0])
def test_bouc_wen_work_per_cycle_is_the_loop_area(building_fmu, n_bw):
    c = last_cycle(cyclic_push(building_fmu, n_bw, 1.3 * FY1))
    work = c["work_storey_1"][-1] - c["work_storey_1"][0]
    area = shoelace(c["drift_1"], c["V_storey_1"])
    print(f"n = {n_bw}: work per cycle {work:.2f} J/m (FMU state), loop area {area:.2f} J/m (shoelace), "
          f"ratio {work / area:.5f}")
    assert area > 0.2 * FY1 * FY1 / K1, "no hysteresis loop to speak of"
    assert work == pytest.approx(area, rel=1e-2)


def test_bouc_wen_with_large_n_is_elastoplastic(building_fmu):
    c = last_cycle(cyclic_push(building_fmu, 40.0, 1.3 * FY1))
    d, V = c["drift_1"], c["V_storey_1"]
    hysteretic = V - ALPHA1 * K1 * d
    d_max = 0.5 * (d.max() - d.min())
    dy = FY1 / K1
    bilinear_area = 4 * (1 - ALPHA1) * FY1 * (d_max - dy)
    area = shoelace(d, V)
    print(f"peak hysteretic force {hysteretic.max():.1f} / {-hysteretic.min():.1f} N/m vs (1 - alpha) Fy = "
          f"{(1 - ALPHA1) * FY1:.1f}; loop area {area:.1f} vs bilinear {bilinear_area:.1f} J/m")
    assert hysteretic.max() == pytest.approx((1 - ALPHA1) * FY1, rel=1e-2)
    assert -hysteretic.min() == pytest.approx((1 - ALPHA1) * FY1, rel=1e-2)
    assert area == pytest.approx(bilinear_area, rel=3e-2)


def test_pinched_diaphragm_loop(building_fmu):
    """Foliente's pinching (diaphragmLaw 2) on diaphragm 1, pushed cyclically through its stiff
    floor: the work per cycle is the loop area; the loop's tangent stiffness dF/dd (central
    differences of the sampled outputs) is the published law's, k [alpha + (1 - alpha) h(z)
    (1 - |z|^n (beta sgn(dd z) + gamma))], h = 1 - zeta1 exp(-((z sgn(dd) - q)/zeta2)^2), written
    here from the paper's formula, within 2 % wherever the deformation moves; and the pinched loop
    is thinner than the plain Bouc-Wen loop under the same push."""
    kd, fyd, alphad, zeta1, zeta2, q, n, beta = 7e5, 1e4, 0.1, 0.8, 0.2, 0.1, 2.0, 0.5
    extra = {"storeyLaw": 0, "kd_1": kd, "Fyd_1": fyd, "alphad_1": alphad, "k_1": 1e9, "rayleighMass": 2.0,
             "pinchSize": zeta1, "pinchWidth": zeta2, "pinchCentre": q, "betaBW": beta}
    areas = {}
    for law in (1, 2):
        c = last_cycle(cyclic_push(building_fmu, n, 1.3e4, extra=dict(extra, diaphragmLaw=law)))
        work = c["work_diaph_1"][-1] - c["work_diaph_1"][0]
        areas[law] = shoelace(c["d_diaph_1"], c["F_diaph_1"])
        print(f"diaphragmLaw {law}: work per cycle {work:.2f} J/m, loop area {areas[law]:.2f} J/m")
        assert work == pytest.approx(areas[law], rel=1e-2)
    assert areas[2] < areas[1]
    d, F = c["d_diaph_1"], c["F_diaph_1"]
    z = (F - alphad * kd * d) / ((1 - alphad) * fyd)
    dd, dF = d[2:] - d[:-2], F[2:] - F[:-2]
    zc, s = z[1:-1], np.sign(d[2:] - d[:-2])
    moving = np.abs(dd) > 0.2 * np.max(np.abs(dd))
    h = 1 - zeta1 * np.exp(-((zc * s - q) / zeta2) ** 2)
    tangent = kd * (alphad + (1 - alphad) * h * (1 - np.abs(zc) ** n * (beta * np.sign(s * zc) + (1 - beta))))
    err = np.abs(dF / dd - tangent)[moving] / kd
    pinched = (h < 0.5)[moving]
    print(f"tangent stiffness vs the law: max error {err.max():.2e} of kd over {moving.sum()} samples, "
          f"{pinched.sum()} of them in the pinched region (h < 0.5)")
    assert pinched.sum() > 20, "the loop never passes the pinched region"
    assert err.max() < 2e-2


def test_building_variables_match_its_c_table(building_fmu):
    """The packaged modelDescription.xml is the one generated from building_variables.h: names,
    value references, causalities, and the state order of the physics (8 states per floor)."""
    import gen_model_description as gen
    table, _, defines = gen.parse_model("Building")
    from fmpy import read_model_description
    md = read_model_description(str(building_fmu))
    assert md.guid == defines["RW_GUID"] and md.numberOfEventIndicators == 0
    assert [(v.name, v.valueReference, v.causality) for v in md.modelVariables] == \
        [(v["name"], v["vr"], v["causality"]) for v in table]
    per_floor = ["u_floor", "v_floor", "z_storey", "u_diaph", "v_diaph", "z_diaph", "work_storey", "work_diaph"]
    assert [d.variable.derivative.name for d in md.derivatives] == \
        [f"{name}_{i}" for i in range(1, 6) for name in per_floor]


def test_wall_force_static_deflection(building_fmu):
    """A constant F_wall_2 on the linear three-storey building, damped out: the static deflections
    by hand (the force goes through diaphragm 2 into floor 2 and down storeys 2 and 1; storey 3
    and floor 3 just follow): u_floor_1 = F/k_1, u_floor_2 = u_floor_1 + F/k_2, u_diaph_2 =
    u_floor_2 + F/kd_2, floor 3 and diaphragm 3 move with floor 2, diaphragm 1 with floor 1; the
    storey shears are F below the loaded floor and 0 above; u_top_i the diaphragm differences."""
    F = 800.0
    start = dict(elastic_start(30.0, 0.0))
    signal = np.array([(0.0, F), (60.0, F)], dtype=[("time", float), ("F_wall_2", float)])
    r = simulate_fmu(str(building_fmu), fmi_type="ModelExchange", start_values=start, stop_time=60.0,
                     output_interval=0.1, relative_tolerance=1e-10, input=signal,
                     output=["u_floor_1", "u_floor_2", "u_floor_3", "u_diaph_1", "u_diaph_2", "u_diaph_3",
                             "V_storey_1", "V_storey_2", "V_storey_3", "u_top_2", "u_top_3", "a_diaph_2"])
    end = r[-1]
    u1 = F / K_STOREY[0]
    u2 = u1 + F / K_STOREY[1]
    expected = {"u_floor_1": u1, "u_floor_2": u2, "u_floor_3": u2, "u_diaph_1": u1, "u_diaph_2": u2 + F / K_DIAPH[1],
                "u_diaph_3": u2, "V_storey_1": F, "V_storey_2": F, "u_top_2": u2 + F / K_DIAPH[1] - u1,
                "u_top_3": -F / K_DIAPH[1]}
    for name, value in expected.items():
        assert end[name] == pytest.approx(value, rel=1e-6), name
    assert abs(end["V_storey_3"]) < 1e-6 * F and abs(end["a_diaph_2"]) < 1e-9
