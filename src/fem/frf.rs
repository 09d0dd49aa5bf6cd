//! Frequency response of a linear model with viscous damping, from load patterns (inputs) to
//! linear combinations of nodal displacements (outputs), two ways:
//!
//! - **modal superposition with static correction** (the mode-acceleration / residual-
//!   flexibility method; R. R. Craig, A. J. Kurdila, Fundamentals of Structural Dynamics, 2nd
//!   ed., Wiley 2006, §11.4):
//!   H(ω) = Σᵣ cᵀφᵣ φᵣᵀf / (ωᵣ² − ω² + 2iζᵣωᵣω) + cᵀ(K⁻¹ − Σᵣ φᵣφᵣᵀ/ωᵣ²)f over the retained
//!   mass-normalised modes, so that H(0) is the static compliance exactly;
//! - **direct solve** of (K − ω²M + iωC) x = f with Rayleigh damping C = αM + βK, as the real
//!   block system [[K − ω²M, −ωC], [ωC, K − ω²M]] [Re x; Im x] = [f; 0] by sparse LU, one
//!   factorisation per frequency (the check of the modal result).
//!
//! Modal damping ratios: ζᵣ = ζ + α/(2ωᵣ) + βωᵣ/2 — a constant ratio ζ plus the Rayleigh
//! damping projected on the mode (Craig & Kurdila §9.4; C = αM + βK is diagonal in the modes).
//! A constant modal ratio has no sparse C, so the direct solve takes Rayleigh damping only.
//!
//! Units as the model: inputs in N (N·mm for moments), outputs as the output vectors weight the
//! displacements (mm, rad); frequencies in Hz at this interface, rad/s inside.

use super::cache::SolverCache;
use super::error::FemError;
use super::matrices::Reduced;
use super::modal::{solve_modal_cached, ModalOptions};
use super::model::Model;
use super::solve::{LuPattern, Parallelism};
use nalgebra::{Complex, DMatrix};
use std::f64::consts::PI;

/// Complex double.
pub type C64 = Complex<f64>;

/// Viscous damping: Rayleigh C = αM + βK plus a constant modal damping ratio ζ.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Damping {
    /// Mass-proportional coefficient α, 1/s.
    pub alpha: f64,
    /// Stiffness-proportional coefficient β, s.
    pub beta: f64,
    /// Constant modal damping ratio (modal superposition only).
    pub zeta: f64,
}

impl Damping {
    /// Damping ratio of a mode of circular frequency `omega` (rad/s): ζ + α/(2ω) + βω/2.
    pub fn ratio(&self, omega: f64) -> f64 {
        self.zeta + self.alpha / (2.0 * omega) + self.beta * omega / 2.0
    }
}

/// Inputs and outputs as global nodal vectors (6 per node: ux uy uz rx ry rz, global axes):
/// input j is the load pattern fⱼ (N, N·mm) per unit input; output k is yₖ = cₖᵀu.
#[derive(Debug, Clone, PartialEq)]
pub struct Ports {
    /// Load patterns fⱼ.
    pub inputs: Vec<Vec<f64>>,
    /// Output weights cₖ.
    pub outputs: Vec<Vec<f64>>,
}

impl Ports {
    fn check(&self, model: &Model) -> Result<(), FemError> {
        let n = model.n_dofs();
        if self.inputs.is_empty() || self.outputs.is_empty() {
            return Err(FemError::BadInput(
                "frequency response needs at least one input and one output".into(),
            ));
        }
        if let Some(v) = self.inputs.iter().chain(&self.outputs).find(|v| v.len() != n) {
            return Err(FemError::BadInput(format!(
                "an input/output vector has {} entries; the model has {n} DOFs",
                v.len()
            )));
        }
        Ok(())
    }
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// The modal model of the ports: retained modes, their input and output participations, the
/// static gain and the residual (static-correction) term.
#[derive(Debug, Clone, PartialEq)]
pub struct ModalFrf {
    /// Circular frequencies ωᵣ of the retained modes, rad/s (ascending, all > 0).
    pub omega: Vec<f64>,
    /// φᵣᵀfⱼ (modes × inputs).
    pub phi_in: DMatrix<f64>,
    /// cₖᵀφᵣ (outputs × modes).
    pub phi_out: DMatrix<f64>,
    /// Static gain cₖᵀK⁻¹fⱼ (outputs × inputs).
    pub static_gain: DMatrix<f64>,
    /// Residual flexibility cₖᵀ(K⁻¹ − Σᵣ φᵣφᵣᵀ/ωᵣ²)fⱼ (outputs × inputs).
    pub residual: DMatrix<f64>,
    /// Equations of the reduced system.
    pub n_eq: usize,
}

/// The modal model of `ports` on the `n_modes` lowest modes of `model` (see the module docs).
/// Errors if the model is not supported against every rigid motion (K singular: no static
/// correction exists) or a mode has ω² ≤ 0.
pub fn modal_frf(model: &Model, ports: &Ports, n_modes: usize, cache: &mut SolverCache) -> Result<ModalFrf, FemError> {
    ports.check(model)?;
    let modal = solve_modal_cached(model, &ModalOptions::new(n_modes), cache)?;
    if let Some((i, m)) = modal.modes.iter().enumerate().find(|(_, m)| m.eigenvalue <= 0.0) {
        return Err(FemError::BadInput(format!(
            "mode {} has ω² = {:.3e} (rad/s)² ≤ 0: the frequency response with static correction needs a model supported against every rigid motion",
            i + 1,
            m.eigenvalue
        )));
    }
    let sys = cache.system(model, &[], Parallelism::Rayon)?;
    let map = sys.dof_map();
    let n = map.n_eq();
    let (ni, no, nm) = (ports.inputs.len(), ports.outputs.len(), modal.modes.len());
    let mut x: Vec<f64> = ports.inputs.iter().flat_map(|f| map.reduce(f)).collect();
    sys.solve_checked(&mut x, ni)?;
    let c_eq: Vec<Vec<f64>> = ports.outputs.iter().map(|c| map.reduce(c)).collect();
    let static_gain = DMatrix::from_fn(no, ni, |k, j| dot(&c_eq[k], &x[j * n..(j + 1) * n]));
    let flat = |s: &[[f64; 6]]| -> Vec<f64> { s.iter().flatten().copied().collect() };
    let shapes: Vec<Vec<f64>> = modal.modes.iter().map(|m| flat(&m.shape)).collect();
    let phi_in = DMatrix::from_fn(nm, ni, |r, j| dot(&shapes[r], &ports.inputs[j]));
    let phi_out = DMatrix::from_fn(no, nm, |k, r| dot(&ports.outputs[k], &shapes[r]));
    let omega: Vec<f64> = modal.modes.iter().map(|m| m.eigenvalue.sqrt()).collect();
    let inv_w2 = DMatrix::from_diagonal(&nalgebra::DVector::from_iterator(
        nm,
        omega.iter().map(|w| 1.0 / (w * w)),
    ));
    let residual = &static_gain - &phi_out * inv_w2 * &phi_in;
    Ok(ModalFrf {
        omega,
        phi_in,
        phi_out,
        static_gain,
        residual,
        n_eq: n,
    })
}

impl ModalFrf {
    /// H(f) (outputs × inputs) at `f_hz` by modal superposition plus the residual term.
    pub fn response(&self, f_hz: f64, damping: &Damping) -> DMatrix<C64> {
        let w = 2.0 * PI * f_hz;
        let mut h = self.residual.map(|v| C64::new(v, 0.0));
        for (r, &wr) in self.omega.iter().enumerate() {
            let den = C64::new(wr * wr - w * w, 2.0 * damping.ratio(wr) * wr * w);
            let g = den.inv();
            for k in 0..h.nrows() {
                for j in 0..h.ncols() {
                    h[(k, j)] += g * (self.phi_out[(k, r)] * self.phi_in[(r, j)]);
                }
            }
        }
        h
    }

    /// Natural frequencies of the retained modes, Hz.
    pub fn frequencies_hz(&self) -> Vec<f64> {
        self.omega.iter().map(|w| w / (2.0 * PI)).collect()
    }
}

/// The direct frequency response: the block system's LU pattern and the model's K, M values
/// on it (see the module docs).
#[derive(Debug, Clone)]
pub struct DirectFrf {
    n: usize,
    lower: Vec<(usize, usize)>,
    k: Vec<f64>,
    m: Vec<f64>,
    lu: LuPattern,
    rhs: Vec<f64>,
    c_eq: Vec<Vec<f64>>,
    damping: Damping,
}

/// The four n×n blocks of the real form of a complex matrix, per lower-triangle entry (r, c)
/// of a symmetric pattern, mirrored off the diagonal: (row, col, block) with block 0 = Re on
/// the diagonal blocks, 1 = −Im (upper right), 2 = +Im (lower left).
fn block_pairs(n: usize, lower: &[(usize, usize)]) -> Vec<(usize, usize, u8)> {
    let mut out = Vec::with_capacity(8 * lower.len());
    for &(r, c) in lower {
        let mut push = |r: usize, c: usize| {
            out.extend([(r, c, 0), (n + r, n + c, 0), (r, n + c, 1), (n + r, c, 2)]);
        };
        push(r, c);
        if r != c {
            push(c, r);
        }
    }
    out
}

impl DirectFrf {
    /// Assembles K and M of `model` and the pattern of the block system. Errors if `damping`
    /// has a modal ratio ζ (no sparse C).
    pub fn new(model: &Model, ports: &Ports, damping: Damping) -> Result<DirectFrf, FemError> {
        ports.check(model)?;
        if damping.zeta != 0.0 {
            return Err(FemError::BadInput(
                "the direct frequency response takes Rayleigh damping (α, β) only: a constant modal damping ratio has no sparse damping matrix".into(),
            ));
        }
        let red = Reduced::new(model)?;
        let n = red.map.n_eq();
        let (kt, mt) = (red.k.lower_triplets(), red.m.lower_triplets());
        let lower: Vec<(usize, usize)> = kt.iter().map(|&(r, c, _)| (r, c)).collect();
        if mt.iter().map(|&(r, c, _)| (r, c)).ne(lower.iter().copied()) {
            return Err(FemError::PatternMismatch("K and M patterns differ".into()));
        }
        let pairs: Vec<(usize, usize)> = block_pairs(n, &lower).iter().map(|&(r, c, _)| (r, c)).collect();
        let lu = LuPattern::new(2 * n, &pairs)?;
        let mut rhs = vec![0.0; 2 * n * ports.inputs.len()];
        for (j, f) in ports.inputs.iter().enumerate() {
            rhs[2 * n * j..2 * n * j + n].copy_from_slice(&red.map.reduce(f));
        }
        Ok(DirectFrf {
            n,
            k: kt.iter().map(|t| t.2).collect(),
            m: mt.iter().map(|t| t.2).collect(),
            lower,
            lu,
            rhs,
            c_eq: ports.outputs.iter().map(|c| red.map.reduce(c)).collect(),
            damping,
        })
    }

    /// Equations of the reduced system (the block system has twice as many).
    pub fn n_eq(&self) -> usize {
        self.n
    }

    /// H(f) (outputs × inputs) at `f_hz` by one sparse LU solve of the block system.
    pub fn response(&self, f_hz: f64) -> Result<DMatrix<C64>, FemError> {
        let w = 2.0 * PI * f_hz;
        let Damping { alpha, beta, .. } = self.damping;
        let mut values = Vec::with_capacity(self.lu.n_triplets());
        for (t, &(r, c)) in self.lower.iter().enumerate() {
            let re = self.k[t] - w * w * self.m[t];
            let im = w * (alpha * self.m[t] + beta * self.k[t]);
            let copies = if r != c { 2 } else { 1 };
            for _ in 0..copies {
                values.extend([re, re, -im, im]);
            }
        }
        let ni = self.rhs.len() / (2 * self.n);
        let mut x = self.rhs.clone();
        self.lu
            .solve_in_place(&values, &mut x, ni, Parallelism::Sequential)
            .map_err(|e| FemError::Solver(format!("direct frequency response at {f_hz} Hz: {e}")))?;
        let n = self.n;
        Ok(DMatrix::from_fn(self.c_eq.len(), ni, |k, j| {
            let col = &x[2 * n * j..2 * n * (j + 1)];
            C64::new(dot(&self.c_eq[k], &col[..n]), dot(&self.c_eq[k], &col[n..]))
        }))
    }
}

/// ‖a − b‖ / ‖b‖ (Frobenius norms over all input/output pairs); where ‖b‖ = 0 (every output
/// decoupled from every input), 0 if a is zero as well, else 1.
pub fn relative_difference(a: &DMatrix<C64>, b: &DMatrix<C64>) -> f64 {
    let scale = b.norm();
    if scale == 0.0 {
        return if a.norm() == 0.0 { 0.0 } else { 1.0 };
    }
    (a - b).norm() / scale
}
