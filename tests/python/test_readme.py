"""Every command and Python example of the README runs, as a user would type it: commands in a
fresh folder with `rockingwall` on the PATH, Python blocks from the repository's root. Lines that
are not run here say why in NOT_RUN_HERE, and the README must hold exactly those lines (so a new
command cannot slip past untested)."""
import os
import pathlib
import re
import shlex
import subprocess
import sys

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
BIN = pathlib.Path(sys.executable).parent

NOT_RUN_HERE = {
    "scripts/run_tests.sh": "the test command itself (CI runs it; running it here would recurse)",
    "pip install .": "test_install.py runs exactly this in a fresh virtual environment",
}


def blocks(language):
    text = (REPO / "README.md").read_text()
    return re.findall(rf"```{language}\n(.*?)```", text, re.S)


def commands(block):
    out = []
    for line in block.splitlines():
        command = line.split("  #")[0].strip()
        if command:
            out.append(command)
    return out


def test_the_readme_names_exactly_the_commands_not_run_here():
    every = [c for block in blocks("sh") for c in commands(block)]
    assert {c for c in every if c in NOT_RUN_HERE} == set(NOT_RUN_HERE)


@pytest.mark.parametrize("index", range(len(blocks("sh"))))
def test_readme_commands_run(index, tmp_path):
    """One block's commands in order, in one fresh folder (a later command may read what an
    earlier one wrote, as in the README)."""
    env = dict(os.environ, PATH=f"{BIN}{os.pathsep}{os.environ['PATH']}")
    (tmp_path / "examples").symlink_to(REPO / "examples")  # files of the repository, as in a clone
    for command in commands(blocks("sh")[index]):
        if command in NOT_RUN_HERE:
            continue
        argv = shlex.split(command)
        cwd = tmp_path
        if argv[0].startswith("scripts/"):
            argv[0], cwd = str(REPO / argv[0]), REPO
        proc = subprocess.run(argv, cwd=cwd, env=env, capture_output=True, text=True, timeout=1200)
        assert proc.returncode == 0, f"{command}\n{proc.stdout[-2000:]}\n{proc.stderr[-3000:]}"
        assert "Traceback" not in proc.stderr, command


@pytest.mark.parametrize("index", range(len(blocks("python"))))
def test_readme_python_example_runs(index):
    code = blocks("python")[index]
    proc = subprocess.run([sys.executable, "-c", code], cwd=REPO, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-3000:]
