"""docs/codes.md stays true: its worked example, run as written, prints exactly the output the
page shows."""
import pathlib
import re
import subprocess
import sys

PAGE = pathlib.Path(__file__).resolve().parents[2] / "docs" / "codes.md"


def test_the_worked_example_prints_what_the_page_shows():
    text = PAGE.read_text()
    code = re.search(r"## Worked example.*?```python\n(.*?)```", text, re.S).group(1)
    shown = re.search(r"prints \(a test runs this block and compares\):\n\n```\n(.*?)```", text, re.S).group(1)
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout == shown
