"""RockingWall: does this unreinforced-masonry wall fall out of plane, and how does the
flexibility of the floor diaphragm change that?

    import rockingwall as rw
    wall = rw.Wall.make(b="230 mm", h=3.2, W="14.08 kN/m", psi=0.2, Kd="30 kN/m per m")
    record = rw.read_record("elcentro").to_pga(0.35)
    result = rw.simulate(wall, record)          # the exact engine, in this process
    result.peak_s1, result.peak_s2              # m

Units are SI throughout (m, N per m of wall, N/m per m of wall, m/s^2); values given as strings
may carry their unit. `rockingwall info` lists every parameter with its unit, default and range.
"""
from .api import Result, simulate
from .names import HINGE_LAWS, PAPER_WALLS, SUPPORTS
from .records import Record, RecordError, el_centro, gaussian, read_at2, read_csv
from .records import load as read_record
from .wall import PlausibilityWarning, Wall

__all__ = ["Wall", "Record", "Result", "simulate", "read_record", "read_at2", "read_csv", "el_centro", "gaussian",
           "RecordError", "PlausibilityWarning", "SUPPORTS", "HINGE_LAWS", "PAPER_WALLS"]
__version__ = "0.2.0"
