"""FMUs coupled to each other: the FMI slave helpers (`slaves`), the package's one Jacobi master
(`jacobi`), the wall tied to the Diaphragm FMU (`wall_diaphragm`, the scene of `rockingwall
couple`) with its libcosim master (`libcosim`), its monolithic run under one CVODE
(`monolithic`), its safety rules (`rules`), its masters in child processes (`isolation`) and what
the command writes (`output`). The building scene is rockingwall.building."""
