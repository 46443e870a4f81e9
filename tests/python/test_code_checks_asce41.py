"""ASCE/SEI 41-17's h/t check of URM walls out of plane (rockingwall.codes.asce41): the table's
cells, its S_X1 bands at their edges, and the verdict."""
import pytest

from rockingwall.codes import asce41

# storey -> permissible h/t for S_X1 <= 0.24 g, 0.24-0.37 g, > 0.37 g (as the module's docs state it)
TABLE = {"one_storey_building": (20, 16, 13), "first_storey": (20, 18, 15),
         "top_storey": (14, 14, 9), "other_storey": (20, 16, 13)}


@pytest.mark.parametrize("storey", sorted(TABLE))
@pytest.mark.parametrize("s_x1, column", [(0.0, 0), (0.24, 0), (0.2401, 1), (0.37, 1), (0.3701, 2), (1.2, 2)])
def test_every_cell_and_band_edge(storey, s_x1, column):
    r = asce41.check_wall(3.0, 0.2, storey, s_x1)
    assert r.limit == TABLE[storey][column]
    assert r.band == asce41.BANDS[column]


def test_the_assessors_wall():
    # h/t = 3.6 / 0.23 = 15.65: passes as an intermediate storey at S_X1 = 0.3 g (limit 16), fails in the
    # top storey (14) and at S_X1 = 0.5 g (13)
    assert asce41.check_wall(3.6, 0.23, "other_storey", 0.3).verdict == "pass"
    top = asce41.check_wall(3.6, 0.23, "top_storey", 0.3)
    assert top.h_over_t == pytest.approx(3.6 / 0.23) and top.verdict == "fail"
    assert asce41.check_wall(3.6, 0.23, "other_storey", 0.5).verdict == "fail"


def test_a_wall_exactly_at_the_limit_passes():
    assert asce41.check_wall(2.8, 0.2, "top_storey", 0.1).verdict == "pass"        # 14 = 14


def test_the_table_is_marked_unconfirmed():
    r = asce41.check_wall(3.6, 0.23, "top_storey", 0.3)
    assert [ref.status for ref in r.refs] == ["unconfirmed"]
    assert r.notes[0].startswith("UNCONFIRMED")


@pytest.mark.parametrize("args, words", [
    ((3.6, 0.23, "attic", 0.3), "storey"),
    ((3.6, 0.23, "top_storey", -0.1), "S_X1 = -0.1"),
    ((3.6, 0.0, "top_storey", 0.3), "t = 0"),
    ((0.0, 0.23, "top_storey", 0.3), "h = 0"),
])
def test_bad_inputs_are_refused_by_name(args, words):
    with pytest.raises(ValueError, match=words):
        asce41.check_wall(*args)
