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
