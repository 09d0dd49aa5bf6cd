//! The result of the `frf` analysis ([`super`]) and its report: frequency response of a mesh model from nodal loads (inputs) to nodal
//! DOFs (outputs) by modal superposition with static correction ([`crate::fem::frf`]), checked
//! by the direct solve of (K − ω²M + iωC), and the state-space model of the same inputs and
//! outputs ([`crate::fem::state_space`]). Files: `frf.csv`, `bode_magnitude.svg`,
//! `bode_phase.svg`, `state_space.json` and `A.mtx`, `B.mtx`, `C.mtx`, `D.mtx`.
//!
//! Units: inputs in N (N·mm for moments); outputs in mm and degrees, so H is in mm/N, °/N,
//! mm/(N·mm) or °/(N·mm); the state-space model's time unit is the second.

use crate::analysis::Report;
use crate::report::markdown::Table;
use nalgebra::DMatrix;
use serde::Serialize;

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
    /// Unit of |H|: `mm_per_N`, `deg_per_N`, `mm_per_Nmm`, `deg_per_Nmm` (or `…_per_input`
    /// for an input of both force and moment).
    pub unit: String,
    /// |H| at each frequency.
    pub magnitude: Vec<f64>,
    /// arg H at each frequency, degrees in (−180, 180].
    pub phase_deg: Vec<f64>,
}

/// The direct solve's check of the modal result.
#[derive(Debug, Clone, Serialize)]
pub struct DirectCheck {
    /// Largest ‖H_modal − H_direct‖ / ‖H_direct‖ (Frobenius over all pairs) at the
    /// frequencies up to twice the highest retained mode (`null` if there are none); at a
    /// frequency where H_direct = 0 (outputs decoupled from the inputs) 0 if H_modal = 0 too,
    /// else 1.
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

/// The rows of a matrix.
pub fn rows(m: &DMatrix<f64>) -> Vec<Vec<f64>> {
    (0..m.nrows()).map(|i| m.row(i).iter().copied().collect()).collect()
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

/// `frf.csv`: frequency, then magnitude and phase (degrees) of every (input, output) pair, in
/// columns `magnitude INPUT to OUTPUT_UNIT` and `phase INPUT to OUTPUT_deg`.
pub fn csv(r: &FrfResult) -> String {
    let mut s = String::from("frequency_hz");
    for p in &r.response {
        let tag = format!("{} to {}", p.input, p.output).replace(',', ";");
        s += &format!(",magnitude {tag}_{},phase {tag}_deg", p.unit);
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
