"""The package's own error kinds, which the command line reports as one line and exit status 2.

Every error the package raises on purpose (refused input, a run the model or a solver cannot
make) is a ValueError or derives from RockingWallError; anything else reaching the command line
is a bug and keeps its traceback."""


class RockingWallError(Exception):
    """Base of the package's errors that are not ValueErrors: the engine's, fmi2sim's, the
    coupled scenes'. A new error kind of the package derives from it (or from ValueError)."""
