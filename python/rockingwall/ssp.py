"""rockingwall.ssp, where docs/building-coupling.md has long named the SSP functions: the same
functions as rockingwall.building.ssp, which holds them."""
from .building.ssp import SSPError, read, run_libcosim, write

__all__ = ["SSPError", "read", "run_libcosim", "write"]
