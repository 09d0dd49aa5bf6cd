//! Names of the `constraints` result: constraints in joint terms with their case-file paths,
//! bodies, free motions, releases.

use super::{motion_word, Kinematic};
use crate::case::mesh::{ElementSpec, JointKind, MeshSpec};
use crate::kinematics::exact::release::{Candidate, Kind};
use crate::kinematics::exact::{BodyMotion, Constraint, Motion, Source};
use crate::report::markdown::sig;
use serde::Serialize;

/// A body of the check.
#[derive(Debug, Clone, Serialize)]
pub struct BodyOut {
    /// Body number (as in the texts).
    pub body: usize,
    /// Its nodes.
    pub nodes: Vec<usize>,
    /// Paths of the elements that join it (beam, hinge, shell4, rigid).
    pub elements: Vec<String>,
}

/// A redundant constraint.
#[derive(Debug, Clone, Serialize)]
pub struct RedundancyOut {
    /// Case-file path of the joint, support or load case.
    pub path: String,
    /// The constraint in joint terms.
    pub constraint: String,
    /// The independent constraints it is a combination of (empty: it ties a body to itself).
    pub with: Vec<String>,
    /// One sentence.
    pub text: String,
}

/// One free motion.
#[derive(Debug, Clone, Serialize)]
pub struct MotionOut {
    /// The moving bodies.
    pub bodies: Vec<BodyMotionOut>,
    /// One sentence.
    pub text: String,
}

/// How one body moves in a free motion.
#[derive(Debug, Clone, Serialize)]
pub struct BodyMotionOut {
    pub body: usize,
    /// `translation`, `rotation` or `screw`.
    pub motion: &'static str,
    /// Translation direction or rotation axis (unit, largest component positive).
    pub direction: [f64; 3],
    /// A point of the rotation axis (the one nearest the body's centre), mm; absent for a
    /// translation.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub point: Option<[f64; 3]>,
    /// Pitch of a screw, mm/rad (0 for a rotation).
    pub pitch_mm_per_rad: f64,
    /// Relative rate (translation speed, or angular rate times the model size), the largest 1.
    pub share: f64,
}

/// A suggested release.
#[derive(Debug, Clone, Serialize)]
pub struct SuggestionOut {
    /// Case-file path of the joint or support to change.
    pub path: String,
    /// What to make it.
    pub change: String,
    /// Redundant constraints left after this and the releases before it.
    pub redundant_after: usize,
}

/// Names the parts of a model for the result.
pub struct Names<'a> {
    spec: &'a MeshSpec,
    k: &'a Kinematic,
}

/// A number for a text: four significant digits, trailing zeros dropped.
fn num(v: f64) -> String {
    if v.abs() < 1e-9 {
        return "0".into();
    }
    let s = sig(v, 4);
    if s.contains('.') && !s.contains('e') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// `[x, y, z]` for a text.
pub fn vec3(v: [f64; 3]) -> String {
    format!("[{}, {}, {}]", num(v[0]), num(v[1]), num(v[2]))
}

impl<'a> Names<'a> {
    pub fn new(spec: &'a MeshSpec, k: &'a Kinematic) -> Self {
        Names { spec, k }
    }

    /// The case element a joint source names.
    fn element(&self, s: Source) -> Option<usize> {
        match s {
            Source::Tie(t) => self.k.joint_elements.get(t).copied(),
            Source::Element(e) => Some(e),
            _ => None,
        }
    }

    /// Path and description of the joint, support or drive of constraint `row`.
    fn owner(&self, row: usize) -> (String, String) {
        let c = &self.k.constraints[row];
        match c.source {
            // Supports the nodes added by "shell_elements": "shell9" inherited are not in the case.
            Source::Support(i) if self.spec.promoted.as_ref().is_some_and(|p| i >= p.first_support) => (
                "shell_elements".to_string(),
                format!("the support added node {} inherits from the ends of its edge (\"shell_elements\": \"shell9\")", c.node),
            ),
            Source::Support(i) => (format!("supports[{i}]"), format!("supports[{i}] (node {})", c.node)),
            Source::Prescribed { case, .. } => {
                let name = self.spec.load_cases.get(case).map(|l| l.name.as_str()).unwrap_or("");
                (format!("load_cases[{case}]"), format!("load_cases[{case}] (\"{name}\", node {})", c.node))
            }
            s => {
                let e = self.element(s).unwrap_or(0);
                let what = match self.spec.elements.get(e) {
                    Some(ElementSpec::Joint { kind, .. }) => format!("{} joint", kind_name(*kind)),
                    _ => "hinge seen as a revolute joint".into(),
                };
                let other = c.other.map(|o| format!("–{o}")).unwrap_or_default();
                (format!("elements[{e}]"), format!("elements[{e}] ({what}, nodes {}{other})", c.node))
            }
        }
    }

    /// Name of frame axis `i` of the joint (or support) of constraint `row`.
    fn axis_name(&self, row: usize, i: usize) -> String {
        let c = &self.k.constraints[row];
        let joint = self.element(c.source).and_then(|e| self.spec.elements.get(e));
        let name = match joint {
            Some(ElementSpec::Joint { kind, .. }) => match (kind, i) {
                (JointKind::Universal, 0) => "its axis",
                (JointKind::Universal, 1) => "its axis2",
                (JointKind::Universal, _) => "the normal to its axis and axis2",
                (JointKind::Spherical | JointKind::Weld, _) => ["its frame's x", "its frame's y", "its frame's z"][i],
                (_, _) => ["its axis", "its first normal", "its second normal"][i],
            },
            Some(ElementSpec::Hinge { .. }) => ["its axis (node to node)", "its compliant axis", "its thin direction"][i],
            _ => ["x", "y", "z"][i],
        };
        format!("{name} {}", vec3(self.k.frames[row][i]))
    }

    /// The constraint of `row` in joint terms.
    pub fn constraint(&self, row: usize) -> String {
        let c = &self.k.constraints[row];
        let motion = if c.dof < 3 { "translation along" } else { "rotation about" };
        let what = match c.source {
            Source::Prescribed { .. } => format!("prescribed {motion}"),
            _ => motion.to_string(),
        };
        format!("{}: {what} {}", self.owner(row).1, self.axis_name(row, c.dof % 3))
    }

    /// A redundant constraint and its partners.
    pub fn redundancy(&self, row: usize, with: &[(usize, f64)]) -> RedundancyOut {
        let constraint = self.constraint(row);
        let with: Vec<String> = with.iter().map(|(r, _)| self.constraint(*r)).collect();
        let text = if with.is_empty() {
            format!("{constraint} is redundant: it ties a body to itself (both nodes on one body)")
        } else {
            let shown: Vec<&str> = with.iter().take(6).map(String::as_str).collect();
            let more = with.len().saturating_sub(6);
            format!(
                "{constraint} is redundant with {}{}",
                shown.join("; "),
                if more > 0 { format!(" (and {more} more)") } else { String::new() }
            )
        };
        RedundancyOut {
            path: self.owner(row).0,
            constraint,
            with,
            text,
        }
    }

    /// The elements joining body `b`.
    fn body_elements(&self, b: usize) -> Vec<String> {
        let of = &self.k.bodies.of_node;
        self.k
            .joining
            .iter()
            .filter(|&&i| {
                let first = match &self.spec.elements[i] {
                    ElementSpec::Beam { nodes, .. } | ElementSpec::Hinge { nodes, .. } => nodes[0],
                    ElementSpec::Shell4 { nodes, .. } => nodes[0],
                    ElementSpec::Shell9 { nodes, .. } => nodes[0],
                    ElementSpec::Rigid { master, .. } => *master,
                    _ => return false,
                };
                of.get(first) == Some(&b)
            })
            .map(|i| format!("elements[{i}]"))
            .collect()
    }

    /// "body k (nodes …; elements …)".
    fn body_label(&self, b: usize) -> String {
        let m = &self.k.bodies.members[b];
        let nodes: Vec<String> = m.iter().take(6).map(|n| n.to_string()).collect();
        let els = self.body_elements(b);
        let shown: Vec<&str> = els.iter().take(3).map(String::as_str).collect();
        format!(
            "body {b} (nodes {}{}{})",
            nodes.join(", "),
            if m.len() > 6 { ", …" } else { "" },
            if shown.is_empty() {
                String::new()
            } else {
                format!("; {}{}", shown.join(", "), if els.len() > 3 { ", …" } else { "" })
            }
        )
    }

    /// Every body.
    pub fn bodies(&self) -> Vec<BodyOut> {
        (0..self.k.bodies.members.len())
            .map(|b| BodyOut {
                body: b,
                nodes: self.k.bodies.members[b].clone(),
                elements: self.body_elements(b),
            })
            .collect()
    }

    /// A free motion.
    pub fn motion(&self, m: &Motion) -> MotionOut {
        let mut parts = Vec::new();
        let mut bodies = Vec::new();
        for &(b, bm, share) in &m.bodies {
            let (direction, point, pitch) = match bm {
                BodyMotion::Translation { direction } => (direction, None, 0.0),
                BodyMotion::Rotation { direction, point, pitch } => (direction, Some(point), pitch),
            };
            let word = motion_word(&bm);
            let mut t = format!("{} {word} ", self.body_label(b));
            t += &match point {
                None => format!("along {}", vec3(direction)),
                Some(p) => format!("about {} through {}", vec3(direction), vec3(p)),
            };
            if pitch != 0.0 {
                t += &format!(" (pitch {} mm/rad)", num(pitch));
            }
            if m.bodies.len() > 1 {
                t += &format!(" (rate {})", num(share));
            }
            parts.push(t);
            bodies.push(BodyMotionOut {
                body: b,
                motion: word,
                direction,
                point,
                pitch_mm_per_rad: pitch,
                share,
            });
        }
        MotionOut {
            bodies,
            text: parts.join("; with "),
        }
    }

    /// The releases applied by the search, one per joint or support DOF (a joint released
    /// twice shown with its final kind, at the place of its last release).
    pub fn suggestions(&self, cands: &[Candidate], applied: &[(usize, usize)]) -> Vec<SuggestionOut> {
        let mut out: Vec<(Source, SuggestionOut)> = Vec::new();
        for &(ic, after) in applied {
            let c = &cands[ic];
            let row = c.removes[0];
            let (path, _) = self.owner(row);
            let f = self.k.frames[row];
            let ax = |i: usize| vec3(f[i]);
            let make = match c.source {
                Source::Element(_) => format!("replace the hinge {path} by"),
                _ => format!("make {path}"),
            };
            let change = match c.kind {
                Kind::Revolute(i) => format!("{make} a revolute joint with axis {}", ax(i)),
                Kind::Universal(i, j) => format!("{make} a universal joint with axis {} and axis2 {}", ax(i), ax(j)),
                Kind::Spherical => format!("{make} a spherical joint"),
                Kind::Cylindrical(i) => format!("{make} a cylindrical joint with axis {}", ax(i)),
                Kind::Prismatic(i) => format!("{make} a prismatic joint with axis {}", ax(i)),
                Kind::SupportDof(d) => format!(
                    "free {} of {path} (node {})",
                    ["ux", "uy", "uz", "rx", "ry", "rz"][d],
                    self.k.constraints[row].node
                ),
            };
            let s = SuggestionOut {
                path,
                change,
                redundant_after: after,
            };
            let joint = !matches!(c.kind, Kind::SupportDof(_));
            out.retain(|(src, _)| !(joint && *src == c.source));
            out.push((c.source, s));
        }
        out.into_iter().map(|(_, s)| s).collect()
    }
}

/// The case-file name of a joint kind.
fn kind_name(k: JointKind) -> &'static str {
    match k {
        JointKind::Revolute => "revolute",
        JointKind::Spherical => "spherical",
        JointKind::Universal => "universal",
        JointKind::Cylindrical => "cylindrical",
        JointKind::Prismatic => "prismatic",
        JointKind::Weld => "weld",
    }
}

/// The five constraints of hinge element `e` seen as a revolute joint about its compliant axis
/// (local y: z is `up` normal to the axis) at its midpoint; none if the geometry is degenerate.
pub fn hinge_revolute(spec: &MeshSpec, e: usize, [a, b]: [usize; 2], up: [f64; 3]) -> Vec<Constraint> {
    use nalgebra::Vector3;
    let (xa, xb) = (Vector3::from(spec.nodes[a]), Vector3::from(spec.nodes[b]));
    let x = (xb - xa).normalize();
    let u = Vector3::from(up);
    let z = u - x * x.dot(&u);
    if z.norm().is_nan() || z.norm() <= 1e-9 * u.norm() || !x.iter().all(|v| v.is_finite()) {
        return Vec::new();
    }
    let z = z.normalize();
    let y = z.cross(&x);
    let rows: [[f64; 3]; 3] = [x.into(), y.into(), z.into()];
    [0, 1, 2, 3, 5]
        .map(|dof| Constraint {
            source: Source::Element(e),
            dof,
            axis: rows[dof % 3],
            node: a,
            at: ((xa + xb) / 2.0).into(),
            other: Some(b),
        })
        .to_vec()
}

/// The frame of an element seen as a joint, from its constraints (translations along x, y, z).
pub fn element_frame(constraints: &[Constraint], s: Source) -> [[f64; 3]; 3] {
    let mut f = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    for c in constraints.iter().filter(|c| c.source == s && c.dof < 3) {
        f[c.dof] = c.axis;
    }
    f
}

/// Springs between two nodes join nothing in the check: say so.
pub fn spring_warnings(spec: &MeshSpec) -> Vec<String> {
    let springs: Vec<String> = spec
        .elements
        .iter()
        .enumerate()
        .filter(|(_, e)| matches!(e, ElementSpec::Spring { nodes, .. } if nodes.len() == 2))
        .map(|(i, _)| format!("elements[{i}]"))
        .collect();
    (!springs.is_empty())
        .then(|| {
            format!(
                "springs join nothing in the exact-constraint check (they are compliant): {}",
                springs.join(", ")
            )
        })
        .into_iter()
        .collect()
}
