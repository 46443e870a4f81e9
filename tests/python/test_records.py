"""The package's one record reader (rockingwall.records): AT2 and CSV, errors naming file and line."""
import numpy as np
import pytest

from rockingwall import records

AT2 = """PEER NGA STRONG MOTION DATABASE RECORD
TEST EVENT, 1/1/2000, STATION, 000
ACCELERATION TIME SERIES IN UNITS OF G
NPTS=    5, DT=   .0100 SEC
  .1000000E-01  .2000000E-01 -.1000000E-01
  .0000000E+00  .5000000E-02
"""


def test_read_at2(tmp_path):
    f = tmp_path / "r.AT2"
    f.write_text(AT2)
    r = records.read_at2(f)
    assert r.t.size == 5 and r.t[1] == pytest.approx(0.01)
    assert r.ag[1] == pytest.approx(0.02 * 9.81) and r.pga == pytest.approx(0.02 * 9.81)
    assert r.scaled(0.5).ag[1] == pytest.approx(0.01 * 9.81)
    assert r.to_pga(0.3).pga == pytest.approx(0.3 * 9.81)
    for text, where in [(AT2.replace("NPTS=    5", "NPTS=    6"), r"r\.AT2:6: .*NPTS=6"),
                        (AT2.replace("-.1000000E-01", "-.1x0E-01"), r"r\.AT2:5: "),
                        (AT2.replace("NPTS=    5, DT=   .0100 SEC", "garbage"), r"r\.AT2:4: "),
                        (AT2.replace("UNITS OF G", "UNITS OF CM/S2"), r"r\.AT2:3: ")]:
        f.write_text(text)
        with pytest.raises(records.RecordError, match=where):
            records.read_at2(f)


def test_old_nga_header_layout(tmp_path):
    f = tmp_path / "old.at2"
    f.write_text(AT2.replace("NPTS=    5, DT=   .0100 SEC", "    5   .0100   NPTS, DT"))
    assert records.read_at2(f).t[-1] == pytest.approx(0.04)


def test_read_csv(tmp_path):
    f = tmp_path / "a.csv"
    f.write_text("time,accel\n0,0\n0.01,0.1\n0.02,-0.1\n")
    assert records.read_csv(f, units="g").ag[1] == pytest.approx(0.1 * 9.81)
    assert records.read_csv(f, units="m/s2").ag[1] == pytest.approx(0.1)
    for text, where in [("time,accel\n0,0\n0.01,abc\n", r"a\.csv:3: .*abc"),
                        ("0,0\n0.01,1\n0.005,2\n", r"a\.csv:3: .*after"),
                        ("0,0,1\n", r"a\.csv:1: .*2 columns")]:
        f.write_text(text)
        with pytest.raises(records.RecordError, match=where):
            records.read_csv(f)


def test_el_centro_and_gaussian():
    ec = records.el_centro()
    assert np.diff(ec.t)[0] == pytest.approx(0.02)
    assert ec.pga == pytest.approx(0.3128806 * 9.81, rel=1e-4)
    gp = records.gaussian(0.04, 1.0, dt=1e-4)
    # the acceleration is the second derivative of D exp(-(t - T/2)^2 / (2 (T/8)^2))
    u = 0.04 * np.exp(-(gp.t - 0.5) ** 2 / (2 * (1 / 8) ** 2))
    assert np.allclose(np.gradient(np.gradient(u, gp.t), gp.t)[10:-10], gp.ag[10:-10], atol=1e-3 * gp.pga)


def test_load_refuses_what_is_not_a_record(tmp_path):
    with pytest.raises(records.RecordError, match="not a record"):
        records.load(tmp_path / "x.bin")
    with pytest.raises(records.RecordError, match="missing.AT2"):
        records.load(tmp_path / "missing.AT2")
