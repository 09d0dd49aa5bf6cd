//! `"analysis": "prs_stiffness"`: Jacobian stiffness of a 3-PRS with compliant legs at chosen
//! poses and over a (ψ, θ) grid at fixed height, with the stiffness-limited workspace.
//!
//! The model, its sign and unit conventions are those of
//! [`crate::kinematics::prs_stiffness`]. Case files give angles in degrees; outputs give angles in
//! degrees, derivatives and stiffnesses per radian (K in N/mm, N and N·mm/rad).
//!
//! Files: this one holds the result types and the analysis kind; `prs_stiffness/solve.rs` runs
//! a case, `prs_stiffness/report.rs` writes the report and files.

mod report;
mod solve;

use crate::analysis::common::kind::{Analysis, Ctx};
use super::{Report, RunError};
use crate::case::prs_stiffness::PrsStiffnessCase;
use crate::case::CaseError;
use serde::Serialize;
pub use report::{files, report};
pub use solve::solve;

/// Eigen-decomposition in the result (length-scaled, N/mm).
#[derive(Debug, Clone, Serialize)]
pub struct EigenOut {
    /// ℓ, mm.
    pub length_mm: f64,
    /// Ascending eigenvalues, N/mm.
    pub values: Vec<f64>,
    /// Unit eigenvectors (one per value) in [δp (mm); ℓ·δα (mm)] coordinates.
    pub vectors: Vec<Vec<f64>>,
}

/// Deformation at the tool point.
#[derive(Debug, Clone, Serialize)]
pub struct DeformationOut {
    /// Applied wrench in the fixed frame [f (N); m (N·mm)].
    pub wrench_fixed: [f64; 6],
    /// Translation of the tool point, mm (fixed frame).
    pub translation_mm: [f64; 3],
    /// |translation|, mm.
    pub translation_norm_mm: f64,
    /// Rotation vector, degrees (fixed frame).
    pub rotation_deg: [f64; 3],
}

/// One pose's results.
#[derive(Debug, Clone, Serialize)]
pub struct PoseOut {
    /// Absolute height, mm.
    pub pz: f64,
    /// ψ, degrees.
    pub psi_deg: f64,
    /// θ, degrees.
    pub theta_deg: f64,
    /// Parasitic φ, degrees.
    pub phi_deg: f64,
    /// Parasitic pₓ, mm.
    pub px: f64,
    /// Parasitic p_y, mm.
    pub py: f64,
    /// Strokes from Aᵢ, mm.
    pub strokes: [f64; 3],
    /// Tool point in the fixed frame, mm.
    pub point: [f64; 3],
    /// ∂s/∂(p_z, ψ, θ) rows, mm/mm and mm/rad.
    pub jacobian: [[f64; 3]; 3],
    /// Wrench matrix G about the tool point (rows: f_x, f_y, f_z, m_x, m_y, m_z; columns:
    /// actuation 1–3, constraint 1–3).
    pub g: [[f64; 6]; 6],
    /// Leg compliances [c_a1, c_a2, c_a3, c_c1, c_c2, c_c3], mm/N.
    pub leg_compliance: [f64; 6],
    /// Stiffness about the tool point (N/mm, N, N·mm/rad); absent when a leg is rigid.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stiffness: Option<[[f64; 6]; 6]>,
    /// Compliance about the tool point (mm/N, rad/N, rad/(N·mm)).
    pub compliance: [[f64; 6]; 6],
    /// Directional stiffness 1/C_ii (N/mm, N·mm/rad); "unbounded" where rigid.
    #[serde(serialize_with = "unbounded_list")]
    pub directional: [Option<f64>; 6],
    /// Stiffness on (p_z, ψ, θ): Jᵀ·diag(k_a)·J.
    pub independent: [[f64; 3]; 3],
    /// Length-scaled eigen-decomposition of the 3×3 `independent`.
    pub eigen_independent: EigenOut,
    /// Length-scaled eigen-decomposition of the 6×6 K; absent when a leg is rigid.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub eigen: Option<EigenOut>,
    /// Deformation for the case's load.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub deformation: Option<DeformationOut>,
}

/// One map cell.
#[derive(Debug, Clone, Serialize)]
pub struct CellOut {
    /// ψ, degrees.
    pub psi_deg: f64,
    /// θ, degrees.
    pub theta_deg: f64,
    /// Reachable and non-singular.
    pub reachable: bool,
    /// Parasitic pₓ, mm (0 when unreachable).
    pub px: f64,
    /// Parasitic p_y, mm.
    pub py: f64,
    /// Parasitic φ, degrees.
    pub phi_deg: f64,
    /// Metric values (empty when unreachable, "unbounded" where a rigid leg makes it infinite).
    #[serde(serialize_with = "unbounded_list")]
    pub values: Vec<Option<f64>>,
    /// In the stiffness-limited workspace.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub in_workspace: Option<bool>,
}

/// Map results.
#[derive(Debug, Clone, Serialize)]
pub struct MapOut {
    /// Absolute height, mm.
    pub pz: f64,
    /// Points per axis.
    pub n: usize,
    /// Metric names.
    pub metrics: Vec<String>,
    /// Metric units.
    pub units: Vec<String>,
    /// Minimum and maximum of each metric over reachable cells ("unbounded" if no cell has a finite value).
    #[serde(serialize_with = "unbounded_list")]
    pub ranges: Vec<Option<[f64; 2]>>,
    /// Cells, ψ outer, θ inner.
    pub cells: Vec<CellOut>,
    /// Stiffness-limited workspace summary.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub workspace: Option<WorkspaceOut>,
}

/// Stiffness-limited workspace summary.
#[derive(Debug, Clone, Serialize)]
pub struct WorkspaceOut {
    /// Metric.
    pub metric: String,
    /// Threshold.
    pub threshold: f64,
    /// Fraction of the reachable cells kept.
    pub fraction: f64,
    /// Cells kept.
    pub cells: usize,
}

/// The `prs_stiffness` result.
#[derive(Debug, Clone, Serialize)]
pub struct PrsStiffnessResult {
    /// Moment convention, stated.
    pub conventions: String,
    /// Poses.
    pub poses: Vec<PoseOut>,
    /// Map.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub map: Option<MapOut>,
}

/// Serialises `None` entries as the string "unbounded" (never null).
fn unbounded_list<'a, T, I, S>(v: I, s: S) -> Result<S::Ok, S::Error>
where
    T: Serialize + 'a,
    I: IntoIterator<Item = &'a Option<T>>,
    S: serde::Serializer,
{
    use serde::ser::SerializeSeq;
    let items: Vec<&Option<T>> = v.into_iter().collect();
    let mut seq = s.serialize_seq(Some(items.len()))?;
    for it in items {
        match it {
            Some(x) => seq.serialize_element(x)?,
            None => seq.serialize_element("unbounded")?,
        }
    }
    seq.end()
}

/// `prs_stiffness`: the registered analysis kind.
pub struct PrsStiffnessAnalysis;

impl Analysis for PrsStiffnessAnalysis {
    type Case = PrsStiffnessCase;
    type Result = PrsStiffnessResult;

    fn check(case: &Self::Case) -> Result<(), CaseError> {
        case.validate().map(|_| ())
    }
    fn run(case: &Self::Case, ctx: &mut Ctx) -> Result<Self::Result, RunError> {
        let r = solve(case)?;
        if ctx.with_files {
            ctx.files.extend(files(&r));
        }
        Ok(r)
    }
    fn report(r: &Self::Result) -> Report {
        report(r)
    }
}
