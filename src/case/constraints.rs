//! The `constraints` case: the exact-constraint check of a mesh model (as in `static`/`modal`
//! cases; load cases optional, their prescribed DOFs count as drives).

use super::error::CaseError;
use super::fem_case::{model_rules, read_model, split, MODEL_FIELDS};
use super::gmsh::GmshMapping;
use super::mesh::{ElementSpec, MeshSpec};
use super::from_value;
use serde::Deserialize;
use serde_json::Value;
use std::path::Path;

/// `"analysis": "constraints"`: over- and under-constraint of a model whose bodies are taken
/// rigid. A body is a set of nodes joined by beam, hinge, shell4 or rigid elements (and
/// rigid links); `joint` elements, supports and prescribed displacements constrain the bodies;
/// springs, masses and the elements listed in `compliant` join nothing.
#[derive(Debug, Clone, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(extend("allOf" = model_rules(false)))]
pub struct ConstraintsCase {
    /// Free text saying what the model is (not used by the analysis).
    pub description: Option<String>,
    /// Mesh file, as for `static`: a JSON mesh file or a Gmsh `.msh` file.
    pub mesh: Option<String>,
    /// Physical-group mapping of a Gmsh `.msh` mesh (only with a `.msh` mesh, which needs it).
    pub gmsh: Option<GmshMapping>,
    /// Indices into `elements` of beam, hinge or shell4 elements taken as compliant: they join
    /// nothing, so their nodes may belong to different bodies (default none).
    #[serde(default)]
    pub compliant: Vec<usize>,
    /// Hinge elements as `"rigid"` (default: they join their nodes into one body) or as
    /// `"revolute"`: an ideal revolute joint about the hinge's compliant axis (local y) at its
    /// midpoint, between the bodies of its two nodes (the pseudo-rigid-body view of a notch
    /// flexure).
    #[serde(default)]
    pub hinges: HingeView,
    /// Prescribed displacements of the load cases count as constraints (drives, default true);
    /// a DOF prescribed in several load cases counts once.
    #[serde(default = "yes")]
    pub drives: bool,
    /// The model.
    #[serde(flatten)]
    pub model: MeshSpec,
}

/// How the check sees hinge elements.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum HingeView {
    /// A rigid part of the body.
    #[default]
    Rigid,
    /// An ideal revolute joint about the compliant axis (local y) at the midpoint.
    Revolute,
}

fn yes() -> bool {
    true
}

/// The options of a `constraints` case besides its model.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
struct Options {
    #[serde(default)]
    description: Option<String>,
    #[serde(default)]
    mesh: Option<String>,
    #[serde(default)]
    gmsh: Option<GmshMapping>,
    #[serde(default)]
    compliant: Vec<usize>,
    #[serde(default)]
    hinges: HingeView,
    #[serde(default = "yes")]
    drives: bool,
}

const OWN: [&str; 7] = ["analysis", "description", "mesh", "gmsh", "compliant", "hinges", "drives"];

/// Parses a `constraints` case; files it names resolve against `base` first.
pub fn parse(value: Value, base: Option<&Path>) -> Result<ConstraintsCase, CaseError> {
    if let Some(key) = value
        .as_object()
        .and_then(|m| m.keys().find(|k| !OWN.contains(&k.as_str()) && !MODEL_FIELDS.contains(&k.as_str())))
    {
        let expected: Vec<String> = OWN.iter().chain(MODEL_FIELDS.iter()).map(|f| format!("`{f}`")).collect();
        return Err(CaseError::new(
            key.clone(),
            format!("unknown field `{key}` in a `constraints` case, expected one of {}", expected.join(", ")),
        ));
    }
    let (options, model) = split(value, &OWN);
    let o: Options = from_value(options, "")?;
    let model = read_model(model, o.mesh.as_deref(), o.gmsh.as_ref(), base)?;
    let case = ConstraintsCase {
        description: o.description,
        mesh: o.mesh,
        gmsh: o.gmsh,
        compliant: o.compliant,
        hinges: o.hinges,
        drives: o.drives,
        model,
    };
    case.check_compliant()?;
    Ok(case)
}

impl ConstraintsCase {
    /// Each `compliant` entry names a beam, hinge or shell4 element.
    pub fn check_compliant(&self) -> Result<(), CaseError> {
        let n = self.model.elements.len();
        for (i, &e) in self.compliant.iter().enumerate() {
            let p = format!("compliant[{i}]");
            match self.model.elements.get(e) {
                None => {
                    return Err(CaseError::value(
                        p,
                        e,
                        format!("no such element: the model has {n} elements (indices 0 … {})", n.max(1) - 1),
                    ))
                }
                Some(ElementSpec::Beam { .. } | ElementSpec::Hinge { .. } | ElementSpec::Shell4 { .. }) => {}
                Some(_) => {
                    return Err(CaseError::value(
                        p,
                        e,
                        "only beam, hinge and shell4 elements can be taken as compliant (springs and masses join nothing anyway; joints and rigid links are the constraints)",
                    ))
                }
            }
        }
        Ok(())
    }
}
