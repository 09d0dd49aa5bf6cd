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
    /// How `model.svg` (written by `run --out`) draws the model: view, deformation scale, load
    /// case, numbers. Default: isometric view, automatic scale, the first load case.
    #[serde(default)]
    pub picture: PictureRequest,
}

/// `"output": {"picture": …}` of a `static` case: how `model.svg` draws the model.
#[derive(Debug, Clone, Default, PartialEq, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PictureRequest {
    /// The viewing direction: `"iso"` (default, from the +x +y +z octant), `"front"` (from −y: x
    /// right, z up), `"side"` (from +x: y right, z up), `"top"` (from +z: x right, y up), or
    /// `{"azimuth": deg, "elevation": deg}` (the viewer's direction: azimuth about z from +x,
    /// elevation above the x–y plane).
    #[serde(default)]
    pub view: Option<ViewRequest>,
    /// Deformation scale (drawn displacement / computed displacement), > 0; default automatic:
    /// 1 when the largest displacement is at least 5 % of the model's size, else a round
    /// number that draws it as about 8 % of the model's size.
    #[serde(default)]
    pub scale: Option<f64>,
    /// The load case drawn deformed (its name); default the first.
    #[serde(default)]
    pub load_case: Option<String>,
    /// Write node numbers beside the nodes. Default false.
    #[serde(default)]
    pub numbers: bool,
}

/// A viewing direction of `model.svg`.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, schemars::JsonSchema)]
#[serde(untagged)]
pub enum ViewRequest {
    /// A named view.
    Named(NamedView),
    /// The viewer's direction, degrees.
    Angles {
        /// Azimuth about global z from +x, degrees.
        azimuth: f64,
        /// Elevation above the x–y plane, −90 … 90 degrees.
        elevation: f64,
    },
}

/// Named views of `model.svg`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum NamedView {
    /// From the +x +y +z octant.
    Iso,
    /// From −y: x right, z up.
    Front,
    /// From +x: y right, z up.
    Side,
    /// From +z: x right, y up.
    Top,
}

impl ViewRequest {
    /// (azimuth, elevation) of the view, degrees.
    pub fn angles(&self) -> (f64, f64) {
        match *self {
            ViewRequest::Named(NamedView::Iso) => (45.0, 35.264_389_682_754_654),
            ViewRequest::Named(NamedView::Front) => (-90.0, 0.0),
            ViewRequest::Named(NamedView::Side) => (0.0, 0.0),
            ViewRequest::Named(NamedView::Top) => (0.0, 90.0),
            ViewRequest::Angles { azimuth, elevation } => (azimuth, elevation),
        }
    }
}

/// Validates `output.picture` (paths `output.picture.…`) against the model's load cases.
pub fn check_picture(p: &PictureRequest, load_cases: &[super::LoadCaseSpec]) -> Result<(), CaseError> {
    if let Some(ViewRequest::Angles { azimuth, elevation }) = p.view {
        if !azimuth.is_finite() {
            return Err(CaseError::new(
                "output.picture.view.azimuth",
                format!("{azimuth} is not a finite angle (degrees)"),
            ));
        }
        if !(elevation.is_finite() && (-90.0..=90.0).contains(&elevation)) {
            return Err(CaseError::new(
                "output.picture.view.elevation",
                format!("{elevation} is outside −90 … 90 degrees"),
            ));
        }
    }
    if let Some(s) = p.scale {
        if !(s.is_finite() && s > 0.0) {
            return Err(CaseError::new(
                "output.picture.scale",
                format!("{s} is not a deformation scale: give a number > 0 (or leave it out for automatic)"),
            ));
        }
    }
    if let Some(name) = &p.load_case {
        if !load_cases.iter().any(|c| &c.name == name) {
            let names: Vec<&str> = load_cases.iter().map(|c| c.name.as_str()).collect();
            return Err(CaseError::new(
                "output.picture.load_case",
                format!(
                    "\"{name}\" is no load case of the model (load cases: {})",
                    names.join(", ")
                ),
            ));
        }
    }
    Ok(())
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
