//! Releases that remove redundant constraints without adding a free motion: a joint made a kind
//! that frees more of its DOFs (a revolute joint made universal, spherical or cylindrical …),
//! or one supported DOF freed. Chosen greedily: at each step the release freeing the most
//! redundant constraints while keeping the rank (mobility unchanged), the first in the
//! candidate order on ties; then the next, until no redundancy is left or no release helps.
//! This is the exact-constraint design step of Blanding (*Exact Constraint*, 1999, ch. 3):
//! every redundant constraint removed, none of the needed ones.

use super::{rank, Constraint, Source};
use nalgebra::DMatrix;
use std::collections::BTreeSet;

/// A joint kind, or a freed support DOF, in the frame of the joint (support) node: axes are
/// frame axes 0, 1, 2 (local x, y, z).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// Rotation about axis i free.
    Revolute(usize),
    /// Rotations about axes i (`axis`) and j (`axis2`) free.
    Universal(usize, usize),
    /// All rotations free.
    Spherical,
    /// Translation along and rotation about axis i free.
    Cylindrical(usize),
    /// Translation along axis i free.
    Prismatic(usize),
    /// One support DOF (0..6) freed.
    SupportDof(usize),
}

impl Kind {
    /// The DOFs (0..6, frame) the kind leaves free.
    pub fn free(self) -> Vec<usize> {
        match self {
            Kind::Revolute(i) => vec![3 + i],
            Kind::Universal(i, j) => vec![3 + i, 3 + j],
            Kind::Spherical => vec![3, 4, 5],
            Kind::Cylindrical(i) => vec![i, 3 + i],
            Kind::Prismatic(i) => vec![i],
            Kind::SupportDof(d) => vec![d],
        }
    }

    /// Joint kinds, fewest freed DOFs first.
    fn joints() -> Vec<Kind> {
        let mut v: Vec<Kind> = (0..3).map(Kind::Prismatic).collect();
        v.extend((0..3).map(Kind::Revolute));
        v.extend([(0, 1), (0, 2), (1, 2)].map(|(i, j)| Kind::Universal(i, j)));
        v.extend((0..3).map(Kind::Cylindrical));
        v.push(Kind::Spherical);
        v
    }
}

/// A release to try: a kind for one joint (or support DOF) and the constraint equations it
/// removes.
#[derive(Debug, Clone, PartialEq)]
pub struct Candidate {
    /// The joint (tie) or support.
    pub source: Source,
    pub kind: Kind,
    /// Indices into the constraints.
    pub removes: Vec<usize>,
}

/// The candidates: every joint kind that frees more than a joint does now (each joint's in order
/// of freed DOFs), the joints in reverse order (the joint closing a loop last is released first
/// on ties), then each supported DOF.
pub fn candidates(constraints: &[Constraint]) -> Vec<Candidate> {
    let mut joints: Vec<Source> = Vec::new();
    for c in constraints {
        if is_joint(c.source) && !joints.contains(&c.source) {
            joints.push(c.source);
        }
    }
    let mut out = Vec::new();
    for &t in joints.iter().rev() {
        let rows: Vec<usize> = (0..constraints.len()).filter(|&r| constraints[r].source == t).collect();
        let tied: BTreeSet<usize> = rows.iter().map(|&r| constraints[r].dof).collect();
        for kind in Kind::joints() {
            let free = kind.free();
            // Frees everything the tie frees now, and more.
            if (0..6).any(|d| !tied.contains(&d) && !free.contains(&d)) || free.iter().all(|d| !tied.contains(d)) {
                continue;
            }
            let removes = rows
                .iter()
                .copied()
                .filter(|&r| free.contains(&constraints[r].dof))
                .collect();
            out.push(Candidate {
                source: t,
                kind,
                removes,
            });
        }
    }
    for (r, c) in constraints.iter().enumerate() {
        if let Source::Support(_) = c.source {
            out.push(Candidate {
                source: c.source,
                kind: Kind::SupportDof(c.dof),
                removes: vec![r],
            });
        }
    }
    out
}

/// A joint (a tie, or an element seen as a joint), whose releases are joint kinds.
fn is_joint(s: Source) -> bool {
    matches!(s, Source::Tie(_) | Source::Element(_))
}

/// Largest amount of work (rows · columns · rank, summed over the candidates of one step) the
/// search does per step.
pub const MAX_WORK: f64 = 4e8;

/// The greedy search: the releases applied in order, each with the redundancy left after it
/// (`max_steps` at most); `None` if the model is too large ([`MAX_WORK`]).
pub fn search(j: &DMatrix<f64>, candidates: &[Candidate], max_steps: usize) -> Option<Vec<(usize, usize)>> {
    let (m, n) = j.shape();
    if (m * n * m.min(n)) as f64 * candidates.len() as f64 > MAX_WORK {
        return None;
    }
    let rank0 = rank::rank(j);
    let mut redundant = m - rank0;
    let mut removed: BTreeSet<usize> = BTreeSet::new();
    let mut applied = Vec::new();
    while redundant > 0 && applied.len() < max_steps {
        let mut best: Option<(usize, usize)> = None;
        for (ic, c) in candidates.iter().enumerate() {
            // A later release of the same joint must contain what was released there before.
            let same: Vec<usize> = removed
                .iter()
                .copied()
                .filter(|r| {
                    is_joint(c.source) && candidates.iter().any(|o| o.source == c.source && o.removes.contains(r))
                })
                .collect();
            if same.iter().any(|r| !c.removes.contains(r)) {
                continue;
            }
            let new = c.removes.iter().filter(|r| !removed.contains(r)).count();
            if new == 0 || best.is_some_and(|(_, s)| s >= new) {
                continue;
            }
            let keep: Vec<usize> = (0..m)
                .filter(|r| !removed.contains(r) && !c.removes.contains(r))
                .collect();
            if rank::rank(&j.select_rows(keep.iter())) == rank0 {
                best = Some((ic, new));
            }
        }
        let Some((ic, new)) = best else { break };
        removed.extend(candidates[ic].removes.iter().copied());
        redundant -= new;
        applied.push((ic, redundant));
    }
    Some(applied)
}
