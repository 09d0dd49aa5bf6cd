#!/usr/bin/env python3
"""Converged peak stress of a flat-notch hinge under its compliant-axis moment, by CalculiX
(not used by the build or the tests).

`tools/ccx_reference.py` meshes the whole hinge with an element size of the local thickness / n.
That converges the stiffnesses (h², extrapolated) but not the peak stress of a small fillet: the
fillet radius, not the thickness, sets the stress gradient there, and at n = 4 a fillet of
R/t = 0.5 has two elements across its radius (the l5/R0.5/t1/w1 hinge's nodal peak rises 7.018,
7.335, 7.382, 7.449 MPa/(N·mm) at n = 4, 6, 8, 10). This script solves the same hinge for the
peak stress alone, with the mesh sized by the notch radius where the peak is:

- one eighth of the hinge, x ≥ 0, y ≥ 0, z ≥ 0. Under a pure moment about y the stresses are
  symmetric about the planes x = 0 (one end clamped and the other rigid differ from two rigid
  ends loaded by ±M only by a rigid motion) and y = 0, and antisymmetric about z = 0: u_x = 0 on
  x = 0, u_y = 0 on y = 0, u_x = u_y = 0 on z = 0, u_z = 0 at the origin (the rigid translation
  left). The end face x = X is rigid (*RIGID BODY) with the reference node at its centre held in
  x and y and its rotations about x and z held; a unit moment about y there is a moment of 4 on
  the whole hinge (each quarter of the section carries a quarter), so the peak von Mises stress
  per unit moment is the peak / 4, and the compliant-axis stiffness 2 / θ (the eighth's rotation
  is half the whole hinge's);
- C3D10 elements, size thickness(x)/n at most h/3 as in `ccx_reference.py`, and near the notch
  root at most min(ρ, t)/k + g·d: ρ the root radius (R; ax²/ay for the ellipse), d the distance in the
  x–z plane from the surface where the peak lies (corner-filleted: the fillet arc from the flat's
  end to 60° up it, and the flat's last ρ/2; circular and elliptical: the root ±30° of arc), g
  the growth rate;
- the peak is the largest nodal-averaged von Mises stress (ccx's extrapolated, averaged nodal
  stresses), as in `ccx_reference.py`.

    OMP_NUM_THREADS=1 python3 tools/ccx_peak_stress.py corner_filleted l=5 R=0.5 t=1 w=1 h=4 blank_length=4 k=8
    OMP_NUM_THREADS=1 python3 tools/ccx_peak_stress.py --rows [--k 8] [--jobs 2]

`--rows` solves every circular and corner-filleted reference of the `ccx_*_results.jsonl` files
at radius-refinement k (default 8) and appends to `tools/ccx_peak_stress_k{k}.jsonl`; it resumes.
"""

import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time
from multiprocessing import Pool

import gmsh
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ccx_reference import ids, von_mises, write_mesh  # noqa: E402
from ccx_refine import SOURCES  # noqa: E402
from solid_reference import geometry, profile  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
KINDS = ("circular_notch", "elliptical_notch", "corner_filleted")
GEOMETRY = ("l", "R", "t", "w", "h", "blank_length", "ax", "ay")


def hot_curve(kind, p):
    """Points (x, z), x, z ≥ 0, sampling the surface where the peak stress lies, and the root
    radius ρ."""
    t = p["t"]
    if kind == "corner_filleted":
        r, s = p["R"], p["l"] / 2 - p["R"]
        arc = [(s + r * math.sin(a), t / 2 + r - r * math.cos(a)) for a in np.radians(np.linspace(0, 60, 25))]
        flat = [(s - r / 2 * f, t / 2) for f in np.linspace(0, 1, 9)[1:]]
        return np.array(arc + flat), r
    if kind == "circular_notch":
        r = p["R"]
        return np.array([(r * math.sin(a), t / 2 + r - r * math.cos(a)) for a in np.radians(np.linspace(0, 30, 25))]), r
    ax, ay = p["ax"], p["ay"]
    pts = [(ax * math.sin(a), t / 2 + ay - ay * math.cos(a)) for a in np.radians(np.linspace(0, 30, 25))]
    return np.array(pts), ax * ax / ay


def mesh_eighth(kind, p, n, k, g, hmax=None):
    """The eighth x, y, z ≥ 0 of the hinge in 10-node tetrahedra; returns (X, points, connectivity
    in gmsh's order)."""
    half, thick = profile(kind, p)
    hot, rho = hot_curve(kind, p)
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("eighth")
    occ = gmsh.model.occ
    X, whole = geometry(kind, p, half, big=10 * p["h"])
    quarter = occ.addBox(0, 0, 0, 2 * X, p["w"], p["h"])
    occ.intersect(whole, [(3, quarter)])
    occ.synchronize()
    hmax = hmax or p["h"] / 3
    hmin = thick(0.0) / n
    h_hot = min(rho, p["t"]) / k

    def size(dim, tag, x, y, z, lc):
        base = min(max(thick(x) / n, hmin), hmax)
        d = np.sqrt(((hot[:, 0] - abs(x)) ** 2 + (hot[:, 1] - abs(z)) ** 2).min())
        return min(base, h_hot + g * d)

    gmsh.model.mesh.setSizeCallback(size)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
    gmsh.option.setNumber("Mesh.ElementOrder", 2)
    gmsh.option.setNumber("Mesh.HighOrderOptimize", 2)
    gmsh.option.setNumber("Mesh.SecondOrderLinear", 0)
    gmsh.model.mesh.generate(3)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    etypes, _, enodes = gmsh.model.mesh.getElements(3)
    gmsh.finalize()
    e = list(etypes).index(11)
    pts = coords.reshape(-1, 3)
    idx = np.zeros(int(tags.max()) + 1, dtype=np.int64)
    idx[tags.astype(np.int64)] = np.arange(len(tags))
    return X, pts, idx[enodes[e].astype(np.int64)].reshape(-1, 10)


def write_inp(path, X, pts, conn, e, nu):
    tol = 1e-7 * X
    on = lambda axis, v: np.abs(pts[:, axis] - v) < tol  # noqa: E731
    rigid = on(0, X)
    origin = np.where(on(0, 0) & on(1, 0) & on(2, 0))[0]
    assert len(origin) == 1, "a node at the origin"

    def nset(f, name, mask):
        ids(f, name, np.where(mask)[0] + 1)

    with open(path, "w") as f:
        ref, rot = write_mesh(f, X, pts, conn)
        nset(f, "RIGHT", rigid)
        nset(f, "SX", on(0, 0))
        nset(f, "SY", on(1, 0) & ~rigid)
        nset(f, "AZ", on(2, 0) & ~rigid)
        f.write("*MATERIAL, NAME=M\n*ELASTIC\n" f"{e:.12g}, {nu:.12g}\n")
        f.write("*SOLID SECTION, ELSET=EALL, MATERIAL=M\n")
        f.write(f"*RIGID BODY, NSET=RIGHT, REF NODE={ref}, ROT NODE={rot}\n")
        f.write("*BOUNDARY\nSX, 1, 1\nSY, 2, 2\nAZ, 1, 2\n")
        f.write(f"{origin[0] + 1}, 3, 3\n{ref}, 1, 2\n{rot}, 1, 1\n{rot}, 3, 3\n")
        f.write(f"*NSET, NSET=RN\n{rot}\n")
        f.write("*STEP\n*STATIC\n*CLOAD\n" f"{rot}, 2, 1.0\n")
        f.write("*NODE PRINT, NSET=RN\nU\n*EL FILE\nS\n*END STEP\n")
    return rot


def frd_nodal_stress(path):
    """(node numbers, stresses) of the .frd's nodal stress block."""
    ids, vals, block = [], [], False
    with open(path) as f:
        for line in f:
            if line.startswith(" -4  STRESS"):
                block = True
            elif block and line.startswith(" -1"):
                ids.append(int(line[3:13]))
                vals.append([float(line[13 + 12 * k : 25 + 12 * k]) for k in range(6)])
            elif block and line.startswith(" -3"):
                break
    return np.array(ids), np.array(vals)


def rotation(path, rot):
    with open(path) as f:
        for line in f:
            v = line.split()
            if len(v) == 4 and v[0] == str(rot):
                return float(v[2])
    raise SystemExit(f"no rotation of node {rot} in {path}")


def run(kind, p, n=4.0, k=8.0, g=0.4, nu=0.33, e=72000.0, hmax=None, keep=None):
    work = keep or tempfile.mkdtemp(prefix="ccx_peak_")
    os.makedirs(work, exist_ok=True)
    env = dict(os.environ, OMP_NUM_THREADS=os.environ.get("OMP_NUM_THREADS", "1"))
    X, pts, conn = mesh_eighth(kind, p, n, k, g, hmax)
    rot = write_inp(os.path.join(work, "eighth.inp"), X, pts, conn, e, nu)
    out = subprocess.run(["ccx", "-i", "eighth"], cwd=work, env=env, capture_output=True, text=True)
    if out.returncode != 0 or "ERROR" in out.stdout or "nonpositive jacobian" in out.stdout:
        raise SystemExit(out.stdout[-2000:] + out.stderr[-2000:])
    theta = rotation(os.path.join(work, "eighth.dat"), rot)
    ids, s = frd_nodal_stress(os.path.join(work, "eighth.frd"))
    vm = von_mises(s)
    at = pts[ids[vm.argmax()] - 1]
    if not keep:
        shutil.rmtree(work)
    fields = {"nu": nu, "E": e, "n": n}
    return {
        "type": kind,
        **p,
        **fields,
        "k": k,
        "g": g,
        "hmax": hmax or p["h"] / 3,
        "dofs": int(3 * len(pts)),
        "solver": "ccx 2.20 C3D10, eighth model, *RIGID BODY end face",
        "k_bend": 2.0 / theta,
        "stress_per_moment_nodal": float(vm.max()) / 4.0,
        "peak_at": [round(float(c), 4) for c in at],
    }


def job(args):
    source, index, row, k = args
    p = {key: row[key] for key in GEOMETRY if key in row}
    start = time.time()
    out = run(row["type"], p, 4.0, k, 0.4, row["nu"], row["E"], row["hmax"])
    return {"source": source, "index": index, **out, "seconds": round(time.time() - start, 1)}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rows", action="store_true")
    ap.add_argument("--only", help="FILE:INDEX,... (with --rows)")
    ap.add_argument("--k", type=float, default=8.0)
    ap.add_argument("--jobs", type=int, default=2)
    a, rest = ap.parse_known_args()
    if not a.rows:
        kind = rest[0]
        kv = dict(x.split("=") for x in rest[1:])
        opts = {key: float(kv.pop(key)) for key in ("n", "k", "g", "nu", "E", "hmax") if key in kv}
        keep = kv.pop("keep", None)
        p = {key: float(v) for key, v in kv.items()}
        print(json.dumps(run(kind, p, opts.get("n", 4.0), opts.get("k", a.k), opts.get("g", 0.4),
                             opts.get("nu", 0.33), opts.get("E", 72000.0), opts.get("hmax"), keep)))
        return
    only = None
    if a.only:
        only = {(f, int(i)) for f, i in (x.rsplit(":", 1) for x in a.only.split(","))}
    out_path = os.path.join(HERE, f"ccx_peak_stress_k{a.k:g}.jsonl")
    done = set()
    if os.path.exists(out_path):
        done = {(r["source"], r["index"]) for r in map(json.loads, open(out_path))}
    todo = []
    for source in SOURCES:
        for index, line in enumerate(open(os.path.join(HERE, source))):
            row = json.loads(line)
            if row["type"] in KINDS and (source, index) not in done and (only is None or (source, index) in only):
                todo.append((source, index, row, a.k))
    # Small models first, so the file fills steadily.
    todo.sort(key=lambda j: j[2]["dofs"])
    with Pool(a.jobs) as pool, open(out_path, "a") as f:
        for r in pool.imap_unordered(job, todo):
            f.write(json.dumps(r) + "\n")
            f.flush()
            print(r["source"], r["index"], r["dofs"], "dofs", r["seconds"], "s", flush=True)


if __name__ == "__main__":
    main()
