//! Reduced-order model: modal truncation with static correction as a continuous-time state-space
//! model ẋ = A x + B u, y = C x + D u.
//!
//! States are the modal coordinates and their rates, x = [η; η̇] (η = Φᵀ M q of the retained
//! mass-normalised modes): A = [[0, I], [−Ω², −2ZΩ]], B = [0; Φᵀ F], C = [C_y Φ, 0] and
//! D = C_y (K⁻¹ − Φ Ω⁻² Φᵀ) F, the residual flexibility of the truncated modes as a
//! feed-through (R. R. Craig, A. J. Kurdila, Fundamentals of Structural Dynamics, 2nd ed.,
//! Wiley 2006, §11.4; W. K. Gawronski, Advanced Structural Dynamics and Active Control of
//! Structures, Springer 2004, §2.2). The DC gain D − C A⁻¹ B is then the static compliance
//! C_y K⁻¹ F exactly, and the poles are −ζᵣωᵣ ± iωᵣ√(1 − ζᵣ²), of modulus ωᵣ.

use super::frf::{Damping, ModalFrf, C64};
use nalgebra::DMatrix;

/// A continuous-time state-space model (time in s).
#[derive(Debug, Clone, PartialEq)]
pub struct StateSpace {
    /// State matrix (2r × 2r).
    pub a: DMatrix<f64>,
    /// Input matrix (2r × inputs).
    pub b: DMatrix<f64>,
    /// Output matrix (outputs × 2r).
    pub c: DMatrix<f64>,
    /// Feed-through (outputs × inputs): the static correction.
    pub d: DMatrix<f64>,
    /// Circular frequency of each retained mode, rad/s.
    pub omega: Vec<f64>,
    /// Damping ratio of each retained mode.
    pub zeta: Vec<f64>,
}

/// The state-space model of a modal model with `damping` (see the module docs).
pub fn state_space(m: &ModalFrf, damping: &Damping) -> StateSpace {
    let r = m.omega.len();
    let (ni, no) = (m.phi_in.ncols(), m.phi_out.nrows());
    let zeta: Vec<f64> = m.omega.iter().map(|&w| damping.ratio(w)).collect();
    let mut a = DMatrix::zeros(2 * r, 2 * r);
    for (i, (&w, &z)) in m.omega.iter().zip(&zeta).enumerate() {
        a[(i, r + i)] = 1.0;
        a[(r + i, i)] = -w * w;
        a[(r + i, r + i)] = -2.0 * z * w;
    }
    let mut b = DMatrix::zeros(2 * r, ni);
    b.rows_mut(r, r).copy_from(&m.phi_in);
    let mut c = DMatrix::zeros(no, 2 * r);
    c.columns_mut(0, r).copy_from(&m.phi_out);
    StateSpace {
        a,
        b,
        c,
        d: m.residual.clone(),
        omega: m.omega.clone(),
        zeta,
    }
}

impl StateSpace {
    /// Number of states.
    pub fn n_states(&self) -> usize {
        self.a.nrows()
    }

    /// DC gain D − C A⁻¹ B (`None` if A is singular).
    pub fn dc_gain(&self) -> Option<DMatrix<f64>> {
        let x = self.a.clone().lu().solve(&self.b)?;
        Some(&self.d - &self.c * x)
    }

    /// Eigenvalues of A (the poles), 1/s.
    pub fn poles(&self) -> Vec<C64> {
        self.a.complex_eigenvalues().iter().copied().collect()
    }

    /// G(iω) = C (iωI − A)⁻¹ B + D at `f_hz` (`None` if iω is a pole).
    pub fn response(&self, f_hz: f64) -> Option<DMatrix<C64>> {
        let w = 2.0 * std::f64::consts::PI * f_hz;
        let n = self.n_states();
        let s = DMatrix::<C64>::from_fn(n, n, |i, j| {
            let iw = if i == j { C64::new(0.0, w) } else { C64::new(0.0, 0.0) };
            iw - self.a[(i, j)]
        });
        let x = s.lu().solve(&self.b.map(C64::from))?;
        Some(self.c.map(C64::from) * x + self.d.map(C64::from))
    }

    /// The four matrices as [`sprs::CsMat`] (exact zeros left out), named `A`, `B`, `C`, `D`.
    pub fn sparse(&self) -> [(&'static str, sprs::CsMat<f64>); 4] {
        [
            ("A", dense_to_csmat(&self.a)),
            ("B", dense_to_csmat(&self.b)),
            ("C", dense_to_csmat(&self.c)),
            ("D", dense_to_csmat(&self.d)),
        ]
    }
}

/// A dense matrix as a [`sprs::CsMat`] (compressed rows, exact zeros left out).
pub fn dense_to_csmat(m: &DMatrix<f64>) -> sprs::CsMat<f64> {
    let mut tri = sprs::TriMat::new((m.nrows(), m.ncols()));
    for j in 0..m.ncols() {
        for i in 0..m.nrows() {
            if m[(i, j)] != 0.0 {
                tri.add_triplet(i, j, m[(i, j)]);
            }
        }
    }
    tri.to_csr()
}
