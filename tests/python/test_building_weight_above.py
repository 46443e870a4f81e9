"""The weight of the walls above in a building's walls: a lower wall carries the upper walls'
weight (their own and the overburdens they carry) as weight-only overburden, psiWeightOnly, while
their mass stays in their own walls (docs/your-building.md). Numbers by hand from the building
file's contract (examples/two-storey-brick.toml)."""
import pytest

from rockingwall import engine
from rockingwall.building import building_file, monolithic, with_walls

@pytest.fixture(scope="module")
def house(repo):
    """the issue's contract as the example file holds it"""
    return building_file.read(repo / "examples" / "two-storey-brick.toml")


# by hand: the upper wall weighs 18 kN/m3 x 0.23 m x 3.6 m = 14.904 kN/m and carries the roof's
# 1.5 kN/m, so 16.404 kN/m bear on the lower wall's top besides its own floor's 3.2 kN/m
W_GROUND, W_UPPER = 25200.0, 14904.0
ABOVE_GROUND = 14904.0 + 1500.0                     # 16404 N/m
PSI_WO_GROUND = 2 * 16404.0 / 25200.0               # 1.301904... (over W1 = W/2)
PSI_GROUND, PSI_UPPER = 2 * 3200.0 / 25200.0, 2 * 1500.0 / 14904.0


def test_the_lower_wall_carries_the_upper_walls_weight_without_their_mass(house):
    assert house.weight_above(0) == pytest.approx(ABOVE_GROUND, rel=1e-12)
    assert house.weight_above(1) == 0.0
    ground, upper = house.wall_parameters(0), house.wall_parameters(1)
    assert ground["psiWeightOnly"] == pytest.approx(PSI_WO_GROUND, rel=1e-12)
    assert upper["psiWeightOnly"] == 0.0
    # the mass moving with each wall's top is its own overburden's alone: the upper wall's mass is
    # in the upper wall, not counted again in the lower one
    assert ground["psi"] == pytest.approx(PSI_GROUND, rel=1e-12)
    assert upper["psi"] == pytest.approx(PSI_UPPER, rel=1e-12)
    # the scene the solver runs and the BuildingWithWalls FMU's start values say the same
    walls = [s.wall for s in monolithic.building_spec(house).storeys]
    assert walls[0]["psi"] == pytest.approx(PSI_GROUND, rel=1e-12)
    assert walls[0]["psiWeightOnly"] == pytest.approx(PSI_WO_GROUND, rel=1e-12)
    assert walls[1]["psiWeightOnly"] == 0.0
    v = with_walls.start_values(house)
    assert v["psi_1"] == pytest.approx(PSI_GROUND, rel=1e-12)
    assert v["psiWeightOnly_1"] == pytest.approx(PSI_WO_GROUND, rel=1e-12) and v["psiWeightOnly_2"] == 0.0
    # and the echo says so
    lines = house.describe().splitlines()
    assert "overburden 3.2 kN/m + walls above 16.4 kN/m (weight only)" in lines[2]
    assert "overburden 1.5 kN/m, dohertyHinge" in lines[4]


def test_the_lower_walls_delta_u_counts_the_weight_above(house):
    """Every top load at the centreline and the reactions on the faces: C8's Delta_i is
    b (1 + 0.75 psi_t)/(1 + psi_t) with psi_t the whole top load over W/2, here
    (3200 + 16404)/12600 = 1.555873...: 0.35 (1 + 1.166905)/(2.555873) = 0.296738... m, against
    0.35 (1 + 0.75 x 0.253968)/(1.253968) = 0.332278... m without the walls above."""
    psi_t = (3200.0 + 16404.0) / 12600.0
    want = 0.35 * (1 + 0.75 * psi_t) / (1 + psi_t)
    assert want == pytest.approx(0.2967, abs=1e-4)
    got = engine.statics(**house.wall_parameters(0))["Delta_u"]
    assert got[1] == pytest.approx(want, rel=1e-12) and got[-1] == pytest.approx(want, rel=1e-12)
