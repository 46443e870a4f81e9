"""The motion of walls with NZSEE C8's statics (docs/model.md: pointing, the reactions set in from
the faces, an eccentric overburden, a weight-only overburden): the exact engine (the C model)
against the independent reference solver (written from docs/model.md) on three records, the
paper's Gaussian impulse, El Centro at 50 % and a FEMA P695 record (Kobe 1995, NIS000).

Peaks agree within 1e-5 of the larger peak, against the reference at rtol 1e-11, integrated from
one sample of the record to the next (where the input has its kinks), its peaks taken at the
extrema of its dense output (exact_peaks: the grid's points alone miss a peak by up to 5e-4 of it
on a record's 0.02 s samples, which is what once looked like the reference's own spread). The
rigid 2DOF is chaotic over long records (docs/model.md "Known limitations"): it is compared on the
impulse only, and its impacts are not counted (the tail of ever smaller impacts before its hinges
close differs between solvers, docs/model.md).

Measured when this was written: El Centro and Kobe 8e-10 or less, the impulse 1e-11 to 5.5e-6."""
import pytest

from rockingwall import engine, read_record
from rockingwall import fmu as rw_fmu
from rockingwall.sweep import suites
from rwref import Params, inputs, simulate

PEAK_RTOL = 1e-5
# the paper's wall 2 with every statics parameter away from its default, and with a weight-only
# overburden alone (the walls above a storey's wall)
WALLS = {"C8": dict(h=2.5, b=0.15, W=6622.0, psi=0.5, pointing=0.005, e_base_ratio=0.9, e_hinge_ratio=0.95,
                    e_top=0.04, psi_weight_only=0.6),
         "weight only": dict(h=2.5, b=0.15, W=6622.0, psi=0.5, psi_weight_only=1.0)}
LAWS = {"1DOF trilinear": ("simplySupported", "dohertyHinge", 0.0),
        "dohertyHinge": ("flexibleTop", "dohertyHinge", 1e5),
        "semiRigidHinge": ("flexibleTop", "semiRigidHinge", 1e5),
        "rigid": ("flexibleTop", "rigid", 1e5)}
CASES = ([("C8", law, rec) for rec in ("gaussian", "El Centro", "Kobe") for law in
          ("1DOF trilinear", "dohertyHinge", "semiRigidHinge")]
         + [("weight only", law, "El Centro") for law in ("1DOF trilinear", "dohertyHinge")]
         + [("C8", "rigid", "gaussian")])


def record(name):
    if name == "gaussian":  # the paper's impulse, D = 0.04 m, T = 1 s (Section 5.3)
        return inputs.sampled(inputs.gaussian(0.04, 1.0), 8.0, 0.002)
    if name == "El Centro":
        return inputs.el_centro(0.5)
    rec = read_record(suites.fema_cache() / "ff07a.AT2").to_pga(0.25)
    return inputs.Signal(rec.t, rec.ag, rec.name)


def reference(params, sig):
    return simulate(params, sig, float(sig.t[-1]), method="DOP853", rtol=1e-11, atol=1e-14, stop_at_samples=True,
                    exact_peaks=True)


def gap(r, ref):
    """The largest difference of the peaks, over the larger peak."""
    scale = max(ref.peak_s1, ref.peak_s2)
    return max(abs(r.peak_s1 - ref.peak_s1), abs(r.peak_s2 - ref.peak_s2)) / scale


@pytest.mark.parametrize("wall, law, rec", CASES)
def test_engine_and_reference_agree(wall, law, rec):
    support, hinge_law, kd = LAWS[law]
    sig = record(rec)
    values = WALLS[wall]
    r = engine.run(sig.t, sig.a, support=rw_fmu.SUPPORTS[support], hingeLaw=rw_fmu.HINGE_LAWS[hinge_law], Kd=kd,
                   **{rw_fmu.PARAMETER_NAMES[k]: v for k, v in values.items()})
    params = Params(support=support, hinge_law=hinge_law, Kd=kd, **values)
    ref = reference(params, sig)
    assert r.collapsed == ref.collapsed, (r, ref.collapsed)
    if law != "rigid":  # the rigid law's count differs in its tail of ever smaller impacts (docs/model.md)
        assert r.impacts == ref.impacts, (r, ref.impacts)
    assert max(r.peak_s1, r.peak_s2) > 5e-3, "the wall barely moves: the comparison would say little"
    print(f"{wall} {law} {rec}: engine {r.peak_s1:.9f} {r.peak_s2:.9f}, reference {ref.peak_s1:.9f} "
          f"{ref.peak_s2:.9f}: {gap(r, ref):.2e}")
    assert gap(r, ref) <= PEAK_RTOL
