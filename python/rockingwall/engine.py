"""Python binding of the exact event-driven engine (fmu_src/engine/rw_engine.h, librwengine.so).

    from rockingwall import engine
    r = engine.run(t, ag, t_end=80.0, support=3, hingeLaw=4, Kd=5e4)
    r.peak_s1, r.peak_s2, r.collapsed, r.t_collapse, r.impacts

`t`, `ag` (and optionally `u_top`) are the samples of a piecewise-linear record (unequal spacing
allowed, ends held). Parameters are the FMU's, by name; the struct layout, defaults, units and
ranges are read from the library's own parameter table (RW_PARAM_INFO, generated from
fmu_src/wall/rw_parameters.h), so they cannot drift from the C side.
"""
import ctypes
import dataclasses
import functools
import math

import numpy as np

from . import paths
from .errors import RockingWallError

NX = 4
ERRORS = {1: "bad argument", 2: "bad parameters", 3: "unsupported", 4: "Zeno", 5: "no memory"}
UNSUPPORTED = 3


class _ParamInfo(ctypes.Structure):
    _fields_ = [("name", ctypes.c_char_p), ("vr", ctypes.c_uint), ("is_integer", ctypes.c_int),
                ("unit", ctypes.c_char_p), ("default", ctypes.c_double), ("lo", ctypes.c_double),
                ("hi", ctypes.c_double), ("offset", ctypes.c_size_t), ("description", ctypes.c_char_p)]


@dataclasses.dataclass(frozen=True)
class Parameter:
    """One row of the parameter table: unit is the SI unit values are given in."""
    name: str
    vr: int
    is_integer: bool
    unit: str
    default: float
    lo: float
    hi: float
    offset: int
    description: str

    def check(self, value):
        """ValueError naming the parameter, the value and its closed range, and the unit slip that
        would put it in range (3600 for a height: mm; 86 for a ratio: %)."""
        ok = math.isfinite(value) and self.lo <= value <= self.hi and (not self.is_integer or value == int(value))
        if not ok:
            kind = "an integer in" if self.is_integer else "in"
            unit = f" {self.unit}" if self.unit not in ("", "1") else ""
            ratio = " (a ratio)" if self.unit == "1" else ""
            raise ValueError(f"{self.name} = {value:g}{unit}: must be {kind} [{self.lo:g}, {self.hi:g}]{ratio}"
                             f"{self._slip(value)}")

    def _slip(self, value):
        factor, written = UNIT_SLIPS.get(self.unit, (None, None))
        if factor is None or not math.isfinite(value) or not self.lo <= value * factor <= self.hi:
            return ""
        return f"; did you mean {value:g} {written} (write '{value:g}{written}')?"


# a number given in a unit the parameter's SI unit is not, which lands in range once converted:
# {SI unit: (factor to it, the unit the number was likely meant in)}
UNIT_SLIPS = {"m": (1e-3, "mm"), "N/m": (1e3, "kN/m"), "1": (1e-2, "%")}


@functools.cache
def parameter_table():
    """{name: Parameter} in the order of the C table."""
    lib = library()
    n = ctypes.c_size_t.in_dll(lib, "RW_NUMBER_OF_PARAMETERS").value
    rows = (_ParamInfo * n).in_dll(lib, "RW_PARAM_INFO")
    return {r.name.decode(): Parameter(r.name.decode(), r.vr, bool(r.is_integer), r.unit.decode(), r.default,
                                       r.lo, r.hi, r.offset, r.description.decode()) for r in rows}


@functools.cache
def params_struct():
    """The ctypes twin of struct rw_params, checked field by field against the C offsets."""
    table = parameter_table()
    cls = type("Params", (ctypes.Structure,), {"_fields_": [
        (name, ctypes.c_int if row.is_integer else ctypes.c_double) for name, row in table.items()]})
    for name, row in table.items():
        if getattr(cls, name).offset != row.offset:
            raise RuntimeError(f"rw_params layout differs from the library at {name}")
    return cls


class _Record(ctypes.Structure):
    _fields_ = [("n", ctypes.c_size_t), ("t", ctypes.POINTER(ctypes.c_double)),
                ("ag", ctypes.POINTER(ctypes.c_double)), ("u_top", ctypes.POINTER(ctypes.c_double))]


class _Options(ctypes.Structure):
    _fields_ = [("t_start", ctypes.c_double), ("t_end", ctypes.c_double), ("x0", ctypes.POINTER(ctypes.c_double)),
                ("n_out", ctypes.c_size_t), ("t_out", ctypes.POINTER(ctypes.c_double)),
                ("max_events_per_instant", ctypes.c_int)]


class _Result(ctypes.Structure):
    _fields_ = [("peak_s1", ctypes.c_double), ("peak_s2", ctypes.c_double), ("collapsed", ctypes.c_int),
                ("collapse_reason", ctypes.c_int), ("t_collapse", ctypes.c_double), ("impacts", ctypes.c_long),
                ("events", ctypes.c_long), ("steps", ctypes.c_long), ("t_reached", ctypes.c_double),
                ("x_end", ctypes.c_double * NX), ("x_out", ctypes.POINTER(ctypes.c_double)),
                ("s1_out", ctypes.POINTER(ctypes.c_double)), ("s2_out", ctypes.POINTER(ctypes.c_double)),
                ("impact_t", ctypes.POINTER(ctypes.c_double)), ("impact_energy", ctypes.POINTER(ctypes.c_double)),
                ("impact_cap", ctypes.c_size_t), ("message", ctypes.c_char * 256)]


# rw_engine.h's RW_ENGINE_PARAPET_MAX_B_OVER_H: the parapet runs on the engine in Housner's
# small-rotation form up to this b/h, where its peaks stay within 1 % of the nonlinear block's
PARAPET_MAX_B_OVER_H = 0.1


def covers(params):
    """True where the engine solves the wall: every support but a parapet stockier than
    PARAPET_MAX_B_OVER_H, which stays on CVODE (fmi2sim)."""
    return int(params["support"]) != 1 or float(params["b"]) <= PARAPET_MAX_B_OVER_H * float(params["h"])


class EngineError(RockingWallError, RuntimeError):
    """The engine refused or could not finish a run: its code and message."""

    def __init__(self, code, message):
        super().__init__(f"rw_engine ({ERRORS.get(code, code)}): {message}")
        self.code = code
        self.detail = message


class Result:
    """Peaks, collapse, counters, and the time history on the grid if one was asked for."""

    def __init__(self, r, t_out, x_out, s1, s2, imp_t, imp_e):
        self.peak_s1, self.peak_s2 = r.peak_s1, r.peak_s2
        self.collapsed, self.collapse_reason = bool(r.collapsed), r.collapse_reason
        self.t_collapse = r.t_collapse if r.collapsed else math.nan
        self.impacts, self.events, self.steps = r.impacts, r.events, r.steps
        self.t_reached, self.x_end = r.t_reached, np.array(r.x_end[:])
        self.t, self.x, self.s1, self.s2 = t_out, x_out, s1, s2
        n = min(r.impacts, imp_t.size) if imp_t is not None else 0
        self.impact_t = imp_t[:n] if imp_t is not None else None
        self.impact_energy = imp_e[:n] if imp_t is not None else None

    def __repr__(self):
        return (f"Result(peak_s1={self.peak_s1:.6g}, peak_s2={self.peak_s2:.6g}, collapsed={self.collapsed}, "
                f"t_collapse={self.t_collapse:.6g}, impacts={self.impacts}, events={self.events})")


_lib = None


def library():
    global _lib
    if _lib is None:
        lib = ctypes.CDLL(str(paths.engine_library()))
        lib.rw_engine_run.argtypes = [ctypes.c_void_p, ctypes.POINTER(_Record), ctypes.POINTER(_Options),
                                      ctypes.POINTER(_Result)]
        lib.rw_engine_run.restype = ctypes.c_int
        _lib = lib
    return _lib


def params(**values):
    """The C parameter struct: the table's defaults, then `values` by name."""
    p = params_struct()()
    library().rw_params_default(ctypes.byref(p))
    names = {name for name, _ in p._fields_}
    for k, v in values.items():
        if k not in names:
            raise KeyError(f"unknown parameter {k!r} (known: {', '.join(sorted(names))})")
        setattr(p, k, int(v) if parameter_table()[k].is_integer else float(v))
    return p


class _Statics(ctypes.Structure):
    _fields_ = [("Du", ctypes.c_double * 2), ("Fr", ctypes.c_double * 2), ("cap_b", ctypes.c_double * 2),
                ("cap_m", ctypes.c_double * 2)]


def statics(**values):
    """The wall's statics from the C model (rw_wall_statics): {"Delta_u", "F_r"} per direction of
    the mid-height's motion and {"cap_b", "cap_m"} per side of a hinge, each a dict {+1: .., -1: ..}
    (+1 toward +x, the inner face). ValueError with the C message when the parameters break a
    rule (docs/model.md "Parameters")."""
    lib = library()
    fn = lib.rw_wall_statics
    fn.argtypes = [ctypes.c_void_p, ctypes.POINTER(_Statics), ctypes.c_char_p, ctypes.c_size_t]
    fn.restype = ctypes.c_int
    p, out, msg = params(**values), _Statics(), ctypes.create_string_buffer(512)
    if fn(ctypes.byref(p), ctypes.byref(out), msg, len(msg)):
        raise ValueError(msg.value.decode(errors="replace"))
    return {name: {1: getattr(out, field)[0], -1: getattr(out, field)[1]}
            for name, field in (("Delta_u", "Du"), ("F_r", "Fr"), ("cap_b", "cap_b"), ("cap_m", "cap_m"))}


def delta_u(**values):
    """Delta_u [m] of a wall (statics): the smaller of its two directions' (they differ under an
    eccentric top load); b (1 + 0.75 psi)/(1 + psi) for the paper's walls (Table 5.1). ValueError
    as statics."""
    return min(statics(**values)["Delta_u"].values())


def tie_held(**values):
    """Whether the Model Exchange FMU holds this wall's tie rigid when it starts at rest with its far
    end still (rw_tie_held_from_rest; docs/model.md "A stiff tie held rigid"): this engine never
    does, and solves the tie's mode exactly instead."""
    fn = library().rw_tie_held_from_rest
    fn.argtypes = [ctypes.c_void_p]
    fn.restype = ctypes.c_int
    return bool(fn(ctypes.byref(params(**values))))


def peak_F_top(params, peak_s2):
    """Peak |F_top| [N/m] of a wall on its own (u_top = 0): F_top = Kd (s2 - u_top), so Kd times
    the peak of s2 with the spring (support 3), else 0."""
    return float(params["Kd"]) * peak_s2 if int(params["support"]) == 3 else 0.0


def _ptr(a):
    return a.ctypes.data_as(ctypes.POINTER(ctypes.c_double)) if a is not None else None


def _array(a, n=None):
    if a is None:
        return None
    a = np.ascontiguousarray(a, dtype=np.float64)
    if a.ndim != 1 or (n is not None and a.size != n):
        raise ValueError("record arrays must be 1-D and of the same length as t")
    return a


def run(t, ag, u_top=None, t_end=None, t_start=0.0, x0=None, t_out=None, max_events_per_instant=0, impact_log=0,
        **param_values):
    """One run of the engine. Raises EngineError for bad input (the C API's code and message).
    impact_log > 0 keeps the time and the energy before each of the first impact_log impacts."""
    t = _array(t)
    ag, u_top = _array(ag, t.size), _array(u_top, t.size)
    t_end = float(t[-1]) if t_end is None else float(t_end)
    x0 = _array(x0, NX)
    t_out = _array(t_out)
    n_out = 0 if t_out is None else t_out.size
    x_out = np.full((n_out, NX), np.nan) if n_out else None
    s1 = np.full(n_out, np.nan) if n_out else None
    s2 = np.full(n_out, np.nan) if n_out else None
    p = params(**param_values)
    rec = _Record(t.size, _ptr(t), _ptr(ag), _ptr(u_top))
    opt = _Options(float(t_start), t_end, _ptr(x0), n_out, _ptr(t_out), int(max_events_per_instant))
    res = _Result()
    res.x_out, res.s1_out, res.s2_out = _ptr(x_out), _ptr(s1), _ptr(s2)
    imp_t = np.full(impact_log, np.nan) if impact_log > 0 else None
    imp_e = np.full(impact_log, np.nan) if impact_log > 0 else None
    res.impact_t, res.impact_energy, res.impact_cap = _ptr(imp_t), _ptr(imp_e), max(0, int(impact_log))
    code = library().rw_engine_run(ctypes.byref(p), ctypes.byref(rec), ctypes.byref(opt), ctypes.byref(res))
    if code:
        raise EngineError(code, res.message.decode(errors="replace"))
    return Result(res, t_out, x_out, s1, s2, imp_t, imp_e)


# ---- sweeps: many runs over one record in one C call (rw_engine_run_many) ------------------------
class _Batch(ctypes.Structure):
    _fields_ = [("peak_s1", ctypes.POINTER(ctypes.c_double)), ("peak_s2", ctypes.POINTER(ctypes.c_double)),
                ("collapsed", ctypes.POINTER(ctypes.c_int)), ("t_collapse", ctypes.POINTER(ctypes.c_double)),
                ("impacts", ctypes.POINTER(ctypes.c_long)), ("code", ctypes.POINTER(ctypes.c_int))]


def _run_many_function():
    lib = library()
    fn = lib.rw_engine_run_many
    if fn.restype is not ctypes.c_int:
        fn.argtypes = [ctypes.c_size_t, ctypes.c_void_p, ctypes.c_int, ctypes.POINTER(ctypes.c_double),
                       ctypes.POINTER(_Record), ctypes.POINTER(_Options), ctypes.POINTER(_Batch), ctypes.c_char_p,
                       ctypes.c_size_t]
        fn.restype = ctypes.c_int
    return fn


def run_many(t, ag, scale=None, u_top=None, t_end=None, t_start=0.0, max_events_per_instant=0, **param_values):
    """N runs over one record in one C call (no Python work between runs; ctypes releases the GIL,
    so threads can run calls side by side). Each parameter value and `scale` (the factor on ag) is
    a scalar or an array of length N (N: the longest given; scale None = 1). Returns a dict of
    arrays of length N: peak_s1, peak_s2, collapsed (bool), t_collapse (NaN if standing),
    impacts, code (0 ok, else the run's error code as in run(); its peaks are NaN unless Zeno).
    A bad parameter set makes only its own run fail (code 2), as a sweep wants."""
    t = _array(t)
    ag, u_top = _array(ag, t.size), _array(u_top, t.size)
    t_end = float(t[-1]) if t_end is None else float(t_end)
    columns = {k: np.atleast_1d(np.asarray(v)) for k, v in param_values.items()}
    scale_arr = None if scale is None else np.atleast_1d(np.asarray(scale, dtype=np.float64))
    sizes = {a.size for a in list(columns.values()) + ([scale_arr] if scale_arr is not None else []) if a.size != 1}
    if len(sizes) > 1:
        raise ValueError(f"run_many: array arguments of different lengths {sorted(sizes)}")
    n = sizes.pop() if sizes else 1
    if scale_arr is not None:
        scale_arr = np.ascontiguousarray(np.broadcast_to(scale_arr, (n,)), dtype=np.float64)
    base = params(**{k: v.item() for k, v in columns.items() if v.size == 1})
    varying = {k: v for k, v in columns.items() if v.size != 1}
    sets = (type(base) * (n if varying else 1))()
    for i in range(len(sets)):
        ctypes.memmove(ctypes.byref(sets, i * ctypes.sizeof(base)), ctypes.byref(base), ctypes.sizeof(base))
        for k, v in varying.items():
            setattr(sets[i], k, type(getattr(base, k))(v[i].item()))
    out = {"peak_s1": np.full(n, np.nan), "peak_s2": np.full(n, np.nan), "collapsed": np.zeros(n, np.intc),
           "t_collapse": np.full(n, np.nan), "impacts": np.zeros(n, np.int_), "code": np.zeros(n, np.intc)}
    batch = _Batch(*(out[k].ctypes.data_as(ctypes.POINTER(c)) for k, c in
                     (("peak_s1", ctypes.c_double), ("peak_s2", ctypes.c_double), ("collapsed", ctypes.c_int),
                      ("t_collapse", ctypes.c_double), ("impacts", ctypes.c_long), ("code", ctypes.c_int))))
    rec = _Record(t.size, _ptr(t), _ptr(ag), _ptr(u_top))
    opt = _Options(float(t_start), t_end, None, 0, None, int(max_events_per_instant))
    msg = ctypes.create_string_buffer(256)
    code = _run_many_function()(n, ctypes.cast(sets, ctypes.c_void_p), int(bool(varying)), _ptr(scale_arr),
                                ctypes.byref(rec), ctypes.byref(opt), ctypes.byref(batch), msg, len(msg))
    if code:
        raise EngineError(code, msg.value.decode(errors="replace"))
    out["collapsed"] = out["collapsed"].astype(bool)
    return out
