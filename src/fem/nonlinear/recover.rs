//! Recovery of a converged state: displacements and rotation vectors, element end forces and
//! stresses, reactions, and the final check of nodal and global equilibrium.

use super::residual::norm;
use super::state::{fail, CaseCtx, ElemData, State};
use super::{NonlinearCase, PathPoint};
use crate::fem::corot;
use crate::fem::error::FemError;
use crate::fem::recovery;
use crate::fem::results::{resultant, CaseResult, Statics};
use nalgebra::Vector3;

#[allow(clippy::too_many_arguments)]
pub(super) fn finish(
    ctx: &CaseCtx,
    st: &State,
    name: &str,
    lambda: f64,
    path: Vec<PathPoint>,
    iterations: usize,
    steps: usize,
    cuts: usize,
) -> Result<NonlinearCase, FemError> {
    let model = ctx.model;
    let nn = model.nodes.len();
    let arms = ctx.arms(st);
    let mut f_int = vec![0.0; 6 * nn];
    let mut elements = Vec::with_capacity(ctx.elems.len());
    let mut frames = Vec::with_capacity(ctx.elems.len());
    for (ie, e) in ctx.elems.iter().enumerate() {
        match e {
            ElemData::Corot { .. } => {
                let (nodes, r) = ctx
                    .corot_response(st, ie, false)
                    .ok_or_else(|| fail(name, steps, lambda, f64::NAN, format!("element {ie} degenerate")))?;
                for s in 0..2 {
                    for d in 0..6 {
                        f_int[6 * nodes[s] + d] += r.f[6 * s + d];
                    }
                }
                elements.push(recovery::from_local_end_forces(
                    &model.elements[ie],
                    r.f_local.as_slice(),
                    0.5 * r.d_local.dot(&r.f_local),
                ));
                let rt = r.rr.transpose();
                frames.push(std::array::from_fn(|i| std::array::from_fn(|j| rt[(i, j)])));
            }
            ElemData::Spring { nodes, n_nodes, b, k } => {
                let (_, _, _, f) = ctx
                    .element_response(st, ie, false)
                    .ok_or_else(|| fail(name, steps, lambda, f64::NAN, format!("element {ie} degenerate")))?;
                for s in 0..*n_nodes {
                    for d in 0..6 {
                        f_int[6 * nodes[s] + d] += f[6 * s + d];
                    }
                }
                let dvec = CaseCtx::spring_motion(st, nodes, *n_nodes);
                elements.push(recovery::spring_result(k, &(**b * dvec), *n_nodes));
                frames.push([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
            }
        }
    }
    let f_app: Vec<f64> = ctx.f_ext.iter().map(|v| v * lambda).collect();
    let net: Vec<f64> = f_int.iter().zip(&f_app).map(|(a, b)| a - b).collect();
    let gi = ctx.to_independent(&arms, &net);
    let reactions = recovery::reactions_at(&ctx.map, &gi);
    let pos = |n: usize| Vector3::from(model.nodes[n]) + st.u[n];
    let mut statics = Statics::default();
    for n in 0..nn {
        statics.add_load(pos(n), &f_app[6 * n..6 * n + 6]);
    }
    for (n, r) in &reactions {
        statics.add_reaction(pos(*n), r);
    }
    let equilibrium = verify_equilibrium(ctx, st, name, steps, lambda, &f_int, &f_app, &gi, &reactions)?;
    let displacements: Vec<[f64; 6]> = (0..nn)
        .map(|n| {
            let rv = corot::rot_log(&st.r[n]);
            [st.u[n][0], st.u[n][1], st.u[n][2], rv[0], rv[1], rv[2]]
        })
        .collect();
    let rotations =
        st.r.iter()
            .map(|r| std::array::from_fn(|i| std::array::from_fn(|j| r[(i, j)])))
            .collect();
    let equilibrium = path.iter().map(|p| p.equilibrium).fold(equilibrium, f64::max);
    Ok(NonlinearCase {
        equilibrium,
        fe: CaseResult::new(name, displacements, reactions, elements, statics),
        rotations,
        path,
        iterations,
        steps,
        cuts,
        stable: true,
        critical_load_factor: None,
        critical_points: Vec::new(),
        element_frames: frames,
        step_quantities: Vec::new(),
    })
}

/// Relative equilibrium bound of an accepted state (of the applied load; of the reactions
/// when displacements are prescribed).
pub(super) const EQUILIBRIUM_TOL: f64 = 1e-6;

/// Checks the accepted path point `st` at `lambda` (point `step` of load case `name`) as
/// [`finish`] checks the final state ([`verify_equilibrium`]): every returned state of the
/// path (load control, arc length, tracked steps) is balanced or the solve fails naming it.
/// Returns the relative residual ([`PathPoint::equilibrium`]).
pub(super) fn verify_point(ctx: &CaseCtx, st: &State, name: &str, step: usize, lambda: f64) -> Result<f64, FemError> {
    let (ev, _) = ctx.residual(st, lambda).ok_or_else(|| {
        fail(
            name,
            step,
            lambda,
            f64::NAN,
            "degenerate element or non-finite internal force",
        )
    })?;
    let f_app: Vec<f64> = ctx.f_ext.iter().map(|v| v * lambda).collect();
    let f_int: Vec<f64> = ev.net.iter().zip(&f_app).map(|(a, b)| a + b).collect();
    let gi = ctx.to_independent(&ev.arms, &ev.net);
    let reactions = recovery::reactions_at(&ctx.map, &gi);
    verify_equilibrium(ctx, st, name, step, lambda, &f_int, &f_app, &gi, &reactions)
}

/// Checks the accepted state: (1) the unbalanced force and moment at every free equation
/// (nodal equilibrium at the deformed positions, spins as rotational unknowns), and (2) the
/// global statics — applied loads, reactions and spring forces (springs count as supports:
/// their small-rotation moments are not objective) summed as forces and moments about the
/// origin at the deformed positions — both within [`EQUILIBRIUM_TOL`] of the applied load
/// (plus the reactions where displacements are prescribed), with a round-off allowance of
/// 1e-11 of the summed element forces. Fails naming the step otherwise; returns the largest
/// of the three residuals over its scale ([`PathPoint::equilibrium`]).
#[allow(clippy::too_many_arguments)]
pub(super) fn verify_equilibrium(
    ctx: &CaseCtx,
    st: &State,
    name: &str,
    step: usize,
    lambda: f64,
    f_int: &[f64],
    f_app: &[f64],
    gi: &[f64],
    reactions: &[(usize, [f64; 6])],
) -> Result<f64, FemError> {
    let model = ctx.model;
    let nn = model.nodes.len();
    let pos = |n: usize| Vector3::from(model.nodes[n]) + st.u[n];
    let prescribed = ctx.u_c.iter().any(|v| *v != 0.0);
    // Spring forces on their nodes (to be moved to the "support" side of the balance).
    let mut f_spring = vec![0.0; 6 * nn];
    for (ie, e) in ctx.elems.iter().enumerate() {
        if let ElemData::Spring { nodes, n_nodes, .. } = e {
            if let Some((_, _, _, f)) = ctx.element_response(st, ie, false) {
                for s in 0..*n_nodes {
                    for d in 0..6 {
                        f_spring[6 * nodes[s] + d] += f[6 * s + d];
                    }
                }
            }
        }
    }
    let (mut sum, mut scale_f, mut scale_m) = ([0.0; 6], 0.0, 0.0);
    let mut add = |x: Vector3<f64>, f: &[f64], sign: f64, counts: bool| {
        let v = resultant(x, f);
        for (a, b) in sum.iter_mut().zip(v) {
            *a += sign * b;
        }
        if counts {
            let fv = Vector3::new(f[0], f[1], f[2]);
            scale_f += fv.norm();
            scale_m += Vector3::new(f[3], f[4], f[5]).norm();
        }
    };
    for n in 0..nn {
        add(pos(n), &f_app[6 * n..6 * n + 6], 1.0, true);
        add(pos(n), &f_spring[6 * n..6 * n + 6], -1.0, false);
    }
    for (n, r) in reactions {
        add(pos(*n), r, 1.0, prescribed);
    }
    let internal: f64 = f_int.iter().map(|v| v.abs()).sum();
    let arms = ctx.arms(st);
    let fi = norm(&ctx.to_independent(&arms, f_int));
    let residual: Vec<f64> = ctx.map.eq_dof.iter().map(|&g| gi[g]).collect();
    let rn = norm(&residual);
    let round = ctx.round + 1e-13 * internal;
    let nodal_scale = norm(f_app).max(fi);
    let nodal_ok = rn <= EQUILIBRIUM_TOL * nodal_scale + round;
    let fsum = Vector3::new(sum[0], sum[1], sum[2]).norm();
    let msum = Vector3::new(sum[3], sum[4], sum[5]).norm();
    // Moments about the origin: forces act on levers up to the model's extent from it.
    let lever = (0..nn).map(|n| pos(n).norm()).fold(0.0, f64::max).max(1.0);
    // Force scale: the applied forces plus the applied moments over the model's size (a pure
    // moment loads the structure with internal force pairs of order M/size; without this term a
    // moment-only load case would be checked against a zero force).
    let size = model_size(model, st).max(1e-300);
    let (force_scale, moment_scale) = (scale_f + scale_m / size, scale_m + lever * scale_f);
    let force_ok = fsum <= EQUILIBRIUM_TOL * force_scale + round;
    let moment_ok = msum <= EQUILIBRIUM_TOL * moment_scale + round * lever;
    if nodal_ok && force_ok && moment_ok {
        let rel = |r: f64, scale: f64| if r == 0.0 { 0.0 } else { r / scale };
        return Ok(rel(rn, nodal_scale)
            .max(rel(fsum, force_scale))
            .max(rel(msum, moment_scale)));
    }
    Err(fail(
        name,
        step,
        lambda,
        rn,
        format!(
            "the accepted state is not in equilibrium: unbalanced force {fsum:.3e} N and moment {msum:.3e} N·mm (statics at the deformed positions, against applied loads of {scale_f:.3e} N and {scale_m:.3e} N·mm over a model size of {size:.3e} mm); nodal residual {rn:.3e}"
        ),
    ))
}

/// Diagonal of the bounding box of the deformed nodes, mm.
fn model_size(model: &crate::fem::Model, st: &State) -> f64 {
    let mut lo = Vector3::repeat(f64::INFINITY);
    let mut hi = Vector3::repeat(f64::NEG_INFINITY);
    for (n, x) in model.nodes.iter().enumerate() {
        let p = Vector3::from(*x) + st.u[n];
        lo = lo.inf(&p);
        hi = hi.sup(&p);
    }
    if model.nodes.is_empty() {
        0.0
    } else {
        (hi - lo).norm()
    }
}
