//! Validation of a [`Model`] and its load cases (indices, geometry, elements, frames, ties,
//! masses, loads).

use super::{Element, LoadCase, Model};
use crate::fem::dof::NodeDof;
use crate::fem::error::FemError;

/// Distance between two nodes, relative to the model size ([`model_size`]), up to which they
/// count as coincident (the nodes of a tie, a joint, a superelement's interface).
pub const COINCIDENT: f64 = 1e-6;

/// Diagonal of the nodes' bounding box, mm (1 for a single point or none).
pub fn model_size(nodes: &[[f64; 3]]) -> f64 {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for x in nodes {
        for k in 0..3 {
            lo[k] = lo[k].min(x[k]);
            hi[k] = hi[k].max(x[k]);
        }
    }
    let d = ((hi[0] - lo[0]).powi(2) + (hi[1] - lo[1]).powi(2) + (hi[2] - lo[2]).powi(2)).sqrt();
    if d > 0.0 && d.is_finite() {
        d
    } else {
        1.0
    }
}

impl Model {
    /// Checks indices, geometry, sections, materials, compliances and loads (not constraints;
    /// those are checked by [`crate::fem::constraints::DofMap::new`]).
    pub fn validate(&self) -> Result<(), FemError> {
        for (i, x) in self.nodes.iter().enumerate() {
            if x.iter().any(|v| !v.is_finite()) {
                return Err(FemError::BadNode { node: i });
            }
        }
        for (ie, e) in self.elements.iter().enumerate() {
            match e {
                Element::Shell4(_) => {
                    self.shell_matrix(ie)?;
                }
                Element::Shell9(_) => {
                    self.shell9_matrix(ie)?;
                }
                _ => {
                    self.element_matrix(ie)?;
                }
            }
        }
        for (i, s) in self.supports.iter().enumerate() {
            self.check_node(|| format!("support {i}"), s.node)?;
        }
        for (i, l) in self.rigid_links.iter().enumerate() {
            self.check_node(|| format!("rigid link {i} (master)"), l.master)?;
            for &s in &l.slaves {
                self.check_node(|| format!("rigid link {i} (slave)"), s)?;
            }
        }
        for (&node, f) in &self.frames {
            self.check_node(|| "node frame".to_string(), node)?;
            let m = nalgebra::Matrix3::from_row_slice(&[
                f[0][0], f[0][1], f[0][2], f[1][0], f[1][1], f[1][2], f[2][0], f[2][1], f[2][2],
            ]);
            let err = (m * m.transpose() - nalgebra::Matrix3::identity()).norm();
            if !(err < 1e-9 && m.determinant() > 0.0) {
                return Err(FemError::BadInput(format!(
                    "node {node}: its frame must be orthonormal and right-handed (rows {f:?})"
                )));
            }
        }
        let coincident = COINCIDENT * model_size(&self.nodes);
        for (i, t) in self.ties.iter().enumerate() {
            self.check_node(|| format!("tie {i}"), t.a)?;
            self.check_node(|| format!("tie {i}"), t.b)?;
            if t.a == t.b {
                return Err(FemError::BadInput(format!("tie {i}: ties node {} to itself", t.a)));
            }
            let (xa, xb) = (self.nodes[t.a], self.nodes[t.b]);
            let dist = ((xa[0] - xb[0]).powi(2) + (xa[1] - xb[1]).powi(2) + (xa[2] - xb[2]).powi(2)).sqrt();
            if dist > coincident {
                return Err(FemError::BadInput(format!(
                    "tie {i}: nodes {} and {} are {dist} mm apart; a tie joins coincident nodes (within {COINCIDENT} of the model size, {coincident} mm)",
                    t.a, t.b
                )));
            }
            let fa = self.frames.get(&t.a);
            let fb = self.frames.get(&t.b);
            let same = match (fa, fb) {
                (None, None) => true,
                (Some(x), Some(y)) => x
                    .iter()
                    .flatten()
                    .zip(y.iter().flatten())
                    .all(|(p, q)| (p - q).abs() < 1e-12),
                _ => false,
            };
            if !same {
                return Err(FemError::BadInput(format!(
                    "tie {i}: nodes {} and {} must have the same frame (or none)",
                    t.a, t.b
                )));
            }
        }
        for (i, m) in self.masses.iter().enumerate() {
            self.check_node(|| format!("point mass {i}"), m.node)?;
            if !(m.mass.is_finite() && m.mass >= 0.0 && m.inertia.iter().all(|v| v.is_finite() && *v >= 0.0)) {
                return Err(FemError::BadInput(format!(
                    "point mass {i}: mass and inertia must be finite and non-negative"
                )));
            }
        }
        for case in &self.load_cases {
            self.validate_case(case)?;
        }
        Ok(())
    }

    /// Checks one load case (node indices, finite values, no DOF prescribed twice).
    pub fn validate_case(&self, case: &LoadCase) -> Result<(), FemError> {
        let err = |reason: String| FemError::LoadCase {
            case: case.name.clone(),
            reason,
        };
        for (i, f) in case.forces.iter().enumerate() {
            self.check_node(|| format!("load case {:?} force {i}", case.name), f.node)?;
            if f.f.iter().any(|v| !v.is_finite()) {
                return Err(err(format!("force {i} has a non-finite component")));
            }
        }
        let mut seen: Vec<NodeDof> = Vec::new();
        for (i, p) in case.displacements.iter().enumerate() {
            self.check_node(|| format!("load case {:?} displacement {i}", case.name), p.node)?;
            if !p.value.is_finite() {
                return Err(err(format!("displacement {i} is not finite")));
            }
            let nd = NodeDof {
                node: p.node,
                dof: p.dof,
            };
            if seen.contains(&nd) {
                return Err(err(format!("{nd} is prescribed twice")));
            }
            seen.push(nd);
        }
        Ok(())
    }
}
