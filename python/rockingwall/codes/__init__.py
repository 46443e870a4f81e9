"""The verdicts of three codes on a face-loaded unreinforced-masonry wall, as pure functions:
NZSEE C8 with NZS 1170.5's parts spectrum (nzsee), NTC 2018 with its Circolare 2019 (ntc) and
ASCE/SEI 41-17 (asce41). Each check returns a frozen result with its capacity, demand, verdict,
the values an engineer reports, the clause of each (refs) and its notes, unconfirmed formulas
among them. All of them assume stiff diaphragms; RockingWall's dynamic answer with a flexible
diaphragm is meant to stand beside them. docs/codes.md says what is confirmed and how.

    from rockingwall.codes import FaceLoadedWall, TopLoad, NzSite, nzsee
    wall = FaceLoadedWall(h=3.6, b=0.23, W=14904, top_loads=(TopLoad(1500),))
    nzsee.check_wall(wall, NzSite(Z=0.4, soil="C"), h_i=5.8, h_n=9.0).nbs
"""
from . import asce41, ntc, nzsee
from .mechanism import FaceLoadedWall, Parapet, TopLoad
from .ntc_spectrum import NtcSite
from .nzs1170 import NzSite

__all__ = ["FaceLoadedWall", "Parapet", "TopLoad", "NzSite", "NtcSite", "nzsee", "ntc", "asce41"]
