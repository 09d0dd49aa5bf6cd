#!/usr/bin/env python3
"""Solid-FEM reference for flexfem's hinge models (not used by the build or the tests).

Builds the exact 3-D geometry of a hinge (the profiles of flexfem's src/hinge/profile.rs) with gmsh's OpenCASCADE kernel,
meshes it with second-order (10-node) tetrahedra — the element class of the C3D10 models
the hinge accuracy bands refer to — and solves linear elasticity with scikit-fem (P2 Lagrange)
and CHOLMOD. Boundary conditions as in flexfem's `hinge` analysis: the face x = -X clamped,
the face x = +X rigid. The 6x6 stiffness of the rigid face (reactions to six unit rigid motions)
is inverted to the compliance at the face centre; the peak nodal-averaged von Mises stress under
a pure compliant-axis moment gives the stress per unit moment.

Axes as in flexfem: x along the hinge, y the width w, z the thickness t (compliant bending
about y). Units mm, N, MPa.

    pip install gmsh scikit-fem scikit-sparse   # scikit-sparse needs numpy<2 and libsuitesparse
    python3 tools/solid_reference.py circular_notch R=8 t=2 w=10 h=10 blank_length=20 n=6

`n` is the number of element sizes across the local thickness (mesh size = thickness(x)/n,
clamped). Results print as one JSON line.
"""

import json
import math
import sys

import gmsh
import numpy as np
import skfem
from skfem.models.elasticity import lame_parameters, linear_elasticity


def profile(kind, p):
    """(half notch length, thickness(x) function) as in flexfem's hinge::profile."""
    h = p["h"]

    def arc_cap(depth, ext, t):
        if t + 2 * depth <= h:
            return None
        q = 1 - (h - t) / (2 * depth)
        return ext * math.sqrt(max(1 - q * q, 0))

    def arc(t, depth, ext, v):
        s = min(v / ext, 1)
        return min(t + 2 * depth * (1 - math.sqrt(1 - s * s)), h)

    if kind == "circular_notch":
        r, t = p["R"], p["t"]
        half = arc_cap(r, r, t) or r
        return half, lambda x: h if abs(x) >= half else arc(t, r, r, abs(x))
    if kind == "elliptical_notch":
        ax, ay, t = p["ax"], p["ay"], p["t"]
        half = arc_cap(ay, ax, t) or ax
        return half, lambda x: h if abs(x) >= half else arc(t, ay, ax, abs(x))
    if kind == "corner_filleted":
        l, r, t = p["l"], p["R"], p["t"]
        s = l / 2 - r
        half = s + (arc_cap(r, r, t) or r)
        return half, lambda x: h if abs(x) >= half else (t if abs(x) <= s else arc(t, r, r, abs(x) - s))
    if kind == "leaf":
        half = p["l"] / 2
        return half, lambda x: p["t"] if abs(x) < half else h
    if kind == "spherical_neck":
        l, t, r = p["l"], p["t"], p["R"]
        half = l / 2 + r
        return half, lambda x: h if abs(x) >= half else (t if abs(x) <= l / 2 else arc(t, r, r, abs(x) - l / 2))
    raise SystemExit(f"unknown hinge type {kind}")


def geometry(kind, p, half, big):
    """Builds the hinge solid with OCC; returns the total half length X."""
    occ = gmsh.model.occ
    h, b = p["h"], p["blank_length"]
    X = half + b
    if kind == "spherical_neck":
        l, t, r = p["l"], p["t"], p["R"]
        rs = t / 2 + r
        # Revolve the half-profile (x, radius) about the x axis.
        pts = [
            occ.addPoint(-half, 0, 0),
            occ.addPoint(-half, 0, rs),
            occ.addPoint(-l / 2, 0, t / 2),
            occ.addPoint(l / 2, 0, t / 2),
            occ.addPoint(half, 0, rs),
            occ.addPoint(half, 0, 0),
        ]
        c1 = occ.addPoint(-l / 2, 0, rs)
        c2 = occ.addPoint(l / 2, 0, rs)
        curves = [
            occ.addLine(pts[0], pts[1]),
            occ.addCircleArc(pts[1], c1, pts[2]),
            occ.addLine(pts[2], pts[3]) if l > 0 else None,
            occ.addCircleArc(pts[3], c2, pts[4]),
            occ.addLine(pts[4], pts[5]),
            occ.addLine(pts[5], pts[0]),
        ]
        loop = occ.addCurveLoop([c for c in curves if c is not None])
        surf = occ.addPlaneSurface([loop])
        rev = occ.revolve([(2, surf)], 0, 0, 0, 1, 0, 0, 2 * math.pi)
        body = [d for d in rev if d[0] == 3]
        square = occ.addBox(-half, -h / 2, -h / 2, 2 * half, h, h)
        neck, _ = occ.intersect(body, [(3, square)])
        parts = [(3, occ.addBox(-X, -h / 2, -h / 2, b, h, h))] if b > 0 else []
        parts += [(3, occ.addBox(half, -h / 2, -h / 2, b, h, h))] if b > 0 else []
        if parts:
            out, _ = occ.fuse(neck, parts)
        else:
            out = neck
        return X, out
    w = p["w"]
    box = occ.addBox(-X, -w / 2, -h / 2, 2 * X, w, h)
    tools = []
    for sgn in (1, -1):
        if kind == "circular_notch":
            r, t = p["R"], p["t"]
            zc = sgn * (t / 2 + r)
            tools.append(occ.addCylinder(0, -w, zc, 0, 2 * w, 0, r))
            # A blank thicker than t + 2R: flexfem's profile is the arc below the centre and
            # the full blank from |x| = R on (a slot with a round bottom). The cylinder alone
            # would leave a closed hole under a bridge of material.
            tools.append(occ.addBox(-r, -w, zc if sgn > 0 else zc - big, 2 * r, 2 * w, big))
        elif kind == "elliptical_notch":
            ax, ay, t = p["ax"], p["ay"], p["t"]
            zc = sgn * (t / 2 + ay)
            cyl = occ.addCylinder(0, -w, 0, 0, 2 * w, 0, 1.0)
            occ.dilate([(3, cyl)], 0, 0, 0, ax, 1, ay)
            occ.translate([(3, cyl)], 0, 0, zc)
            tools.append(cyl)
            tools.append(occ.addBox(-ax, -w, zc if sgn > 0 else zc - big, 2 * ax, 2 * w, big))
        elif kind == "corner_filleted":
            l, r, t = p["l"], p["R"], p["t"]
            s = l / 2 - r
            z0 = t / 2
            if sgn > 0:
                tools.append(occ.addBox(-s, -w, z0, 2 * s, 2 * w, big))
                tools.append(occ.addBox(-s - r, -w, z0 + r, 2 * (s + r), 2 * w, big))
            else:
                tools.append(occ.addBox(-s, -w, -z0 - big, 2 * s, 2 * w, big))
                tools.append(occ.addBox(-s - r, -w, -z0 - r - big, 2 * (s + r), 2 * w, big))
            for xc in (-s, s):
                tools.append(occ.addCylinder(xc, -w, sgn * (z0 + r), 0, 2 * w, 0, r))
        elif kind == "leaf":
            l, t = p["l"], p["t"]
            z0 = t / 2 if sgn > 0 else -t / 2 - big
            tools.append(occ.addBox(-l / 2, -w, z0, l, 2 * w, big))
    out, _ = occ.cut([(3, box)], [(3, k) for k in tools])
    return X, out


def mesh_hinge(kind, p, n, hmax=None, ho_optimize=0, linear=False):
    """Meshes the hinge with 10-node tetrahedra of size thickness(x)/n (at most hmax, default h/3).

    `ho_optimize` is gmsh's Mesh.HighOrderOptimize (0: the curved mid-side nodes as placed on the
    surface, which can leave an element with a non-positive Jacobian; 2: gmsh untangles them).
    `linear` puts the mid-side nodes at the edges' midpoints (straight-sided elements, gmsh's
    Mesh.SecondOrderLinear): the last resort where neither places them well.

    Returns (X, node coordinates (N, 3), connectivity (nel, 10) in gmsh's node order: the four
    corners, then the mid-side nodes of the edges 01, 12, 20, 30, 32, 31)."""
    half, thick = profile(kind, p)
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("hinge")
    X, _ = geometry(kind, p, half, big=10 * p["h"])
    gmsh.model.occ.synchronize()
    hmax = hmax or p["h"] / 3
    hmin = thick(0.0) / n

    def size(dim, tag, x, y, z, lc):
        return min(max(thick(x) / n, hmin), hmax)

    gmsh.model.mesh.setSizeCallback(size)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
    gmsh.option.setNumber("Mesh.ElementOrder", 2)
    gmsh.option.setNumber("Mesh.HighOrderOptimize", ho_optimize)
    gmsh.option.setNumber("Mesh.SecondOrderLinear", 1 if linear else 0)
    gmsh.model.mesh.generate(3)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    etypes, _, enodes = gmsh.model.mesh.getElements(3)
    gmsh.finalize()
    k = list(etypes).index(11)  # 10-node tetrahedron
    pts_all = coords.reshape(-1, 3)
    idx = np.zeros(int(tags.max()) + 1, dtype=np.int64)
    idx[tags.astype(np.int64)] = np.arange(len(tags))
    conn = idx[enodes[k].astype(np.int64)].reshape(-1, 10)
    return X, pts_all, conn


def run(kind, p, n, nu, e=72000.0, hmax=None):
    X, pts_all, conn = mesh_hinge(kind, p, n, hmax)
    corners = np.unique(conn[:, :4])
    cidx = np.full(len(pts_all), -1, dtype=np.int64)
    cidx[corners] = np.arange(len(corners))
    t1 = cidx[conn[:, :4]].T.copy()
    m1 = skfem.MeshTet1(pts_all[corners].T.copy(), t1)
    mesh = skfem.MeshTet2.from_mesh(m1)
    # Curved geometry: put each edge node where gmsh placed it (on the true surface). Match the
    # element's six edges to its mid-side nodes by proximity to the straight midpoints.
    pairs = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)]
    mids = pts_all[conn[:, 4:]]  # (nel, 6, 3)
    nv = len(corners)
    keys, locs = [], []
    for a, b in pairs:
        va, vb = conn[:, a], conn[:, b]
        straight = 0.5 * (pts_all[va] + pts_all[vb])
        d = np.linalg.norm(mids - straight[:, None, :], axis=2)
        pick = mids[np.arange(len(conn)), d.argmin(axis=1)]
        ca, cb = cidx[va], cidx[vb]
        keys.append(np.minimum(ca, cb) * nv + np.maximum(ca, cb))
        locs.append(pick)
    keys = np.concatenate(keys)
    locs = np.concatenate(locs)
    ukeys, first = np.unique(keys, return_index=True)
    edges = mesh.edges  # (2, nedges) corner indices
    ekeys = np.minimum(edges[0], edges[1]) * nv + np.maximum(edges[0], edges[1])
    pos = np.searchsorted(ukeys, ekeys)
    doflocs = mesh.doflocs.copy()
    doflocs[:, nv + np.arange(edges.shape[1])] = locs[first[pos]].T
    from dataclasses import replace

    mesh = replace(mesh, doflocs=doflocs)
    elem = skfem.ElementVector(skfem.ElementTetP2())
    basis = skfem.Basis(mesh, elem, intorder=4)
    lam, mu = lame_parameters(e, nu)
    K = skfem.asm(linear_elasticity(lam, mu), basis).tocsc()
    loc = basis.doflocs
    ndof = K.shape[0]
    tol = 1e-6 * X
    # Component of each DOF: ElementVector interleaves per node (u_x, u_y, u_z).
    comp = np.zeros(ndof, dtype=np.int64)
    for c in range(3):
        comp[basis.nodal_dofs[c]] = c
        comp[basis.edge_dofs[c]] = c
    left = np.where(np.abs(loc[0] + X) < tol)[0]
    right = np.where(np.abs(loc[0] - X) < tol)[0]
    fixed = np.concatenate([left, right])
    free = np.setdiff1d(np.arange(ndof), fixed)
    try:
        from sksparse.cholmod import cholesky

        chol = cholesky(K[free][:, free])
    except ImportError:  # scikit-sparse does not build against every SuiteSparse: sparse LU
        from scipy.sparse.linalg import factorized

        chol = factorized(K[free][:, free].tocsc())
    x0 = np.array([X, 0.0, 0.0])
    rel = loc[:, right] - x0[:, None]
    cr = comp[right]
    U = np.zeros((ndof, 6))
    for j in range(6):
        ub = np.zeros(len(right))
        if j < 3:
            ub[cr == j] = 1.0
        else:
            th = np.zeros(3)
            th[j - 3] = 1.0
            disp = np.cross(th, rel.T).T  # theta x r
            ub = disp[cr, np.arange(len(right))]
        U[right, j] = ub
        U[free, j] = chol(-(K[free][:, right] @ ub))
    R = K[right] @ U  # reactions at the rigid face
    S = np.zeros((6, 6))
    for j in range(6):
        f = np.array([R[cr == c, j].sum() for c in range(3)])
        fr = np.zeros((3, len(right)))
        fr[cr, np.arange(len(right))] = R[:, j]
        m = np.cross(rel.T, fr.T).sum(axis=0)
        S[:, j] = np.concatenate([f, m])
    S = 0.5 * (S + S.T)
    C = np.linalg.inv(S)
    # Pure unit moment about y: face motion C e_y, then nodal-averaged von Mises.
    u = U @ C[:, 4]
    sig_vm = von_mises_nodal(basis, u, lam, mu, mesh)
    return {
        "type": kind,
        **p,
        "nu": nu,
        "E": e,
        "n": n,
        "dofs": int(ndof),
        "k_axial": 1 / C[0, 0],
        "k_torsion": 1 / C[3, 3],
        "k_bend": 1 / C[4, 4],
        "k_bend_off": 1 / C[5, 5],
        "stress_per_moment": float(sig_vm),
    }


def von_mises_nodal(basis, u, lam, mu, mesh):
    """Peak of the nodal-averaged von Mises stress (element values at the vertices)."""
    ref = np.array([[0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]])
    qb = skfem.Basis(mesh, basis.elem, quadrature=(ref, np.full(4, 1 / 24)))
    g = qb.interpolate(u).grad  # (3, 3, nelem, 4)
    eps = 0.5 * (g + np.transpose(g, (1, 0, 2, 3)))
    tr = eps[0, 0] + eps[1, 1] + eps[2, 2]
    s = 2 * mu * eps
    for i in range(3):
        s[i, i] += lam * tr
    vm = np.sqrt(
        0.5 * ((s[0, 0] - s[1, 1]) ** 2 + (s[1, 1] - s[2, 2]) ** 2 + (s[2, 2] - s[0, 0]) ** 2)
        + 3 * (s[0, 1] ** 2 + s[1, 2] ** 2 + s[2, 0] ** 2)
    )
    t = mesh.t[:4]  # (4, nelem) vertex indices
    acc = np.zeros(mesh.p.shape[1])
    cnt = np.zeros(mesh.p.shape[1])
    np.add.at(acc, t.T.ravel(), vm.ravel())
    np.add.at(cnt, t.T.ravel(), 1)
    nodal = acc[cnt > 0] / cnt[cnt > 0]
    return nodal.max()


if __name__ == "__main__":
    kind = sys.argv[1]
    kv = dict(a.split("=") for a in sys.argv[2:])
    n = float(kv.pop("n", 4))
    nu = float(kv.pop("nu", 0.33))
    e = float(kv.pop("E", 72000))
    p = {k: float(v) for k, v in kv.items()}
    print(json.dumps(run(kind, p, n, nu, e)))
