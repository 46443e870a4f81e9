"""Hostile and malformed SSP archives (made here from a written scene, never stored): every
problem is an SSPError naming the file and the component, never a traceback, and nothing outside
the archive is opened: a `source` may not leave it, only what the .ssd references is extracted,
within size limits; two components with one name are refused instead of the last one winning."""
import re
import shutil
import zipfile

import pytest

from cli_harness import assert_refused, cli
from rockingwall.building import scene as bs
from rockingwall.building import ssp

WALL = "resources/RockingWall.fmu"


@pytest.fixture(scope="module")
def archive(tmp_path_factory):
    return ssp.write(bs.default_scene(2, walls=[1, 2], diaphragm_law=1), tmp_path_factory.mktemp("ssp") / "scene.ssp")


def variant(src, dst, ssd=None, add=None, drop=()):
    """A copy of the archive with its .ssd rewritten by ssd(text) and members added or dropped."""
    with zipfile.ZipFile(src) as zin, zipfile.ZipFile(dst, "w", zipfile.ZIP_DEFLATED) as zout:
        for item in zin.infolist():
            if item.filename in drop:
                continue
            data = zin.read(item.filename)
            if item.filename == "SystemStructure.ssd" and ssd:
                data = ssd(data.decode()).encode()
            zout.writestr(item, data)
        for name, data in (add or {}).items():
            if callable(data):
                with zout.open(name, "w", force_zip64=True) as member:
                    data(member)
            else:
                zout.writestr(name, data)
    return dst


def component(text, name):
    """The <ssd:Component> element of `name` in the .ssd text."""
    return re.search(rf'<ssd:Component name="{name}".*?</ssd:Component>', text, re.S).group(0)


def refused(path, *needles):
    with pytest.raises(ssp.SSPError) as caught:
        ssp.read(path)
    for needle in (str(path), *needles):
        assert needle in str(caught.value), (needle, str(caught.value))
    proc = cli("couple-building", "--from-ssp", path, "--record", "gaussian", "--t-end", "0.01")
    assert_refused(proc, *needles)


def test_finding_an_ssp_source_outside_the_archive_is_refused(archive, tmp_path):
    escape = "resources/../../../../elsewhere/RockingWall.fmu"
    bad = variant(archive, tmp_path / "escape.ssp", ssd=lambda s: s.replace(f'source="{WALL}"', f'source="{escape}"'),
                  add={escape: zipfile.ZipFile(archive).read(WALL)})
    dest = tmp_path / "a" / "b" / "c" / "x"
    decoy = tmp_path / "a" / "elsewhere" / "RockingWall.fmu"  # where the source resolves from `dest`
    decoy.parent.mkdir(parents=True)
    shutil.copy(zipfile.ZipFile(archive).extract(WALL, tmp_path / "unzipped"), decoy)
    with pytest.raises(ssp.SSPError, match="outside the archive"):
        ssp.read(bad, extract_to=dest)
    refused(bad, "wall_1", "outside the archive")
    absolute = variant(archive, tmp_path / "absolute.ssp", ssd=lambda s: s.replace(f'source="{WALL}"', f'source="{decoy}"'))
    refused(absolute, "wall_1", "outside the archive")


def test_finding_two_ssp_components_with_the_same_name_are_refused(archive, tmp_path):
    def twice(s):  # a second wall_2, stiffer: it silently replaced the first
        first = component(s, "wall_2")
        return s.replace(first, first + first.replace("1000000.0", "5000.0"))
    refused(variant(archive, tmp_path / "twice.ssp", ssd=twice), "two components named 'wall_2'")


@pytest.mark.parametrize("case, needles", [
    ("garbage_fmu", ("wall_1", WALL)), ("unknown_parameter", ("wall_1", "nosuch")),
    ("not_a_number", ("wall_1", "abc")), ("untyped_system_connector", ("ag",)),
    ("two_connections_to_one_input", ("wall_2.u_top",)),
])
def test_finding_malformed_ssp_files_are_ssp_errors_naming_file_and_component(archive, tmp_path, case, needles):
    malformed(archive, tmp_path, case, needles)


@pytest.mark.parametrize("case, needles", [("untyped_connector", ("building", "u_top_1")),
                                           ("no_end_connector", ("connection",))])
def test_ssp_connector_problems_stay_named(archive, tmp_path, case, needles):
    malformed(archive, tmp_path, case, needles)


def malformed(archive, tmp_path, case, needles):
    add, ssd = {}, None
    if case == "garbage_fmu":
        ssd, add = (lambda s: s.replace(f'source="{WALL}"', 'source="resources/junk.fmu"')), {"resources/junk.fmu": b"junk"}
        needles = ("wall_1", "resources/junk.fmu")
    elif case == "unknown_parameter":
        ssd = lambda s: s.replace('<ssv:Parameter name="psi">', '<ssv:Parameter name="nosuch">', 1)
    elif case == "untyped_connector":
        ssd = lambda s: re.sub(r'(<ssd:Connector name="u_top_1" kind="output">)\s*<ssc:Real unit="m" />', r"\1", s)
    elif case == "not_a_number":
        ssd = lambda s: re.sub(r'(<ssv:Parameter name="b">\s*<ssv:Real value=")[^"]*', r"\1abc", s, count=1)
    elif case == "untyped_system_connector":
        ssd = lambda s: re.sub(r'(<ssd:Connector name="ag" kind="input">)\s*<ssc:Real unit="m/s2" />', r"\1", s, count=1)
    elif case == "no_end_connector":
        ssd = lambda s: s.replace('endConnector="F_wall_2"', "", 1)
    elif case == "two_connections_to_one_input":
        ssd = lambda s: s.replace('endElement="wall_1" endConnector="u_top"', 'endElement="wall_2" endConnector="u_top"')
    refused(variant(archive, tmp_path / f"{case}.ssp", ssd=ssd, add=add), *needles)


def test_finding_ssp_read_extracts_only_what_the_ssd_references(archive, tmp_path, monkeypatch):
    zeros = b"\0" * (1 << 20)
    junk = variant(archive, tmp_path / "junk.ssp", add={
        "resources/junk.bin": lambda member: [member.write(zeros) for _ in range(200)],  # 200 MB, unreferenced
        "../outside.txt": b"escaped"})
    dest = tmp_path / "dest"
    scene = ssp.read(junk, extract_to=dest)
    assert sorted(str(p.relative_to(dest)) for p in dest.rglob("*") if p.is_file()) == \
        ["resources/Building.fmu", "resources/RockingWall.fmu"]
    assert scene.wall_fmu == str(dest / WALL) and not (tmp_path / "outside.txt").exists()
    from rockingwall.building import ssp_read
    monkeypatch.setattr(ssp_read, "FMU_MAX_BYTES", 250_000)  # the wall FMU (330 kB) too large, not the building (180 kB)
    with pytest.raises(ssp.SSPError, match=r"wall_1.*250000 bytes"):
        ssp.read(junk, extract_to=tmp_path / "dest2")
