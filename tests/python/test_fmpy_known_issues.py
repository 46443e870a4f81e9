"""Known problems of fmpy that this project works around, shown rather than hidden.

fmpy 0.3.32's CVodeSolver.f does not apply inputs (only the root function does), so the FMU's
right-hand side sees a lagged ground acceleration. rockingwall.fmu installs (for the duration of its own runs) a right-hand side
that applies the input; this test shows that it matters. If it starts failing because the two
runs agree, fmpy has been fixed: drop the workaround in rockingwall/fmu.py.
"""

from rockingwall import fmu as rw_fmu
from rwref import Params, simulate, inputs


def test_fmpy_rhs_ignores_inputs_and_the_workaround_fixes_it(rockingwall_fmu):
    signal = inputs.sampled(inputs.gaussian(0.04, 1.0), 6.0, 0.002)  # Table 5.2's impulse, rigid 1DOF
    kw = dict(support="simplySupported", hinge_law="rigid", rtol=1e-6, output_interval=0.01)
    plain = rw_fmu.simulate(rockingwall_fmu, 6.0, signal.t, signal.a, fmpy_input_fix=False, **kw)
    fixed = rw_fmu.simulate(rockingwall_fmu, 6.0, signal.t, signal.a, **kw)
    ref = simulate(Params(support="simplySupported", hinge_law="rigid"), signal, 6.0,
                   method="DOP853", rtol=1e-9, atol=1e-12)
    err_fixed = abs(fixed.peak_s1 - ref.peak_s1) / ref.peak_s1
    err_plain = abs(plain.peak_s1 - ref.peak_s1) / ref.peak_s1
    print(f"peak s1: reference {ref.peak_s1:.6f}, fmpy+fix {fixed.peak_s1:.6f} ({err_fixed:.1e}), "
          f"plain fmpy {plain.peak_s1:.6f} ({err_plain:.1e})")
    assert err_fixed < 1e-3
    assert err_plain > 0.01, "plain fmpy now agrees: fmpy applies inputs in f, drop the workaround"
