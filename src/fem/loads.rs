//! Distributed loads a user expects, as consistent nodal loads [Fx, Fy, Fz (N), Mx, My, Mz
//! (N·mm)] in global axes (add them to a [`LoadCase`] with [`add_to_case`]):
//!
//! * **Gravity** ([`gravity_loads`]): f = M·r_g, with M the very mass matrices of the modal
//!   analysis ([`super::mass`]: consistent beam mass, lumped shell mass, point masses; flexibility
//!   elements and springs are massless) and r_g the rigid translation field with the
//!   acceleration g (mm/s²) at every node. On a beam this is the consistent load of the uniform
//!   line load q = ρ·A·g: q·L/2 and the end moments ±q·L²/12 (also with shear deformation, whose
//!   interdependent interpolation reproduces a rigid translation exactly); on a shell each node
//!   takes its lumped mass times g, with no moment. The resultant is (total mass)·g, the total
//!   mass rᵀMr of the modal analysis. Density in tonne/mm³ and g in mm/s² give N.
//! * **Uniform line loads on beams** ([`beam_line_load`]): q (N/mm) in global or element-local
//!   axes over the whole element. Local consistent loads (J. S. Przemieniecki, Theory of Matrix
//!   Structural Analysis, 1968, §5.9 fixed-end forces):
//!
//!   ```text
//!   axial qx:  qx·L/2 at each end
//!   qy:        qy·L/2 at each end,  θz: +qy·L²/12 at node 1, −qy·L²/12 at node 2
//!   qz:        qz·L/2 at each end,  θy: −qz·L²/12 at node 1, +qz·L²/12 at node 2  (θy = −dw/dx)
//!   ```
//!   These are the exact fixed-end forces of a prismatic beam, Euler–Bernoulli or Timoshenko, so
//!   the nodal displacements of a beam mesh under them are exact.
//! * **Forces on a node group** ([`tributary_weights`], [`spread_total`]): a total force F and
//!   moment M (about the group's weighted centroid c) spread over the group's nodes with weights
//!   wᵢ — the tributary length or area of each node (the consistent share ∫Nᵢ of linear
//!   elements: L/2 per end of a line, A/3 per corner of a triangle, ∫Nᵢ dA of a bilinear quad) or
//!   equal weights for a plain node list. Node i takes fᵢ = wᵢ·F/W + wᵢ·(a × rᵢ), rᵢ = xᵢ − c,
//!   where a = J⁺M with J = Σ wᵢ(|rᵢ|²I − rᵢrᵢᵀ): the forces of a rigid rotation of the group,
//!   weighted like the force share (the distributing-constraint rule of NASTRAN's RBE3). The part
//!   of M about an axis the group has no lever arm for (a single node, the axis of a straight
//!   line of nodes) is applied as nodal moments wᵢ·M/W. The resultant is F and the moment about
//!   c is M (the largest-weight node takes the round-off remainder, so the sums are exact to the
//!   last bit of the summation).
//!
//! The node-group functions live in `loads/group.rs`; this file holds gravity, beam line loads
//! and the helpers that add and sum per-node loads.

use super::error::FemError;
use super::mass::{element_mass, point_mass, shell_mass_matrix};
use super::model::{Element, LoadCase, Model};
use nalgebra::Vector3;

mod group;
pub use group::{centroid, spread_total, tributary_weights};

/// Nodal loads per node of the model (dense, `model.nodes.len()` entries).
pub type NodeLoads = Vec<[f64; 6]>;

/// Axes in which a line load is given.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LoadAxes {
    /// Global x, y, z.
    Global,
    /// The beam's local x (along the axis, node 1 → node 2), y, z.
    Local,
}

fn add(loads: &mut [[f64; 6]], node: usize, f: &[f64]) {
    for (d, v) in f.iter().enumerate() {
        loads[node][d] += v;
    }
}

/// Consistent gravity loads of every element with mass and every point mass of the model, for
/// the acceleration `g` (mm/s², global axes, e.g. `[0, 0, -9810]`). f = M·r_g with the modal
/// mass matrices (see the module documentation). Errors name an element whose mass cannot be
/// built (negative density, bad geometry).
pub fn gravity_loads(model: &Model, g: [f64; 3]) -> Result<NodeLoads, FemError> {
    if g.iter().any(|v| !v.is_finite()) {
        return Err(FemError::BadInput(format!("gravity {g:?} must be finite")));
    }
    let mut loads = vec![[0.0; 6]; model.nodes.len()];
    // Superelement modal nodes carry modal coordinates, no rigid motion.
    let modal = model.modal_node_flags();
    let field = |n: usize| -> Vec<f64> { (0..n).flat_map(|_| [g[0], g[1], g[2], 0.0, 0.0, 0.0]).collect() };
    for (ie, e) in model.elements.iter().enumerate() {
        match e {
            Element::Shell4(_) => {
                let m = shell_mass_matrix(model, ie)?;
                let f = m.k * nalgebra::SVector::<f64, 24>::from_iterator(field(4));
                for (k, &n) in m.nodes.iter().enumerate() {
                    add(&mut loads, n, &f.as_slice()[6 * k..6 * k + 6]);
                }
            }
            Element::Shell9(_) => {
                let m = model.shell9_mass_matrix(ie)?;
                let f = &m.k * nalgebra::DVector::from_vec(field(9));
                for (k, &n) in m.nodes.iter().enumerate() {
                    add(&mut loads, n, &f.as_slice()[6 * k..6 * k + 6]);
                }
            }
            _ => {
                let Some(m) = element_mass(model, ie)? else {
                    continue;
                };
                for &n in &m.nodes[..m.n_nodes] {
                    if n >= loads.len() {
                        return Err(FemError::NodeOutOfRange {
                            what: format!("element {ie}"),
                            node: n,
                            n_nodes: loads.len(),
                        });
                    }
                }
                // A one-node element (ground spring) uses only the top-left 6×6 block.
                let r = nalgebra::SVector::<f64, 12>::from_iterator(field(2).into_iter().enumerate().map(|(i, v)| {
                    if i < 6 * m.n_nodes && !modal[m.nodes[i / 6]] {
                        v
                    } else {
                        0.0
                    }
                }));
                let f = m.k * r;
                for (k, &n) in m.nodes[..m.n_nodes].iter().enumerate() {
                    add(&mut loads, n, &f.as_slice()[6 * k..6 * k + 6]);
                }
            }
        }
    }
    for (i, pm) in model.masses.iter().enumerate() {
        if pm.node >= loads.len() {
            return Err(FemError::NodeOutOfRange {
                what: format!("point mass {i}"),
                node: pm.node,
                n_nodes: loads.len(),
            });
        }
        let m = point_mass(model, i);
        let r = nalgebra::Vector6::new(g[0], g[1], g[2], 0.0, 0.0, 0.0);
        add(&mut loads, pm.node, (m * r).as_slice());
    }
    Ok(loads)
}

/// Consistent end loads of a uniform line load `q` (N/mm) over the whole length of beam `ie`,
/// in `axes` (see the module documentation): `[node 1, node 2]`, global axes.
pub fn beam_line_load(model: &Model, ie: usize, q: [f64; 3], axes: LoadAxes) -> Result<[[f64; 6]; 2], FemError> {
    if !matches!(model.elements.get(ie), Some(Element::Beam(_))) {
        return Err(FemError::BadInput(format!(
            "element {ie} is not a beam: a line load acts on beams"
        )));
    }
    if q.iter().any(|v| !v.is_finite()) {
        return Err(FemError::BadElement {
            element: ie,
            reason: format!("line load {q:?} must be finite"),
        });
    }
    let (lam, l) = model.element_frame(ie)?;
    let qv = Vector3::from(q);
    let ql = match axes {
        LoadAxes::Global => lam * qv,
        LoadAxes::Local => qv,
    };
    let (h, m) = (0.5 * l, l * l / 12.0);
    let f1 = [ql.x * h, ql.y * h, ql.z * h, 0.0, -ql.z * m, ql.y * m];
    let f2 = [ql.x * h, ql.y * h, ql.z * h, 0.0, ql.z * m, -ql.y * m];
    let global = |f: [f64; 6]| -> [f64; 6] {
        let a = lam.transpose() * Vector3::new(f[0], f[1], f[2]);
        let b = lam.transpose() * Vector3::new(f[3], f[4], f[5]);
        [a.x, a.y, a.z, b.x, b.y, b.z]
    };
    Ok([global(f1), global(f2)])
}

/// Adds the nonzero entries of per-node loads to a load case.
pub fn add_to_case(case: &mut LoadCase, loads: impl IntoIterator<Item = (usize, [f64; 6])>) {
    for (node, f) in loads {
        if f.iter().any(|v| *v != 0.0) {
            case.forces.push(super::model::NodalLoad { node, f });
        }
    }
}

/// Sum of per-node loads about `origin`: [ΣF, Σ(r × F) + ΣM].
pub fn resultant(model: &Model, loads: &[(usize, [f64; 6])], origin: [f64; 3]) -> [f64; 6] {
    let (mut f, mut m) = (Vector3::zeros(), Vector3::zeros());
    for &(n, l) in loads {
        let fi = Vector3::new(l[0], l[1], l[2]);
        f += fi;
        m += (Vector3::from(model.nodes[n]) - Vector3::from(origin)).cross(&fi) + Vector3::new(l[3], l[4], l[5]);
    }
    [f.x, f.y, f.z, m.x, m.y, m.z]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fem::{Beam, PointMass, Section, Shell4};
    use crate::material::Material;

    fn beam_model(shear: bool) -> Model {
        let mut m = Model::new();
        m.add_node([0.0, 0.0, 0.0]);
        m.add_node([30.0, 40.0, 0.0]);
        let mut b = Beam::new(0, 1, Section::Rect { w: 4.0, h: 2.0 }, Material::STEEL, [0.0, 0.0, 1.0]);
        b.shear = shear;
        m.add_beam(b);
        m
    }

    fn indexed(l: &NodeLoads) -> Vec<(usize, [f64; 6])> {
        l.iter().copied().enumerate().collect()
    }

    /// Gravity on a beam = the consistent load of q = ρAg: ρAgL/2 per end, end moments
    /// ±ρAgL²/12 (closed form of the fixed-end forces), with and without shear deformation.
    #[test]
    fn beam_gravity_is_consistent_line_load() {
        for shear in [false, true] {
            let m = beam_model(shear);
            let g = [0.0, 0.0, -9810.0];
            let grav = gravity_loads(&m, g).unwrap();
            let q = Material::STEEL.density * 8.0 * -9810.0;
            let line = beam_line_load(&m, 0, [0.0, 0.0, q], LoadAxes::Global).unwrap();
            for k in 0..2 {
                for d in 0..6 {
                    let scale = q.abs() * 50.0 * 50.0 / 12.0;
                    assert!(
                        (grav[k][d] - line[k][d]).abs() < 1e-12 * scale,
                        "{shear} {k} {d}: {grav:?} vs {line:?}"
                    );
                }
            }
            // L = 50: qL/2 and qL²/12 (moment about the horizontal axis normal to the beam).
            assert!((grav[0][2] - q * 25.0).abs() < 1e-12 * (q * 25.0).abs());
            let mom = Vector3::new(grav[0][3], grav[0][4], grav[0][5]).norm();
            assert!((mom - q.abs() * 2500.0 / 12.0).abs() < 1e-12 * q.abs() * 2500.0 / 12.0);
        }
    }

    /// Local line loads: qy along local y gives +qL²/12 about local z at node 1 (Przemieniecki
    /// fixed-end forces); axial load no moment.
    #[test]
    fn local_line_load_signs() {
        let mut m = Model::new();
        m.add_node([0.0; 3]);
        m.add_node([10.0, 0.0, 0.0]);
        m.add_beam(Beam::new(
            0,
            1,
            Section::Circle { d: 1.0 },
            Material::STEEL,
            [0.0, 0.0, 1.0],
        ));
        let f = beam_line_load(&m, 0, [1.0, 2.0, 3.0], LoadAxes::Local).unwrap();
        let exp1 = [5.0, 10.0, 15.0, 0.0, -25.0, 100.0 / 6.0];
        let exp2 = [5.0, 10.0, 15.0, 0.0, 25.0, -100.0 / 6.0];
        for d in 0..6 {
            assert!((f[0][d] - exp1[d]).abs() < 1e-12 * 25.0, "{f:?}");
            assert!((f[1][d] - exp2[d]).abs() < 1e-12 * 25.0, "{f:?}");
        }
        assert!(beam_line_load(&m, 3, [0.0; 3], LoadAxes::Local).is_err());
    }

    /// Gravity resultant = total mass × g (beams, shells, point masses) to 1e-12; the moment
    /// about the centre of mass is zero.
    #[test]
    fn gravity_resultant_is_total_mass_times_g() {
        let mut m = beam_model(true);
        let a = m.add_node([0.0, 10.0, 5.0]);
        let b = m.add_node([20.0, 10.0, 5.0]);
        let c = m.add_node([20.0, 25.0, 5.0]);
        let d = m.add_node([0.0, 25.0, 5.0]);
        m.add_element(Element::Shell4(Shell4 {
            nodes: [a, b, c, d],
            t: 1.5,
            material: Material::AL7075,
        }));
        m.masses.push(PointMass {
            node: 1,
            mass: 2e-3,
            inertia: [1.0, 1.0, 1.0],
        });
        let g = [100.0, -200.0, -9810.0];
        let loads = indexed(&gravity_loads(&m, g).unwrap());
        let mass = Material::STEEL.density * 8.0 * 50.0 + Material::AL7075.density * 1.5 * 300.0 + 2e-3;
        let res = resultant(&m, &loads, [0.0; 3]);
        for k in 0..3 {
            assert!((res[k] - mass * g[k]).abs() <= 1e-12 * mass * 9810.0, "{res:?}");
        }
        // Centre of mass: beam mid (15, 20, 0), shell centre (10, 17.5, 5), point mass (30, 40, 0).
        let (mb, ms, mp) = (Material::STEEL.density * 400.0, Material::AL7075.density * 450.0, 2e-3);
        let cm = [
            (15.0 * mb + 10.0 * ms + 30.0 * mp) / mass,
            (20.0 * mb + 17.5 * ms + 40.0 * mp) / mass,
            (5.0 * ms) / mass,
        ];
        let rc = resultant(&m, &loads, cm);
        for k in 3..6 {
            assert!(rc[k].abs() <= 1e-12 * mass * 9810.0 * 50.0, "{rc:?}");
        }
    }

    /// Group spreading: the resultant force and the moment about the centroid equal the total
    /// to 1e-12; a straight edge under a pure force gets the consistent L/2 shares (end nodes
    /// half of an interior node).
    #[test]
    fn spread_resultants() {
        let mut m = Model::new();
        for i in 0..5 {
            m.add_node([10.0 * i as f64, 0.0, 0.0]);
        }
        m.add_node([0.0, 10.0, 3.0]);
        let cells: Vec<Vec<usize>> = (0..4).map(|i| vec![i, i + 1]).collect();
        let w = tributary_weights(&m, &cells).unwrap();
        assert_eq!(w, vec![(0, 5.0), (1, 10.0), (2, 10.0), (3, 10.0), (4, 5.0)]);
        let f = spread_total(&m, &w, [0.0, 0.0, -80.0, 0.0, 0.0, 0.0]).unwrap();
        assert_eq!(f[0].1[2], -10.0);
        assert_eq!(f[2].1[2], -20.0);
        for total in [[1.0, -2.0, 3.0, 40.0, -50.0, 60.0], [0.0, 0.0, 0.0, 7.0, 0.0, 0.0]] {
            for cells in [cells.clone(), vec![vec![0], vec![2], vec![5]], vec![vec![5]]] {
                let w = tributary_weights(&m, &cells).unwrap();
                let f = spread_total(&m, &w, total).unwrap();
                let c = centroid(&m, &w);
                let r = resultant(&m, &f, c);
                for k in 0..6 {
                    assert!((r[k] - total[k]).abs() <= 1e-12 * 100.0, "{cells:?} {r:?} vs {total:?}");
                }
            }
        }
    }

    /// Area shares: a triangle gives A/3 per corner, also as a degenerate quad [a, b, c, c].
    #[test]
    fn triangle_shares() {
        let mut m = Model::new();
        m.add_node([0.0; 3]);
        m.add_node([6.0, 0.0, 0.0]);
        m.add_node([1.0, 4.0, 0.0]);
        for cell in [vec![0, 1, 2], vec![0, 1, 2, 2]] {
            let w = tributary_weights(&m, &[cell]).unwrap();
            for (_, wi) in w {
                assert!((wi - 4.0).abs() < 1e-12, "{wi}");
            }
        }
        assert!(tributary_weights(&m, &[vec![0, 1], vec![2]]).is_err());
    }
}
