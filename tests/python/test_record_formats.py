"""The downloaded record formats (rockingwall.records): ESM, GeoNet V2A, K-NET and COSMOS V2
files written here from known samples read back to the samples of their two-column source (in
m/s^2, to 1e-12); a wrong sample count, a wrong time step and a header the reader cannot interpret
are refused naming the file, the line and the problem; the format is found from the content,
whatever the file's name; a component is chosen by name or position."""
import re

import numpy as np
import pytest

import record_files as rf
from record_files import FORMATS, write
from rockingwall import records


def same_samples(record, t, ag):
    np.testing.assert_allclose(record.t, t, rtol=1e-12, atol=0)
    np.testing.assert_allclose(record.ag, ag, rtol=1e-12, atol=1e-15)


@pytest.mark.parametrize("fmt", FORMATS)
def test_each_format_reads_to_the_samples_of_its_two_column_source(fmt, tmp_path):
    path = tmp_path / FORMATS[fmt]
    expected = write(fmt, path)
    rf.two_columns(tmp_path / "source.csv", expected)
    source = records.read_csv(tmp_path / "source.csv", units="m/s2")
    assert records.detect_format(path) == fmt
    record = records.load(path)
    same_samples(record, source.t, source.ag)
    assert record.t[0] == 0.0 and record.t.size == rf.N
    t, ag, name, meta = records.read_format(path)
    same_samples(records.Record(name, t, ag), source.t, source.ag)
    assert meta["npts"] == rf.N and meta["dt"] == pytest.approx(rf.DT, rel=1e-12)
    assert name.startswith("r") and meta["component"] in name


def lines_of(path):
    return path.read_text().splitlines()


def line_no(lines, prefix):
    """The 1-based number of the first line that starts with prefix."""
    return next(i for i, line in enumerate(lines, 1) if line.lstrip().startswith(prefix))


def edit(path, number, old, new):
    lines = lines_of(path)
    assert old in lines[number - 1], (old, lines[number - 1])
    lines[number - 1] = lines[number - 1].replace(old, new, 1)
    path.write_text("\n".join(lines) + "\n")


def drop(path, number):
    lines = lines_of(path)
    del lines[number - 1]
    path.write_text("\n".join(lines) + "\n")


def refused(path, pattern):
    with pytest.raises(records.RecordError, match=pattern) as err:
        records.load(path)
    return str(err.value)


def test_esm_refuses_a_wrong_count_a_wrong_time_step_and_unknown_units(tmp_path):
    path = tmp_path / FORMATS["esm"]
    write("esm", path)
    lines = lines_of(path)
    n_at, dt_at, dur_at, units_at = (line_no(lines, key) for key in
                                     ("NDATA:", "SAMPLING_INTERVAL_S:", "DURATION_S:", "UNITS:"))
    edit(path, n_at, "NDATA: 400", "NDATA: 401")
    refused(path, rf"^{re.escape(str(path))}:{n_at}: the header announces 401 samples \(NDATA\), the file holds 400$")
    write("esm", path)
    edit(path, dt_at, "0.010000", "0.020000")
    refused(path, rf":{dt_at}: SAMPLING_INTERVAL_S = 0.02 s and NDATA = 400 give 8 s, but DURATION_S \(line {dur_at}\) "
                  r"is 4\.000 s")
    write("esm", path)
    edit(path, units_at, "cm/s^2", "furlong/s^2")
    refused(path, rf":{units_at}: acceleration units 'furlong/s\^2' are not ones this reader converts")


def test_knet_refuses_a_wrong_count_a_wrong_time_step_and_an_unknown_scale(tmp_path):
    path = tmp_path / FORMATS["knet"]
    write("knet", path)
    drop(path, len(lines_of(path)))  # the last 8 samples
    refused(path, rf"^{re.escape(str(path))}:12: Duration Time x Sampling Freq \(lines 11-12\) make 400 samples, "
                  r"the file holds 392$")
    write("knet", path)
    edit(path, 11, "100Hz", "200Hz")
    refused(path, r":12: Duration Time x Sampling Freq \(lines 11-12\) make 800 samples, the file holds 400")
    write("knet", path)
    edit(path, 14, "(gal)", "(m/s2)")
    refused(path, r":14: expected the Scale Factor as 'num\(gal\)/denom', found '3920\(m/s2\)/6182761'")
    write("knet", path)
    edit(path, 15, "Max. Acc. (gal)   ", "Max. Acc. (gal)   1")  # a peak the samples do not have
    refused(path, r":15: Max. Acc. is 1\d*\.\d+ gal, but the samples")


def test_geonet_refuses_a_wrong_count_a_wrong_time_step_and_other_units(tmp_path):
    path = tmp_path / FORMATS["geonet"]
    write("geonet", path)
    block = 16 + 4 + 6 + 3 * 40  # lines of one component
    drop(path, 16 + 4 + 6 + 5)  # an acceleration line of the first component: its block ends a line early
    refused(path, rf"^{re.escape(str(path))}:{block}: text where the 1200 values announced on line 20 should be")
    write("geonet", path)
    edit(path, 23, "  0.0100", "  0.0200")  # real 26, the time step
    refused(path, r":10: 400 points every 0\.02 s \(real 26, line 23\) last 7\.98 s, but the text says a duration "
                  r"of 3\.99 s")
    write("geonet", path)
    edit(path, 14, "mm/s/s at", "cm/s/s at")
    refused(path, r":14: the text gives a peak of -?\d+\.\d cm/s/s, the samples")


def test_cosmos_refuses_a_wrong_count_a_wrong_time_step_and_raw_counts(tmp_path):
    path = tmp_path / FORMATS["cosmos"]
    write("cosmos", path)
    lines = lines_of(path)
    data_at, reals_at = line_no(lines, "400 acceleration pts"), line_no(lines, "100 Real-header")
    edit(path, data_at, "400 acceleration", "410 acceleration")
    refused(path, rf"^{re.escape(str(path))}:{data_at + 51}: text where the 410 values announced on line {data_at} "
                  "should be")
    write("cosmos", path)
    edit(path, reals_at + 11, "10.000000", "20.000000")  # real 62, the time step in ms
    refused(path, rf":{reals_at}: 400 points every 0\.02 s \(real 62\) last 8 s, but real 63 says 4 s")
    write("cosmos", path)
    edit(path, data_at, "(04)", "(50)")
    refused(path, rf":{data_at}: units code 50 \(cm/sec2\) is not read: only accelerations in g \(02\) or "
                  r"cm/sec2 \(04\)")


def test_an_unknown_format_is_refused_listing_the_formats_read(tmp_path):
    path = tmp_path / "mystery.ASC"
    path.write_text("SEISMOGRAM OF SOMEWHERE\n1 2 3\n4 5 6\n")
    message = refused(path, rf"^{re.escape(str(path))}:1: not a record in a format this program reads")
    for name in ("AT2", "CSV", "ESM", "GeoNet", "K-NET", "COSMOS"):
        assert name in message
    with pytest.raises(records.RecordError, match="not a record"):
        records.load(tmp_path / "absent.V2A")


@pytest.mark.parametrize("fmt, name", [("esm", "quake.AT2"), ("knet", "quake.csv"), ("geonet", "quake.txt"),
                                       ("cosmos", "quake")])
def test_the_content_decides_whatever_the_name(fmt, name, tmp_path):
    path = tmp_path / name
    expected = write(fmt, path)
    assert records.detect_format(path) == fmt
    same_samples(records.load(path), np.arange(rf.N) * rf.DT, expected)


def test_at2_and_csv_are_recognised_by_content_too(tmp_path):
    at2, csv = tmp_path / "pulse.acc", tmp_path / "pulse.tbl"
    at2.write_text("PEER NGA STRONG MOTION DATABASE RECORD\nTEST\nACCELERATION TIME SERIES IN UNITS OF G\n"
                   "NPTS=    3, DT=   .0100 SEC\n .1 .2 -.1\n")
    csv.write_text("time,acc\n0,0.1\n0.01,0.2\n")
    assert records.detect_format(at2) == "at2" and records.detect_format(csv) == "csv"
    assert records.load(at2).ag[1] == pytest.approx(0.2 * 9.81)
    assert records.load(csv, units="m/s2").ag[1] == pytest.approx(0.2)


def test_a_component_is_chosen_by_name_or_position(tmp_path):
    path = tmp_path / "r.V2A"
    acc = rf.accelerations()
    comps = rf.geonet(path, {"N28W": acc, "S74E": -0.5 * acc[::-1], "Up": 0.2 * acc})
    for spec, comp in [(path, "N28W"), (f"{path}:s74e", "S74E"), (f"{path}:3", "Up"), (f"{path}:UP", "Up")]:
        record = records.load(spec)
        same_samples(record, np.arange(rf.N) * rf.DT, comps[comp])
        assert record.name == f"r {comp}"
    refused(f"{path}:N", r"r\.V2A: no component 'N' in this file; it has 1 = N28W, 2 = S74E, 3 = Up")
    cosmos = tmp_path / "r.V2c"
    chans = rf.cosmos(cosmos, [acc, 0.7 * acc[::-1]])
    same_samples(records.load(f"{cosmos}:2"), np.arange(rf.N) * rf.DT, chans[1])
    assert records.load(cosmos).name == "r chan 1"
    knet = tmp_path / "r.NS"
    rf.knet(knet, acc, direction="N-S")
    assert records.load(f"{knet}:ns").name == records.load(knet).name == "r NS"
    refused(f"{knet}:EW", "no component 'EW' in this file; it has 1 = NS")
