//! The `frf` analysis: frequency response of a mesh model from nodal loads (inputs) to nodal
//! DOFs (outputs) by modal superposition with static correction ([`crate::fem::frf`]), checked
//! by the direct solve of (K − ω²M + iωC), and the state-space model of the same inputs and
//! outputs ([`crate::fem::state_space`]). Files: `frf.csv`, `bode_magnitude.svg`,
//! `bode_phase.svg`, `state_space.json` and `A.mtx`, `B.mtx`, `C.mtx`, `D.mtx`.
//!
//! Units: inputs in N (N·mm for moments); outputs in mm and degrees, so H is in mm/N, °/N,
//! mm/(N·mm) or °/(N·mm); the state-space model's time unit is the second.

use super::kind::{Analysis, Ctx, UsedMaterial};
use super::{AnalysisError, Report, RunError};
use crate::case::frf::FrfCase;
use crate::case::CaseError;
use crate::fem::frf::{modal_frf, relative_difference, Damping, DirectFrf, ModalFrf, Ports, C64};
use crate::fem::state_space::{state_space, StateSpace};
use crate::fem::Model;
use crate::report::markdown::Table;
use nalgebra::DMatrix;
use serde::Serialize;

/// `frf`: frequency response and state-space model of a mesh model.
pub struct FrfKind;

/// One output of the result.
#[derive(Debug, Clone, Serialize)]
pub struct OutputInfo {
    /// Name (`"NAME DOF"`).
    pub name: String,
    /// Unit of the output (`mm` or `deg`).
    pub unit: &'static str,
}

/// One retained mode.
#[derive(Debug, Clone, Serialize)]
pub struct FrfMode {
    /// 1-based mode number.
    pub mode: usize,
    /// Natural frequency, Hz.
    pub frequency_hz: f64,
    /// Damping ratio ζ + α/(2ω) + βω/2.
    pub damping_ratio: f64,
}

/// The response of one output to one input.
#[derive(Debug, Clone, Serialize)]
pub struct Pair {
    /// Input name.
    pub input: String,
    /// Output name.
    pub output: String,
    /// |H| at each frequency (output unit per N or per N·mm).
    pub magnitude: Vec<f64>,
    /// arg H at each frequency, degrees in (−180, 180].
    pub phase_deg: Vec<f64>,
}

/// The direct solve's check of the modal result.
#[derive(Debug, Clone, Serialize)]
pub struct DirectCheck {
    /// Largest ‖H_modal − H_direct‖ / ‖H_direct‖ (Frobenius over all pairs) at the
    /// frequencies up to twice the highest retained mode (`null` if there are none).
    pub max_relative_difference_to_2x_highest_mode: Option<f64>,
    /// The same over all frequencies.
    pub max_relative_difference: f64,
    /// Where the largest difference is, Hz.
    pub at_hz: f64,
}

/// The state-space model (x = [η; η̇], modal coordinates and rates; t in s).
#[derive(Debug, Clone, Serialize)]
pub struct StateSpaceOut {
    /// Number of states (twice the retained modes).
    pub states: usize,
    /// A (states × states), rows.
    pub a: Vec<Vec<f64>>,
    /// B (states × inputs).
    pub b: Vec<Vec<f64>>,
    /// C (outputs × states).
    pub c: Vec<Vec<f64>>,
    /// D (outputs × inputs): the static correction.
    pub d: Vec<Vec<f64>>,
    /// Poles (eigenvalues of A) as [re, im], 1/s.
    pub poles: Vec<[f64; 2]>,
    /// max |(D − C A⁻¹ B) − static gain| / max |static gain|.
    pub dc_gain_relative_error: f64,
}

/// Result of the `frf` analysis.
#[derive(Debug, Clone, Serialize)]
pub struct FrfResult {
    /// Input names.
    pub inputs: Vec<String>,
    /// Outputs.
    pub outputs: Vec<OutputInfo>,
    /// Retained modes.
    pub modes: Vec<FrfMode>,
    /// Static gain (compliance) K⁻¹ per output (rows) and input (columns).
    pub static_gain: Vec<Vec<f64>>,
    /// Frequencies, Hz.
    pub frequencies_hz: Vec<f64>,
    /// Modal-superposition response per (input, output) pair.
    pub response: Vec<Pair>,
    /// Direct-solve check (`null` with a modal damping ratio or `"direct": false`).
    pub direct: Option<DirectCheck>,
    /// State-space model.
    pub state_space: StateSpaceOut,
    /// Model notes.
    pub model: Vec<String>,
}

fn rows(m: &DMatrix<f64>) -> Vec<Vec<f64>> {
    (0..m.nrows()).map(|i| m.row(i).iter().copied().collect()).collect()
}

/// Global axes of a frame given by rows (x_local = R x_global): v_global = Rᵀ v_local.
fn to_global(frame: Option<[[f64; 3]; 3]>, v: [f64; 3]) -> [f64; 3] {
    match frame {
        None => v,
        Some(r) => std::array::from_fn(|j| (0..3).map(|i| r[i][j] * v[i]).sum()),
    }
}

/// The ports of a case, their names and the output units.
pub fn ports(case: &FrfCase, model: &Model) -> (Ports, Vec<String>, Vec<OutputInfo>) {
    let n = model.n_dofs();
    let node_name = |name: &Option<String>, node: usize| name.clone().unwrap_or_else(|| format!("node {node}"));
    let mut inputs = Vec::new();
    let mut in_names = Vec::new();
    for s in &case.inputs {
        let mut f = vec![0.0; n];
        f[6 * s.node..6 * s.node + 3].copy_from_slice(&to_global(s.frame, s.force));
        f[6 * s.node + 3..6 * s.node + 6].copy_from_slice(&to_global(s.frame, s.moment));
        inputs.push(f);
        in_names.push(node_name(&s.name, s.node));
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

fn fem_err(e: crate::fem::FemError) -> RunError {
    RunError::from(AnalysisError::new("model", e.to_string()))
}

/// Runs an `frf` case.
pub fn run(case: &FrfCase, model: &Model, cache: &mut crate::fem::SolverCache) -> Result<(FrfResult, StateSpace), RunError> {
    let (ports, in_names, out_info) = ports(case, model);
    let d = case.damping;
    let damping = Damping {
        alpha: d.alpha,
        beta: d.beta,
        zeta: d.zeta,
    };
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
    for (j, input) in in_names.iter().enumerate() {
        for (k, out) in out_info.iter().enumerate() {
            response.push(Pair {
                input: input.clone(),
                output: out.name.clone(),
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
        inputs: in_names,
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

impl Analysis for FrfKind {
    const KIND: &'static str = "frf";
    type Case = FrfCase;
    type Result = FrfResult;

    fn check(case: &Self::Case) -> Result<(), CaseError> {
        case.check_options()?;
        case.model.build_model(false).map(|_| ())
    }
    fn run(case: &Self::Case, ctx: &mut Ctx) -> Result<Self::Result, RunError> {
        case.check_options()?;
        let model = case.model.build_model(false)?;
        let (r, ss) = run(case, &model, ctx.cache)?;
        if ctx.with_files {
            ctx.files = super::frf_files::files(&r, &ss)?;
        }
        Ok(r)
    }
    fn report(r: &Self::Result) -> Report {
        report(r)
    }
    fn case_warnings(case: &Self::Case) -> Vec<String> {
        super::warn::density_warnings(&case.model)
    }
    fn materials(case: &Self::Case) -> Vec<UsedMaterial> {
        case.model
            .materials
            .iter()
            .filter_map(|(k, spec)| spec.resolve(k).ok().map(|m| (k.clone(), spec.clone(), m)))
            .collect()
    }
}

/// Markdown and CSV views: modes, static gain, direct check; the CSV is the response table.
pub fn report(r: &FrfResult) -> Report {
    let mut md = String::from("# Frequency response\n\n");
    let mut t = Table::new(&["mode", "f (Hz)", "ζ"]);
    for m in &r.modes {
        t.row(vec![
            m.mode.to_string(),
            format!("{:.4}", m.frequency_hz),
            format!("{:.4e}", m.damping_ratio),
        ]);
    }
    md += "Retained modes:\n\n";
    md += &t.render();
    md += "\nStatic gain (output per unit input):\n\n";
    let mut head = vec!["output".to_string()];
    head.extend(r.inputs.iter().cloned());
    let head_ref: Vec<&str> = head.iter().map(String::as_str).collect();
    let mut g = Table::new(&head_ref);
    for (o, row) in r.outputs.iter().zip(&r.static_gain) {
        let mut cells = vec![format!("{} ({})", o.name, o.unit)];
        cells.extend(row.iter().map(|v| format!("{v:.6e}")));
        g.row(cells);
    }
    md += &g.render();
    if let Some(d) = &r.direct {
        md += &format!(
            "\nDirect solve check: largest relative difference {:.3e} (at {:.4} Hz); up to twice the highest retained mode {}\n",
            d.max_relative_difference,
            d.at_hz,
            d.max_relative_difference_to_2x_highest_mode
                .map_or("—".to_string(), |v| format!("{v:.3e}"))
        );
    }
    md += &format!(
        "\nState-space model: {} states; DC gain equals the static gain to {:.2e} (relative).\n\n",
        r.state_space.states, r.state_space.dc_gain_relative_error
    );
    for n in &r.model {
        md += &format!("- {n}\n");
    }
    Report {
        markdown: md,
        csv: csv(r),
    }
}

/// `frf.csv`: frequency, then magnitude and phase (degrees) of every (input, output) pair.
pub fn csv(r: &FrfResult) -> String {
    let mut s = String::from("frequency_hz");
    for p in &r.response {
        let tag = format!("{} -> {}", p.input, p.output).replace(',', ";");
        s += &format!(",|H| {tag},phase_deg {tag}");
    }
    s.push('\n');
    for (i, f) in r.frequencies_hz.iter().enumerate() {
        s += &f.to_string();
        for p in &r.response {
            s += &format!(",{},{}", p.magnitude[i], p.phase_deg[i]);
        }
        s.push('\n');
    }
    s
}
