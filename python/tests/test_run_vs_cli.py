"""Every bundled case through both `flexfem run` (the binary) and `flexfem.run` (the package):
the results are equal, floats exactly or to 1e-12 relative (results hold no timing fields).
The sweep cases go through `flexfem sweep` and `flexfem.sweep`: the same lines, by index (rows
read key by key and as plain dicts), and their tables: `Sweep.columns()` against `--csv`."""

import json

import pytest

import flexfem
from conftest import CASES, cli, cli_json, column_differences, differences

ALL = sorted(p.name for p in CASES.glob("*.json"))
SWEEPS = [n for n in ALL if json.loads((CASES / n).read_text()).get("analysis") == "sweep"]
SINGLE = [n for n in ALL if n not in SWEEPS]


def test_every_bundled_case_is_covered():
    # 52 bundled cases when this suite was written, of which 4 are sweeps.
    assert len(ALL) >= 52 and len(SWEEPS) >= 4
    assert len(SINGLE) + len(SWEEPS) == len(ALL)


@pytest.mark.parametrize("name", SINGLE)
def test_run_equals_cli(name):
    want = cli_json("run", CASES / name)
    got = flexfem.run(CASES / name)
    assert differences(want, got) == []


@pytest.mark.parametrize("name", SWEEPS)
def test_sweep_equals_cli(name, tmp_path):
    code, out, err = cli("sweep", CASES / name, "--csv", tmp_path / "t.csv")
    assert code == 0, err
    want = sorted((json.loads(line) for line in out.splitlines()), key=lambda r: r["index"])
    got = list(flexfem.sweep(CASES / name))
    assert [r["index"] for r in got] == list(range(len(want)))
    # The rows read through their own keys, and as plain dicts.
    assert differences(want, got) == []
    assert differences(want, [r.to_dict() for r in got]) == []
    # The table as numpy columns, cell by cell against the command line's --csv.
    s = flexfem.sweep(CASES / name)
    assert column_differences(tmp_path / "t.csv", s.columns()) == []
