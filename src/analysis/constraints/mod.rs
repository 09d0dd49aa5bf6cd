//! The `constraints` analysis: exact-constraint check of a mesh model (see
//! [`crate::kinematics::exact`]): redundant constraints named in joint terms with their
//! case-file paths, free motions named by body, and releases that remove the redundancy.

mod report;
mod text;

use crate::case::fields::case_struct;
use crate::analysis::common::kind::{Analysis, Ctx, UsedMaterial};
use super::{AnalysisError, Report, RunError};
use crate::case::fem_case::{model_rules, parse_with_model};
use crate::case::gmsh::GmshMapping;
use crate::case::mesh::{ElementSpec, MeshSpec};
use crate::case::CaseError;
use crate::kinematics::exact::{self, release, Bodies, BodyMotion, Constraint, Source};
use serde::{Deserialize, Serialize};
use serde_json::Value;

case_struct! {
    /// `"analysis": "constraints"`: over- and under-constraint of a model whose bodies are taken
    /// rigid. A body is a set of nodes joined by beam, hinge, shell4 or rigid elements (and
    /// rigid links); `joint` elements, supports and prescribed displacements constrain the bodies;
    /// springs, masses and the elements listed in `compliant` join nothing.
    #[derive(Debug, Clone, schemars::JsonSchema)]
    #[serde(deny_unknown_fields)]
    #[schemars(extend("allOf" = model_rules(false)))]
    pub struct ConstraintsCase {
        /// Indices into `elements` of beam, hinge or shell4 elements taken as compliant: they join
        /// nothing, so their nodes may belong to different bodies (default none).
        #[serde(default)]
        pub compliant: Vec<usize>,
        /// Hinge elements as `"rigid"` (default: they join their nodes into one body) or as
        /// `"revolute"`: an ideal revolute joint about the hinge's compliant axis (local y) at its
        /// midpoint, between the bodies of its two nodes (the pseudo-rigid-body view of a notch
        /// flexure).
        #[serde(default)]
        pub hinges: HingeView,
        /// Prescribed displacements of the load cases count as constraints (drives, default true);
        /// a DOF prescribed in several load cases counts once.
        #[serde(default = "yes")]
        pub drives: bool,
        include model_source {
            /// Free text saying what the model is (not used by the analysis).
            description,
            /// Mesh file, as for `static`: a JSON mesh file or a Gmsh `.msh` file.
            mesh,
            /// Physical-group mapping of a Gmsh `.msh` mesh (only with a `.msh` mesh, which needs it).
            gmsh,
            /// The model.
            model,
        }
    }
}

/// How the check sees hinge elements.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum HingeView {
    /// A rigid part of the body.
    #[default]
    Rigid,
    /// An ideal revolute joint about the compliant axis (local y) at the midpoint.
    Revolute,
}

fn yes() -> bool {
    true
}

/// The options of a `constraints` case besides its model (each optional).
#[derive(Debug, Clone, Deserialize)]
#[serde(default, deny_unknown_fields)]
struct Options {
    compliant: Vec<usize>,
    hinges: HingeView,
    drives: bool,
    description: Option<String>,
    mesh: Option<String>,
    gmsh: Option<GmshMapping>,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            compliant: Vec::new(),
            hinges: HingeView::Rigid,
            drives: true,
            description: None,
            mesh: None,
            gmsh: None,
        }
    }
}

const OWN: [&str; 7] = ["analysis", "description", "mesh", "gmsh", "compliant", "hinges", "drives"];

/// Parses a `constraints` case; files it names resolve against `base` first.
pub fn parse(value: Value, base: &crate::case::Source<'_>) -> Result<ConstraintsCase, CaseError> {
    let (o, model) =
        parse_with_model(value, "constraints", &OWN, &[], base, |o: &Options| (o.mesh.as_deref(), o.gmsh.as_ref()))?;
    let case = ConstraintsCase {
        description: o.description,
        mesh: o.mesh,
        gmsh: o.gmsh,
        compliant: o.compliant,
        hinges: o.hinges,
        drives: o.drives,
        model,
    };
    Ok(case)
}

impl ConstraintsCase {
    /// Validates the case once (the `compliant` list, then the model): the model seen by the
    /// check, which [`diagnose`] takes.
    pub fn validate(&self) -> Result<Kinematic, CaseError> {
        self.check_compliant()?;
        kinematic(&self.model, &self.compliant, self.hinges, self.drives)
    }

    /// Each `compliant` entry names a beam, hinge or shell4 element.
    pub fn check_compliant(&self) -> Result<(), CaseError> {
        let n = self.model.elements.len();
        for (i, &e) in self.compliant.iter().enumerate() {
            let p = format!("compliant[{i}]");
            match self.model.elements.get(e) {
                None => {
                    return Err(CaseError::value(
                        p,
                        e,
                        format!("no such element: the model has {n} elements (indices 0 … {})", n.max(1) - 1),
                    ))
                }
                Some(
                    ElementSpec::Beam { .. }
                    | ElementSpec::Hinge { .. }
                    | ElementSpec::Shell4 { .. }
                    | ElementSpec::Shell9 { .. },
                ) => {}
                Some(_) => {
                    return Err(CaseError::value(
                        p,
                        e,
                        "only beam, hinge, shell4 and shell9 elements can be taken as compliant (springs and masses join nothing anyway; joints and rigid links are the constraints)",
                    ))
                }
            }
        }
        Ok(())
    }
}

/// Most releases suggested.
pub const MAX_SUGGESTIONS: usize = 12;

/// The result of a `constraints` run.
#[derive(Debug, Clone, Serialize)]
pub struct ConstraintsResult {
    /// Number of bodies (the ground not counted).
    pub bodies: usize,
    /// Scalar constraint equations (joints, supports, drives).
    pub constraints: usize,
    /// Rank of the constraint Jacobian.
    pub rank: usize,
    /// Grübler–Kutzbach count 6·bodies − constraints (negative: at least that many redundant).
    pub grubler_kutzbach: i64,
    /// Redundant constraints (degree of over-constraint), constraints − rank.
    pub redundant: usize,
    /// Free motions (mobility, degree of under-constraint), 6·bodies − rank.
    pub mobility: usize,
    /// Smallest singular value of the independent constraints (unit rows; 1 = orthogonal,
    /// near 0 = nearly dependent).
    pub smallest_singular_value: f64,
    /// The bodies.
    pub body_list: Vec<text::BodyOut>,
    /// Each redundant constraint and the independent ones it depends on.
    pub redundancies: Vec<text::RedundancyOut>,
    /// A basis of the free motions.
    pub free_motions: Vec<text::MotionOut>,
    /// Releases that remove redundant constraints without adding a free motion, in order.
    pub suggestions: Vec<text::SuggestionOut>,
}

/// `constraints`: the exact-constraint check. Its hinge elements are rigid or ideal joints, so
/// their calibration (`Analysis::mesh_model`) does not enter and is not warned about.
pub struct ConstraintsAnalysis;

impl Analysis for ConstraintsAnalysis {
    type Case = ConstraintsCase;
    type Result = ConstraintsResult;

    fn check(case: &Self::Case) -> Result<(), CaseError> {
        case.validate().map(drop)
    }
    fn run(case: &Self::Case, ctx: &mut Ctx) -> Result<Self::Result, RunError> {
        let (r, warnings) = diagnose(&case.model, case.validate()?, true)?;
        ctx.warnings = warnings;
        Ok(r)
    }
    fn report(r: &Self::Result) -> Report {
        report::report(r)
    }
    fn materials(case: &Self::Case) -> Vec<UsedMaterial> {
        crate::analysis::common::kind::named_materials(&case.model.materials)
    }
}

/// The model seen by the check: its constraints and bodies.
pub struct Kinematic {
    pub constraints: Vec<Constraint>,
    pub bodies: Bodies,
    /// Case element index of each tie (the joint elements in order).
    pub joint_elements: Vec<usize>,
    /// Case elements that join their nodes into a body.
    pub joining: Vec<usize>,
    /// Frame of each constraint's joint or support node (rows: local x, y, z).
    pub frames: Vec<[[f64; 3]; 3]>,
}

/// The bodies and constraints of a model (validated by building it): bodies joined by the
/// beam, hinge (unless seen as revolute joints), shell4 and rigid elements not listed in
/// `compliant`, and by rigid links.
pub fn kinematic(
    spec: &MeshSpec,
    compliant: &[usize],
    hinges: HingeView,
    drives: bool,
) -> Result<Kinematic, CaseError> {
    let mut model = spec.build_model(false)?;
    let n = spec.nodes.len();
    // Superelement modal nodes (after the case's nodes) carry no motion of a body.
    model.supports.retain(|s| s.node < n);
    let mut groups: Vec<Vec<usize>> = spec
        .rigid_links
        .iter()
        .map(|r| std::iter::once(r.master).chain(r.slaves.iter().copied()).collect())
        .collect();
    let mut joint_elements = Vec::new();
    let mut joining = Vec::new();
    let mut extra = Vec::new();
    for (i, e) in spec.elements.iter().enumerate() {
        let rigid = !compliant.contains(&i);
        let group: Vec<usize> = match e {
            ElementSpec::Beam { nodes, .. } if rigid => nodes.to_vec(),
            ElementSpec::Shell4 { nodes, .. } if rigid => nodes.to_vec(),
            ElementSpec::Shell9 { nodes, .. } if rigid => nodes.to_vec(),
            ElementSpec::Superelement { nodes, .. } if rigid => nodes.clone(),
            ElementSpec::Hinge { nodes, up, .. } if rigid => match hinges {
                HingeView::Rigid => nodes.to_vec(),
                HingeView::Revolute => {
                    extra.extend(text::hinge_revolute(spec, i, *nodes, *up));
                    continue;
                }
            },
            ElementSpec::Rigid { master, slaves } => std::iter::once(*master).chain(slaves.iter().copied()).collect(),
            ElementSpec::Joint { .. } => {
                joint_elements.push(i);
                continue;
            }
            _ => continue,
        };
        groups.push(group);
        joining.push(i);
    }
    let mut constraints = exact::model_constraints(&model, drives);
    constraints.extend(extra);
    let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let frames = constraints
        .iter()
        .map(|c| match c.source {
            Source::Element(_) => text::element_frame(&constraints, c.source),
            _ => model.frames.get(&c.node).copied().unwrap_or(identity),
        })
        .collect();
    Ok(Kinematic {
        constraints,
        bodies: Bodies::new(n, &groups),
        joint_elements,
        joining,
        frames,
    })
}

/// Runs the check on a model (with the search of releases when `suggest`): the result and its
/// warnings.
pub fn check(
    spec: &MeshSpec,
    compliant: &[usize],
    hinges: HingeView,
    drives: bool,
    suggest: bool,
) -> Result<(ConstraintsResult, Vec<String>), RunError> {
    diagnose(spec, kinematic(spec, compliant, hinges, drives)?, suggest)
}

/// [`check`] of the model `k` seen by the check, built from `spec` (e.g. by
/// [`ConstraintsCase::validate`]).
pub fn diagnose(spec: &MeshSpec, k: Kinematic, suggest: bool) -> Result<(ConstraintsResult, Vec<String>), RunError> {
    let nodes = &spec.nodes;
    let d = exact::diagnose(nodes, &k.bodies, &k.constraints).map_err(|e| AnalysisError::new("model", e))?;
    let names = text::Names::new(spec, &k);
    let mut warnings = text::spring_warnings(spec);
    let j = exact::jacobian(nodes, &k.bodies, &k.constraints);
    let cands = release::candidates(&k.constraints);
    let suggestions = match release::search(&j, &cands, if suggest { MAX_SUGGESTIONS } else { 0 }) {
        Some(applied) => names.suggestions(&cands, &applied),
        None => {
            warnings.push("the model is too large for the search of releases: no suggestions".into());
            Vec::new()
        }
    };
    if d.svd_rank != d.rank {
        warnings.push(format!(
            "the singular values give rank {} where the row-by-row decision gives {}: some constraints are nearly dependent (smallest singular value {:.3e}); the counts are those of the row-by-row decision",
            d.svd_rank, d.rank, d.min_singular
        ));
    }
    let m = k.constraints.len();
    if k.bodies.members.len() == 1 && m > d.rank {
        warnings.push("the whole model is one rigid body (every element is taken rigid): its redundant constraints are the supports beyond six, as in any clamped beam or plate; list the deformable elements in `compliant`, or see hinges as joints with `\"hinges\": \"revolute\"`, to check the mechanism".into());
    }
    let r = ConstraintsResult {
        bodies: k.bodies.members.len(),
        constraints: m,
        rank: d.rank,
        grubler_kutzbach: 6 * k.bodies.members.len() as i64 - m as i64,
        redundant: m - d.rank,
        mobility: 6 * k.bodies.members.len() - d.rank,
        smallest_singular_value: d.min_singular,
        body_list: names.bodies(),
        redundancies: d.redundant.iter().map(|(row, with)| names.redundancy(*row, with)).collect(),
        free_motions: d.motions.iter().map(|mo| names.motion(mo)).collect(),
        suggestions,
    };
    Ok((r, warnings))
}

/// The error of a static solve, with the exact-constraint check appended when the solve found
/// a mechanism, an unconstrained DOF or a free body (`e` unchanged otherwise, or when the check
/// itself cannot run).
pub fn singular_hint(e: AnalysisError, spec: &MeshSpec) -> AnalysisError {
    let singular = ["mechanism", "free body"].iter().any(|w| e.message.contains(w));
    let Some((r, _)) = singular.then(|| check(spec, &[], HingeView::Rigid, true, false).ok()).flatten() else {
        return e;
    };
    let motions: Vec<String> = r.free_motions.iter().take(3).map(|m| m.text.clone()).collect();
    let more = r.free_motions.len().saturating_sub(3);
    let hint = format!(
        "exact-constraint check (elements rigid; `\"analysis\": \"constraints\"` gives the full report): {} free motion{}, {} redundant constraint{}{}{}",
        r.mobility,
        if r.mobility == 1 { "" } else { "s" },
        r.redundant,
        if r.redundant == 1 { "" } else { "s" },
        if motions.is_empty() { String::new() } else { format!("; free: {}", motions.join("; ")) },
        if more > 0 { format!(" (and {more} more)") } else { String::new() }
    );
    AnalysisError::new(e.context, format!("{}\n{hint}", e.message))
}

/// Which kind of motion a body makes (for the text).
pub(crate) fn motion_word(m: &BodyMotion) -> &'static str {
    match m {
        BodyMotion::Translation { .. } => "translation",
        BodyMotion::Rotation { pitch, .. } if *pitch != 0.0 => "screw",
        BodyMotion::Rotation { .. } => "rotation",
    }
}
