"""The building scene as an SSP 1.0 archive (rockingwall.ssp): written from the master's scene,
read back, run by the fmpy master (through this package's reader) and by libcosim (its own SSP
loader, in a child process: libcosim aborts the process on some errors); the two agree. A
malformed archive is refused with an error naming the problem; a user replaces the Building FMU
by editing the archive."""
import json
import re
import subprocess
import sys
import zipfile

import numpy as np
import pytest

from rockingwall import records
from rockingwall.building import scene as bs
from rockingwall.building import ssp

T_END, H = 2.5, 1e-3


def pulse():
    return records.gaussian(0.03, 1.0, dt=1e-3)


def scene():
    """Two storeys, the wall in storey 2 (on floor 1, tied to floor 2): every kind of connection."""
    return bs.default_scene(2, walls=[2], diaphragm_law=1)


@pytest.fixture(scope="module")
def archive(tmp_path_factory):
    path = tmp_path_factory.mktemp("ssp") / "scene.ssp"
    ssp.write(scene(), path)
    return path


def libcosim_peaks(path, storey=2):
    outputs = [(f"wall_{storey}", "s1"), (f"wall_{storey}", "s2"), ("building", f"u_diaph_{storey}")]
    code = ("import json, sys; import numpy as np; from rockingwall import records\nfrom rockingwall.building import ssp\n"
            f"o = ssp.run_libcosim({str(path)!r}, records.gaussian(0.03, 1.0, dt=1e-3), {T_END}, {H}, {outputs!r})\n"
            "print(json.dumps({k[0] + '.' + k[1]: float(np.abs(v).max()) for k, v in o.items() if k != 'time'}))")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-2000:]
    return json.loads(proc.stdout.strip().splitlines()[-1])


def test_round_trip(archive):
    read = ssp.read(archive)
    original = scene()
    assert [(w.storey, w.real, w.integer) for w in read.walls] == [(w.storey, w.real, w.integer) for w in original.walls]
    assert read.building_integer == original.building_integer
    assert read.connections() == original.connections()


def test_fmpy_and_libcosim_agree(archive):
    """Inputs held (libcosim passes no derivatives) and the FMUs' own default tolerance in both."""
    check_masters_agree(archive, 2)


def test_fmpy_and_libcosim_agree_one_storey(tmp_path):
    """The wall of storey 1 takes the system's ag (the ground) and the building's u_top_1."""
    path = ssp.write(bs.default_scene(1, diaphragm_law=2), tmp_path / "one.ssp")
    check_masters_agree(path, 1)


def check_masters_agree(path, storey):
    r = bs.run(ssp.read(path), pulse(), T_END, H, order=1, rtol=None)
    theirs = libcosim_peaks(path, storey)
    assert r.peak(storey, "s1") > 0.01  # the wall rocks
    for key, mine in ((f"wall_{storey}.s1", r.peak(storey, "s1")), (f"wall_{storey}.s2", r.peak(storey, "s2")),
                      (f"building.u_diaph_{storey}", float(np.abs(r[f"u_diaph_{storey}"]).max()))):
        assert mine == pytest.approx(theirs[key], rel=1e-3), key  # measured 2e-13 relative


def rewrite(src, dst, edit_ssd=None, drop=None, add=None):
    """A copy of the archive src with its .ssd edited, a member dropped or members added."""
    with zipfile.ZipFile(src) as zin, zipfile.ZipFile(dst, "w") as zout:
        for item in zin.infolist():
            if item.filename == drop:
                continue
            data = zin.read(item.filename)
            if item.filename == "SystemStructure.ssd" and edit_ssd:
                data = edit_ssd(data.decode()).encode()
            zout.writestr(item, data)
        for name, data in (add or {}).items():
            zout.writestr(name, data)
    return dst


def test_missing_fmu(archive, tmp_path):
    bad = rewrite(archive, tmp_path / "bad.ssp", drop="resources/Building.fmu")
    with pytest.raises(ssp.SSPError, match=r"component 'building': its FMU 'resources/Building.fmu' is not in the archive"):
        ssp.read(bad)


def test_unknown_connector(archive, tmp_path):
    bad = rewrite(archive, tmp_path / "bad.ssp",
                  edit_ssd=lambda s: s.replace('endConnector="F_wall_2"', 'endConnector="F_wall_7"'))
    with pytest.raises(ssp.SSPError, match=r"component 'building' has no connector 'F_wall_7'"):
        ssp.read(bad)


def test_connector_the_fmu_does_not_have(archive, tmp_path):
    def edit(s):
        s = s.replace('endConnector="F_wall_2"', 'endConnector="F_wall_9"')
        return s.replace('<ssd:Connector name="F_wall_2"', '<ssd:Connector name="F_wall_9"')
    with pytest.raises(ssp.SSPError, match=r"the FMU of 'building' has no variable 'F_wall_9'"):
        ssp.read(rewrite(archive, tmp_path / "bad.ssp", edit_ssd=edit))


def test_unit_mismatch(archive, tmp_path):
    def edit(s):  # the wall's u_top declared in mm
        return re.sub(r'(<ssd:Connector name="u_top" kind="input">\s*<ssc:Real unit=")m(")', r"\1mm\2", s)
    with pytest.raises(ssp.SSPError, match=r"connector wall_2.u_top has unit 'mm', its FMU's variable 'm'"):
        ssp.read(rewrite(archive, tmp_path / "bad.ssp", edit_ssd=edit))


def test_not_an_archive(tmp_path):
    (tmp_path / "x.ssp").write_text("not a zip")
    with pytest.raises(ssp.SSPError, match="not an SSP archive"):
        ssp.read(tmp_path / "x.ssp")


def test_not_xml(archive, tmp_path):
    bad = rewrite(archive, tmp_path / "bad.ssp", edit_ssd=lambda s: s[: len(s) // 2])
    with pytest.raises(ssp.SSPError, match="not well-formed XML"):
        ssp.read(bad)


def test_replacement_building_without_the_masters_variables(archive, tmp_path):
    """The Diaphragm FMU put in the building's place: named as lacking what the master reads."""
    from rockingwall.paths import diaphragm_fmu

    def edit(s):  # its connectors still name the building's variables: drop those checks' cause
        return s.replace('source="resources/Building.fmu"', 'source="resources/Diaphragm.fmu"')
    bad = rewrite(archive, tmp_path / "bad.ssp", edit_ssd=edit, drop="resources/Building.fmu",
                  add={"resources/Diaphragm.fmu": diaphragm_fmu().read_bytes()})
    with pytest.raises(ssp.SSPError, match="the FMU of 'building' has no variable"):
        ssp.read(bad)


def test_a_wall_in_every_storey_is_written_and_both_masters_agree(tmp_path):
    """Walls in adjacent storeys: the wall above's F_base goes to the building's F_above_1, the wall
    below's F_top to F_wall_1, one connection each; both masters agree on both walls, and the
    archive runs as the in-process scene does."""
    path = ssp.write(bs.default_scene(2, diaphragm_law=1), tmp_path / "both.ssp")
    assert ("wall_2", "F_base", "building", "F_above_1") in ssp.read(path).connections()
    check_masters_agree(path, 1)
    check_masters_agree(path, 2)
    direct = bs.run(bs.default_scene(2, diaphragm_law=1), pulse(), T_END, H, order=1, rtol=None)
    via_ssp = bs.run(ssp.read(path), pulse(), T_END, H, order=1, rtol=None)
    assert via_ssp.peak(1, "s1") == direct.peak(1, "s1") and via_ssp.peak(2, "s1") == direct.peak(2, "s1")


def test_user_replaces_the_building(archive, tmp_path):
    """Another building FMU (here the same binary under another name, its diaphragm 2 four times
    stiffer through the edited start values) named in the component's source: the scene runs it."""
    building = zipfile.ZipFile(archive).read("resources/Building.fmu")

    def edit(s):
        s = s.replace('source="resources/Building.fmu"', 'source="resources/StiffBuilding.fmu"')
        return s.replace('</ssv:Parameters>', '<ssv:Parameter name="kd_2"><ssv:Real value="2.8e6"/></ssv:Parameter>'
                         '</ssv:Parameters>', 1)
    edited = rewrite(archive, tmp_path / "edited.ssp", edit_ssd=edit, drop="resources/Building.fmu",
                     add={"resources/StiffBuilding.fmu": building})
    new = ssp.read(edited)
    assert new.building_fmu.endswith("StiffBuilding.fmu") and new.building_real["kd_2"] == 2.8e6
    r_new = bs.run(new, pulse(), T_END, H)
    r_old = bs.run(ssp.read(archive), pulse(), T_END, H)
    # a stiffer diaphragm moves less relative to its floor
    assert np.abs(r_new["u_diaph_2"] - r_new["u_floor_2"]).max() < 0.7 * np.abs(r_old["u_diaph_2"] - r_old["u_floor_2"]).max()


def test_building_variables_the_master_reads_are_checked():
    """A replacement building with the connected variables but not, e.g., the velocities."""
    full = ssp.fmu_units(scene().building_fmu)
    ssp.check_building_variables(scene(), full, "x.ssp")  # the Building has them all
    lacking = {k: v for k, v in full.items() if not k.startswith("v_floor_")}
    with pytest.raises(ssp.SSPError, match="lacks variables the master reads: v_floor_1, v_floor_2"):
        ssp.check_building_variables(scene(), lacking, "x.ssp")


def test_the_documented_module_path_names_the_same_functions():
    """docs/building-coupling.md has long named rockingwall.ssp; it is rockingwall.building.ssp."""
    import rockingwall.ssp as documented
    assert (documented.write, documented.read, documented.run_libcosim, documented.SSPError) == (
        ssp.write, ssp.read, ssp.run_libcosim, ssp.SSPError)
