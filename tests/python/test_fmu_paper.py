"""The paper's numbers reproduced through the FMU (fmpy, CVode), not only through the reference."""
import pytest

from rockingwall import fmu as rw_fmu
from rwref import inputs

# Table 5.2, 1DOF column: wall (psi, Gaussian amplitude D [m], paper's peak s1 [m]); T = 1 s.
TABLE_5_2_1DOF = [(1, 0.0, 0.040, 0.064), (2, 0.5, 0.040, 0.040), (3, 1.0, 0.050, 0.033)]


@pytest.mark.parametrize("wall,psi,D,paper", TABLE_5_2_1DOF)
def test_table_5_2_1dof_column(rockingwall_fmu, wall, psi, D, paper):
    pulse = inputs.sampled(inputs.gaussian(D, 1.0), 10.0, 1e-3)
    run = rw_fmu.simulate(rockingwall_fmu, 10.0, pulse.t, pulse.a, rtol=1e-6,
                          support="simplySupported", hinge_law="semiRigidHinge", psi=psi)
    print(f"wall {wall}: peak s1 {run.peak_s1:.4f} m, paper {paper}")
    assert run.peak_s1 == pytest.approx(paper, abs=0.002)


def test_table_5_4_el_centro_1dof(rockingwall_fmu):
    record = inputs.el_centro(0.5)
    run = rw_fmu.simulate(rockingwall_fmu, float(record.t[-1]), record.t, record.a, rtol=1e-6,
                          support="simplySupported", hinge_law="semiRigidHinge")
    print(f"El Centro x0.5 1DOF: peak s1 {run.peak_s1:.4f} m, paper 0.043")
    assert run.peak_s1 == pytest.approx(0.043, rel=0.10)
