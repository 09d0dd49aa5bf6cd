//! The `modal` analysis on a generic beam/shell model: lowest natural frequencies, mass-normalised
//! mode shapes, effective mass fractions; VTK file with the mode shapes.

mod coarse;
pub use coarse::{
    coarse_shell_warnings, shell_dispersion_estimates, square_mesh_frequency_ratio, worst_square_mesh_error,
    COARSE_SHELL_ERROR,
};

use super::{AnalysisError, Report};
use crate::fem::modal::{ModalOptions, ModalResults};
use crate::fem::Model;
use crate::report::markdown::Table;
use serde::Serialize;

/// Effective mass fractions per global direction.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Directions {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub rx: f64,
    pub ry: f64,
    pub rz: f64,
}

impl From<[f64; 6]> for Directions {
    fn from(v: [f64; 6]) -> Self {
        Directions {
            x: v[0],
            y: v[1],
            z: v[2],
            rx: v[3],
            ry: v[4],
            rz: v[5],
        }
    }
}

/// One mode of the result (`frequency_hz`, `shape`).
#[derive(Debug, Clone, Serialize)]
pub struct ModeRow {
    /// 1-based mode number.
    pub mode: usize,
    /// Natural frequency, Hz.
    pub frequency_hz: f64,
    /// ω², (rad/s)².
    pub eigenvalue: f64,
    /// A rigid-body mode: its strain energy ω² (≈ 0, possibly slightly negative from roundoff)
    /// is within roundoff of zero (see [`mark_rigid_body`]); its frequency is reported as 0.
    pub rigid_body: bool,
    /// Mass-normalised shape per node [ux, uy, uz (mm), rx, ry, rz (degrees)], global axes
    /// (scaled so that φᵀMφ = 1 with the rotations in radians and M in tonne, mm). Omitted with
    /// `"shapes": false` (the shapes are in `modes.vtu`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shape: Option<Vec<[f64; 6]>>,
    /// Effective mass fraction Γ²/(rᵀMr) per direction (rotations about global axes through the
    /// origin; relative to the mass on free DOFs).
    pub effective_mass_fraction: Directions,
}

/// Result of the `modal` analysis.
#[derive(Debug, Clone, Serialize)]
pub struct ModalResult {
    /// Modes by increasing frequency.
    pub modes: Vec<ModeRow>,
    /// Sum of the effective mass fractions of the modes found, per direction.
    pub cumulative_effective_mass_fraction: Directions,
    /// Mass on free DOFs (tonne) and rotary inertia about the global axes (tonne·mm²).
    pub total_mass: Directions,
    /// Model notes (method, shift, steps).
    pub model: Vec<String>,
}

/// Solves the modal problem.
pub fn solve(model: &Model, modes: usize, shift_hz: Option<f64>) -> Result<(ModalResult, ModalResults), AnalysisError> {
    solve_with(model, modes, shift_hz, &mut crate::fem::SolverCache::new())
}

/// [`solve`] reusing the pattern and symbolic factorisation of the worker's solver cache where
/// the topology matches.
pub fn solve_with(
    model: &Model,
    modes: usize,
    shift_hz: Option<f64>,
    cache: &mut crate::fem::SolverCache,
) -> Result<(ModalResult, ModalResults), AnalysisError> {
    let mut opts = ModalOptions::new(modes);
    opts.shift = shift_hz.map(|f| (2.0 * std::f64::consts::PI * f).powi(2));
    let r = crate::fem::modal::solve_modal_cached(model, &opts, cache)
        .map_err(|e| AnalysisError::new("model", e.to_string()))?;
    let mut cum = [0.0; 6];
    let rows = r
        .modes
        .iter()
        .enumerate()
        .map(|(i, m)| {
            for (c, v) in cum.iter_mut().zip(m.effective_mass_fraction) {
                *c += v;
            }
            ModeRow {
                mode: i + 1,
                frequency_hz: m.frequency_hz,
                eigenvalue: m.eigenvalue,
                rigid_body: false,
                shape: Some(m.shape.iter().map(crate::report::numbers::mm_deg).collect()),
                effective_mass_fraction: m.effective_mass_fraction.into(),
            }
        })
        .collect();
    let (shell4, shell9) = model.shell_kinds();
    // The four-node shells' part stands in every model but one of nine-node shells alone.
    let four_node = if shell4 || !shell9 {
        "four-node shells lumped (row sums of the bilinear ρt and ρt³/12 mass, plus the rotary inertia of each node's tributary tile), "
    } else {
        ""
    };
    let mut notes = vec![
        format!("mass: beams consistent (Hermite, with rotary inertia), {four_node}point masses"),
        format!(
            "block shift-invert Lanczos on {} equations, shift {:.4e} (rad/s)², {} solves",
            r.n_eq, r.shift, r.lanczos_steps
        ),
    ];
    if shell9 {
        notes.push(
            "mass: 9-node shells (shell9) consistent (biquadratic ρt and ρt³/12 mass, none on the drilling rotation)"
                .to_string(),
        );
    }
    notes.extend(crate::fem::superelement::notes(model));
    Ok((
        ModalResult {
            modes: rows,
            cumulative_effective_mass_fraction: cum.into(),
            total_mass: r.total_mass.into(),
            model: notes,
        },
        r,
    ))
}

/// Roundoff factor of [`mark_rigid_body`]: a mode is rigid when ω² ≤ RIGID_MODE_TOL · S.
/// Measured: rigid-body modes of free shell plates (2 to 6400 elements) give |ω²|/S ≤ 1.3e-16;
/// a genuine 0.0007 Hz mode (a 0.01 mm steel leaf carrying a 100×100×200 mm steel block)
/// gives 1.7e-14, a 1 kHz plate mode 1e-7.
pub const RIGID_MODE_TOL: f64 = 3e-15;

/// Strain energy φₑᵀKₑφₑ of one element (at most 9 nodes) in `shape` (global rows, mm and rad)
/// and its round-off scale |φₑ|ᵀ|Kₑ||φₑ| (|·| entrywise).
fn element_energy(k: impl Fn(usize, usize) -> f64, nodes: &[usize], shape: &[[f64; 6]]) -> (f64, f64) {
    let mut v = [0.0; 54];
    for (i, &n) in nodes.iter().enumerate() {
        v[6 * i..6 * i + 6].copy_from_slice(&shape[n]);
    }
    let len = 6 * nodes.len();
    let (mut e, mut s) = (0.0, 0.0);
    for a in 0..len {
        for b in 0..len {
            let t = k(a, b) * v[a] * v[b];
            e += t;
            s += t.abs();
        }
    }
    (e, s)
}

/// Strain energy φᵀKφ of every mode of `raw` summed element by element and its round-off scale
/// S = Σₑ |φₑ|ᵀ|Kₑ||φₑ|, in one pass over the elements (each element matrix built once for all
/// modes); `each(element, mode, energy)` sees every element's share on the way.
pub fn mode_energies_with(
    model: &Model,
    raw: &ModalResults,
    mut each: impl FnMut(usize, usize, f64),
) -> Vec<(f64, f64)> {
    let mut out = vec![(0.0, 0.0); raw.modes.len()];
    // Generic over the matrix (inlined entry access: this loop is most of a shell model's
    // post-processing).
    fn add<K: Fn(usize, usize) -> f64>(
        raw: &ModalResults,
        out: &mut [(f64, f64)],
        each: &mut impl FnMut(usize, usize, f64),
        ie: usize,
        k: K,
        nodes: &[usize],
    ) {
        for (mode, (m, (e, s))) in raw.modes.iter().zip(out.iter_mut()).enumerate() {
            let (de, ds) = element_energy(&k, nodes, &m.shape);
            *e += de;
            *s += ds;
            each(ie, mode, de);
        }
    }
    for (ie, el) in model.elements.iter().enumerate() {
        if let crate::fem::Element::Shell4(_) = el {
            if let Ok(em) = model.shell_matrix(ie) {
                add(raw, &mut out, &mut each, ie, |a, b| em.k[(a, b)], &em.nodes);
            }
        } else if let crate::fem::Element::Shell9(_) = el {
            if let Ok(em) = model.shell9_matrix(ie) {
                add(raw, &mut out, &mut each, ie, |a, b| em.k[(a, b)], &em.nodes);
            }
        } else if let Ok(em) = model.element_matrix(ie) {
            add(
                raw,
                &mut out,
                &mut each,
                ie,
                |a, b| em.k[(a, b)],
                &em.nodes[..em.n_nodes],
            );
        }
    }
    out
}

/// [`mode_energies_with`] without the per-element shares.
pub fn mode_energies(model: &Model, raw: &ModalResults) -> Vec<(f64, f64)> {
    mode_energies_with(model, raw, |_, _, _| {})
}

/// Share of a mode's strain energy on the shells' drilling penalty above which the mode is
/// reported as drilling-dominated.
pub const DRILLING_SHARE: f64 = 0.5;

/// Warnings for modes whose strain energy rests mostly on the shells' drilling penalty
/// ([`crate::fem::shell::shell_drilling_stiffness`]): the drilling rotation is not a degree of
/// freedom of shell theory, so such a mode is either spurious or held only by an artificial
/// stiffness (e.g. a rotary inertia or a beam turning a shell node about the shell normal).
/// Rigid-body modes are skipped.
pub fn drilling_warnings(model: &Model, raw: &ModalResults) -> Vec<String> {
    use crate::fem::{shell::shell_drilling_stiffness, shell9::shell9_drilling_stiffness, Element};
    // Each shell's drilling stiffness on its nodes (four-node shells, the bulk, inline).
    #[allow(clippy::large_enum_variant)]
    enum Drilling {
        Four(crate::fem::shell::Mat24, [usize; 4]),
        Nine(nalgebra::DMatrix<f64>, [usize; 9]),
    }
    let shells: Vec<Drilling> = model
        .elements
        .iter()
        .filter_map(|e| match e {
            Element::Shell4(s) => {
                let x = s.nodes.map(|n| model.nodes[n]);
                shell_drilling_stiffness(&x, s.t, &s.material).map(|k| Drilling::Four(k, s.nodes))
            }
            Element::Shell9(s) => {
                let x = s.nodes.map(|n| model.nodes[n]);
                shell9_drilling_stiffness(&x, s.t, &s.material).map(|k| Drilling::Nine(k, s.nodes))
            }
            _ => None,
        })
        .collect();
    if shells.is_empty() {
        return Vec::new();
    }
    let mut out = Vec::new();
    let energies = mode_energies(model, raw);
    for (k, (m, &(total, scale))) in raw.modes.iter().zip(&energies).enumerate() {
        if total <= RIGID_MODE_TOL * scale {
            continue;
        }
        let drill: f64 = shells
            .iter()
            .map(|d| match d {
                Drilling::Four(k, nodes) => element_energy(|a, b| k[(a, b)], nodes, &m.shape).0,
                Drilling::Nine(k, nodes) => element_energy(|a, b| k[(a, b)], nodes, &m.shape).0,
            })
            .sum();
        let share = drill / total;
        if share > DRILLING_SHARE {
            out.push(format!(
                "mode {} ({:.4} Hz): {:.0} % of its strain energy rests on the shells' drilling rotation, an artificial stiffness that shell theory does not have; the mode is spurious, or is held only by the in-plane rotation of a shell (e.g. a rotary inertia or a beam turning a shell node about the shell normal)",
                k + 1,
                m.frequency_hz,
                share * 100.0
            ));
        }
    }
    out
}

/// Flags rigid-body modes: ω² ≤ [`RIGID_MODE_TOL`] · S, with S the roundoff scale of the mode's
/// strain energy ([`mode_energies`]). Roundoff in φᵀKφ is a few ε·S (ε ≈ 2.2e-16), so a rigid
/// motion computes to |ω²| of that order and possibly negative; a deforming mode has
/// ω² = φᵀKφ far above it. Rigid-body modes get frequency 0 and a note.
pub fn mark_rigid_body(model: &Model, raw: &ModalResults, r: &mut ModalResult) {
    let mut n = 0;
    let energies = mode_energies(model, raw);
    for ((row, m), &(_, s)) in r.modes.iter_mut().zip(&raw.modes).zip(&energies) {
        if m.eigenvalue <= RIGID_MODE_TOL * s {
            row.rigid_body = true;
            row.frequency_hz = 0.0;
            n += 1;
        }
    }
    if n > 0 {
        r.model.push(format!(
            "{n} rigid-body mode(s) (ω² zero within roundoff of the mode's strain energy, possibly slightly negative): frequency reported as 0, `rigid_body`: true"
        ));
    }
}

/// `modes.vtu`: the undeformed mesh with the translations (`mode_K_translation_mm`) and
/// rotations (`mode_K_rotation_deg`) of each mass-normalised mode shape and the frequencies
/// (field data `frequency_hz`); see [`super::vtu`].
pub fn vtu(model: &Model, r: &ModalResults) -> Result<Vec<u8>, AnalysisError> {
    let modes: Vec<(f64, &[[f64; 6]])> = r.modes.iter().map(|m| (m.frequency_hz, m.shape.as_slice())).collect();
    crate::analysis::common::vtu::modes_vtu(model, &modes, &Default::default())
}

/// Markdown/CSV views.
pub fn report(r: &ModalResult) -> Report {
    let mut md = String::from("# Modal analysis\n\n");
    // Effective mass fractions are dimensionless (fractions of the mass on free DOFs).
    let mut csv = String::from("mode,frequency_hz,mef_x,mef_y,mef_z,mef_rx,mef_ry,mef_rz\n");
    let mut t = Table::new(&["mode", "f (Hz)", "x", "y", "z", "rx", "ry", "rz"]);
    for m in &r.modes {
        let e = m.effective_mass_fraction;
        t.row(vec![
            m.mode.to_string(),
            if m.rigid_body {
                "0 (rigid body)".to_string()
            } else {
                format!("{:.4}", m.frequency_hz)
            },
            format!("{:.4}", e.x),
            format!("{:.4}", e.y),
            format!("{:.4}", e.z),
            format!("{:.4}", e.rx),
            format!("{:.4}", e.ry),
            format!("{:.4}", e.rz),
        ]);
        csv += &format!(
            "{},{},{},{},{},{},{},{}\n",
            m.mode, m.frequency_hz, e.x, e.y, e.z, e.rx, e.ry, e.rz
        );
    }
    md += "Frequencies and effective mass fractions per direction:\n\n";
    md += &t.render();
    md += "\n";
    for n in &r.model {
        md += &format!("- {n}\n");
    }
    Report { markdown: md, csv }
}

/// `model.svg` of a modal run: the first mode shape (its amplitude scaled to about 8 % of the
/// model's size) over the undeformed ghost, hinges drawn as grey notch symbols (a mode has no
/// stress level); nothing when no mode was found.
pub fn picture(model: &Model, r: &ModalResults, hinges: &[crate::case::mesh::BuiltHinge]) -> Option<(String, Vec<u8>)> {
    use crate::analysis::common::picture::{self, HingeMark, Scene};
    let m = r.modes.first()?;
    let marks = hinges
        .iter()
        .filter_map(|b| {
            Some(HingeMark {
                label: format!("element {}", b.case_element),
                nodes: b.end_nodes(model)?,
                utilisation: None,
            })
        })
        .collect();
    let scene = Scene {
        model,
        displacements: Some(&m.shape),
        marks,
        drawn: &Default::default(),
        load_case: None,
        title: "flexfem modal: the first mode".to_string(),
        name: "mode 1".to_string(),
        what: format!("mode 1, {} Hz", crate::report::markdown::sig(m.frequency_hz, 5)),
        mode: true,
    };
    let text = picture::render(&scene, &Default::default());
    Some(("model.svg".to_string(), text.into_bytes()))
}
