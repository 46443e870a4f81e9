"""The run grid of a sweep: walls x models x hinge laws x K_d x records x intensities, from a TOML
file and/or command-line flags, expanded into one RunSpec per run with a stable run_id (the key
that lets an interrupted sweep resume)."""
import itertools
import math
import tomllib


from .. import scenes
from ..names import HINGE_LAWS, PAPER_WALLS, SUPPORTS as MODELS, paper_wall
from . import suites
from .run_spec import RunSpec

WALL_KEYS = ("b", "h", "W", "psi")  # what a [walls.NAME] table gives (SI units, or strings with units)

# The defaults of a grid; a TOML file's [grid] table and the flags replace them key by key.
DEFAULTS = dict(walls=[1], models=["flexibleTop"], hinge_laws=["dohertyHinge"], kd_kN=[50.0],
                scales=[1.0], pga_g=[], er=0.86, tail=5.0, rtol=1e-6, suite="fema", records_dir="",
                records=[], building="")


def load_config(path):
    """The [grid] table of a TOML file (an empty dict without a file), with the walls the file
    defines ([walls.NAME] tables of b, h, W, psi) under the key 'wall_table'."""
    if not path:
        return {}
    try:
        with open(path, "rb") as f:
            cfg = tomllib.load(f)
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        raise ValueError(f"{path}: not a valid TOML file: {exc}") from None
    unknown = set(cfg.get("grid", {})) - set(DEFAULTS)
    if unknown:
        raise ValueError(f"{path}: unknown [grid] keys {sorted(unknown)}; known: {sorted(DEFAULTS)}")
    out = dict(cfg.get("grid", {}))
    out["wall_table"] = {name: _wall_table(path, name, t) for name, t in cfg.get("walls", {}).items()}
    return out


def _wall_table(path, name, table):
    from ..units import parse
    if not isinstance(table, dict):
        raise ValueError(f"{path}: [walls.{name}] must be a table of {', '.join(WALL_KEYS)}")
    missing, extra = set(WALL_KEYS) - set(table), set(table) - set(WALL_KEYS)
    if missing or extra:
        raise ValueError(f"{path}: [walls.{name}] needs exactly {', '.join(WALL_KEYS)}"
                         + (f"; missing {sorted(missing)}" if missing else "") + (f"; unknown {sorted(extra)}" if extra else ""))
    units = {"b": "m", "h": "m", "W": "N/m", "psi": "1"}
    return {k: parse(v, units[k], f"[walls.{name}] {k}") for k, v in table.items()}


def merge(config, flags):
    """DEFAULTS, then the file's values, then the flags that were given (not None)."""
    out = dict(DEFAULTS)
    out.update({k: v for k, v in config.items() if k != "wall_table"})
    out["wall_table"] = dict(config.get("wall_table", {}))
    out.update({k: v for k, v in flags.items() if v is not None and k in DEFAULTS})
    check(out)
    bad = [m for m in out["models"] if m not in MODELS]
    if bad:
        raise ValueError(f"unknown model(s) {bad}; known: {list(MODELS)}")
    bad = [h for h in out["hinge_laws"] if h not in HINGE_LAWS]
    if bad:
        raise ValueError(f"unknown hinge law(s) {bad}; known: {list(HINGE_LAWS)}")
    return out


# The meaningful range of each number of a grid: (low, high, whether low itself is allowed).
RANGES = dict(kd_kN=(0.0, 1e9, False), scales=(0.0, 100.0, False), pga_g=(0.0, 10.0, False),
              er=(0.0, 1.0, True), tail=(0.0, 3600.0, True), rtol=(1e-12, 1e-2, True))
_LISTS = ("walls", "models", "hinge_laws", "kd_kN", "scales", "pga_g", "records")


def in_range(name, value, low, high, low_ok=True):
    """value as a float, or ValueError naming the option and its range."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ValueError(f"{name} = {value!r} is not a number")
    v = float(value)
    inside = (v >= low if low_ok else v > low) and v <= high
    if not (math.isfinite(v) and inside):
        raise ValueError(f"{name} = {value!r} is outside {'[' if low_ok else '('}{low:g}, {high:g}]")
    return v


def check(cfg):
    """Refuse a grid whose values are of the wrong type or outside their meaningful range."""
    for key in _LISTS:
        if not isinstance(cfg[key], list):
            raise ValueError(f"{key} = {cfg[key]!r} must be a list")
    for key in ("walls", "models", "hinge_laws", "kd_kN"):
        if not cfg[key]:
            raise ValueError(f"{key}: give at least one value")
    if not cfg["pga_g"] and not cfg["scales"]:
        raise ValueError("give intensities: scales or pga_g")
    for key, (low, high, low_ok) in RANGES.items():
        for v in cfg[key] if isinstance(cfg[key], list) else [cfg[key]]:
            in_range(key, v, low, high, low_ok)
    for w in cfg["walls"]:
        wall_parameters(w, cfg["wall_table"])
    if not isinstance(cfg["suite"], str) or not cfg["suite"]:
        raise ValueError(f"suite = {cfg['suite']!r}: 'fema' or a folder of .AT2 files")


def wall_parameters(wall, table=None):
    """b, h, W, psi of a wall: one the TOML file defines ([walls.NAME]) or a preset of the paper
    (1, 2, 3 or paper1, paper2, paper3)."""
    table = table or {}
    if isinstance(wall, bool) or not isinstance(wall, (int, str)):
        raise ValueError(f"wall {wall!r}: give a preset ({', '.join(PAPER_WALLS)}) or the name of a [walls.NAME] table")
    if str(wall) in table:
        return table[str(wall)]
    try:
        return paper_wall(wall)
    except ValueError:
        known = list(PAPER_WALLS) + list(table)
        raise ValueError(f"wall {wall!r}: not a preset nor a wall of the file; known: {', '.join(known)}") from None


def _fmt(x):
    return f"{x:.6g}"


def expand(grid, suite):
    """All RunSpecs of the grid over a record suite. Models without the top spring (parapet,
    simplySupported) do not depend on K_d, so they get one run per record and intensity, not one
    per K_d. With pga_g given, each record is scaled to each target PGA; else by each factor."""
    specs = []
    for wall, model, law in itertools.product(grid["walls"], grid["models"], grid["hinge_laws"]):
        geometry = wall_parameters(wall, grid.get("wall_table"))
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
                                     rec.error, rec.sha256))
    ids = [s.run_id for s in specs]
    if len(set(ids)) != len(ids):
        raise ValueError("the grid has duplicate runs (a value given twice, or two records with one name)")
    return specs


def plan(config_path, flags):
    """(merged grid, suite of records, RunSpecs) from a TOML file (or None) and the command's
    flags ({key of DEFAULTS: value}; flags win). With a building file (`building`), the runs are
    its storeys' (rockingwall.sweep.building_runs)."""
    cfg = merge(load_config(config_path), flags)
    suite = suites.load(cfg["suite"], cfg["records"])
    if cfg["building"]:
        from . import building_runs
        return cfg, suite, building_runs.expand(cfg, suite)
    return cfg, suite, expand(cfg, suite)


def describe(cfg, suite, specs):
    """The plan in a few lines: the grid, the records and the number of runs."""
    if cfg["building"]:
        from . import building_runs
        return building_runs.describe(cfg, suite, specs)
    kd = ", ".join(f"{k:g}" for k in cfg["kd_kN"])
    levels = (f"target PGA [g] {cfg['pga_g']}" if cfg["pga_g"] else f"scale factors {cfg['scales']}")
    bad = [r.name for r in suite if r.error]
    lines = [f"walls {cfg['walls']}; models {cfg['models']}; hinge laws {cfg['hinge_laws']}",
             f"K_d [kN/m per m] {kd} (flexibleTop only); e_r {cfg['er']}; rtol {cfg['rtol']:g}; tail {cfg['tail']:g} s",
             f"records: {len(suite)} from '{cfg['suite']}'" + (f" ({len(bad)} unreadable: {bad})" if bad else ""),
             levels,
             f"{len(specs)} runs, {sum(s.stop_time for s in specs):.0f} s of simulated time"]
    return "\n".join(lines + [scenes.swept(model).text() for model in dict.fromkeys(cfg["models"])])
