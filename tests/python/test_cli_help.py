"""Every command's --help shows its description as written: the examples a user copies stay one
command a line."""
import importlib

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
