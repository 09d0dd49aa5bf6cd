#!/usr/bin/env python3
"""Coarse-mesh plate candidates measured for tests/shell_coarse_mesh.rs (numpy + scipy only).

Thin-plate (Kirchhoff-limit) Bloch dispersion on a mesh of unit squares, w = W·exp(i q·x), and
the clamped square / 45° rhombic plates of that test, for two bending stiffnesses:

* MITC4 in the thin limit (rotations tied to the edge chords: the mean rotation of an edge equals
  its chord slope), bilinear rotations, bending energy at Gauss points ±sqrt(g) (g = 1/3 is the
  2×2 rule; g ≠ 1/3 scales the hourglass part of the energy by f = 3g);
* DKQ (J.-L. Batoz, M. Ben Tahar, IJNME 18 (1982) 1655): serendipity rotations, mid-side
  tangential rotation from the edge cubic, normal rotation linear.

Prints the coefficient c(φ) of ω_h/ω − 1 = (qh)²/8·c(φ) (lumped translational mass; the tiles of
flexfem's shell mass subtract 1/3) and, for DKQ with the lumped mass, λ = ωa²√(ρt/D) of modes
1–6 of the clamped plates against the references of tests/shell_coarse_mesh.rs.
Conventions here: θx = ∂w/∂x, θy = ∂w/∂y; κ = (∂θx/∂x, ∂θy/∂y, ∂θx/∂y + ∂θy/∂x).
"""
import numpy as np
import scipy.linalg as sl

NU = 0.33
XI = np.array([-1.0, 1.0, 1.0, -1.0])
ETA = np.array([-1.0, -1.0, 1.0, 1.0])
SQUARE = [35.992, 73.413, 73.413, 108.27, 131.64, 132.24]
SKEW45 = [65.642, 106.489, 148.300, 157.226, 196.743, 229.464]


def dmat(nu=NU):
    return np.array([[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu) / 2]]) / (12 * (1 - nu**2))


def bilinear(xi, eta):
    return (0.25 * (1 + XI * xi) * (1 + ETA * eta), 0.25 * XI * (1 + ETA * eta), 0.25 * ETA * (1 + XI * xi))


def mitc4_thin_bending(g=1 / 3, nu=NU):
    """Bending stiffness of a unit square over (w, θx, θy) × 4, points at ±sqrt(g)."""
    k = np.zeros((12, 12))
    s = np.sqrt(g)
    for xi in (-s, s):
        for eta in (-s, s):
            _, dxi, deta = bilinear(xi, eta)
            dx, dy = 2 * dxi, 2 * deta
            b = np.zeros((3, 12))
            b[0, 1::3], b[1, 2::3] = dx, dy
            b[2, 1::3], b[2, 2::3] = dy, dx
            k += 0.25 * b.T @ dmat(nu) @ b
    return k


def serendipity(xi, eta):
    """8-node serendipity N and natural derivatives; corners as XI/ETA, then mid-sides 0-1, 1-2, 2-3, 3-0."""
    n, dxi, deta = np.zeros(8), np.zeros(8), np.zeros(8)
    for k in range(4):
        a, b = XI[k], ETA[k]
        n[k] = 0.25 * (1 + a * xi) * (1 + b * eta) * (a * xi + b * eta - 1)
        dxi[k] = 0.25 * a * (1 + b * eta) * (2 * a * xi + b * eta)
        deta[k] = 0.25 * b * (1 + a * xi) * (a * xi + 2 * b * eta)
    n[4:] = [0.5 * (1 - xi**2) * (1 - eta), 0.5 * (1 + xi) * (1 - eta**2), 0.5 * (1 - xi**2) * (1 + eta), 0.5 * (1 - xi) * (1 - eta**2)]
    dxi[4:] = [-xi * (1 - eta), 0.5 * (1 - eta**2), -xi * (1 + eta), -0.5 * (1 - eta**2)]
    deta[4:] = [-0.5 * (1 - xi**2), -(1 + xi) * eta, 0.5 * (1 - xi**2), -(1 - xi) * eta]
    return n, dxi, deta


def dkq_bending(x, npt=2, nu=NU):
    """DKQ bending stiffness over (w, θx, θy) × 4 of the quadrilateral with corners x (4×2)."""
    t = np.zeros((16, 12))  # [θx at 8 nodes, θy at 8 nodes] from the corner dofs
    for k in range(4):
        t[k, 3 * k + 1] = t[8 + k, 3 * k + 2] = 1
    for m in range(4):
        i, j = m, (m + 1) % 4
        d = x[j] - x[i]
        l = np.linalg.norm(d)
        c, s = d / l
        ts, tn = np.zeros(12), np.zeros(12)
        ts[3 * i], ts[3 * j] = -1.5 / l, 1.5 / l
        for k in (i, j):
            ts[3 * k + 1] -= 0.25 * c
            ts[3 * k + 2] -= 0.25 * s
            tn[3 * k + 1] -= 0.5 * s
            tn[3 * k + 2] += 0.5 * c
        t[4 + m], t[12 + m] = c * ts - s * tn, s * ts + c * tn
    g, wg = np.polynomial.legendre.leggauss(npt)
    k = np.zeros((12, 12))
    for xi, wx in zip(g, wg):
        for eta, wy in zip(g, wg):
            _, dxi, deta = serendipity(xi, eta)
            _, cx, ce = bilinear(xi, eta)
            jac = np.array([cx @ x, ce @ x])
            ji = np.linalg.inv(jac)
            dx, dy = ji[0, 0] * dxi + ji[0, 1] * deta, ji[1, 0] * dxi + ji[1, 1] * deta
            z = np.zeros(8)
            b = np.vstack([np.concatenate([dx, z]) @ t, np.concatenate([z, dy]) @ t, np.concatenate([dy, dx]) @ t])
            k += wx * wy * np.linalg.det(jac) * b.T @ dmat(nu) @ b
    return k


def bloch_ratio(k, qh, phi, tied):
    """ω_h/ω on unit squares, lumped mass ρt = 1; `tied`: rotations from the edge chords."""
    a, b = qh * np.cos(phi), qh * np.sin(phi)
    p = np.zeros((12, 3), complex)
    for m, (i, j) in enumerate([(0, 0), (1, 0), (1, 1), (0, 1)]):
        p[3 * m: 3 * m + 3, :] = np.exp(1j * (a * i + b * j)) * np.eye(3)
    kb = p.conj().T @ k @ p
    if tied:
        r = np.array([1, 2 * 1j * np.tan(a / 2), 2 * 1j * np.tan(b / 2)])
        keff = (r.conj() @ kb @ r).real
    else:
        keff = (kb[0, 0] - kb[0, 1:] @ np.linalg.solve(kb[1:, 1:], kb[1:, 0])).real
    d = 1 / (12 * (1 - NU**2))
    return np.sqrt(keff / (d * qh**4))


def coefficient(k, phi, tied, qh=0.1):
    """c(φ) with ω_h/ω − 1 = (qh)²/8·c(φ) + O((qh)⁴) (Richardson over qh, qh/2)."""
    c1 = (bloch_ratio(k, qh, phi, tied) - 1) / (qh**2 / 8)
    c2 = (bloch_ratio(k, qh / 2, phi, tied) - 1) / (qh**2 / 32)
    return (4 * c2 - c1) / 3


def clamped_plate_dkq(n, skew_deg, nmodes=6, consistent=False):
    """λ of modes 1–6 of the clamped plate (side 1) with DKQ and the lumped mass (or, with
    `consistent`, the consistent bilinear translational mass ∫ρt NᵢNⱼ, no rotary inertia: the
    mass of OpenSees 3.7.1's ShellDKGQ, whose frequencies this reproduces to every digit printed:
    45° skew 8×8 59.707 98.223 133.873 138.938 190.481 201.579, square 8×8 36.295 76.532 76.532
    113.061 145.671 146.468, openseespy 3.7.1.2, eigen -fullGenLapack; an independent check of
    the DKQ stiffness here, skew mesh included)."""
    sn, cs = np.sin(np.radians(skew_deg)), np.cos(np.radians(skew_deg))
    idx = lambda i, j: i * (n + 1) + j
    xy = np.array([[i / n + j / n * sn, j / n * cs] for i in range(n + 1) for j in range(n + 1)])
    nd = 3 * (n + 1) ** 2
    k, m = np.zeros((nd, nd)), np.zeros((nd, nd))
    g, wg = np.polynomial.legendre.leggauss(2)
    for i in range(n):
        for j in range(n):
            nodes = [idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)]
            x = xy[nodes]
            dofs = np.array([[3 * q, 3 * q + 1, 3 * q + 2] for q in nodes]).ravel()
            k[np.ix_(dofs, dofs)] += dkq_bending(x)
            wd = 3 * np.array(nodes)
            for xi, wx in zip(g, wg):
                for eta, wy in zip(g, wg):
                    nn, cx, ce = bilinear(xi, eta)
                    da = wx * wy * np.linalg.det(np.array([cx @ x, ce @ x]))
                    m[np.ix_(wd, wd)] += da * (np.outer(nn, nn) if consistent else np.diag(nn))
    inner = [idx(i, j) for i in range(1, n) for j in range(1, n)]
    w = np.array([3 * q for q in inner])
    r = np.array([3 * q + d for q in inner for d in (1, 2)])
    # No rotary inertia: the rotations are condensed out statically (exact for the eigenvalues).
    kc = k[np.ix_(w, w)] - k[np.ix_(w, r)] @ np.linalg.solve(k[np.ix_(r, r)], k[np.ix_(r, w)])
    ev = sl.eigh(kc, m[np.ix_(w, w)], eigvals_only=True)[:nmodes]
    return np.sqrt(ev * 12 * (1 - NU**2))


if __name__ == "__main__":
    angles = np.radians([0, 22.5, 45])
    unit = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    f = 1 + (13 + NU) / (3 - NU)
    for name, k, tied in [
        ("MITC4 (closed form 1/3 − (13+ν)/24·sin²2φ)", mitc4_thin_bending(), True),
        (f"MITC4, hourglass part × {f:.4f}", mitc4_thin_bending(g=f / 3), True),
        ("DKQ (closed form −(7+ν)/24·sin²2φ)", dkq_bending(unit), False),
    ]:
        print(name, "c(0°, 22.5°, 45°) =", " ".join(f"{coefficient(k, p, tied):+.4f}" for p in angles))
    for consistent in (False, True):
        for n in (8, 12):
            for skew, ref in ((0, SQUARE), (45, SKEW45)):
                lam = clamped_plate_dkq(n, skew, consistent=consistent)
                name = "consistent" if consistent else "lumped"
                print(f"DKQ {name} {n}x{n} skew {skew}°:", " ".join(f"{l:.3f} ({100 * (l / r - 1):+.2f} %)" for l, r in zip(lam, ref)))
