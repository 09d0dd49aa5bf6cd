import numpy as np
import scipy.linalg as sla
from mitc9 import *

E, nu, rho = 72000.0, 0.33, 2.81e-9
a = 100.0
import sys
DRIVER = sys.argv[1] if len(sys.argv) > 1 else 'gvx'
VERBOSE = len(sys.argv) > 2
s45 = np.sin(np.pi / 4); c45 = np.cos(np.pi / 4)


def free_dofs(nnodes, bnd):
    fixed = set()
    for b in bnd:
        fixed |= {3 * b, 3 * b + 1, 3 * b + 2}
    return np.array([d for d in range(3 * nnodes) if d not in fixed])


def modes(NE, mapxy, t, nmodes=6):
    X, conn, bnd = grid_mesh(NE, mapxy)
    K, M, F = assemble(X, conn, E, nu, t, rho)
    fr = free_dofs(len(X), bnd)
    Kf = K[np.ix_(fr, fr)]; Mf = M[np.ix_(fr, fr)]
    sc = 1 / np.sqrt(np.diag(Kf))  # Jacobi scaling (eigenvalues unchanged, better conditioning)
    Kf = Kf * np.outer(sc, sc); Mf = Mf * np.outer(sc, sc)
    w2, V = sla.eigh(Kf, Mf, subset_by_index=[0, nmodes - 1], driver=DRIVER)
    # Rayleigh-quotient refinement with element-wise (cancellation-free) strain energies
    w2rq = []
    for k in range(nmodes):
        u = np.zeros(3 * len(X)); u[fr] = sc * V[:, k]
        num = sum(element_energy(X[c], u[np.array([[3*n, 3*n+1, 3*n+2] for n in c]).ravel()], E, nu, t) for c in conn)
        w2rq.append(num / (u @ M @ u))
    w2rq = np.array(w2rq)
    if VERBOSE: print('   rel diff eigh vs RQ:', np.abs(w2rq / w2 - 1).max())
    w2 = w2rq
    D = E * t ** 3 / (12 * (1 - nu ** 2))
    return np.sqrt(w2) * a ** 2 * np.sqrt(rho * t / D)


def fmt(v):
    return f"{v:#.6g}"


sq = lambda NE: (lambda i, j: (a * i / (2 * NE), a * j / (2 * NE)))
def rh(NE):
    def m(i, j):
        u, v = a * i / (2 * NE), a * j / (2 * NE)
        return (u + v * s45, v * c45)
    return m

for name, mp in [("square", sq), ("rhombic45", rh)]:
    print(f"== {name} clamped, t=0.1, lambda = omega a^2 sqrt(rho t/D)")
    for NE in (4, 6, 8):
        lam = modes(NE, mp(NE), 0.1)
        print(f"NE={NE}: " + "  ".join(fmt(x) for x in lam))

print("== square clamped, t=1, uniform q: w_centre / (q a^4/D)")
t = 1.0
D = E * t ** 3 / (12 * (1 - nu ** 2))
for NE in (4, 8, 16):
    X, conn, bnd = grid_mesh(NE, sq(NE))
    K, M, F = assemble(X, conn, E, nu, t, rho)
    fr = free_dofs(len(X), bnd)
    u = np.zeros(3 * len(X))
    u[fr] = np.linalg.solve(K[np.ix_(fr, fr)], F[fr])  # q = 1
    n = 2 * NE + 1
    c = NE * n + NE
    print(f"NE={NE}: {fmt(u[3 * c] / (a ** 4 / D))}")
