"""A scene run's numbers are a result only where its energy balance closes: BuildingError otherwise,
for the main run and for every run a result is built from (the floors' sampled histories, the
sensitivity check's scaled records)."""
from ..coupling.rules import ENERGY_SHARE_MAX
from ..errors import RockingWallError


class BuildingError(RockingWallError, RuntimeError):
    """A run whose numbers cannot be trusted (the energy balance does not close): never a result."""


def check_energy(r, where):
    """The residual's share of the input work of a scene_engine.Result; BuildingError naming
    `where` when it is more than ENERGY_SHARE_MAX."""
    share = r.max_residual / r.max_work if r.max_work > 0 else 0.0
    if not share <= ENERGY_SHARE_MAX:
        raise BuildingError(
            f"{where}: the energy balance does not close (residual {share:.2g} of the input work, more than "
            f"{ENERGY_SHARE_MAX:g}): the run is not converged; run again with a tighter tolerance (rtol)")
    return share
