//! Exact condensation of serial chains for linear analyses.
//!
//! A chain is a path of two-node beam or flexibility elements whose inner nodes join exactly two
//! elements and carry nothing else: no load or prescribed displacement in any load case, no
//! support, rigid link, tie, mass or node frame, and no request (`keep`). With its inner nodes
//! unloaded, a chain is statically determinate between its end nodes a and b: a force f_b at b
//! (global axes) reaches every element unchanged but for the rigid transfer to the element's
//! far node q, f_q = R(x_b − x_q)ᵀ f_b, and the motion of b relative to a carried rigidly,
//! δ = u_b − R(x_b − x_a)·u_a, is the sum of the elements' relative motions carried to b:
//!
//! ```text
//! C_b = Σₑ R(x_b − x_q) C_q R(x_b − x_q)ᵀ,   δ = C_b f_b,
//! ```
//!
//! with C_q the element's cantilever tip compliance at its far node in global axes
//! (beams: [`cantilever_compliance`]; flexibility elements: their compliance; an element
//! pointing back towards a has C_q = R(x_s − x_t) C_t R(x_s − x_t)ᵀ, s and t its nodes 1 and
//! 2). The chain is therefore exactly one [`FlexElement`](super::FlexElement) from a to b with
//! compliance C_b: its 12×12 stiffness Bᵀ C_b⁻¹ B is the static condensation of the chain's
//! stiffness onto the end nodes (J. S. Przemieniecki, Theory of Matrix Structural Analysis,
//! 1968, §6.5 and §9.6, flexibility of a statically determinate structure and the condensed
//! stiffness).
//!
//! Inner-node results are recovered from the end displacements: f_b = C_b⁻¹ δ, then walking
//! from a, u_q = R(x_q − x_p)·u_p + C_q f_q for each element from p to q; the elements'
//! results then come from their own recovery on the full displacement vector.
//!
//! This file finds the chains and holds one [`Chain`] (its compliance, the recovery of its inner
//! nodes and its elements' results); `chain/link.rs` holds the fixed-size, allocation-free
//! arithmetic of one chain ([`Link`], [`Summation`], [`Ends`]), usable without a model (a
//! caller generating its pieces on the fly); `chain/condensed.rs` builds the condensed model,
//! [`Condensed`], and maps results back.

use super::element::cantilever_compliance;
use super::error::FemError;
use super::model::{Element, LoadCase, Model};
use super::recovery;
use super::results::ElementResult;
use super::section::SectionProps;
use super::transform::{rigid_arm, t6};
use nalgebra::{Matrix6, Vector3, Vector6};

mod condensed;
mod link;
pub use condensed::Condensed;
pub use link::{checked_compliance, Ends, Link, Summation};

/// One serial chain: its nodes from end a to end b and its elements in order.
#[derive(Debug, Clone, PartialEq)]
pub struct Chain {
    /// Nodes a, inner…, b (original numbering).
    pub nodes: Vec<usize>,
    /// Elements from a to b (original numbering).
    pub elements: Vec<usize>,
    /// Per element, its ends in chain order and axes, and its compliance at its far node
    /// (towards b), global axes (one vector: one allocation per chain).
    links: Vec<(Link, Matrix6<f64>)>,
    /// Per element, a beam's section properties (for its stresses).
    props: Vec<Option<SectionProps>>,
    /// The chain condensed onto a and b.
    ends: Ends,
}

/// Nodes that must stay: anything attached to them besides two chain elements.
fn pinned(model: &Model, cases: &[&LoadCase], keep: &[usize]) -> Vec<bool> {
    let mut pin = vec![false; model.nodes.len()];
    let mut set = |n: usize| {
        if let Some(p) = pin.get_mut(n) {
            *p = true;
        }
    };
    keep.iter().for_each(|&n| set(n));
    model.supports.iter().for_each(|s| set(s.node));
    model.masses.iter().for_each(|m| set(m.node));
    model.frames.keys().for_each(|&n| set(n));
    for l in &model.rigid_links {
        set(l.master);
        l.slaves.iter().for_each(|&s| set(s));
    }
    for t in &model.ties {
        set(t.a);
        set(t.b);
    }
    for c in cases.iter().copied().chain(model.load_cases.iter()) {
        c.forces
            .iter()
            .filter(|f| f.f.iter().any(|&v| v != 0.0))
            .for_each(|f| set(f.node));
        c.displacements.iter().for_each(|p| set(p.node));
    }
    pin
}

/// Serial chains of `model` (see the module docs); `cases` are the load cases to be solved and
/// `keep` nodes whose results are wanted directly.
pub fn find_chains(model: &Model, cases: &[&LoadCase], keep: &[usize]) -> Vec<(Vec<usize>, Vec<usize>)> {
    let nn = model.nodes.len();
    let pin = pinned(model, cases, keep);
    // Incident elements per node (at most 3 recorded: more means "not inner").
    let mut inc: Vec<[usize; 3]> = vec![[usize::MAX; 3]; nn];
    let mut deg = vec![0usize; nn];
    for (ie, e) in model.elements.iter().enumerate() {
        let mut nodes = e.nodes();
        nodes.sort_unstable();
        nodes.dedup();
        for n in nodes {
            if n < nn {
                if deg[n] < 3 {
                    inc[n][deg[n]] = ie;
                }
                deg[n] += 1;
            }
        }
    }
    let serial = |ie: usize| matches!(model.elements[ie], Element::Beam(_) | Element::Flex(_));
    let inner = |n: usize| deg[n] == 2 && !pin[n] && serial(inc[n][0]) && serial(inc[n][1]);
    let other = |ie: usize, n: usize| {
        let [p, q] = model.elements[ie].end_nodes();
        if p == n {
            q
        } else {
            p
        }
    };
    let mut seen = vec![false; nn];
    let mut chains = Vec::new();
    for start in 0..nn {
        if !inner(start) || seen[start] {
            continue;
        }
        // Walk both ways from an inner node to the chain's ends.
        let walk = |first: usize, seen: &mut Vec<bool>| {
            let (mut nodes, mut elems) = (Vec::new(), vec![first]);
            let (mut n, mut e) = (other(first, start), first);
            while inner(n) && n != start {
                seen[n] = true;
                nodes.push(n);
                e = if inc[n][0] == e { inc[n][1] } else { inc[n][0] };
                elems.push(e);
                n = other(e, n);
            }
            nodes.push(n);
            (nodes, elems)
        };
        seen[start] = true;
        let (left, le) = walk(inc[start][0], &mut seen);
        let (right, re) = walk(inc[start][1], &mut seen);
        let (a, b) = (*left.last().expect("end"), *right.last().expect("end"));
        if a == b || left.contains(&start) {
            continue; // a closed ring: nothing to condense onto two ends
        }
        let nodes: Vec<usize> = left.into_iter().rev().chain([start]).chain(right).collect();
        let elems: Vec<usize> = le.into_iter().rev().chain(re).collect();
        chains.push((nodes, elems));
    }
    chains
}

/// A beam's section properties, E and G ([`super::Beam::props`]).
type BeamProps = (SectionProps, f64, f64);

/// An element's local compliance at node 2, T = diag(Λ, Λ), and a beam's [`BeamProps`].
type ElementFlex = (Matrix6<f64>, Matrix6<f64>, Option<BeamProps>);

/// Element `ie`'s cantilever tip compliance at node 2 relative to node 1, local axes, its
/// frame, and a beam's section properties, E and G (`prev`: those of the previous beam, reused
/// when the section and material are the same).
fn element_compliance(model: &Model, ie: usize, prev: Option<(&Element, &BeamProps)>) -> Result<ElementFlex, FemError> {
    let (lam, l) = model.element_frame(ie)?;
    let (local, props) = match &model.elements[ie] {
        Element::Beam(b) => {
            let props = match prev {
                Some((Element::Beam(q), p)) if q.section == b.section && q.material == b.material => *p,
                _ => b.props(ie)?,
            };
            let (p, e, g) = &props;
            (cantilever_compliance(*e, *g, p, l, b.shear), Some(props))
        }
        Element::Flex(f) => {
            if checked_compliance(&f.compliance).is_none() {
                // The element's own check and error (flex_tip_stiffness).
                f.tip_stiffness(ie)?;
            }
            (Matrix6::from_fn(|i, j| f.compliance[i][j]), None)
        }
        _ => return Err(not_serial(ie)),
    };
    Ok((local, t6(&lam), props))
}

fn not_serial(ie: usize) -> FemError {
    FemError::BadInput(format!("element {ie} is not a beam"))
}

fn x(model: &Model, n: usize) -> Vector3<f64> {
    Vector3::from(model.nodes[n])
}

impl Chain {
    fn new(model: &Model, nodes: Vec<usize>, elements: Vec<usize>) -> Result<Chain, FemError> {
        let mut sum = Summation::new(x(model, *nodes.last().expect("chain end")));
        let mut links = Vec::with_capacity(elements.len());
        let mut props: Vec<Option<BeamProps>> = Vec::with_capacity(elements.len());
        for (k, &ie) in elements.iter().enumerate() {
            let prev = k
                .checked_sub(1)
                .and_then(|j| props[j].as_ref().map(|p| (&model.elements[elements[j]], p)));
            let (local, t, p) = element_compliance(model, ie, prev)?;
            props.push(p);
            let q = nodes[k + 1];
            let link = Link {
                p: x(model, nodes[k]),
                q: x(model, q),
                t,
            };
            let c_q = link.compliance(&local, model.elements[ie].end_nodes()[1] != q);
            sum.add(&link.q, &c_q);
            links.push((link, c_q));
        }
        let ends = sum.ends(x(model, nodes[0])).ok_or_else(|| FemError::BadElement {
            element: elements[0],
            reason: "the serial chain starting here has no positive definite compliance".into(),
        })?;
        Ok(Chain {
            nodes,
            elements,
            links,
            props: props.into_iter().map(|p| p.map(|p| p.0)).collect(),
            ends,
        })
    }

    /// The chain condensed onto its end nodes (C_b, C_b⁻¹, global axes).
    pub fn ends(&self) -> &Ends {
        &self.ends
    }

    /// Writes the displacements of the inner nodes into `u` (6 per original node) from those of
    /// the two ends; returns the chain's end force at b, f_b = C_b⁻¹ δ (global axes).
    pub fn recover(&self, u: &mut [f64]) -> Vector6<f64> {
        let get = |u: &[f64], n: usize| Vector6::from_column_slice(&u[6 * n..6 * n + 6]);
        let (a, b) = (self.nodes[0], *self.nodes.last().expect("chain end"));
        let f_b = self.ends.end_force(&get(u, a), &get(u, b));
        for k in 1..self.nodes.len() - 1 {
            let (p, q) = (self.nodes[k - 1], self.nodes[k]);
            let (link, c_q) = &self.links[k - 1];
            let f_q = rigid_arm(&(self.ends.xb - link.q)).transpose() * f_b;
            let uq = link.carry(&get(u, p), c_q, &f_q);
            u[6 * q..6 * q + 6].copy_from_slice(uq.as_slice());
        }
        f_b
    }

    /// The results of the chain's elements (in chain order) for the end force `f_b` of
    /// [`Chain::recover`]: element from p to q carries f_q = R(x_b − x_q)ᵀ f_b at q and
    /// f_p = −R(x_q − x_p)ᵀ f_q at p ([`Link::end_forces`]), strain energy ½ f_qᵀ C_q f_q.
    pub fn element_results(&self, model: &Model, f_b: &Vector6<f64>) -> Vec<ElementResult> {
        let mut out = Vec::with_capacity(self.elements.len());
        for (k, &ie) in self.elements.iter().enumerate() {
            let (link, c_q) = &self.links[k];
            let (f_p, f_q) = link.end_forces(&self.ends.xb, f_b);
            let (l_p, l_q) = (link.t * f_p, link.t * f_q);
            let (f1, f2) = if model.elements[ie].end_nodes()[1] == self.nodes[k + 1] {
                (l_p, l_q)
            } else {
                (l_q, l_p)
            };
            let f: [f64; 12] = std::array::from_fn(|i| if i < 6 { f1[i] } else { f2[i - 6] });
            let energy = 0.5 * f_q.dot(&(c_q * f_q));
            out.push(recovery::from_local_end_forces_with(
                &model.elements[ie],
                &f,
                energy,
                self.props[k].as_ref(),
            ));
        }
        out
    }
}

#[cfg(test)]
mod tests;
