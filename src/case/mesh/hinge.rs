//! The `hinge` element of mesh cases: a flexure hinge between two nodes as one flexibility
//! element carrying the compliance of the `hinge` analysis, plus its mass.

pub use super::lookup::BuiltHinge;
use super::lookup::Ctx;
use super::shapes::ElementSpec;
use crate::case::error::CaseError;
use crate::case::hinge::hinge_error;
use crate::fem;
use crate::hinge::{self, HingeSpec};
use serde_json::Value;

/// Builds a `hinge` element at JSON path `p` (case element `case_element`).
///
/// One [`fem::FlexElement`] from node a to node b: its compliance is exactly that of the
/// `hinge` analysis for the same hinge with `blank_length` = (node distance − notch length)/2
/// (blank per side), so the solid-calibrated model (load spreading, short-notch and
/// plane-strain factors, warping-restrained torsion) comes with it. One element rather than
/// blank beam + notch + blank beam: the compliance between the two end faces is what the hinge
/// analysis computes, and it is reproduced with no internal nodes (the flexibility element is
/// co-rotational in the nonlinear solver, as the stage's hinges). Mass: the geometric volume of
/// notch and blank times the density, lumped on the nodes with rotary inertia
/// ([`chain_masses`]).
///
/// With `segments` ([`set_segments`]; 1 … 64; default 1, or [`hinge::NONLINEAR_SEGMENTS`] in a
/// geometrically nonlinear run, where one co-rotational element loses the shortening along the
/// bent notch) the element is split into a chain of that many
/// co-rotational flexibility elements over equal lengths ([`hinge::split_flex`], as the
/// stage's nonlinear solve), once every case element is built, so the inner nodes and
/// elements come after the case's own.
pub(super) fn hinge_element(
    cx: &mut Ctx,
    p: &str,
    nodes: [usize; 2],
    hinge: &Value,
    material: &str,
    up: [f64; 3],
    case_element: usize,
) -> Result<(), CaseError> {
    let (a, b) = cx.two_nodes(p, nodes, "hinge")?;
    let mat = *cx.materials.get(&format!("{p}.material"), material)?;
    let len = cx.axis_and_up(p, (a, b), up, "hinge")?;
    let hp = format!("{p}.hinge");
    // Hinges of one `hinge_types` entry hold equal objects: each is read once per model.
    let spec = match cx.specs.iter().find(|(v, _)| v == hinge) {
        Some(&(_, spec)) => spec,
        None => {
            let spec = parse_spec(&hp, hinge)?;
            cx.specs.push((hinge.clone(), spec));
            spec
        }
    };
    let herr = |e: hinge::HingeError| hinge_error(&e, &hp, &format!("materials.{material}"));
    let notch = spec.profile_with_blank(Some(0.0)).map_err(herr)?;
    let notch_len = 2.0 * notch.half_notch;
    if len < notch_len * (1.0 - 1e-12) {
        return Err(CaseError::value(
            format!("{p}.nodes"),
            format!("[{a}, {b}]"),
            format!("the node distance {len} mm is shorter than the notch length {notch_len} mm of the hinge"),
        ));
    }
    let length = len.max(notch_len);
    // Identical hinges (one `hinge_types` entry at equal node distances) are integrated once,
    // and once per thread for designs of a sweep that repeat them ([`super::hinge_memo`]).
    let same = |(s, m, l, _): &&(HingeSpec, crate::material::Material, f64, hinge::HingeRegion)| {
        *s == spec && *m == mat && *l == length
    };
    let region = match cx.regions.iter().find(same) {
        Some((.., r)) => r.clone(),
        None => {
            let r = super::hinge_memo::region(&spec, &mat, length).map_err(herr)?;
            cx.regions.push((spec, mat, length, r.clone()));
            r
        }
    };
    let element = cx.model.add_element(fem::Element::Flex(fem::FlexElement {
        nodes: [a, b],
        compliance: region.compliance(),
        up,
    }));
    cx.hinges.push(BuiltHinge {
        case_element,
        element,
        last: element,
        inner_nodes: 0..0,
        segments: if cx.nonlinear { hinge::NONLINEAR_SEGMENTS } else { 1 },
        default_segments: cx.nonlinear,
        material: mat,
        region,
        allowable: mat.allowable,
    });
    // The mass is lumped on the chain's nodes once the hinge is split ([`chain_masses`]).
    Ok(())
}

/// Lumps the mass of a hinge element (density × geometric volume, tonne) on its chain `nodes`
/// (end node a, the inner nodes of its segments, end node b, equally spaced): each node takes
/// the mass of its share of the length (half a segment at an end, a whole segment inside) and
/// that share's rotary inertia about the node, as a box of the blank's cross-section b₁ × b₂
/// (w × h; h × h for a neck) and length ℓ along the axis (the rectangular prism of J. L. Meriam,
/// L. G. Kraige, Engineering Mechanics: Dynamics, Appendix D, Table D/4, with the parallel-axis
/// theorem for the end nodes):
///
/// ```text
/// about the axis        m (b₁² + b₂²)/12
/// about a transverse    m (ℓ²/12 + (b₁² + b₂²)/24)   inner node (share centred on it)
///                       m (ℓ²/3 + (b₁² + b₂²)/24)    end node (share of length ℓ beside it)
/// ```
/// (the two transverse inertias averaged). Point masses take rotary inertia about the global
/// axes, so the node's inertia tensor I = I_t 𝟙 + (I_a − I_t) e eᵀ (e the hinge axis) is given
/// by its diagonal: exact for hinges along a global axis; an oblique hinge loses the products
/// of inertia (I_a − I_t) eᵢ eⱼ. Without rotary inertia the inner nodes' rotations were
/// massless and the mass matrix singular.
pub(super) fn chain_masses(model: &mut fem::Model, nodes: &[usize], region: &hinge::HingeRegion, density: f64) {
    let (Some(&a), Some(&b)) = (nodes.first(), nodes.last()) else {
        return;
    };
    let (xa, xb) = (model.nodes[a], model.nodes[b]);
    let axis: [f64; 3] = std::array::from_fn(|i| xb[i] - xa[i]);
    let len = axis.iter().map(|v| v * v).sum::<f64>().sqrt();
    if nodes.len() < 2 || len <= 0.0 {
        return;
    }
    let e = axis.map(|v| v / len);
    let p = &region.profile;
    let (b1, b2) = if region.is_neck() { (p.h, p.h) } else { (p.w, p.h) };
    let section = b1 * b1 + b2 * b2;
    let segments = (nodes.len() - 1) as f64;
    let (mass, seg) = (density * super::hinge_memo::volume(region), len / segments);
    for (k, &node) in nodes.iter().enumerate() {
        let end = k == 0 || k + 1 == nodes.len();
        let (m, i_t) = if end {
            let m = mass / segments / 2.0;
            (m, m * ((seg / 2.0).powi(2) / 3.0 + section / 24.0))
        } else {
            let m = mass / segments;
            (m, m * (seg * seg / 12.0 + section / 24.0))
        };
        let i_a = m * section / 12.0;
        model.masses.push(fem::PointMass {
            node,
            mass: m,
            inertia: e.map(|ei| i_t + (i_a - i_t) * ei * ei),
        });
    }
}

/// Makes the hinge element just built at JSON path `p` a chain of `segments` (1 … 64)
/// co-rotational elements (split once every case element is built).
pub(super) fn set_segments(cx: &mut Ctx, p: &str, segments: usize) -> Result<(), CaseError> {
    if !(1..=64).contains(&segments) {
        return Err(CaseError::value(
            format!("{p}.segments"),
            segments,
            "must be an integer from 1 to 64",
        ));
    }
    if let Some(h) = cx.hinges.last_mut() {
        h.segments = segments;
        h.default_segments = false;
    }
    Ok(())
}

/// The hinge spec of an element (its `blank_length` comes from the node distance).
fn parse_spec(hp: &str, hinge: &Value) -> Result<HingeSpec, CaseError> {
    let mut v = hinge.clone();
    let Value::Object(map) = &mut v else {
        return Err(CaseError::value(
            hp,
            crate::case::short(hinge),
            "must be a hinge object {\"type\": …}",
        ));
    };
    if map.contains_key("blank_length") {
        return Err(CaseError::new(
            format!("{hp}.blank_length"),
            "a hinge element takes no blank_length: the blank fills the node distance beyond the notch",
        ));
    }
    map.insert("blank_length".into(), Value::from(0.0));
    crate::case::from_value(v, hp)
}

/// Schema of a hinge element's `hinge`: that of the `hinge` analysis without `blank_length`.
pub fn element_hinge_schema(_: &mut schemars::SchemaGenerator) -> schemars::Schema {
    let mut v = schemars::schema_for!(HingeSpec).to_value();
    strip_blank(&mut v);
    if let Value::Object(m) = &mut v {
        m.remove("$schema");
        m.remove("title");
    }
    schemars::Schema::try_from(v).unwrap_or_default()
}

fn strip_blank(v: &mut Value) {
    match v {
        Value::Object(m) => {
            if let Some(Value::Object(props)) = m.get_mut("properties") {
                props.remove("blank_length");
            }
            if let Some(Value::Array(req)) = m.get_mut("required") {
                req.retain(|r| r != "blank_length");
            }
            m.values_mut().for_each(strip_blank);
        }
        Value::Array(a) => a.iter_mut().for_each(strip_blank),
        _ => {}
    }
}

impl super::shapes::MeshSpec {
    /// The calibration warnings of the model's `hinge` elements
    /// ([`hinge::calibration::calibration_warnings`]: geometry outside the solid-calibrated
    /// ranges, or inside them in a regime with a known bias), each distinct warning once, naming
    /// every element it applies to (`elements[i].hinge`, then the others alike; in a mesh file,
    /// `mesh: in mesh file "F" at `elements[i].hinge``, as errors there are; the `hinge_types`
    /// names they were given by, if any: `(hinge type "flex"; likewise elements 1–7)`, or
    /// `(likewise elements 1; hinge type "thick" on element 1)` when not all were); past
    /// [`MAX_HINGE_WARNINGS`] distinct warnings, one more line counts the rest and names their
    /// elements. A mechanism's hinge element has continuous material at its ends, so the `hinge`
    /// analysis's warnings of its blank and rigid end faces do not apply. Elements that do not
    /// build (a malformed hinge) give none: building the model reports them. Linear in the
    /// number of elements (each distinct hinge object is checked once).
    pub fn hinge_warnings(&self) -> Vec<String> {
        use std::collections::HashMap;
        let mut found: Vec<(String, Vec<usize>)> = Vec::new();
        let mut found_at: HashMap<String, usize> = HashMap::new();
        // Hinges of one `hinge_types` entry are checked once: an element's object equal to the
        // previous hinge element's is not serialised; others are looked up by their text.
        let mut checked: HashMap<String, Vec<String>> = HashMap::new();
        let mut last: Option<(&Value, String)> = None;
        for (ie, e) in self.elements.iter().enumerate() {
            let ElementSpec::Hinge { hinge, .. } = e else {
                continue;
            };
            let key = match &last {
                Some((v, key)) if *v == hinge => key.clone(),
                _ => hinge.to_string(),
            };
            let warnings = checked.entry(key.clone()).or_insert_with(|| element_calibration(hinge));
            last = Some((hinge, key));
            for w in warnings.iter() {
                match found_at.get(w) {
                    Some(&i) => found[i].1.push(ie),
                    None => {
                        found_at.insert(w.clone(), found.len());
                        found.push((w.clone(), vec![ie]));
                    }
                }
            }
        }
        // In a mesh file, named as errors in it are: `mesh: in mesh file "F" at `PATH` ...`.
        let in_file = self.mesh_file.as_ref().map(|f| format!("mesh: in mesh file \"{f}\""));
        let path = |first: &usize| match &in_file {
            Some(file) => format!("{file} at `elements[{first}].hinge`"),
            None => format!("elements[{first}].hinge"),
        };
        let mut out: Vec<String> = found
            .iter()
            .take(MAX_HINGE_WARNINGS)
            .map(|(w, elements)| {
                let Some((first, rest)) = elements.split_first() else {
                    return w.clone();
                };
                // One type for all first, else after the elements: which element has which.
                let (all_one_type, mut by_type) = self.type_names_of(elements);
                let mut notes = if all_one_type {
                    std::mem::take(&mut by_type)
                } else {
                    Vec::new()
                };
                if !rest.is_empty() {
                    notes.push(format!("likewise elements {}", index_runs(rest)));
                }
                notes.append(&mut by_type);
                let notes = match notes.is_empty() {
                    true => String::new(),
                    false => format!(" ({})", notes.join("; ")),
                };
                format!("{}{notes}: {w}", path(first))
            })
            .collect();
        if found.len() > MAX_HINGE_WARNINGS {
            let mut rest: Vec<usize> = found[MAX_HINGE_WARNINGS..]
                .iter()
                .flat_map(|(_, elements)| elements.iter().copied())
                .collect();
            rest.sort_unstable();
            rest.dedup();
            let of = match &in_file {
                Some(file) => format!("{file}, hinge elements"),
                None => "hinge elements".to_string(),
            };
            out.push(format!(
                "{of}: {} more calibration warnings, not listed, on elements {}",
                found.len() - MAX_HINGE_WARNINGS,
                index_runs(&rest)
            ));
        }
        out
    }

    /// The `hinge_types` names that `elements` were given by: `(true, ["hinge type \"NAME\""])`
    /// when every one of them was given by that one name; else `(false, [note])` naming, per
    /// name in order of first use, the elements given by it (`hinge type "a" on elements 0–3,
    /// "b" on element 4`), at most [`MAX_TYPE_NAMES`] names and then how many more; `(false,
    /// [])` when none was.
    fn type_names_of(&self, elements: &[usize]) -> (bool, Vec<String>) {
        use std::collections::HashMap;
        let mut order: Vec<(&str, Vec<usize>)> = Vec::new();
        let mut at: HashMap<&str, usize> = HashMap::new();
        for &i in elements {
            let Some(n) = self.hinge_type_names.get(&i) else {
                continue;
            };
            match at.get(n.as_str()) {
                Some(&k) => order[k].1.push(i),
                None => {
                    at.insert(n, order.len());
                    order.push((n, vec![i]));
                }
            }
        }
        match order.as_slice() {
            [] => (false, Vec::new()),
            [(n, given)] if given.len() == elements.len() => (true, vec![format!("hinge type \"{n}\"")]),
            _ => {
                let mut named: Vec<String> = order
                    .iter()
                    .take(MAX_TYPE_NAMES)
                    .map(|(n, given)| match given.as_slice() {
                        [one] => format!("\"{n}\" on element {one}"),
                        _ => format!("\"{n}\" on elements {}", index_runs(given)),
                    })
                    .collect();
                if order.len() > MAX_TYPE_NAMES {
                    named.push(format!("{} more", order.len() - MAX_TYPE_NAMES));
                }
                (false, vec![format!("hinge type {}", named.join(", "))])
            }
        }
    }
}

/// Hinge-type names one warning line lists (the rest are counted).
pub const MAX_TYPE_NAMES: usize = 3;

/// Ascending indices as a list with runs of three or more as `a–b`: `[1, 2, 3, 5]` → `1–3, 5`.
fn index_runs(indices: &[usize]) -> String {
    let mut out: Vec<String> = Vec::new();
    let mut i = 0;
    while i < indices.len() {
        let mut j = i;
        while j + 1 < indices.len() && indices[j + 1] == indices[j] + 1 {
            j += 1;
        }
        if j >= i + 2 {
            out.push(format!("{}–{}", indices[i], indices[j]));
        } else {
            out.extend(indices[i..=j].iter().map(usize::to_string));
        }
        i = j + 1;
    }
    out.join(", ")
}

/// Distinct calibration warnings [`super::shapes::MeshSpec::hinge_warnings`] lists one by one
/// (a model of many different hinges, each a little outside a range, would otherwise list one
/// per hinge).
pub const MAX_HINGE_WARNINGS: usize = 20;

/// [`hinge::calibration::calibration_warnings`] of a hinge element's `hinge` object; none if it
/// does not parse. They depend on the notch and the blank's section, not on the blank's length
/// (which the node distance sets), so the notch alone is checked.
fn element_calibration(hinge: &Value) -> Vec<String> {
    // As [`parse_spec`], without its JSON-path tracking: an error here is the builder's to report.
    let mut v = hinge.clone();
    if let Value::Object(map) = &mut v {
        map.entry("blank_length").or_insert(Value::from(0.0));
    }
    match serde_json::from_value::<HingeSpec>(v).map(|spec| spec.profile_with_blank(Some(0.0))) {
        Ok(Ok(p)) => hinge::calibration::calibration_warnings(&p),
        _ => Vec::new(),
    }
}
