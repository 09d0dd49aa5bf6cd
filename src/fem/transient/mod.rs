//! Linear transient dynamics M ü + C u̇ + K u = F(t) by implicit time integration: the HHT-α
//! method (H. M. Hilber, T. J. R. Hughes, R. L. Taylor, "Improved numerical dissipation for time
//! integration algorithms in structural dynamics", Earthquake Engineering and Structural
//! Dynamics 5 (1977) 283–292), which with α = 0 is Newmark's average-acceleration (trapezoidal)
//! rule (N. M. Newmark, "A method of computation for structural dynamics", J. Eng. Mech. Div.
//! ASCE 85 (1959) 67–94), unconditionally stable and free of numerical damping:
//!
//! ```text
//! M aₙ₊₁ + (1+α) C vₙ₊₁ − α C vₙ + (1+α) K uₙ₊₁ − α K uₙ = (1+α) Fₙ₊₁ − α Fₙ
//! uₙ₊₁ = uₙ + Δt vₙ + Δt² ((½ − β) aₙ + β aₙ₊₁),  vₙ₊₁ = vₙ + Δt ((1 − γ) aₙ + γ aₙ₊₁)
//! α ∈ [−⅓, 0],  γ = ½ − α,  β = (1 − α)²/4
//! ```
//!
//! M is the consistent mass of the modal analysis ([`super::assembly::MatrixKind::Mass`]),
//! C = a M + b K + Σₑ bₑ Kₑ (Rayleigh plus per-element stiffness-proportional damping). The
//! effective matrix c₀M + (1+α)c₁C + (1+α)K is factorised once; each step is one solve and two
//! (three with element damping) sparse products. Prescribed motions follow the same Newmark
//! relations (their accelerations and velocities are the scheme's, so a velocity jump is an
//! impulse spread over one step) and load the free equations through the coupling columns of
//! M, C and K. A motion prescribed on a supported DOF moves that support (base excitation).

mod checks;
mod record;

use super::assembly::{MatrixKind, Pattern};
use super::constraints::DofMap;
use super::diagnose::diagnose_mechanism;
use super::dof::{Dof, NodeDof};
use super::error::FemError;
pub use super::history::History;
use super::model::Model;
use super::solve::{Factor, FactorError, FullSymmetric, Parallelism, SparseMatrix, SymbolicFactor};
pub(crate) use checks::check_inputs;

/// A nodal force/moment [Fx Fy Fz Mx My Mz] (N, N·mm; node axes) times a history.
#[derive(Debug, Clone, PartialEq)]
pub struct TransientLoad {
    pub node: usize,
    pub f: [f64; 6],
    pub history: History,
}

/// A prescribed displacement (mm) or rotation (rad) of one DOF: `value` times a history.
#[derive(Debug, Clone, PartialEq)]
pub struct PrescribedMotion {
    pub node: usize,
    pub dof: Dof,
    pub value: f64,
    pub history: History,
}

/// Damping C = `alpha` M + `beta` K + Σ `element_beta`ₑ Kₑ.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Damping {
    /// Mass-proportional Rayleigh coefficient, 1/s.
    pub alpha: f64,
    /// Stiffness-proportional Rayleigh coefficient, s.
    pub beta: f64,
    /// Extra stiffness-proportional damping of single elements (element index, coefficient s).
    pub element_beta: Vec<(usize, f64)>,
}

/// Time-integration scheme.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Scheme {
    /// Newmark average acceleration (γ = ½, β = ¼): no numerical damping.
    AverageAcceleration,
    /// HHT-α with α ∈ [−⅓, 0] (γ = ½ − α, β = (1 − α)²/4): damps high modes.
    Hht { alpha: f64 },
}

impl Scheme {
    /// (α, γ, β) of the HHT form (α = 0 for average acceleration).
    pub fn parameters(self) -> (f64, f64, f64) {
        let a = match self {
            Scheme::AverageAcceleration => 0.0,
            Scheme::Hht { alpha } => alpha,
        };
        (a, 0.5 - a, 0.25 * (1.0 - a) * (1.0 - a))
    }

    /// Plain-text name with its parameters.
    pub fn describe(self) -> String {
        match self {
            Scheme::AverageAcceleration => "Newmark average acceleration (gamma = 1/2, beta = 1/4)".into(),
            Scheme::Hht { alpha } => {
                let (_, g, b) = self.parameters();
                format!("HHT-alpha (Hilber, Hughes & Taylor 1977), alpha = {alpha}, gamma = {g}, beta = {b}")
            }
        }
    }
}

/// Usable time steps, s: below 1e-12 s (far under the period of any structural mode) the
/// Newmark coefficient 1/(β Δt²) swamps the stiffness in floating point (and overflows near
/// 1e-154 s); above 1e6 s the end time of a long run is no longer a usable number.
pub const DT_RANGE: std::ops::RangeInclusive<f64> = 1e-12..=1e6;

/// Options of [`solve_transient`].
#[derive(Debug, Clone, PartialEq)]
pub struct TransientOptions {
    /// Time step, s.
    pub dt: f64,
    /// Number of steps.
    pub steps: usize,
    pub scheme: Scheme,
    pub damping: Damping,
    /// DOFs whose displacement, velocity and acceleration histories are recorded (global axes).
    pub record: Vec<NodeDof>,
    /// Keep the full displacement field every this many steps (0: never).
    pub snapshot_every: usize,
    /// Record kinetic and strain energy at every step.
    pub energy: bool,
    /// Initial displacements and velocities, 6 per node in node axes (`None`: at rest).
    pub initial: Option<(Vec<f64>, Vec<f64>)>,
    pub par: Parallelism,
}

impl TransientOptions {
    /// `steps` steps of `dt` by average acceleration, undamped, nothing recorded.
    pub fn new(dt: f64, steps: usize) -> TransientOptions {
        TransientOptions {
            dt,
            steps,
            scheme: Scheme::AverageAcceleration,
            damping: Damping::default(),
            record: Vec::new(),
            snapshot_every: 0,
            energy: false,
            initial: None,
            par: Parallelism::Rayon,
        }
    }
}

/// Kinetic ½vᵀMv and strain ½uᵀKu energy of the free equations, N·mm.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Energy {
    pub kinetic: f64,
    pub strain: f64,
}

/// Results of [`solve_transient`]: every series has `steps + 1` values (t = 0 first).
#[derive(Debug, Clone, PartialEq)]
pub struct TransientResults {
    pub time: Vec<f64>,
    /// Per recorded DOF: displacement (mm or rad), velocity (/s), acceleration (/s²).
    pub displacement: Vec<Vec<f64>>,
    pub velocity: Vec<Vec<f64>>,
    pub acceleration: Vec<Vec<f64>>,
    /// (time, displacements per node [ux uy uz rx ry rz], global axes).
    pub snapshots: Vec<(f64, Vec<[f64; 6]>)>,
    /// Per time (only with `energy`).
    pub energy: Vec<Energy>,
    /// Number of equations.
    pub n_eq: usize,
    /// Things the caller should be told (e.g. a zero initial acceleration on a singular mass).
    pub warnings: Vec<String>,
    /// Geometrically nonlinear runs: the largest dynamic equilibrium residual of an accepted
    /// step relative to its force scale (applied load, or the inertia and internal forces when
    /// larger), each step checked to 1e-6 of it (plus a round-off floor); `None` when linear.
    pub equilibrium: Option<f64>,
}

/// Coupling columns of one prescribed DOF into the free equations (M, K, element damping).
struct Coupling {
    m: Vec<f64>,
    k: Vec<f64>,
    ce: Vec<f64>,
}

/// Free-equation parts of the columns of M, K and the element damping for each prescribed DOF
/// (from the system where those DOFs are free). A prescribed DOF that a support also fixes is a
/// moving support (base excitation): its support is released here so that it has a column.
fn couplings(
    model: &Model,
    map: &DofMap,
    prescribed: &[NodeDof],
    damping: &Damping,
) -> Result<Vec<Coupling>, FemError> {
    if prescribed.is_empty() {
        return Ok(Vec::new());
    }
    let moving = |s: &super::model::Support| prescribed.iter().any(|p| p.node == s.node && s.fix[p.dof.index()]);
    let released;
    let model = if model.supports.iter().any(moving) {
        let mut m = model.clone();
        for s in &mut m.supports {
            for p in prescribed.iter().filter(|p| p.node == s.node) {
                s.fix[p.dof.index()] = false;
            }
        }
        released = m;
        &released
    } else {
        model
    };
    let all = DofMap::new(model, &[], None)?;
    let pattern = Pattern::new(model, &all)?;
    let (k, m, ce) = matrices(model, &all, &pattern, damping)?;
    let to_free = |col: Vec<f64>| -> Vec<f64> { map.eq_dof.iter().map(|&g| col[all.eq[g]]).collect() };
    prescribed
        .iter()
        .map(|p| {
            // Supports of prescribed DOFs are released above, so a DOF without an equation here is
            // a rigid-link slave or a tied DOF (the case reader refuses those; kept as a backstop).
            let Some(&eq) = all.eq.get(p.global()).filter(|&&q| q < all.n_eq()) else {
                return Err(FemError::OverConstrained(format!(
                    "{p} has a prescribed motion but no equation of its own (a rigid-link slave or a tied DOF): prescribe the master's motion instead"
                )));
            };
            let mut e = vec![0.0; all.n_eq()];
            e[eq] = 1.0;
            Ok(Coupling {
                m: to_free(m.mul_vec(&e)),
                k: to_free(k.mul_vec(&e)),
                ce: ce
                    .as_ref()
                    .map_or_else(|| vec![0.0; map.n_eq()], |c| to_free(c.mul_vec(&e))),
            })
        })
        .collect()
}

/// K, M and the element damping (if any) on `pattern`.
pub(crate) fn matrices(
    model: &Model,
    map: &DofMap,
    pattern: &Pattern,
    damping: &Damping,
) -> Result<(SparseMatrix, SparseMatrix, Option<SparseMatrix>), FemError> {
    let kv = pattern.values_of(model, map, MatrixKind::Stiffness)?;
    let mv = pattern.values_of(model, map, MatrixKind::Mass)?;
    let ce = if damping.element_beta.is_empty() {
        None
    } else {
        let mut cv = vec![0.0; kv.len()];
        for &(ie, b) in &damping.element_beta {
            for r in pattern.element_values(ie) {
                cv[r] += b * kv[r];
            }
        }
        Some(pattern.matrix(&cv)?)
    };
    Ok((pattern.matrix(&kv)?, pattern.matrix(&mv)?, ce))
}

/// Integrates the model from rest (or `opts.initial`) under `loads` and `motions`.
pub fn solve_transient(
    model: &Model,
    loads: &[TransientLoad],
    motions: &[PrescribedMotion],
    opts: &TransientOptions,
) -> Result<TransientResults, FemError> {
    check_inputs(model, loads, opts)?;
    let n_nodes = model.nodes.len();
    let mut prescribed = Vec::with_capacity(motions.len());
    for m in motions {
        m.history.validate()?;
        let nd = NodeDof {
            node: m.node,
            dof: m.dof,
        };
        if m.node >= n_nodes || !m.value.is_finite() || prescribed.contains(&nd) {
            return Err(FemError::BadInput(format!(
                "prescribed motion of {nd}: no such node, a non-finite value or given twice"
            )));
        }
        if m.history.value(0.0) != 0.0 {
            return Err(FemError::BadInput(format!(
                "prescribed motion of {nd} is {} at t = 0; the model starts at rest and undeformed, so a motion must start from 0 (start a step later than 0, or use a ramp)",
                m.value * m.history.value(0.0)
            )));
        }
        prescribed.push(nd);
    }
    let map = DofMap::new(model, &prescribed, Some("transient"))?;
    let n = map.n_eq();
    let pattern = Pattern::new(model, &map)?;
    let (k, m, ce) = matrices(model, &map, &pattern, &opts.damping)?;
    let coupling = couplings(model, &map, &prescribed, &opts.damping)?;
    let (alpha, gamma, beta) = opts.scheme.parameters();
    let dt = opts.dt;
    let (c0, c1, c2, c3) = (
        1.0 / (beta * dt * dt),
        gamma / (beta * dt),
        1.0 / (beta * dt),
        0.5 / beta - 1.0,
    );
    let (c4, c5) = (1.0 - gamma / beta, dt * (1.0 - 0.5 * gamma / beta));
    let (ra, rb) = (opts.damping.alpha, opts.damping.beta);
    // Effective matrix c0 M + (1+α) c1 (a M + b K + Ce) + (1+α) K.
    let ap = 1.0 + alpha;
    let mut eff = k
        .lin_comb(ap * (1.0 + c1 * rb), &m, c0 + ap * c1 * ra)
        .ok_or_else(|| FemError::PatternMismatch("K and M patterns differ".into()))?;
    if let Some(ce) = &ce {
        eff = eff
            .lin_comb(1.0, ce, ap * c1)
            .ok_or_else(|| FemError::PatternMismatch("K and C patterns differ".into()))?;
    }
    let symbolic = SymbolicFactor::with_ordering(pattern.sparse(), model.ordering)?;
    let factor = match Factor::new(&symbolic, &eff, opts.par) {
        Ok(f) => f,
        Err(FactorError::NotPositiveDefinite) => {
            return Err(diagnose_mechanism(model, &map, &eff, &symbolic, opts.par))
        }
        Err(FactorError::Other(s)) => return Err(FemError::Solver(s)),
    };
    let (kf, mf) = (k.full(), m.full());
    let cef: Option<FullSymmetric> = ce.as_ref().map(|c| c.full());
    // Reduced spatial load vectors.
    let nd = model.n_dofs();
    let load_vecs: Vec<(Vec<f64>, &History)> = loads
        .iter()
        .map(|l| {
            let mut f = vec![0.0; nd];
            f[6 * l.node..6 * l.node + 6].copy_from_slice(&l.f);
            (map.reduce(&f), &l.history)
        })
        .collect();
    let force = |t: f64| -> Vec<f64> {
        let mut f = vec![0.0; n];
        for (v, h) in &load_vecs {
            let g = h.value(t);
            if g != 0.0 {
                f.iter_mut().zip(v).for_each(|(fi, vi)| *fi += g * vi);
            }
        }
        f
    };
    let mut warnings = Vec::new();
    let (mut u, mut v) = match &opts.initial {
        Some((u0, v0)) => (
            map.eq_dof.iter().map(|&g| u0[g]).collect::<Vec<f64>>(),
            map.eq_dof.iter().map(|&g| v0[g]).collect::<Vec<f64>>(),
        ),
        None => (vec![0.0; n], vec![0.0; n]),
    };
    // Initial acceleration from M a₀ = F(0) − C v₀ − K u₀.
    let damp = |x: &[f64]| -> Vec<f64> {
        let (mx, kx) = (mf.mul_vec(x), kf.mul_vec(x));
        let mut c: Vec<f64> = mx.iter().zip(&kx).map(|(a, b)| ra * a + rb * b).collect();
        if let Some(cef) = &cef {
            c.iter_mut().zip(cef.mul_vec(x)).for_each(|(ci, e)| *ci += e);
        }
        c
    };
    let mut r0 = force(0.0);
    for (ri, (cv, ku)) in r0.iter_mut().zip(damp(&v).iter().zip(kf.mul_vec(&u))) {
        *ri -= cv + ku;
    }
    let mut a = vec![0.0; n];
    if r0.iter().any(|&x| x != 0.0) {
        match Factor::new(&symbolic, &m, opts.par) {
            Ok(mfac) => {
                a.copy_from_slice(&r0);
                mfac.solve_in_place(&mut a, 1)?;
            }
            Err(_) => warnings.push(
                "the mass matrix is singular (DOFs without mass): the initial acceleration is taken as zero, so a load jumping at t = 0 acts as a ramp over the first step".into(),
            ),
        }
    }
    // Prescribed DOFs: (u, v, a) per DOF.
    let mut pstate = vec![[0.0f64; 3]; prescribed.len()];
    let mut out = record::Recorder::new(opts, model, &map, &prescribed);
    out.push(0.0, &u, &v, &a, &pstate, &kf, &mf)?;
    let mut f_prev = force(0.0);
    for step in 0..opts.steps {
        let t1 = (step + 1) as f64 * dt;
        let f1 = force(t1);
        let y: Vec<f64> = v.iter().zip(&a).map(|(vi, ai)| c2 * vi + c3 * ai).collect();
        let w: Vec<f64> = v
            .iter()
            .zip(&a)
            .map(|(vi, ai)| ap * (c4 * vi + c5 * ai) - alpha * vi)
            .collect();
        let mx: Vec<f64> = y.iter().zip(&w).map(|(yi, wi)| yi - ra * wi).collect();
        let kx: Vec<f64> = u.iter().zip(&w).map(|(ui, wi)| ui + rb * wi).collect();
        let (mm, kk) = (mf.mul_vec(&mx), kf.mul_vec(&kx));
        let mut rhs: Vec<f64> = (0..n).map(|i| ap * f1[i] - alpha * f_prev[i] + mm[i] - kk[i]).collect();
        if let Some(cef) = &cef {
            rhs.iter_mut().zip(cef.mul_vec(&w)).for_each(|(r, c)| *r -= c);
        }
        for ((mo, s), c) in motions.iter().zip(pstate.iter_mut()).zip(&coupling) {
            let u1 = mo.value * mo.history.value(t1);
            let du = u1 - s[0];
            let a1 = c0 * du - c2 * s[1] - c3 * s[2];
            let v1 = s[1] + dt * ((1.0 - gamma) * s[2] + gamma * a1);
            let (ku, cv) = (ap * u1 - alpha * s[0], ap * v1 - alpha * s[1]);
            for (i, r) in rhs.iter_mut().enumerate() {
                *r -= c.m[i] * (a1 + ra * cv) + c.k[i] * (ku + rb * cv) + c.ce[i] * cv;
            }
            *s = [u1, v1, a1];
        }
        factor.solve_in_place(&mut rhs, 1)?;
        for i in 0..n {
            let du = rhs[i];
            let a1 = c0 * du - c2 * v[i] - c3 * a[i];
            v[i] += dt * ((1.0 - gamma) * a[i] + gamma * a1);
            a[i] = a1;
            u[i] += du;
        }
        if u.iter().any(|x| !x.is_finite()) {
            return Err(FemError::Solver(format!(
                "transient: non-finite displacement at step {} (t = {t1} s)",
                step + 1
            )));
        }
        out.push(t1, &u, &v, &a, &pstate, &kf, &mf)?;
        f_prev = f1;
    }
    let mut res = out.finish();
    res.n_eq = n;
    res.warnings = warnings;
    Ok(res)
}
