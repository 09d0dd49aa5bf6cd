#!/usr/bin/env python3
"""Converged CalculiX peak stresses of corner-filleted notches swept one dimension at a time
(not used by the build; read by tests/hinge_peak_sweep.rs).

The designs of `tools/ccx_heldout_doe.py` sample the corner-filleted family in Latin hypercubes;
their peaks left a trend in flexfem's error that a hypercube of 30 rows cannot resolve (long
mid-width leaves with sharp fillets read low). This sweep resolves it: t = 1 mm, blank length =
blank height, and around R/t = 0.5, w/t = 6, h/t = 4:

- narrow notches (w = t): R/t 0.5, 0.7, 1, 1.5, 2.5 at flat/t 1 and 5 (h/t = max(4, 2R/t + 3));
- R/t = 0.5, h/t = 4: flat/t 0.5, 1, 2, 3, 5, 8 by w/t 1, 2, 3, 4, 6, 9, 14, 20; flat/t 12 at
  w/t 6, 9, 14; flat/t 20 at w/t 14;
- h/t 2.5, 3, 6, 8 at flat/t 5, w/t 6; h/t 2.5, 6 at flat/t 1, w/t 14;
- R/t = 1, h/t = 5: flat/t 1, 3, 8 by w/t 1, 3, 6, 14;
- R/t 0.7, 1, 1.5 at flat/t 5, w/t 6; R/t 0.7 at flat/t 1 and 5, w/t 6 and 14; R/t 1.5 at
  flat/t 1, w/t 6 and 14 (h/t 6).

Each is `tools/ccx_peak_stress.py`'s symmetric eighth at k = 12 (the converged peaks of the
designs), one line per geometry in `tools/ccx_peak_sweep_k12.jsonl`; it resumes.

    OMP_NUM_THREADS=1 python3 tools/ccx_peak_sweep.py [--jobs 2]
"""

import argparse
import json
import os
import sys
from multiprocessing import Pool

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ccx_peak_stress import run  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "ccx_peak_sweep_k12.jsonl")


def grid():
    rows = []

    def add(r, flat, w, h):
        row = {"l": round(flat + 2 * r, 4), "R": r, "t": 1.0, "w": float(w), "h": float(h), "blank_length": float(h)}
        if row not in rows:
            rows.append(row)

    for r in (0.7, 1.0, 1.5, 2.5):
        for flat in (1, 5):
            add(r, flat, 1, max(4, 2 * r + 3))
    for flat in (0.5, 1, 2, 3, 5, 8):
        for w in (1, 2, 3, 4, 6, 9, 14, 20):
            add(0.5, flat, w, 4)
    for w in (6, 9, 14):
        add(0.5, 12, w, 4)
    add(0.5, 20, 14, 4)
    for h in (2.5, 3, 6, 8):
        add(0.5, 5, 6, h)
    for h in (2.5, 6):
        add(0.5, 1, 14, h)
    for flat in (1, 3, 8):
        for w in (1, 3, 6, 14):
            add(1.0, flat, w, 5)
    for r in (0.7, 1.0, 1.5):
        add(r, 5, 6, 4)
    for flat in (1, 5):
        for w in (6, 14):
            add(0.7, flat, w, 4)
    for w in (6, 14):
        add(1.5, 1, w, 6)
    return rows


def key(row):
    return tuple(float(row[k]) for k in ("l", "R", "t", "w", "h", "blank_length"))


def job(row):
    return run("corner_filleted", dict(row), 4.0, 12.0, 0.4, 0.33, 72000.0, None)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    done = set()
    if os.path.exists(OUT):
        done = {key(r) for r in map(json.loads, open(OUT))}
    todo = [r for r in grid() if key(r) not in done]
    with Pool(a.jobs) as pool, open(OUT, "a") as f:
        for r in pool.imap(job, todo):
            f.write(json.dumps(r) + "\n")
            f.flush()
            print(r["l"], r["R"], r["w"], r["h"], r["stress_per_moment_nodal"], flush=True)


if __name__ == "__main__":
    main()
