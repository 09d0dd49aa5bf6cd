//! The headline of each `static` load case: its largest von Mises stress and its largest
//! utilisation (von Mises / allowable) over every stressed element — beams and shells (their
//! recovered stresses, [`crate::fem::ElementResult::max_von_mises`]) and hinge elements (the
//! peak stress of the notch, [`super::HingeRow::peak_von_mises`], the stress model of the
//! `hinge` analysis and the `stage`) — with the element that carries each.

use super::{StaticCaseRow, StaticResult, StressAt, Utilisation};
use crate::case::mesh::BuiltHinge;
use crate::fem::{Element, Model};

/// Where a stress of a load case comes from.
#[derive(Debug, Clone, Copy)]
enum Source {
    /// `element_von_mises[i]` of the row.
    Element(usize),
    /// `hinges[k].peak_von_mises` of the row.
    Hinge(usize),
}

/// A stressed element of the model: where it is, what it is and its allowable stress (MPa,
/// ∞ without one).
#[derive(Debug, Clone, Copy)]
struct Site {
    element: usize,
    kind: &'static str,
    model_element: usize,
    allowable: f64,
    source: Source,
}

/// The stressed elements of `model`; `case_index[i]`: the model element of case element `i`
/// (as [`crate::case::mesh::MeshSpec::build_indexed`] gives it).
fn sites(model: &Model, case_index: &[Option<usize>], hinges: &[BuiltHinge]) -> Vec<Site> {
    let case_of = |ie: usize| case_index.iter().position(|m| *m == Some(ie)).unwrap_or(ie);
    let mut out: Vec<Site> = model
        .elements
        .iter()
        .enumerate()
        .filter_map(|(ie, e)| {
            let (kind, allowable) = match e {
                Element::Beam(b) => ("beam", b.material.allowable),
                Element::Shell4(s) => ("shell", s.material.allowable),
                Element::Shell9(s) => ("shell", s.material.allowable),
                _ => return None,
            };
            Some(Site {
                element: case_of(ie),
                kind,
                model_element: ie,
                allowable,
                source: Source::Element(ie),
            })
        })
        .collect();
    out.extend(hinges.iter().enumerate().map(|(k, h)| Site {
        element: h.case_element,
        kind: "hinge",
        model_element: h.element,
        allowable: h.allowable,
        source: Source::Hinge(k),
    }));
    out
}

/// Sets `max_von_mises`, `max_von_mises_at`, `max_utilisation` and `loaded_nodes` of every load
/// case of `r`, and adds to its `warnings` the elements above their allowable stress (after
/// [`super::add_hinges`]; `r.load_cases` in the order of `model.load_cases`).
pub fn add_headlines(r: &mut StaticResult, model: &Model, case_index: &[Option<usize>], hinges: &[BuiltHinge]) {
    let sites = sites(model, case_index, hinges);
    for (ic, (row, lc)) in r.load_cases.iter_mut().zip(&model.load_cases).enumerate() {
        let over = set_headline(row, &sites);
        row.warnings
            .extend(super::warnings::allowable_warning(ic, &row.name, &over));
        let mut nodes: Vec<usize> = lc
            .forces
            .iter()
            .map(|f| f.node)
            .chain(lc.displacements.iter().map(|p| p.node))
            .collect();
        nodes.sort_unstable();
        nodes.dedup();
        row.loaded_nodes = nodes;
    }
}

/// Sets the headline of one load case; returns the elements above their allowable stress,
/// worst first.
fn set_headline(row: &mut StaticCaseRow, sites: &[Site]) -> Vec<Utilisation> {
    let mut top: Option<StressAt> = None;
    let mut util: Option<Utilisation> = None;
    let mut over = Vec::new();
    for s in sites {
        let von_mises = match s.source {
            Source::Element(ie) => row.element_von_mises.get(ie).copied().flatten(),
            Source::Hinge(k) => row.hinges.get(k).map(|h| h.peak_von_mises),
        };
        let Some(von_mises) = von_mises else { continue };
        if top.is_none_or(|t| von_mises > t.von_mises) {
            top = Some(StressAt {
                element: s.element,
                kind: s.kind,
                model_element: s.model_element,
                von_mises,
            });
        }
        if s.allowable.is_finite() {
            let u = Utilisation {
                value: von_mises / s.allowable,
                element: s.element,
                kind: s.kind,
                model_element: s.model_element,
                von_mises,
                allowable: s.allowable,
            };
            if util.is_none_or(|w| u.value > w.value) {
                util = Some(u);
            }
            if u.value > 1.0 {
                over.push(u);
            }
        }
    }
    row.max_von_mises = top.map(|t| t.von_mises);
    row.max_von_mises_at = top;
    row.max_utilisation = util;
    over.sort_by(|a, b| b.value.total_cmp(&a.value));
    over
}
