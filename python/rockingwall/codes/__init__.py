"""The verdicts of codes on a face-loaded unreinforced-masonry wall, as pure functions: NZSEE C8
with NZS 1170.5's parts spectrum (nzsee) and NTC 2018 with its Circolare 2019 (ntc), on the
statics of the rocking mechanisms (mechanism)."""
from . import ntc, nzsee
from .mechanism import FaceLoadedWall, Parapet, TopLoad
from .ntc_spectrum import NtcSite
from .nzs1170 import NzSite

__all__ = ["FaceLoadedWall", "Parapet", "TopLoad", "NzSite", "NtcSite", "nzsee", "ntc"]
