#!/usr/bin/env python3
"""Writes the Rust test module of a CalculiX design for tests/hinge_ccx_reference.rs (not used by
the build or the tests).

Each row of `tools/ccx_heldout{N}_results.jsonl` (the n = 4 solves of `ccx_heldout{N}_doe.json`)
becomes a `CcxRef` with its n = 3 line of `tools/ccx_refine_n3_results.jsonl`, the quantities to
6 significant digits, in the order of the design. The module's doc comment is read from a file
(it says when the design was drawn and which laws it is held out from).

    python3 tools/ccx_doe_module.py 11 DOE11 doc.txt > tests/hinge_ccx_reference/doe11.rs

Add the module to tests/hinge_ccx_reference.rs (`mod`, `DESIGNS`, `held_out`) and take the design
off `PENDING` only when it is to be compared.
"""

import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
KEYS = {
    "corner_filleted": ["l", "R", "t", "w", "h", "blank_length"],
    "circular_notch": ["R", "t", "w", "h", "blank_length"],
}


def six(x):
    """x to 6 significant digits, as a Rust float literal."""
    return repr(float(f"{x:.6g}"))


def main():
    number, name, doc_file = sys.argv[1], sys.argv[2], sys.argv[3]
    source = f"ccx_heldout{number}_results.jsonl"
    rows = [json.loads(line) for line in open(os.path.join(HERE, source))]
    n3 = {
        r["index"]: r
        for r in map(json.loads, open(os.path.join(HERE, "ccx_refine_n3_results.jsonl")))
        if r["source"] == source
    }
    missing = [i for i in range(len(rows)) if i not in n3]
    if missing:
        sys.exit(f"{source}: no n = 3 line for rows {missing}")
    out = ["//! " + line if line else "//!" for line in open(doc_file).read().rstrip().split("\n")]
    out += ["", "use super::references::CcxRef;", "", "/// The rows (see the module docs).", f"pub const {name}: &[CcxRef] = &["]
    for i, r in enumerate(rows):
        geometry = {"type": r["type"], **{k: r[k] for k in KEYS[r["type"]]}}
        c = n3[i]
        out.append(
            "    CcxRef {\n"
            f'        hinge: r#"{json.dumps(geometry)}"#,\n'
            f"        e: {six(r['E'])},\n"
            f"        nu: {r['nu']},\n"
            f"        k_bend: {six(r['k_bend'])},\n"
            f"        k_torsion: {six(r['k_torsion'])},\n"
            f"        k_axial: {six(r['k_axial'])},\n"
            f"        spm_nodal: {six(r['stress_per_moment_nodal'])},\n"
            f"        spm_ip: {six(r['stress_per_moment_ip'])},\n"
            f"        n3: [{six(c['k_bend'])}, {six(c['k_torsion'])}, {six(c['k_axial'])}, "
            f"{six(c['stress_per_moment_nodal'])}],\n"
            "    },"
        )
    out.append("];")
    print("\n".join(out))


if __name__ == "__main__":
    main()
