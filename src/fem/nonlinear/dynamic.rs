//! Geometrically nonlinear transient dynamics: Newmark's average-acceleration rule (γ = ½,
//! β = ¼; N. M. Newmark, J. Eng. Mech. Div. ASCE 85 (1959) 67–94) with Newton iterations per
//! step on the dynamic residual
//!
//! ```text
//! R(Δ) = M aₙ₊₁ + C vₙ₊₁ + f_int(uₙ₊₁) − f(tₙ₊₁) = 0
//! aₙ₊₁ = 4 Δ/Δt² − 4 vₙ/Δt − aₙ,  vₙ₊₁ = 2 Δ/Δt − vₙ,  tangent K_t + 4 M/Δt² + 2 C/Δt
//! ```
//!
//! with the co-rotational internal force and consistent tangent of the static solver
//! ([`super::CaseCtx::evaluate`]). Model (stated approximation): the generalised coordinates are
//! the translations and the *accumulated incremental rotation vectors* (the sums of the spins
//! δw by which the nodal rotation matrices are updated, R ← exp([δw×]) R); M and C are the
//! matrices of the undeformed configuration (constant, global axes). This is exact for the
//! translational inertia of point masses; it neglects the rotation of element mass matrices
//! and of rotary inertia tensors (gyroscopic terms ω × Jω), so distributed beam mass and rotary
//! inertia are approximate once elements rotate by large angles. Rigid-link slaves carry their
//! mass with the undeformed arm. Loads are fixed in space. No step cutting: a step whose Newton
//! iterations fail is an error naming the step and time (take a smaller Δt).

use super::convergence::{Convergence, Iterate, Verdict};
use super::load_case::case_ctx;
use super::recover::EQUILIBRIUM_TOL;
use super::residual::{dot, norm};
use super::state::{CaseCtx, ElemData, State};
use super::{element_data, NonlinearOptions};
use crate::fem::assembly::Pattern;
use crate::fem::constraints::DofMap;
use crate::fem::error::FemError;
use crate::fem::model::Model;
use crate::fem::solve::{Factor, SparseMatrix, SymbolicFactor};
use crate::fem::transient::{
    check_inputs, matrices, Energy, Scheme, TransientLoad, TransientOptions, TransientResults,
};
use nalgebra::{Matrix3, Vector3, Vector6};

/// One-line description of the model of [`solve_transient_nonlinear`] (for result files).
pub const NONLINEAR_TRANSIENT_MODEL: &str = "geometrically nonlinear: co-rotational beams and hinge elements, Newmark average acceleration with Newton iterations per step on M a + C v + f_int(u) = f(t); M and C of the undeformed configuration (constant, global axes) act on the translations and on accumulated incremental rotation vectors: exact for the translational inertia of point masses, approximate for distributed beam mass and rotary inertia under large rotations (rotation of element mass matrices and gyroscopic terms neglected); loads fixed in space";

fn err(step: usize, t: f64, residual: f64, reason: &str) -> FemError {
    FemError::Solver(format!(
        "nonlinear transient: step {step} (t = {t} s) failed: {reason} (dynamic residual {residual:.3e}); try a smaller time step"
    ))
}

/// Strain energy of the elements at `st` (½ dᵀ K d of each co-rotated element and spring).
fn strain_energy(ctx: &CaseCtx, st: &State) -> f64 {
    (0..ctx.elems.len())
        .filter_map(|ie| match &ctx.elems[ie] {
            ElemData::Corot { .. } => ctx
                .corot_response(st, ie, false)
                .map(|(_, r)| 0.5 * r.d_local.dot(&r.f_local)),
            ElemData::Spring { nodes, n_nodes, .. } => {
                let d = CaseCtx::spring_motion(st, nodes, *n_nodes);
                ctx.element_response(st, ie, false)
                    .map(|(_, _, _, f)| 0.5 * (0..12).map(|i| d[i] * f[i]).sum::<f64>())
            }
        })
        .sum()
}

/// Equation values carried to every node with the current arms (6 per node, global).
fn expand_current(ctx: &CaseCtx, st: &State, q: &[f64]) -> Vec<f64> {
    let d = ctx.map.scatter(q, None);
    let arms = ctx.arms(st);
    let mut out = vec![0.0; d.len()];
    for (n, arm) in arms.iter().enumerate() {
        let m = ctx.map.rep[n];
        let dm = Vector6::from_column_slice(&d[6 * m..6 * m + 6]);
        let v = arm.map_or(dm, |a| a * dm);
        out[6 * n..6 * n + 6].copy_from_slice(v.as_slice());
    }
    out
}

/// Integrates `model` from rest under `loads` with geometric nonlinearity (see the module
/// docs). `opts`: time step, steps, damping, records, snapshots and energies as for the linear
/// solver (average acceleration only, no initial state); `nl`: the Newton tolerances and
/// iteration budget of the static solver. Recorded and snapshot rotations are rotation vectors
/// log(R) (rad, global); velocities and accelerations of rotations are the rates of the
/// accumulated incremental rotation vectors.
pub fn solve_transient_nonlinear(
    model: &Model,
    loads: &[TransientLoad],
    opts: &TransientOptions,
    nl: &NonlinearOptions,
) -> Result<TransientResults, FemError> {
    check_inputs(model, loads, opts)?;
    if opts.scheme != Scheme::AverageAcceleration || opts.initial.is_some() {
        return Err(FemError::BadInput(
            "nonlinear transient: Newmark average acceleration from rest only (no HHT, no initial state)".into(),
        ));
    }
    let elems = element_data(model)?;
    let nn = model.nodes.len();
    // Constant M and C on the linear equations (the same numbering as the nonlinear map).
    let lin_map = DofMap::new(model, &[], Some("transient"))?;
    let pattern = Pattern::new(model, &lin_map)?;
    let (k0, m, ce) = matrices(model, &lin_map, &pattern, &opts.damping)?;
    let (ra, rb) = (opts.damping.alpha, opts.damping.beta);
    let pm = |e: Option<SparseMatrix>| e.ok_or_else(|| FemError::PatternMismatch("K and M patterns differ".into()));
    let mut c = pm(k0.lin_comb(rb, &m, ra))?;
    if let Some(ce) = &ce {
        c = pm(c.lin_comb(1.0, ce, 1.0))?;
    }
    let dt = opts.dt;
    let (c0, c1) = (4.0 / (dt * dt), 2.0 / dt);
    let dyn_lower = pm(m.lin_comb(c0, &c, c1))?.lower_triplets();
    let extra: Vec<(usize, usize)> = dyn_lower.iter().map(|&(r, cc, _)| (r, cc)).collect();
    let mut ctx = case_ctx(
        model,
        &elems,
        &[],
        "transient",
        vec![0.0; 6 * nn],
        vec![0.0; 6 * nn],
        nl,
        &extra,
    )?;
    let full = ctx.full.is_some();
    let extra_values: Vec<f64> = dyn_lower
        .iter()
        .flat_map(|&(r, cc, v)| std::iter::repeat_n(v, if full && r != cc { 2 } else { 1 }))
        .collect();
    let n = ctx.n_eq();
    let force = |t: f64| -> Vec<f64> {
        let mut f = vec![0.0; 6 * nn];
        for l in loads {
            let g = l.history.value(t);
            for d in 0..6 {
                f[6 * l.node + d] += g * l.f[d];
            }
        }
        f
    };
    let mut st = State {
        u: vec![Vector3::zeros(); nn],
        r: vec![Matrix3::identity(); nn],
    };
    let (mut v, mut a) = (vec![0.0; n], vec![0.0; n]);
    let mut res = TransientResults {
        time: Vec::with_capacity(opts.steps + 1),
        displacement: vec![Vec::new(); opts.record.len()],
        velocity: vec![Vec::new(); opts.record.len()],
        acceleration: vec![Vec::new(); opts.record.len()],
        snapshots: Vec::new(),
        energy: Vec::new(),
        n_eq: n,
        warnings: Vec::new(),
        equilibrium: Some(0.0),
    };
    // Initial acceleration: M a₀ = f(0) (at rest and undeformed, f_int = 0).
    ctx.f_ext = force(0.0);
    let r0 = ctx.reduced_load(&st);
    if r0.iter().any(|&x| x != 0.0) {
        match Factor::new(&SymbolicFactor::new(pattern.sparse())?, &m, opts.par) {
            Ok(mf) => {
                a.copy_from_slice(&r0);
                mf.solve_in_place(&mut a, 1)?;
            }
            Err(_) => res.warnings.push(
                "the mass matrix is singular (DOFs without mass): the initial acceleration is taken as zero, so a load jumping at t = 0 acts as a ramp over the first step".into(),
            ),
        }
    }
    let (mf, cf) = (m.full(), c.full());
    record(&mut res, &ctx, &st, opts, 0.0, &v, &a, &mf);
    let (mut internal, mut inertia) = (0.0, norm(&r0));
    for step in 1..=opts.steps {
        let t1 = step as f64 * dt;
        ctx.f_ext = force(t1);
        let mut test = Convergence::new(nl.tol_residual, nl.tol_energy, ctx.round, nl.max_iterations, internal);
        let mut delta = vec![0.0; n];
        let mut last: Option<Vec<f64>> = None;
        let mut done = false;
        for it in 0..=nl.max_iterations {
            let ev = ctx
                .evaluate(&st, 1.0, ctx.newton_tangent())
                .ok_or_else(|| err(step, t1, f64::NAN, "degenerate element or non-finite internal force"))?;
            let a1: Vec<f64> = (0..n).map(|i| c0 * delta[i] - 2.0 * c1 * v[i] - a[i]).collect();
            let v1: Vec<f64> = (0..n).map(|i| c1 * delta[i] - v[i]).collect();
            let (ma, cv) = (mf.mul_vec(&a1), cf.mul_vec(&v1));
            let r: Vec<f64> = (0..n).map(|i| ma[i] + cv[i] + ev.r[i]).collect();
            // Force scale: the applied load, and the inertia and damping forces and the
            // internal forces of the last converged state (not of the predictor, whose inertia
            // is an artefact of the zero increment).
            let load = ev.load.max(inertia);
            let rn = norm(&r);
            match test.check(&Iterate::after(&r, load, ev.internal, last.as_deref(), &delta)) {
                Verdict::Converged => {
                    let scale = load.max(internal);
                    if rn > EQUILIBRIUM_TOL * scale + ctx.round {
                        return Err(err(step, t1, rn, "the accepted state is not in dynamic equilibrium"));
                    }
                    if rn > 0.0 {
                        res.equilibrium = res.equilibrium.map(|e| e.max(rn / scale));
                    }
                    let f: Vec<f64> = (0..n).map(|i| ma[i] + cv[i]).collect();
                    (v, a, internal, inertia, done) = (v1, a1, ev.internal, norm(&f), true);
                    break;
                }
                Verdict::NoConvergence => return Err(err(step, t1, rn, "no convergence of the Newton iterations")),
                Verdict::Diverges => return Err(err(step, t1, rn, "the Newton iterations diverge")),
                Verdict::Continue => {}
            }
            let mut values = ev.values;
            values.extend_from_slice(&extra_values);
            let neg: Vec<f64> = r.iter().map(|x| -x).collect();
            let dq = ctx
                .solve(&values, &[neg])
                .map_err(|e| err(step, t1, rn, &e))?
                .x
                .into_iter()
                .next()
                .unwrap_or_default();
            if dq.iter().any(|x| !x.is_finite()) {
                return Err(err(step, t1, rn, "non-finite correction"));
            }
            if it == 0 {
                test.first_correction(dot(&dq, &r).abs());
            }
            ctx.apply(&mut st, &dq, None);
            delta.iter_mut().zip(&dq).for_each(|(d, x)| *d += x);
            last = Some(dq);
        }
        if !done {
            return Err(err(step, t1, f64::NAN, "no convergence of the Newton iterations"));
        }
        record(&mut res, &ctx, &st, opts, t1, &v, &a, &mf);
    }
    Ok(res)
}

#[allow(clippy::too_many_arguments)]
fn record(
    res: &mut TransientResults,
    ctx: &CaseCtx,
    st: &State,
    opts: &TransientOptions,
    t: f64,
    v: &[f64],
    a: &[f64],
    mf: &crate::fem::solve::FullSymmetric,
) {
    let step = res.time.len();
    res.time.push(t);
    if !opts.record.is_empty() {
        let u = ctx.tracked(st, &opts.record);
        let (vf, af) = (expand_current(ctx, st, v), expand_current(ctx, st, a));
        for (i, r) in opts.record.iter().enumerate() {
            res.displacement[i].push(u[i]);
            res.velocity[i].push(vf[r.global()]);
            res.acceleration[i].push(af[r.global()]);
        }
    }
    let every = opts.snapshot_every;
    if every > 0 && step.is_multiple_of(every) {
        let nodes = (0..ctx.model.nodes.len())
            .map(|n| {
                let w = crate::fem::corot::rot_log(&st.r[n]);
                [st.u[n][0], st.u[n][1], st.u[n][2], w[0], w[1], w[2]]
            })
            .collect();
        res.snapshots.push((t, nodes));
    }
    if opts.energy {
        res.energy.push(Energy {
            kinetic: 0.5 * dot(v, &mf.mul_vec(v)),
            strain: strain_energy(ctx, st),
        });
    }
}
