"""ModelStructure of Building.fmu against finite differences (the probe of
test_model_structure.py): every output and state derivative, each continuous state and Real input
perturbed in turn, at every combination of the spring laws, with all five storeys active and
every state away from zero (so no dependency hides behind a zero factor)."""
import itertools

import numpy as np
import pytest

from test_model_structure import compare

LAWS = list(itertools.product([0, 1, 3], [0, 1, 2, 3]))  # storeyLaw x diaphragmLaw (3 bilinear; no pinched storey)


def operating_point(seed):
    """40 states (per floor: u_floor, v_floor, z_storey, u_diaph, v_diaph, z_diaph, work_storey,
    work_diaph) and the inputs, all nonzero, |z| < 1, velocities of both signs."""
    rng = np.random.default_rng(seed)
    states = []
    for _ in range(5):
        u, v = rng.uniform(-0.02, 0.02), rng.uniform(-0.2, 0.2)
        y, w = u + rng.uniform(-0.01, 0.01), rng.uniform(-0.2, 0.2)
        states += [u, v, rng.uniform(-0.8, 0.8), y, w, rng.uniform(-0.8, 0.8), rng.uniform(1, 5), rng.uniform(1, 5)]
    inputs = dict(ag=rng.uniform(-2, 2), **{f"F_{kind}_{i}": rng.uniform(-500, 500)
                                            for kind in ("wall", "above") for i in range(1, 6)})
    return dict(states=tuple(states), inputs=inputs)


@pytest.mark.parametrize("storey_law,diaphragm_law", LAWS)
def test_building_model_structure(build_dir, storey_law, diaphragm_law):
    integers = dict(nStoreys=5, storeyLaw=storey_law, diaphragmLaw=diaphragm_law)
    cases = [(integers, operating_point(seed)) for seed in (1, 2)]
    missing, extra = compare(build_dir / "Building.fmu", cases)
    if extra:
        print("Building: declared but not seen at any operating point:", extra)
    assert not missing, "\n".join(missing)
