//! A parameterised case compiled once for many parameter values (a sweep's designs): the
//! declarations of the case and its mesh file merged, the hinge types expanded and every
//! expression site parsed, as [`super::resolve_case_in`] does for one case. A design then only
//! resolves its parameter table and evaluates the sites; where the sites' numbers go in a parsed
//! case is the caller's (see [`crate::case::mesh::MeshSpec::number_slot`]).
//!
//! Only the values of a design that resolves are given: every failure is `None`, and the caller
//! resolves that design as a case of its own ([`super::resolve_case_in`]) for its error.

use super::template::{self, Step, Template};
use super::{expand_hinge_types, read_mesh, resolve_table, take_declared, take_hinge_types, Declared, Parameters};
use serde_json::{Map, Value};
use std::collections::BTreeMap;
use std::path::Path;

/// Where an expression site is written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SiteIn {
    /// In the case object.
    Case,
    /// In the JSON mesh file the case names.
    Mesh,
}

/// A compiled parameterised case (see the module docs).
#[derive(Debug, Clone)]
pub struct Compiled {
    /// Every declaration, the mesh file's overridden by the case's of the same name.
    declared: BTreeMap<String, Declared>,
    /// Each hinge type's definition (a design resolves only if every definition fills).
    types: Vec<Template>,
    /// The case's sites, then the mesh file's.
    case: Template,
    mesh: Option<Template>,
}

impl Compiled {
    /// Compiles case object `value` (parameters unresolved), reading the JSON mesh file it names
    /// from `base`. `None` for a case with neither parameters nor hinge types, or one that does
    /// not resolve.
    pub fn new(value: &Value, base: Option<&Path>) -> Option<Compiled> {
        let mut value = value.clone();
        if !value.is_object() {
            return None;
        }
        let mut mesh = read_mesh(&value, base);
        let declared = take_declared(&mut value).ok()?;
        let case_types = take_hinge_types(&mut value).ok()?;
        let (mut all, mut types) = (BTreeMap::new(), Map::new());
        if let Some((name, mv)) = &mut mesh {
            all = take_declared(mv).ok()?;
            types = take_hinge_types(mv).ok()?;
            for d in all.values_mut() {
                d.file = Some(name.clone());
            }
        }
        all.extend(declared);
        types.extend(case_types);
        if all.is_empty() && types.is_empty() {
            return None;
        }
        let type_templates = types
            .values()
            .map(|spec| Template::new(spec.clone()).ok())
            .collect::<Option<Vec<_>>>()?;
        expand_hinge_types(&mut value, &types, &mut String::new(), &mut Vec::new()).ok()?;
        let mesh = match mesh {
            Some((_, mut mv)) => {
                expand_hinge_types(&mut mv, &types, &mut String::new(), &mut Vec::new()).ok()?;
                Some(Template::new(mv).ok()?)
            }
            None => None,
        };
        Some(Compiled {
            declared: all,
            types: type_templates,
            case: Template::new(value).ok()?,
            mesh,
        })
    }

    /// The declarations, to be given each design's values ([`Self::set`]) and resolved
    /// ([`Self::resolve`]).
    pub fn declared(&self) -> BTreeMap<String, Declared> {
        self.declared.clone()
    }

    /// Sets parameter `name` to `value` in `declared`, as a case's `parameters.NAME` does.
    pub fn set(declared: &mut BTreeMap<String, Declared>, name: &str, value: &Value) {
        match declared.get_mut(name) {
            Some(d) => {
                d.raw = value.clone();
                d.file = None;
                // Set once per worker, not once per design.
                if d.path.strip_prefix("parameters.") != Some(name) {
                    d.path = format!("parameters.{name}");
                }
            }
            None => {
                declared.insert(
                    name.to_string(),
                    Declared {
                        path: format!("parameters.{name}"),
                        raw: value.clone(),
                        file: None,
                    },
                );
            }
        }
    }

    /// The parameter values of `declared`, when every hinge type's definition fills with them.
    pub fn resolve(&self, declared: &BTreeMap<String, Declared>) -> Option<Parameters> {
        let params = resolve_table(declared).ok()?;
        for t in &self.types {
            for (_, expr) in t.expressions() {
                template::evaluate(expr, &params).ok()?;
            }
        }
        Some(params)
    }

    /// Every expression site: where it is written, its way from that root and its number for
    /// `params` (as a resolved case holds it: [`template::number`]); `None` when any fails.
    pub fn numbers<'c>(
        &'c self,
        params: &'c Parameters,
    ) -> impl Iterator<Item = (SiteIn, &'c [Step], Option<Value>)> + 'c {
        let case = self.case.expressions().map(|(s, e)| (SiteIn::Case, s, e));
        let mesh = self
            .mesh
            .iter()
            .flat_map(|m| m.expressions())
            .map(|(s, e)| (SiteIn::Mesh, s, e));
        case.chain(mesh).map(move |(at, steps, expr)| {
            let x = template::evaluate(expr, params).ok().map(template::number);
            (at, steps, x)
        })
    }

    /// The number of sites ([`Self::numbers`]).
    pub fn site_count(&self) -> usize {
        self.case.expressions().count() + self.mesh.iter().map(|m| m.expressions().count()).sum::<usize>()
    }
}
