"""rwref: independent Python reference solver of the RockingWall model (docs/model.md).

    from rwref import Params, simulate, inputs
    res = simulate(Params(support="flexibleTop", hinge_law="dohertyHinge", Kd=1e5),
                   inputs.gaussian(0.04, 1.0), 10.0)
"""
from . import inputs
from .params import Params, table_5_1, WALLS, TABLE_5_1_PAPER
from .solver import simulate, Result, ZenoError

__all__ = ["Params", "simulate", "inputs", "Result", "ZenoError", "table_5_1", "WALLS", "TABLE_5_1_PAPER"]
