#!/usr/bin/env python3
"""Generate each FMU's modelDescription.xml from its C variable table, the one source of truth
for its variables: RockingWall (fmu_src/models/RockingWall/model_variables.h), Diaphragm
(fmu_src/models/Diaphragm/diaphragm_variables.h), Building (fmu_src/models/Building/building_variables.h)
and BuildingWithWalls (fmu_src/models/BuildingWithWalls/bw_variables.h),
each into its folder fmu_src/models/NAME/: the FMI 2.0 fmi2/modelDescription.xml, and the FMI 3.0
fmi3/modelDescription.xml and fmi3/buildDescription.xml (the FMU's sources/buildDescription.xml).

The parameter table of docs/model.md comes from fmu_src/wall/rw_parameters.h too.

    scripts/gen_model_description.py                    # (re)write both and the docs table
    scripts/gen_model_description.py --check            # exit 1 if a committed file differs
    scripts/gen_model_description.py --stdout Diaphragm # print one
"""
import argparse
import pathlib
import re
import sys
from xml.sax.saxutils import escape

REPO = pathlib.Path(__file__).resolve().parents[1]

# Sources listed in <SourceFiles> of <ModelExchange>: they build without SUNDIALS (cs_without_cvode.c
# stands in for cs_cvode.c), so Co-Simulation, which needs CVODE, lists none.
# The FMI layer's version-free half, under either API layer
VERSION_FREE_SOURCES = ["fmu_instance.c", "fmu_functions.c", "fmu_core.c", "cs_without_cvode.c"]
SHARED_SOURCES = ["fmi2Functions.c"] + VERSION_FREE_SOURCES
FMI3_SHARED_SOURCES = ["fmi3Functions.c"] + VERSION_FREE_SOURCES
MODELS_DIR = REPO / "fmu_src" / "models"
# the value reference of FMI 3.0's independent variable `time` (FMU_TIME_VR of fmu_instance.h)
FMI3_TIME_VR = 0
MODELS = {
    "RockingWall": dict(
        header=MODELS_DIR / "RockingWall" / "model_variables.h",
        output=MODELS_DIR / "RockingWall" / "fmi2" / "modelDescription.xml", prefix="RW",
        parameters=REPO / "fmu_src" / "wall" / "rw_parameters.h",
        description="Unreinforced masonry wall in out-of-plane rocking: parapet, simply supported, "
                    "or two rigid bodies with a flexible diaphragm spring at the top (2DOF)",
        sources=["rw_parameters.c", "rw_hinge_laws.c", "rw_dynamics.c", "rw_indicators.c", "rw_outputs.c",
                 "rw_events.c", "rw_rigid_tie.c", "rw_engine_indicators.c", "rw_engine_search.c", "rw_engine_peaks.c",
                 "rw_engine_events.c", "rw_engine_resolve.c", "rw_engine_band.c", "rw_engine_stepper.c",
                 "rw_engine_object.c", "rw_engine_regions.c", "rw_engine_batch.c", "rw_model.c",
                 "cs_exact.c", "rw_ground_motion.c"] + SHARED_SOURCES,
        log_events="Impacts, mid-hinge switches, opening and closing of hinges, collapse"),
    "Diaphragm": dict(
        header=MODELS_DIR / "Diaphragm" / "diaphragm_variables.h",
        output=MODELS_DIR / "Diaphragm" / "fmi2" / "modelDescription.xml", prefix="DG",
        description="Floor or roof diaphragm as one degree of freedom per metre of wall (mass, stiffness, "
                    "damping ratio), driven by the ground acceleration and the wall's top force",
        sources=["diaphragm_model.c"] + SHARED_SOURCES,
        log_events="Instantiation and Co-Simulation steps"),
    "Building": dict(
        header=MODELS_DIR / "Building" / "building_variables.h",
        output=MODELS_DIR / "Building" / "fmi2" / "modelDescription.xml", prefix="BD",
        description="In-plane building of 1 to 5 storeys per metre of out-of-plane wall: storey shear springs "
                    "and floor diaphragms (linear, Bouc-Wen, Bouc-Wen with pinching, or bilinear), Rayleigh damping, "
                    "driven by the ground acceleration and the out-of-plane walls' forces",
        sources=["building_physics.c", "building_model.c"] + SHARED_SOURCES,
        log_events="Instantiation and Co-Simulation steps"),
    "BuildingWithWalls": dict(
        header=MODELS_DIR / "BuildingWithWalls" / "bw_variables.h",
        output=MODELS_DIR / "BuildingWithWalls" / "fmi2" / "modelDescription.xml", prefix="BW",
        description="A building of 1 to 5 storeys per metre of face-loaded wall as one model: in each storey a "
                    "rocking wall (RockingWall's physics and event rules) standing on the diaphragm below and tied "
                    "to the one above, the diaphragms and floors (linear, Bouc-Wen, pinched, bilinear) as states of the same "
                    "integration, driven by the ground acceleration",
        sources=["rw_parameters.c", "rw_hinge_laws.c", "rw_dynamics.c", "rw_indicators.c", "rw_outputs.c",
                 "rw_events.c", "building_physics.c", "rw_scene.c", "bw_params.c", "bw_model.c"] + SHARED_SOURCES,
        log_events="Walls that collapse and leave the scene"),
}
# the defaults of the functions below: RockingWall
HEADER = MODELS["RockingWall"]["header"]
OUTPUT = MODELS["RockingWall"]["output"]

FIELDS = ["id", "vr", "name", "type", "causality", "variability", "initial", "start", "unit",
          "nominal", "derivative_of", "description"]
PARAM_FIELDS = ["id", "vr", "type", "unit", "start", "min", "max", "description"]
TOKEN = re.compile(r'"(?:[^"\\]|\\.)*"|[^,\s]+')

# SI base-unit exponents of the units used in the table
UNITS = {
    "1": {},
    "m": {"m": 1},
    "N/m": {"kg": 1, "s": -2},
    "N/m2": {"kg": 1, "m": -1, "s": -2},
    "m/s2": {"m": 1, "s": -2},
    "m/s": {"m": 1, "s": -1},
    "kg/m": {"kg": 1, "m": -1},
    "W/m": {"kg": 1, "m": 1, "s": -3},
    "J/m": {"kg": 1, "m": 1, "s": -2},
    "rad": {"rad": 1},
    "rad/s": {"rad": 1, "s": -1},
    "rad/s2": {"rad": 1, "s": -2},
    "1/s": {"s": -1},
    "N.s/m2": {"kg": 1, "m": -1, "s": -1},
    "s": {"s": 1},
}
LOG_CATEGORIES = [
    ("logEvents", None),  # the model's own description
    ("logStatusWarning", "Warnings (e.g. collapse)"),
    ("logStatusError", "Errors: invalid parameters or inputs, illegal calls"),
]
SOURCE_FILES = MODELS["RockingWall"]["sources"]


def write_units_logs_experiment(w, model, variables):
    """<UnitDefinitions>, <LogCategories> and <DefaultExperiment>: the same in FMI 2.0 and 3.0."""
    w('  <UnitDefinitions>')
    for unit in sorted({v["unit"] for v in variables if v["unit"]}):
        attrs = "".join(f' {k}="{e}"' for k, e in UNITS[unit].items())
        w(f'    <Unit name="{unit}"><BaseUnit{attrs}/></Unit>')
    w('  </UnitDefinitions>')
    w('  <LogCategories>')
    for cat, desc in LOG_CATEGORIES:
        w(f'    <Category name="{cat}" description="{escape(desc or model["log_events"])}"/>')
    w('  </LogCategories>')
    # stepSize: fmpy (and other importers) take it as the output / communication step, and in
    # Co-Simulation the inputs are held over it: 5 ms keeps fmpy's defaults within 0.03 % of the
    # converged peak s1 under El Centro (50 ms, fmpy's stop/500 here, was 24 % low on a soft wall)
    w('  <DefaultExperiment startTime="0" stopTime="10" tolerance="1e-06" stepSize="0.005"/>')


def _unquote(tok):
    return tok[1:-1].replace('\\"', '"') if tok.startswith('"') else tok


def _macro_rows(text, letter, fields, path):
    rows = []
    for line in text.splitlines():
        m = re.match(rf'\s*{letter}\((.*)\)\s*\\?\s*$', line)
        if not m:
            continue
        toks = [_unquote(t) for t in TOKEN.findall(m.group(1))]
        if len(toks) != len(fields):
            raise SystemExit(f"{path}: cannot parse line: {line}")
        rows.append(dict(zip(fields, toks)))
    return rows


def parse_parameters(path=REPO / "fmu_src" / "wall" / "rw_parameters.h"):
    """The parameter table P(ID, VR, TYPE, UNIT, DEFAULT, MIN, MAX, DESCRIPTION) as variable dicts."""
    params = []
    for p in _macro_rows(path.read_text(), "P", PARAM_FIELDS, path):
        p.update(name=p["id"], vr=int(p["vr"]), causality="parameter", variability="fixed", initial="exact",
                 nominal=0.0, derivative_of=0, min=float(p["min"]), max=float(p["max"]))
        params.append(p)
    return params


def parse_header(path=HEADER, prefix="RW", parameters=None):
    """Variables (list of dicts, table order: the parameter table first, if any), dependencies
    {id: [names]} and #defines (with the model's prefix replaced by RW_, so RW_GUID etc. for every
    model)."""
    text = path.read_text()
    defines = dict(re.findall(rf'#define\s+({prefix}_\w+)\s+("[^"]*"|\d+)\s*$', text, re.M))
    defines = {"RW_" + k[len(prefix) + 1:]: _unquote(v) for k, v in defines.items()}
    variables = parse_parameters(parameters) if parameters else []
    for v in _macro_rows(text, "X", FIELDS, path):
        v["vr"] = int(v["vr"])
        v["nominal"] = float(v["nominal"])
        v["derivative_of"] = int(v["derivative_of"])
        variables.append(v)
    deps = {}
    for line in text.splitlines():
        m = re.match(r'\s*D\((\w+),\s*"([^"]*)"\)\s*\\?\s*$', line)
        if m:
            deps[m.group(1)] = m.group(2).split()
    return variables, deps, defines


def parse_event_indicators(path, prefix="RW"):
    """The event indicators as variables, Z(ID, VR, DESCRIPTION), in the model's order."""
    text = path.read_text()
    if f"#define {prefix}_EVENT_INDICATORS(Z)" not in text:
        raise SystemExit(f"{path}: no {prefix}_EVENT_INDICATORS(Z) table")
    return [dict(id=z["id"], name=z["id"], vr=int(z["vr"]), description=z["description"])
            for z in _macro_rows(text, "Z", ["id", "vr", "description"], path)]


def parse_model(name):
    model = MODELS[name]
    return parse_header(model["header"], model["prefix"], model.get("parameters"))


def _fmt_number(value, typ):
    return repr(float(value)) if typ == "Real" else str(int(float(value)))


def _fmt_start(v):
    value = v["start"]
    if v["type"] == "Real":
        return repr(float(value))
    if v["type"] == "Integer":
        return str(int(float(value)))
    if v["type"] == "String":
        return escape(value, {chr(34): "&quot;"})
    return "true" if float(value) != 0 else "false"


def generate(name="RockingWall"):
    model = MODELS[name]
    variables, deps, defines = parse_model(name)
    index = {v["id"]: i + 1 for i, v in enumerate(variables)}  # 1-based ScalarVariable index
    by_vr = {v["vr"]: v for v in variables}
    by_name = {v["name"]: v for v in variables}
    states = [v for v in variables if v["vr"] in {d["derivative_of"] for d in variables if d["derivative_of"]}]
    derivatives = [v for v in variables if v["derivative_of"]]
    out = []
    w = out.append
    w('<?xml version="1.0" encoding="UTF-8"?>')
    w(f'<!-- Generated by scripts/gen_model_description.py from {model["header"].relative_to(REPO)}: do not edit. -->')
    w(f'<fmiModelDescription fmiVersion="2.0" modelName="{name}"')
    w(f'  guid="{defines["RW_GUID"]}"')
    w(f'  description="{escape(model["description"])}"')
    w('  generationTool="RockingWall scripts/gen_model_description.py" version="0.1.0"')
    w(f'  variableNamingConvention="flat" numberOfEventIndicators="{defines["RW_NUMBER_OF_EVENT_INDICATORS"]}">')
    w(f'  <ModelExchange modelIdentifier="{defines["RW_MODEL_IDENTIFIER"]}" '
      'needsExecutionTool="false" completedIntegratorStepNotNeeded="true" '
      'canBeInstantiatedOnlyOncePerProcess="false" canNotUseMemoryManagementFunctions="false" '
      'canGetAndSetFMUstate="true" canSerializeFMUstate="true" providesDirectionalDerivative="false">')
    w('    <SourceFiles>')
    for f in model["sources"]:
        w(f'      <File name="{f}"/>')
    w('    </SourceFiles>')
    w('  </ModelExchange>')
    # Co-Simulation: CVODE inside (cs_cvode.c), events located within the step; inputs held or
    # ramped with their first derivative over a step; any step size
    w(f'  <CoSimulation modelIdentifier="{defines["RW_MODEL_IDENTIFIER"]}" '
      'needsExecutionTool="false" canHandleVariableCommunicationStepSize="true" '
      'canInterpolateInputs="true" maxOutputDerivativeOrder="0" canRunAsynchronuously="false" '
      'canBeInstantiatedOnlyOncePerProcess="false" canNotUseMemoryManagementFunctions="false" '
      'canGetAndSetFMUstate="true" canSerializeFMUstate="true" providesDirectionalDerivative="false"/>')
    write_units_logs_experiment(w, model, variables)
    w('  <ModelVariables>')
    for i, v in enumerate(variables, 1):
        attrs = f'name="{escape(v["name"])}" valueReference="{v["vr"]}" description="{escape(v["description"], {chr(34): "&quot;"})}"'
        attrs += f' causality="{v["causality"]}" variability="{v["variability"]}"'
        if v["initial"]:
            attrs += f' initial="{v["initial"]}"'
        w(f'    <!-- index {i} -->')
        w(f'    <ScalarVariable {attrs}>')
        t = []
        if v["type"] == "Real":
            if v["unit"]:
                t.append(f'unit="{v["unit"]}"')
            if v["nominal"]:
                t.append(f'nominal="{v["nominal"]!r}"')
            if v["derivative_of"]:
                t.append(f'derivative="{index[by_vr[v["derivative_of"]]["id"]]}"')
        if "min" in v:
            t += [f'min="{_fmt_number(v["min"], v["type"])}"', f'max="{_fmt_number(v["max"], v["type"])}"']
        if v["initial"] != "calculated":
            t.append(f'start="{_fmt_start(v)}"')
        w(f'      <{v["type"]}{"" if not t else " " + " ".join(t)}/>')
        w('    </ScalarVariable>')
    w('  </ModelVariables>')

    def unknown(v):
        d = deps.get(v["id"])
        if d is None:
            return f'<Unknown index="{index[v["id"]]}"/>'
        ids = " ".join(str(index[by_name[n]["id"]]) for n in d)
        return f'<Unknown index="{index[v["id"]]}" dependencies="{ids}"/>'

    outputs = [v for v in variables if v["causality"] == "output"]
    w('  <ModelStructure>')
    w('    <Outputs>')
    for v in outputs:
        w(f'      {unknown(v)}')
    w('    </Outputs>')
    w('    <Derivatives>')
    for v in derivatives:
        w(f'      {unknown(v)}')
    w('    </Derivatives>')
    w('    <InitialUnknowns>')
    initial = [v for v in variables if (v in outputs or v in derivatives or v in states)
               and v["initial"] in ("approx", "calculated")]
    for v in sorted(initial, key=lambda v: index[v["id"]]):
        w(f'      <Unknown index="{index[v["id"]]}"/>')
    w('    </InitialUnknowns>')
    w('  </ModelStructure>')
    w('</fmiModelDescription>')
    return "\n".join(out) + "\n"


FMI3_TYPES = {"Real": "Float64", "Integer": "Int32", "Boolean": "Boolean", "String": "String"}


def _fmi3_variable(v):
    """One <Float64>/<Int32>/<Boolean> element of the FMI 3.0 ModelVariables."""
    attrs = (f'name="{escape(v["name"])}" valueReference="{v["vr"]}" '
             f'description="{escape(v["description"], {chr(34): "&quot;"})}" '
             f'causality="{v["causality"]}" variability="{v["variability"]}"')
    if v["initial"]:
        attrs += f' initial="{v["initial"]}"'
    if v["type"] == "Real":
        if v["unit"]:
            attrs += f' unit="{v["unit"]}"'
        if v["nominal"]:
            attrs += f' nominal="{v["nominal"]!r}"'
        if v["derivative_of"]:
            attrs += f' derivative="{v["derivative_of"]}"'
    if "min" in v:
        attrs += f' min="{_fmt_number(v["min"], v["type"])}" max="{_fmt_number(v["max"], v["type"])}"'
    if v["type"] == "String":  # FMI 3.0: a String's start value is a <Start> element
        return f'    <String {attrs}><Start value="{_fmt_start(v)}"/></String>'
    if v["initial"] != "calculated":
        attrs += f' start="{_fmt_start(v)}"'
    return f'    <{FMI3_TYPES[v["type"]]} {attrs}/>'


def generate3(name="RockingWall"):
    """The FMI 3.0 modelDescription.xml of one FMU: the FMI 2.0 one's variables, units, structure
    and default experiment, plus FMI 3.0's independent variable `time` and the event indicators
    as variables (<EventIndicator> names them by value reference)."""
    model = MODELS[name]
    variables, deps, defines = parse_model(name)
    zs = parse_event_indicators(model["header"], model["prefix"])
    by_name = {v["name"]: v for v in variables}
    derivatives = [v for v in variables if v["derivative_of"]]
    states = [v for v in variables if v["vr"] in {d["derivative_of"] for d in derivatives}]
    out = []
    w = out.append
    w('<?xml version="1.0" encoding="UTF-8"?>')
    w(f'<!-- Generated by scripts/gen_model_description.py from {model["header"].relative_to(REPO)}: do not edit. -->')
    w(f'<fmiModelDescription fmiVersion="3.0" modelName="{name}"')
    w(f'  instantiationToken="{defines["RW_GUID"]}"')
    w(f'  description="{escape(model["description"])}"')
    w('  generationTool="RockingWall scripts/gen_model_description.py" version="0.1.0"')
    w('  variableNamingConvention="flat">')
    common = (f'modelIdentifier="{defines["RW_MODEL_IDENTIFIER"]}" needsExecutionTool="false" '
              'canBeInstantiatedOnlyOncePerProcess="false" canGetAndSetFMUState="true" canSerializeFMUState="true" '
              'providesDirectionalDerivatives="false" providesAdjointDerivatives="false" '
              'providesPerElementDependencies="false"')
    w(f'  <ModelExchange {common} needsCompletedIntegratorStep="false" providesEvaluateDiscreteStates="false"/>')
    # Co-Simulation: the step (exact engine or CVODE) handles its events inside; Event Mode only
    # lets the importer change inputs between steps; inputs are held over a step
    w(f'  <CoSimulation {common} canHandleVariableCommunicationStepSize="true" maxOutputDerivativeOrder="0" '
      'providesIntermediateUpdate="false" mightReturnEarlyFromDoStep="false" '
      'canReturnEarlyAfterIntermediateUpdate="false" hasEventMode="true" providesEvaluateDiscreteStates="false"/>')
    write_units_logs_experiment(w, model, variables)
    w('  <ModelVariables>')
    w(f'    <Float64 name="time" valueReference="{FMI3_TIME_VR}" description="Simulation time" '
      'causality="independent" variability="continuous"/>')
    for v in variables:
        w(_fmi3_variable(v))
    for z in zs:
        w(f'    <Float64 name="{z["name"]}" valueReference="{z["vr"]}" description="{escape(z["description"])}" '
          'causality="local" variability="continuous" initial="calculated"/>')
    w('  </ModelVariables>')

    def unknown(tag, v):
        d = deps.get(v["id"])
        if d is None:
            return f'    <{tag} valueReference="{v["vr"]}"/>'
        return f'    <{tag} valueReference="{v["vr"]}" dependencies="{" ".join(str(by_name[n]["vr"]) for n in d)}"/>'

    outputs = [v for v in variables if v["causality"] == "output"]
    w('  <ModelStructure>')
    for v in outputs:
        w(unknown("Output", v))
    for v in derivatives:
        w(unknown("ContinuousStateDerivative", v))
    initial = [v for v in variables if (v in outputs or v in derivatives or v in states)
               and v["initial"] in ("approx", "calculated")]
    for v in initial:
        w(f'    <InitialUnknown valueReference="{v["vr"]}"/>')
    for z in zs:
        w(f'    <EventIndicator valueReference="{z["vr"]}"/>')
    w('  </ModelStructure>')
    w('</fmiModelDescription>')
    return "\n".join(out) + "\n"


def build_description3(name="RockingWall"):
    """sources/buildDescription.xml of the FMI 3.0 FMU: its C sources (without SUNDIALS, as the
    FMI 2.0 <SourceFiles>)."""
    model = MODELS[name]
    defines = parse_model(name)[2]
    sources = [f for f in model["sources"] if f not in SHARED_SOURCES] + FMI3_SHARED_SOURCES
    out = ['<?xml version="1.0" encoding="UTF-8"?>',
           '<!-- Generated by scripts/gen_model_description.py: do not edit. -->',
           '<fmiBuildDescription fmiVersion="3.0">',
           f'  <BuildConfiguration modelIdentifier="{defines["RW_MODEL_IDENTIFIER"]}">',
           '    <SourceFileSet language="C99">']
    out += [f'      <SourceFile name="{f}"/>' for f in sources]
    out += ['    </SourceFileSet>', '  </BuildConfiguration>', '</fmiBuildDescription>']
    return "\n".join(out) + "\n"


def fmi3_outputs(name):
    """(path, content) of the FMI 3.0 files of one FMU."""
    return [(MODELS_DIR / name / "fmi3" / "modelDescription.xml", generate3(name)),
            (MODELS_DIR / name / "fmi3" / "buildDescription.xml", build_description3(name))]


DOCS = REPO / "docs" / "model.md"
DOCS_BEGIN, DOCS_END = "<!-- BEGIN parameters (generated from fmu_src/wall/rw_parameters.h) -->", "<!-- END parameters -->"


def _fmt_doc_number(value, typ):
    return str(int(value)) if typ == "Integer" else f"{float(value):g}"


def parameter_table():
    """The Markdown table of the parameters, from the C table."""
    rows = ["| name | default | range | unit | meaning |", "|---|---|---|---|---|"]
    for v in parse_parameters():
        unit = {"N/m2": "N/m per m", "1": "-", "": "-"}.get(v["unit"], v["unit"])
        rng = f'[{_fmt_doc_number(v["min"], v["type"])}, {_fmt_doc_number(v["max"], v["type"])}]'
        rows.append(f'| `{v["name"]}` | {_fmt_doc_number(v["start"], v["type"])} | {rng} | {unit} | {v["description"]} |')
    return "\n".join(rows)


def docs_with_parameter_table(text):
    start, end = text.index(DOCS_BEGIN) + len(DOCS_BEGIN), text.index(DOCS_END)
    return text[:start] + "\n" + parameter_table() + "\n" + text[end:]


def _write_or_check(path, content, args):
    """Returns 1 if --check finds path stale."""
    if args.stdout:
        sys.stdout.write(content)
    elif args.check:
        if (path.read_text() if path.exists() else "") != content:
            print(f"{path} is out of date: run scripts/gen_model_description.py", file=sys.stderr)
            return 1
        print(f"{path} is up to date")
    else:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(content)
        print(f"wrote {path}")
    return 0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--check", action="store_true", help="exit 1 if modelDescription.xml is out of date")
    ap.add_argument("--stdout", action="store_true", help="print instead of writing")
    ap.add_argument("models", nargs="*", metavar="MODEL", help=f"which FMUs: {', '.join(MODELS)} (default: all)")
    args = ap.parse_args(argv)
    for name in args.models:
        if name not in MODELS:
            ap.error(f"unknown model {name!r}: choose from {', '.join(MODELS)}")
    stale = 0
    for name in args.models or list(MODELS):
        stale |= _write_or_check(MODELS[name]["output"], generate(name), args)
        if not args.stdout:
            for path, content in fmi3_outputs(name):
                stale |= _write_or_check(path, content, args)
    if not args.models and not args.stdout:
        stale |= _write_or_check(DOCS, docs_with_parameter_table(DOCS.read_text()), args)
    return stale


if __name__ == "__main__":
    sys.exit(main())
