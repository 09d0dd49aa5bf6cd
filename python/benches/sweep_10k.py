"""Wall time of a 10,000-design hinge sweep from Python (flexfem.sweep) against the command line
(`flexfem sweep CASE > /dev/null`), best of N runs each.

Like with like: the command line writes every value of every row (its JSON lines); Python hands
out every row and reads every line whole into the table a notebook works with —
`Sweep.columns()`, one numpy array per column: every number, flag and text leaf of the result,
the index and the varied values (checked below: 105 of a hinge line's 113 values; the other 8
are the design hash and the 7 model notes, text that is the same for every design, which the
table leaves out as `flexfem sweep --csv` does). With `--dicts` it also times every row turned
into plain dicts (`row.to_dict()`: a Python object for every value, what every row cost before
rows were read lazily), for reference.

The issue asks for Python within 1.5× the command line (full rows), in wall time. The CPU time
(user + system, all threads) of both is printed too: on a loaded machine it is the steadier
figure. Run after building the
wheel and `cargo build --release`; measure with the same profile for both (the wheel links the
same library build): python python/benches/sweep_10k.py [--runs N] [--threads T] [--dicts]
"""

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import flexfem

ROOT = Path(__file__).resolve().parents[2]
BASE = {
    "analysis": "hinge",
    "material": "Al7075",
    "hinge": {"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20},
}
# 100 × 100 = 10,000 designs.
VARY = {"hinge.t": {"from": 0.5, "to": 3.0, "steps": 100}, "hinge.R": {"from": 2, "to": 12, "steps": 100}}
N = 10_000


def leaves(v, tabled=False):
    """Number of scalar values in a JSON value (what the line writes); with `tabled`, those
    the table holds (not in arrays of more than 16 elements or holding text)."""
    if isinstance(v, dict):
        return sum(leaves(x, tabled) for x in v.values())
    if isinstance(v, list):
        if tabled and (len(v) > 16 or any(isinstance(x, str) for x in v)):
            return 0
        return sum(leaves(x, tabled) for x in v)
    return 1


def children_cpu() -> float:
    """CPU seconds (user + system) of the finished child processes."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def python_columns(case, fields, threads):
    s = flexfem.sweep(case, fields=fields, threads=threads)
    cols = s.columns()
    assert len(s.rows()) == N and all(len(a) == N for a in cols.values())
    return s, cols


def python_dicts(case, fields, threads):
    rows = [r.to_dict() for r in flexfem.sweep(case, fields=fields, threads=threads)]
    assert len(rows) == N and all("result" in r for r in rows)
    return rows


def main() -> float:
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--threads", type=int, default=None)
    ap.add_argument("--dicts", action="store_true", help="also time rows as plain dicts (reference)")
    args = ap.parse_args()
    binary = Path(os.environ.get("FLEXFEM_BIN", ROOT / "target" / "release" / "flexfem"))
    with tempfile.TemporaryDirectory() as tmp:
        case = Path(tmp) / "hinge_sweep_10k.json"
        case.write_text(json.dumps({"analysis": "sweep", "base": BASE, "vary": VARY}))
        threads = [] if args.threads is None else ["--threads", str(args.threads)]
        ratios = {}
        # Full rows (every result field, as `flexfem sweep` prints them), then two fields only.
        for label, fields in (("full rows", None), ("fields k_bend,max_rotation_deg", ["k_bend", "max_rotation_deg"])):
            extra = [] if fields is None else ["--fields", ",".join(fields)]
            ways = [("columns", python_columns)] + ([("dicts", python_dicts)] if args.dicts else [])
            cli_times, py_times = [], {w: [] for w, _ in ways}
            cli_cpu, py_cpu = [], {w: [] for w, _ in ways}
            # Untimed check of what Python reads: a column per scalar of a line the table holds,
            # besides design_hash (text, not a column), plus `error`.
            out = subprocess.run(
                [str(binary), *threads, "sweep", str(case), *extra], capture_output=True, check=True
            )
            line = json.loads(out.stdout.splitlines()[0])
            per_row, tabled = leaves(line), leaves(line, tabled=True)
            _, cols = python_columns(case, fields, args.threads)
            assert len(cols) == tabled, (len(cols), tabled)
            for _ in range(args.runs):
                t0, c0 = time.perf_counter(), children_cpu()
                subprocess.run(
                    [str(binary), *threads, "sweep", str(case), *extra],
                    stdout=subprocess.DEVNULL,
                    stderr=subprocess.DEVNULL,
                    check=True,
                )
                cli_times.append(time.perf_counter() - t0)
                cli_cpu.append(children_cpu() - c0)
                for way, f in ways:
                    t0, c0 = time.perf_counter(), time.process_time()
                    f(case, fields, args.threads)
                    py_times[way].append(time.perf_counter() - t0)
                    py_cpu[way].append(time.process_time() - c0)
            cli, cli_c = min(cli_times), min(cli_cpu)
            for way, times in py_times.items():
                py, py_c = min(times), min(py_cpu[way])
                ratios[(label, way)] = py / cli
                print(
                    f"10,000 hinge designs, {label}, Python {way}: command line {cli:.3f} s, "
                    f"Python {py:.3f} s (best of {args.runs}); ratio {py / cli:.2f} "
                    f"(CPU time {cli_c:.3f} s vs {py_c:.3f} s: {py_c / cli_c:.2f}); "
                    f"{per_row} values a line, {tabled - 1} read into numpy"
                )
    return ratios[("full rows", "columns")]


if __name__ == "__main__":
    sys.exit(0 if main() <= 1.5 else 1)
