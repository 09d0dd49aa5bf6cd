"""Independent MITC9 Reissner-Mindlin plate element (Bucalem & Bathe 1993; Bathe FEP 2014 §5.4).

DOFs per node: (w, bx, by).  Rotation convention: in-plane displacements
u = z*bx, v = z*by (bx, by are the rotations of the normal in the x-z and y-z
planes, "displacement-type" rotations).  Hence
  curvatures  kxx = d(bx)/dx, kyy = d(by)/dy, kxy = d(bx)/dy + d(by)/dx
  shear       gxz = dw/dx + bx,  gyz = dw/dy + by
Covariant shear strains: e_r = dw/dr + bx*dx/dr + by*dy/dr, e_s likewise,
and (gxz, gyz)^T = J^{-1} (e_r, e_s)^T with J = [[x_r, y_r], [x_s, y_s]].

Local node order (r, s): 0:(-1,-1) 1:(1,-1) 2:(1,1) 3:(-1,1) 4:(0,-1) 5:(1,0)
6:(0,1) 7:(-1,0) 8:(0,0).
"""
import numpy as np
import scipy.linalg as sla

NODE_RS = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1], [0, -1], [1, 0], [0, 1], [-1, 0], [0, 0]], float)


def lag1d_quad(x):
    """quadratic Lagrange at nodes -1,0,1 and derivatives"""
    N = np.array([0.5 * x * (x - 1), 1 - x * x, 0.5 * x * (x + 1)])
    dN = np.array([x - 0.5, -2 * x, x + 0.5])
    return N, dN


def shape9(r, s):
    Nr, dNr = lag1d_quad(r)
    Ns, dNs = lag1d_quad(s)
    idx = {-1: 0, 0: 1, 1: 2}
    N = np.zeros(9); Dr = np.zeros(9); Ds = np.zeros(9)
    for k, (ri, si) in enumerate(NODE_RS):
        a, b = idx[int(ri)], idx[int(si)]
        N[k] = Nr[a] * Ns[b]; Dr[k] = dNr[a] * Ns[b]; Ds[k] = Nr[a] * dNs[b]
    return N, Dr, Ds


def lagrange(pts, x):
    """1D Lagrange basis through pts evaluated at x"""
    L = np.ones(len(pts))
    for i, pi in enumerate(pts):
        for j, pj in enumerate(pts):
            if i != j:
                L[i] *= (x - pj) / (pi - pj)
    return L


g3 = np.sqrt(0.6)
GP3 = np.array([-g3, 0.0, g3]); GW3 = np.array([5 / 9, 8 / 9, 5 / 9])
A2 = 1 / np.sqrt(3)
P2 = np.array([-A2, A2]); P3 = np.array([-g3, 0.0, g3])
# tying points: e_rt at (r in P2) x (s in P3); e_st at (r in P3) x (s in P2)
TIE_R = [(r, s) for r in P2 for s in P3]
TIE_S = [(r, s) for r in P3 for s in P2]


def cov_shear_rows(xy, r, s):
    """rows (1x27) giving covariant e_r and e_s at (r,s) from element dofs"""
    N, Dr, Ds = shape9(r, s)
    xr = Dr @ xy; xs = Ds @ xy
    er = np.zeros(27); es = np.zeros(27)
    er[0::3] = Dr; er[1::3] = N * xr[0]; er[2::3] = N * xr[1]
    es[0::3] = Ds; es[1::3] = N * xs[0]; es[2::3] = N * xs[1]
    return er, es


def element(xy, E, nu, t, rho, kappa=5.0 / 6.0, shear='mitc'):
    """returns K (27x27), M (27x27), fq (27, consistent load for unit pressure)"""
    D = E * t ** 3 / (12 * (1 - nu ** 2))
    Db = D * np.array([[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu) / 2]])
    G = E / (2 * (1 + nu))
    Ds_ = kappa * G * t * np.eye(2)
    # tied covariant strain rows
    ER = np.array([cov_shear_rows(xy, r, s)[0] for (r, s) in TIE_R])  # 6x27
    ES = np.array([cov_shear_rows(xy, r, s)[1] for (r, s) in TIE_S])  # 6x27
    K = np.zeros((27, 27)); M = np.zeros((27, 27)); f = np.zeros(27)
    for i, r in enumerate(GP3):
        for j, s in enumerate(GP3):
            wgt = GW3[i] * GW3[j]
            N, Dr, Dsv = shape9(r, s)
            J = np.array([Dr @ xy, Dsv @ xy])  # [[x_r,y_r],[x_s,y_s]]
            detJ = np.linalg.det(J)
            assert detJ > 0, 'left-handed / inverted element'
            Ji = np.linalg.inv(J)
            dN = Ji @ np.vstack([Dr, Dsv])  # rows: d/dx, d/dy
            Bb = np.zeros((3, 27))
            Bb[0, 1::3] = dN[0]; Bb[1, 2::3] = dN[1]
            Bb[2, 1::3] = dN[1]; Bb[2, 2::3] = dN[0]
            if shear == 'mitc':
                Lr = np.outer(lagrange(P2, r), lagrange(P3, s)).ravel()  # order matches TIE_R
                Ls = np.outer(lagrange(P3, r), lagrange(P2, s)).ravel()  # order matches TIE_S
                e_r = Lr @ ER; e_s = Ls @ ES
            else:  # pure displacement (locking) for comparison
                e_r, e_s = cov_shear_rows(xy, r, s)
            Bs = Ji @ np.vstack([e_r, e_s])
            dA = wgt * detJ
            K += dA * (Bb.T @ Db @ Bb + Bs.T @ Ds_ @ Bs)
            Nw = np.zeros((3, 27)); Nw[0, 0::3] = N; Nw[1, 1::3] = N; Nw[2, 2::3] = N
            M += dA * Nw.T @ np.diag([rho * t, rho * t ** 3 / 12, rho * t ** 3 / 12]) @ Nw
            f[0::3] += dA * N
    return K, M, f


def moments_at(xy, ue, E, nu, t, r, s):
    D = E * t ** 3 / (12 * (1 - nu ** 2))
    Db = D * np.array([[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu) / 2]])
    N, Dr, Dsv = shape9(r, s)
    J = np.array([Dr @ xy, Dsv @ xy]); dN = np.linalg.inv(J) @ np.vstack([Dr, Dsv])
    k = np.array([dN[0] @ ue[1::3], dN[1] @ ue[2::3], dN[1] @ ue[1::3] + dN[0] @ ue[2::3]])
    return Db @ k


def grid_mesh(NE, mapxy):
    n = 2 * NE + 1
    X = np.zeros((n * n, 2))
    for i in range(n):
        for j in range(n):
            X[i * n + j] = mapxy(i, j)
    nid = lambda i, j: i * n + j
    conn = []
    for ei in range(NE):
        for ej in range(NE):
            i0, j0 = 2 * ei, 2 * ej
            conn.append([nid(i0, j0), nid(i0 + 2, j0), nid(i0 + 2, j0 + 2), nid(i0, j0 + 2),
                         nid(i0 + 1, j0), nid(i0 + 2, j0 + 1), nid(i0 + 1, j0 + 2), nid(i0, j0 + 1),
                         nid(i0 + 1, j0 + 1)])
    bnd = [nid(i, j) for i in range(n) for j in range(n) if i in (0, n - 1) or j in (0, n - 1)]
    return X, np.array(conn), bnd


def assemble(X, conn, E, nu, t, rho, shear='mitc'):
    nd = 3 * len(X)
    K = np.zeros((nd, nd)); M = np.zeros((nd, nd)); F = np.zeros(nd)
    for c in conn:
        Ke, Me, fe = element(X[c], E, nu, t, rho, shear=shear)
        dofs = np.array([[3 * n, 3 * n + 1, 3 * n + 2] for n in c]).ravel()
        K[np.ix_(dofs, dofs)] += Ke; M[np.ix_(dofs, dofs)] += Me; F[dofs] += fe
    return K, M, F


def element_energy(xy, ue, E, nu, t, kappa=5.0 / 6.0):
    """2 x strain energy of one element computed from strains (sum of non-negative terms,
    avoids the cancellation in u^T K u for thin plates)"""
    D = E * t ** 3 / (12 * (1 - nu ** 2))
    Db = D * np.array([[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu) / 2]])
    G = E / (2 * (1 + nu))
    # tied covariant strains (values), computed directly as dw/dr + beta.g_r
    def cov(r, s):
        N, Dr, Ds = shape9(r, s)
        xr = Dr @ xy; xs = Ds @ xy
        b = np.array([N @ ue[1::3], N @ ue[2::3]])
        return Dr @ ue[0::3] + b @ xr, Ds @ ue[0::3] + b @ xs
    ER = np.array([cov(r, s)[0] for (r, s) in TIE_R]); ES = np.array([cov(r, s)[1] for (r, s) in TIE_S])
    U = 0.0
    for i, r in enumerate(GP3):
        for j, s in enumerate(GP3):
            N, Dr, Dsv = shape9(r, s)
            J = np.array([Dr @ xy, Dsv @ xy]); Ji = np.linalg.inv(J); dA = GW3[i] * GW3[j] * np.linalg.det(J)
            dN = Ji @ np.vstack([Dr, Dsv])
            k = np.array([dN[0] @ ue[1::3], dN[1] @ ue[2::3], dN[1] @ ue[1::3] + dN[0] @ ue[2::3]])
            g = Ji @ np.array([np.outer(lagrange(P2, r), lagrange(P3, s)).ravel() @ ER,
                               np.outer(lagrange(P3, r), lagrange(P2, s)).ravel() @ ES])
            U += dA * (k @ Db @ k + kappa * G * t * g @ g)
    return U
