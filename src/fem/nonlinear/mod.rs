//! Geometrically nonlinear statics (large displacements and rotations, small strains):
//! co-rotational beams and flexibility elements ([`super::corot`]), Newton–Raphson with load
//! (and prescribed-displacement) stepping, automatic step cutting, and Crisfield's arc-length
//! method through limit points ([`arc`]: M. A. Crisfield, "A fast incremental/iterative
//! solution procedure that handles snap-through", Computers & Structures 13 (1981) 55–62;
//! E. Riks, IJSS 15 (1979) 529–551; cylindrical or spherical), and the location of critical
//! points along the path ([`critical`]).
//!
//! Kinematics of the nodes: translations are additive, rotations are rotation matrices updated
//! multiplicatively, Rᵢ ← exp([δwᵢ×])Rᵢ, with the spatial spin δwᵢ (global components) as the
//! rotational increment. The equations are numbered by the linear [`DofMap`]; its maps act on
//! *increments*:
//!
//! * framed nodes (skew supports, sliders): increments in the node frame, d = F·d_local —
//!   exact, the frame is fixed;
//! * ties: equal increments of coincident nodes — exact for tied translations and for ties of
//!   all three rotations; a partial rotation tie (a revolute joint) equates spin components
//!   about the fixed frame axes, which is exact only while the joint axis does not rotate
//!   (approximation);
//! * rigid links: slave position x_s = x_m + R_m·(X_s − X_m) and R_s = R_m, **exact** for any
//!   finite rotation of the master; the arm in the increment map is the current one,
//!   δu_s = δu_m + δw_m × (R_m a₀), and the link's geometric stiffness [F_s×][a×] (from the
//!   rotating arm) is added to the master;
//! * springs: linear in the translations and the nodal rotation vectors, axes fixed
//!   (approximation: exact for small rotations of the spring's nodes only).
//!
//! Loads are fixed in space (no follower forces). The reported rotation of a node is its
//! rotation vector log(R) (|θ| ≤ π).
//!
//! Acceptance and stability:
//!
//! * a Newton iteration converges when its residual is below the tolerance relative to the
//!   applied load and the internal forces (reactions) of the last converged state — a scale
//!   fixed for the step, which a wandering iterate cannot inflate — plus a round-off floor from
//!   the stiffest element; every returned state is checked once more for nodal and global
//!   equilibrium (forces and moments at the deformed positions) to 1e-6 of the applied load,
//!   otherwise the solve fails naming the step;
//! * the tangent is the consistent one: non-symmetric (sparse LU) where moments are applied
//!   ([`Tangent`]), so Newton stays quadratic and the answer objective; symmetric (sparse
//!   Cholesky) elsewhere;
//! * the load step adapts (cut on failure, on a node rotating more than
//!   [`path::MAX_STEP_ROTATION`] in a step, on an increment [`path::MAX_JUMP`] times its predictor, on an
//!   iteration crossing an indefinite tangent; shrunk after slow and grown after fast steps),
//!   with caps on cuts and steps so a failing case stops quickly;
//! * each converged point is stable when the symmetric tangent of the reduced system is
//!   positive definite (Cholesky succeeds with every pivot above
//!   [`super::diagnose::PIVOT_TOL`] of its diagonal) and it was reached without a jump; the
//!   first loss is bracketed by the load factors of the last stable and first unstable
//!   points. With applied moments this is the static (divergence) criterion on the symmetric
//!   part only.

use crate::fem::dof::NodeDof;
use crate::fem::error::FemError;
use crate::fem::model::Model;
use crate::fem::results::CaseResult;
use crate::fem::solve::Parallelism;

mod arc;
pub mod continuation;
mod convergence;
mod critical;
mod dynamic;
mod load_case;
mod newton;
mod path;
pub mod probe;
mod recover;
mod residual;
mod state;
mod track;

use load_case::solve_case;
use state::element_data;

pub use critical::{CriticalKind, CriticalPoint, CRITICAL_TOL};
pub use dynamic::{solve_transient_nonlinear, NONLINEAR_TRANSIENT_MODEL};

/// Options of the nonlinear solver.
#[derive(Debug, Clone, PartialEq)]
pub struct NonlinearOptions {
    /// Number of equal load steps from λ = 0 to 1 (≥ 1). With arc length: the first step's
    /// load increment is 1/steps, which fixes the arc length.
    pub steps: usize,
    /// Newton iterations per step before the step is cut.
    pub max_iterations: usize,
    /// Residual tolerance, relative to the step's force scale: the larger of the applied loads
    /// (λ f) and the internal forces of the last converged state carried into the step
    /// (reactions included), Euclidean norms over the equations. The scale is fixed for the
    /// step, so it cannot grow with the error of a wandering iterate.
    pub tol_residual: f64,
    /// Energy tolerance: |δqₖ₋₁·rₖ| relative to |δq₀·r₀| of the step.
    pub tol_energy: f64,
    /// How many times a step may be halved (in a row) before the solve fails.
    pub max_cuts: usize,
    /// Step cuts allowed over the whole load case (so a failing case stops quickly).
    pub max_total_cuts: usize,
    /// Which tangent the Newton iterations factorise.
    pub tangent: Tangent,
    /// Crisfield's arc-length control instead of load control ([`ArcLength`] sets it up). Only
    /// for cases without non-zero prescribed displacements.
    pub arc_length: bool,
    /// Parameters of the arc-length control.
    pub arc: ArcLength,
    /// Locate each change of stability along the path (bisection to [`CRITICAL_TOL`] in λ) and
    /// its critical mode ([`NonlinearCase::critical_points`]).
    pub locate_critical: bool,
    /// DOFs whose values are recorded along the path (translations in mm; rotations: the
    /// rotation-vector component, rad; global axes).
    pub track: Vec<NodeDof>,
    /// Natural frequencies and node compliances evaluated at every accepted point of the path
    /// with the current tangent stiffness ([`NonlinearCase::step_quantities`]); none by default.
    pub step_track: StepTrack,
    /// Threading of the sparse factorisation.
    pub parallelism: Parallelism,
}

impl Default for NonlinearOptions {
    fn default() -> Self {
        NonlinearOptions {
            steps: 20,
            max_iterations: 30,
            tol_residual: 1e-8,
            tol_energy: 1e-12,
            max_cuts: 12,
            max_total_cuts: 60,
            tangent: Tangent::Auto,
            arc_length: false,
            arc: ArcLength::default(),
            locate_critical: true,
            track: Vec::new(),
            step_track: StepTrack::default(),
            parallelism: Parallelism::Sequential,
        }
    }
}

/// What to evaluate at every accepted point of a nonlinear path (nothing by default).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct StepTrack {
    /// Number of natural frequencies (the lowest) with the current tangent stiffness; 0: none.
    pub modes: usize,
    /// Nodes whose 6×6 compliance with the current tangent stiffness is evaluated.
    pub compliance: Vec<usize>,
}

impl StepTrack {
    pub(super) fn is_empty(&self) -> bool {
        self.modes == 0 && self.compliance.is_empty()
    }
}

/// The tracked quantities at one accepted point of the path.
#[derive(Debug, Clone, PartialEq)]
pub struct StepQuantities {
    /// Index of the point in [`NonlinearCase::path`].
    pub point: usize,
    /// Load factor λ of the point.
    pub lambda: f64,
    /// The lowest [`StepTrack::modes`] eigenvalues ω² of K_T φ = ω² M φ, ascending, (rad/s)²;
    /// negative where the state is unstable.
    pub eigenvalues: Vec<f64>,
    /// Per node of [`StepTrack::compliance`]: C[i][j] = displacement i of the node per unit
    /// load j at it, [ux, uy, uz, rx, ry, rz] × [Fx, Fy, Fz, Mx, My, Mz], global axes (mm/N,
    /// rad/N, rad/(N·mm)); rows and columns of held DOFs are zero. Symmetric.
    pub compliance: Vec<[[f64; 6]; 6]>,
}

impl StepQuantities {
    /// Natural frequencies, Hz: √ω²/2π, with a minus sign where ω² < 0 (unstable state).
    pub fn frequencies_hz(&self) -> Vec<f64> {
        self.eigenvalues
            .iter()
            .map(|l| l.signum() * l.abs().sqrt() / (2.0 * std::f64::consts::PI))
            .collect()
    }
}

/// Parameters of the arc-length control ([`NonlinearOptions::arc_length`]). Arc lengths are
/// dimensionless: Δs² = ‖Δq‖²/q_ref² + ψ²Δλ² with q_ref = ‖K₀⁻¹f‖ the linear response to the
/// full load (Δs = 0.05: 5 % of it).
#[derive(Debug, Clone, PartialEq)]
pub struct ArcLength {
    /// First arc length; `None`: 1/steps.
    pub initial: Option<f64>,
    /// Smallest arc length before the solve fails; `None`: 10⁻⁴ of the initial one.
    pub min: Option<f64>,
    /// Largest arc length; `None`: 20 times the initial one.
    pub max: Option<f64>,
    /// Newton iterations per step the arc length adapts to (×√(target/iterations)).
    pub target_iterations: usize,
    /// Spherical (ψ = 1) instead of cylindrical (ψ = 0) constraint.
    pub spherical: bool,
    /// Steps before the solve fails without reaching λ = 1.
    pub max_steps: usize,
}

impl Default for ArcLength {
    fn default() -> Self {
        ArcLength {
            initial: None,
            min: None,
            max: None,
            target_iterations: 5,
            spherical: false,
            max_steps: 500,
        }
    }
}

/// The tangent stiffness of the Newton iterations.
///
/// With the spatial spin as rotational increment, the consistent tangent is not symmetric
/// away from equilibrium, and at equilibrium its skew part is ½[M×] at every node carrying an
/// applied moment M (the moment of loads fixed in space does not derive from a potential in
/// the spin variables). Symmetrising it (Cholesky) keeps Newton quadratic only where no
/// moment is applied; under large moments not about a fixed axis the symmetrised iteration
/// converges slowly or not at all. The non-symmetric tangent needs a sparse LU.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Tangent {
    /// Non-symmetric (LU) where the load case applies moments (directly, or as forces on
    /// rigid-link slaves, which load their master with a moment); symmetric (Cholesky)
    /// otherwise.
    #[default]
    Auto,
    /// Always the symmetric part (sparse Cholesky; LU only for indefinite tangents).
    Symmetric,
    /// Always the consistent non-symmetric tangent (sparse LU).
    Full,
}

/// One converged point of the equilibrium path.
#[derive(Debug, Clone, PartialEq)]
pub struct PathPoint {
    /// Load factor λ (loads and prescribed displacements are λ times the case's values).
    pub lambda: f64,
    /// Values of [`NonlinearOptions::track`] at λ.
    pub values: Vec<f64>,
    /// Whether the symmetric tangent stiffness of the reduced system is positive definite at
    /// this point (a stable equilibrium against static perturbations), and the step reaching
    /// it stayed on a continuous stable path (no jump over a limit point).
    pub stable: bool,
    /// Euclidean norms of the residual at each Newton iteration of the step that reached this
    /// point (N and N·mm mixed, as the equations), the last one converged: the iteration log.
    pub residuals: Vec<f64>,
    /// Equilibrium residual of this state relative to its load scale: the largest of the
    /// nodal residual, the unbalanced total force and the unbalanced total moment (statics at
    /// the deformed positions), each over its scale (applied loads; with prescribed
    /// displacements the reactions too) — what the equilibrium check bounds by 1e-6 (plus a
    /// round-off floor of the stiffest element). 0 at the unloaded start.
    pub equilibrium: f64,
}

/// Result of one load case.
#[derive(Debug, Clone, PartialEq)]
pub struct NonlinearCase {
    /// Final state in the linear result's shape: `displacements` per node = [ux, uy, uz (mm),
    /// rotation vector (rad)], global; reactions (global, at the deformed configuration);
    /// per-element end forces and section forces in the element's *deformed* (co-rotated)
    /// local frame, with stresses; statics about the origin at the deformed positions.
    pub fe: CaseResult,
    /// Final nodal rotation matrices (rows of R, global).
    pub rotations: Vec<[[f64; 3]; 3]>,
    /// Converged path, starting at λ = 0.
    pub path: Vec<PathPoint>,
    /// Newton iterations over all converged steps.
    pub iterations: usize,
    /// Converged steps.
    pub steps: usize,
    /// Step cuts (halvings) that were needed.
    pub cuts: usize,
    /// Whether every converged point of the path was stable ([`PathPoint::stable`]).
    pub stable: bool,
    /// When not stable: the load factors [lo, hi] between which stability was first lost (lo
    /// the last stable converged point, hi the first unstable one or the end of a jump).
    pub critical_load_factor: Option<[f64; 2]>,
    /// The changes of stability along the path (the first four), each located to
    /// [`CRITICAL_TOL`] with its mode (with [`NonlinearOptions::locate_critical`]; a change the
    /// bisection cannot bracket, e.g. the end of a jump under load control, is left out).
    pub critical_points: Vec<CriticalPoint>,
    /// Co-rotated frame of each beam/flexibility element at the end (rows: local x, y, z in
    /// global coordinates; identity for springs).
    pub element_frames: Vec<[[f64; 3]; 3]>,
    /// With [`NonlinearOptions::step_track`]: the tracked quantities at every accepted point of
    /// the path, in path order (empty otherwise).
    pub step_quantities: Vec<StepQuantities>,
    /// The largest [`PathPoint::equilibrium`] over every returned state: each accepted point of
    /// the path and the final state.
    pub equilibrium: f64,
}

/// Results of all load cases, in model order.
#[derive(Debug, Clone, PartialEq)]
pub struct NonlinearResults {
    pub load_cases: Vec<NonlinearCase>,
}

/// Solves every load case of the model with geometric nonlinearity. Each case starts from the
/// undeformed configuration.
pub fn solve_nonlinear(model: &Model, opts: &NonlinearOptions) -> Result<NonlinearResults, FemError> {
    solve_nonlinear_each(model, &vec![opts.clone(); model.load_cases.len()])
}

/// [`solve_nonlinear`] with options per load case (`opts[i]` for load case i; as many as the
/// model has load cases).
pub fn solve_nonlinear_each(model: &Model, opts: &[NonlinearOptions]) -> Result<NonlinearResults, FemError> {
    model.validate()?;
    if opts.len() != model.load_cases.len() {
        return Err(FemError::BadInput(format!(
            "nonlinear options: {} option sets for {} load cases",
            opts.len(),
            model.load_cases.len()
        )));
    }
    if opts.iter().any(|o| o.steps == 0 || o.max_iterations == 0) {
        return Err(FemError::BadInput(
            "nonlinear options: steps and max_iterations must be at least 1".into(),
        ));
    }
    let elems = element_data(model)?;
    let load_cases = model
        .load_cases
        .iter()
        .zip(opts)
        .map(|(case, o)| solve_case(model, &elems, case, o))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(NonlinearResults { load_cases })
}
