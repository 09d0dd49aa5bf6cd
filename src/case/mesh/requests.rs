//! Extra outputs a `static` case asks for: beam section forces and node compliances.

use super::frames;
use crate::case::error::CaseError;
use serde::Deserialize;

/// `"output"` of a `static` case: optional result fields (all off by default, so results stay
/// compact).
#[derive(Debug, Clone, Default, PartialEq, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct StaticOutput {
    /// Section forces [N, Vy, Vz, T, My, Mz] at both ends of every beam element, per load case
    /// (`beam_forces` in each load case of the result). Default false.
    #[serde(default)]
    pub section_forces: bool,
    /// Also list the inner nodes of segmented hinge elements (`"segments"` > 1; numbered after
    /// the case's nodes) in `displacements`. Default false: one row per node of the case.
    #[serde(default)]
    pub internal_nodes: bool,
}

/// One entry of `"compliance"`: the 6×6 compliance of a node with the model's supports.
#[derive(Debug, Clone, PartialEq, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ComplianceRequest {
    /// The node.
    pub node: usize,
    /// Axes of the result: three orthonormal right-handed rows (local x, y, z in global
    /// coordinates); default the global axes.
    #[serde(default)]
    pub frame: Option<[[f64; 3]; 3]>,
}

/// Validates the compliance requests against a model of `n_nodes` nodes (paths
/// `compliance[i].node`, `compliance[i].frame`).
pub fn check_compliance(reqs: &[ComplianceRequest], n_nodes: usize) -> Result<(), CaseError> {
    check_compliance_at("compliance", reqs, n_nodes)
}

/// Most natural frequencies `"track"` may ask for per step.
pub const MAX_TRACK_MODES: usize = 100;

/// `"track"` of a nonlinear `static` case: quantities evaluated at every accepted load step
/// with the tangent stiffness of the deformed state.
#[derive(Debug, Clone, Default, PartialEq, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct TrackRequest {
    /// Number of natural frequencies (the lowest) per step, with the current tangent
    /// stiffness (geometric stiffness included) and the mass; 0 … 100 (default 0).
    #[serde(default)]
    #[schemars(range(max = 100))]
    pub modes: usize,
    /// Nodes whose 6×6 compliance (and support stiffness, its inverse diagonal) per step the
    /// result lists, as the top-level `compliance`: `[{"node": n, "frame": [[..], [..], [..]]}]`.
    #[serde(default)]
    pub compliance: Vec<ComplianceRequest>,
}

/// Validates `"track"` (paths `track.modes`, `track.compliance[i]…`): only with
/// `"nonlinear": true`, and asking for something.
pub fn check_track(track: Option<&TrackRequest>, nonlinear: bool, n_nodes: usize) -> Result<(), CaseError> {
    let Some(t) = track else {
        return Ok(());
    };
    if !nonlinear {
        return Err(CaseError::new(
            "track",
            "tracking along the load path applies to a nonlinear analysis only: add \"nonlinear\": true or remove \"track\"",
        ));
    }
    if t.modes > MAX_TRACK_MODES {
        return Err(CaseError::value(
            "track.modes",
            t.modes,
            format!("must be at most {MAX_TRACK_MODES}"),
        ));
    }
    if t.modes == 0 && t.compliance.is_empty() {
        return Err(CaseError::new(
            "track",
            "asks for nothing: give \"modes\" ≥ 1 and/or \"compliance\": [{\"node\": n}]",
        ));
    }
    check_compliance_at("track.compliance", &t.compliance, n_nodes)
}

fn check_compliance_at(path: &str, reqs: &[ComplianceRequest], n_nodes: usize) -> Result<(), CaseError> {
    for (i, r) in reqs.iter().enumerate() {
        check_node_frame(&format!("{path}[{i}]"), r.node, r.frame, n_nodes)?;
    }
    Ok(())
}

/// Validates the `node` and optional `frame` (orthonormal right-handed rows) of an entry at
/// JSON path `p` against a model of `n_nodes` nodes.
pub fn check_node_frame(p: &str, node: usize, frame: Option<[[f64; 3]; 3]>, n_nodes: usize) -> Result<(), CaseError> {
    if node >= n_nodes {
        return Err(CaseError::value(
            format!("{p}.node"),
            node,
            format!("the model has nodes 0 … {}", n_nodes.saturating_sub(1)),
        ));
    }
    if let Some(f) = frame {
        for (k, v) in f.iter().flatten().enumerate() {
            crate::case::error::check::finite(format_args!("{p}.frame[{}][{}]", k / 3, k % 3), *v)?;
        }
    }
    frames::local(p, frame, None)?;
    Ok(())
}
