//! What a model builder looks up: node indices, named sections and materials (one helper,
//! [`Named`]), and the model built so far.

use super::shapes::MeshSpec;
use crate::case::error::CaseError;
use crate::fem;
use crate::material::Material;
use std::collections::BTreeMap;

/// Validated named items of one kind (`what`: "section", "material"), looked up by name with
/// an error naming the JSON path, the name given and the names defined.
pub struct Named<'a, V> {
    what: &'static str,
    items: BTreeMap<&'a str, V>,
}

impl<'a, V> Named<'a, V> {
    /// Validates every item of `specs` (named `FIELD.KEY` in errors) by `validate`.
    pub fn validate<S>(
        what: &'static str,
        field: &str,
        specs: &'a BTreeMap<String, S>,
        mut validate: impl FnMut(&S, &str) -> Result<V, CaseError>,
    ) -> Result<Self, CaseError> {
        let mut items = BTreeMap::new();
        for (k, s) in specs {
            items.insert(k.as_str(), validate(s, &format!("{field}.{k}"))?);
        }
        Ok(Named { what, items })
    }

    /// The item called `name`, referenced at `path`.
    pub fn get(&self, path: &str, name: &str) -> Result<&V, CaseError> {
        self.items.get(name).ok_or_else(|| {
            CaseError::value(
                path,
                format!("\"{name}\""),
                format!("unknown {}; defined: {}", self.what, self.defined()),
            )
        })
    }

    fn defined(&self) -> String {
        if self.items.is_empty() {
            "none".into()
        } else {
            self.items
                .keys()
                .map(|k| format!("\"{k}\""))
                .collect::<Vec<_>>()
                .join(", ")
        }
    }
}

/// A validated section: for beams, or the thickness of a shell.
#[derive(Debug, Clone, Copy)]
pub(super) enum BuiltSection {
    Beam(fem::Section),
    Shell(f64),
}

/// A hinge element of a built model: where it is and its hinge (for the per-hinge results).
#[derive(Debug, Clone)]
pub struct BuiltHinge {
    /// Index of the element in the case's `elements`.
    pub case_element: usize,
    /// Index of the element in the FE model (model order, as `element_von_mises`); with
    /// `segments` > 1 the first segment of the chain.
    pub element: usize,
    /// The last segment of the chain (`element` for a hinge of one segment); the inner
    /// segments are appended to the model after the case's own elements.
    pub last: usize,
    /// Co-rotational segments the hinge is made of.
    pub segments: usize,
    /// The inner nodes of its segments (after every node of the case; empty for one segment).
    pub inner_nodes: std::ops::Range<usize>,
    /// Whether `segments` is the nonlinear default ([`crate::hinge::NONLINEAR_SEGMENTS`], the
    /// case giving none) rather than the case's.
    pub default_segments: bool,
    /// Its material.
    pub material: Material,
    /// Its hinge region: compliance and stress model, as in the `hinge` analysis.
    pub region: crate::hinge::HingeRegion,
    /// Allowable stress of its material, MPa (∞ when the material has none).
    pub allowable: f64,
}

impl BuiltHinge {
    /// The hinge's end nodes in `model`: the first segment's first node and the last segment's
    /// second node (`None` when those elements are no hinge elements).
    pub fn end_nodes(&self, model: &fem::Model) -> Option<[usize; 2]> {
        match (model.elements.get(self.element)?, model.elements.get(self.last)?) {
            (fem::Element::Flex(f), fem::Element::Flex(g)) => Some([f.nodes[0], g.nodes[1]]),
            _ => None,
        }
    }
}

/// A model being built: the validated named items, the model so far and what each case element
/// became.
pub(super) struct Ctx<'a> {
    pub spec: &'a MeshSpec,
    pub materials: Named<'a, Material>,
    pub sections: Named<'a, BuiltSection>,
    pub model: fem::Model,
    /// The JSON path that gave each framed node its frame.
    pub frame_owner: BTreeMap<usize, String>,
    /// Model element index of each case element (masses and rigid links are no elements).
    pub model_index: Vec<Option<usize>>,
    /// The hinge elements built so far (side table: `fem` knows no hinges).
    pub hinges: Vec<BuiltHinge>,
    /// Whether the model is for a geometrically nonlinear run (hinge elements then default to
    /// [`crate::hinge::NONLINEAR_SEGMENTS`] segments).
    pub nonlinear: bool,
    /// The JSON path of the element that made each model tie (`model.ties` order).
    pub tie_paths: Vec<String>,
    /// The hinge regions integrated so far, by hinge spec, material and node distance (mm).
    pub regions: Vec<(crate::hinge::HingeSpec, Material, f64, crate::hinge::HingeRegion)>,
    /// The hinge specs read so far, by the element's `hinge` object (read successfully).
    pub specs: Vec<(serde_json::Value, crate::hinge::HingeSpec)>,
}

impl Ctx<'_> {
    /// Two different nodes of a two-node element, checked.
    pub fn two_nodes(&self, p: &str, nodes: [usize; 2], what: &str) -> Result<(usize, usize), CaseError> {
        let a = self.node(format!("{p}.nodes[0]"), nodes[0])?;
        let b = self.node(format!("{p}.nodes[1]"), nodes[1])?;
        if a == b {
            return Err(CaseError::value(
                format!("{p}.nodes"),
                format!("[{a}, {b}]"),
                format!("a {what} needs two different nodes"),
            ));
        }
        Ok((a, b))
    }

    /// The axis a→b of a two-node element with orientation vector `up`, checked: its length.
    pub fn axis_and_up(&self, p: &str, (a, b): (usize, usize), up: [f64; 3], what: &str) -> Result<f64, CaseError> {
        let (xa, xb) = (self.spec.nodes[a], self.spec.nodes[b]);
        let axis = [xb[0] - xa[0], xb[1] - xa[1], xb[2] - xa[2]];
        let len = norm(axis);
        if len <= 1e-12 {
            return Err(CaseError::value(
                format!("{p}.nodes"),
                format!("[{a}, {b}]"),
                format!("the two nodes coincide (zero-length {what})"),
            ));
        }
        let un = norm(up);
        let cross = norm([
            axis[1] * up[2] - axis[2] * up[1],
            axis[2] * up[0] - axis[0] * up[2],
            axis[0] * up[1] - axis[1] * up[0],
        ]);
        if !(un.is_finite() && un > 0.0 && cross > 1e-6 * len * un) {
            return Err(CaseError::value(
                format!("{p}.up"),
                format!("{up:?}"),
                format!("must be a non-zero vector not parallel to the {what} axis"),
            ));
        }
        Ok(len)
    }

    /// Checks a node index given at `path`.
    pub fn node(&self, path: String, i: usize) -> Result<usize, CaseError> {
        let n = self.spec.nodes.len();
        if i < n {
            Ok(i)
        } else {
            Err(CaseError::value(
                path,
                i,
                format!("node index must be < {n} (the number of nodes)"),
            ))
        }
    }
}

pub(super) fn norm(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

/// The unit vector along the direction `v` given at `path`, refusing a zero or non-finite one.
pub(super) fn unit_direction(path: String, v: [f64; 3]) -> Result<[f64; 3], CaseError> {
    let n = norm(v);
    if !(n.is_finite() && n > 0.0) {
        return Err(CaseError::value(
            path,
            format!("{v:?}"),
            "must be a non-zero direction [x, y, z]",
        ));
    }
    Ok(v.map(|c| c / n))
}
