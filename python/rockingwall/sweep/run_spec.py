"""One run of a sweep as planned: what it simulates and the stable run_id that lets an interrupted
sweep resume (rockingwall.sweep.grid makes them for walls, rockingwall.sweep.building_runs for
the storeys of a building)."""
import dataclasses


@dataclasses.dataclass(frozen=True)
class RunSpec:
    run_id: str
    wall: str           # a preset (1, 2, 3 = paper1..3) or the name of a [walls.NAME] table
    model: str
    hinge_law: str
    kd_kN: float        # NaN for models without the top spring
    record: str
    record_path: str
    record_pga_g: float
    scale: float        # factor on the record as given
    pga_g: float        # scale * record PGA: the intensity measure
    stop_time: float
    sets: tuple         # (("NAME", "VALUE"), ...) for fmi2sim --set
    error: str = ""     # the record could not be planned: reported without running
    record_sha256: str = ""  # the record's content: part of the run's key (rockingwall.sweep.provenance)
