#!/usr/bin/env python3
"""Independent references for the four-node shell's statics (validation only; nothing in the
build or the tests runs this). OpenSees (openseespy 3.7.1.2, `pip install openseespy`):
ShellMITC4 (Dvorkin-Bathe MITC4 bending/shear, Hughes-Brezzi drilling membrane) and ASDShellQ4
(MITC4 shear, enhanced membrane) on the meshes that `tests/shell_opensees.rs` builds node for
node, with the same nodal loads (each element's area / 4 to each node for surface loads).
Prints one JSON line per model and mesh, plus the Richardson extrapolation (4 u_2n - u_n) / 3
of the two finest meshes (the tests extrapolate the folded angle section with its observed order).

    python3 tools/opensees_shell.py            # all problems
    python3 tools/opensees_shell.py scordelis_lo   # one
    python3 tools/opensees_shell.py plate_modes    # coarse-mesh plate frequencies (MITC4, DKQ)
    python3 tools/opensees_shell.py plate_modes_mitc9     # the same plates, nine-node ShellMITC9
    python3 tools/opensees_shell.py plate_pressure_mitc9  # clamped square plate under pressure, ShellMITC9
"""
import json
import math
import sys

import openseespy.opensees as ops


def grid(nx, ny, at):
    """Nodes of an (nx+1) x (ny+1) grid at at(i, j); node (i, j) has tag j(nx+1)+i+1."""
    nodes = {}
    for j in range(ny + 1):
        for i in range(nx + 1):
            nodes[(i, j)] = at(i, j)
    quads = [((i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)) for j in range(ny) for i in range(nx)]
    return nodes, quads


def solve(element, nodes, quads, nx, t, e, nu, fixes, loads, out):
    """Builds and solves a linear static model; returns the displacement `out` = (node, dof)."""
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    tag = lambda ij: ij[1] * (nx + 1) + ij[0] + 1
    for ij, x in nodes.items():
        ops.node(tag(ij), *x)
    ops.section("ElasticMembranePlateSection", 1, e, nu, t, 0.0)
    for k, q in enumerate(quads):
        ops.element(element, k + 1, *[tag(ij) for ij in q], 1)
    for ij, dofs in fixes.items():
        ops.fix(tag(ij), *[1 if d in dofs else 0 for d in range(6)])
    ops.timeSeries("Constant", 1)
    ops.pattern("Plain", 1, 1)
    for ij, f in loads.items():
        ops.load(tag(ij), *f)
    ops.constraints("Plain")
    ops.numberer("RCM")
    ops.system("UmfPack")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Linear")
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")
    if ops.analyze(1) != 0:
        raise RuntimeError("analysis failed")
    return ops.nodeDisp(tag(out[0]), out[1] + 1)


def area_loads(nodes, quads, q):
    """Each element's area / 4 times the traction q (per unit area) to each of its nodes."""
    f = {}
    for qd in quads:
        p = [nodes[ij] for ij in qd]
        d1 = [p[2][k] - p[0][k] for k in range(3)]
        d2 = [p[3][k] - p[1][k] for k in range(3)]
        c = [d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]]
        area = 0.5 * math.sqrt(sum(v * v for v in c))
        for ij in qd:
            acc = f.setdefault(ij, [0.0] * 6)
            for k in range(3):
                acc[k] += q[k] * area / 4.0
    return f


def angle_section(nb):
    """Equal-angle cantilever: legs b = 20 (mid-surface), t = 1.8, length L = 100, steel
    E = 210000, nu = 0.3; clamped at x = 0; P = 100 N in -z along the tip edge of the
    horizontal leg (line load P/b, nodal shares of the tributary lengths). Section coordinate
    s = 2b j/(2 nb): leg A (x, b - s, 0) for s <= b, leg B (x, 0, s - b). Output: uz at the
    free tip corner of leg A (i = nl, j = 0)."""
    b, t, l, p = 20.0, 1.8, 100.0, 100.0
    nl, ny = 5 * nb, 2 * nb

    def at(i, j):
        s, x = 2.0 * b * j / ny, l * i / nl
        return (x, b - s, 0.0) if s <= b else (x, 0.0, s - b)

    nodes, quads = grid(nl, ny, at)
    fixes = {(0, j): range(6) for j in range(ny + 1)}
    h = b / nb
    loads = {(nl, j): [0, 0, -p / b * h * (0.5 if j in (0, nb) else 1.0), 0, 0, 0] for j in range(nb + 1)}
    return nodes, quads, nl, t, 210000.0, 0.3, fixes, loads, ((nl, 0), 2)


def roof(n):
    """Scordelis-Lo roof, full, n x n: R = 25, L = 50, 2 x 40 deg, t = 0.25, E = 4.32e8,
    nu = 0, 90 per unit area downwards; ends uy = uz = 0, node (0, 0) also ux. Output: -uz at
    the midside of the free edge (i = n/2, j = 0)."""
    r, l, t, phi0 = 25.0, 50.0, 0.25, math.radians(40.0)

    def at(i, j):
        phi = -phi0 + 2.0 * phi0 * j / n
        return (l * i / n, r * math.sin(phi), r * math.cos(phi))

    nodes, quads = grid(n, n, at)
    fixes = {}
    for j in range(n + 1):
        fixes[(0, j)] = {1, 2}
        fixes[(n, j)] = {1, 2}
    fixes[(0, 0)] = {0, 1, 2}
    loads = area_loads(nodes, quads, (0.0, 0.0, -90.0))
    return nodes, quads, n, t, 4.32e8, 0.0, fixes, loads, ((n // 2, 0), 2)


def distorted_plate(n):
    """Clamped square plate a = 100, t = 1, E = 210000, nu = 0.3, pressure 0.01 MPa (-z),
    n x n mesh with the interior nodes moved by 0.2 h ((-1)^(i+j), (-1)^i) (h = a/n): every
    element a general convex quadrilateral. Output: uz at the centre node (n/2, n/2)."""
    a, t, q = 100.0, 1.0, 0.01
    h = a / n

    def at(i, j):
        x, y = a * i / n, a * j / n
        if 0 < i < n and 0 < j < n:
            x += 0.2 * h * (-1) ** (i + j)
            y += 0.2 * h * (-1) ** i
        return (x, y, 0.0)

    nodes, quads = grid(n, n, at)
    fixes = {ij: range(6) for ij in nodes if ij[0] in (0, n) or ij[1] in (0, n)}
    loads = area_loads(nodes, quads, (0.0, 0.0, -q))
    return nodes, quads, n, t, 210000.0, 0.3, fixes, loads, ((n // 2, n // 2), 2)


def pinched_cylinder(n):
    """Pinched cylinder with rigid diaphragms, one octant n x n: R = 300, L = 600, t = 3,
    E = 3e6, nu = 0.3, P/4 = 0.25 at (n, n). Output: -uz under the load."""
    r, l, t = 300.0, 600.0, 3.0

    def at(i, j):
        phi = 0.5 * math.pi * j / n
        return (0.5 * l * i / n, r * math.cos(phi), r * math.sin(phi))

    nodes, quads = grid(n, n, at)
    fixes = {}
    for j in range(n + 1):
        fixes.setdefault((0, j), set()).update({1, 2, 3})
        fixes.setdefault((n, j), set()).update({0, 4, 5})
    for i in range(n + 1):
        fixes.setdefault((i, 0), set()).update({2, 3, 4})
        fixes.setdefault((i, n), set()).update({1, 3, 5})
    loads = {(n, n): [0, 0, -0.25, 0, 0, 0]}
    return nodes, quads, n, t, 3e6, 0.3, fixes, loads, ((n, n), 2)


def pinched_hemisphere(n):
    """Pinched hemisphere with an 18 deg hole, quarter n x n: R = 10, t = 0.04, E = 6.825e7,
    nu = 0.3, +1 along x at (0, 0), -1 along y at (n, 0). Output: ux under the load."""
    r, t = 10.0, 0.04

    def at(i, j):
        polar = 0.5 * math.pi - math.radians(72.0) * j / n
        az = 0.5 * math.pi * i / n
        return (r * math.sin(polar) * math.cos(az), r * math.sin(polar) * math.sin(az), r * math.cos(polar))

    nodes, quads = grid(n, n, at)
    fixes = {}
    for j in range(n + 1):
        fixes.setdefault((0, j), set()).update({1, 3, 5})
        fixes.setdefault((n, j), set()).update({0, 4, 5})
    fixes.setdefault((0, 0), set()).add(2)
    loads = {(0, 0): [1.0, 0, 0, 0, 0, 0], (n, 0): [0, -1.0, 0, 0, 0, 0]}
    return nodes, quads, n, t, 6.825e7, 0.3, fixes, loads, ((0, 0), 0)


PROBLEMS = {
    "angle_section": (angle_section, [4, 8, 16, 32, 64]),
    "scordelis_lo": (roof, [8, 16, 32, 64]),
    "distorted_plate": (distorted_plate, [8, 16, 32, 64]),
    "pinched_cylinder": (pinched_cylinder, [16, 32, 64]),
    "pinched_hemisphere": (pinched_hemisphere, [8, 16, 32, 64]),
}

def clamped_plate_modes(element, n, skew_deg, a=100.0, t=0.1, e=71700.0, nu=0.33, rho=2.81e-9):
    """Frequency parameters λ = ωa²√(ρt/D) of modes 1–6 of the clamped square (skew 0) or 45°
    rhombic plate of tests/shell_coarse_mesh.rs, n×n elements, with `element`'s own mass (the
    consistent bilinear translational mass in ShellMITC4 and ShellDKGQ: ShellMITC4 8×8 square
    +4.20…+28.48 %, skew +6.96…+47.82 %, as flexfem's MITC4 with that mass; ShellDKGQ, the
    DKQ plate, 45° skew 8×8 −12.15…−3.18 %, as tools/plate_dispersion.py's DKQ)."""
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    sn, cs = math.sin(math.radians(skew_deg)), math.cos(math.radians(skew_deg))
    tag = lambda i, j: j * (n + 1) + i + 1
    for j in range(n + 1):
        for i in range(n + 1):
            u, v = a * i / n, a * j / n
            ops.node(tag(i, j), u + v * sn, v * cs, 0.0)
            if i in (0, n) or j in (0, n):
                ops.fix(tag(i, j), 1, 1, 1, 1, 1, 1)
    ops.section("ElasticMembranePlateSection", 1, e, nu, t, rho)
    for k, (i, j) in enumerate((i, j) for j in range(n) for i in range(n)):
        ops.element(element, k + 1, tag(i, j), tag(i + 1, j), tag(i + 1, j + 1), tag(i, j + 1), 1)
    d = e * t**3 / (12 * (1 - nu**2))
    return [math.sqrt(lam) * a * a * math.sqrt(rho * t / d) for lam in ops.eigen("-fullGenLapack", 6)]


# λ of modes 1–6 of the clamped plates (tests/shell_coarse_mesh.rs): square, Leissa NASA SP-160
# Table 4.23; 45° rhombus, the converged (Richardson 32/64) reference computed there.
SQUARE = [35.992, 73.413, 73.413, 108.27, 131.64, 132.24]
SKEW45 = [65.642, 106.489, 148.300, 157.226, 196.743, 229.464]


def nine_node_quads(ne):
    """Elements of an ne x ne mesh of nine-node quads on the (2ne+1) x (2ne+1) node grid, in
    ShellMITC9's node order (its shape2d: corners 1-4 counter-clockwise, then the midsides of
    edges 1-2, 2-3, 3-4, 4-1, then the centre)."""
    quads = []
    for ej in range(ne):
        for ei in range(ne):
            i, j = 2 * ei, 2 * ej
            quads.append(((i, j), (i + 2, j), (i + 2, j + 2), (i, j + 2),
                          (i + 1, j), (i + 2, j + 1), (i + 1, j + 2), (i, j + 1), (i + 1, j + 1)))
    return quads


def area_loads9(nodes, quads, q):
    """Consistent nodal loads of the traction q (per unit area) on nine-node parallelograms:
    corner 1/36, midside 4/36, centre 16/36 of the element's area times q."""
    w = [1.0 / 36.0] * 4 + [4.0 / 36.0] * 4 + [16.0 / 36.0]
    f = {}
    for qd in quads:
        p = [nodes[ij] for ij in qd[:4]]
        d1 = [p[2][k] - p[0][k] for k in range(3)]
        d2 = [p[3][k] - p[1][k] for k in range(3)]
        c = [d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]]
        area = 0.5 * math.sqrt(sum(v * v for v in c))
        for ij, wk in zip(qd, w):
            acc = f.setdefault(ij, [0.0] * 6)
            for k in range(3):
                acc[k] += q[k] * area * wk
    return f


def clamped_plate_modes_mitc9(ne, skew_deg, a=100.0, t=0.1, e=71700.0, nu=0.33, rho=2.81e-9):
    """As clamped_plate_modes, on ne x ne nine-node ShellMITC9 elements ((2ne+1)² nodes; its
    own consistent biquadratic translational mass). OpenSees's ShellMITC9 (Tesser, Talledo)
    takes the transverse shear strains from the displacements at the 3 x 3 Gauss points, with
    no assumed-strain tying despite its name: a Lagrangian Q9 that locks at a/t = 1000 (8×8
    square +3.27…+12.83 %, skew +8.58…+44.43 %; 2×2 ~100 times the reference)."""
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    n = 2 * ne
    sn, cs = math.sin(math.radians(skew_deg)), math.cos(math.radians(skew_deg))
    tag = lambda ij: ij[1] * (n + 1) + ij[0] + 1
    for j in range(n + 1):
        for i in range(n + 1):
            u, v = a * i / n, a * j / n
            ops.node(tag((i, j)), u + v * sn, v * cs, 0.0)
            if i in (0, n) or j in (0, n):
                ops.fix(tag((i, j)), 1, 1, 1, 1, 1, 1)
    ops.section("ElasticMembranePlateSection", 1, e, nu, t, rho)
    for k, q in enumerate(nine_node_quads(ne)):
        ops.element("ShellMITC9", k + 1, *[tag(ij) for ij in q], 1)
    d = e * t**3 / (12 * (1 - nu**2))
    return [math.sqrt(lam) * a * a * math.sqrt(rho * t / d) for lam in ops.eigen("-fullGenLapack", 6)]


def clamped_plate_pressure_mitc9(ne, a=100.0, t=1.0, e=210000.0, nu=0.3, q=0.01):
    """distorted_plate's clamped square plate (a = 100, t = 1, E = 210000, nu = 0.3, pressure
    0.01 MPa in -z) undistorted, on ne x ne ShellMITC9 elements with consistent nodal loads;
    returns the centre deflection in units of q a⁴/D (Timoshenko & Woinowsky-Krieger 0.00126;
    2×2 −98.8 %, 4×4 −20.8 %, 8×8 −4.4 %: shear locking, as in the modes)."""
    n = 2 * ne
    nodes, _ = grid(n, n, lambda i, j: (a * i / n, a * j / n, 0.0))
    quads = nine_node_quads(ne)
    fixes = {ij: range(6) for ij in nodes if ij[0] in (0, n) or ij[1] in (0, n)}
    loads = area_loads9(nodes, quads, (0.0, 0.0, -q))
    w = -solve("ShellMITC9", nodes, quads, n, t, e, nu, fixes, loads, ((ne, ne), 2))
    return w / (q * a**4 / (e * t**3 / (12 * (1 - nu**2))))


if __name__ == "__main__":
    if sys.argv[1:] == ["plate_modes"]:
        for element in ("ShellMITC4", "ShellDKGQ"):
            for skew in (0, 45):
                for n in (8, 12):
                    lam = clamped_plate_modes(element, n, skew)
                    print(json.dumps({"problem": "plate_modes", "element": element, "skew": skew, "n": n, "lambda": lam}), flush=True)
        sys.exit(0)
    if sys.argv[1:] == ["plate_modes_mitc9"]:
        for skew, ref in ((0, SQUARE), (45, SKEW45)):
            for ne in (2, 3, 4, 6, 8):
                lam = clamped_plate_modes_mitc9(ne, skew)
                err = [100.0 * (l / r - 1.0) for l, r in zip(lam, ref)]
                print(json.dumps({"problem": "plate_modes_mitc9", "element": "ShellMITC9", "skew": skew, "ne": ne,
                                  "lambda": [round(l, 4) for l in lam], "err_pct": [round(x, 2) for x in err]}), flush=True)
        sys.exit(0)
    if sys.argv[1:] == ["plate_pressure_mitc9"]:
        for ne in (2, 4, 8):
            c = clamped_plate_pressure_mitc9(ne)
            print(json.dumps({"problem": "plate_pressure_mitc9", "element": "ShellMITC9", "ne": ne, "w_qa4_D": round(c, 7),
                              "err_pct": round(100.0 * (c / 0.00126 - 1.0), 2)}), flush=True)
        sys.exit(0)
    which = sys.argv[1:] or list(PROBLEMS)
    for name in which:
        build, meshes = PROBLEMS[name]
        for element in ("ShellMITC4", "ASDShellQ4"):
            u = []
            for n in meshes:
                u.append(solve(element, *build(n)))
                print(json.dumps({"problem": name, "element": element, "n": n, "u": u[-1]}), flush=True)
            print(json.dumps({"problem": name, "element": element, "richardson": (4 * u[-1] - u[-2]) / 3}), flush=True)
