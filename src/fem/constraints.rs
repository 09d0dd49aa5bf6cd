//! Supports, prescribed displacements and rigid links, by elimination (scikit-fem's
//! `condense` idea): the reduced system over the free equations stays SPD — no penalty, no
//! Lagrange multipliers.
//!
//! Every node follows an *independent* node (itself, or the master of its rigid link) through a
//! rigid arm: d_node = R(x_node − x_master)·d_master. The DOFs of independent nodes are either
//! constrained (supported or prescribed) or numbered as equations.

use super::dof::{describe, Dof, NodeDof};
use super::error::FemError;
use super::model::{ElementMatrix, Model};
use super::transform::{rigid_arm, Mat12};
use nalgebra::{Matrix6, Vector3, Vector6};

/// Marks a DOF without an equation (constrained, or belonging to a slave node).
pub const NONE: usize = usize::MAX;

/// DOF numbering for one set of constrained DOFs.
#[derive(Debug, Clone)]
pub struct DofMap {
    /// Independent node followed by each node (itself unless it is a rigid-link slave).
    pub rep: Vec<usize>,
    /// Rigid arm R(x_slave − x_master) of slave nodes (`None` = identity).
    pub arm: Vec<Option<Matrix6<f64>>>,
    /// Equation of each global DOF 6·node+dof of an independent node; [`NONE`] if constrained
    /// or on a slave node.
    pub eq: Vec<usize>,
    /// Global DOF of each equation.
    pub eq_dof: Vec<usize>,
    /// Constrained (supported or prescribed) global DOFs of independent nodes, sorted.
    pub constrained: Vec<usize>,
}

/// Global DOFs fixed by the model's supports, sorted and deduplicated.
pub fn supported_dofs(model: &Model) -> Vec<usize> {
    let mut v: Vec<usize> = model
        .supports
        .iter()
        .flat_map(|s| (0..6).filter(move |&d| s.fix[d]).map(move |d| 6 * s.node + d))
        .collect();
    v.sort_unstable();
    v.dedup();
    v
}

impl DofMap {
    /// Numbers the equations with the model's supports plus `prescribed` constrained.
    /// `case` names the load case that prescribes them (for messages).
    ///
    /// Errors on conflicting constraints: a node that is a slave of two links (or twice in one),
    /// a master that is itself a slave (chains are not resolved), a master listed as its own
    /// slave, a supported or prescribed slave DOF.
    pub fn new(model: &Model, prescribed: &[NodeDof], case: Option<&str>) -> Result<DofMap, FemError> {
        let n = model.nodes.len();
        let mut slave_of = vec![NONE; n];
        for (il, link) in model.rigid_links.iter().enumerate() {
            for &node in std::iter::once(&link.master).chain(&link.slaves) {
                if node >= n {
                    return Err(FemError::NodeOutOfRange {
                        what: format!("rigid link {il}"),
                        node,
                        n_nodes: n,
                    });
                }
            }
            for &s in &link.slaves {
                if s == link.master {
                    return Err(FemError::OverConstrained(format!(
                        "rigid link {il}: node {s} is listed as its own slave"
                    )));
                }
                if slave_of[s] != NONE {
                    let other = slave_of[s];
                    return Err(FemError::OverConstrained(if other == il {
                        format!("rigid link {il} lists node {s} twice as a slave")
                    } else {
                        format!(
                            "node {s} is a slave of rigid link {other} (master {}) and of rigid link {il} (master {}); a node can follow only one master — redundant links",
                            model.rigid_links[other].master, link.master
                        )
                    }));
                }
                slave_of[s] = il;
            }
        }
        for (il, link) in model.rigid_links.iter().enumerate() {
            let m = link.master;
            if slave_of[m] != NONE {
                let other = slave_of[m];
                return Err(FemError::OverConstrained(format!(
                    "node {m} is the master of rigid link {il} and a slave of rigid link {other} (master {}); chained rigid links are not resolved — list the slaves of link {il} under master {} instead",
                    model.rigid_links[other].master, model.rigid_links[other].master
                )));
            }
        }
        let mut rep: Vec<usize> = (0..n).collect();
        let mut arm = vec![None; n];
        for (s, &il) in slave_of.iter().enumerate() {
            if il != NONE {
                let m = model.rigid_links[il].master;
                rep[s] = m;
                let a = Vector3::from(model.nodes[s]) - Vector3::from(model.nodes[m]);
                arm[s] = Some(rigid_arm(&a));
            }
        }
        let mut constrained = supported_dofs(model);
        for &g in &constrained {
            let node = g / 6;
            if node >= n {
                return Err(FemError::NodeOutOfRange {
                    what: "support".into(),
                    node,
                    n_nodes: n,
                });
            }
            if slave_of[node] != NONE {
                let il = slave_of[node];
                let dofs: Vec<NodeDof> = constrained
                    .iter()
                    .filter(|&&h| h / 6 == node)
                    .map(|&h| NodeDof::from_global(h))
                    .collect();
                return Err(FemError::OverConstrained(format!(
                    "{} is supported but node {node} is a slave of rigid link {il}; its motion is fixed by master {} — support the master instead",
                    describe(&dofs),
                    model.rigid_links[il].master
                )));
            }
        }
        for p in prescribed {
            if p.node >= n {
                return Err(FemError::NodeOutOfRange {
                    what: "prescribed displacement".into(),
                    node: p.node,
                    n_nodes: n,
                });
            }
            if slave_of[p.node] != NONE {
                let il = slave_of[p.node];
                return Err(FemError::OverConstrained(format!(
                    "{p} is prescribed{} but node {} is a slave of rigid link {il}; prescribe the master {} instead",
                    case.map(|c| format!(" in load case {c:?}")).unwrap_or_default(),
                    p.node,
                    model.rigid_links[il].master
                )));
            }
            constrained.push(p.global());
        }
        constrained.sort_unstable();
        constrained.dedup();
        let mut eq = vec![NONE; 6 * n];
        let mut eq_dof = Vec::with_capacity(6 * n);
        let mut ci = 0;
        for (node, &r) in rep.iter().enumerate() {
            if r != node {
                continue;
            }
            for d in 0..6 {
                let g = 6 * node + d;
                while ci < constrained.len() && constrained[ci] < g {
                    ci += 1;
                }
                if ci < constrained.len() && constrained[ci] == g {
                    continue;
                }
                eq[g] = eq_dof.len();
                eq_dof.push(g);
            }
        }
        Ok(DofMap {
            rep,
            arm,
            eq,
            eq_dof,
            constrained,
        })
    }

    /// Number of equations (free DOFs).
    pub fn n_eq(&self) -> usize {
        self.eq_dof.len()
    }

    /// The node DOF of equation `i`.
    pub fn eq_node_dof(&self, i: usize) -> NodeDof {
        NodeDof::from_global(self.eq_dof[i])
    }

    /// Is global DOF `g` (of an independent node) constrained?
    pub fn is_constrained(&self, g: usize) -> bool {
        self.constrained.binary_search(&g).is_ok()
    }

    /// Element matrix carried to the independent nodes: K' = Aᵀ K A with
    /// A = diag(R₁, R₂) the rigid arms of the element's nodes. Returns the independent nodes
    /// and K'.
    pub fn element_on_independent(&self, em: &ElementMatrix) -> ([usize; 2], Mat12) {
        let [a, b] = em.nodes;
        let reps = [self.rep[a], self.rep[b]];
        let arms = [&self.arm[a], &self.arm[b]];
        if arms.iter().all(|x| x.is_none()) {
            return (reps, em.k);
        }
        let mut t = Mat12::identity();
        for (i, arm) in arms.iter().enumerate().take(em.n_nodes) {
            if let Some(r) = arm {
                t.fixed_view_mut::<6, 6>(6 * i, 6 * i).copy_from(r);
            }
        }
        (reps, t.transpose() * em.k * t)
    }

    /// Equation numbers of the element's 12 (or 6) DOFs on independent nodes.
    pub fn element_eqs(&self, reps: [usize; 2], n_nodes: usize) -> [usize; 12] {
        let mut e = [NONE; 12];
        for (i, slot) in e.iter_mut().enumerate().take(6 * n_nodes) {
            *slot = self.eq[6 * reps[i / 6] + i % 6];
        }
        e
    }

    /// Moves a global nodal vector (6 per node) onto independent nodes: f_m += Rᵀ f_s for
    /// every slave s of master m (force resultant and moment about the master preserved).
    pub fn to_independent(&self, f: &[f64]) -> Vec<f64> {
        let mut out = f.to_vec();
        for (node, arm) in self.arm.iter().enumerate() {
            if let Some(r) = arm {
                let fs = Vector6::from_column_slice(&f[6 * node..6 * node + 6]);
                let fm = r.transpose() * fs;
                let m = self.rep[node];
                for d in 0..6 {
                    out[6 * m + d] += fm[d];
                    out[6 * node + d] = 0.0;
                }
            }
        }
        out
    }

    /// Reduced right-hand side: the equation entries of [`DofMap::to_independent`].
    pub fn reduce(&self, f: &[f64]) -> Vec<f64> {
        let fi = self.to_independent(f);
        self.eq_dof.iter().map(|&g| fi[g]).collect()
    }

    /// Full displacement vector (6 per node) from the equation values `q` and the values of the
    /// constrained DOFs `u_c` (a full-length vector read only at constrained DOFs).
    pub fn expand(&self, q: &[f64], u_c: &[f64]) -> Vec<f64> {
        let mut u = vec![0.0; self.eq.len()];
        for &g in &self.constrained {
            u[g] = u_c[g];
        }
        for (i, &g) in self.eq_dof.iter().enumerate() {
            u[g] = q[i];
        }
        for (node, arm) in self.arm.iter().enumerate() {
            if let Some(r) = arm {
                let m = self.rep[node];
                let um = Vector6::from_column_slice(&u[6 * m..6 * m + 6]);
                let us = r * um;
                u[6 * node..6 * node + 6].copy_from_slice(us.as_slice());
            }
        }
        u
    }

    /// Names the DOF behind equation `i` as the user sees it.
    pub fn describe_eq(&self, i: usize) -> NodeDof {
        let g = self.eq_dof[i];
        NodeDof {
            node: g / 6,
            dof: Dof::ALL[g % 6],
        }
    }
}
