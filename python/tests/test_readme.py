"""The README's "From Python" example runs and prints the output the README shows."""

import subprocess
import sys

from conftest import ROOT


def blocks():
    section = (ROOT / "README.md").read_text().split("\n## From Python\n", 1)[1].split("\n## ", 1)[0]
    code = section.split("```python\n", 1)[1].split("```", 1)[0]
    output = section.split("```text\n", 1)[1].split("```", 1)[0]
    return code, output


def test_readme_from_python_example_prints_what_the_readme_shows():
    code, want = blocks()
    p = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert p.stdout == want
