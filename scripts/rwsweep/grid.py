"""The run grid of a sweep: walls x models x hinge laws x K_d x records x intensities, from a TOML
file and/or command-line flags, expanded into one RunSpec per run with a stable run_id (the key
that lets an interrupted sweep resume)."""
import dataclasses
import itertools
import math
import sys
import tomllib


MODELS = {"parapet": 1, "simplySupported": 2, "flexibleTop": 3}
HINGE_LAWS = {"rigid": 1, "semiRigidPaper": 2, "semiRigidHinge": 3, "dohertyHinge": 4}

# The defaults of a grid; a TOML file's [grid] table and the flags replace them key by key.
DEFAULTS = dict(walls=[1], models=["flexibleTop"], hinge_laws=["dohertyHinge"], kd_kN=[50.0],
                scales=[1.0], pga_g=[], er=0.86, tail=5.0, rtol=1e-6, suite="fema", records_dir="",
                records=[])


@dataclasses.dataclass(frozen=True)
class RunSpec:
    run_id: str
    wall: int
    model: str
    hinge_law: str
    kd_kN: float        # NaN for models without the top spring
    record: str
    record_path: str
    record_pga_g: float
    scale: float        # factor on the record as given
    pga_g: float        # scale * record PGA: the intensity measure
    stop_time: float
    sets: tuple         # (("NAME", "VALUE"), ...) for fmi2sim --set
    error: str = ""     # the record could not be planned: reported without running


def load_config(path):
    """The [grid] table of a TOML file (an empty dict without a file)."""
    if not path:
        return {}
    with open(path, "rb") as f:
        cfg = tomllib.load(f)
    unknown = set(cfg.get("grid", {})) - set(DEFAULTS)
    if unknown:
        raise ValueError(f"{path}: unknown [grid] keys {sorted(unknown)}; known: {sorted(DEFAULTS)}")
    return cfg.get("grid", {})


def merge(config, flags):
    """DEFAULTS, then the file's values, then the flags that were given (not None)."""
    out = dict(DEFAULTS)
    out.update(config)
    out.update({k: v for k, v in flags.items() if v is not None and k in DEFAULTS})
    bad = [m for m in out["models"] if m not in MODELS]
    if bad:
        raise ValueError(f"unknown model(s) {bad}; known: {list(MODELS)}")
    bad = [h for h in out["hinge_laws"] if h not in HINGE_LAWS]
    if bad:
        raise ValueError(f"unknown hinge law(s) {bad}; known: {list(HINGE_LAWS)}")
    return out


def wall_parameters(wall):
    """b, h, W, psi of the paper's walls 1-3 (reference/rwref/params.py is the one table)."""
    from rwref.params import WALLS
    if wall not in WALLS:
        raise ValueError(f"wall {wall}: the paper's walls are {sorted(WALLS)}")
    return WALLS[wall]


def _fmt(x):
    return f"{x:.6g}"


def expand(grid, suite):
    """All RunSpecs of the grid over a record suite. Models without the top spring (parapet,
    simplySupported) do not depend on K_d, so they get one run per record and intensity, not one
    per K_d. With pga_g given, each record is scaled to each target PGA; else by each factor."""
    specs = []
    for wall, model, law in itertools.product(grid["walls"], grid["models"], grid["hinge_laws"]):
        geometry = wall_parameters(wall)
        kds = [float(k) for k in grid["kd_kN"]] if model == "flexibleTop" else [math.nan]
        if model == "parapet" and law != grid["hinge_laws"][0]:
            continue  # a parapet ignores the hinge law: one set of runs is enough
        for kd, rec in itertools.product(kds, suite):
            if grid["pga_g"]:
                pairs = [(p / rec.pga_g if rec.pga_g > 0 else math.nan, float(p)) for p in grid["pga_g"]]
                tag = "pga"
            else:
                pairs = [(float(s), float(s) * rec.pga_g) for s in grid["scales"]]
                tag = "x"
            for scale, pga in pairs:
                sets = dict(h=geometry["h"], b=geometry["b"], W=geometry["W"], psi=geometry["psi"],
                            er=grid["er"], support=MODELS[model], hingeLaw=HINGE_LAWS[law])
                if not math.isnan(kd):
                    sets["Kd"] = kd * 1e3  # kN/m per m -> N/m per m
                level = pga if tag == "pga" else scale
                # everything that changes the result is in the id, so a resumed sweep never reuses a
                # run made with other settings
                run_id = (f"w{wall}|{model}|{law}|kd{_fmt(kd)}|{rec.name}|{tag}{_fmt(level)}"
                          f"|er{_fmt(grid['er'])}|rtol{_fmt(grid['rtol'])}|tail{_fmt(grid['tail'])}")
                specs.append(RunSpec(run_id, wall, model, law, kd, rec.name, rec.path, rec.pga_g, scale, pga,
                                     rec.duration + float(grid["tail"]),
                                     tuple((k, repr(float(v)) if isinstance(v, float) else str(v)) for k, v in sets.items()),
                                     rec.error))
    ids = [s.run_id for s in specs]
    if len(set(ids)) != len(ids):
        sys.exit("the grid has duplicate runs (a value given twice, or two records with one name)")
    return specs
