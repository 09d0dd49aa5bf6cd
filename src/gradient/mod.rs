//! Gradients of the metrics of a linear `static` case with respect to its parameters, through
//! the element matrices: d metric / d parameter for every parameter declared as a number.
//!
//! A case declares `"parameters"` used in expressions anywhere a number goes (hinge
//! dimensions t, R, …, section dimensions, material constants, node coordinates, loads). For a
//! parameter p the linear system K(p) q = f(p) of the reduced (constrained) model gives, on the
//! one factorisation of K,
//!
//! dq/dp = K⁻¹ (df/dp − dK/dp q)            (direct method; one solve per parameter and load case)
//!
//! and a metric m(p, q) has dm/dp = ∂m/∂p + ∂m/∂q · dq/dp: a stiffness 1/c, compliance c,
//! displacement, hinge rotation, stroke at allowable, element von Mises stress
//! ([`Target::VonMises`]) or the largest utilisation (its gradient is that of the element
//! where the largest one is, the arg-max: not differentiable where two elements tie). Natural
//! frequencies by the eigenvalue derivative of a simple mode ([`frequency`]).
//!
//! What is exact and what is differenced: the expressions of the case are differentiated
//! analytically ([`crate::case::params::expr::Expr::eval_tangent`]), and the model is moved
//! along the exact tangent of its numbers. The hinge elements' compliance is differentiated
//! analytically too ([`crate::hinge::tangent`]: forward mode through the flexibility integrals,
//! their limits and calibration factors; dK = −K dC K on each element, `hinges`), except the
//! warping-restrained torsion compliance of rectangular notches (a Vlasov finite-element solve).
//! The rest of the reduced stiffness, mass and loads (beams, shells, the hinges' Vlasov torsion
//! and geometry, the rigid-link transforms that node coordinates move, loads) and the recovery
//! of the metrics are differentiated by sixth-order central differences at element level (no
//! solve is differenced): exact to ≈ 1e-10 relative ([`linear::RELATIVE_STEP`]). The direct
//! method is used rather than the adjoint one (one solve per metric) because its right-hand
//! sides need no ∂m/∂q; a triangular solve costs little beside the factorisation and the
//! element matrices of the moved models, which both methods need.
//!
//! Units: a gradient is in the units of its metric per unit of its parameter (a stiffness in
//! N/mm per mm of `t`: N/mm²; a frequency in Hz per unit).

pub mod frequency;
mod hinges;
pub mod linear;
pub mod nonlinear;
mod point;

use crate::analysis::{AnalysisError, RunError};
use crate::case::CaseError;
use crate::fem::FemError;
pub use linear::Linear;
use serde::ser::SerializeMap;

/// A quantity whose gradient is wanted.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Target {
    /// A metric of the case's `"metrics"`, by name (every kind of a linear run).
    Metric(String),
    /// The peak von Mises stress of element `element` (index in the case's `elements`; a
    /// hinge's peak at its notch, a beam's largest over its section points) in `load_case`, MPa.
    VonMises {
        /// Load case name.
        load_case: String,
        /// Index in the case's `elements`.
        element: usize,
    },
    /// The natural frequency of mode `mode` (1 = lowest) with the case's supports, Hz.
    Frequency {
        /// Mode number, from 1.
        mode: usize,
    },
}

impl Target {
    /// The name in the result: the metric's, `von_mises[ELEMENT]@CASE`, `frequency[MODE]`.
    pub fn name(&self) -> String {
        match self {
            Target::Metric(n) => n.clone(),
            Target::VonMises { load_case, element } => format!("von_mises[{element}]@{load_case}"),
            Target::Frequency { mode } => format!("frequency[{mode}]"),
        }
    }
}

/// The targets' values and gradients.
#[derive(Debug, Clone, PartialEq)]
pub struct Gradients {
    /// The parameters, in column order.
    pub parameters: Vec<String>,
    /// The targets' names ([`Target::name`]), in row order.
    pub targets: Vec<String>,
    /// Each target's value (its metric's units).
    pub values: Vec<f64>,
    /// `jacobian[target][parameter]`: d target / d parameter, target units per parameter unit.
    pub jacobian: Vec<Vec<f64>>,
    /// How they were computed.
    pub model: Vec<String>,
    /// A frequency target's mode is repeated: its derivative is one-sided
    /// ([`frequency`], noted in `model`), not a gradient.
    pub repeated_mode: bool,
}

impl Gradients {
    /// d `target` / d `parameter`, by name.
    pub fn get(&self, target: &str, parameter: &str) -> Option<f64> {
        let i = self.targets.iter().position(|t| t == target)?;
        let j = self.parameters.iter().position(|p| p == parameter)?;
        Some(self.jacobian[i][j])
    }

    /// The `{"METRIC": {"PARAM": value}}` table of a result.
    pub fn table(&self) -> Table {
        Table(
            self.targets
                .iter()
                .zip(&self.jacobian)
                .map(|(t, row)| {
                    (
                        t.clone(),
                        self.parameters.iter().cloned().zip(row.iter().copied()).collect(),
                    )
                })
                .collect(),
        )
    }
}

/// `{"METRIC": {"PARAM": d metric / d param}}` in the case's order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Table(pub Vec<(String, Vec<(String, f64)>)>);

impl serde::Serialize for Table {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        struct Row<'a>(&'a [(String, f64)]);
        impl serde::Serialize for Row<'_> {
            fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                let mut m = s.serialize_map(Some(self.0.len()))?;
                for (k, v) in self.0 {
                    m.serialize_entry(k, v)?;
                }
                m.end()
            }
        }
        let mut m = s.serialize_map(Some(self.0.len()))?;
        for (k, row) in &self.0 {
            m.serialize_entry(k, &Row(row))?;
        }
        m.end()
    }
}

/// Why gradients could not be computed: the case (exit 2) or the analysis (exit 1).
#[derive(Debug, Clone)]
pub struct GradientError(pub RunError);

impl GradientError {
    /// A case error at `gradients`.
    pub fn case(message: impl Into<String>) -> GradientError {
        GradientError(RunError::Case(CaseError::new("gradients", message)))
    }

    /// A metric without a value at this design (`null`: no allowable, a supported DOF).
    pub fn undefined(name: &str) -> GradientError {
        GradientError(RunError::Analysis(AnalysisError::new(
            "gradients",
            format!("metric `{name}` has no value (null) at this design, so no gradient"),
        )))
    }
}

impl From<CaseError> for GradientError {
    fn from(e: CaseError) -> Self {
        GradientError(RunError::Case(e))
    }
}

impl From<AnalysisError> for GradientError {
    fn from(e: AnalysisError) -> Self {
        GradientError(RunError::Analysis(e))
    }
}

impl From<FemError> for GradientError {
    fn from(e: FemError) -> Self {
        GradientError(RunError::Analysis(AnalysisError::new("gradients", e.to_string())))
    }
}

impl From<GradientError> for RunError {
    fn from(e: GradientError) -> Self {
        e.0
    }
}

impl std::fmt::Display for GradientError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.0.fmt(f)
    }
}

impl std::error::Error for GradientError {}

/// The gradients of every metric of a `static` case as written (see [`Linear`]) with respect
/// to every parameter it declares as a number, at the declared values.
pub fn linear(written: std::sync::Arc<crate::case::params::tangent::Written>) -> Result<Gradients, GradientError> {
    let p = point::Point::new(&written, &Default::default(), None)?;
    let targets = p.case.metrics.iter().map(|m| Target::Metric(m.name.clone())).collect();
    Linear::new(written, targets).evaluate(&Default::default(), &mut crate::fem::SolverCache::new())
}
