"""The verdicts of codes on a face-loaded unreinforced-masonry wall, as pure functions: NZSEE C8
with NZS 1170.5's parts spectrum (nzsee), on the statics of the rocking mechanisms (mechanism)."""
from . import nzsee
from .mechanism import FaceLoadedWall, Parapet, TopLoad
from .nzs1170 import NzSite

__all__ = ["FaceLoadedWall", "Parapet", "TopLoad", "NzSite", "nzsee"]
