//! The solve of one load case: its fixed data (DOF map, loads, prescribed values, sparsity
//! pattern and symbolic factorisation), the path control, and the recovery of every converged
//! point.

use super::arc::arc_length;
use super::critical::locate;
use super::path::{load_control, Predictor, Stability};
use super::recover::finish;
use super::residual::for_each_pair_in;
use super::state::{CaseCtx, ElemData, State};
use super::{NonlinearCase, NonlinearOptions, PathPoint, Tangent};
use crate::fem::analysis::prescribed_dofs;
use crate::fem::constraints::DofMap;
use crate::fem::error::FemError;
use crate::fem::model::{LoadCase, Model};
use crate::fem::solve::{LuPattern, SparsePattern, SymbolicFactor};
use nalgebra::{Matrix3, Vector3};

pub(super) fn solve_case(
    model: &Model,
    elems: &[ElemData],
    case: &LoadCase,
    opts: &NonlinearOptions,
) -> Result<NonlinearCase, FemError> {
    model.validate_case(case)?;
    let prescribed = prescribed_dofs(case);
    let nn = model.nodes.len();
    let (f_ext, u_c) = case_vectors(nn, case);
    let ctx = case_ctx(model, elems, &prescribed, &case.name, f_ext, u_c, opts, &[])?;
    let mut st = State {
        u: vec![Vector3::zeros(); nn],
        r: vec![Matrix3::identity(); nn],
    };
    let mut path = vec![PathPoint {
        lambda: 0.0,
        values: ctx.tracked(&st, &opts.track),
        stable: true,
        residuals: Vec::new(),
        equilibrium: 0.0,
    }];
    ctx.record_step(&st, 0.0, 0)?;
    let has_prescribed = ctx.u_c.iter().any(|&v| v != 0.0);
    let mut stab = Stability::default();
    let (iterations, steps, cuts, lambda) = if opts.arc_length {
        if has_prescribed {
            return Err(FemError::LoadCase {
                case: case.name.clone(),
                reason: "arc-length control needs a load-controlled case (no non-zero prescribed displacements)".into(),
            });
        }
        arc_length(&ctx, &mut st, opts, &case.name, &mut path, &mut stab)?
    } else {
        load_control(
            &ctx,
            &mut st,
            [0.0, 1.0],
            1.0 / opts.steps as f64,
            opts,
            &case.name,
            &mut path,
            0,
            &mut stab,
            Predictor::Moved,
        )?
    };
    let mut out = finish(&ctx, &st, &case.name, lambda, path, iterations, steps, cuts)?;
    out.stable = stab.bracket.is_none();
    out.critical_load_factor = stab.bracket;
    if let Some(t) = &ctx.tracker {
        out.step_quantities = t.steps.take();
    }
    if opts.locate_critical {
        out.critical_points = stab
            .changes
            .iter()
            .filter_map(|c| locate(&ctx, c, opts, &opts.track))
            .collect();
    }
    Ok(out)
}

/// The fixed data of a solve on `model` with `prescribed` DOFs removed: DOF map, loads
/// `f_ext` and prescribed values `u_c` (6 per node), sparsity pattern (element pairs, rigid-link
/// master blocks, one diagonal slot per equation, then the lower-triangle pairs `extra`, whose
/// values the caller appends to [`CaseCtx::evaluate`]'s) and symbolic factorisation.
#[allow(clippy::too_many_arguments)]
pub(super) fn case_ctx<'a>(
    model: &'a Model,
    elems: &'a [ElemData],
    prescribed: &[crate::fem::dof::NodeDof],
    name: &str,
    f_ext: Vec<f64>,
    u_c: Vec<f64>,
    opts: &NonlinearOptions,
    extra: &[(usize, usize)],
) -> Result<CaseCtx<'a>, FemError> {
    let map = DofMap::new(model, prescribed, Some(name))?;
    let nn = model.nodes.len();
    let arm0: Vec<Vector3<f64>> = (0..nn)
        .map(|n| Vector3::from(model.nodes[n]) - Vector3::from(model.nodes[map.rep[n]]))
        .collect();
    let mut masters: Vec<usize> = model.rigid_links.iter().map(|l| l.master).collect();
    masters.sort_unstable();
    masters.dedup();
    // Pattern: element pairs, master blocks, one diagonal slot per equation.
    let n_eq = map.n_eq();
    let pairs_of = |lower: bool| {
        let mut pairs = Vec::new();
        for e in elems {
            let (nodes, nn_e) = match e {
                ElemData::Corot { nodes, .. } => (*nodes, 2),
                ElemData::Spring { nodes, n_nodes, .. } => (*nodes, *n_nodes),
            };
            let eqs = map.element_eqs([map.rep[nodes[0]], map.rep[nodes[1]]], nn_e);
            for_each_pair_in(lower, &eqs, 6 * nn_e, |_, _, r, c| pairs.push((r, c)));
        }
        for &m in &masters {
            let eqs = map.element_eqs([m, m], 1);
            for_each_pair_in(lower, &eqs, 6, |_, _, r, c| pairs.push((r, c)));
        }
        pairs.extend((0..n_eq).map(|i| (i, i)));
        for &(r, c) in extra {
            pairs.push((r, c));
            if !lower && r != c {
                pairs.push((c, r));
            }
        }
        pairs
    };
    let pairs = pairs_of(true);
    let pattern = SparsePattern::new(n_eq, &pairs)?;
    let symbolic = SymbolicFactor::new(&pattern)?;
    // Moments applied at independent nodes, or forces on rigid-link slaves (a moment on the
    // master): the tangent's skew part survives at equilibrium ([`Tangent`]).
    let moments = (0..nn).any(|n| {
        let f = &f_ext[6 * n..6 * n + 6];
        f[3..].iter().any(|v| *v != 0.0) || (map.rep[n] != n && f[..3].iter().any(|v| *v != 0.0))
    });
    let full = match opts.tangent {
        Tangent::Full => true,
        Tangent::Symmetric => false,
        Tangent::Auto => moments,
    };
    let full = if full {
        Some(LuPattern::new(n_eq, &pairs_of(false))?)
    } else {
        None
    };
    let tracker = super::state::Tracker::new(model, elems, &map, &pairs, &opts.step_track)?;
    Ok(CaseCtx {
        model,
        elems,
        map,
        arm0,
        f_ext,
        u_c,
        pattern,
        symbolic,
        lower_pairs: pairs,
        mirror: std::cell::OnceCell::new(),
        round: 1e-14
            * elems
                .iter()
                .map(|e| match e {
                    ElemData::Corot { geom, k_local, .. } => {
                        let k = |i: usize| k_local[(i, i)].abs();
                        (0..3).map(k).fold(0.0, f64::max) * geom.l0 + (3..6).map(k).fold(0.0, f64::max)
                    }
                    ElemData::Spring { k, .. } => k.iter().fold(0.0f64, |m, v| m.max(v.abs())),
                })
                .fold(0.0, f64::max),
        full,
        masters,
        par: opts.parallelism,
        tracker,
    })
}

/// The applied forces and the prescribed displacements of `case` as full vectors (6 per node of
/// a model of `nn` nodes): N, N·mm; mm, rad.
pub(super) fn case_vectors(nn: usize, case: &LoadCase) -> (Vec<f64>, Vec<f64>) {
    let mut f_ext = vec![0.0; 6 * nn];
    for l in &case.forces {
        for d in 0..6 {
            f_ext[6 * l.node + d] += l.f[d];
        }
    }
    let mut u_c = vec![0.0; 6 * nn];
    for p in &case.displacements {
        u_c[6 * p.node + p.dof.index()] = p.value;
    }
    (f_ext, u_c)
}
