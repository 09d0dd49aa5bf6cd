//! One design of a parametric case: the case resolved at given parameter values (optionally a
//! step along one of them), its model, and the targets evaluated from equation values that
//! need not come from a solve of this model (the direct method evaluates them along
//! q + s·dq/dp, see [`super::linear`]).

use super::{GradientError, Target};
use crate::analysis::case_file::{self, Case};
use crate::analysis::fem_static::{self, metrics};
use crate::case::mesh::{BuiltHinge, MetricKind, StaticCase};
use crate::case::params::{self, tangent::Written, Along, Parameters};
use crate::fem::{self, constraints::DofMap, recovery, LoadCase, Model};

/// A design: the resolved case and its linear model.
pub(crate) struct Point {
    pub case: StaticCase,
    pub model: Model,
    pub hinges: Vec<BuiltHinge>,
    pub case_index: Vec<Option<usize>>,
    /// Every declared parameter's value.
    pub parameters: Parameters,
    /// The parameters declared as numbers.
    pub independent: Vec<String>,
}

impl Point {
    /// The case `written` with the parameters `values` (overriding those declared; others as
    /// declared), moved by `along` if given.
    pub fn new(written: &Written, values: &Parameters, along: Option<Along<'_>>) -> Result<Point, GradientError> {
        let mut v = written.value.clone();
        if !values.is_empty() {
            let obj = v
                .as_object_mut()
                .ok_or_else(|| GradientError::case("the case is not a JSON object"))?;
            let p = obj
                .entry("parameters")
                .or_insert_with(|| serde_json::Value::Object(Default::default()));
            if let Some(p) = p.as_object_mut() {
                for (k, x) in values {
                    p.insert(k.clone(), serde_json::Value::from(*x));
                }
            }
        }
        let resolved = params::resolve_case_in(&mut v, written.mesh.clone(), along)?;
        let independent = resolved.independent.clone();
        let parsed = case_file::parse_with(v, written.dir.as_deref(), resolved)?;
        let Case::Static(case) = parsed.case else {
            return Err(GradientError::case("gradients are computed for `static` cases"));
        };
        if case.nonlinear {
            return Err(GradientError::case("gradients are computed for linear runs only"));
        }
        let (model, hinges, case_index) = case.model.build_indexed(true, false)?;
        Ok(Point {
            case,
            model,
            hinges,
            case_index,
            parameters: parsed.parameters,
            independent,
        })
    }

    /// `targets` with each `frequency` metric replaced by the [`Target::Frequency`] of its mode:
    /// its value and derivative then come from the modes of the base design
    /// ([`super::frequency`], dω²/dp = φᵀ(dK − ω² dM)φ) rather than from a modal solve of each
    /// moved model.
    pub fn eigen_targets(&self, targets: &[Target]) -> Vec<Target> {
        targets
            .iter()
            .map(|t| match t {
                Target::Metric(name) => match self.case.metrics.iter().find(|m| &m.name == name) {
                    Some(m) if m.kind == MetricKind::Frequency => {
                        m.mode.map_or_else(|| t.clone(), |mode| Target::Frequency { mode })
                    }
                    _ => t.clone(),
                },
                _ => t.clone(),
            })
            .collect()
    }

    /// The load cases in model order.
    pub fn load_cases(&self) -> &[LoadCase] {
        &self.model.load_cases
    }

    /// The reduced right-hand side of load case `lc` on `map` (Aᵀ(f − K u_c), as the linear
    /// solver forms it), the prescribed values u_c and the applied loads f (6 per node).
    pub fn rhs(&self, map: &DofMap, lc: &LoadCase) -> Result<[Vec<f64>; 3], GradientError> {
        let [u_c, f] = self.loads(lc);
        let u_c_full = map.expand(&vec![0.0; map.n_eq()], &u_c);
        let mut g = f.clone();
        if u_c_full.iter().any(|&v| v != 0.0) {
            let ku = recovery::internal_forces(&self.model, &u_c_full)?;
            g.iter_mut().zip(&ku).for_each(|(gi, ki)| *gi -= ki);
        }
        Ok([map.reduce(&g), u_c, f])
    }

    /// The prescribed values u_c and the applied loads f of load case `lc` (6 per node).
    fn loads(&self, lc: &LoadCase) -> [Vec<f64>; 2] {
        let nd = self.model.n_dofs();
        let mut f = vec![0.0; nd];
        for l in &lc.forces {
            for d in 0..6 {
                f[6 * l.node + d] += l.f[d];
            }
        }
        let mut u_c = vec![0.0; nd];
        for p in &lc.displacements {
            u_c[6 * p.node + p.dof.index()] = p.value;
        }
        [u_c, f]
    }

    /// The values of `targets` with the equation values `q[i]` of load case i (on `maps[i]`)
    /// and `unit[k]` of the k-th unit load of a stiffness or compliance target (on `free`, the
    /// map with the supports only). Frequencies are not evaluated here (NaN).
    pub fn evaluate(
        &self,
        targets: &[Target],
        maps: &[&DofMap],
        q: &[Vec<f64>],
        free: Option<&DofMap>,
        unit: &[Vec<f64>],
    ) -> Result<Vec<f64>, GradientError> {
        let mut cases = Vec::with_capacity(q.len());
        for (i, lc) in self.load_cases().iter().enumerate() {
            let [u_c, f] = self.loads(lc);
            let u = maps[i].expand(&q[i], &u_c);
            cases.push(recovery::case_result_unchecked(&self.model, maps[i], &lc.name, &u, &f)?);
        }
        let raw = fem::StaticResults { load_cases: cases };
        let (mut r, raw) = fem_static::result_of(&self.model, raw, false)?;
        fem_static::add_hinges(&mut r, &self.model, &raw, &self.hinges, false)?;
        if let Some(f) = &self.case.fatigue {
            fem_static::fatigue::add(&mut r, &self.hinges, f);
        }
        fem_static::add_headlines(&mut r, &self.model, &self.case_index, &self.hinges);
        let reqs: Vec<_> = self
            .case
            .metrics
            .iter()
            .filter(|m| !matches!(m.kind, MetricKind::Stiffness | MetricKind::Compliance))
            .filter(|m| m.kind != MetricKind::Frequency || asks(targets, &m.name))
            .cloned()
            .collect();
        let m = metrics::evaluate(&self.model, &self.case.model, &reqs, &r)?;
        let mut units = unit.iter();
        let mut out = Vec::with_capacity(targets.len());
        for t in targets {
            let v = match t {
                Target::Metric(name) => {
                    let req = self.case.metrics.iter().find(|m| &m.name == name);
                    let req = req.ok_or_else(|| GradientError::case(format!("no metric named `{name}`")))?;
                    match req.kind {
                        MetricKind::Stiffness | MetricKind::Compliance => {
                            let (node, dof) = req.node.zip(req.dof()).expect("checked when parsed");
                            let free = free.expect("a unit load system for stiffness targets");
                            let q = units.next().expect("one unit load per stiffness target");
                            let c = free.expand(q, &vec![0.0; self.model.n_dofs()])[6 * node + dof.index()];
                            if req.kind == MetricKind::Compliance {
                                c
                            } else {
                                1.0 / c
                            }
                        }
                        _ => match m.get(name) {
                            Some(metrics::MetricValue::Number(Some(v))) => v,
                            Some(metrics::MetricValue::Stroke(s)) => s.stroke,
                            _ => return Err(GradientError::undefined(name)),
                        },
                    }
                }
                Target::VonMises { load_case, element } => {
                    let row = r.load_cases.iter().find(|c| &c.name == load_case);
                    let row = row.ok_or_else(|| GradientError::case(format!("no load case `{load_case}`")))?;
                    match row.hinges.iter().find(|h| h.element == *element) {
                        Some(h) => h.peak_von_mises,
                        None => self
                            .case_index
                            .get(*element)
                            .copied()
                            .flatten()
                            .and_then(|ie| row.element_von_mises.get(ie).copied().flatten())
                            .ok_or_else(|| {
                                GradientError::case(format!(
                                    "element {element} has no stress (a rigid link, mass or spring)"
                                ))
                            })?,
                    }
                }
                Target::Frequency { .. } => f64::NAN,
            };
            out.push(v);
        }
        Ok(out)
    }
}

/// True if `targets` asks for metric `name` by name.
fn asks(targets: &[Target], name: &str) -> bool {
    targets.iter().any(|t| matches!(t, Target::Metric(n) if n == name))
}
