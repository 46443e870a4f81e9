"""The code checks beside `rockingwall assess`: NZSEE C8, NTC 2018 and ASCE 41-17 on the assessed
wall (or parapet) at the site the options describe, as columns of every case, with a flag where a
code says the wall is fine and the time history says it collapses or passes the code's own limit.

The codes assume stiff diaphragms: their verdict does not change with K_d or with the record, so
every case of one wall carries the same code columns; the time history is what changes."""
import dataclasses
import math

import numpy as np

from . import units
from .codes import FaceLoadedWall, NtcSite, NzSite, Parapet, TopLoad, asce41, ntc, nzsee
from .codes.common import PASS
from .names import SUPPORTS

CODES = ("nzsee", "ntc", "asce41")
LABELS = {"nzsee": "NZSEE C8", "ntc": "NTC 2018", "asce41": "ASCE 41-17"}
NTC_T1_COEFFICIENT = 0.05   # T1 = 0.05 H^0.75 for masonry buildings (NTC 2018 Eq. 7.3.6; unconfirmed)

# option -> (attribute, SI unit for units.parse, default, help); None: derived from the wall (help says how)
OPTIONS = {
    "--attachment-height": ("attachment_height", "m", 0.0, "height above the ground of the part's attachment: "
                            "C8's h_i and the Circolare's z (default 0: a wall at ground level; for a parapet "
                            "the roof)"),
    "--building-height": ("building_height", "m", None, "the building's height h_n (C8) and H (NTC) [m] "
                          "(default: the attachment height plus the wall's h, a wall in the top storey)"),
    "--top-eccentricity": ("top_eccentricity", "m", 0.0, "the top load's eccentricity from the wall's "
                           "centreline, positive toward the inner face (joists bearing on it) [m] (default 0); "
                           "the codes only: the time histories run the model's wall"),
    "--pointing": ("pointing", "m", 0.0, "depth of recessed mortar pointing on each face [m]: effective "
                   "thickness b - 2 pointing (default 0); the codes only"),
    "--e-base": ("e_base", "m", None, "the base reaction's distance from the centreline [m] (default: the face)"),
    "--e-hinge": ("e_hinge", "m", None, "the hinge reaction's distance from the centreline [m] (default: the face)"),
    "--nz-Z": ("nz_Z", "1", 0.4, "NZS 1170.5 hazard factor Z (default 0.4)"),
    "--nz-soil": ("nz_soil", None, "C", "NZS 1170.5 site subsoil class A-E (default C)"),
    "--nz-R": ("nz_R", "1", 1.0, "NZS 1170.5 return period factor R (default 1.0, 500 years)"),
    "--nz-N": ("nz_N", "1", 1.0, "NZS 1170.5 near-fault factor N (default 1.0)"),
    "--nz-Rp": ("nz_Rp", "1", 1.0, "NZS 1170.5 part risk factor R_p (default 1.0)"),
    "--ntc-ag": ("ntc_ag", "g", 0.25, "NTC 2018 a_g of the limit state [g] (default 0.25g)"),
    "--ntc-F0": ("ntc_F0", "1", 2.4, "NTC 2018 F0 (default 2.4)"),
    "--ntc-Tc": ("ntc_Tc", "s", 0.3, "NTC 2018 T*_C [s] (default 0.3s)"),
    "--ntc-soil": ("ntc_soil", None, "B", "NTC 2018 soil category A-E (default B)"),
    "--ntc-topography": ("ntc_topography", None, "T1", "NTC 2018 topographic category T1-T4 (default T1)"),
    "--ntc-FC": ("ntc_FC", "1", 1.35, "confidence factor FC (default 1.35, knowledge level LC1)"),
    "--ntc-q": ("ntc_q", "1", 2.0, "behaviour factor q of the linear check (default 2)"),
    "--ntc-T1": ("ntc_T1", "s", None, "the building's fundamental period T1 [s] for the floor spectrum "
                 f"(default {NTC_T1_COEFFICIENT:g} H^0.75)"),
    "--asce-SX1": ("asce_SX1", "g", 0.3, "ASCE 41-17 S_X1 of the hazard level [g] (default 0.3g)"),
    "--asce-storey": ("asce_storey", None, None, f"ASCE 41 storey: {', '.join(asce41.STOREYS)} (default: from "
                      "the attachment and building heights)"),
}


def option_values(args):
    """{attribute: value in SI (or a name)} of OPTIONS from parsed arguments; a bad value is a
    ValueError naming the option."""
    out = {}
    for flag, (attr, unit, default, _) in OPTIONS.items():
        given = getattr(args, attr, None)
        if given is None:
            out[attr] = default
        elif unit is None:
            out[attr] = str(given)
        else:
            out[attr] = units.parse(given, unit, flag)
    return out


@dataclasses.dataclass(frozen=True)
class CodeChecks:
    """The requested codes' results on one element; usable: the code's usable displacement at the
    time history's control point (s1 for a wall, s2 for a parapet) [m], or None (ASCE 41: collapse only)."""
    element: str
    results: dict
    usable: dict
    site: list

    @property
    def codes(self):
        return tuple(self.results)


def element_of(wall, values):
    """The codes' FaceLoadedWall or Parapet of the model's wall (support, h, b, W, psi)."""
    p = wall.params
    support = int(p["support"])
    if support == SUPPORTS["parapet"]:
        if values["top_eccentricity"] or values["e_hinge"] is not None:
            raise ValueError("--top-eccentricity and --e-hinge: a parapet has no top load and no hinge")
        return Parapet(h=p["h"], b=p["b"], W=p["W"], pointing=values["pointing"], e_base=values["e_base"])
    load = p["psi"] * p["W"] / 2.0   # psi = 2 P / W
    loads = (TopLoad(load, values["top_eccentricity"]),) if load > 0 or values["top_eccentricity"] else ()
    return FaceLoadedWall(h=p["h"], b=p["b"], W=p["W"], top_loads=loads, pointing=values["pointing"],
                          e_base=values["e_base"], e_hinge=values["e_hinge"])


def heights(wall, values):
    """(attachment height, building height) [m]."""
    h_i = values["attachment_height"]
    h_n = values["building_height"]
    if h_n is None:
        h_n = h_i + (0.0 if int(wall.params["support"]) == SUPPORTS["parapet"] else wall.params["h"])
    if not 0.0 <= h_i <= h_n or h_n <= 0.0 or h_n > 300.0:
        raise ValueError(f"--attachment-height = {h_i:g} m and --building-height = {h_n:g} m: need "
                         "0 <= attachment height <= building height <= 300 m, building height > 0")
    return h_i, h_n


def asce_storey(wall, values, h_i, h_n):
    """The storey of ASCE 41's table: given, or from where the wall is in the building."""
    if values["asce_storey"] is not None:
        return values["asce_storey"]
    top = h_i + wall.params["h"] >= h_n - 1e-9
    if h_i == 0.0:
        return "one_storey_building" if top else "first_storey"
    return "top_storey" if top else "other_storey"


# the codes module's names of its inputs -> the options that give them (its errors start with the name)
FLAG_OF = {"Z": "--nz-Z", "soil class": "--nz-soil", "R": "--nz-R", "N": "--nz-N", "Rp": "--nz-Rp",
           "ag": "--ntc-ag", "F0": "--ntc-F0", "Tc_star": "--ntc-Tc", "soil category": "--ntc-soil",
           "topography": "--ntc-topography", "FC": "--ntc-FC", "q": "--ntc-q", "T1": "--ntc-T1",
           "H": "--building-height", "z": "--attachment-height", "h_i": "--attachment-height",
           "h_n": "--building-height", "S_X1": "--asce-SX1", "storey": "--asce-storey",
           "top load eccentricity": "--top-eccentricity", "pointing depth": "--pointing", "e_base": "--e-base",
           "e_hinge": "--e-hinge"}


def check(wall, codes, values):
    """CodeChecks of `codes` (a subset of CODES) on the model's wall, values from option_values; a
    value a code refuses is a ValueError naming its option."""
    try:
        return _check(wall, codes, values)
    except ValueError as exc:
        text = str(exc)
        for name, flag in sorted(FLAG_OF.items(), key=lambda item: -len(item[0])):
            if text.startswith(name + " ") or text.startswith(name + ":"):
                raise ValueError(f"{flag}: {text}") from None
        raise


def _check(wall, codes, values):
    unknown = [c for c in codes if c not in CODES]
    if unknown or not codes:
        raise ValueError(f"--code {' '.join(unknown)}: one or more of {', '.join(CODES)}")
    element = element_of(wall, values)
    parapet = isinstance(element, Parapet)
    h_i, h_n = heights(wall, values)
    results, usable, site = {}, {}, [f"codes at height {h_i:g} m of a {h_n:g}-m building"]
    for code in dict.fromkeys(codes):
        if code == "nzsee":
            nz = NzSite(Z=values["nz_Z"], soil=values["nz_soil"], R=values["nz_R"], N=values["nz_N"])
            fn = nzsee.check_parapet if parapet else nzsee.check_wall
            results[code] = fn(element, nz, h_i=h_i, h_n=h_n, Rp=values["nz_Rp"])
            usable[code] = results[code].delta_m
            site.append(f"NZSEE C8 site: Z = {nz.Z:g}, soil {nz.soil}, R = {nz.R:g}, N = {nz.N:g}, "
                        f"R_p = {values['nz_Rp']:g}, C(0) = {nz.C0:.3g} g")
        elif code == "ntc":
            it = NtcSite(ag=values["ntc_ag"], F0=values["ntc_F0"], Tc_star=values["ntc_Tc"],
                         soil=values["ntc_soil"], topography=values["ntc_topography"])
            floor = {}
            if h_i > 0:
                t1 = values["ntc_T1"] if values["ntc_T1"] is not None else NTC_T1_COEFFICIENT * h_n ** 0.75
                floor = dict(z=h_i, H=h_n, T1=t1)
            r = ntc.check_mechanism(element, it, FC=values["ntc_FC"], q=values["ntc_q"], **floor)
            results[code] = r
            usable[code] = r.du_star * element.mechanism(r.direction).delta_i / r.d0_star  # du* at the control point
            site.append(f"NTC 2018 site: a_g = {it.ag:g} g, F0 = {it.F0:g}, T*_C = {it.Tc_star:g} s, soil "
                        f"{it.soil}, {it.topography}, S = {it.S:.3g}, FC = {values['ntc_FC']:g}, q = {values['ntc_q']:g}"
                        + (f", floor spectrum with T1 = {floor['T1']:.3g} s" if floor else ""))
        else:
            if parapet:
                raise ValueError("--code asce41: ASCE 41's h/t table is for walls between floors; its parapet "
                                 "check is not implemented")
            storey = asce_storey(wall, values, h_i, h_n)
            results[code] = asce41.check_wall(wall.params["h"], element.t, storey, values["asce_SX1"])
            usable[code] = None
            site.append(f"ASCE 41-17: S_X1 = {values['asce_SX1']:g} g, {storey.replace('_', ' ')}")
    return CodeChecks("parapet" if parapet else "wall", results, usable, site)


def columns(checks):
    """The code columns every case of the wall carries (lengths mm, accelerations g)."""
    out = {}
    for code, r in checks.results.items():
        if code == "nzsee":
            out.update(nzsee_delta_i_mm=r.delta_i * 1e3, nzsee_delta_m_mm=r.delta_m * 1e3, nzsee_Tp_s=r.Tp,
                       nzsee_C_Hi=r.C_Hi, nzsee_Cp_g=r.Cp, nzsee_demand_mm=r.demand * 1e3, nzsee_nbs=r.nbs,
                       nzsee_verdict=r.verdict)
        elif code == "ntc":
            out.update(ntc_a0_star_g=r.a0_star / 9.81, ntc_linear_demand_g=r.linear_demand / 9.81,
                       ntc_linear_verdict=r.linear_verdict, ntc_du_star_mm=r.du_star * 1e3, ntc_Ts_s=r.Ts,
                       ntc_SDe_mm=r.nonlinear_demand * 1e3, ntc_nonlinear_verdict=r.nonlinear_verdict,
                       ntc_verdict=r.verdict)
        else:
            out.update(asce41_h_over_t=r.h_over_t, asce41_limit=r.limit, asce41_verdict=r.verdict)
    return out


def unconservative(checks, peak_m, collapsed):
    """{code: True where the code passes the wall and the time history collapses or its peak at the
    code's control point passes the code's usable displacement}; peak_m [m] (NaN when collapsed)."""
    out = {}
    for code, r in checks.results.items():
        limit = checks.usable[code]
        beyond = bool(collapsed) or (limit is not None and math.isfinite(peak_m) and peak_m > limit)
        out[code] = r.verdict == PASS and beyond
    return out


def add_to_cases(cases, checks):
    """cases (assess's DataFrame) with the code columns and <code>_unconservative per row."""
    out = cases.copy()
    for name, value in columns(checks).items():
        out[name] = value
    peak_column = "peak_s2_mm" if checks.element == "parapet" else "peak_s1_mm"
    flags = [unconservative(checks, peak / 1e3 if np.isfinite(peak) else math.nan, c)
             for peak, c in zip(out[peak_column], out["collapsed"])]
    for code in checks.codes:
        out[f"{code}_unconservative"] = [f[code] for f in flags]
    return out


def head_lines(checks):
    """The report's lines on the codes: the site, each code's capacity, demand and verdict."""
    lines = list(checks.site)
    for code, r in checks.results.items():
        if code == "nzsee":
            lines.append(f"NZSEE C8 ({r.element}, {r.direction}): Delta_i = {r.delta_i * 1e3:.1f} mm, capacity "
                         f"Delta_m = {r.delta_m * 1e3:.1f} mm, Tp = {r.Tp:.2f} s, C_Hi = {r.C_Hi:.2f}, "
                         f"Cp(Tp) = {r.Cp:.3f} g, demand {r.demand * 1e3:.0f} mm: {r.nbs:.0f} %NBS, {r.verdict}")
        elif code == "ntc":
            lines.append(f"NTC 2018 ({r.direction}): linear a0* = {r.a0_star / 9.81:.3f} g against "
                         f"{r.linear_demand / 9.81:.3f} g, {r.linear_verdict}; nonlinear du* = {r.du_star * 1e3:.1f} "
                         f"mm against S_De({r.Ts:.2f} s) = {r.nonlinear_demand * 1e3:.1f} mm, {r.nonlinear_verdict}")
        else:
            lines.append(f"ASCE 41-17: h/t = {r.h_over_t:.2f} against {r.limit:g} ({r.band}): {r.verdict}")
    lines.append("the codes assume stiff diaphragms: their columns do not change with K_d or the record; "
                 "UNCONSERVATIVE: the code passes, the time history collapses or passes the code's usable "
                 "displacement (C8 Delta_m; NTC du* at the control point; ASCE 41 collapse only)")
    return lines


def to_json(checks):
    """The checks as plain data: per code every reported quantity, its clauses and notes."""
    out = {"element": checks.element, "site": checks.site}
    for code, r in checks.results.items():
        data = dataclasses.asdict(r)
        data["refs"] = [str(ref) for ref in r.refs]
        data["notes"] = list(r.notes)
        data["usable_displacement_m"] = checks.usable[code]
        out[code] = data
    return out
