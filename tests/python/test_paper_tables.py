"""`rockingwall paper`'s printed tables: columns a reader can follow."""
from rockingwall import paper_tables


def test_the_models_column_holds_the_longest_model(capsys):
    """`rockingwall paper --quick` printed '2DOF semiRigidHinge    500' beside '1DOF' rows in a
    model column six characters wide: every 2DOF row's K_d stood further right than its header.
    The column is as wide as its longest model, so each K_d ends under 'Kd'."""
    rows = [["5.4", 1, "elce 50%", "1DOF", "", "s1", 0.044, 0.043],
            ["5.4", 1, "elce 50%", "2DOF semiRigidHinge", 500, "s1", 0.0371, 0.043],
            ["5.4", 1, "elce 50%", "2DOF dohertyHinge", 50, "s2", 0.0159, 0.019]]
    paper_tables.print_table("Table 5.4", rows)
    header, *lines = capsys.readouterr().out.strip().splitlines()[1:]
    end = header.index("Kd") + len("Kd")
    assert [line[end - 3:end] for line in lines] == ["   ", "500", " 50"]
    qty = header.index("qty") + len("qty")
    assert [line[qty - 2:qty] for line in lines] == ["s1", "s1", "s2"]
