"""Small record files in the formats engineers download, for the tests of rockingwall.records:
each writer lays its file out as the format's documentation and the agencies' published files do
(header fields, units, fixed-width columns) from known accelerations, and returns the samples in
m/s^2 that a reader must give back (the values as the file prints them)."""
import numpy as np

DT, N = 0.01, 400
FORMATS = {"esm": "r.ASC", "knet": "r.EW", "geonet": "r.V2A", "cosmos": "r.V2c"}  # a file name of each


def accelerations(n=N, dt=DT, amp=9.0, seed=0):
    """A record [m/s^2] with peaks above 10 m/s^2 (10 000 mm/s^2: GeoNet's 8-character fields
    then touch) and of both signs."""
    t = np.arange(n) * dt
    noise = np.random.default_rng(seed).normal(0.0, 0.2, n)
    return amp * np.sin(2 * np.pi * t / 0.8) * np.exp(-0.3 * t) + 3.0 * np.sin(2 * np.pi * t / 0.13) + noise


def esm(path, acc, dt=DT):
    """ESM ASCII: 64 'KEY: value' lines, then one value per line in cm/s^2 with 6 decimals."""
    cm = np.array([float(f"{v:.6f}") for v in acc * 100])
    peak = cm[np.argmax(np.abs(cm))]
    keys = [("EVENT_NAME", "TEST EVENT"), ("EVENT_ID", "TEST-20000101_0000001"), ("EVENT_DATE_YYYYMMDD", "20000101"),
            ("NETWORK", "XX"), ("STATION_CODE", "TEST"), ("STATION_NAME", "Test station, Somewhere"),
            ("DATE_TIME_FIRST_SAMPLE_YYYYMMDD_HHMMSS", "20000101_000000.000"),
            ("SAMPLING_INTERVAL_S", f"{dt:.6f}"), ("NDATA", str(len(cm))), ("DURATION_S", f"{len(cm) * dt:.3f}"),
            ("STREAM", "HNE"), ("UNITS", "cm/s^2"), ("PGA_CM/S^2", f"{peak:.6f}"),
            ("BASELINE_CORRECTION", "BASELINE REMOVED"),
            ("DATA_TYPE", "ACCELERATION"), ("HEADER_FORMAT", "DYNA 1.2")]
    keys += [(f"USER{i}", "") for i in range(1, 64 - len(keys) + 1)]
    lines = [f"{k}: {v}" for k, v in keys] + [f"{v:.6f}" for v in cm]
    path.write_text("\n".join(lines) + "\n")
    return cm * 0.01


def knet(path, acc, dt=DT, direction="E-W", num=3920.0, denom=6182761.0):
    """K-NET ASCII: 17 header lines (18-character labels), counts 8 to a line; counts x num/denom
    are gal, and NIED removes the mean (its 'Max. Acc.' is the peak after that)."""
    counts = np.round(acc * 100 / (num / denom) + 5000).astype(int)  # an offset, as recorders have
    gal = counts * (num / denom)
    gal = gal - gal.mean()
    header = [("Origin Time", "2000/01/01 00:00:00"), ("Lat.", "41.0"), ("Long.", "142.5"), ("Depth. (km)", "30"),
              ("Mag.", "6.2"), ("Station Code", "TST001"), ("Station Lat.", "41.5"), ("Station Long.", "140.9"),
              ("Station Height(m)", "39"), ("Record Time", "2000/01/01 00:00:15"),
              ("Sampling Freq(Hz)", f"{round(1 / dt)}Hz"), ("Duration Time(s)", f"{len(counts) * dt:g}"),
              ("Dir.", direction), ("Scale Factor", f"{num:.0f}(gal)/{denom:.0f}"),
              ("Max. Acc. (gal)", f"{np.max(np.abs(gal)):.3f}"), ("Last Correction", "2000/01/01 00:00:15"),
              ("Memo.", "")]
    lines = [f"{label:<18}{value}" for label, value in header]
    lines += ["".join(f"{c:9d}" for c in counts[i:i + 8]) for i in range(0, len(counts), 8)]
    path.write_text("\n".join(lines) + "\n")
    return gal * 0.01


def fortran_lines(values, per_line, fmt):
    return ["".join(fmt.format(v) for v in values[i:i + per_line]) for i in range(0, len(values), per_line)]


def geonet_block(acc_mm, dt, component):
    """One component of a V2A file: 16 text lines, 40 integers (10I8), 60 reals (10F8), then the
    accelerations, velocities and displacements, 10 to a line, 8 characters each."""
    n = len(acc_mm)
    peak = acc_mm[np.argmax(np.abs(acc_mm))]
    text = ["Corrected accelerogram 20000101_000000_TEST_20 GNS Science",
            "Site TEST      42 37 10S  173 03 13E     Basalt file:  20000101_000000_TEST",
            "Test site", "Instrument Basalt_0001", "Resolution: 24-bit   Instr Period: 0.0050 s   Damping: 0.700",
            "Accelerogram 20000101_000000_TEST_20                 Processed 2000 January 02",
            "5 km south of Somewhere", "2000 January 01         00:00:00 UT",
            "Epicentre  42 41 33S 173 01 19E  Bearing S18W  Dist    9km  Depth   15km M  6.00",
            f"Number of points  {n}    Duration {(n - 1) * dt:.2f} sec",
            f"Instrument corrected data at {dt:.3f} sec intervals",
            "Band-pass filter transition bands are .10-.25 Hz and 24.50-25.50 Hz",
            f"Component {component}  Longitudinal Accelerometer Axis",
            f"Acceleration:  peak {peak:8.1f} mm/s/s at   1.00 sec     rms    100.0 mm/s/s",
            "Velocity:      peak     1.00 mm/s   at   1.00 sec     rms     0.10 mm/s",
            "Displacement:  peak    0.100 mm     at   1.00 sec     rms    0.010 mm"]
    ints = [2000, 1, 1, 0, 0, 0, 0, 0, 2000, 1] + [0] * 23 + [n, n, n, 0, 0, 0, 0]
    reals = [0.0] * 60
    reals[23], reals[24], reals[25] = (n - 1) * dt, 0.005, dt
    velocity = np.cumsum(acc_mm) * dt
    return (text + fortran_lines(ints, 10, "{:8d}") + fortran_lines(reals, 10, "{:8.4f}")
            + fortran_lines(acc_mm, 10, "{:8.1f}") + fortran_lines(velocity, 10, "{:8.2f}")
            + fortran_lines(np.zeros(n), 10, "{:8.3f}"))


def geonet(path, components, dt=DT):
    """GeoNet V2A: {name: acc [m/s^2]} as three blocks in mm/s^2 with one decimal."""
    lines, out = [], {}
    for name, acc in components.items():
        mm = np.array([float(f"{v:.1f}") for v in acc * 1000])
        lines += geonet_block(mm, dt, name)
        out[name] = mm * 1e-3
    path.write_text("\n".join(lines) + "\n")
    return out


def cosmos_channel(acc_cm, dt, chan):
    """One channel of a COSMOS V2 file (format v01.20): 13 text lines, 100 integers (10I8), 100
    reals (6F13.6: real 62 the time step in ms, 63 the length N dt, 64 the peak), a comment, the
    accelerations in cm/sec2 (8F12.5), the velocities, and the end-of-data line."""
    n = len(acc_cm)
    peak = acc_cm[np.argmax(np.abs(acc_cm))]
    text = ["Corrected acceleration    (Format v01.20 with 13 text lines) Src: written by the tests",
            "Record of Test Earthquake of Sat Jan 01, 2000 00:00 UTC", "Hypocenter: 34.0 -117.0 H= 12km Mw=6.0",
            "Origin: 2000/01/01 00:00:00 UTC", "Statn No: 01-00001 Code:XX-TEST  Test network  Test station",
            "Coords: 34.0460 -117.0350  Site geology:", f"Recorder: test      ( 2 Chns of   2 at Sta) Sensor: test",
            "Rcrd start time: 2000/01/01 00:00:05.000 UTC (Q=5) RcrdId: test",
            f"Sta Chan   {chan}: 90 deg (Rcrdr Chan  {chan}) Location: free field",
            f"Raw record length = {n * dt:.3f} sec, Uncor max = -999, at -999 sec.",
            f"Processed: 2000/01/02, TEST, Max = {peak:.3f} cm/sec2 at 1.000 sec",
            "Record filtered below  0.10 Hz (periods over 10.0 secs), and above 25.0 Hz",
            "Values used when parameter or data value is unknown/unspecified:   -999, -999.0"]
    ints = [2, 1, 4] + [-999] * 97
    reals = [-999.0] * 100
    reals[61], reals[62], reals[63], reals[64] = dt * 1000, n * dt, peak, 1.0
    velocity = np.cumsum(acc_cm) * dt
    return (text + [" 100 Integer-header values follow on  10 lines, Format= (10I8)"] + fortran_lines(ints, 10, "{:8d}")
            + [" 100 Real-header values follow on  17 lines, Format= (6F13.6)"] + fortran_lines(reals, 6, "{:13.6f}")
            + ['  1 Comment line(s) follow, each starting with a "|":', "| written by the tests"]
            + [f"   {n} acceleration pts, approx {round(n * dt)} secs, units=cm/sec2(04),Format=(8F12.5)"]
            + fortran_lines(acc_cm, 8, "{:12.5f}")
            + [f"   {n} velocity     pts, approx {round(n * dt)} secs, units=cm/sec (05),Format=(8F10.5)"]
            + fortran_lines(velocity, 8, "{:10.5f}") + [f"End-of-data for Chan  {chan} acceleration"])


def cosmos(path, channels, dt=DT):
    """COSMOS V2: a list of acc [m/s^2], one channel each, in cm/sec2 with 5 decimals."""
    lines, out = [], []
    for chan, acc in enumerate(channels, 1):
        cm = np.array([float(f"{v:.5f}") for v in acc * 100])
        lines += cosmos_channel(cm, dt, chan)
        out.append(cm * 0.01)
    path.write_text("\n".join(lines) + "\n")
    return out


def two_columns(path, acc, dt=DT):
    """The source: time [s] and acceleration [m/s^2], every digit."""
    rows = [f"{k * dt!r},{float(v)!r}" for k, v in enumerate(acc)]
    path.write_text("time,ag\n" + "\n".join(rows) + "\n")


def write(fmt, path, scale=1.0):
    """A file of format `fmt` at `path`: the samples [m/s^2] its default component reads to."""
    acc = scale * accelerations()
    if fmt == "esm":
        return esm(path, acc)
    if fmt == "knet":
        return knet(path, acc)
    if fmt == "geonet":
        return geonet(path, {"N28W": acc, "S74E": -0.5 * acc[::-1], "Up": 0.2 * acc})["N28W"]
    return cosmos(path, [acc, 0.7 * acc[::-1]])[0]
