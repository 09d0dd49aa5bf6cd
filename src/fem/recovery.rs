//! Recovery: element end forces and section forces in local axes, stresses at the section's
//! critical points (von Mises), reactions and the statics check (PyNite's `_check_statics`).

use super::constraints::DofMap;
use super::error::FemError;
use super::model::{Element, Model};
pub use super::results::{CaseResult, ElementResult, Statics};
use super::section::{Section, SectionProps, StressPoint};
use super::shell::{shell_stress, ShellStress, Vec24};
use super::shell9::shell9_largest_stress;
use nalgebra::{SVector, Vector3};
use rayon::prelude::*;

/// Element count below which assembly and recovery run on the calling thread.
pub const PARALLEL_MIN: usize = 64;

/// Von Mises stress at one stress point for section forces s = [N, Vy, Vz, T, My, Mz]:
/// σ = N/A + My·z/Iy − Mz·y/Iz, τxy = T·t_xy + Vy·vy_xy, τxz = T·t_xz + Vz·vz_xz,
/// σ_vM = √(σ² + 3(τxy² + τxz²)), MPa.
pub fn point_von_mises(p: &SectionProps, pt: &StressPoint, s: &[f64; 6]) -> f64 {
    let sigma = s[0] / p.a + s[4] * pt.z / p.iy - s[5] * pt.y / p.iz;
    let (mut txy, mut txz) = (s[3] * pt.t_xy + s[1] * pt.vy_xy, s[3] * pt.t_xz + s[2] * pt.vz_xz);
    if pt.round_shear != 0.0 {
        let v = s[1].hypot(s[2]);
        let r = pt.y.hypot(pt.z);
        if v > 0.0 && r > 0.0 {
            let c = (pt.y * s[1] + pt.z * s[2]) / (r * v);
            let f = pt.round_shear * (1.0 - c * c);
            txy += f * s[1];
            txz += f * s[2];
        }
    }
    (sigma * sigma + 3.0 * (txy * txy + txz * txz)).sqrt()
}

/// Largest von Mises stress over the section's stress points (MPa); for round sections the two
/// exact peak-bending points (direction (−Mz, My)) are added. `None` for general sections.
pub fn section_von_mises(section: &Section, p: &SectionProps, s: &[f64; 6]) -> Option<f64> {
    let mut pts = section.stress_points();
    if section.is_round() {
        for sign in [1.0, -1.0] {
            if let Some(pt) = section.round_point(-sign * s[5], sign * s[4]) {
                pts.push(pt);
            }
        }
    }
    pts.iter()
        .map(|pt| point_von_mises(p, pt, s))
        .fold(None, |m, v| Some(m.map_or(v, |m: f64| m.max(v))))
}

fn node_vec(u: &[f64], n: usize) -> SVector<f64, 6> {
    SVector::<f64, 6>::from_column_slice(&u[6 * n..6 * n + 6])
}

fn elem_vec(u: &[f64], nodes: [usize; 2]) -> SVector<f64, 12> {
    let mut d = SVector::<f64, 12>::zeros();
    d.fixed_rows_mut::<6>(0).copy_from(&node_vec(u, nodes[0]));
    d.fixed_rows_mut::<6>(6).copy_from(&node_vec(u, nodes[1]));
    d
}

fn shell_vec(u: &[f64], nodes: [usize; 4]) -> Vec24 {
    let mut d = Vec24::zeros();
    for (k, &n) in nodes.iter().enumerate() {
        d.fixed_rows_mut::<6>(6 * k).copy_from(&node_vec(u, n));
    }
    d
}

/// A shell's element result: its stresses and strain energy (N·mm); von Mises the largest of
/// its top, middle and bottom values at both "ends".
fn shell_result(stress: ShellStress, strain_energy: f64) -> ElementResult {
    let vm = stress.von_mises.iter().copied().fold(0.0, f64::max);
    ElementResult {
        end_forces: [[0.0; 6]; 2],
        section_forces: [[0.0; 6]; 2],
        von_mises: Some([vm, vm]),
        strain_energy,
        shell: Some(stress),
    }
}

fn shell9_vec(u: &[f64], nodes: [usize; 9]) -> nalgebra::DVector<f64> {
    nalgebra::DVector::from_iterator(54, nodes.iter().flat_map(|&n| u[6 * n..6 * n + 6].iter().copied()))
}

/// Internal force vector p = Σₑ Kₑ uₑ (6 per node, global axes), ground springs included.
pub fn internal_forces(model: &Model, u: &[f64]) -> Result<Vec<f64>, FemError> {
    let mut p = vec![0.0; model.n_dofs()];
    for ie in 0..model.elements.len() {
        if let Element::Shell4(_) = model.elements[ie] {
            let em = model.shell_matrix(ie)?;
            let f = em.k * shell_vec(u, em.nodes);
            for k in 0..4 {
                for i in 0..6 {
                    p[6 * em.nodes[k] + i] += f[6 * k + i];
                }
            }
            continue;
        }
        if let Element::Shell9(_) = model.elements[ie] {
            let em = model.shell9_matrix(ie)?;
            let f = &em.k * shell9_vec(u, em.nodes);
            for k in 0..9 {
                for i in 0..6 {
                    p[6 * em.nodes[k] + i] += f[6 * k + i];
                }
            }
            continue;
        }
        let em = model.element_matrix(ie)?;
        let d = elem_vec(u, em.nodes);
        let f = em.k * d;
        for k in 0..em.n_nodes {
            for i in 0..6 {
                p[6 * em.nodes[k] + i] += f[6 * k + i];
            }
        }
    }
    Ok(p)
}

/// Results of element `ie` for the global displacement vector `u`.
pub fn element_result(model: &Model, ie: usize, u: &[f64]) -> Result<ElementResult, FemError> {
    match &model.elements[ie] {
        Element::Shell4(sh) => {
            let em = model.shell_matrix(ie)?;
            let d = shell_vec(u, em.nodes);
            let x = sh.nodes.map(|n| model.nodes[n]);
            let stress = shell_stress(&x, sh.t, &sh.material, &d).ok_or_else(|| FemError::BadElement {
                element: ie,
                reason: "degenerate shell geometry".into(),
            })?;
            Ok(shell_result(stress, 0.5 * d.dot(&(em.k * d))))
        }
        Element::Shell9(sh) => {
            let em = model.shell9_matrix(ie)?;
            let d = shell9_vec(u, em.nodes);
            let x = sh.nodes.map(|n| model.nodes[n]);
            // The element's stress is its largest over the 3×3 Gauss points (the centre among them).
            let stress = shell9_largest_stress(&x, sh.t, &sh.material, &d).map_err(|e| FemError::BadElement {
                element: ie,
                reason: e.to_string(),
            })?;
            Ok(shell_result(stress, 0.5 * d.dot(&(&em.k * &d))))
        }
        Element::Spring(s) => {
            let (b, k, n) = model.spring_b(ie)?;
            let nodes = [s.a, s.b.unwrap_or(s.a)];
            let mut d = elem_vec(u, nodes);
            if n == 1 {
                d.fixed_rows_mut::<6>(6).fill(0.0);
            }
            Ok(spring_result(&k, &(b * d), n))
        }
        Element::Matrix(_) => {
            // Superelement piece: end forces K·d in global axes, no section forces or stresses.
            let em = model.element_matrix(ie)?;
            let mut d = elem_vec(u, em.nodes);
            if em.n_nodes == 1 {
                d.fixed_rows_mut::<6>(6).fill(0.0);
            }
            let f = em.k * d;
            Ok(ElementResult {
                end_forces: [std::array::from_fn(|i| f[i]), std::array::from_fn(|i| f[6 + i])],
                section_forces: [[0.0; 6]; 2],
                von_mises: None,
                strain_energy: 0.5 * d.dot(&f),
                shell: None,
            })
        }
        e => {
            let (k, t) = model.element_local(ie)?;
            let d = t * elem_vec(u, e.end_nodes());
            let f = k * d;
            Ok(from_local_end_forces(e, f.as_slice(), 0.5 * d.dot(&f)))
        }
    }
}

/// Result of a spring from its relative motion δ = B·d in spring axes, its stiffnesses `k` and
/// its node count (1 = ground spring): spring forces k·δ, end forces, energy ½ Σ kᵢ δᵢ². Shared
/// by the linear recovery and the co-rotational solver (which passes δ of the current state).
pub fn spring_result(k: &[f64; 6], delta: &SVector<f64, 6>, n_nodes: usize) -> ElementResult {
    let f: [f64; 6] = std::array::from_fn(|i| k[i] * delta[i]);
    let energy = 0.5 * (0..6).map(|i| k[i] * delta[i] * delta[i]).sum::<f64>();
    let end_forces = if n_nodes == 1 {
        [f, [0.0; 6]]
    } else {
        [f.map(|v| -v), f]
    };
    ElementResult {
        end_forces,
        section_forces: [f, f],
        von_mises: None,
        strain_energy: energy,
        shell: None,
    }
}

/// Result of a two-node beam or flexibility element from its end forces f = k·d in element
/// local axes (12 values, node 1 then node 2) and its strain energy (N·mm). Shared by the linear
/// recovery and the co-rotational solver (which passes the forces of the deformed local frame).
pub fn from_local_end_forces(e: &Element, f: &[f64], strain_energy: f64) -> ElementResult {
    let props = match e {
        Element::Beam(b) => Some(b.section.properties(b.material.nu)),
        _ => None,
    };
    from_local_end_forces_with(e, f, strain_energy, props.as_ref())
}

/// [`from_local_end_forces`] with a beam's section properties `props` given (computed once for
/// many elements or load cases).
pub fn from_local_end_forces_with(
    e: &Element,
    f: &[f64],
    strain_energy: f64,
    props: Option<&SectionProps>,
) -> ElementResult {
    let f1: [f64; 6] = std::array::from_fn(|i| f[i]);
    let f2: [f64; 6] = std::array::from_fn(|i| f[6 + i]);
    let s1 = f1.map(|v| -v);
    let von_mises = match (e, props) {
        (Element::Beam(b), Some(p)) => {
            match (
                section_von_mises(&b.section, p, &s1),
                section_von_mises(&b.section, p, &f2),
            ) {
                (Some(a), Some(c)) => Some([a, c]),
                _ => None,
            }
        }
        _ => None,
    };
    ElementResult {
        end_forces: [f1, f2],
        section_forces: [s1, f2],
        von_mises,
        strain_energy,
        shell: None,
    }
}

/// Largest distance between nodes along any axis (statics tolerance scale), mm.
pub fn model_size(model: &Model) -> f64 {
    let (lo, hi) = model.bounding_box();
    (0..3).map(|i| hi[i] - lo[i]).fold(0.0, f64::max).max(1.0)
}

/// Reactions per constrained node from the out-of-balance forces `gi` in independent (node-frame)
/// components: [Fx, Fy, Fz (N), Mx, My, Mz (N·mm)], rotated to global axes at framed nodes.
/// Shared by the linear and the nonlinear recovery.
pub(crate) fn reactions_at(map: &DofMap, gi: &[f64]) -> Vec<(usize, [f64; 6])> {
    let mut reactions: Vec<(usize, [f64; 6])> = Vec::new();
    for &c in &map.constrained {
        let node = c / 6;
        if reactions.last().map(|r| r.0) != Some(node) {
            reactions.push((node, [0.0; 6]));
        }
        if let Some(r) = reactions.last_mut() {
            r.1[c % 6] = gi[c];
        }
    }
    // Framed nodes: reactions were found in the node frame; report them in global axes.
    for (node, r) in reactions.iter_mut() {
        if map.framed.contains(node) {
            if let Some(t) = &map.arm[*node] {
                let g = t * nalgebra::Vector6::from_column_slice(r);
                *r = std::array::from_fn(|i| g[i]);
            }
        }
    }
    reactions
}

/// Builds the [`CaseResult`] from the full displacement vector `u` and the applied load
/// vector `f` (6 per node). Reactions r = Aᵀ(K u − f) at constrained DOFs.
pub fn case_result(model: &Model, map: &DofMap, name: &str, u: &[f64], f: &[f64]) -> Result<CaseResult, FemError> {
    let r = case_result_unchecked(model, map, name, u, f)?;
    debug_assert!(
        r.statics.is_balanced(1e-6, model_size(model)),
        "statics check failed in load case {name:?}: loads {:?}, reactions {:?}",
        r.statics.loads,
        r.statics.reactions
    );
    Ok(r)
}

/// [`case_result`] without the statics check: for displacements `u` that are not a solution of
/// the model (a gradient evaluates results along a first-order path, in balance to second order).
pub fn case_result_unchecked(
    model: &Model,
    map: &DofMap,
    name: &str,
    u: &[f64],
    f: &[f64],
) -> Result<CaseResult, FemError> {
    let p = internal_forces(model, u)?;
    let g: Vec<f64> = p.iter().zip(f).map(|(a, b)| a - b).collect();
    let reactions = reactions_at(map, &map.to_independent(&g));
    let mut statics = Statics::default();
    for (n, x) in model.nodes.iter().enumerate() {
        statics.add_load(Vector3::from(*x), &f[6 * n..6 * n + 6]);
    }
    for (n, r) in &reactions {
        statics.add_reaction(Vector3::from(model.nodes[*n]), r);
    }
    for ie in 0..model.elements.len() {
        if let Element::Spring(s) = &model.elements[ie] {
            if s.b.is_none() {
                let em = model.element_matrix(ie)?;
                let fs = em.k.fixed_view::<6, 6>(0, 0) * node_vec(u, s.a);
                let neg: Vec<f64> = fs.iter().map(|v| -v).collect();
                statics.add_reaction(Vector3::from(model.nodes[s.a]), &neg);
            }
        }
    }
    let ne = model.elements.len();
    let elements: Vec<ElementResult> = if ne < PARALLEL_MIN {
        (0..ne)
            .map(|ie| element_result(model, ie, u))
            .collect::<Result<_, _>>()?
    } else {
        (0..ne)
            .into_par_iter()
            .map(|ie| element_result(model, ie, u))
            .collect::<Result<_, _>>()?
    };
    let displacements = (0..model.nodes.len())
        .map(|n| std::array::from_fn(|i| u[6 * n + i]))
        .collect();
    Ok(CaseResult::new(name, displacements, reactions, elements, statics))
}
