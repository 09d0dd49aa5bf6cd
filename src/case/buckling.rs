//! `buckling` cases: a model as for `static` (inline or from a mesh file, hinges and joints
//! included) with exactly one load case, the reference load, and the number of buckling modes.

use super::error::CaseError;
use super::fem_case::{read_model, split};
use super::gmsh::GmshMapping;
use super::mesh::MeshSpec;
use super::from_value;
use serde::Deserialize;
use serde_json::Value;
use std::path::Path;

/// `"analysis": "buckling"`: the `modes` smallest load multipliers λ (by magnitude) of the
/// reference load (the case's one `load_cases` entry) at which the linear structure bifurcates,
/// (K + λ K_G) φ = 0, with their mode shapes. λ < 0: buckling under the reversed load.
#[derive(Debug, Clone, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct BucklingCase {
    /// Free text saying what the model is (not used by the analysis).
    pub description: Option<String>,
    /// Mesh file, as for `static`: a JSON mesh file or a Gmsh `.msh` file.
    pub mesh: Option<String>,
    /// Physical-group mapping of a Gmsh `.msh` mesh (only with a `.msh` mesh, which needs it).
    pub gmsh: Option<GmshMapping>,
    /// Number of buckling modes (smallest |λ|), 1 … 1000.
    #[schemars(range(min = 1, max = 1000))]
    pub modes: usize,
    /// Mode shapes in the JSON result (default true); `buckling_modes.vtu` (with `--out`)
    /// always holds them.
    #[serde(default = "shapes_default")]
    pub shapes: bool,
    /// The model; its `load_cases` holds exactly one entry, the reference load.
    #[serde(flatten)]
    pub model: MeshSpec,
}

fn shapes_default() -> bool {
    true
}

/// The options of a `buckling` case besides its model, as in the case file.
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
    modes: Option<usize>,
    #[serde(default)]
    shapes: Option<bool>,
}

const OWN: [&str; 6] = ["analysis", "description", "mesh", "gmsh", "modes", "shapes"];

/// Parses a `buckling` case; files it names resolve against `base` first.
pub fn parse_buckling(value: Value, base: Option<&Path>) -> Result<BucklingCase, CaseError> {
    if let Some(k) = ["nonlinear", "steps", "shift_hz", "compliance", "output"]
        .iter()
        .find(|k| value.get(**k).is_some())
    {
        return Err(CaseError::new(
            *k,
            format!("a buckling case does not take `{k}` (it takes {}, and the model's fields)", OWN[1..].join(", ")),
        ));
    }
    let (options, model) = split(value, &OWN);
    let o: Options = from_value(options, "")?;
    let modes = match o.modes {
        Some(k) if (1..=1000).contains(&k) => k,
        Some(k) => return Err(CaseError::value("modes", k, "must be an integer from 1 to 1000")),
        None => {
            return Err(CaseError::new(
                "modes",
                "missing field `modes` (number of buckling modes wanted)",
            ))
        }
    };
    let model = read_model(model, o.mesh.as_deref(), o.gmsh.as_ref(), base)?;
    match model.load_cases.len() {
        1 => {}
        0 => {
            return Err(CaseError::new(
                "load_cases",
                "a buckling case needs one load case, the reference load (its multipliers λ are the results)",
            ))
        }
        n => {
            return Err(CaseError::value(
                "load_cases",
                format!("{n} load cases"),
                "a buckling case takes exactly one load case (the reference load); run one case per load",
            ))
        }
    }
    Ok(BucklingCase {
        description: o.description,
        mesh: o.mesh,
        gmsh: o.gmsh,
        modes,
        shapes: o.shapes.unwrap_or(true),
        model,
    })
}
