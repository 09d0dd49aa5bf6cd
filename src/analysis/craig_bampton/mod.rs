//! `"analysis": "craig_bampton"`: Craig–Bampton reduction of a beam/hinge/joint model to
//! interface nodes ([`crate::fem::craig_bampton`]): a superelement (K and M on the interface
//! DOFs plus fixed-interface modal coordinates), its frequencies against the full model's, and
//! with `--out` its matrices in Matrix Market (`superelement_K.mtx`, `superelement_M.mtx`).
//! The result JSON (`result.json`) is the superelement file a host mesh case attaches with a
//! `superelement` element ([`crate::case::mesh::superelement`]).

use crate::analysis::common::kind::{named_materials, Analysis, Ctx, UsedMaterial};
use super::{AnalysisError, Report, RunError};
use crate::case::fem_case::{mesh_rules, read_model, split, MODEL_FIELDS};
use crate::case::mesh::MeshSpec;
use crate::case::{from_value, CaseError};
use crate::fem::craig_bampton::{craig_bampton, partition, Superelement, MAX_INTERIOR, MAX_REDUCED};
use crate::fem::matrices::ReducedMatrices;
use crate::fem::modal::{solve_modal, ModalOptions};
use serde::{Deserialize, Serialize};
use serde_json::Value;
use std::f64::consts::PI;

/// `"analysis": "craig_bampton"`.
#[derive(Debug, Clone, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(extend("allOf" = mesh_rules(false)))]
pub struct CraigBamptonCase {
    /// Interface nodes: every equation (free DOF) of these nodes is a boundary coordinate.
    #[schemars(length(min = 1))]
    pub interface: Vec<usize>,
    /// Number of fixed-interface modes kept, 0 … 1000 (0: Guyan's static condensation).
    #[schemars(range(min = 0, max = 1000))]
    pub modes: usize,
    /// Free text (not used).
    pub description: Option<String>,
    /// The model's JSON mesh file, as for `static` (its load cases are ignored), or the model
    /// inline.
    pub mesh: Option<String>,
    /// The model.
    #[serde(flatten)]
    pub model: MeshSpec,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct Options {
    interface: Vec<usize>,
    modes: usize,
    #[serde(default)]
    mesh: Option<String>,
    #[serde(default)]
    description: Option<String>,
}

const OWN: [&str; 6] = ["analysis", "description", "mesh", "interface", "modes", "load_cases"];

/// Parses a `craig_bampton` case; a mesh file it names resolves against `base` first.
pub fn parse(value: Value, base: &crate::case::Source<'_>) -> Result<CraigBamptonCase, CaseError> {
    let (mut options, model) = split(value, &OWN);
    let stray = model
        .as_object()
        .and_then(|m| m.keys().find(|k| !MODEL_FIELDS.contains(&k.as_str())).cloned());
    if let Some(key) = stray {
        let allowed = format!("unknown field `{key}` in a `craig_bampton` case, expected one of the model's fields or {OWN:?}");
        return Err(CaseError::new(key, allowed));
    }
    if let Value::Object(m) = &mut options {
        m.remove("load_cases");
    }
    let Options {
        description,
        mesh,
        interface,
        modes,
    } = from_value(options, "")?;
    let case = CraigBamptonCase {
        model: read_model(model, mesh.as_deref(), None, base)?,
        description,
        mesh,
        interface,
        modes,
    };
    // A shell edge on the interface would get a midpoint inside the superelement, so the
    // host's edge and the superelement's would not match.
    if let Some(p) = &case.model.promoted {
        if let Some((m, a, b)) = p
            .midpoints()
            .find(|(_, a, b)| case.interface.contains(a) && case.interface.contains(b))
        {
            return Err(CaseError::value(
                "shell_elements",
                "shell9",
                format!("the shell edge {a}–{b} lies on the interface and its added midpoint (node {m}) would be an interior node of the superelement, so the superelement's edge would not match its host's: write the shells as `shell9` with their midpoints in `interface`, or keep \"shell_elements\": \"as_given\""),
            ));
        }
    }
    case.check_options().map(|()| case)
}

impl CraigBamptonCase {
    /// The model, after the options are checked, and its sizes checked.
    fn build(&self) -> Result<crate::fem::Model, CaseError> {
        self.check_options()?;
        let model = self.model.build_model(false)?;
        self.check_sizes(&model)?;
        Ok(model)
    }

    /// Refuses a reduction the dense algebra cannot take (interior, superelement size, memory)
    /// or more modes than the interior has, before anything large is allocated.
    fn check_sizes(&self, model: &crate::fem::Model) -> Result<(), CaseError> {
        // Conflicting constraints are reported by the run with the solver's message.
        let Ok(part) = partition(model, &self.interface) else {
            return Ok(());
        };
        if let Some(k) = part.bare {
            let allowed = "has no equations (fully supported, or a rigid-link slave: use its master)";
            return Err(CaseError::value(format!("interface[{k}]"), self.interface[k], allowed));
        }
        let (nb, ni) = (part.boundary, part.interior);
        let nodes = format!("({} nodes)", self.interface.len());
        if ni > MAX_INTERIOR {
            let allowed = format!(
                "leaves {ni} interior equations; the dense reduction takes at most {MAX_INTERIOR} (reduce a smaller part of the model)"
            );
            return Err(CaseError::value("interface", nodes, allowed));
        }
        if nb + self.modes > MAX_REDUCED {
            let allowed = format!(
                "has {nb} boundary equations, which with {} modes make a superelement of {} coordinates; the dense superelement takes at most {MAX_REDUCED} (use fewer interface nodes or modes)",
                self.modes,
                nb + self.modes
            );
            return Err(CaseError::value("interface", nodes, allowed));
        }
        if self.modes > ni {
            let allowed = format!(
                "must be at most {ni}: the interior (the model's equations off the interface nodes) has {ni} equations, so it has at most {ni} fixed-interface modes"
            );
            return Err(CaseError::value("modes", self.modes, allowed));
        }
        crate::case::limits::check_craig_bampton(nb + ni, nb, self.modes, self.interface.len())
    }

    fn check_options(&self) -> Result<(), CaseError> {
        let n = self.model.nodes.len();
        if self.interface.is_empty() {
            return Err(CaseError::new("interface", "must name at least one node"));
        }
        for (i, &node) in self.interface.iter().enumerate() {
            if node >= n {
                return Err(CaseError::value(format!("interface[{i}]"), node, format!("must be a node index below {n}")));
            }
            if self.interface[..i].contains(&node) {
                return Err(CaseError::value(format!("interface[{i}]"), node, "is named twice"));
            }
        }
        if self.modes > 1000 {
            return Err(CaseError::value("modes", self.modes, "must be an integer from 0 to 1000"));
        }
        Ok(())
    }
}

/// One boundary coordinate.
#[derive(Debug, Clone, Serialize)]
pub struct BoundaryDof {
    pub node: usize,
    pub dof: String,
}

/// An interface node: what a host case's `superelement` element checks its nodes against.
#[derive(Debug, Clone, Serialize)]
pub struct InterfaceNode {
    pub node: usize,
    /// Coordinates, mm.
    pub x: [f64; 3],
    /// The node's frame (rows: local x, y, z in global axes) when it has one: its boundary
    /// DOFs are then local.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub frame: Option<[[f64; 3]; 3]>,
}

/// The superelement and its check against the full model.
#[derive(Debug, Clone, Serialize)]
pub struct CraigBamptonResult {
    /// Method and units.
    pub model: String,
    /// The interface nodes in the case's order (a host case's `superelement` element names its
    /// own nodes in this order).
    pub interface_nodes: Vec<InterfaceNode>,
    /// Boundary coordinates (the first rows of K and M), then `modes` modal coordinates.
    pub boundary: Vec<BoundaryDof>,
    pub modes: usize,
    /// Reduced stiffness (N/mm, N/rad, N·mm/rad; modal rows 1/s²) and mass, dense rows.
    pub k: Vec<Vec<f64>>,
    pub m: Vec<Vec<f64>>,
    /// Frequencies of the retained fixed-interface modes, Hz.
    pub fixed_interface_frequencies_hz: Vec<f64>,
    /// Lowest frequencies of the superelement (interface held only by the model's supports) and
    /// of the full model, Hz (up to 6; absent when the interface is free, K singular: a warning
    /// when the model has supports, none for an unsupported substructure).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub superelement_frequencies_hz: Option<Vec<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub full_model_frequencies_hz: Option<Vec<f64>>,
    /// Largest relative difference of the two lists' ω².
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_relative_difference: Option<f64>,
}

fn hz(lam: &[f64]) -> Vec<f64> {
    lam.iter().map(|l| l.max(0.0).sqrt() / (2.0 * PI)).collect()
}

fn rows(m: &sprs::CsMat<f64>) -> Vec<Vec<f64>> {
    let mut d = vec![vec![0.0; m.cols()]; m.rows()];
    for (v, (i, j)) in m.iter() {
        d[i][j] = *v;
    }
    d
}

fn result(case: &CraigBamptonCase, se: &Superelement, model: &crate::fem::Model) -> CraigBamptonResult {
    let n = se.k.rows().min(6);
    let cb = se.eigenvalues(n).ok();
    let full = cb
        .as_ref()
        .and_then(|_| solve_modal(model, &ModalOptions::new(n)).ok())
        .map(|r| r.modes.iter().map(|m| m.eigenvalue).collect::<Vec<f64>>());
    let diff = cb.as_ref().zip(full.as_ref()).map(|(a, b)| {
        a.iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs() / y.abs().max(f64::MIN_POSITIVE))
            .fold(0.0, f64::max)
    });
    CraigBamptonResult {
        model: std::iter::once("Craig–Bampton (1968): boundary = every equation of the interface nodes (node frames kept), constraint modes plus mass-normalised fixed-interface modes; dense reduction".to_string())
            .chain(case.model.promotion_note())
            .collect::<Vec<_>>()
            .join("; "),
        boundary: se
            .boundary
            .iter()
            .map(|d| BoundaryDof {
                node: d.node,
                dof: d.dof.name().into(),
            })
            .collect(),
        interface_nodes: case
            .interface
            .iter()
            .map(|&node| InterfaceNode {
                node,
                x: model.nodes[node],
                frame: model.frames.get(&node).copied(),
            })
            .collect(),
        modes: case.modes,
        fixed_interface_frequencies_hz: hz(&se.fixed_interface_eigenvalues),
        superelement_frequencies_hz: cb.as_deref().map(hz),
        full_model_frequencies_hz: full.as_deref().map(hz),
        max_relative_difference: diff,
        k: rows(&se.k),
        m: rows(&se.m),
    }
}

fn report(r: &CraigBamptonResult) -> Report {
    let mut md = format!(
        "# Craig–Bampton superelement\n\n{} boundary coordinates + {} fixed-interface modes.\n\n| mode | superelement, Hz | full model, Hz |\n|---|---|---|\n",
        r.boundary.len(),
        r.modes
    );
    let mut csv = String::from("mode,superelement_hz,full_model_hz\n");
    let (a, b) = (r.superelement_frequencies_hz.clone().unwrap_or_default(), r.full_model_frequencies_hz.clone().unwrap_or_default());
    for (i, x) in a.iter().enumerate() {
        let y = b.get(i).map_or(String::new(), |v| format!("{v:.6}"));
        md += &format!("| {} | {x:.6} | {y} |\n", i + 1);
        csv += &format!("{},{x},{y}\n", i + 1);
    }
    Report { markdown: md, csv }
}

/// `craig_bampton`: the analysis kind.
pub struct CraigBamptonKind;

impl Analysis for CraigBamptonKind {
    type Case = CraigBamptonCase;
    type Result = CraigBamptonResult;

    fn report(r: &Self::Result) -> Report {
        report(r)
    }
    fn materials(case: &Self::Case) -> Vec<UsedMaterial> {
        named_materials(&case.model.materials)
    }
    fn mesh_model(case: &Self::Case) -> Option<&MeshSpec> {
        Some(&case.model)
    }

    fn check(case: &Self::Case) -> Result<(), CaseError> {
        case.build().map(|_| ())
    }
    fn run(case: &Self::Case, ctx: &mut Ctx) -> Result<Self::Result, RunError> {
        let model = case.build()?;
        let se = craig_bampton(&model, &case.interface, case.modes)
            .map_err(|e| AnalysisError::new("craig_bampton", e.to_string()))?;
        let r = result(case, &se, &model);
        // An unsupported substructure (the usual superelement for a host case) is free by design.
        if r.superelement_frequencies_hz.is_none() && !model.supports.is_empty() {
            ctx.warnings
                .push("the superelement's stiffness is singular (the interface is free): its frequencies are not computed".into());
        }
        if ctx.with_files {
            for (name, m) in [("superelement_K.mtx", &se.k), ("superelement_M.mtx", &se.m)] {
                let bytes = ReducedMatrices::matrix_market(m).map_err(|e| AnalysisError::new("matrices", e.to_string()))?;
                ctx.files.push((name.into(), bytes));
            }
        }
        Ok(r)
    }
}
