//! Exact-constraint check of a model: the bodies (sets of nodes joined rigidly) as rigid
//! bodies of six DOFs each, the constraint Jacobian of the joints (ties), supports and
//! prescribed displacements (drives) between them and the ground, and its rank analysis.
//!
//! With n bodies and m constraint equations of rank r, the model has m − r redundant
//! constraints (over-constraint, the statically indeterminate part: constraint forces that no
//! load determines) and 6n − r free motions (mobility, under-constraint). This is the
//! mobility count of Grübler–Kutzbach, M = 6n − Σ cᵢ, made exact by the rank
//! (M = 6n − r, the redundancy m − r being the amount by which Grübler–Kutzbach undercounts):
//! the approach of SPACAR's over-constraint check (J. P. Meijaard, D. M. Brouwer, J. B.
//! Jonker, "Analytical and experimental investigation of a parallel leaf spring guidance",
//! Multibody Syst. Dyn. 23 (2010) 77–97; D. M. Brouwer, J. P. Meijaard, J. B. Jonker,
//! "Large deflection stiffness analysis of parallel prismatic leaf-spring flexures", Precis.
//! Eng. 37 (2013) 505–521) and of the design rules in D. L. Blanding, *Exact Constraint:
//! Machine Design Using Kinematic Principles*, ASME Press, 1999.
//!
//! Body twist coordinates: per body, the velocity v of its reference point c (the mean of its
//! nodes) and L·ω (L the model size), so that every column has the unit of a length rate. A
//! translation constraint along e at point p between bodies A and B is
//! e·(v_A + ω_A × (p − c_A)) − e·(v_B + ω_B × (p − c_B)) = 0, a rotation constraint
//! e·(ω_A − ω_B) = 0 (the ground has no columns); every row is scaled to unit length.

pub mod rank;
pub mod release;

use crate::fem::Model;
use nalgebra::{DMatrix, DVector, Vector3};

/// Where a constraint comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Source {
    /// `model.supports[i]`.
    Support(usize),
    /// `model.ties[i]` (a joint).
    Tie(usize),
    /// `model.load_cases[case].displacements[i]` (a drive).
    Prescribed { case: usize, index: usize },
    /// An element seen as a joint (numbered by the caller).
    Element(usize),
}

/// One scalar constraint equation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Constraint {
    pub source: Source,
    /// DOF in the node frame, 0..6 (ux uy uz rx ry rz).
    pub dof: usize,
    /// The frame axis of `dof` in global coordinates.
    pub axis: [f64; 3],
    /// The node the constraint acts on (its body).
    pub node: usize,
    /// Where it acts, mm (a tie or support: the node).
    pub at: [f64; 3],
    /// The other node of a tie; `None` for the ground.
    pub other: Option<usize>,
}

/// The frame rows of `node` (identity without a frame).
fn frame(model: &Model, node: usize) -> [[f64; 3]; 3] {
    model
        .frames
        .get(&node)
        .copied()
        .unwrap_or([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
}

/// The constraint equations of the model: supports, ties and (with `drives`) the prescribed
/// DOFs of every load case (a DOF prescribed in several load cases counted once).
pub fn model_constraints(model: &Model, drives: bool) -> Vec<Constraint> {
    let mut out = Vec::new();
    let mut push = |source, node: usize, other, fix: [bool; 6]| {
        let f = frame(model, node);
        for (dof, _) in fix.iter().enumerate().filter(|(_, on)| **on) {
            out.push(Constraint {
                source,
                dof,
                axis: f[dof % 3],
                node,
                at: model.nodes[node],
                other,
            });
        }
    };
    for (i, s) in model.supports.iter().enumerate() {
        push(Source::Support(i), s.node, None, s.fix);
    }
    for (i, t) in model.ties.iter().enumerate() {
        push(Source::Tie(i), t.a, Some(t.b), t.dofs);
    }
    if drives {
        let mut seen = std::collections::BTreeSet::new();
        for (c, lc) in model.load_cases.iter().enumerate() {
            for (index, p) in lc.displacements.iter().enumerate() {
                if seen.insert((p.node, p.dof.index())) {
                    let mut fix = [false; 6];
                    fix[p.dof.index()] = true;
                    push(Source::Prescribed { case: c, index }, p.node, None, fix);
                }
            }
        }
    }
    out
}

/// The bodies: connected sets of nodes under the rigid groups given (each group joins its
/// nodes), numbered by their smallest node.
#[derive(Debug, Clone)]
pub struct Bodies {
    /// Body of each node.
    pub of_node: Vec<usize>,
    /// Nodes of each body, ascending.
    pub members: Vec<Vec<usize>>,
}

impl Bodies {
    /// Bodies of `n_nodes` nodes joined by `groups` (union–find).
    pub fn new(n_nodes: usize, groups: &[Vec<usize>]) -> Bodies {
        let mut parent: Vec<usize> = (0..n_nodes).collect();
        fn root(p: &mut [usize], mut i: usize) -> usize {
            while p[i] != i {
                p[i] = p[p[i]];
                i = p[i];
            }
            i
        }
        for g in groups {
            for w in g.windows(2) {
                let (a, b) = (root(&mut parent, w[0]), root(&mut parent, w[1]));
                parent[a.max(b)] = a.min(b);
            }
        }
        let mut of_node = vec![usize::MAX; n_nodes];
        let mut members: Vec<Vec<usize>> = Vec::new();
        let mut id = vec![usize::MAX; n_nodes];
        for (n, body) in of_node.iter_mut().enumerate() {
            let r = root(&mut parent, n);
            if id[r] == usize::MAX {
                id[r] = members.len();
                members.push(Vec::new());
            }
            *body = id[r];
            members[id[r]].push(n);
        }
        Bodies { of_node, members }
    }
}

/// Largest model the check accepts: 6·bodies columns and constraint rows (the rank analysis is
/// dense, O(rows·columns·min) plus an SVD of the columns squared).
pub const MAX_COLUMNS: usize = 1200;
/// Largest number of constraint equations the check accepts.
pub const MAX_ROWS: usize = 6000;

/// The Jacobian (rows: `constraints`, columns: six per body) of the twist coordinates.
pub fn jacobian(nodes: &[[f64; 3]], bodies: &Bodies, constraints: &[Constraint]) -> DMatrix<f64> {
    let l = model_size(nodes);
    let centres = centres(nodes, bodies);
    let mut j = DMatrix::zeros(constraints.len(), 6 * bodies.members.len());
    for (r, c) in constraints.iter().enumerate() {
        let e = Vector3::from(c.axis);
        let p = Vector3::from(c.at);
        let sides = [(c.node, 1.0)].into_iter().chain(c.other.map(|o| (o, -1.0)));
        for (n, sign) in sides {
            let b = bodies.of_node[n];
            let (lin, ang) = if c.dof < 3 {
                (e, (p - centres[b]).cross(&e) / l)
            } else {
                (Vector3::zeros(), e)
            };
            for k in 0..3 {
                j[(r, 6 * b + k)] += sign * lin[k];
                j[(r, 6 * b + 3 + k)] += sign * ang[k];
            }
        }
        let norm = j.row(r).norm();
        if norm > 1e-12 {
            j.row_mut(r).scale_mut(1.0 / norm);
        } else {
            j.row_mut(r).fill(0.0);
        }
    }
    j
}

/// Reference point of each body: the mean of its nodes.
fn centres(nodes: &[[f64; 3]], bodies: &Bodies) -> Vec<Vector3<f64>> {
    bodies
        .members
        .iter()
        .map(|m| m.iter().map(|&n| Vector3::from(nodes[n])).sum::<Vector3<f64>>() / m.len() as f64)
        .collect()
}

/// Diagonal of the nodes' bounding box, mm (1 for a single point).
pub fn model_size(nodes: &[[f64; 3]]) -> f64 {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for x in nodes {
        for k in 0..3 {
            lo[k] = lo[k].min(x[k]);
            hi[k] = hi[k].max(x[k]);
        }
    }
    let d = (0..3).map(|k| (hi[k] - lo[k]).powi(2)).sum::<f64>().sqrt();
    if d > 0.0 {
        d
    } else {
        1.0
    }
}

/// How one body moves in a free motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BodyMotion {
    /// Translation along `direction` (unit).
    Translation { direction: [f64; 3] },
    /// Rotation about the axis along `direction` (unit) through `point` (the point of the
    /// axis nearest the body's reference point), with `pitch` mm/rad (0: pure rotation).
    Rotation {
        direction: [f64; 3],
        point: [f64; 3],
        pitch: f64,
    },
}

/// One free motion: the bodies that move, with their rate (signed against the direction; the
/// largest ±1, the first body's positive).
#[derive(Debug, Clone, PartialEq)]
pub struct Motion {
    pub bodies: Vec<(usize, BodyMotion, f64)>,
}

/// The result of the check.
#[derive(Debug, Clone)]
pub struct Diagnosis {
    /// Rank of the constraint Jacobian.
    pub rank: usize,
    /// Rank by the singular values (above [`rank::DEPENDENT`] times the largest): equals
    /// `rank` unless the constraints are nearly dependent.
    pub svd_rank: usize,
    /// Smallest singular value of the independent part (rows of unit length): how far the
    /// constraints are from a further dependency (1 for orthogonal constraints).
    pub min_singular: f64,
    /// Redundant constraints: (constraint, [(independent constraint, coefficient)]).
    pub redundant: Vec<(usize, Vec<(usize, f64)>)>,
    /// The free motions (a basis, one per mobility).
    pub motions: Vec<Motion>,
}

/// The check, or why the model is too large for it.
pub fn diagnose(nodes: &[[f64; 3]], bodies: &Bodies, constraints: &[Constraint]) -> Result<Diagnosis, String> {
    let cols = 6 * bodies.members.len();
    if cols > MAX_COLUMNS || constraints.len() > MAX_ROWS {
        return Err(format!(
            "{} bodies and {} constraint equations: the dense check takes at most {} bodies and {} equations (join more nodes into bodies)",
            bodies.members.len(),
            constraints.len(),
            MAX_COLUMNS / 6,
            MAX_ROWS
        ));
    }
    let j = jacobian(nodes, bodies, constraints);
    let a = rank::analyse(&j);
    let s = &a.singular_values;
    let top = s.first().copied().unwrap_or(0.0);
    let svd_rank = s.iter().filter(|&&v| v > rank::DEPENDENT * top.max(1.0)).count();
    let l = model_size(nodes);
    let centres = centres(nodes, bodies);
    Ok(Diagnosis {
        rank: a.independent.len(),
        svd_rank,
        min_singular: s.get(a.independent.len().max(1) - 1).copied().unwrap_or(0.0),
        redundant: a.redundant,
        motions: a.null_space.iter().map(|q| motion(q, &centres, l)).collect(),
    })
}

/// The screw of every moving body in the null vector `q`.
fn motion(q: &DVector<f64>, centres: &[Vector3<f64>], l: f64) -> Motion {
    let twist = |b: usize| {
        (
            Vector3::new(q[6 * b], q[6 * b + 1], q[6 * b + 2]),
            Vector3::new(q[6 * b + 3], q[6 * b + 4], q[6 * b + 5]),
        )
    };
    let size = |b: usize| {
        let (v, w) = twist(b);
        v.norm().max(w.norm())
    };
    let big = (0..centres.len()).map(size).fold(0.0_f64, f64::max);
    let mut bodies = Vec::new();
    for (b, c) in centres.iter().enumerate() {
        if size(b) <= 1e-9 * big {
            continue;
        }
        let (v, w) = twist(b);
        let (dir, rate) = if w.norm() <= 1e-9 * big {
            (v, v.norm())
        } else {
            (w, w.norm())
        };
        // Sign: the largest component of the direction positive.
        let k = dir.iamax();
        let sign = if dir[k] < 0.0 { -1.0 } else { 1.0 };
        let unit = clean(dir * (sign / dir.norm()), 1.0);
        let m = if w.norm() <= 1e-9 * big {
            BodyMotion::Translation { direction: unit.into() }
        } else {
            let om = w / l;
            let p = c + om.cross(&v) / om.norm_squared();
            let pitch = om.dot(&v) / om.norm_squared();
            BodyMotion::Rotation {
                direction: unit.into(),
                point: clean(p, l).into(),
                pitch: if pitch.abs() <= 1e-9 * l { 0.0 } else { pitch },
            }
        };
        bodies.push((b, m, sign * rate / big));
    }
    // A free motion has no sign: the first body's rate positive.
    if bodies.first().is_some_and(|b| b.2 < 0.0) {
        bodies.iter_mut().for_each(|b| b.2 = -b.2);
    }
    Motion { bodies }
}

/// `v` with components below 1e-12 of `scale` set to +0 (no −0, no roundoff residue).
fn clean(v: Vector3<f64>, scale: f64) -> Vector3<f64> {
    v.map(|c| if c.abs() < 1e-12 * scale { 0.0 } else { c })
}
