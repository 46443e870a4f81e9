"""Paper reproduction cells that must hold (Table 5.2 1DOF column, Table 5.4 El Centro 1DOF, wall-1 2DOF)."""
import pytest

from rwref import Params, simulate, inputs, WALLS

CASES = [(1, 0.040, 0.064), (2, 0.040, 0.040), (3, 0.050, 0.033)]


@pytest.mark.parametrize("wall,D,paper", CASES)
def test_table_5_2_1dof(wall, D, paper):
    r = simulate(Params(support="simplySupported", hinge_law="semiRigidHinge", **WALLS[wall]), inputs.gaussian(D, 1.0), 10.0)
    assert not r.collapsed
    assert abs(r.peak_s1 - paper) <= 0.002
    assert r.peak_s2 == 0.0


def test_table_5_4_el_centro_1dof():
    ag = inputs.el_centro(0.5)
    r = simulate(Params(support="simplySupported", **WALLS[1]), ag, ag.duration)
    assert abs(r.peak_s1 - 0.043) <= 0.1 * 0.043


@pytest.mark.parametrize("Kd_kN,paper", [(1000, 0.066), (100, 0.069), (50, 0.073)])
def test_table_5_2_wall1_2dof_s1_within_10pct(Kd_kN, paper):
    """Holds with the default semiRigidHinge law and hingeSat = 2 (not calibrated on these cells)."""
    r = simulate(Params(support="flexibleTop", hinge_law="semiRigidHinge", Kd=Kd_kN * 1e3, **WALLS[1]),
                 inputs.gaussian(0.04, 1.0), 10.0)
    assert abs(r.peak_s1 - paper) <= 0.1 * paper
