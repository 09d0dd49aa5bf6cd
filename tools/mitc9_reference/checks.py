import numpy as np
from mitc9 import *

E, nu, t, rho = 72000.0, 0.33, 0.1, 2.81e-9
rng = np.random.default_rng(1)

# --- distorted 2x2 mesh: straight-sided quads, midside nodes at edge midpoints,
# centre node at bilinear centre (so quadratic fields in x,y are in the element space)
corners = np.array([[0, 0], [1, 0], [2, 0], [0, 1], [1, 1], [2, 1], [0, 2], [1, 2], [2, 2]], float)
corners[4] = [1.17, 0.83]
corners[1] = [0.93, 0.0]; corners[7] = [1.12, 2.0]; corners[3] = [0.0, 1.09]; corners[5] = [2.0, 0.88]
X = np.zeros((25, 2))
for I in range(3):
    for J in range(3):
        X[(2 * I) * 5 + 2 * J] = corners[J * 3 + I]  # i -> x, j -> y (right-handed)
nid = lambda i, j: i * 5 + j
for i in range(5):
    for j in range(5):
        if i % 2 == 1 and j % 2 == 0:
            X[nid(i, j)] = 0.5 * (X[nid(i - 1, j)] + X[nid(i + 1, j)])
        if i % 2 == 0 and j % 2 == 1:
            X[nid(i, j)] = 0.5 * (X[nid(i, j - 1)] + X[nid(i, j + 1)])
for i in (1, 3):
    for j in (1, 3):
        X[nid(i, j)] = 0.25 * (X[nid(i - 1, j - 1)] + X[nid(i + 1, j - 1)] + X[nid(i + 1, j + 1)] + X[nid(i - 1, j + 1)])
X *= 10.0
conn = []
for ei in range(2):
    for ej in range(2):
        i0, j0 = 2 * ei, 2 * ej
        conn.append([nid(i0, j0), nid(i0 + 2, j0), nid(i0 + 2, j0 + 2), nid(i0, j0 + 2),
                     nid(i0 + 1, j0), nid(i0 + 2, j0 + 1), nid(i0 + 1, j0 + 2), nid(i0, j0 + 1), nid(i0 + 1, j0 + 1)])
conn = np.array(conn)
bnd = [nid(i, j) for i in range(5) for j in range(5) if i in (0, 4) or j in (0, 4)]
inner = [n for n in range(25) if n not in bnd]
K, M, F = assemble(X, conn, E, nu, t, rho)
D = E * t ** 3 / (12 * (1 - nu ** 2))
Db = D * np.array([[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu) / 2]])


def field(x, y, case):
    if case == 'bending':  # w quadratic, beta = -grad w  => zero shear, constant curvature
        kx, ky, kxy = 1e-3, -2e-3, 1.5e-3
        w = -0.5 * (kx * x * x + ky * y * y + kxy * x * y) + 0.3 + 0.01 * x - 0.02 * y
        bx = kx * x + 0.5 * kxy * y - 0.01
        by = ky * y + 0.5 * kxy * x + 0.02
        return np.array([w, bx, by])
    else:  # constant shear: w linear, beta constant
        return np.array([0.01 * x - 0.02 * y + 0.1, 0.003, -0.004])


for case in ('bending',):
    uex = np.concatenate([field(x, y, case) for x, y in X])
    fixed = np.array([3 * n + k for n in bnd for k in range(3)])
    free = np.array([3 * n + k for n in inner for k in range(3)])
    u = uex.copy(); u[free] = 0
    u[free] = np.linalg.solve(K[np.ix_(free, free)], -K[np.ix_(free, fixed)] @ uex[fixed])
    err = np.abs(u - uex).max() / np.abs(uex).max()
    # moments at Gauss points of all elements
    mom = []
    for c in conn:
        ue = u[np.array([[3 * n, 3 * n + 1, 3 * n + 2] for n in c]).ravel()]
        for r in GP3:
            for s in GP3:
                mom.append(moments_at(X[c], ue, E, nu, t, r, s))
    mom = np.array(mom)
    print(f"patch [{case}] max rel nodal error = {err:.3e}; moment spread = {np.ptp(mom, axis=0)}; M = {mom[0]}")
    # residual forces at free dofs with exact field
    res = K @ uex
    print(f"   |K u_exact| at interior dofs (rel) = {np.abs(res[free]).max() / np.abs(K).max() / np.abs(uex).max():.3e}")

if True:
    # force-driven constant moment patch: apply boundary nodal loads = K u_exact, support rigid modes minimally
    uex = np.concatenate([field(x, y, 'bending') for x, y in X])
    fext = K @ uex  # equivalent nodal forces (nonzero only at boundary)
    sup = [3 * nid(0, 0), 3 * nid(0, 0) + 1, 3 * nid(0, 0) + 2]  # fix w, bx, by at one node -> removes 3 rigid modes
    free = np.array([d for d in range(75) if d not in sup])
    u = uex.copy()
    u[free] = np.linalg.solve(K[np.ix_(free, free)], fext[free] - K[np.ix_(free, sup)] @ uex[sup])
    print(f"patch [force-driven bending] max rel error = {np.abs(u - uex).max() / np.abs(uex).max():.3e}")

# single element rank (3 rigid modes expected: w const, and two tilts with beta=-grad w)
xy = X[conn[0]]
Ke, _, _ = element(xy, E, nu, t, rho)
ev = np.sort(np.linalg.eigvalsh(Ke))
print("single distorted element smallest eigenvalues / max:", (ev[:5] / ev[-1]))

# x<->y mirror symmetry of element on square
xy = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [.5, 0], [1, .5], [.5, 1], [0, .5], [.5, .5]]) * 7.0
Ke, _, _ = element(xy, E, nu, t, rho)
# mirror: node (r,s)->(s,r): permutation of local nodes
perm = [0, 3, 2, 1, 7, 6, 5, 4, 8]
P = np.zeros((27, 27))
for a, b in enumerate(perm):
    P[3 * a, 3 * b] = 1; P[3 * a + 1, 3 * b + 2] = 1; P[3 * a + 2, 3 * b + 1] = 1
print("mirror-symmetry error:", np.abs(P @ Ke @ P.T - Ke).max() / np.abs(Ke).max())
