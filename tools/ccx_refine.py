#!/usr/bin/env python3
"""Re-runs every CalculiX hinge reference at a second mesh density (not used by the build or tests).

The references in `ccx_reference_results.jsonl` and `ccx_heldout{,2,3}_results.jsonl` were solved
with n = 4 element sizes across the local thickness. Refining one of them to n = 5, 6 and 8
(`ccx_refine_convergence.jsonl`) showed that n = 4 is not converged to 0.5 % everywhere and that
the stiffnesses converge as h² (the clamped face's edges are singular), so each reference is
re-solved at n = 3 with everything else unchanged (the blank size cap; `ccx_reference.run` as before) and
the pair is extrapolated, k∞ = k₄ + (k₄ − k₃)·3²/(4² − 3²) (Richardson, order 2; the order
measured on the rows of `ccx_reference_convergence.jsonl` and on that hinge is 1.85–2.5). The peak
nodal-averaged stress is not extrapolated: from n = 3 to 4 it moves either way (its maximum node
changes), so it stays the n = 4 value and its discretisation error is measured on the n = 6 rows.

    OMP_NUM_THREADS=1 python3 tools/ccx_refine.py [--jobs 2] [--n 3]

`--n 6 --rows FILE:INDEX,...` re-solves chosen references at a finer mesh instead
(`tools/ccx_refine_n6_results.jsonl`): first every reference with at most 30,000 unknowns at n = 4,
to check the extrapolation; then every corner-filleted one that is short (l/t <= 2.75) or wide
(w/l > 3), after the n = 3/4 extrapolation of a short wide leaf with small fillets
(l2.7/R0.7/t1.35/w18.55, `ccx_heldout6_results.jsonl` line 23) was found 3.1 % below its n = 4/6
one in bending (n = 3 is too coarse there for the asymptotic rate); and, from the seventeenth
design on, every reference whose n = 3/4 extrapolation lies more than 5 % from n = 4 in bending (a
convergence criterion, blind to the model: on two circular notches in tall short blanks of the
seventeenth design it was 40 % and 14.5 %; on no earlier reference without an n = 6 line above
5 %). Where a reference has an n = 6 line, tests/hinge_ccx_reference.rs compares with the n = 4/6
extrapolation. Where n = 4 and n = 6 differ by more than 5 % in bending, n = 4 is not yet in the
asymptotic range (the eighteenth design's circular R1.1/t0.35/w5.8/h7.2: 2733, 2085, 2081 N·mm/rad
at n = 4, 6, 8): `--n 8 --rows ...` re-solves it at n = 8 (`tools/ccx_refine_n8_results.jsonl`)
and the test takes the n = 6/8 extrapolation. Where n = 6 and n = 8 still differ by more than
5 % (the nineteenth design's circular R1.1/t0.5/w5.6/h9.05: 6194, 5195, 4736, 4731 N·mm/rad at
n = 4, 6, 8, 10), `--n 10 --rows ...` re-solves it at n = 10 (`tools/ccx_refine_n10_results.jsonl`,
491,082 unknowns, 37 min on one core) and the test takes the n = 8/10 extrapolation.

`--design tools/ccx_heldout4_doe.json` solves a fresh design's rows at n = 4 (the earlier designs'
`_results.jsonl` files have the same fields), before `--n 3` re-solves them.

`tools/ccx_refine_convergence.jsonl` holds the finer solves of the hinge that prompted this
(l5.95/R1.45/t1.95/w10.15/h11.9, `ccx_heldout2_results.jsonl` line 14): n = 5 and 8, and n = 4 and
6 with the blank size cap halved (h/6), which moves n = 4 by -0.42 % in bending and n = 6 by 0.01 %;
and the small-fillet hinge l5/R0.5/t1/w1/h4 (`ccx_reference_results.jsonl` line 35) at n = 8 and 10,
whose nodal-averaged peak stress is still rising (n = 4, 6, 8, 10: 7.018, 7.335, 7.382, 7.449
MPa/(N·mm)) while its bending stiffness has settled (1145.8, 1143.3, 1142.0, 1141.1 N·mm/rad).

Appends one JSON line per reference to `tools/ccx_refine_n3_results.jsonl` (its "source" file and
"index" there, then ccx_reference.py's fields); rows already present are skipped, so it resumes.
"""

import argparse
import json
import os
import sys
import time
from multiprocessing import Pool

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ccx_reference import run  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCES = [
    "ccx_reference_results.jsonl",
    "ccx_heldout_results.jsonl",
    "ccx_heldout2_results.jsonl",
    "ccx_heldout3_results.jsonl",
    "ccx_heldout4_results.jsonl",
    "ccx_heldout5_results.jsonl",
    "ccx_heldout6_results.jsonl",
    "ccx_heldout7_results.jsonl",
    "ccx_heldout8_results.jsonl",
    "ccx_heldout9_results.jsonl",
    "ccx_heldout10_results.jsonl",
    "ccx_heldout11_results.jsonl",
    "ccx_heldout12_results.jsonl",
    "ccx_heldout13_results.jsonl",
    "ccx_heldout14_results.jsonl",
    "ccx_heldout15_results.jsonl",
    "ccx_heldout16_results.jsonl",
    "ccx_heldout17_results.jsonl",
    "ccx_heldout18_results.jsonl",
    "ccx_heldout19_results.jsonl",
]
# The fields of a results line that are not the hinge's geometry.
NOT_GEOMETRY = {
    "type", "nu", "E", "n", "hmax", "dofs", "high_order_optimize", "second_order_linear", "solver", "doe_index", "seconds",
}


def by_reference(path):
    """The lines of a re-solve file keyed by the reference they re-solve, (source, index); {} if
    the file does not exist yet."""
    if not os.path.exists(path):
        return {}
    return {(r["source"], r["index"]): r for r in map(json.loads, open(path))}


def job(args):
    source, index, row, n = args
    p = {k: v for k, v in row.items() if k not in NOT_GEOMETRY and not k.startswith(("k_", "stress_"))}
    start = time.time()
    out = run(row["type"], p, n, row["nu"], row["E"], row["hmax"])
    return {"source": source, "index": index, **out, "seconds": round(time.time() - start, 1)}


def design_job(args):
    index, row = args
    p = {k: v for k, v in row.items() if k not in ("type", "regime")}
    start = time.time()
    out = run(row["type"], p, 4.0, 0.33)
    return {**out, "doe_index": index, "seconds": round(time.time() - start, 1)}


def solve_design(path, jobs):
    """Solves each row of a design file (`tools/ccx_heldout*_doe.json`) at n = 4, as the earlier
    designs were, into the matching `_results.jsonl` (in the design's order; resumes)."""
    out_path = path.replace("_doe.json", "_results.jsonl")
    design = json.load(open(path))
    done = {}
    if os.path.exists(out_path):
        done = {r["doe_index"]: r for r in map(json.loads, open(out_path))}
    todo = [(i, row) for i, row in enumerate(design) if i not in done]
    with Pool(jobs) as pool:
        for r in pool.imap_unordered(design_job, todo):
            done[r["doe_index"]] = r
            print("design row", r["doe_index"], r["seconds"], "s", flush=True)
            with open(out_path, "w") as f:
                for i in sorted(done):
                    f.write(json.dumps(done[i]) + "\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--n", type=float, default=3.0)
    ap.add_argument("--design", help="solve a design file's rows at n = 4 instead")
    ap.add_argument("--report", action="store_true", help="print the extrapolation summary and stop")
    ap.add_argument("--rows", help="only these references: FILE:INDEX,FILE:INDEX,...")
    a = ap.parse_args()
    if a.report:
        return report()
    if a.design:
        return solve_design(a.design, a.jobs)
    only = None
    if a.rows:
        only = {(f, int(i)) for f, i in (x.rsplit(":", 1) for x in a.rows.split(","))}
    out_path = os.path.join(HERE, f"ccx_refine_n{a.n:g}_results.jsonl")
    done = by_reference(out_path)
    todo = []
    for source in filter(lambda s: os.path.exists(os.path.join(HERE, s)), SOURCES):
        for index, line in enumerate(open(os.path.join(HERE, source))):
            if (source, index) not in done and (only is None or (source, index) in only):
                todo.append((source, index, json.loads(line), a.n))
    with Pool(a.jobs) as pool, open(out_path, "a") as f:
        for r in pool.imap_unordered(job, todo):
            f.write(json.dumps(r) + "\n")
            f.flush()
            print(r["source"], r["index"], r["seconds"], "s", flush=True)


QUANTITIES = ["k_bend", "k_torsion", "k_axial", "stress_per_moment_nodal"]


def richardson(fine, coarse, n_fine, n_coarse, order=2.0):
    """The order-`order` extrapolation of a quantity solved at n_coarse and n_fine sizes/thickness."""
    r = (n_fine / n_coarse) ** order
    return fine + (fine - coarse) / (r - 1.0)


def report():
    """Prints, per quantity, how far n = 4 is from the n = 3/4 extrapolation, and on the references
    re-solved at n = 6 how the n = 3/4 extrapolation compares with the n = 4/6 one."""
    n3 = by_reference(os.path.join(HERE, "ccx_refine_n3_results.jsonl"))
    n6 = by_reference(os.path.join(HERE, "ccx_refine_n6_results.jsonl"))
    for q in QUANTITIES:
        off, agree = [], []
        for source in filter(lambda s: os.path.exists(os.path.join(HERE, s)), SOURCES):
            for index, line in enumerate(open(os.path.join(HERE, source))):
                r4 = json.loads(line)
                r3 = n3.get((source, index))
                if r3 is None:
                    continue
                k = richardson(r4[q], r3[q], 4, 3)
                off.append(100 * (r4[q] / k - 1))
                r6 = n6.get((source, index))
                if r6 is not None:
                    agree.append(100 * (k / richardson(r6[q], r4[q], 6, 4) - 1))
        if off:
            print(f"{q}: n = 4 vs n = 3/4 extrapolation {min(off):+.2f} … {max(off):+.2f} % ({len(off)} rows)")
        if agree:
            print(f"    n = 3/4 vs n = 4/6 extrapolation {min(agree):+.2f} … {max(agree):+.2f} % ({len(agree)} rows)")


if __name__ == "__main__":
    main()
