//! `model.svg` of a `static` run: the load case of `output.picture` (default the first) drawn
//! deformed over the undeformed ghost, its hinges coloured by the utilisation the result lists
//! (`load_cases[i].hinges[j].utilisation`).

use super::StaticResult;
use crate::analysis::common::picture::{self, HingeMark, Scene};
use crate::analysis::AnalysisError;
use crate::case::mesh::{BuiltHinge, PictureRequest};
use crate::fem::{self, Model};

/// The hinge marks of load case `ic`: one per hinge element of the case (from its first
/// segment's first node to its last segment's second node), labelled `element N` with N the
/// case's element index, as in `load_cases[i].hinges[j].element`.
pub fn hinge_marks(model: &Model, r: &StaticResult, ic: usize, hinges: &[BuiltHinge]) -> Vec<HingeMark> {
    let Some(row) = r.load_cases.get(ic) else {
        return Vec::new();
    };
    row.hinges
        .iter()
        .filter_map(|h| {
            let b = hinges.iter().find(|b| b.case_element == h.element)?;
            Some(HingeMark {
                label: format!("element {}", h.element),
                nodes: b.end_nodes(model)?,
                utilisation: b.allowable.is_finite().then_some(h.utilisation),
            })
        })
        .collect()
}

/// `("model.svg", bytes)` of a static run (see the module docs).
pub fn file(
    model: &Model,
    raw: &fem::StaticResults,
    r: &StaticResult,
    hinges: &[BuiltHinge],
    req: &PictureRequest,
) -> Result<(String, Vec<u8>), AnalysisError> {
    let ic = match &req.load_case {
        Some(name) => r
            .load_cases
            .iter()
            .position(|c| &c.name == name)
            .ok_or_else(|| AnalysisError::new("output.picture.load_case", format!("no load case \"{name}\"")))?,
        None => 0,
    };
    let case = raw.load_cases.get(ic);
    let name = r.load_cases.get(ic).map_or(String::new(), |c| c.name.clone());
    let scene = Scene {
        model,
        displacements: case.map(|c| c.displacements.as_slice()),
        marks: hinge_marks(model, r, ic, hinges),
        drawn: &Default::default(),
        load_case: model.load_cases.iter().find(|c| c.name == name),
        title: "flexfem static: the model".to_string(),
        what: format!("load case \"{name}\""),
        name,
        mode: false,
    };
    Ok(("model.svg".to_string(), picture::render(&scene, req).into_bytes()))
}
