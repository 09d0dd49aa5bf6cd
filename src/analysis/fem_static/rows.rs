//! The typed result of a `static` run: one row per load case with its displacements,
//! reactions, section forces, hinge and shell stresses.

use super::ComplianceRow;
use serde::Serialize;

/// One load case of a `static` result.
#[derive(Debug, Clone, Serialize)]
pub struct StaticCaseRow {
    /// Load-case name.
    pub name: String,
    /// Per node [ux, uy, uz (mm), rx, ry, rz (degrees)], global axes.
    pub displacements: Vec<[f64; 6]>,
    /// Per supported node [Fx, Fy, Fz (N), Mx, My, Mz (N·mm)], in the order of `reaction_nodes`.
    pub reactions: Vec<[f64; 6]>,
    /// The supported nodes, ascending.
    pub reaction_nodes: Vec<usize>,
    /// Largest von Mises stress over every stressed element — beams and shells (their recovered
    /// stresses) and hinge elements (their `peak_von_mises`) — MPa; `null` only when the model
    /// has no stressed element (springs, joints, rigid links, superelements, masses only).
    pub max_von_mises: Option<f64>,
    /// The element that carries `max_von_mises` (`null` with it).
    pub max_von_mises_at: Option<StressAt>,
    /// Largest von Mises / allowable over the stressed elements whose material has an allowable
    /// stress, and where it is; `null` when none has one (utilisation is not defined without an
    /// allowable: such elements count in `max_von_mises` only).
    pub max_utilisation: Option<Utilisation>,
    /// Sum of the support (and ground-spring) reactions about the global origin:
    /// [Fx, Fy, Fz (N), Mx, My, Mz (N·mm)].
    pub total_reaction: [f64; 6],
    /// Largest von Mises stress per element, MPa (`null` for springs).
    pub element_von_mises: Vec<Option<f64>>,
    /// Shells only: von Mises at the element centre on the top, mid and bottom surfaces, MPa
    /// (omitted for models without shells).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub shell_von_mises: Vec<ShellVonMises>,
    /// Sum of loads plus reactions (should vanish): [N, N, N, N·mm, N·mm, N·mm].
    pub equilibrium_residual: [f64; 6],
    /// Nonlinear only: the largest equilibrium residual over every returned state of the path
    /// (each accepted load step or arc-length point, the final state included), relative to
    /// its load scale: the largest of nodal residual, unbalanced total force and unbalanced
    /// total moment at the deformed positions, each over the applied loads (with prescribed
    /// displacements, the reactions too). Every state is checked to 1e-6 of it (plus a
    /// round-off floor of the stiffest element).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub path_equilibrium_residual: Option<f64>,
    /// Nonlinear only: whether every converged point of the equilibrium path was stable
    /// (positive definite tangent stiffness, no jump over a limit point).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stable: Option<bool>,
    /// Nonlinear and not stable: load factors [lo, hi] bracketing the first loss of stability.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub critical_load_factor: Option<[f64; 2]>,
    /// Nonlinear: the located changes of stability along the path (omitted when none).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub critical_points: Vec<super::path_rows::CriticalPointRow>,
    /// Nonlinear with `trace`: the load–displacement curve of the traced DOF.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub trace: Option<super::path_rows::TraceRow>,
    /// Shells only: nodal surface stresses (omitted for models without shells).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shell_stress: Option<ShellStressRow>,
    /// Shells only: stress resultants at each shell element's centre, element axes (omitted
    /// for models without shells).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub shell_forces: Vec<ShellForcesRow>,
    /// Per `hinge` element: rotation, end forces, peak stress and margin (omitted for models
    /// without hinge elements).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub hinges: Vec<HingeRow>,
    /// With `"output": {"section_forces": true}`: section forces of every beam element
    /// (omitted otherwise).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub beam_forces: Vec<BeamForcesRow>,
    /// Nonlinear with `"track"`: frequencies and node compliances at every accepted load step
    /// (omitted otherwise).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub track: Option<super::track::TrackRow>,
    /// Nonlinear runs with rigid bodies: each body's instantaneous centre of rotation per step
    /// of the path and its drift ([`super::pivot`]; omitted otherwise).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub centre_of_rotation: Vec<super::pivot::BodyPivotRow>,
    /// The nodes with applied nodal loads or prescribed displacements, ascending (for the
    /// report's summary; not written to the JSON).
    #[serde(skip)]
    pub loaded_nodes: Vec<usize>,
    /// The warnings about this load case (also in the result's `warnings`), for the report's
    /// summary; not written to the JSON.
    #[serde(skip)]
    pub warnings: Vec<String>,
}

/// A stressed element of a load case.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct StressAt {
    /// Index of the element in the case's `elements`.
    pub element: usize,
    /// What it is: `"beam"`, `"shell"` or `"hinge"`.
    pub kind: &'static str,
    /// Index of the element in the FE model (the order of `element_von_mises`; a hinge of
    /// several segments: its first).
    pub model_element: usize,
    /// Its von Mises stress, MPa (a hinge: its `peak_von_mises`, notch factor included).
    pub von_mises: f64,
}

/// The largest utilisation of a load case.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Utilisation {
    /// von Mises / allowable, dimensionless (above 1: the allowable stress is exceeded).
    pub value: f64,
    /// Index of the element in the case's `elements`.
    pub element: usize,
    /// What it is: `"beam"`, `"shell"` or `"hinge"`.
    pub kind: &'static str,
    /// Index of the element in the FE model (see [`StressAt::model_element`]).
    pub model_element: usize,
    /// Its von Mises stress, MPa.
    pub von_mises: f64,
    /// Allowable stress of its material, MPa.
    pub allowable: f64,
}

/// Section forces of one beam element in one load case.
#[derive(Debug, Clone, Serialize)]
pub struct BeamForcesRow {
    /// Index of the element in the FE model (the order of `element_von_mises`).
    pub element: usize,
    /// [N, Vy, Vz (N), T, My, Mz (N·mm)] at end a (first node) and end b, element axes
    /// (deformed element axes in nonlinear runs); positive-face convention: N > 0 in tension,
    /// the forces the part beyond the section exerts on the part before it.
    pub section_forces: [[f64; 6]; 2],
}

/// Fatigue of one hinge element in one load case (the case is the peak of the cycle).
#[derive(Debug, Clone, Copy, Serialize, PartialEq)]
pub struct HingeFatigue {
    /// Fatigue utilisation σ_a/S_f(N) + σ_m/S_mean at the required cycles; ≤ 1 passes.
    pub utilisation: f64,
    /// Predicted life, cycles (`"infinite"` within the endurance limit).
    pub life_cycles: crate::analysis::common::fatigue::Life,
    /// Alternating and mean fatigue stresses (peak stress × K_f/K_t), MPa.
    pub stress_alternating: f64,
    pub stress_mean: f64,
    /// Fatigue notch factor K_f = 1 + q (K_t − 1) of the hinge.
    pub kf: f64,
    /// Corrected endurance limit S_e, MPa, and fatigue strength at the required cycles S_f, MPa.
    pub endurance_corrected: f64,
    pub strength_at_cycles: f64,
}

/// Results of one `hinge` element in one load case.
#[derive(Debug, Clone, Serialize)]
pub struct HingeRow {
    /// Index of the element in the case's `elements`.
    pub element: usize,
    /// Index of the element in the FE model (the order of `element_von_mises`).
    pub model_element: usize,
    /// Rotation about the compliant axis (element local y), degrees: the relative rotation of
    /// node b with respect to node a about the element's local y. Linear: (θ_b − θ_a)·e_y.
    /// Nonlinear: the local-y component of the rotation vector of R_aᵀ·R_b (finite rotations,
    /// in the undeformed element axes).
    pub rotation_deg: f64,
    /// Section forces [N, Vy, Vz (N), T, My, Mz (N·mm)] at end a and end b, element axes
    /// (deformed element axes in nonlinear runs; N > 0 in tension).
    pub end_forces: [[f64; 6]; 2],
    /// Peak von Mises stress along the hinge with the notch factor, MPa (the stress model of the
    /// `hinge` analysis and the `stage`).
    pub peak_von_mises: f64,
    /// peak_von_mises / allowable of the element's material (0 without an allowable).
    pub utilisation: f64,
    /// Rotation left until the peak stress reaches the allowable, degrees, by linear
    /// extrapolation of the load case (stress proportional to rotation):
    /// rotation_deg · (allowable/peak_von_mises − 1). Signed like rotation_deg (further rotation
    /// in the same sense); of the opposite sign when the allowable is already exceeded; `null`
    /// when unbounded (no allowable, or no stress).
    #[serde(serialize_with = "crate::report::numbers::ratio_or_null")]
    pub remaining_rotation_deg: f64,
    /// Fatigue of the hinge, the load case as the peak of its cycle (`"fatigue"` only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fatigue: Option<HingeFatigue>,
}

/// Nodal stresses of the shells: per node [sxx, syy, szz, sxy, syz, szx] (MPa, global axes),
/// integration-point values extrapolated to the nodes and averaged over the shells at the
/// node; `null` for nodes without shells. Top and bottom follow each element's normal (right-hand
/// rule over its node order): mesh every shell in the same sense (a warning names edges shared
/// by oppositely oriented shells).
#[derive(Debug, Clone, Serialize)]
pub struct ShellStressRow {
    /// Top surface (z = +t/2 along the element normal).
    pub top: Vec<Option<[f64; 6]>>,
    /// Mid-surface (membrane stress; transverse shear as the parabolic peak 1.5·Q/t).
    pub mid: Vec<Option<[f64; 6]>>,
    /// Bottom surface (z = −t/2).
    pub bottom: Vec<Option<[f64; 6]>>,
    /// The same stresses by superconvergent patch recovery, with the error indicator per
    /// element ([`crate::fem::shell_spr`]); absent for a model with nine-node shells (the
    /// recovery is of the four-node shell's Gauss points).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub recovered: Option<ShellRecoveredRow>,
}

/// Nodal shell stresses by superconvergent patch recovery (Zienkiewicz & Zhu 1992): per node
/// [sxx, syy, szz, sxy, syz, szx] (MPa, global axes) from a least-squares fit of the Gauss-point
/// stresses over the patch of shells around each interior node; nodes on the mesh boundary take
/// the fits of the interior patches that contain them (the clamped-edge and leaf-root values).
/// With the Zienkiewicz–Zhu error indicator of each shell.
#[derive(Debug, Clone, Serialize)]
pub struct ShellRecoveredRow {
    /// `"SPR"`, the method.
    pub method: &'static str,
    /// Top surface, recovered.
    pub top: Vec<Option<[f64; 6]>>,
    /// Mid-surface, recovered.
    pub mid: Vec<Option<[f64; 6]>>,
    /// Bottom surface, recovered.
    pub bottom: Vec<Option<[f64; 6]>>,
    /// Global relative error η = √(Σ‖e‖²/(‖u‖² + Σ‖e‖²)) in the energy norm of the membrane and
    /// bending stresses (0…1).
    pub relative_error: f64,
    /// One row per shell element.
    pub error: Vec<ShellErrorRow>,
}

/// The Zienkiewicz–Zhu error of one shell element.
#[derive(Debug, Clone, Serialize)]
pub struct ShellErrorRow {
    /// Element index (model order).
    pub element: usize,
    /// ‖σ* − σ_h‖ in the energy norm over the element, √(N·mm).
    pub norm: f64,
    /// Indicator ξ = norm / √((‖u‖² + Σ‖e‖²)/m), m shells: above a target relative error η̄,
    /// the element is where the recovery (and the solution) is least reliable; refine there.
    pub indicator: f64,
}

impl ShellRecoveredRow {
    /// The row of a recovered field.
    pub fn of(f: crate::fem::shell_spr::SprField) -> ShellRecoveredRow {
        ShellRecoveredRow {
            method: "SPR",
            top: f.top,
            mid: f.mid,
            bottom: f.bottom,
            relative_error: f.relative_error,
            error: f
                .elements
                .into_iter()
                .map(|(element, norm, indicator)| ShellErrorRow {
                    element,
                    norm,
                    indicator,
                })
                .collect(),
        }
    }
}

/// Stress resultants at the centre of one shell element, in its axes.
#[derive(Debug, Clone, Serialize)]
pub struct ShellForcesRow {
    /// Element index (model order).
    pub element: usize,
    /// Element axes: local x, y, z (normal) as unit vectors in global coordinates.
    pub axes: [[f64; 3]; 3],
    /// Membrane forces [Nxx, Nyy, Nxy], N/mm.
    #[serde(rename = "N")]
    pub n: [f64; 3],
    /// Moments [Mxx, Myy, Mxy], N·mm/mm (Mxx > 0 stretches the top surface).
    #[serde(rename = "M")]
    pub m: [f64; 3],
    /// Transverse shear forces [Qx, Qy], N/mm.
    #[serde(rename = "Q")]
    pub q: [f64; 2],
}

/// Surface stresses of one shell element.
#[derive(Debug, Clone, Serialize)]
pub struct ShellVonMises {
    /// Element index (model order).
    pub element: usize,
    /// Von Mises at z = +t/2, MPa.
    pub top: f64,
    /// Von Mises at the mid-surface, MPa.
    pub mid: f64,
    /// Von Mises at z = −t/2, MPa.
    pub bottom: f64,
}

/// Result of the `static` analysis.
#[derive(Debug, Clone, Serialize)]
pub struct StaticResult {
    /// Load cases in input order.
    pub load_cases: Vec<StaticCaseRow>,
    /// Units of the output arrays.
    pub units: Units,
    /// Model notes.
    pub model: Vec<String>,
    /// Node compliances the case asked for (`"compliance"`), linear, with the model's supports
    /// (DOFs prescribed in load cases are free here); omitted when none was asked.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub compliance: Vec<ComplianceRow>,
    /// The named values the case asked for (`"metrics"`), `{"NAME": value}` in the case's order;
    /// omitted when none was asked.
    #[serde(skip_serializing_if = "super::metrics::Metrics::is_empty")]
    pub metrics: super::metrics::Metrics,
    /// `{"METRIC": {"PARAM": d metric / d param}}` when the case asks (`"gradients": true`),
    /// in the metric's units per unit of the parameter; omitted otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gradients: Option<crate::gradient::Table>,
}

/// Units of the `static` result.
#[derive(Debug, Clone, Serialize)]
pub struct Units {
    /// Units of each displacement entry.
    pub displacements: &'static str,
    /// Units of each reaction entry.
    pub reactions: &'static str,
}
