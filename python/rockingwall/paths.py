"""Where the compiled parts are: the FMUs, fmi2sim, the engine library.

One rule for every tool: `$RW_BUILD_DIR` if set; else the binaries installed with the package
(`rockingwall/_bin`, present after `pip install .`); else the `build/` folder of the source
checkout this package lives in (an editable install, or running from the repository)."""
import os
import pathlib

PACKAGE = pathlib.Path(__file__).resolve().parent
_INSTALLED = PACKAGE / "_bin"
_CHECKOUT_BUILD = PACKAGE.parents[1] / "build"


def build_dir():
    """The folder holding RockingWall.fmu, Diaphragm.fmu, fmi2sim and librwengine.so."""
    env = os.environ.get("RW_BUILD_DIR")
    if env:
        return pathlib.Path(env).resolve()
    if (_INSTALLED / "RockingWall.fmu").exists():
        return _INSTALLED
    return _CHECKOUT_BUILD


def where(name):
    """Where a compiled part is, or would be once built: for a message that points a user at it."""
    return build_dir() / name


def binary(name):
    """Path of one compiled part; FileNotFoundError saying how to get it when it is missing."""
    path = build_dir() / name
    if not path.exists():
        raise FileNotFoundError(f"{path} is missing: build it (scripts/setup.sh, or pip install .) "
                                "or point RW_BUILD_DIR at a build folder")
    return path


def wall_fmu():
    return binary("RockingWall.fmu")


def diaphragm_fmu():
    return binary("Diaphragm.fmu")


def building_fmu():
    return binary("Building.fmu")


def building_with_walls_fmu():
    return binary("BuildingWithWalls.fmu")


def fmi2sim():
    return binary("fmi2sim")


def engine_library():
    return pathlib.Path(os.environ["RW_ENGINE_LIB"]) if os.environ.get("RW_ENGINE_LIB") else binary("librwengine.so")
