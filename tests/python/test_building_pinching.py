"""A timber diaphragm's pinching: `law = "boucWenPinched"` in a building file pinches (Foliente's
zeta1, zeta2, q; the Building FMU's timber defaults unless the file gives them) in the scene
solver, the co-simulated Building FMU and BuildingWithWalls.fmu alike. Before, the solver's
pinching was zero whatever the law said: boucWenPinched ran as boucWen."""
import pathlib
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from rockingwall import records
from rockingwall.api import simulate
from rockingwall.building import building_file, cosim, monolithic, with_walls
from rockingwall.building.description import Diaphragm
from rockingwall.wall import Wall

ROOT = pathlib.Path(__file__).resolve().parents[2]
PINCH = ("pinchSize", "pinchWidth", "pinchCentre")

TIMBER = """\
[building]
name = "one storey, pinched timber roof"

[[storey]]
height = "3.6 m"
wall = { b = "230 mm", unit_weight = "18 kN/m3", overburden = "1.5 kN/m" }
diaphragm = { stiffness = "20 kN/m/m", mass = "200 kg/m", law = "boucWenPinched", yield_force = "2 kN/m"%s }
"""


def building_fmu_defaults():
    """The Building FMU's own start values of its pinching parameters, from its model description."""
    xml = ET.parse(ROOT / "fmu_src/models/Building/fmi2/modelDescription.xml")
    starts = {v.get("name"): float(v.find("Real").get("start")) for v in xml.iter("ScalarVariable")
              if v.get("name") in PINCH}
    return tuple(starts[n] for n in PINCH)


def test_finding_a_pinched_law_ran_without_pinching_in_the_scene_solver():
    spec = monolithic.building_spec(building_file.parse(TIMBER % "", "roof.toml"))
    assert (spec.pinch_size, spec.pinch_width, spec.pinch_centre) == building_fmu_defaults()
    assert spec.pinch_size > 0  # the Building FMU's timber default pinches


def test_the_file_sets_the_pinching_and_every_solver_takes_it():
    b = building_file.parse(TIMBER % ', pinch_size = 0.5, pinch_width = 0.3, pinch_centre = 0.05', "roof.toml")
    spec = monolithic.building_spec(b)
    assert (spec.pinch_size, spec.pinch_width, spec.pinch_centre) == (0.5, 0.3, 0.05)
    real, _ = cosim.building_start_values(b)
    fmu = with_walls.start_values(b)
    for values in (real, fmu):
        assert tuple(values[n] for n in PINCH) == (0.5, 0.3, 0.05)


@pytest.mark.parametrize("extra, line, words", [
    (', pinch_size = 1.5', 7, "outside"),  # the diaphragm's line
    (', pinch_width = "0.2 m"', 7, "unit"),
])
def test_bad_pinching_names_the_file_and_line(extra, line, words):
    with pytest.raises(building_file.BuildingFileError) as err:
        building_file.parse(TIMBER % extra, "roof.toml")
    assert f"roof.toml:{line}:" in str(err.value) and words in str(err.value)


def test_pinching_with_another_law_is_refused():
    text = (TIMBER % ', pinch_size = 0.5').replace('"boucWenPinched"', '"boucWen"')
    with pytest.raises(building_file.BuildingFileError) as err:
        building_file.parse(text, "roof.toml")
    assert "roof.toml:7:" in str(err.value) and "boucWenPinched" in str(err.value)


def test_pinching_changes_a_yielding_diaphragm_and_nothing_else():
    """Same wall, record and diaphragm; only the pinching differs. The diaphragm yields (2 kN/m
    under a wall of 14.9 kN/m at 0.5 g), so a pinched loop must change the response; with
    pinch_size 0 the pinched law is Bouc-Wen's."""
    wall = Wall.make(b=0.23, h=3.6, W=14904.0, psi=0.2013, Kd=20e3)
    rec = records.load("elcentro").to_pga(0.5)

    def peak(law, pinching):
        d = Diaphragm(stiffness=20e3, mass=200.0, law=law, yield_force=2e3, post_yield=0.1, pinching=pinching)
        return simulate(wall, rec, diaphragm=d, stop_time=12.0).history[["s1", "s2"]].to_numpy()

    plain = peak("boucWen", None)
    unpinched = peak("boucWenPinched", {"pinch_size": 0.0, "pinch_width": 1.0, "pinch_centre": 0.0})
    pinched = peak("boucWenPinched", None)
    assert np.allclose(unpinched, plain, rtol=0, atol=1e-9, equal_nan=True)  # NaN: the wall after its collapse
    assert np.nanmax(np.abs(pinched - plain)) > 0.01 * np.nanmax(np.abs(plain))
