"""Shared helpers of the Python suite: the repository, the command-line binary, and a
comparison of results with a relative tolerance."""

import csv
import json
import math
import os
import subprocess
from collections.abc import Mapping
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
CASES = ROOT / "cases"


def cli_binary() -> Path:
    """The `flexfem` binary the suite compares with: $FLEXFEM_BIN, else target/release."""
    path = Path(os.environ.get("FLEXFEM_BIN", ROOT / "target" / "release" / "flexfem"))
    if not path.is_file():
        pytest.fail(f"{path} not built: run `cargo build --release` first (or set FLEXFEM_BIN)")
    return path


def cli(*args, cwd=ROOT):
    """Runs the command line; returns (exit code, stdout, stderr)."""
    p = subprocess.run([str(cli_binary()), *map(str, args)], cwd=cwd, capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def cli_json(*args):
    """The JSON result of `flexfem ARGS` (exit 0 required)."""
    code, out, err = cli(*args)
    assert code == 0, err
    return json.loads(out)


def cli_error_path(stderr: str) -> str:
    """The JSON path in the command line's `error: case file error at `PATH`: ...` message."""
    marker = "case file error at `"
    start = stderr.index(marker) + len(marker)
    return stderr[start : stderr.index("`", start)]


def differences(want, got, path="", rel=1e-12, out=None):
    """Where two results differ: paths whose types, keys, lengths or values differ (floats by
    more than `rel` relative to the larger magnitude). Mappings (dicts, sweep rows) compare
    key by key, through their own `[]`."""
    out = [] if out is None else out
    if isinstance(want, Mapping) and isinstance(got, Mapping):
        if list(want) != list(got):
            out.append(f"{path}: keys {list(want)} vs {list(got)}")
        for k in want:
            if k in got:
                differences(want[k], got[k], f"{path}.{k}", rel, out)
    elif isinstance(want, list) and isinstance(got, list):
        if len(want) != len(got):
            out.append(f"{path}: length {len(want)} vs {len(got)}")
        else:
            for i, (w, g) in enumerate(zip(want, got)):  # zip-checked: lengths compared above
                differences(w, g, f"{path}[{i}]", rel, out)
    elif isinstance(want, float) or isinstance(got, float):
        if not (isinstance(want, (int, float)) and isinstance(got, (int, float))):
            out.append(f"{path}: {want!r} vs {got!r}")
        elif not math.isclose(want, got, rel_tol=rel, abs_tol=0.0) and want != got:
            out.append(f"{path}: {want!r} vs {got!r}")
    elif type(want) is not type(got) or want != got:
        out.append(f"{path}: {want!r} vs {got!r}")
    return out


def column_differences(csv_path, columns):
    """Where `Sweep.columns()` differs from the table `flexfem sweep --csv` wrote: the column
    names (the header without its units) and every cell (numbers exactly: the CSV writes the
    shortest text that round-trips; an empty cell is NaN or None)."""
    with open(csv_path, newline="") as f:
        header, *lines = list(csv.reader(f))
    out = []
    names, seen = [], {}
    for h in header:  # a repeated name gets .1, .2 (as pandas.read_csv names it)
        name = h.split(" [")[0]
        seen[name] = seen.get(name, -1) + 1
        names.append(name if seen[name] == 0 else f"{name}.{seen[name]}")
    if names != list(columns):
        return [f"columns {names} vs {list(columns)}"]
    for k, (name, a) in enumerate(columns.items()):
        if len(a) != len(lines):
            out.append(f"{name}: {len(a)} cells for {len(lines)} lines")
            continue
        for i, line in enumerate(lines):
            cell, got = line[k], a[i]
            if cell == "":
                ok = got is None or (isinstance(got, float) and math.isnan(got))
            elif isinstance(got, str):
                ok = got == cell
            else:
                ok = json.loads(cell) == got
            if not ok:
                out.append(f"{name}[{i}]: {cell!r} vs {got!r}")
    return out
