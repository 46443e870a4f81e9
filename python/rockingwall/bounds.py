"""What the package accepts as physically meaningful, in one place: intensities (scale factors,
target PGA and Sa), the run's length, the ground acceleration's magnitude. Each check raises a
ValueError that names the value, what it is and the bound, so that nothing absurd is run silently
(a negative PGA flips the record; 1e300 g prints peaks of 1e258 mm; a 1e9-s run asks numpy for
hundreds of GiB)."""
import math

G = 9.81

# The largest ground acceleration accepted [g]. The largest ever recorded is about 4 g; 100 g is
# beyond any earthquake, but not a unit slip of 1000x (a record in cm/s^2 read as g is 100x).
MAX_AG_G = 100.0
# The longest run [s]: a record plus its free-vibration tail. The longest strong-motion records
# last minutes; 10 000 s (2.8 h) keeps the output grid (10 ms) at one million rows, 32 MB.
MAX_RUN_S = 1.0e4
# The longest output grid [rows], whatever the interval.
MAX_OUTPUT_ROWS = 2_000_000


def positive(value, what):
    """value as a float when it is finite and > 0 (a scale factor, a PGA, an Sa); else a
    ValueError naming `what`."""
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{what} {value!r}: not a number") from None
    if not (math.isfinite(v) and v > 0):
        raise ValueError(f"{what} {value!r}: must be a finite number > 0 (an intensity scales the record; it "
                         "cannot flip or erase it)")
    return v


def intensity_g(value, what):
    """A target PGA or Sa [g]: finite, > 0 and at most MAX_AG_G."""
    v = positive(value, what)
    if v > MAX_AG_G:
        raise ValueError(f"{what} {v:g} g: above {MAX_AG_G:g} g, the largest ground acceleration this program "
                         "accepts (the largest recorded is about 4 g)")
    return v


def peak_ag(peak_m_s2, name):
    """Refuse a record whose peak |ag| [m/s^2] exceeds MAX_AG_G (or is not finite)."""
    if not (math.isfinite(peak_m_s2) and peak_m_s2 <= MAX_AG_G * G):
        raise ValueError(f"{name}: peak |ag| = {peak_m_s2 / G:.3g} g is above {MAX_AG_G:g} g, the largest ground "
                         "acceleration this program accepts (the largest recorded is about 4 g): check the "
                         "record's units and the scale")


def run_length(t_start, t_end, what):
    """Refuse a run that does not go forward, or lasts longer than MAX_RUN_S."""
    if not (math.isfinite(t_start) and math.isfinite(t_end) and t_end > t_start):
        raise ValueError(f"{what}: the run from t = {t_start:g} s to t = {t_end:g} s does not go forward")
    if t_end - t_start > MAX_RUN_S:
        raise ValueError(f"{what}: a run of {t_end - t_start:g} s (t = {t_start:g} to {t_end:g} s) is longer than "
                         f"{MAX_RUN_S:g} s, the longest this program runs (records last minutes)")
