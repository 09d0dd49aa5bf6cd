"""Wall time of a 10,000-design hinge sweep from Python (flexfem.sweep, every row handed out
as a dict) against the command line (`flexfem sweep CASE > /dev/null`), best of N runs each.

The issue asks for Python within 1.5× the command line. Run after building the wheel and
`cargo build --release`; measure with the same profile for both (the wheel links the same
library build): python python/benches/sweep_10k.py [--runs N] [--threads T]
"""

import argparse
import json
import os
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


def main() -> float:
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--threads", type=int, default=None)
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
            cli_times, py_times = [], []
            for _ in range(args.runs):
                t0 = time.perf_counter()
                subprocess.run(
                    [str(binary), *threads, "sweep", str(case), *extra],
                    stdout=subprocess.DEVNULL,
                    stderr=subprocess.DEVNULL,
                    check=True,
                )
                cli_times.append(time.perf_counter() - t0)
                t0 = time.perf_counter()
                rows = list(flexfem.sweep(case, fields=fields, threads=args.threads))
                py_times.append(time.perf_counter() - t0)
                assert len(rows) == 10_000 and all("result" in r for r in rows)
            cli, py = min(cli_times), min(py_times)
            ratios[label] = py / cli
            print(
                f"10,000 hinge designs, {label}: command line {cli:.3f} s, Python {py:.3f} s "
                f"(best of {args.runs}); ratio {py / cli:.2f}"
            )
    return ratios["full rows"]


if __name__ == "__main__":
    sys.exit(0 if main() <= 1.5 else 1)
