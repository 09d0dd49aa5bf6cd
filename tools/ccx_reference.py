#!/usr/bin/env python3
"""CalculiX (ccx) solid reference for flexfem's hinge models (not used by the build or the tests).

The second, independent solver beside `tools/solid_reference.py` (scikit-fem): the same gmsh
geometry and 10-node-tetrahedron mesh (its `mesh_hinge` is imported), written as a CalculiX
input deck and solved by ccx (Debian's `calculix-ccx`, 2.20, SPOOLES):

- elements C3D10 (ccx's quadratic tetrahedron, 4 integration points);
- the face x = -X clamped (*BOUNDARY, all three translations of every node);
- the face x = +X made rigid with *RIGID BODY (REF NODE at the face centre carries the
  translations, ROT NODE the rotations). *RIGID BODY is kinematic: every face node follows the
  rigid motion exactly, which is the boundary condition of flexfem's `hinge` analysis and of the
  scikit-fem script (which prescribes the rigid motion on every face node). A distributing
  coupling would let the face warp and deform, a softer and different problem;
- four steps, each a unit load at the reference nodes (1 N along x; 1 N·mm about x, y, z;
  *CLOAD, OP=NEW), whose reference-node displacements are four columns of the 6x6 compliance
  at the face centre (*NODE PRINT U); k = 1 / C_ii as in the scikit-fem script (the two
  transverse forces are not needed for the four stiffnesses reported: each step costs a
  factorisation in ccx);
- in the step of the unit moment about y (compliant-axis bending), the stresses at the
  integration points (*EL PRINT S) and ccx's nodal stresses (extrapolated from the integration
  points and averaged over the elements at a node, *EL FILE S in the .frd). Both peaks of the
  von Mises stress per unit moment are reported: `stress_per_moment_ip` (integration points) and
  `stress_per_moment_nodal` (averaged nodes, corners and mid-side nodes).

Axes as in flexfem: x along the hinge, y the width w, z the thickness t. Units mm, N, MPa.

    apt-get install calculix-ccx; pip install gmsh scikit-fem
    OMP_NUM_THREADS=1 python3 tools/ccx_reference.py circular_notch R=8 t=2 w=10 h=10 blank_length=20 n=5

`n` is the number of element sizes across the local thickness, as in the scikit-fem script;
`hmax` (default h/3) caps the size in the blanks. One JSON line is printed.
"""

import json
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from solid_reference import mesh_hinge  # noqa: E402

# gmsh's 10-node tetrahedron lists the mid-side nodes of edges 01, 12, 20, 30, 32, 31;
# CalculiX's C3D10 those of 12, 23, 31, 14, 24, 34 (1-based), i.e. 01, 12, 20, 03, 13, 23.
GMSH_TO_CCX = [0, 1, 2, 3, 4, 5, 6, 7, 9, 8]
# The loaded directions, one step each (0 = force along x; 3, 4, 5 = moments about x, y, z).
STEPS = [0, 3, 4, 5]


def ids(f, name, nodes):
    """Writes a node set (1-based node numbers), 16 to a line."""
    f.write(f"*NSET, NSET={name}\n")
    for i in range(0, len(nodes), 16):
        f.write(", ".join(str(int(v)) for v in nodes[i : i + 16]) + "\n")


def write_mesh(f, X, pts, conn):
    """Writes the C3D10 mesh (gmsh's node order in `conn`) and two nodes at the end-face centre
    (x = X), the rigid body's reference and rotation nodes; returns their numbers (ref, rot)."""
    c = conn[:, GMSH_TO_CCX]
    # The mid-side nodes must lie near their edges' midpoints in ccx's order.
    for m, (a, b) in zip(range(4, 10), [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)]):
        d = np.linalg.norm(pts[c[:, m]] - 0.5 * (pts[c[:, a]] + pts[c[:, b]]), axis=1)
        edge = np.linalg.norm(pts[c[:, a]] - pts[c[:, b]], axis=1)
        assert (d < 0.3 * edge).all(), "mid-side node order"
    ref, rot = len(pts) + 1, len(pts) + 2
    f.write("*NODE\n")
    for i, q in enumerate(pts):
        f.write(f"{i + 1}, {q[0]:.12g}, {q[1]:.12g}, {q[2]:.12g}\n")
    f.write(f"{ref}, {X:.12g}, 0, 0\n{rot}, {X:.12g}, 0, 0\n")
    f.write("*ELEMENT, TYPE=C3D10, ELSET=EALL\n")
    for i, row in enumerate(c + 1):
        f.write(f"{i + 1}, " + ", ".join(str(int(v)) for v in row) + "\n")
    return ref, rot


def write_inp(path, X, pts, conn, e, nu):
    tol = 1e-6 * X
    left = np.where(np.abs(pts[:, 0] + X) < tol)[0] + 1
    right = np.where(np.abs(pts[:, 0] - X) < tol)[0] + 1
    with open(path, "w") as f:
        ref, rot = write_mesh(f, X, pts, conn)
        ids(f, "LEFT", left)
        ids(f, "RIGHT", right)
        f.write(f"*NSET, NSET=RN\n{ref}, {rot}\n")
        f.write("*MATERIAL, NAME=M\n*ELASTIC\n" f"{e:.12g}, {nu:.12g}\n")
        f.write("*SOLID SECTION, ELSET=EALL, MATERIAL=M\n")
        f.write(f"*RIGID BODY, NSET=RIGHT, REF NODE={ref}, ROT NODE={rot}\n")
        f.write("*BOUNDARY\nLEFT, 1, 3\n")
        for j in STEPS:
            node, dof = (ref, j + 1) if j < 3 else (rot, j - 2)
            f.write("*STEP\n*STATIC\n*CLOAD, OP=NEW\n" f"{node}, {dof}, 1.0\n")
            f.write("*NODE PRINT, NSET=RN\nU\n")
            if j == 4:
                f.write("*EL PRINT, ELSET=EALL\nS\n*EL FILE\nS\n")
            f.write("*END STEP\n")
    return ref, rot


def parse_dat(path, ref, rot):
    """Per step: displacements of the reference nodes, and integration-point stresses."""
    steps, cur, mode = [], None, None
    with open(path) as f:
        for line in f:
            s = line.strip()
            if s.startswith("displacements"):
                cur = {"u": {}, "s": []}
                steps.append(cur)
                mode = "u"
            elif s.startswith("stresses"):
                mode = "s"
            elif not s:
                continue
            elif mode == "u":
                v = s.split()
                cur["u"][int(v[0])] = [float(x) for x in v[1:4]]
            elif mode == "s":
                v = s.split()
                cur["s"].append([float(x) for x in v[2:8]])
    assert len(steps) == len(STEPS), f"{len(steps)} steps in {path}"
    # Diagonal compliances C_jj of the loaded directions (rows: ux, uy, uz, rx, ry, rz).
    diag = {j: (st["u"][ref] + st["u"][rot])[j] for j, st in zip(STEPS, steps)}
    return diag, np.array(steps[STEPS.index(4)]["s"])


def parse_frd_stress(path):
    """ccx's nodal (extrapolated, averaged) stresses of the first stress block of the .frd (the
    step of the unit moment about y; *EL FILE stays on in the step after it)."""
    vals, block = None, False
    with open(path) as f:
        for line in f:
            if line.startswith(" -4  STRESS") and vals is None:
                vals, block = [], True
            elif block and line.startswith(" -1"):
                vals.append([float(line[13 + 12 * k : 25 + 12 * k]) for k in range(6)])
            elif block and line.startswith(" -3"):
                block = False
    return np.array(vals)


def von_mises(s):
    """s columns sxx, syy, szz, sxy, sxz, syz (ccx's order in both files)."""
    return np.sqrt(
        0.5 * ((s[:, 0] - s[:, 1]) ** 2 + (s[:, 1] - s[:, 2]) ** 2 + (s[:, 2] - s[:, 0]) ** 2)
        + 3 * (s[:, 3] ** 2 + s[:, 4] ** 2 + s[:, 5] ** 2)
    )


def run(kind, p, n, nu, e=72000.0, hmax=None, keep=None):
    work = keep or tempfile.mkdtemp(prefix="ccx_hinge_")
    os.makedirs(work, exist_ok=True)
    env = dict(os.environ, OMP_NUM_THREADS=os.environ.get("OMP_NUM_THREADS", "1"))
    # ccx refuses an element with a non-positive Jacobian (a curved mid-side node placed on the
    # surface beyond its element), and write_mesh one whose mid-side node lies far from its
    # edge's midpoint; then the mesh is remade with gmsh's high-order untangling and, as a last
    # resort (the nineteenth design's circular R1.1/t0.5/w5.6 at n = 3), with straight-sided
    # elements (`linear`, recorded in the result).
    for ho, linear in ((0, False), (2, False), (0, True)):
        X, pts, conn = mesh_hinge(kind, p, n, hmax, ho_optimize=ho, linear=linear)
        try:
            ref, rot = write_inp(os.path.join(work, "hinge.inp"), X, pts, conn, e, nu)
        except AssertionError:
            if not linear:
                continue
            raise
        out = subprocess.run(["ccx", "-i", "hinge"], cwd=work, env=env, capture_output=True, text=True)
        if "nonpositive jacobian" not in out.stdout:
            break
    if out.returncode != 0 or "ERROR" in out.stdout:
        raise SystemExit(out.stdout[-2000:] + out.stderr[-2000:])
    C, s_ip = parse_dat(os.path.join(work, "hinge.dat"), ref, rot)
    s_nodal = parse_frd_stress(os.path.join(work, "hinge.frd"))
    if not keep:
        for name in os.listdir(work):
            os.remove(os.path.join(work, name))
        os.rmdir(work)
    return {
        "type": kind,
        **p,
        "nu": nu,
        "E": e,
        "n": n,
        "hmax": hmax or p["h"] / 3,
        "dofs": int(3 * len(pts)),
        "high_order_optimize": ho,
        **({"second_order_linear": 1} if linear else {}),
        "solver": "ccx 2.20 C3D10, *RIGID BODY end face",
        "k_axial": 1 / C[0],
        "k_torsion": 1 / C[3],
        "k_bend": 1 / C[4],
        "k_bend_off": 1 / C[5],
        "stress_per_moment_ip": float(von_mises(s_ip).max()),
        "stress_per_moment_nodal": float(von_mises(s_nodal).max()),
    }


if __name__ == "__main__":
    kind = sys.argv[1]
    kv = dict(a.split("=") for a in sys.argv[2:])
    n = float(kv.pop("n", 4))
    nu = float(kv.pop("nu", 0.33))
    e = float(kv.pop("E", 72000))
    hmax = float(kv.pop("hmax")) if "hmax" in kv else None
    keep = kv.pop("keep", None)
    p = {k: float(v) for k, v in kv.items()}
    print(json.dumps(run(kind, p, n, nu, e, hmax, keep)))
