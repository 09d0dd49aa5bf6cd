//! `"analysis": "transient"`: linear transient response of a beam/shell/hinge/joint model (as
//! for `static`) to load and prescribed-motion histories, by HHT-α or Newmark average
//! acceleration ([`crate::fem::transient`]), with Rayleigh and per-element damping; with
//! `"nonlinear": true`, geometrically nonlinear by Newmark average acceleration with Newton
//! iterations per step ([`crate::fem::nonlinear::solve_transient_nonlinear`]).

mod history;
mod output;

use crate::case::fields::case_struct;
use crate::analysis::common::kind::{Analysis, Ctx, UsedMaterial};
use crate::analysis::common::kind::named_materials;
use super::{Report, RunError};
use crate::case::fem_case::{mesh_rules, parse_with_model};
use crate::case::mesh::{DofName, ElementSpec, GmshMapping, MeshSpec};
use crate::case::CaseError;
use crate::fem::transient::{Damping, PrescribedMotion, Scheme, TransientLoad, TransientOptions};
use crate::fem::{Dof, NodeDof};
pub use history::{ElementDampingSpec, HistorySpec};
pub use output::{RecordOut, TransientResult};
use serde::Deserialize;
use serde_json::Value;

/// A nodal load history: `F` (as in a `static` load case) or its alias `force`, not both.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(extend("oneOf" = [
    {"required": ["F"], "properties": {"force": {"type": "null"}}},
    {"required": ["force"], "properties": {"F": {"type": "null"}}}
]))]
pub struct LoadSpec {
    /// Node index.
    pub node: usize,
    /// [Fx, Fy, Fz (N), Mx, My, Mz (N·mm)], global axes, times the history (the `F` of a
    /// `static` load).
    #[serde(rename = "F", default)]
    pub f: Option<[f64; 6]>,
    /// Alias of `F` (an earlier spelling, still accepted): [Fx, Fy, Fz (N), Mx, My, Mz (N·mm)].
    #[serde(default)]
    pub force: Option<[f64; 6]>,
    pub history: HistorySpec,
}

impl LoadSpec {
    /// The load [Fx, Fy, Fz (N), Mx, My, Mz (N·mm)] from `F` or its alias `force`, and the
    /// JSON path of the field that gave it (`p` is the load's path).
    pub fn load(&self, p: &str) -> Result<([f64; 6], String), CaseError> {
        match (self.f, self.force) {
            (Some(f), None) => Ok((f, format!("{p}.F"))),
            (None, Some(f)) => Ok((f, format!("{p}.force"))),
            (Some(_), Some(_)) => Err(CaseError::new(p, "give the load as `F` or as its alias `force`, not both")),
            (None, None) => Err(CaseError::new(p, "missing `F`: the load [Fx, Fy, Fz (N), Mx, My, Mz (N·mm)]")),
        }
    }
}

/// A prescribed-motion history of one DOF (node axes at framed nodes).
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MotionSpec {
    /// Node index.
    pub node: usize,
    pub dof: DofName,
    /// Amplitude: mm for translations, degrees for rotations; times the history, which must
    /// be 0 at t = 0.
    pub value: f64,
    pub history: HistorySpec,
}

case_struct! {
    /// Damping C = alpha M + beta K + Σ elements.
    #[derive(Debug, Clone, Default, Deserialize, schemars::JsonSchema)]
    #[serde(deny_unknown_fields)]
    pub struct DampingSpec {
        include rayleigh;
        /// Per-element stiffness-proportional damping.
        #[serde(default)]
        pub elements: Vec<ElementDampingSpec>,
    }
}

/// Time-integration scheme.
#[derive(Debug, Clone, Copy, Default, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum SchemeName {
    /// Newmark average acceleration: no numerical damping.
    #[default]
    Newmark,
    /// HHT-α (Hilber, Hughes & Taylor 1977) with `hht_alpha`: damps the high modes.
    Hht,
}

/// A recorded DOF (all six of the node when `dof` is left out).
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RecordSpec {
    pub node: usize,
    #[serde(default)]
    pub dof: Option<DofName>,
}

case_struct! {
    /// `"analysis": "transient"`.
    #[derive(Debug, Clone, schemars::JsonSchema)]
    #[serde(deny_unknown_fields)]
    #[schemars(extend("allOf" = mesh_rules(false)))]
    pub struct TransientCase {
        /// Time step, s (1e-12 … 1e6).
        #[schemars(range(min = 1e-12, max = 1e6))]
        pub dt: f64,
        /// Number of steps, 1 … 1000000.
        #[schemars(range(min = 1, max = 1000000))]
        pub steps: usize,
        include model_source {
            /// Free text (not used).
            description,
            /// The model's JSON mesh file or Gmsh `.msh` file, as for `static` (its load cases are
            /// ignored), or the model inline.
            mesh,
            /// Physical-group mapping of a Gmsh `.msh` mesh.
            gmsh,
            /// The model.
            model,
        }
        /// `"newmark"` (default) or `"hht"`.
        #[serde(default)]
        pub scheme: SchemeName,
        /// α of HHT, −1/3 … 0 (default −0.05; only with `"scheme": "hht"`).
        pub hht_alpha: Option<f64>,
        #[serde(default)]
        pub damping: DampingSpec,
        /// Load histories.
        #[serde(default)]
        pub loads: Vec<LoadSpec>,
        /// Prescribed-motion histories.
        #[serde(default)]
        pub motions: Vec<MotionSpec>,
        /// DOFs whose histories are recorded (CSV, SVG; peaks in the JSON result).
        #[serde(default)]
        pub record: Vec<RecordSpec>,
        /// Frames of the VTK time series written with `--out` (default 50, at most `steps` + 1).
        pub frames: Option<usize>,
        /// Full recorded series in the JSON result (default false: peaks and final values only).
        #[serde(default)]
        pub histories: bool,
        /// Geometrically nonlinear (co-rotational beams and hinge elements, Newton iterations per
        /// step; Newmark only, loads only, no shells; default false). Mass and damping are those of
        /// the undeformed configuration (see the result's `model`).
        #[serde(default)]
        pub nonlinear: bool,
    }
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct Options {
    dt: f64,
    steps: usize,
    #[serde(default)]
    mesh: Option<String>,
    #[serde(default)]
    gmsh: Option<GmshMapping>,
    #[serde(default)]
    description: Option<String>,
    #[serde(default)]
    scheme: SchemeName,
    #[serde(default)]
    hht_alpha: Option<f64>,
    #[serde(default)]
    damping: DampingSpec,
    #[serde(default)]
    loads: Vec<LoadSpec>,
    #[serde(default)]
    motions: Vec<MotionSpec>,
    #[serde(default)]
    record: Vec<RecordSpec>,
    #[serde(default)]
    frames: Option<usize>,
    #[serde(default)]
    histories: bool,
    #[serde(default)]
    nonlinear: bool,
}

const OWN: [&str; 16] = [
    "analysis",
    "description",
    "mesh",
    "gmsh",
    "dt",
    "steps",
    "scheme",
    "hht_alpha",
    "damping",
    "loads",
    "motions",
    "record",
    "frames",
    "histories",
    "nonlinear",
    "load_cases",
];

/// Parses a `transient` case; files it names resolve against `base` first.
pub fn parse_transient(value: Value, base: &crate::case::Source<'_>) -> Result<TransientCase, CaseError> {
    // `load_cases` is accepted and not used: a transient takes its loads from `loads`.
    let (o, model) = parse_with_model(value, "transient", &OWN, &["load_cases"], base, |o: &Options| {
        (o.mesh.as_deref(), o.gmsh.as_ref())
    })?;
    let mut case = TransientCase {
        description: o.description,
        mesh: o.mesh,
        gmsh: o.gmsh,
        dt: o.dt,
        steps: o.steps,
        scheme: o.scheme,
        hht_alpha: o.hht_alpha,
        damping: o.damping,
        loads: o.loads,
        motions: o.motions,
        record: o.record,
        frames: o.frames,
        histories: o.histories,
        nonlinear: o.nonlinear,
        model,
    };
    case.motions.extend(promoted_motions(&case.model, &case.motions)?);
    case.options(case.model.nodes.len())?;
    Ok(case)
}

/// The motions of the edge midpoints `"shell_elements": "shell9"` added, as their prescribed
/// displacements in statics ([`crate::case::mesh::promote::midpoint_value`]): the mean of the
/// ends' amplitudes when both ends move by one history in a DOF, half the amplitude when one
/// moves and the other is held. A motion acts in its node's axes, so the ends and the midpoint
/// must share them (a framed support at each, or none); refused otherwise, and when the ends
/// move by different histories (the midpoint cannot follow both).
fn promoted_motions(model: &crate::case::mesh::MeshSpec, motions: &[MotionSpec]) -> Result<Vec<MotionSpec>, CaseError> {
    use crate::case::mesh::promote::{edge_prescriptions, holds, midpoint_value, node_axes};
    let Some(p) = &model.promoted else {
        return Ok(Vec::new());
    };
    let own = &model.supports[..p.first_support];
    let refuse = |i: usize, why: String| {
        CaseError::new(
            format!("motions[{i}]"),
            format!("\"shell_elements\": \"shell9\": {why}: give the edge's nodes one frame and one history, or keep \"shell_elements\": \"as_given\""),
        )
    };
    let mut added = Vec::new();
    for e in edge_prescriptions(p, motions.len(), |i| (motions[i].node, motions[i].dof)) {
        let (i, mv, other, m) = (e.item, &motions[e.item], e.other, e.midpoint);
        let other_held = own.iter().any(|s| s.node == other && !s.fix.is_empty());
        if e.paired.is_none() && !other_held {
            continue; // the other end is free: so is the midpoint
        }
        let dof = format!("{:?}", mv.dof).to_lowercase();
        let axes = node_axes(own, mv.node);
        if node_axes(own, other) != axes || node_axes(&model.supports, m) != axes {
            return Err(refuse(
                i,
                format!("node {} moves in {dof} of its own axes, and the other end of its shell edge ({other}) or the node added at the edge's middle ({m}) has other axes, so the midpoint's motion is not defined", mv.node),
            ));
        }
        if let Some(j) = e.paired.filter(|&j| motions[j].history != mv.history) {
            let (a, b) = (mv.node.min(other), mv.node.max(other));
            return Err(refuse(
                i,
                format!("nodes {a} and {b} move in {dof} by different histories (`motions[{i}]`, `motions[{j}]`), and the node added at the middle of their shell edge ({m}) cannot follow both"),
            ));
        }
        let held = holds(own, other, mv.dof, axes);
        if let Some(value) = midpoint_value(mv.value, e.paired.map(|j| motions[j].value), held) {
            added.push(MotionSpec {
                node: m,
                dof: mv.dof,
                value,
                history: mv.history.clone(),
            });
        }
    }
    Ok(added)
}

/// What the solver needs from a case, checked.
struct Inputs {
    loads: Vec<TransientLoad>,
    motions: Vec<PrescribedMotion>,
    opts: TransientOptions,
}

impl TransientCase {
    /// What the nonlinear solver does not take.
    fn check_nonlinear(&self) -> Result<(), CaseError> {
        let refuse = |p: &str, what: &str| Err(CaseError::new(p, format!("{what} is not available with \"nonlinear\": true")));
        if matches!(self.scheme, SchemeName::Hht) {
            return refuse("scheme", "HHT-alpha (the nonlinear solver uses Newmark average acceleration)");
        }
        if !self.motions.is_empty() {
            return refuse("motions", "a prescribed motion");
        }
        if let Some(i) = self.model.elements.iter().position(|e| matches!(e, ElementSpec::Shell4 { .. } | ElementSpec::Shell9 { .. }))
        {
            return refuse(&format!("elements[{i}]"), "a shell element");
        }
        crate::case::mesh::superelement::refuse_in(&self.model, "nonlinear transients")?;
        Ok(())
    }

    /// Refuses a DOF moved twice, or moved at a rigid-link slave (whose motion its master
    /// fixes) or at the second node of a joint (which follows the first).
    fn check_motions(&self, model: &crate::fem::Model, motions: &[PrescribedMotion]) -> Result<(), CaseError> {
        for (i, m) in motions.iter().enumerate() {
            let p = format!("motions[{i}]");
            if let Some(j) = motions[..i].iter().position(|o| o.node == m.node && o.dof == m.dof) {
                return Err(CaseError::value(
                    format!("{p}.dof"),
                    m.dof,
                    format!("node {} {} is already moved by `motions[{j}]`: give each DOF one motion (sum the histories)", m.node, m.dof),
                ));
            }
            if let Some(l) = model.rigid_links.iter().find(|l| l.slaves.contains(&m.node)) {
                return Err(CaseError::value(
                    format!("{p}.node"),
                    m.node,
                    format!("node {} is a rigid-link slave, moved by its master {}: prescribe the master's motion instead", m.node, l.master),
                ));
            }
            if let Some(t) = model.ties.iter().find(|t| t.b == m.node && t.dofs[m.dof.index()]) {
                return Err(CaseError::value(
                    format!("{p}.node"),
                    m.node,
                    format!("node {} {} is tied by a joint to node {}: prescribe node {} instead", m.node, m.dof, t.a, t.a),
                ));
            }
        }
        Ok(())
    }

    fn scheme(&self) -> Result<Scheme, CaseError> {
        match (self.scheme, self.hht_alpha) {
            (SchemeName::Newmark, None) => Ok(Scheme::AverageAcceleration),
            (SchemeName::Newmark, Some(_)) => Err(CaseError::new("hht_alpha", "only with \"scheme\": \"hht\"")),
            (SchemeName::Hht, a) => {
                let a = a.unwrap_or(-0.05);
                if !(-1.0 / 3.0..=0.0).contains(&a) {
                    return Err(CaseError::value("hht_alpha", a, "must be from -1/3 to 0"));
                }
                Ok(Scheme::Hht { alpha: a })
            }
        }
    }

    fn options(&self, n_nodes: usize) -> Result<(TransientOptions, Vec<TransientLoad>, Vec<PrescribedMotion>), CaseError> {
        let node = |p: String, n: usize| {
            if n < n_nodes {
                Ok(n)
            } else {
                Err(CaseError::value(p, n, format!("must be a node index below {n_nodes}")))
            }
        };
        let dts = crate::fem::transient::DT_RANGE;
        if !dts.contains(&self.dt) {
            let allowed = format!("must be a time step from {:e} to {:e} s", dts.start(), dts.end());
            return Err(CaseError::value("dt", format!("{:e}", self.dt), allowed));
        }
        if !(1..=1_000_000).contains(&self.steps) {
            return Err(CaseError::value("steps", self.steps, "must be an integer from 1 to 1000000"));
        }
        let mut opts = TransientOptions::new(self.dt, self.steps);
        opts.scheme = self.scheme()?;
        for (name, v) in [("damping.alpha", self.damping.alpha), ("damping.beta", self.damping.beta)] {
            if !(v.is_finite() && v >= 0.0) {
                return Err(CaseError::value(name, v, "must be ≥ 0"));
            }
        }
        for (i, e) in self.damping.elements.iter().enumerate() {
            if e.element >= self.model.elements.len() {
                let allowed = format!("must be an index into `elements` (below {})", self.model.elements.len());
                return Err(CaseError::value(format!("damping.elements[{i}].element"), e.element, allowed));
            }
            if !(e.beta.is_finite() && e.beta >= 0.0) {
                return Err(CaseError::value(format!("damping.elements[{i}].beta"), e.beta, "must be ≥ 0, s"));
            }
        }
        let mut loads = Vec::with_capacity(self.loads.len());
        for (i, l) in self.loads.iter().enumerate() {
            let p = format!("loads[{i}]");
            let (f, field) = l.load(&p)?;
            if let Some(k) = f.iter().position(|v| !v.is_finite()) {
                return Err(CaseError::value(format!("{field}[{k}]"), f[k], "must be finite"));
            }
            loads.push(TransientLoad {
                node: node(format!("{p}.node"), l.node)?,
                f,
                history: l.history.history(&format!("{p}.history"))?,
            });
        }
        let mut motions = Vec::with_capacity(self.motions.len());
        for (i, m) in self.motions.iter().enumerate() {
            let p = format!("motions[{i}]");
            let history = m.history.history(&format!("{p}.history"))?;
            if history.value(0.0) != 0.0 {
                return Err(CaseError::new(
                    format!("{p}.history"),
                    "a prescribed motion must be 0 at t = 0 (the model starts at rest): start a step after 0 or use a ramp",
                ));
            }
            let dof = m.dof.dof();
            let value = if dof.index() >= 3 { m.value.to_radians() } else { m.value };
            if !value.is_finite() {
                return Err(CaseError::value(format!("{p}.value"), m.value, "must be finite"));
            }
            motions.push(PrescribedMotion {
                node: node(format!("{p}.node"), m.node)?,
                dof,
                value,
                history,
            });
        }
        for (i, r) in self.record.iter().enumerate() {
            let n = node(format!("record[{i}].node"), r.node)?;
            match r.dof {
                Some(d) => opts.record.push(NodeDof { node: n, dof: d.dof() }),
                None => opts.record.extend(Dof::ALL.map(|dof| NodeDof { node: n, dof })),
            }
        }
        if self.nonlinear {
            self.check_nonlinear()?;
        }
        if let Some(f) = self.frames {
            if f > 10_000 {
                return Err(CaseError::value("frames", f, "must be at most 10000"));
            }
        }
        Ok((opts, loads, motions))
    }

    fn inputs(&self, model: &crate::fem::Model, index: &[Option<usize>], hinges: &[crate::case::mesh::BuiltHinge]) -> Result<Inputs, CaseError> {
        let (mut opts, loads, motions) = self.options(model.nodes.len())?;
        if loads.is_empty() && motions.is_empty() {
            return Err(CaseError::new(
                "loads",
                "the transient has no loads and no motions, so the model stays at rest: give `loads` (node, force, history) or `motions` (node, dof, value, history)",
            ));
        }
        self.check_motions(model, &motions)?;
        let mut element_beta = Vec::new();
        for e in &self.damping.elements {
            if let Some(ie) = index.get(e.element).copied().flatten() {
                element_beta.push((ie, e.beta));
                // A superelement's pieces follow its first.
                if let Some(se) = model.superelements.iter().find(|s| s.elements.start == ie) {
                    element_beta.extend(se.elements.clone().skip(1).map(|s| (s, e.beta)));
                }
                // Inner segments of a split hinge are appended after the case's elements.
                if let Some(h) = hinges.iter().find(|h| h.case_element == e.element && h.segments > 1) {
                    let first_inner = h.last + 2 - h.segments;
                    element_beta.extend((first_inner..=h.last).map(|s| (s, e.beta)));
                }
            }
        }
        opts.damping = Damping {
            alpha: self.damping.alpha,
            beta: self.damping.beta,
            element_beta,
        };
        let frames = self.frames.unwrap_or(50).min(self.steps + 1);
        opts.snapshot_every = if frames == 0 { 0 } else { (self.steps / frames.max(1)).max(1) };
        Ok(Inputs { loads, motions, opts })
    }
}

/// `transient`: the analysis kind.
pub struct TransientKind;

impl Analysis for TransientKind {
    type Case = TransientCase;
    type Result = TransientResult;

    fn check(case: &Self::Case) -> Result<(), CaseError> {
        let (model, hinges, index) = case.model.build_indexed(false, case.nonlinear)?;
        case.inputs(&model, &index, &hinges).map(|_| ())
    }
    fn run(case: &Self::Case, ctx: &mut Ctx) -> Result<Self::Result, RunError> {
        let (model, hinges, index) = case.model.build_indexed(false, case.nonlinear)?;
        let mut inputs = case.inputs(&model, &index, &hinges)?;
        if !ctx.with_files {
            inputs.opts.snapshot_every = 0;
        }
        let raw = if case.nonlinear {
            let nl = crate::fem::nonlinear::NonlinearOptions::default();
            crate::fem::nonlinear::solve_transient_nonlinear(&model, &inputs.loads, &inputs.opts, &nl)
        } else {
            crate::fem::transient::solve_transient(&model, &inputs.loads, &inputs.motions, &inputs.opts)
        }
        .map_err(|e| RunError::Analysis(super::AnalysisError::new("transient", e.to_string())))?;
        ctx.warnings.extend(raw.warnings.iter().cloned());
        ctx.warnings.extend(crate::analysis::common::warn::equilibrium_floor_warning("nonlinear transient", raw.equilibrium));
        if ctx.with_files {
            ctx.files.extend(output::files(&model, &inputs.opts, &raw)?);
        }
        let mut r = output::result(case, &inputs.opts, &raw);
        let segments = crate::analysis::common::warn::default_segments_note(&hinges);
        let promoted = case.model.promotion_note();
        for note in crate::fem::superelement::notes(&model).into_iter().chain(segments).chain(promoted) {
            r.model = format!("{}; {note}", r.model);
        }
        Ok(r)
    }
    fn report(r: &Self::Result) -> Report {
        output::report(r)
    }
    fn materials(case: &Self::Case) -> Vec<UsedMaterial> {
        named_materials(&case.model.materials)
    }
    fn mesh_model(case: &Self::Case) -> Option<&MeshSpec> {
        Some(&case.model)
    }
}
