//! The numbers of a parsed mesh model at the JSON paths a case file gives them, for batch
//! drivers that set each design's numbers in a parsed model instead of parsing the design
//! (a sweep over a parameterised case: [`crate::case::params::compiled`]).
//!
//! Only the places parameters usually drive are reached: node coordinates, the numbers of a
//! hinge element's `hinge`, beam and hinge `up` vectors, spring stiffnesses, point masses and
//! the components of nodal forces. Any other path is `None`, and the caller parses the design.

use super::shapes::{ElementSpec, MeshSpec};
use crate::case::params::template::Step;
use serde_json::Value;

/// A number of the parsed model.
#[derive(Debug)]
pub enum NumberSlot<'m> {
    /// A number field.
    Number(&'m mut f64),
    /// A number inside a field kept as JSON (a hinge element's `hinge`, parsed when built).
    Json(&'m mut Value),
}

impl NumberSlot<'_> {
    /// Sets the slot to the JSON number `x` as the parse of a case holding `x` would.
    pub fn set(self, x: &Value) -> Option<()> {
        match self {
            NumberSlot::Number(f) => *f = x.as_f64()?,
            NumberSlot::Json(v) => *v = x.clone(),
        }
        Some(())
    }
}

fn key(s: &Step) -> Option<&str> {
    match s {
        Step::Key(k) => Some(k),
        Step::Index(_) => None,
    }
}

fn index(s: &Step) -> Option<usize> {
    match s {
        Step::Index(i) => Some(*i),
        Step::Key(_) => None,
    }
}

impl MeshSpec {
    /// The number at `path` (from the model's root: `nodes[3][2]`, `elements[0].hinge.t`,
    /// `load_cases[0].forces[1].F[4]`), `None` where the path leads elsewhere.
    pub fn number_slot(&mut self, path: &[Step]) -> Option<NumberSlot<'_>> {
        let (first, rest) = path.split_first()?;
        match (key(first)?, rest) {
            ("nodes", [n, j]) => self
                .nodes
                .get_mut(index(n)?)?
                .get_mut(index(j)?)
                .map(NumberSlot::Number),
            ("elements", [e, rest @ ..]) => element_slot(self.elements.get_mut(index(e)?)?, rest),
            ("load_cases", [c, f, i, field, j]) if key(f)? == "forces" && key(field)? == "F" => self
                .load_cases
                .get_mut(index(c)?)?
                .forces
                .get_mut(index(i)?)?
                .f
                .get_mut(index(j)?)
                .map(NumberSlot::Number),
            _ => None,
        }
    }
}

fn element_slot<'m>(e: &'m mut ElementSpec, path: &[Step]) -> Option<NumberSlot<'m>> {
    let (first, rest) = path.split_first()?;
    let field = key(first)?;
    let one = |v: &'m mut [f64], rest: &[Step]| match rest {
        [j] => v.get_mut(index(j)?).map(NumberSlot::Number),
        _ => None,
    };
    match (e, field) {
        (ElementSpec::Hinge { hinge, .. }, "hinge") => json_slot(hinge, rest),
        (ElementSpec::Hinge { up, .. } | ElementSpec::Beam { up, .. }, "up") => one(up, rest),
        (ElementSpec::Spring { k, .. }, "k") => one(k, rest),
        (ElementSpec::Mass { mass, .. }, "mass") if rest.is_empty() => Some(NumberSlot::Number(mass)),
        (ElementSpec::Mass { inertia, .. }, "inertia") => one(inertia, rest),
        _ => None,
    }
}

/// The number at `path` inside a JSON value.
fn json_slot<'m>(v: &'m mut Value, path: &[Step]) -> Option<NumberSlot<'m>> {
    let mut cur = v;
    for s in path {
        cur = match (s, cur) {
            (Step::Key(k), Value::Object(m)) => m.get_mut(k.as_str())?,
            (Step::Index(i), Value::Array(a)) => a.get_mut(*i)?,
            _ => return None,
        };
    }
    cur.is_number().then_some(NumberSlot::Json(cur))
}
