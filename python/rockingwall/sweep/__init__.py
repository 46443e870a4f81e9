"""Parametric studies of the RockingWall FMU through fmi2sim: record suites, the run grid, one run,
the results file, and fragility fits. The command lines are `rockingwall sweep` and `rockingwall ida`."""
