"""Out-of-plane walls in a multi-storey building: the scene of Building.fmu and one RockingWall.fmu
per storey and its run (`scene`), the scene as an SSP 1.0 file (`ssp`), and the worked example of
docs/building-coupling.md (`example`). The command line is `rockingwall couple-building`."""
