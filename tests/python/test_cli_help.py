"""Every command's --help shows its description as written: the examples a user copies stay one
command a line."""
import importlib
import shlex

import pytest

from rockingwall.cli import DELEGATED, main

BUILT_IN = {"run": "rockingwall.commands.run", "assess": "rockingwall.commands.assess",
            "building": "rockingwall.commands.building", "info": "rockingwall.commands.info"}


@pytest.mark.parametrize("command", sorted(BUILT_IN) + sorted(DELEGATED))
def test_help_keeps_the_descriptions_lines(command, capsys):
    """`rockingwall building --help` ran its three examples into one paragraph ('... --pga 0.5
    rockingwall building house.toml elcentro --scale 1 --json rockingwall ...'): the commands built
    into the main parser were reflowed, the delegated ones were not. Each line of a command's
    description now appears in its help as it is written."""
    module = BUILT_IN.get(command) or DELEGATED[command][0]
    described = [line.rstrip() for line in importlib.import_module(module).__doc__.splitlines() if line.strip()]
    with pytest.raises(SystemExit) as exit_:
        main([command, "--help"])
    assert exit_.value.code == 0
    shown = {line.rstrip() for line in capsys.readouterr().out.splitlines()}
    missing = [line for line in described if line not in shown]
    assert not missing, missing


def test_top_help_lists_every_command_apart_from_its_text(capsys):
    """`rockingwall --help` printed 'couple-buildingwalls in a Building FMU, ...': the delegated
    commands' list was padded to nine characters, and couple-building has fifteen. Each delegated
    command now stands on its own line with its text at least two spaces after it."""
    with pytest.raises(SystemExit) as exit_:
        main(["--help"])
    assert exit_.value.code == 0
    lines = capsys.readouterr().out.splitlines()
    for name, (_, text) in DELEGATED.items():
        rows = [line.split() for line in lines if line.strip().startswith(name + " ")]
        assert [row[0] for row in rows] == [name], (name, lines)
        assert any(line.rstrip().endswith(text) and f"{name}  " in line for line in lines), name


def test_assess_takes_the_records_after_its_intensities(tmp_path):
    """`rockingwall assess --help`'s first example ends '--pga 0.1 0.2 0.35 0.5 fema --out ...', and
    it failed: 'argument --pga: intensity 'fema': not a number' (argparse gave every token after
    --pga to it). Records after a list of numbers are records now, with the same cases as the
    records written first; a token that starts like a number and is none is still refused."""
    import pandas as pd
    wall = ["--b", "230mm", "--h", "3.2", "--W", "14.08kN/m", "--psi", "0.2", "--ensemble", "0"]
    pulse = "gaussian:0.04,1"
    first, after = tmp_path / "first", tmp_path / "after"
    assert main(["assess", pulse, *wall, "--kd-values", "30kN/m/m", "--pga", "0.1", "0.2", "--out", str(first)]) == 0
    assert main(["assess", *wall, "--kd-values", "30kN/m/m", "--pga", "0.1", "0.2", pulse, "--out", str(after)]) == 0
    assert main(["assess", *wall, "--pga", "0.1", "--kd-values", "30kN/m/m", pulse, "--out", str(after)]) == 0
    pd.testing.assert_frame_equal(pd.read_csv(first / "cases.csv").iloc[:1], pd.read_csv(after / "cases.csv"))
    with pytest.raises(SystemExit) as exit_:
        main(["assess", pulse, *wall, "--pga", "0.1", "0.2x", "--out", str(tmp_path / "bad")])
    assert exit_.value.code == 2


def test_records_before_lists_moves_only_what_follows_a_number_list():
    from rockingwall.commands.common import records_before_lists
    lists = ("--pga", "--kd-values")
    assert records_before_lists(["assess", "--pga", "0.1", "0.2", "fema", "--out", "x"], lists) == [
        "assess", "fema", "--pga", "0.1", "0.2", "--out", "x"]
    assert records_before_lists(["assess", "--kd-values", "30kN/m/m", "-5", "a.AT2", "b.csv", "--pga", "0.1"],
                                lists) == ["assess", "a.AT2", "b.csv", "--kd-values", "30kN/m/m", "-5", "--pga", "0.1"]
    unchanged = ["assess", "elcentro", "--out", "results", "--pga", "0.3", "--table", "md", "--", "odd"]
    assert records_before_lists(unchanged, lists) == unchanged
    assert records_before_lists(["assess", "--pga=0.1", "fema"], lists) == ["assess", "--pga=0.1", "fema"]


def help_examples():
    """(command, argv) of every example line in the descriptions of the commands with a parser of
    their own ('rockingwall ...', continued over a trailing backslash); the lines with [optional]
    parts are a syntax, not an example. ida, animate, paper and demo parse in their main only:
    their tests run them."""
    out = []
    for command, module in {**BUILT_IN, **{name: m for name, (m, _) in DELEGATED.items()}}.items():
        if command not in BUILT_IN and not hasattr(importlib.import_module(module), "parse_args"):
            continue
        text = importlib.import_module(module).__doc__.replace("\\\n", " ")
        for line in text.splitlines():
            line = line.split("  #")[0].strip()
            if line.startswith(f"rockingwall {command} ") and "[" not in line:
                out.append((command, shlex.split(line)[1:]))
    return out


@pytest.mark.parametrize("command, argv", help_examples())
def test_every_help_example_parses(command, argv):
    """assess --help's first example did not parse (its records after --pga's numbers). Every
    example a --help shows now parses as the command's own arguments."""
    from rockingwall import cli
    if command in BUILT_IN:
        assert cli.parse(argv).command is not None
    else:
        importlib.import_module(DELEGATED[command][0]).parse_args(argv[1:])


@pytest.mark.parametrize("command,default", [("run", "default 0: none)"), ("assess", "default 100; 0: none)")])
def test_ensemble_help_says_its_default_once(command, default, capsys):
    """`rockingwall run --help` said '--ensemble N  members per case (default 0: none; 0: none)'."""
    with pytest.raises(SystemExit):
        main([command, "--help"])
    text = " ".join(capsys.readouterr().out.split())
    said = text[text.index("--ensemble N members"):][:60]
    assert said.startswith(f"--ensemble N members per case ({default}"), said
