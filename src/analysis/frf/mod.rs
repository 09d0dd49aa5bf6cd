//! `"analysis": "frf"`: frequency response of a mesh model (as for `modal`) from nodal loads to
//! nodal DOFs, by modal superposition with static correction, checked by a direct solve, with a
//! state-space model of the same inputs and outputs — the run and the [`Analysis`]
//! implementation; the case shape, its parser and its validation are in [`case`], the result
//! and report in [`result`], the files in [`files`].

use result::{rows, DirectCheck, FrfMode, FrfResult, OutputInfo, Pair, StateSpaceOut};
use crate::analysis::common::kind::{Analysis, Ctx, UsedMaterial};
use super::{AnalysisError, Report, RunError};
use crate::case::error::CaseError;
use crate::case::mesh::MeshSpec;
use crate::fem::frf::{modal_frf, relative_difference, Damping, DirectFrf, ModalFrf, Ports, C64};
use crate::fem::state_space::{state_space, StateSpace};
use crate::fem::Model;
use nalgebra::DMatrix;

pub mod case;
pub mod files;
pub mod result;

pub use case::{parse_frf, DampingSpec, FrequencySpec, FrfCase, InputSpec, OutputSpec, Spacing, ValidFrf};

/// Global axes of a frame given by rows (x_local = R x_global): v_global = Rᵀ v_local.
fn to_global(frame: Option<[[f64; 3]; 3]>, v: [f64; 3]) -> [f64; 3] {
    match frame {
        None => v,
        Some(r) => std::array::from_fn(|j| (0..3).map(|i| r[i][j] * v[i]).sum()),
    }
}

/// The ports of a case, the inputs' names and units (`N` for a force, `Nmm` for a moment,
/// `input` for both) and the outputs.
pub fn ports(case: &FrfCase, model: &Model) -> (Ports, Vec<(String, &'static str)>, Vec<OutputInfo>) {
    let n = model.n_dofs();
    let node_name = |name: &Option<String>, node: usize| name.clone().unwrap_or_else(|| format!("node {node}"));
    let mut inputs = Vec::new();
    let mut in_names = Vec::new();
    for (i, s) in case.inputs.iter().enumerate() {
        // Checked when the case was validated.
        let load = s.load(&format!("inputs[{i}]")).unwrap_or_default();
        let (force, moment) = ([load[0], load[1], load[2]], [load[3], load[4], load[5]]);
        let mut f = vec![0.0; n];
        f[6 * s.node..6 * s.node + 3].copy_from_slice(&to_global(s.frame, force));
        f[6 * s.node + 3..6 * s.node + 6].copy_from_slice(&to_global(s.frame, moment));
        inputs.push(f);
        let unit = match (force.iter().any(|v| *v != 0.0), moment.iter().any(|v| *v != 0.0)) {
            (true, false) => "N",
            (false, true) => "Nmm",
            _ => "input",
        };
        in_names.push((node_name(&s.name, s.node), unit));
    }
    let mut outputs = Vec::new();
    let mut out_info = Vec::new();
    for s in &case.outputs {
        for d in &s.dofs {
            let k = d.dof().index();
            let mut axis = [0.0; 3];
            axis[k % 3] = 1.0;
            let (off, scale, unit) = if k < 3 {
                (0, 1.0, "mm")
            } else {
                (3, 180.0 / std::f64::consts::PI, "deg")
            };
            let mut c = vec![0.0; n];
            for (j, v) in to_global(s.frame, axis).iter().enumerate() {
                c[6 * s.node + off + j] = v * scale;
            }
            outputs.push(c);
            out_info.push(OutputInfo {
                name: format!("{} {}", node_name(&s.name, s.node), d.dof().name()),
                unit,
            });
        }
    }
    (Ports { inputs, outputs }, in_names, out_info)
}

/// Refuses an input that loads only fixed DOFs or an output that reads only fixed DOFs (its
/// response would be a silent zero), naming the case path. The ports are those of [`ports`],
/// reduced onto the model's equations (supports, rigid links, node frames and ties applied).
fn check_ports(case: &FrfCase, model: &Model) -> Result<(), CaseError> {
    // A model whose constraints conflict is refused by the run with the solver's message.
    let Ok(map) = crate::fem::constraints::DofMap::new(model, &[], None) else {
        return Ok(());
    };
    let (ports, _, _) = ports(case, model);
    let dead = |v: &[f64]| map.reduce(v).iter().all(|x| *x == 0.0);
    for (i, (s, f)) in case.inputs.iter().zip(&ports.inputs).enumerate() {
        if dead(f) {
            return Err(CaseError::value(
                format!("inputs[{i}].node"),
                s.node,
                "the input's force and moment act only on DOFs the supports fix, so its response is zero: load a free DOF",
            ));
        }
    }
    let mut columns = ports.outputs.iter();
    for (i, s) in case.outputs.iter().enumerate() {
        for (j, (d, c)) in s.dofs.iter().zip(columns.by_ref()).enumerate() {
            if dead(c) {
                return Err(CaseError::value(
                    format!("outputs[{i}].dofs[{j}]"),
                    d.dof().name(),
                    format!("node {} does not move in this direction (the supports fix it), so its response is zero: give a free DOF", s.node),
                ));
            }
        }
    }
    Ok(())
}

/// Validates the case ([`FrfCase::validate`]) and its ports ([`check_ports`]).
fn validated(case: &FrfCase) -> Result<ValidFrf<'_>, CaseError> {
    let valid = case.validate()?;
    check_ports(case, &valid.model)?;
    Ok(valid)
}

fn fem_err(e: crate::fem::FemError) -> RunError {
    RunError::from(AnalysisError::new("model", e.to_string()))
}

/// The damping of a case as the solver takes it.
fn damping_of(case: &FrfCase) -> Damping {
    let d = case.damping;
    Damping {
        alpha: d.alpha,
        beta: d.beta,
        zeta: d.zeta,
    }
}

/// The state-space model of a validated `frf` case alone (modal solve only: no frequency
/// sweep, no direct check), as [`run`] returns it.
pub fn state_space_of(valid: &ValidFrf, cache: &mut crate::fem::SolverCache) -> Result<StateSpace, RunError> {
    let (ports, _, _) = ports(valid.case, &valid.model);
    let modal = modal_frf(&valid.model, &ports, valid.case.modes, cache).map_err(fem_err)?;
    Ok(state_space(&modal, &damping_of(valid.case)))
}

/// Runs a validated `frf` case.
pub fn run(valid: &ValidFrf, cache: &mut crate::fem::SolverCache) -> Result<(FrfResult, StateSpace), RunError> {
    let (case, model) = (valid.case, &valid.model);
    let (ports, in_names, out_info) = ports(case, model);
    let d = case.damping;
    let damping = damping_of(case);
    let modal: ModalFrf = modal_frf(model, &ports, case.modes, cache).map_err(fem_err)?;
    let freqs = case.frequencies.values();
    let h: Vec<DMatrix<C64>> = freqs.iter().map(|&f| modal.response(f, &damping)).collect();
    let f_top = modal.frequencies_hz().last().copied().unwrap_or(0.0);
    let direct = if case.direct && d.zeta == 0.0 {
        let solver = DirectFrf::new(model, &ports, damping).map_err(fem_err)?;
        let (mut worst, mut at, mut worst_2x) = (0.0f64, freqs[0], None::<f64>);
        for (&f, hm) in freqs.iter().zip(&h) {
            let e = relative_difference(hm, &solver.response(f).map_err(fem_err)?);
            if e > worst {
                (worst, at) = (e, f);
            }
            if f <= 2.0 * f_top {
                worst_2x = Some(worst_2x.map_or(e, |w| w.max(e)));
            }
        }
        Some(DirectCheck {
            max_relative_difference_to_2x_highest_mode: worst_2x,
            max_relative_difference: worst,
            at_hz: at,
        })
    } else {
        None
    };
    let ss = state_space(&modal, &damping);
    let dc = ss
        .dc_gain()
        .ok_or_else(|| RunError::from(AnalysisError::new("state_space", "A is singular")))?;
    let scale = modal.static_gain.amax();
    let dc_err = if scale > 0.0 {
        (&dc - &modal.static_gain).amax() / scale
    } else {
        0.0
    };
    let mut response = Vec::new();
    for (j, (input, in_unit)) in in_names.iter().enumerate() {
        for (k, out) in out_info.iter().enumerate() {
            response.push(Pair {
                input: input.clone(),
                output: out.name.clone(),
                unit: format!("{}_per_{in_unit}", out.unit),
                magnitude: h.iter().map(|m| m[(k, j)].norm()).collect(),
                phase_deg: h.iter().map(|m| m[(k, j)].arg().to_degrees()).collect(),
            });
        }
    }
    let mut notes = vec![
        format!(
            "modal superposition of {} modes with static correction (residual flexibility of the truncated modes) on {} equations",
            modal.omega.len(),
            modal.n_eq
        ),
        format!(
            "damping: Rayleigh α = {} 1/s, β = {} s, modal ratio ζ = {}",
            d.alpha, d.beta, d.zeta
        ),
    ];
    if case.direct && d.zeta != 0.0 {
        notes.push("no direct check: a constant modal damping ratio has no sparse damping matrix".into());
    }
    let result = FrfResult {
        inputs: in_names.into_iter().map(|(n, _)| n).collect(),
        outputs: out_info,
        modes: modal
            .frequencies_hz()
            .iter()
            .zip(&ss.zeta)
            .enumerate()
            .map(|(i, (&f, &z))| FrfMode {
                mode: i + 1,
                frequency_hz: f,
                damping_ratio: z,
            })
            .collect(),
        static_gain: rows(&modal.static_gain),
        frequencies_hz: freqs,
        response,
        direct,
        state_space: StateSpaceOut {
            states: ss.n_states(),
            a: rows(&ss.a),
            b: rows(&ss.b),
            c: rows(&ss.c),
            d: rows(&ss.d),
            poles: ss.poles().iter().map(|p| [p.re, p.im]).collect(),
            dc_gain_relative_error: dc_err,
        },
        model: notes,
    };
    Ok((result, ss))
}

/// `frf`: frequency response and state-space model of a mesh model.
pub struct FrfKind;

impl Analysis for FrfKind {
    type Case = FrfCase;
    type Result = FrfResult;

    fn check(case: &Self::Case) -> Result<(), CaseError> {
        validated(case).map(drop)
    }
    fn run(case: &Self::Case, ctx: &mut Ctx) -> Result<Self::Result, RunError> {
        let (mut r, ss) = run(&validated(case)?, ctx.cache)?;
        r.model.extend(case.model.promotion_note());
        ctx.warnings.extend(crate::analysis::common::warn::fewer_modes(case.modes, r.modes.len(), None));
        if ctx.with_files {
            ctx.files = files::files(&r, &ss)?;
        }
        Ok(r)
    }
    fn report(r: &Self::Result) -> Report {
        result::report(r)
    }
    fn materials(case: &Self::Case) -> Vec<UsedMaterial> {
        crate::analysis::common::kind::named_materials(&case.model.materials)
    }
    fn mesh_model(case: &Self::Case) -> Option<&MeshSpec> {
        Some(&case.model)
    }
}
