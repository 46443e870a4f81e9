"""The code checks beside `rockingwall assess`: NZSEE C8, NTC 2018 and ASCE 41-17 on the assessed
wall (or parapet) at the site the options describe, as columns of every case, with a flag where a
code says the wall is fine and the time history says it collapses or passes the code's own limit.

The codes assume stiff diaphragms: their verdict does not change with K_d or with the record. The
site's hazard comes from the options (hazard 'site': every case carries the same code columns), or
from each case's PGA (hazard 'pga': C8's C(0) and NTC's a_g S equal the PGA the record is run at,
so the code and the time history answer the same ground motion)."""
import dataclasses
import math

import numpy as np
import pandas as pd
from scipy.optimize import brentq

from . import units
from .codes import FaceLoadedWall, NtcSite, NzSite, Parapet, TopLoad, asce41, ntc, nzsee
from .codes.common import PASS, choice
from .codes.nzs1170 import SHAPE_AT_ZERO, SOILS
from .names import SUPPORTS

CODES = ("nzsee", "ntc", "asce41")
LABELS = {"nzsee": "NZSEE C8", "ntc": "NTC 2018", "asce41": "ASCE 41-17"}
NTC_T1_COEFFICIENT = 0.05   # T1 = 0.05 H^0.75 for masonry buildings (NTC 2018 Eq. 7.3.6; unconfirmed)
HAZARDS = ("site", "pga")
METAVARS = {"m": "LENGTH", "g": "ACCELERATION", "s": "PERIOD", "1": "NUMBER", None: "NAME"}

# option -> (attribute, SI unit for units.parse, default, help); None: derived from the wall (help says how)
OPTIONS = {
    "--attachment-height": ("attachment_height", "m", 0.0, "height above the ground of the part's attachment "
                            "[m]: C8's h_i and the Circolare's z (default 0: a wall at ground level; for a parapet "
                            "the roof)"),
    "--building-height": ("building_height", "m", None, "the building's height h_n (C8) and H (NTC) [m] "
                          "(default: the attachment height plus the wall's h, a wall in the top storey; for a "
                          "parapet the attachment height, the roof)"),
    "--code-hazard": ("code_hazard", None, "site", "where the codes' ground motion comes from: 'site' (default: "
                      "the options below) or 'pga' (each case's PGA is C8's C(0) and NTC's a_g S)"),
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
    time history's control point (s1 for a wall, s2 for a parapet) [m], or None (ASCE 41: collapse
    only); pga [g]: the case PGA the hazard was set to (None: the options' site)."""
    element: str
    results: dict
    usable: dict
    site: list
    pga: float = None
    ntc_ag: float = None

    @property
    def codes(self):
        return tuple(self.results)


def element_of(wall, values):
    """The codes' FaceLoadedWall or Parapet of the model's wall: the same statics the time histories
    run (support, h, b, W; the overburden psi W/2 at eTop, the weight-only overburden psiWeightOnly
    W/2 at the centreline, the pointing, the reactions' positions eBaseRatio and eHingeRatio of t/2)."""
    p = wall.params
    pointing = p.get("pointing", 0.0)
    half_t = (p["b"] - 2.0 * pointing) / 2.0
    e_base = p.get("eBaseRatio", 1.0) * half_t
    if int(p["support"]) == SUPPORTS["parapet"]:
        if p.get("eTop", 0.0) or p.get("psiWeightOnly", 0.0):
            raise ValueError("--e-top, --psi-weight-only: a parapet has no top load")
        return Parapet(h=p["h"], b=p["b"], W=p["W"], pointing=pointing, e_base=e_base)
    loads = tuple(TopLoad(ratio * p["W"] / 2.0, e) for ratio, e in  # psi = 2 P / W
                  ((p["psi"], p.get("eTop", 0.0)), (p.get("psiWeightOnly", 0.0), 0.0)) if ratio > 0)
    return FaceLoadedWall(h=p["h"], b=p["b"], W=p["W"], top_loads=loads, pointing=pointing,
                          e_base=e_base, e_hinge=p.get("eHingeRatio", 1.0) * half_t)


def heights(wall, values):
    """(attachment height, building height) [m]."""
    h_i = values["attachment_height"]
    h_n = values["building_height"]
    if h_n is None:
        parapet = int(wall.params["support"]) == SUPPORTS["parapet"]
        # a parapet stands on the roof (the building's top) or, at the ground, is the building
        h_n = (h_i if h_i > 0 else wall.params["h"]) if parapet else h_i + wall.params["h"]
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
           "top load eccentricity": "--e-top", "pointing depth": "--pointing", "e_base": "eBaseRatio",
           "e_hinge": "eHingeRatio"}


# each code's options that set the ground motion it checks against; the hazard 'pga' sets Z and a_g
HAZARD_OPTIONS = {"nzsee": ("--nz-Z", "--nz-soil"), "ntc": ("--ntc-ag", "--ntc-F0", "--ntc-Tc", "--ntc-soil"),
                  "asce41": ("--asce-SX1",)}
SET_BY_PGA = ("--nz-Z", "--ntc-ag")


def checks_by_hazard(wall, codes, values, pgas=(), given=()):
    """{None: CodeChecks} at the options' site, or with values['code_hazard'] 'pga' {pga_key(PGA):
    CodeChecks} for every PGA [g] in pgas; given: the options the user gave (a site's Z or a_g
    clashes with the hazard 'pga'; a site line names the ground motion's options left at defaults)."""
    hazard = choice("--code-hazard", values["code_hazard"], HAZARDS)
    if hazard == "site":
        return {None: defaults_named(check(wall, codes, values), given)}
    clash = [flag for flag in SET_BY_PGA if flag in given]
    if clash:
        raise ValueError(f"{clash[0]}: with --code-hazard pga each case's PGA sets the codes' ground motion; "
                         "give one or the other")
    return {key: defaults_named(check(wall, codes, values, pga=key), given)
            for key in sorted({pga_key(p) for p in pgas})}


def defaults_named(checks, given):
    """checks whose site lines (one per code, after the heights') name the options of the code's ground
    motion the user left at their defaults: those are an example site's (docs/codes.md), not theirs."""
    lines = list(checks.site[:1])
    for code, line in zip(checks.results, checks.site[1:]):
        left = [flag for flag in HAZARD_OPTIONS[code]
                if flag not in given and not (checks.pga is not None and flag in SET_BY_PGA)]
        lines.append(line + (f" ({', '.join(left)} not given: an example site's defaults, not yours)" if left else ""))
    return dataclasses.replace(checks, site=lines)


def nz_Z_for(pga, values):
    """The hazard factor Z that makes NZS 1170.5's C(0) = C_h(0) Z R N equal `pga` [g]."""
    soil = choice("soil class", values["nz_soil"], SOILS)
    z = pga / (SHAPE_AT_ZERO[soil] * values["nz_R"] * values["nz_N"])
    if not 0 < z <= 0.6 or z * values["nz_R"] > 0.7:
        raise ValueError(f"--code-hazard pga: PGA {pga:g} g on soil {soil} needs Z = {z:.3g} (R = {values['nz_R']:g}, "
                         f"N = {values['nz_N']:g}), outside NZS 1170.5's Z <= 0.6, Z R <= 0.7")
    return z


def ntc_ag_for(pga, values):
    """The a_g [g] whose a_g S (S = S_S S_T, S_S depending on a_g) equals `pga` [g]."""
    def site(ag):
        return NtcSite(ag=ag, F0=values["ntc_F0"], Tc_star=values["ntc_Tc"], soil=values["ntc_soil"],
                       topography=values["ntc_topography"])
    high = 1.5
    top = site(high)
    if pga > high * top.S:
        raise ValueError(f"--code-hazard pga: PGA {pga:g} g is above a_g S = {high * top.S:.3g} g, NTC 2018's "
                         f"largest a_g ({high:g} g) on soil {top.soil}")
    return brentq(lambda ag: ag * site(ag).S - pga, 1e-9, high, xtol=1e-14, rtol=1e-13)


def check(wall, codes, values, pga=None):
    """CodeChecks of `codes` (a subset of CODES) on the model's wall, values from option_values; with
    pga [g], C8's Z and NTC's a_g set so that C(0) and a_g S equal it. A value a code refuses is a
    ValueError naming its option."""
    try:
        if pga is not None:
            values = dict(values, nz_Z=nz_Z_for(pga, values) if "nzsee" in codes else values["nz_Z"],
                          ntc_ag=ntc_ag_for(pga, values) if "ntc" in codes else values["ntc_ag"])
        return dataclasses.replace(_check(wall, codes, values), pga=pga, ntc_ag=values["ntc_ag"])
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
    h_i, h_n = heights(wall, values)
    results, usable, site = {}, {}, [f"codes at height {h_i:g} m of a {h_n:g}-m building"]
    for code in dict.fromkeys(codes):
        results[code], usable[code], line = CHECKS[code](wall, element, values, h_i, h_n)
        site.append(line)
    return CodeChecks("parapet" if isinstance(element, Parapet) else "wall", results, usable, site)


def _nzsee(wall, element, values, h_i, h_n):
    """(result, usable displacement, site line) of C8's wall or parapet check."""
    nz = NzSite(Z=values["nz_Z"], soil=values["nz_soil"], R=values["nz_R"], N=values["nz_N"])
    fn = nzsee.check_parapet if isinstance(element, Parapet) else nzsee.check_wall
    r = fn(element, nz, h_i=h_i, h_n=h_n, Rp=values["nz_Rp"])
    return r, r.delta_m, (f"NZSEE C8 site: Z = {nz.Z:g}, soil {nz.soil}, R = {nz.R:g}, N = {nz.N:g}, "
                          f"R_p = {values['nz_Rp']:g}, C(0) = {nz.C0:.3g} g")


def _ntc(wall, element, values, h_i, h_n):
    """(result, usable displacement, site line) of the Circolare's kinematic checks; above the
    ground with the floor spectrum."""
    it = NtcSite(ag=values["ntc_ag"], F0=values["ntc_F0"], Tc_star=values["ntc_Tc"],
                 soil=values["ntc_soil"], topography=values["ntc_topography"])
    floor = {}
    if h_i > 0:
        t1 = values["ntc_T1"] if values["ntc_T1"] is not None else NTC_T1_COEFFICIENT * h_n ** 0.75
        floor = dict(z=h_i, H=h_n, T1=t1)
    r = ntc.check_mechanism(element, it, FC=values["ntc_FC"], q=values["ntc_q"], **floor)
    usable = r.du_star * element.mechanism(r.direction).delta_i / r.d0_star  # du* at the control point
    line = (f"NTC 2018 site: a_g = {it.ag:.4g} g, F0 = {it.F0:g}, T*_C = {it.Tc_star:g} s, soil {it.soil}, "
            f"{it.topography}, S = {it.S:.3g}, FC = {values['ntc_FC']:g}, q = {values['ntc_q']:g}"
            + (f", floor spectrum with T1 = {floor['T1']:.3g} s" if floor else ""))
    return r, usable, line


def _asce41(wall, element, values, h_i, h_n):
    """(result, None: no usable displacement, site line) of ASCE 41's h/t check."""
    if isinstance(element, Parapet):
        raise ValueError("--code asce41: ASCE 41's h/t table is for walls between floors; its parapet "
                         "check is not implemented")
    storey = asce_storey(wall, values, h_i, h_n)
    r = asce41.check_wall(wall.params["h"], element.t, storey, values["asce_SX1"])
    return r, None, f"ASCE 41-17: S_X1 = {values['asce_SX1']:g} g, {storey.replace('_', ' ')}"


CHECKS = {"nzsee": _nzsee, "ntc": _ntc, "asce41": _asce41}


def columns(checks):
    """The code columns every case of the wall carries (lengths mm, accelerations g)."""
    out = {}
    for code, r in checks.results.items():
        if code == "nzsee":
            out.update(nzsee_C0_g=r.C0, nzsee_delta_i_mm=r.delta_i * 1e3, nzsee_delta_m_mm=r.delta_m * 1e3, nzsee_Tp_s=r.Tp,
                       nzsee_C_Hi=r.C_Hi, nzsee_Cp_g=r.Cp, nzsee_demand_mm=r.demand * 1e3, nzsee_nbs=r.nbs,
                       nzsee_verdict=r.verdict)
        elif code == "ntc":
            out.update(ntc_ag_g=checks.ntc_ag, ntc_a0_star_g=r.a0_star / 9.81, ntc_linear_demand_g=r.linear_demand / 9.81,
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


def pga_key(pga_g):
    """The key of a case's PGA [g] in the checks per PGA (the same PGA computed twice may differ in
    its last bits)."""
    return round(float(pga_g), 9)


def checks_at(by_pga, pga_g):
    """The CodeChecks for a case at pga_g [g] in the checks per hazard: the options' site's, or
    that PGA's."""
    return by_pga[None] if None in by_pga else by_pga[pga_key(pga_g)]


def add_to_cases(cases, by_pga):
    """cases (assess's DataFrame) with the code columns and <code>_unconservative per row; by_pga:
    {None: CodeChecks} for the options' site, or {pga_key(PGA): CodeChecks} per case PGA."""
    rows = []
    for r in cases.to_dict("records"):
        checks = checks_at(by_pga, r["pga_g"])
        peak = r["peak_s2_mm"] if checks.element == "parapet" else r["peak_s1_mm"]
        flags = unconservative(checks, peak / 1e3 if np.isfinite(peak) else math.nan, r["collapsed"])
        rows.append({**columns(checks), **{f"{code}_unconservative": flags[code] for code in checks.codes}})
    extra = pd.DataFrame(rows, index=cases.index)
    return pd.concat([cases, extra], axis=1)


UNCONSERVATIVE_MEANING = ("UNCONSERVATIVE: the code passes, the time history collapses or passes the code's usable "
                          "displacement (C8 Delta_m; NTC du* at the control point; ASCE 41 collapse only)")
STIFF_DIAPHRAGMS = f"the codes assume stiff diaphragms: their columns do not change with K_d; {UNCONSERVATIVE_MEANING}"


def head_lines(by_pga):
    """The report's lines on the codes: the site, each code's capacity, demand and verdict (per case
    PGA with the hazard 'pga')."""
    lines = []
    for key, checks in by_pga.items():
        lines += ([f"code hazard at PGA {key:g} g (each case's):"] if key is not None else []) + checks_lines(checks)
    lines.append(STIFF_DIAPHRAGMS)
    return lines


def checks_lines(checks):
    """The site and each code's capacity, demand and verdict of one CodeChecks."""
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
    return lines


def to_json(by_pga):
    """The checks as plain data: a list, one per hazard (the options' site, or each case PGA), with
    per code every reported quantity, its clauses and notes."""
    return [checks_json(checks) for checks in by_pga.values()]


def checks_json(checks):
    out = {"element": checks.element, "hazard_pga_g": checks.pga, "site": checks.site}
    for code, r in checks.results.items():
        data = dataclasses.asdict(r)
        data["refs"] = [str(ref) for ref in r.refs]
        data["notes"] = list(r.notes)
        data["usable_displacement_m"] = checks.usable[code]
        out[code] = data
    return out
