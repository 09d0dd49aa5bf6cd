//! Derivatives of natural frequencies: for a simple mode with mass-normalised shape φ
//! (φᵀMφ = 1), dω²/dp = φᵀ(dK/dp − ω² dM/dp)φ (R. L. Fox & M. P. Kapoor, "Rates of change of
//! eigenvalues and eigenvectors", AIAA Journal 6(12):2426–2429, 1968), no extra solve; the
//! frequency f = ω/2π has df/dp = (dω²/dp)/(8π² f).
//!
//! A repeated eigenvalue (m modes within [`REPEATED`] of each other) is not differentiable: its
//! modes may rotate into one another. What is given there is the one-sided derivative for an
//! increasing parameter: the eigenvalues of the m×m matrix Φᵀ(dK − ω² dM)Φ over the cluster's
//! shapes Φ, sorted, the k-th going to the k-th mode of the cluster (each parameter on its
//! own); a model note says so.

use super::{GradientError, Target};
use crate::fem::{self, modal, solve::SparseMatrix, System};
use nalgebra::DMatrix;

/// Relative gap between eigenvalues below which modes count as repeated.
pub const REPEATED: f64 = 1e-6;

/// The modes the targets need: eigenvalues ω², (rad/s)², and reduced mass-normalised shapes.
pub(crate) struct Modes {
    lambda: Vec<f64>,
    shapes: Vec<Vec<f64>>,
    /// Notes for the result: one per repeated mode (none when every mode asked for is simple).
    pub notes: Vec<String>,
}

impl Modes {
    /// The modes of `model` up to the highest one a target asks for (the supports-only
    /// system `free` gives the equation numbering), one more to see whether the last repeats.
    pub fn new(model: &fem::Model, free: &System, targets: &[Target]) -> Result<Modes, GradientError> {
        let n = targets
            .iter()
            .filter_map(|t| match t {
                Target::Frequency { mode } => Some(*mode),
                _ => None,
            })
            .max()
            .unwrap_or(0);
        if n == 0 {
            return Ok(Modes {
                lambda: Vec::new(),
                shapes: Vec::new(),
                notes: Vec::new(),
            });
        }
        let map = free.dof_map();
        let mut opts = modal::ModalOptions::new((n + 1).min(map.n_eq()));
        opts.tol = 1e-10;
        opts.par = fem::solve::Parallelism::Sequential;
        let r = modal::solve_modal(model, &opts)?;
        if r.modes.len() < n {
            return Err(GradientError::case(format!(
                "mode {n}: the model has {} modes",
                r.modes.len()
            )));
        }
        let mut shapes = Vec::with_capacity(r.modes.len());
        for m in &r.modes {
            // Equation values from the node displacements (framed nodes back to their frame).
            let q: Vec<f64> = map
                .eq_dof
                .iter()
                .map(|&g| {
                    let (node, d) = (g / 6, g % 6);
                    let u = nalgebra::Vector6::from_row_slice(&m.shape[node]);
                    match (&map.arm[node], map.framed.contains(&node)) {
                        (Some(t), true) => (t.transpose() * u)[d],
                        _ => u[d],
                    }
                })
                .collect();
            shapes.push(q);
        }
        let lambda: Vec<f64> = r.modes.iter().map(|m| m.eigenvalue).collect();
        let mut notes = Vec::new();
        for k in 1..=n {
            let c = cluster(&lambda, k - 1);
            if c.len() > 1 {
                notes.push(format!(
                    "mode {k} is repeated (modes {}–{} within {REPEATED:e}): its frequency is not differentiable; its gradient is the one-sided derivative for an increasing parameter (eigenvalues of Φᵀ(dK − ω²dM)Φ over the repeated shapes)",
                    c.start + 1,
                    c.end
                ));
            }
        }
        Ok(Modes { lambda, shapes, notes })
    }

    /// No mode is needed.
    pub fn is_empty(&self) -> bool {
        self.lambda.is_empty()
    }

    /// Sets the frequency targets' values, Hz.
    pub fn fill_values(&self, targets: &[Target], out: &mut [f64]) {
        for (t, o) in targets.iter().zip(out.iter_mut()) {
            if let Target::Frequency { mode } = t {
                *o = self.lambda[mode - 1].max(0.0).sqrt() / (2.0 * std::f64::consts::PI);
            }
        }
    }

    /// Sets the frequency targets' derivatives, Hz per unit parameter, from the reduced dK/dp
    /// and dM/dp.
    pub fn fill_derivatives(&self, targets: &[Target], dk: &SparseMatrix, dm: &SparseMatrix, out: &mut [f64]) {
        for (t, o) in targets.iter().zip(out.iter_mut()) {
            let Target::Frequency { mode } = t else {
                continue;
            };
            let k = mode - 1;
            let lam = self.lambda[k];
            let c = cluster(&self.lambda, k);
            let form = |a: usize, b: usize| {
                let (ka, ma) = (dk.mul_vec(&self.shapes[a]), dm.mul_vec(&self.shapes[a]));
                let phi = &self.shapes[b];
                phi.iter()
                    .zip(ka.iter().zip(&ma))
                    .map(|(p, (x, y))| p * (x - lam * y))
                    .sum::<f64>()
            };
            let dlam = if c.len() == 1 {
                form(k, k)
            } else {
                let m = c.len();
                let d = DMatrix::from_fn(m, m, |i, j| form(c.start + i, c.start + j));
                let d = (&d + d.transpose()) * 0.5;
                let mut e: Vec<f64> = d.symmetric_eigen().eigenvalues.iter().copied().collect();
                e.sort_by(f64::total_cmp);
                e[k - c.start]
            };
            let f = lam.max(0.0).sqrt() / (2.0 * std::f64::consts::PI);
            *o = dlam / (8.0 * std::f64::consts::PI.powi(2) * f);
        }
    }
}

/// The modes whose eigenvalues lie within [`REPEATED`] of mode `k`'s (a contiguous range).
fn cluster(lambda: &[f64], k: usize) -> std::ops::Range<usize> {
    let near = |i: usize| (lambda[i] - lambda[k]).abs() <= REPEATED * lambda[k].abs();
    let mut a = k;
    while a > 0 && near(a - 1) {
        a -= 1;
    }
    let mut b = k + 1;
    while b < lambda.len() && near(b) {
        b += 1;
    }
    a..b
}
