//! The compiled route of a sweep over a parameterised `static` case (parameters and hinge types
//! in the case or its mesh file, the sweep varying `parameters.NAME`): the case and its mesh
//! file are read, parsed and compiled once ([`Compiled`]); each worker keeps a parsed case and,
//! per design, resolves the parameter table, evaluates the expression sites and sets their
//! numbers in its case ([`crate::case::mesh::MeshSpec::number_slot`]) instead of reading the
//! mesh file, resolving the JSON and parsing the design. The design hash continues the state of
//! the base case's canonical text over each varied value's text and the mesh file's bytes (read
//! once). Unless the sink wants each line's JSON value or `--fields` picks fields, the result
//! is written straight into the worker's line buffer as the typed route does ([`super::typed`]:
//! no JSON value); else it goes into the line as on the value route ([`super`]).
//!
//! The route is taken only where it gives the value route's lines: every axis is a parameter
//! given numbers, every site's number reaches a place of the parsed model, and the parsed case
//! with the numbers set equals the parsed design (checked on three designs before the run). A
//! design whose parameters or expressions do not resolve, or whose run fails, is run again on
//! the value route, so error rows are the value route's.

use super::format::LoadedNodes;
use super::hash::{with_mesh, HashTemplate};
use super::typed::{close_line, finished, line_buffers, line_head, param_keys};
use super::{loaded_nodes_of, Line, LineFormat, Shapes};
use crate::analysis::line::{LineSpec, LineTarget, ResultLine};
use crate::analysis::{self, Case, Ctx, DynAnalysis};
use crate::case::fem_case::MODEL_FIELDS;
use crate::case::params::compiled::{Compiled, SiteIn};
use crate::case::params::template::Step;
use crate::case::params::{Declared, Parameters};
use crate::case::sweep::Sweep;
use crate::fem::SolverCache;
use serde_json::Value;
use std::collections::BTreeMap;
use std::path::Path;

/// A sweep ready for the compiled route.
pub(super) struct Route<'s> {
    sweep: &'s Sweep,
    compiled: Compiled,
    /// Each axis's parameter name.
    names: Vec<&'s str>,
    /// The parsed case of design 0 (every site's number is set again for each design).
    base: Case,
    /// Per site (in [`Compiled::numbers`] order): its number goes into the model (else it is
    /// evaluated, as the value route does, but goes nowhere: a mesh file's load cases replaced
    /// by the case's, say).
    into_model: Vec<bool>,
    hash: HashTemplate,
    /// Each axis's values as the JSON text the hash holds.
    texts: Vec<Vec<Vec<u8>>>,
    /// When the case names a mesh file: its bytes (`None`: unreadable), hashed after the case.
    mesh_bytes: Option<Option<Vec<u8>>>,
    loaded_displacements: bool,
    /// How results are written straight into lines (`None`: through JSON values).
    lines: Option<Lines>,
}

/// What a line written straight from the result keeps ([`Route::line`]).
struct Lines {
    kind: &'static dyn DynAnalysis,
    /// Each axis's `"path":` in the line's `params`.
    keys: Vec<Vec<u8>>,
    omit: Vec<Vec<String>>,
    notes_by_ref: bool,
    /// The nodes whose displacements the line keeps, per load case: the same for every design
    /// (parameters reach no node index).
    rows: Option<LoadedNodes>,
}

/// A worker's reused state on the compiled route.
pub(super) struct Worker {
    case: Case,
    declared: BTreeMap<String, Declared>,
    picks: Vec<usize>,
    line: ResultLine,
}

/// Whether a site's number goes into the model (`Some(true)`), nowhere (`Some(false)`), or to a
/// place the route does not reach (`None`).
fn target(at: SiteIn, steps: &[Step], case: &Value) -> Option<bool> {
    let Some(Step::Key(first)) = steps.first() else {
        return None;
    };
    let first = first.as_str();
    match at {
        SiteIn::Case => MODEL_FIELDS.contains(&first).then_some(true),
        SiteIn::Mesh => {
            let inline = case.get(first);
            let replaced = match (first, steps.get(1)) {
                // Inline load cases replace the mesh file's.
                ("load_cases", _) => inline.and_then(Value::as_array).is_some_and(|a| !a.is_empty()),
                // Inline materials and sections win on equal names.
                ("materials" | "sections", Some(Step::Key(name))) => inline.and_then(|m| m.get(name)).is_some(),
                _ => false,
            };
            Some(!replaced && first != "analysis")
        }
    }
}

impl<'s> Route<'s> {
    /// The compiled route of `sweep`, when it gives the value route's lines (see the module
    /// docs); the lines are written straight from the results unless `want_values`.
    pub(super) fn new(
        sweep: &'s Sweep,
        base_dir: Option<&Path>,
        format: &LineFormat,
        shapes: &Shapes,
        want_values: bool,
    ) -> Option<Self> {
        let base = &sweep.base;
        if sweep.is_empty() || base.get("analysis")?.as_str()? != "static" || base.get("gradients").is_some() {
            return None;
        }
        let mut names = Vec::with_capacity(sweep.axes.len());
        let mut texts = Vec::with_capacity(sweep.axes.len());
        for (path, values) in &sweep.axes {
            names.push(path.strip_prefix("parameters.").filter(|n| !n.contains('.'))?);
            if !values.iter().all(Value::is_number) {
                return None;
            }
            texts.push(
                values
                    .iter()
                    .map(|v| serde_json::to_vec(v).ok())
                    .collect::<Option<_>>()?,
            );
        }
        let design0 = sweep.design(0).ok()?;
        let compiled = Compiled::new(&design0, base_dir)?;
        let into_model = {
            let params = compiled.resolve(&compiled.declared())?;
            compiled
                .numbers(&params)
                .map(|(at, steps, _)| target(at, steps, &design0))
                .collect::<Option<Vec<bool>>>()?
        };
        let mesh_bytes = design0
            .get("mesh")
            .and_then(Value::as_str)
            .map(|name| std::fs::read(crate::case::resolve_file(name, base_dir)).ok());
        let parse = |i: usize| shapes.parse(sweep.design(i).ok()?, base_dir).ok();
        let base = parse(0)?.case;
        let lines = match (want_values, &format.fields) {
            (false, None) => Some(Lines {
                kind: analysis::registry::find("static")?,
                keys: param_keys(sweep)?,
                omit: format.omit_segments(),
                notes_by_ref: format.notes_by_ref,
                rows: loaded_nodes_of(&base, format.loaded_displacements),
            }),
            _ => None,
        };
        let route = Route {
            sweep,
            names,
            base,
            lines,
            into_model,
            hash: HashTemplate::new(sweep)?,
            texts,
            mesh_bytes,
            loaded_displacements: format.loaded_displacements,
            compiled,
        };
        // The numbers set in the parsed case must give the parsed design, parameters included.
        let mut w = route.worker();
        for i in [0, sweep.len() / 2, sweep.len() - 1] {
            let Some(parsed) = parse(i) else { continue };
            let params = route.set(&mut w, i)?;
            if params != parsed.parameters || format!("{:?}", w.case) != format!("{:?}", parsed.case) {
                return None;
            }
        }
        Some(route)
    }

    /// A worker's state.
    pub(super) fn worker(&self) -> Worker {
        Worker {
            case: self.base.clone(),
            declared: self.compiled.declared(),
            picks: vec![0; self.names.len()],
            line: line_buffers(),
        }
    }

    /// Sets design `index`'s numbers in the worker's case; its parameter values.
    fn set(&self, w: &mut Worker, index: usize) -> Option<Parameters> {
        self.sweep.picks(index, &mut w.picks);
        for (k, name) in self.names.iter().enumerate() {
            Compiled::set(&mut w.declared, name, &self.sweep.axes[k].1[w.picks[k]]);
        }
        let params = self.compiled.resolve(&w.declared)?;
        let Case::Static(case) = &mut w.case else {
            return None;
        };
        for ((_, steps, x), &into) in self.compiled.numbers(&params).zip(&self.into_model) {
            let x = x?;
            if into {
                case.model.number_slot(steps)?.set(&x)?;
            }
        }
        Some(params)
    }

    /// The design hash of the design whose numbers are set in `w`.
    fn hash_of(&self, w: &Worker) -> u128 {
        let h = self.hash.state(&self.texts, &w.picks);
        match &self.mesh_bytes {
            Some(bytes) => with_mesh(h, bytes.as_deref()),
            None => h,
        }
    }

    /// Writes design `index`'s line straight from its result into the worker's buffer
    /// ([`Worker::finished`] gives it); `None` when the route writes no lines this way or the
    /// design must take the JSON value routes.
    pub(super) fn line(&self, w: &mut Worker, index: usize, cache: &mut SolverCache) -> Option<()> {
        let lines = self.lines.as_ref()?;
        let params = self.set(w, index)?;
        let h = self.hash_of(w);
        line_head(&mut w.line.out, index, &lines.keys, &self.texts, &w.picks, h)?;
        let mut ctx = Ctx::new(cache, false);
        ctx.with_report = false;
        let to = LineTarget {
            line: &mut w.line,
            spec: LineSpec {
                omit: &lines.omit,
                notes_by_ref: lines.notes_by_ref,
                keyed_rows: lines.rows.as_deref(),
            },
            parameters: Some(&params),
        };
        lines.kind.write_result(&w.case, &mut ctx, to)?.ok()?;
        close_line(&mut w.line)
    }

    /// Design `index`'s result (parameters echoed), the nodes its line keeps and its hash; `None`
    /// when the design must take the value route.
    pub(super) fn design(
        &self,
        w: &mut Worker,
        index: usize,
        cache: &mut SolverCache,
    ) -> Option<(Value, Option<LoadedNodes>, String)> {
        let params = self.set(w, index)?;
        let h = self.hash_of(w);
        let loaded = loaded_nodes_of(&w.case, self.loaded_displacements);
        let mut ctx = Ctx::new(cache, false);
        ctx.with_report = false;
        let mut o = analysis::run_with(&w.case, &mut ctx).ok()?;
        o.echo_parameters(&params);
        Some((o.json, loaded, format!("{h:032x}")))
    }
}

impl Worker {
    /// The line [`Route::line`] wrote for design `index`.
    pub(super) fn finished(&self, index: usize) -> Line<'_> {
        finished(&self.line, index)
    }
}
