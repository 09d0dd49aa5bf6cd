//! Supports, prescribed displacements and rigid links, by elimination (scikit-fem's
//! `condense` idea): the reduced system over the free equations stays SPD — no penalty, no
//! Lagrange multipliers.
//!
//! Every node follows an *independent* node (itself, or the master of its rigid link) through a
//! rigid arm: d_node = R(x_node − x_master)·d_master. The DOFs of independent nodes are either
//! constrained (supported or prescribed) or numbered as equations.

use super::dof::{describe, Dof, NodeDof};
use super::error::FemError;
use super::model::{ElementMatrix, Model, Shell9Matrix, ShellMatrix};
use super::shell::Mat24;
use super::transform::{rigid_arm, Mat12};
use nalgebra::{DMatrix, Matrix6, Vector3, Vector6};

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
    /// Tied DOFs: global DOF → the DOF it equals (its root, never itself tied). Sorted by key.
    pub alias: Vec<(usize, usize)>,
    /// Independent nodes with a frame (their DOFs are local: d_global = arm · d_local).
    pub framed: Vec<usize>,
}

/// 6×6 block-diagonal diag(Fᵀ, Fᵀ) taking local DOFs of a frame with rows `f` to global.
pub fn frame_block(f: &[[f64; 3]; 3]) -> Matrix6<f64> {
    let mut t = Matrix6::zeros();
    for i in 0..3 {
        for j in 0..3 {
            t[(i, j)] = f[j][i];
            t[(i + 3, j + 3)] = f[j][i];
        }
    }
    t
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
                if model.frames.contains_key(&s) {
                    return Err(FemError::OverConstrained(format!(
                        "node {s} has a frame but is a slave of rigid link {il}; its motion is fixed by master {} — give the frame to an independent node",
                        model.rigid_links[il].master
                    )));
                }
                let m = model.rigid_links[il].master;
                rep[s] = m;
                let a = Vector3::from(model.nodes[s]) - Vector3::from(model.nodes[m]);
                let mut r = rigid_arm(&a);
                if let Some(f) = model.frames.get(&m) {
                    r *= frame_block(f);
                }
                arm[s] = Some(r);
            }
        }
        let mut framed = Vec::new();
        for (&node, f) in &model.frames {
            if node < n && slave_of[node] == NONE {
                arm[node] = Some(frame_block(f));
                framed.push(node);
            }
        }
        // Ties: DOF 6b+d equals DOF 6a+d. Resolve chains to a root that is not itself tied.
        let mut tied_to: std::collections::BTreeMap<usize, usize> = std::collections::BTreeMap::new();
        for (it, t) in model.ties.iter().enumerate() {
            for node in [t.a, t.b] {
                if node >= n {
                    return Err(FemError::NodeOutOfRange {
                        what: format!("tie {it}"),
                        node,
                        n_nodes: n,
                    });
                }
                if slave_of[node] != NONE {
                    return Err(FemError::OverConstrained(format!(
                        "tie {it}: node {node} is a slave of rigid link {}; tie an independent node (e.g. its master {}) instead",
                        slave_of[node],
                        model.rigid_links[slave_of[node]].master
                    )));
                }
            }
            for d in (0..6).filter(|&d| t.dofs[d]) {
                let gb = 6 * t.b + d;
                if tied_to.insert(gb, 6 * t.a + d).is_some() {
                    return Err(FemError::OverConstrained(format!(
                        "{} is tied twice (tie {it} and an earlier tie): redundant ties",
                        NodeDof::from_global(gb)
                    )));
                }
            }
        }
        let mut alias = Vec::with_capacity(tied_to.len());
        for &g in tied_to.keys() {
            let mut root = g;
            let mut steps = 0;
            while let Some(&next) = tied_to.get(&root) {
                root = next;
                steps += 1;
                if steps > tied_to.len() {
                    return Err(FemError::OverConstrained(format!(
                        "ties form a loop through {}",
                        NodeDof::from_global(g)
                    )));
                }
            }
            alias.push((g, root));
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
        for &(g, root) in &alias {
            if constrained.binary_search(&g).is_ok() {
                return Err(FemError::OverConstrained(format!(
                    "{} is both tied to {} and supported or prescribed; constrain {} instead",
                    NodeDof::from_global(g),
                    NodeDof::from_global(root),
                    NodeDof::from_global(root)
                )));
            }
        }
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
                if tied_to.contains_key(&g) {
                    continue;
                }
                eq[g] = eq_dof.len();
                eq_dof.push(g);
            }
        }
        for &(g, root) in &alias {
            eq[g] = eq[root];
        }
        Ok(DofMap {
            rep,
            arm,
            eq,
            eq_dof,
            constrained,
            alias,
            framed,
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

    /// Shell element matrix carried to the independent nodes (as
    /// [`DofMap::element_on_independent`], four nodes).
    pub fn shell_on_independent(&self, em: &ShellMatrix) -> ([usize; 4], Mat24) {
        let reps = em.nodes.map(|n| self.rep[n]);
        if em.nodes.iter().all(|&n| self.arm[n].is_none()) {
            return (reps, em.k);
        }
        let mut t = Mat24::identity();
        for (i, &n) in em.nodes.iter().enumerate() {
            if let Some(r) = &self.arm[n] {
                t.fixed_view_mut::<6, 6>(6 * i, 6 * i).copy_from(r);
            }
        }
        (reps, t.transpose() * em.k * t)
    }

    /// Nine-node shell matrix carried to the independent nodes (as
    /// [`DofMap::shell_on_independent`]).
    pub fn shell9_on_independent(&self, em: &Shell9Matrix) -> ([usize; 9], DMatrix<f64>) {
        let reps = em.nodes.map(|n| self.rep[n]);
        if em.nodes.iter().all(|&n| self.arm[n].is_none()) {
            return (reps, em.k.clone());
        }
        let mut t = DMatrix::identity(54, 54);
        for (i, &n) in em.nodes.iter().enumerate() {
            if let Some(r) = &self.arm[n] {
                t.view_mut((6 * i, 6 * i), (6, 6)).copy_from(r);
            }
        }
        (reps, t.transpose() * &em.k * t)
    }

    /// A node's 6×6 matrix (global axes, e.g. a point mass) carried to its independent node:
    /// Rᵀ M R with R the rigid arm / frame of the node.
    pub fn node_on_independent(&self, node: usize, m: &Matrix6<f64>) -> (usize, Matrix6<f64>) {
        match &self.arm[node] {
            Some(r) => (self.rep[node], r.transpose() * m * r),
            None => (self.rep[node], *m),
        }
    }

    /// Equation numbers of the 6·len DOFs of independent nodes `reps` (up to nine).
    pub fn nodes_eqs(&self, reps: &[usize]) -> [usize; 54] {
        let mut e = [NONE; 54];
        for (i, slot) in e.iter_mut().enumerate().take(6 * reps.len().min(9)) {
            *slot = self.eq[6 * reps[i / 6] + i % 6];
        }
        e
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
    ///
    /// Framed independent nodes get their own load in local axes (Λ f); tied DOFs pass their
    /// load to the DOF they are tied to.
    pub fn to_independent(&self, f: &[f64]) -> Vec<f64> {
        let mut out = f.to_vec();
        for &node in &self.framed {
            if let Some(r) = &self.arm[node] {
                let fl = r.transpose() * Vector6::from_column_slice(&f[6 * node..6 * node + 6]);
                out[6 * node..6 * node + 6].copy_from_slice(fl.as_slice());
            }
        }
        for (node, m, r) in self.slaves() {
            let fs = Vector6::from_column_slice(&f[6 * node..6 * node + 6]);
            let fm = r.transpose() * fs;
            for d in 0..6 {
                out[6 * m + d] += fm[d];
                out[6 * node + d] = 0.0;
            }
        }
        for &(g, root) in &self.alias {
            out[root] += out[g];
            out[g] = 0.0;
        }
        out
    }

    /// The rigid-link slaves in node order: (slave, its master, the arm from the master's
    /// DOFs to the slave's).
    fn slaves(&self) -> impl Iterator<Item = (usize, usize, &Matrix6<f64>)> + '_ {
        self.arm.iter().enumerate().filter_map(|(node, arm)| {
            let m = self.rep[node];
            arm.as_ref().filter(|_| m != node).map(|r| (node, m, r))
        })
    }

    /// Reduced right-hand side: the equation entries of [`DofMap::to_independent`].
    pub fn reduce(&self, f: &[f64]) -> Vec<f64> {
        let fi = self.to_independent(f);
        self.eq_dof.iter().map(|&g| fi[g]).collect()
    }

    /// Independent components (6 per node, node frame at framed nodes; slaves zero) from the
    /// equation values `q`, the values of the constrained DOFs `u_c` (a full-length vector read
    /// only at constrained DOFs; `None` = zero) and tied DOFs following their roots.
    pub fn scatter(&self, q: &[f64], u_c: Option<&[f64]>) -> Vec<f64> {
        let mut u = vec![0.0; self.eq.len()];
        if let Some(u_c) = u_c {
            for &g in &self.constrained {
                u[g] = u_c[g];
            }
        }
        for (i, &g) in self.eq_dof.iter().enumerate() {
            u[g] = q[i];
        }
        for &(g, root) in &self.alias {
            u[g] = u[root];
        }
        u
    }

    /// Full displacement vector (6 per node) from the equation values `q` and the values of the
    /// constrained DOFs `u_c` (a full-length vector read only at constrained DOFs).
    pub fn expand(&self, q: &[f64], u_c: &[f64]) -> Vec<f64> {
        let mut u = self.scatter(q, Some(u_c));
        // Slaves from their masters' (possibly local) DOFs, then framed nodes to global.
        for (node, m, r) in self.slaves() {
            let um = Vector6::from_column_slice(&u[6 * m..6 * m + 6]);
            let us = r * um;
            u[6 * node..6 * node + 6].copy_from_slice(us.as_slice());
        }
        for &node in &self.framed {
            if let Some(r) = &self.arm[node] {
                let ug = r * Vector6::from_column_slice(&u[6 * node..6 * node + 6]);
                u[6 * node..6 * node + 6].copy_from_slice(ug.as_slice());
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
