//! A static mesh case with parameters and metrics as a design problem of [`crate::problem`]:
//! the named parameters in, the case's metrics out (a `stroke_at_allowable` metric through its
//! `stroke`), plus the 36 entries of one node's compliance for `match_compliance`.
//!
//! Each design is the inner case with the varied parameters set in its `parameters` (which
//! override the mesh file's, and feed every expression that uses them), resolved, parsed and
//! run as `flexfem run` would run it; the case and its JSON mesh file are read and validated
//! once per design run, not per design. Each rayon worker keeps a solver cache: designs with the
//! topology of the previous one are refactorised numerically only.

use crate::analysis::common::kind::{Analysis, Ctx};
use crate::analysis::fem_static::{MetricValue, StaticResult};
use crate::analysis::RunError;
use crate::case::design_mesh::{Inner, ParameterRange};
use crate::case::mesh::{ComplianceRequest, StaticCase};
use crate::case::params::tangent::Written;
use crate::case::params::Parameters;
use crate::case::CaseError;
use crate::fem::SolverCache;
use crate::problem::Problem;
use serde_json::Value;
use std::collections::BTreeMap;
use std::sync::Arc;

/// The mesh case and what the problem reads from it; `A` is the `static` analysis that runs
/// each design (handed in by the caller, so this file does not depend on the list of kinds).
pub struct MeshProblem<A> {
    parameters: Vec<String>,
    responses: Vec<String>,
    /// Number of metrics (the first responses).
    pub metrics: usize,
    /// Node of the compliance entries after the metrics, if any.
    compliance_node: Option<usize>,
    /// The case as written with its JSON mesh file read once: each design is resolved from it
    /// without reading any file again.
    written: Arc<Written>,
    /// Whether the responses have gradients by the direct method ([`crate::gradient::Linear`]):
    /// a linear case, no compliance responses, and no `buckling_margin` metric (a `frequency`
    /// metric by its eigenvalue derivative, [`crate::gradient::frequency`]).
    direct: bool,
    analysis: std::marker::PhantomData<fn() -> A>,
}

/// The `static` analysis: a case shape and typed result, and the case-file reader of a
/// static case (the reader sits in `analysis::dispatch`, above the kinds, which hands it in).
pub trait StaticAnalysis: Analysis<Case = StaticCase, Result = StaticResult> {
    /// Reads a static case value (parameters resolved, mesh file read relative to `dir`):
    /// the typed case, every declared parameter with its value, and where its values outside
    /// the case as written came from.
    fn parse_static(value: Value, dir: Option<&std::path::Path>, check_arrays: bool)
        -> Result<ParsedStatic, CaseError>;

    /// [`Self::parse_static`] of a case value whose JSON mesh file was read already (`mesh`,
    /// [`crate::case::params::read_mesh`]): nothing is read from disk; arrays not re-checked.
    fn parse_static_in(
        value: Value,
        mesh: Option<(String, Value)>,
        dir: Option<&std::path::Path>,
    ) -> Result<ParsedStatic, CaseError>;
}

/// A static case read by [`StaticAnalysis::parse_static`].
pub struct ParsedStatic {
    /// The typed case.
    pub case: StaticCase,
    /// Every declared parameter (the case's and its mesh file's) with its value.
    pub parameters: Parameters,
    /// Where values outside the case as written came from.
    pub origins: crate::case::params::Origins,
}

/// The validated problem with the inner case's base design.
pub struct Validated<A> {
    /// The problem.
    pub problem: MeshProblem<A>,
    /// Declared value of each varied parameter.
    pub base: Vec<f64>,
    /// Every parameter the inner case declares, with its value.
    pub declared: Parameters,
    /// The base design parsed (a static case).
    pub case: StaticCase,
}

/// Names of the compliance responses: `C[i][j]`.
pub fn compliance_names() -> Vec<String> {
    (0..36).map(|k| format!("C[{}][{}]", k / 6, k % 6)).collect()
}

/// Checks the inner case and the varied parameters against it (errors under `case.…` and
/// `parameters.NAME`): a static case with metrics that parses, each parameter declared, its
/// declared value inside its bounds.
pub fn validate<A: StaticAnalysis>(
    inner: &Inner,
    ranges: &BTreeMap<String, ParameterRange>,
    compliance_node: Option<usize>,
) -> Result<Validated<A>, CaseError> {
    let kind = inner.value.get("analysis").and_then(Value::as_str);
    if kind != Some("static") {
        return Err(CaseError::value(
            "case.analysis",
            kind.map_or("(missing)".to_string(), |k| format!("\"{k}\"")),
            "the mechanism of a sensitivity or design must be a \"static\" case with parameters and metrics",
        ));
    }
    let parsed = A::parse_static(inner.value.clone(), inner.dir.as_deref(), true).map_err(|e| e.under("case"))?;
    let case = parsed.case;
    A::check(&case).map_err(|e| parsed.origins.locate(e).under("case"))?;
    if case.metrics.is_empty() {
        return Err(CaseError::new(
            "case.metrics",
            "the case has no metrics: a sensitivity or design reads named metrics ([{\"name\", \"kind\", …}])",
        ));
    }
    let mut base = Vec::with_capacity(ranges.len());
    for (name, r) in ranges {
        let Some(&v) = parsed.parameters.get(name) else {
            let declared: Vec<&str> = parsed.parameters.keys().map(String::as_str).collect();
            return Err(CaseError::value(
                format!("parameters.{name}"),
                format!("\"{name}\""),
                format!(
                    "not a parameter of the case or its mesh file (declared: {})",
                    if declared.is_empty() {
                        "none".to_string()
                    } else {
                        declared.join(", ")
                    }
                ),
            ));
        };
        if let Some(b) = r.bounds.filter(|b| !(b[0] <= v && v <= b[1])) {
            return Err(CaseError::value(
                format!("parameters.{name}.bounds"),
                format!("[{}, {}]", b[0], b[1]),
                format!("must contain the declared value {name} = {v}"),
            ));
        }
        base.push(v);
    }
    if let Some(n) = compliance_node.filter(|&n| n >= case.model.nodes.len()) {
        return Err(CaseError::value(
            "objective.match_compliance.node",
            n,
            format!("must be a node index below {}", case.model.nodes.len()),
        ));
    }
    let mut responses: Vec<String> = case.metrics.iter().map(|m| m.name.clone()).collect();
    let metrics = responses.len();
    if compliance_node.is_some() {
        responses.extend(compliance_names());
    }
    use crate::case::mesh::MetricKind;
    let direct = !case.nonlinear
        && compliance_node.is_none()
        && case.metrics.iter().all(|m| m.kind != MetricKind::BucklingMargin);
    let written = Arc::new(Written {
        value: inner.value.clone(),
        mesh: crate::case::params::read_mesh(&inner.value, inner.dir.as_deref()),
        dir: inner.dir.clone(),
    });
    Ok(Validated {
        problem: MeshProblem {
            written,
            parameters: ranges.keys().cloned().collect(),
            responses,
            metrics,
            compliance_node,
            direct,
            analysis: std::marker::PhantomData,
        },
        base,
        declared: parsed.parameters,
        case,
    })
}

impl<A: StaticAnalysis> MeshProblem<A> {
    /// The inner case value with the parameters set to `p`.
    pub fn design_value(&self, p: &[f64]) -> Value {
        let mut v = self.written.value.clone();
        if let Value::Object(m) = &mut v {
            let params = m
                .entry("parameters")
                .or_insert_with(|| Value::Object(Default::default()));
            if let Value::Object(pm) = params {
                for (name, x) in self.parameters.iter().zip(p) {
                    pm.insert(name.clone(), Value::from(*x));
                }
            }
        }
        v
    }

    /// The calibration warnings of the hinge elements of design `p`
    /// ([`crate::case::mesh::MeshSpec::hinge_warnings`]); none if the design does not parse
    /// (its run reports that).
    pub fn hinge_warnings_at(&self, p: &[f64]) -> Vec<String> {
        let wr = &self.written;
        A::parse_static_in(self.design_value(p), wr.mesh.clone(), wr.dir.as_deref())
            .map(|parsed| parsed.case.model.hinge_warnings())
            .unwrap_or_default()
    }

    /// Runs design `p` as a static case.
    fn run(&self, w: &mut SolverCache, p: &[f64]) -> Result<StaticResult, String> {
        let at = |e: CaseError| format!("{}: {}", e.path, e.message);
        let wr = &self.written;
        let ParsedStatic { mut case, origins, .. } =
            A::parse_static_in(self.design_value(p), wr.mesh.clone(), wr.dir.as_deref()).map_err(at)?;
        if let Some(node) = self.compliance_node {
            case.compliance.push(ComplianceRequest { node, frame: None });
        }
        let mut ctx = Ctx::new(w, false);
        ctx.with_report = false;
        ctx.metrics_only = true;
        A::run(&case, &mut ctx).map_err(|e| match e {
            RunError::Case(c) => at(origins.locate(c)),
            RunError::Analysis(a) => a.to_string(),
        })
    }
}

impl<A: StaticAnalysis> Problem for MeshProblem<A> {
    type Worker = SolverCache;

    fn parameters(&self) -> &[String] {
        &self.parameters
    }
    fn responses(&self) -> &[String] {
        &self.responses
    }
    fn worker(&self) -> SolverCache {
        SolverCache::new()
    }
    fn evaluate(&self, w: &mut SolverCache, p: &[f64]) -> Result<Vec<f64>, String> {
        let r = self.run(w, p)?;
        let mut out = Vec::with_capacity(self.responses.len());
        for (name, v) in &r.metrics.0 {
            let x = match v {
                MetricValue::Stroke(s) => Some(s.stroke),
                other => other.number(),
            };
            out.push(x.ok_or_else(|| format!("metric \"{name}\" has no value (null) at this design"))?);
        }
        if self.compliance_node.is_some() {
            let c = r.compliance.last().ok_or("no compliance computed")?;
            out.extend(c.matrix.iter().flatten());
        }
        Ok(out)
    }

    /// The direct-method gradients of the metrics ([`crate::gradient::Linear`]) where the case
    /// allows them (see `direct`) and no `frequency` metric's mode is repeated at `p`; central
    /// differences otherwise.
    fn gradient(&self, w: &mut SolverCache, p: &[f64]) -> Option<Result<crate::problem::Jacobian, String>> {
        if !self.direct {
            return None;
        }
        let targets = self.responses[..self.metrics]
            .iter()
            .map(|n| crate::gradient::Target::Metric(n.clone()))
            .collect();
        let values: Parameters = self.parameters.iter().cloned().zip(p.iter().copied()).collect();
        let g = crate::gradient::Linear::new(self.written.clone(), targets)
            .with_parameters(self.parameters.clone())
            .evaluate(&values, w);
        match g {
            // A repeated mode has no gradient (only one-sided derivatives): central differences
            // of full runs there, reported as such.
            Ok(g) if g.repeated_mode => None,
            Ok(g) => Some(Ok(g.jacobian)),
            Err(e) => Some(Err(e.to_string())),
        }
    }
}
