"""The verdicts of codes on a face-loaded unreinforced-masonry wall, as pure functions; this
package starts with the statics of the rocking mechanisms they check (mechanism)."""
from .mechanism import FaceLoadedWall, Parapet, TopLoad

__all__ = ["FaceLoadedWall", "Parapet", "TopLoad"]
