//! `sensitivity` and `design` of a static mesh case ([`crate::case::design_mesh`]): the
//! generic Table-1 sensitivity and requirement-driven optimiser of [`crate::problem`] on the
//! case's metrics ([`problem::MeshProblem`]).

use super::problem::{validate, MeshProblem, StaticAnalysis, Validated};
use super::{AnalysisError, Report, RunError};
use crate::case::design_mesh::{MeshDesignCase, MeshSensitivityCase, ObjectiveSpec};
use crate::case::CaseError;
use crate::problem::{self, Constraint, GradientMethod, Objective, Problem, Requirement, Sense};
use crate::report::markdown::{sig, Table};
use serde::Serialize;
use serde_json::{Map, Value};

/// Named numbers in the order given, `null` where undefined.
fn named(names: &[String], values: impl IntoIterator<Item = f64>) -> Map<String, Value> {
    names
        .iter()
        .zip(values)
        .map(|(n, v)| (n.clone(), if v.is_finite() { Value::from(v) } else { Value::Null }))
        .collect()
}

/// One parameter's row of a mesh sensitivity.
#[derive(Debug, Clone, Serialize)]
pub struct MeshSensitivityRow {
    /// Parameter name.
    pub parameter: String,
    /// Declared value.
    pub base: f64,
    /// Increased value, base × (1 + increment).
    pub increased: f64,
    /// Each metric at the increased value over its base value (`null`: base 0).
    pub ratios: Map<String, Value>,
    /// Table-1 bin of each ratio.
    pub bins: Map<String, Value>,
    /// ∂ln|metric|/∂ln parameter at the base (central differences at ±1 %; `null`: undefined).
    pub elasticity: Map<String, Value>,
}

/// Result of a mesh `sensitivity`.
#[derive(Debug, Clone, Serialize)]
pub struct MeshSensitivityResult {
    /// Metrics of the base design.
    pub base: Map<String, Value>,
    /// Relative increment applied.
    pub increment: f64,
    /// One row per parameter (alphabetical).
    pub rows: Vec<MeshSensitivityRow>,
    /// Idealisations.
    pub model: Vec<String>,
}

fn case_error(e: CaseError) -> RunError {
    RunError::Case(e)
}

/// Validates a mesh sensitivity case.
pub fn check_sensitivity<A: StaticAnalysis>(c: &MeshSensitivityCase) -> Result<Validated<A>, CaseError> {
    c.check_fields()?;
    validate(&c.inner, &c.parameters, None)
}

/// Runs a mesh sensitivity case: the result, and the calibration warnings of the base design's
/// hinge elements (`case.elements[i].hinge: ...`).
pub fn run_sensitivity<A: StaticAnalysis>(
    c: &MeshSensitivityCase,
) -> Result<(MeshSensitivityResult, Vec<String>), RunError> {
    let v = check_sensitivity::<A>(c).map_err(case_error)?;
    // The inner case's JSON paths are under `case` (as its errors are).
    let warnings = v
        .case
        .model
        .hinge_warnings()
        .into_iter()
        .map(|w| format!("case.{w}"))
        .collect();
    let names = v.problem.responses().to_vec();
    let (r0, rows) =
        problem::sensitivity(&v.problem, &v.base, c.increment).map_err(|m| AnalysisError::new("sensitivity", m))?;
    let rows = rows
        .into_iter()
        .map(|row| MeshSensitivityRow {
            parameter: row.parameter,
            base: row.base,
            increased: row.increased,
            bins: names
                .iter()
                .zip(&row.ratios)
                .map(|(n, r)| {
                    let b = if r.is_finite() {
                        Value::from(problem::bin(*r))
                    } else {
                        Value::Null
                    };
                    (n.clone(), b)
                })
                .collect(),
            ratios: named(&names, row.ratios),
            elasticity: named(&names, row.elasticity),
        })
        .collect();
    let result = MeshSensitivityResult {
        base: named(&names, r0),
        increment: c.increment,
        rows,
        model: vec![
            "each row: the case run with one parameter increased by `increment` (the others at their declared values); expressions of the case follow the parameter".into(),
            "a stroke_at_allowable metric enters through its `stroke`".into(),
        ],
    };
    Ok((result, warnings))
}

/// Markdown/CSV of a mesh sensitivity.
pub fn sensitivity_report(r: &MeshSensitivityResult) -> Report {
    let names: Vec<&String> = r.base.keys().collect();
    let base: Vec<String> = r
        .base
        .iter()
        .map(|(k, v)| format!("{k} = {}", v.as_f64().map_or("—".into(), |x| sig(x, 5))))
        .collect();
    let mut md = format!(
        "# Influence of the design parameters (Table 1 layout)\n\nBase design: {}. Each parameter increased by {:.0} %; cells: ratio (bin), elasticity.\n\n",
        base.join(", "),
        r.increment * 100.0
    );
    let header: Vec<String> = std::iter::once("positive increase".to_string())
        .chain(names.iter().map(|n| format!("{n}₊/{n}")))
        .collect();
    let header: Vec<&str> = header.iter().map(String::as_str).collect();
    let mut t = Table::new(&header);
    // Long format: every column a label or dimensionless (the case's parameters and metrics
    // carry the case's own units, which the CSV cannot name).
    let mut csv = String::from("parameter,metric,ratio,bin,elasticity\n");
    for row in &r.rows {
        let mut cells = vec![format!(
            "{} ({} → {})",
            row.parameter,
            sig(row.base, 3),
            sig(row.increased, 3)
        )];
        for n in &names {
            let ratio = row.ratios[*n].as_f64();
            let el = row.elasticity[*n].as_f64();
            cells.push(format!(
                "{} ({}), {}",
                ratio.map_or("—".into(), |x| format!("{x:.3}")),
                row.bins[*n].as_str().unwrap_or("—"),
                el.map_or("—".into(), |x| format!("{x:+.2}"))
            ));
            csv += &format!(
                "{},{n},{},{},{}\n",
                row.parameter,
                ratio.map_or(String::new(), |x| x.to_string()),
                row.bins[*n].as_str().unwrap_or_default(),
                el.map_or(String::new(), |x| x.to_string())
            );
        }
        t.row(cells);
    }
    md += &t.render();
    Report { markdown: md, csv }
}

/// Derivatives of the metrics at the design.
#[derive(Debug, Clone, Serialize)]
pub struct Gradients {
    /// How they were obtained.
    pub method: GradientMethod,
    /// Step of the central differences: this fraction of each parameter's bound width (absent
    /// for the direct method, whose element-level step is in `crate::gradient::linear`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub relative_step: Option<f64>,
    /// d metric / d parameter: `{"METRIC": {"PARAMETER": value}}`.
    pub values: Map<String, Value>,
}

/// A visited design.
#[derive(Debug, Clone, Serialize)]
pub struct MeshHistoryEntry {
    /// `"sample"` or `"local"`.
    pub phase: &'static str,
    /// Parameter values.
    pub params: Map<String, Value>,
    /// Metrics (empty if the design failed).
    pub metrics: Map<String, Value>,
    /// Largest normalised requirement violation (≤ 0: feasible; 10⁹: failed).
    pub max_violation: f64,
}

/// Result of a mesh `design`.
#[derive(Debug, Clone, Serialize)]
pub struct MeshDesignResult {
    /// Parameter values found.
    pub design: Map<String, Value>,
    /// Whether every requirement is met.
    pub meets: bool,
    /// Metrics of the design.
    pub metrics: Map<String, Value>,
    /// `match_compliance`: the relative weighted squared error J at the design.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub compliance_error: Option<f64>,
    /// Requirements at the design.
    pub constraints: Vec<Constraint>,
    /// Active (within 1 %) or violated requirements.
    pub binding: Vec<String>,
    /// Explanation when no design meets the requirements.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub message: Option<String>,
    /// d metric / d parameter at the design.
    pub gradients: Gradients,
    /// Designs evaluated.
    pub evaluations: usize,
    /// Samples and local-search steps.
    pub history: Vec<MeshHistoryEntry>,
    /// Idealisations.
    pub model: Vec<String>,
}

/// The requirements and objective of a design case as indices into the problem's responses
/// (errors at `requirements[i].metric`, `objective.…`).
fn goals<A: StaticAnalysis>(
    c: &MeshDesignCase,
    p: &MeshProblem<A>,
) -> Result<(Vec<Requirement>, Objective), CaseError> {
    let metrics = &p.responses()[..p.metrics];
    let index = |at: String, name: &str| {
        metrics.iter().position(|m| m == name).ok_or_else(|| {
            CaseError::value(
                at,
                format!("\"{name}\""),
                format!("must name a metric of the case: {}", metrics.join(", ")),
            )
        })
    };
    let mut reqs = Vec::new();
    for (i, q) in c.requirements.iter().enumerate() {
        let k = index(format!("requirements[{i}].metric"), &q.metric)?;
        for (limit, sense, tag) in [(q.min, Sense::AtLeast, "min"), (q.max, Sense::AtMost, "max")] {
            if let Some(limit) = limit {
                reqs.push(Requirement {
                    name: format!("{}_{tag}", q.metric),
                    response: k,
                    sense,
                    limit,
                });
            }
        }
    }
    let objective = match &c.objective {
        ObjectiveSpec::Maximise(m) => Objective::Maximise(index("objective.maximise".into(), m)?),
        ObjectiveSpec::Minimise(m) => Objective::Minimise(index("objective.minimise".into(), m)?),
        ObjectiveSpec::MatchCompliance(m) => {
            let t: Vec<f64> = m.target.iter().flatten().copied().collect();
            let w: Vec<f64> = match &m.weights {
                Some(w) => w.iter().flatten().copied().collect(),
                // The natural scale of entry ij of an SPD matrix, |C_ij| ≤ √(C_ii C_jj): each
                // entry counts relative to it (1/target² would let round-off entries dominate).
                None => (0..36)
                    .map(|k| {
                        let (a, b) = (m.target[k / 6][k / 6], m.target[k % 6][k % 6]);
                        if a > 0.0 && b > 0.0 {
                            1.0 / (a * b)
                        } else {
                            0.0
                        }
                    })
                    .collect(),
            };
            Objective::LeastSquares {
                responses: (p.metrics..p.metrics + 36).collect(),
                targets: t,
                weights: w,
            }
        }
    };
    Ok((reqs, objective))
}

fn compliance_node(c: &MeshDesignCase) -> Option<usize> {
    match &c.objective {
        ObjectiveSpec::MatchCompliance(m) => Some(m.node),
        _ => None,
    }
}

/// Validates a mesh design case.
pub fn check_design<A: StaticAnalysis>(c: &MeshDesignCase) -> Result<(), CaseError> {
    c.check_fields()?;
    let v = validate::<A>(&c.inner, &c.parameters, compliance_node(c))?;
    goals(c, &v.problem).map(|_| ())
}

/// Runs a mesh design case: the result, and the calibration warnings of the hinge elements of
/// the design found (`design found, case.elements[i].hinge: ...`).
pub fn run_design<A: StaticAnalysis>(c: &MeshDesignCase) -> Result<(MeshDesignResult, Vec<String>), RunError> {
    c.check_fields()?;
    let v = validate::<A>(&c.inner, &c.parameters, compliance_node(c))?;
    let (reqs, objective) = goals(c, &v.problem)?;
    let p = &v.problem;
    let bounds: Vec<[f64; 2]> = c.parameters.values().filter_map(|r| r.bounds).collect();
    let out =
        problem::optimise(p, &bounds, &reqs, &objective, c.samples).map_err(|m| AnalysisError::new("design", m))?;
    let (jac, method) = match &out.jacobian {
        // The local search's last gradient was taken at the design.
        Some(j) => (j.clone(), GradientMethod::Problem),
        None => problem::jacobian(p, &out.params, &bounds).map_err(|m| AnalysisError::new("gradients", m))?,
    };
    let pnames = p.parameters();
    let mnames = &p.responses()[..p.metrics];
    let message = (!out.meets).then(|| {
        let w = out
            .constraints
            .iter()
            .max_by(|a, b| a.violation.total_cmp(&b.violation));
        w.map_or("no design within the bounds could be evaluated".to_string(), |w| {
            format!(
                "no design within the bounds meets the requirements: `{}` cannot be met (best {} {} required {} {})",
                w.name,
                sig(w.value, 4),
                if w.sense == ">=" { "<" } else { ">" },
                w.sense,
                sig(w.limit, 4)
            )
        })
    });
    let compliance_error = match &objective {
        Objective::LeastSquares {
            responses,
            targets,
            weights,
        } => {
            let (mut num, mut den) = (0.0, 0.0);
            for (k, &i) in responses.iter().enumerate() {
                num += weights[k] * (out.responses[i] - targets[k]).powi(2);
                den += weights[k] * targets[k] * targets[k];
            }
            Some(num / den)
        }
        _ => None,
    };
    let mut model = vec![
        "the optimiser: Halton samples over the bounds, then projected gradient descent on the objective plus a quadratic penalty of the normalised requirement violations (see the README)".to_string(),
        "a stroke_at_allowable metric enters through its `stroke`".to_string(),
    ];
    if method == GradientMethod::CentralDifferences {
        model.push(format!(
            "gradients at the design: central differences of full runs, step {} of each bound width (a nonlinear case, a buckling_margin metric, match_compliance, or a frequency metric whose mode is repeated at the design: not differentiable)",
            problem::JACOBIAN_STEP
        ));
    }
    if let Some(n) = compliance_node(c) {
        model.push(format!(
            "match_compliance: J = Σ w (C − C_target)² / Σ w C_target² over the 36 entries of node {n}'s compliance (global axes)"
        ));
    }
    let warnings = p
        .hinge_warnings_at(&out.params)
        .into_iter()
        .map(|w| format!("design found, case.{w}"))
        .collect();
    let result = MeshDesignResult {
        design: named(pnames, out.params.iter().copied()),
        meets: out.meets,
        metrics: named(mnames, out.responses.iter().copied()),
        compliance_error,
        constraints: out.constraints,
        binding: out.binding,
        message,
        gradients: Gradients {
            method,
            relative_step: (method == GradientMethod::CentralDifferences).then_some(problem::JACOBIAN_STEP),
            values: mnames
                .iter()
                .zip(&jac)
                .map(|(m, row)| (m.clone(), Value::Object(named(pnames, row.iter().copied()))))
                .collect(),
        },
        evaluations: out.evaluations,
        history: out
            .history
            .iter()
            .map(|h| MeshHistoryEntry {
                phase: h.phase,
                params: named(pnames, h.params.iter().copied()),
                metrics: named(mnames, h.responses.iter().take(mnames.len()).copied()),
                max_violation: h.max_violation,
            })
            .collect(),
        model,
    };
    Ok((result, warnings))
}

/// Markdown/CSV of a mesh design.
/// No CSV: the parameters and metrics carry the case's own units, which a CSV header cannot
/// name; the history is in the JSON result.
pub fn design_report(r: &MeshDesignResult) -> Report {
    let mut md = super::verdict("# Design of the mechanism", r.meets, r.message.as_deref());
    let num = |v: &Value| v.as_f64().map_or("—".to_string(), |x| sig(x, 5));
    let mut t = Table::new(&["parameter", "value"]);
    for (k, v) in &r.design {
        t.row(vec![k.clone(), num(v)]);
    }
    md += &t.render();
    let mut m = Table::new(&["metric", "value"]);
    for (k, v) in &r.metrics {
        m.row(vec![k.clone(), num(v)]);
    }
    md += "\n";
    md += &m.render();
    if !r.constraints.is_empty() {
        let mut c = Table::new(&["requirement", "value", "limit", "violation"]);
        for k in &r.constraints {
            c.row(vec![
                k.name.clone(),
                sig(k.value, 5),
                format!("{} {}", k.sense, sig(k.limit, 4)),
                format!("{:+.4}", k.violation),
            ]);
        }
        md += "\n";
        md += &c.render();
    }
    md += &format!("\n{} designs evaluated.\n", r.evaluations);
    Report {
        markdown: md,
        csv: String::new(),
    }
}
