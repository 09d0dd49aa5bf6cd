//! The files of an `frf` run: `frf.csv`, the Bode plots (`bode_magnitude.svg`,
//! `bode_phase.svg`), the state-space model as `state_space.json` and in Matrix Market
//! (`A.mtx`, `B.mtx`, `C.mtx`, `D.mtx`, by `sprs::io`).

use super::result::FrfResult;
use crate::analysis::{AnalysisError, Files, RunError};
use crate::fem::state_space::StateSpace;
use crate::report::axis::Scale;
use crate::report::svg;

/// The files of a run.
pub fn files(r: &FrfResult, ss: &StateSpace) -> Result<Files, RunError> {
    let mut out: Files = vec![("frf.csv".to_string(), super::result::csv(r).into_bytes())];
    // Pairs whose response is roundoff (e.g. zero by symmetry: peak below 1e-9 of the largest)
    // are left out of the plots, which would otherwise span fifteen decades of noise.
    let peak = |p: &super::result::Pair| p.magnitude.iter().fold(0.0f64, |a, &b| a.max(b));
    let top = r.response.iter().map(peak).fold(0.0f64, f64::max);
    let shown: Vec<&super::result::Pair> = r.response.iter().filter(|p| peak(p) > 1e-9 * top).collect();
    let names: Vec<String> = shown.iter().map(|p| format!("{} → {}", p.input, p.output)).collect();
    let f = &r.frequencies_hz;
    let mag: Vec<Vec<(f64, f64)>> = shown
        .iter()
        .map(|p| f.iter().copied().zip(p.magnitude.iter().copied()).collect())
        .collect();
    let phase: Vec<Vec<(f64, f64)>> = shown
        .iter()
        .map(|p| f.iter().copied().zip(p.phase_deg.iter().copied()).collect())
        .collect();
    let series = |v: &[Vec<(f64, f64)>]| -> Vec<(String, Vec<(f64, f64)>)> {
        names.iter().cloned().zip(v.iter().cloned()).collect()
    };
    // Bode plots: frequency on a log axis in Hz, magnitude on a log axis, phase in 90° steps.
    for (file, title, ylabel, data, y_scale) in [
        (
            "bode_magnitude.svg",
            "Frequency response: magnitude",
            "|H| (mm or ° per N or N·mm)",
            series(&mag),
            Scale::Log,
        ),
        (
            "bode_phase.svg",
            "Frequency response: phase",
            "phase (°)",
            series(&phase),
            Scale::Degrees,
        ),
    ] {
        let refs: Vec<(&str, &[(f64, f64)])> = data.iter().map(|(n, p)| (n.as_str(), p.as_slice())).collect();
        out.push((
            file.to_string(),
            svg::lines_scaled(title, "frequency (Hz)", ylabel, &refs, (Scale::Log, y_scale)).into_bytes(),
        ));
    }
    let json = serde_json::json!({
        "description": "continuous-time state-space model x' = A x + B u, y = C x + D u; states: modal coordinates then their rates (mass-normalised modes); time in s; inputs in N (N·mm for moments); outputs in mm and degrees",
        "inputs": r.inputs,
        "outputs": r.outputs,
        "modes": r.modes,
        "a": r.state_space.a,
        "b": r.state_space.b,
        "c": r.state_space.c,
        "d": r.state_space.d,
    });
    let text = serde_json::to_string_pretty(&json).map_err(|e| AnalysisError::new("state_space", e.to_string()))?;
    out.push(("state_space.json".to_string(), text.into_bytes()));
    for (name, m) in ss.sparse() {
        let mut bytes = Vec::new();
        sprs::io::write_matrix_market_to_bufwrite(&mut bytes, &m)
            .map_err(|e| AnalysisError::new("state_space", e.to_string()))?;
        out.push((format!("{name}.mtx"), bytes));
    }
    Ok(out)
}
