//! The condensed model: every serial chain of a model replaced by one flexibility element
//! ([`Condensed::new`]), load cases mapped to the reduced numbering, and the original model's
//! results expanded from the reduced one's ([`Condensed::expand`]).

use super::{find_chains, x, Chain};
use crate::fem::error::FemError;
use crate::fem::model::{Element, FlexElement, LoadCase, Model};
use crate::fem::results::{CaseResult, ElementResult};
use crate::fem::transform::t6;
use nalgebra::Vector3;

/// A model with its serial chains condensed, and the maps back to the original.
#[derive(Debug, Clone)]
pub struct Condensed {
    /// The reduced model: kept nodes, the elements outside chains, one flexibility element per
    /// chain (after them), supports, links, ties, masses and frames renumbered. No load cases.
    pub model: Model,
    /// The chains condensed (original numbering).
    pub chains: Vec<Chain>,
    /// Original node of each reduced node.
    pub original_node: Vec<usize>,
    /// Reduced node of each original node (`None` for inner chain nodes).
    pub reduced_node: Vec<Option<usize>>,
    /// Original element of each reduced element (`None` for the chains' elements).
    original_element: Vec<Option<usize>>,
}

/// A global axis far from the direction `d`, as the condensed element's `up`.
fn up_for(d: Vector3<f64>) -> [f64; 3] {
    let i = (0..3).min_by(|&i, &j| d[i].abs().total_cmp(&d[j].abs())).unwrap_or(2);
    let mut up = [0.0; 3];
    up[i] = 1.0;
    up
}

impl Condensed {
    /// Condenses every serial chain of `model` for the load cases `cases`, keeping the nodes
    /// `keep` (see the module docs). A model without chains comes back unchanged.
    pub fn new(model: &Model, cases: &[&LoadCase], keep: &[usize]) -> Result<Condensed, FemError> {
        let chains = find_chains(model, cases, keep)
            .into_iter()
            .map(|(n, e)| Chain::new(model, n, e))
            .collect::<Result<Vec<_>, _>>()?;
        let mut reduced_node = vec![Some(0); model.nodes.len()];
        let mut in_chain = vec![false; model.elements.len()];
        for c in &chains {
            c.nodes[1..c.nodes.len() - 1]
                .iter()
                .for_each(|&n| reduced_node[n] = None);
            c.elements.iter().for_each(|&e| in_chain[e] = true);
        }
        let mut out = Model::new();
        let mut original_node = Vec::new();
        for (n, r) in reduced_node.iter_mut().enumerate() {
            if r.is_some() {
                *r = Some(out.add_node(model.nodes[n]));
                original_node.push(n);
            }
        }
        let map = |n: usize| reduced_node[n].expect("kept node");
        let mut original_element = Vec::new();
        for (ie, e) in model.elements.iter().enumerate() {
            if !in_chain[ie] {
                out.add_element(renumber_element(e, &map));
                original_element.push(Some(ie));
            }
        }
        for c in &chains {
            let (a, b) = (c.nodes[0], *c.nodes.last().expect("chain end"));
            let up = up_for(x(model, b) - x(model, a));
            let (lam, _) = crate::fem::transform::beam_frame(model.nodes[a], model.nodes[b], up).ok_or_else(|| {
                FemError::BadElement {
                    element: c.elements[0],
                    reason: "the serial chain starting here has coincident end nodes".into(),
                }
            })?;
            let t = t6(&lam);
            let local = t * c.ends().c_b * t.transpose();
            let local = (local + local.transpose()) * 0.5;
            out.add_element(Element::Flex(FlexElement {
                nodes: [map(a), map(b)],
                compliance: std::array::from_fn(|i| std::array::from_fn(|j| local[(i, j)])),
                up,
            }));
        }
        // Everything else keeps its data with its nodes renumbered.
        out.supports = model.supports.clone();
        out.supports.iter_mut().for_each(|s| s.node = map(s.node));
        out.masses = model.masses.clone();
        out.masses.iter_mut().for_each(|m| m.node = map(m.node));
        out.rigid_links = model.rigid_links.clone();
        for l in &mut out.rigid_links {
            l.master = map(l.master);
            l.slaves.iter_mut().for_each(|s| *s = map(*s));
        }
        out.ties = model.ties.clone();
        out.ties.iter_mut().for_each(|t| (t.a, t.b) = (map(t.a), map(t.b)));
        out.frames = model.frames.iter().map(|(&n, f)| (map(n), *f)).collect();
        out.superelements = model.superelements.clone();
        for se in &mut out.superelements {
            se.interface
                .iter_mut()
                .chain(&mut se.modal_nodes)
                .for_each(|n| *n = map(*n));
            // Pieces are never in chains: they keep their order, shifted.
            let start = original_element.iter().position(|&o| o == Some(se.elements.start));
            let start = start.unwrap_or(se.elements.start);
            se.elements = start..start + se.elements.len();
        }
        out.load_cases = model
            .load_cases
            .iter()
            .map(|c| Self::map_case(&reduced_node, c))
            .collect();
        Ok(Condensed {
            model: out,
            chains,
            original_node,
            reduced_node,
            original_element,
        })
    }

    fn map_case(reduced_node: &[Option<usize>], c: &LoadCase) -> LoadCase {
        let map = |n: usize| reduced_node.get(n).copied().flatten().unwrap_or(usize::MAX);
        LoadCase {
            name: c.name.clone(),
            forces: c
                .forces
                .iter()
                .filter(|f| f.f.iter().any(|&v| v != 0.0) || reduced_node.get(f.node).is_some_and(|r| r.is_some()))
                .map(|f| crate::fem::NodalLoad {
                    node: map(f.node),
                    ..*f
                })
                .collect(),
            displacements: c
                .displacements
                .iter()
                .map(|p| crate::fem::Prescribed {
                    node: map(p.node),
                    ..*p
                })
                .collect(),
        }
    }

    /// A load case of the original model in the reduced numbering (loads only on kept nodes:
    /// the chains were found for these cases).
    pub fn case(&self, c: &LoadCase) -> LoadCase {
        Self::map_case(&self.reduced_node, c)
    }

    /// The reduced node of an original node (`None` for an inner chain node).
    pub fn node(&self, n: usize) -> Option<usize> {
        self.reduced_node.get(n).copied().flatten()
    }

    /// The original model's result from the reduced model's result `r`: inner-node
    /// displacements recovered, chain elements' results from their own recovery, the rest
    /// (reactions, statics, other elements) renumbered.
    pub fn expand(&self, original: &Model, r: CaseResult) -> Result<CaseResult, FemError> {
        let mut u = vec![0.0; original.n_dofs()];
        for (red, &n) in self.original_node.iter().enumerate() {
            u[6 * n..6 * n + 6].copy_from_slice(&r.displacements[red]);
        }
        let mut elements: Vec<Option<ElementResult>> = vec![None; original.elements.len()];
        for c in &self.chains {
            let f_b = c.recover(&mut u);
            // zip-checked: element_results gives one result per chain element.
            for (&ie, res) in c.elements.iter().zip(c.element_results(original, &f_b)) {
                elements[ie] = Some(res);
            }
        }
        for (ie, res) in r.elements.into_iter().enumerate() {
            if let Some(orig) = self.original_element.get(ie).copied().flatten() {
                elements[orig] = Some(res);
            }
        }
        let elements = elements
            .into_iter()
            .collect::<Option<Vec<_>>>()
            .ok_or_else(|| FemError::BadInput("an element of the condensed model has no result".into()))?;
        let reactions = r.reactions.iter().map(|&(n, f)| (self.original_node[n], f)).collect();
        let displacements = u.chunks_exact(6).map(|c| std::array::from_fn(|i| c[i])).collect();
        Ok(CaseResult::new(&r.name, displacements, reactions, elements, r.statics))
    }
}

/// `e` with its nodes renumbered by `map`.
fn renumber_element(e: &Element, map: &impl Fn(usize) -> usize) -> Element {
    let mut e = e.clone();
    match &mut e {
        Element::Beam(b) => b.nodes = b.nodes.map(map),
        Element::Flex(f) => f.nodes = f.nodes.map(map),
        Element::Spring(s) => {
            s.a = map(s.a);
            s.b = s.b.map(map);
        }
        Element::Shell4(s) => s.nodes = s.nodes.map(map),
        Element::Shell9(s) => s.nodes = s.nodes.map(map),
        Element::Matrix(m) => m.nodes = m.nodes.map(map),
    }
    e
}
