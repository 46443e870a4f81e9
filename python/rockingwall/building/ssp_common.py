"""What the SSP writer and reader share: the SSP 1.0 namespaces, the connectors' units, the error
kind, and the variables of an FMU (for the checks of connectors, units and parameters)."""
from ..errors import RockingWallError

NS = {"ssd": "http://ssp-standard.org/SSP1/SystemStructureDescription",
      "ssc": "http://ssp-standard.org/SSP1/SystemStructureCommon",
      "ssv": "http://ssp-standard.org/SSP1/SystemStructureParameterValues"}

# SI base-unit exponents of the units the connectors use (SSP's ssc:BaseUnit)
UNITS = {"m": {"m": 1}, "m/s2": {"m": 1, "s": -2}, "N/m": {"kg": 1, "s": -2}}


class SSPError(ValueError, RockingWallError):
    """A malformed or unsupported SSP file, with the file, the component and the reason."""


def q(prefix, tag):
    """An element's qualified name, '{namespace}tag'."""
    return f"{{{NS[prefix]}}}{tag}"


def fmu_units(fmu):
    """{variable name: (causality, unit)} of an FMU (file or folder)."""
    from fmpy import read_model_description
    md = read_model_description(str(fmu))
    return {v.name: (v.causality, v.unit or (v.declaredType.unit if v.declaredType is not None else None))
            for v in md.modelVariables}
