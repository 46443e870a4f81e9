"""Python binding of the scene solvers (in librwengine.so): the walls, diaphragms and floors of a
building as one model, with each wall's own event rules, run by the exact engine
(fmu_src/scene/rw_scene_exact.h: linear springs and the hinge laws of q alone) or by CVODES
(fmu_src/scene/rw_scene_run.h: every scene).

    from rockingwall import scene_engine
    spec = scene_engine.Spec(storeys=[scene_engine.StoreySpec(wall=params, md=200.0, kd=2e5, cd=632.0)])
    r = scene_engine.run(spec, t, ag)          # the exact engine where it covers the scene
    r.peak_s1[0], r.collapsed[0], r.max_residual, r.engine

Everything is SI and per metre of out-of-plane wall. The C structs are mirrored here; their sizes
are checked against the library's own (RW_SCENE_STRUCT_SIZES)."""
import ctypes
import dataclasses
import functools

import numpy as np

from . import engine
from .errors import RockingWallError

MAX_STOREYS = 5
# the spring laws by name and by the C code of building_physics.h (bilinear: elastoplastic with
# kinematic hardening; a storey takes every law but boucWenPinched)
SPRING_LAWS = {"linear": 0, "boucWen": 1, "boucWenPinched": 2, "bilinear": 3}
ERRORS = {1: "bad argument", 2: "bad scene", 3: "solver", 4: "Zeno", 5: "no memory", 6: "unsupported"}
ENGINES = ("exact", "cvode")

_D = ctypes.c_double
_D5 = _D * MAX_STOREYS


class _Spring(ctypes.Structure):
    _fields_ = [("k", _D), ("Fy", _D), ("alpha", _D)]


class _Building(ctypes.Structure):
    _fields_ = [("n_storeys", ctypes.c_int), ("storey_law", ctypes.c_int), ("diaphragm_law", ctypes.c_int),
                ("n_bw", _D), ("beta", _D), ("pinch_size", _D), ("pinch_width", _D), ("pinch_centre", _D),
                ("a0", _D), ("a1", _D), ("cs", _D5), ("cd", _D5), ("m", _D5), ("md", _D5),
                ("storey", _Spring * MAX_STOREYS), ("diaph", _Spring * MAX_STOREYS)]


@functools.cache
def _spec_struct():
    params = engine.params_struct()
    return type("SceneSpec", (ctypes.Structure,), {"_fields_": [
        ("n_storeys", ctypes.c_int), ("rigid_in_plane", ctypes.c_int), ("building", _Building),
        ("has_wall", ctypes.c_int * MAX_STOREYS), ("wall", params * MAX_STOREYS)]})


class _Record(ctypes.Structure):
    _fields_ = [("n", ctypes.c_size_t), ("t", ctypes.POINTER(_D)), ("ag", ctypes.POINTER(_D))]


class _Options(ctypes.Structure):
    _fields_ = [("t_end", _D), ("rtol", _D), ("n_out", ctypes.c_size_t), ("t_out", ctypes.POINTER(_D)),
                ("x0", ctypes.POINTER(_D)), ("bdf", ctypes.c_int)]


class _Result(ctypes.Structure):
    _fields_ = [("peak_s1", _D5), ("peak_s2", _D5), ("peak_diaphragm", _D5), ("peak_base_acc", _D5),
                ("collapsed", ctypes.c_int * MAX_STOREYS), ("collapse_reason", ctypes.c_int * MAX_STOREYS),
                ("t_collapse", _D5), ("impacts", ctypes.c_long * MAX_STOREYS),
                ("steps", ctypes.c_long), ("events", ctypes.c_long), ("t_reached", _D),
                ("work_ground", _D), ("work_damping", _D), ("event_losses", _D), ("energy_start", _D),
                ("energy_end", _D), ("max_residual", _D), ("max_work", _D), ("t_newton", _D),
                ("s1_out", ctypes.POINTER(_D)), ("s2_out", ctypes.POINTER(_D)),
                ("diaphragm_out", ctypes.POINTER(_D)), ("base_acc_out", ctypes.POINTER(_D)),
                ("tie_out", ctypes.POINTER(_D)),
                ("message", ctypes.c_char * 256)]


class SceneError(RockingWallError, RuntimeError):
    """The scene solver refused the scene or failed; the message says why."""

    def __init__(self, code, message):
        super().__init__(f"scene solver ({ERRORS.get(code, code)}): {message}")
        self.code = code


@dataclasses.dataclass(frozen=True)
class StoreySpec:
    """One storey: its wall (a dict of the wall's parameters by the FMU's names, support
    flexibleTop and Kd = the tie's stiffness; None for no wall), the diaphragm on top of it (mass
    md [kg/m], stiffness kd [N/m per m], dashpot cd [N s/m per m]; hysteretic yield force Fyd [N/m]
    and post-yield ratio alphad) and the in-plane walls of the storey (floor mass m, stiffness k,
    dashpot cs, Fy, alpha; unused when the scene's in-plane walls are rigid)."""
    wall: dict = None
    md: float = 0.0
    kd: float = 0.0
    cd: float = 0.0
    Fyd: float = 1.0
    alphad: float = 1.0
    m: float = 0.0
    k: float = 0.0
    cs: float = 0.0
    Fy: float = 1.0
    alpha: float = 1.0


@dataclasses.dataclass(frozen=True)
class Spec:
    """A scene: storeys bottom up, the in-plane walls rigid or not, the spring laws (one for all
    diaphragms, one for all storeys: SPRING_LAWS) with the Bouc-Wen shape (n, beta) and pinching,
    Rayleigh."""
    storeys: tuple
    rigid_in_plane: bool = True
    diaphragm_law: str = "linear"
    storey_law: str = "linear"
    n_bw: float = 1.0
    beta: float = 0.5
    pinch_size: float = 0.0
    pinch_width: float = 1.0
    pinch_centre: float = 0.0
    rayleigh_a0: float = 0.0
    rayleigh_a1: float = 0.0


@dataclasses.dataclass
class Result:
    """Per storey (index 0 = ground storey): peaks of the wall's s1, s2 relative to its own base
    [m], of the diaphragm relative to its floor [m] and of the wall base's absolute acceleration
    [m/s2]; collapse, its reason (1 past instability, 2 past the toppling limit) and time (NaN if
    standing); impacts. Energy balance terms [J/m] and the
    largest residual over the run; histories on the grid if one was asked for (HISTORIES: s1, s2,
    the diaphragm's deformation, the base's acceleration, the tie's force); which engine ran
    ("exact" or "cvode"); for CVODES, t_newton: when it went on with Newton iteration (the start with
    bdf; NaN if fixed-point iteration held throughout; None for the exact engine)."""
    peak_s1: np.ndarray
    peak_s2: np.ndarray
    peak_diaphragm: np.ndarray
    peak_base_acc: np.ndarray
    collapsed: np.ndarray
    collapse_reason: np.ndarray
    t_collapse: np.ndarray
    impacts: np.ndarray
    steps: int
    events: int
    t_reached: float
    work_ground: float
    work_damping: float
    event_losses: float
    energy_start: float
    energy_end: float
    max_residual: float
    max_work: float
    engine: str = "cvode"
    t_newton: float = None
    t: np.ndarray = None
    s1: np.ndarray = None
    s2: np.ndarray = None
    diaphragm: np.ndarray = None
    base_acc: np.ndarray = None
    tie: np.ndarray = None   # the tie's force on each diaphragm [N/m] (0 once the wall has collapsed)


@functools.cache
def _function(name="rw_scene_run"):
    lib = engine.library()
    fn = getattr(lib, name)
    fn.argtypes = [ctypes.POINTER(_spec_struct()), ctypes.POINTER(_Record), ctypes.POINTER(_Options),
                   ctypes.POINTER(_Result)]
    fn.restype = ctypes.c_int
    sizes = (ctypes.c_size_t * 3).in_dll(lib, "RW_SCENE_STRUCT_SIZES")
    mine = (ctypes.sizeof(_spec_struct()), ctypes.sizeof(_Result), ctypes.sizeof(_Building))
    if tuple(sizes) != mine:
        raise RuntimeError(f"the scene structs differ from the library's: sizes {tuple(sizes)} against {mine}")
    return fn


def _building(spec):
    b = _Building(n_storeys=len(spec.storeys), storey_law=SPRING_LAWS[spec.storey_law],
                  diaphragm_law=SPRING_LAWS[spec.diaphragm_law], n_bw=spec.n_bw, beta=spec.beta,
                  pinch_size=spec.pinch_size, pinch_width=spec.pinch_width, pinch_centre=spec.pinch_centre,
                  a0=spec.rayleigh_a0, a1=spec.rayleigh_a1)
    for i, s in enumerate(spec.storeys):
        b.m[i], b.md[i], b.cs[i], b.cd[i] = s.m, s.md, s.cs, s.cd
        b.storey[i] = _Spring(s.k, s.Fy, s.alpha)
        b.diaph[i] = _Spring(s.kd, s.Fyd, s.alphad)
    return b


def c_spec(spec):
    """The C struct of a Spec (ValueError for more storeys than the solver holds)."""
    if not 1 <= len(spec.storeys) <= MAX_STOREYS:
        raise ValueError(f"a scene has 1 to {MAX_STOREYS} storeys, not {len(spec.storeys)}")
    s = _spec_struct()(n_storeys=len(spec.storeys), rigid_in_plane=int(spec.rigid_in_plane),
                       building=_building(spec))
    for i, storey in enumerate(spec.storeys):
        if storey.wall is not None:
            s.has_wall[i] = 1
            s.wall[i] = engine.params(**storey.wall)
    return s


def _ptr(a):
    return a.ctypes.data_as(ctypes.POINTER(_D)) if a is not None else None


HISTORIES = ("s1", "s2", "diaphragm", "base_acc", "tie")


def _histories(n_out, keep):
    return [np.full((n_out, MAX_STOREYS), np.nan) if n_out and name in keep else None for name in HISTORIES]


@functools.cache
def _covers_function():
    fn = engine.library().rw_scene_exact_covers
    fn.argtypes = [ctypes.POINTER(_spec_struct()), ctypes.c_char_p, ctypes.c_size_t]
    fn.restype = ctypes.c_int
    return fn


def exact_covers(spec):
    """(True, "") if the exact engine covers the scene, else (False, why)."""
    msg = ctypes.create_string_buffer(256)
    code = _covers_function()(ctypes.byref(c_spec(spec)), msg, 256)
    return code == 0, msg.value.decode(errors="replace")


def state_size(spec):
    """The length of a scene's state vector: 4 wall states per storey, then 8 per floor."""
    return 12 * len(spec.storeys)


def engine_for(spec, engine=None):
    """The engine a run of the scene takes: `engine` ("exact" or "cvode") as given, or for None the
    exact engine where it covers the scene and CVODES elsewhere; ValueError for a name it does not
    know."""
    if engine is None:
        engine = "exact" if exact_covers(spec)[0] else "cvode"
    if engine not in ENGINES:
        raise ValueError(f"engine must be one of {ENGINES}, not {engine!r}")
    return engine


def run(spec, t, ag, t_end=None, rtol=1e-8, t_out=None, engine=None, x0=None, histories=HISTORIES, bdf=False):
    """One run of the scene from rest (or the start state x0, state_size(spec) values) under the
    record (t [s], ag [m/s2], linear between samples, the ends held), to t_end (default: the
    record's end). engine: "exact", "cvode", or None for the exact engine where it covers the
    scene and CVODES (at rtol) elsewhere; the result says which ran. Raises SceneError, or
    ValueError for an engine name it does not know. histories: which of HISTORIES to keep on the
    grid t_out (the others are None). bdf: CVODES takes BDF with Newton throughout (by default
    Adams, with fixed-point iteration and with Newton from where the scene proves stiff)."""
    engine = engine_for(spec, engine)
    t = np.ascontiguousarray(t, dtype=np.float64)
    ag = np.ascontiguousarray(ag, dtype=np.float64)
    t_out = None if t_out is None else np.ascontiguousarray(t_out, dtype=np.float64)
    n_out = 0 if t_out is None else t_out.size
    n = len(spec.storeys)
    start = None
    if x0 is not None:
        x0 = np.asarray(x0, dtype=np.float64).ravel()
        if x0.size != state_size(spec):
            raise ValueError(f"x0 has {x0.size} values; this scene has {state_size(spec)} states")
        start = np.zeros(MAX_STOREYS * 12)
        start[:x0.size] = x0
    hist = _histories(n_out, histories)
    res = _Result()
    res.s1_out, res.s2_out, res.diaphragm_out, res.base_acc_out, res.tie_out = (_ptr(h) for h in hist)
    opt = _Options(float(t[-1]) if t_end is None else float(t_end), float(rtol), n_out, _ptr(t_out), _ptr(start),
                   int(bool(bdf)))
    c = c_spec(spec)
    fn = _function("rw_scene_run_exact" if engine == "exact" else "rw_scene_run")
    code = fn(ctypes.byref(c), ctypes.byref(_Record(t.size, _ptr(t), _ptr(ag))), ctypes.byref(opt), ctypes.byref(res))
    if code:
        raise SceneError(code, res.message.decode(errors="replace"))
    per = {k: np.array(getattr(res, k)[:n]) for k in
           ("peak_s1", "peak_s2", "peak_diaphragm", "peak_base_acc", "t_collapse", "impacts", "collapse_reason")}
    s1, s2, dia, acc, tie = (h[:, :n] if h is not None else None for h in hist)
    return Result(**per, collapsed=np.array(res.collapsed[:n], dtype=bool), steps=res.steps, events=res.events,
                  t_reached=res.t_reached, work_ground=res.work_ground, work_damping=res.work_damping,
                  event_losses=res.event_losses, energy_start=res.energy_start, energy_end=res.energy_end,
                  max_residual=res.max_residual, max_work=res.max_work, engine=engine,
                  t_newton=res.t_newton if engine == "cvode" else None, t=t_out, s1=s1, s2=s2, diaphragm=dia, base_acc=acc,
                  tie=tie)
