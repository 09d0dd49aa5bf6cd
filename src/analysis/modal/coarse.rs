//! Warnings for modes that bend shells meshed too coarsely to trust their frequency.
//!
//! Nine-node shells ([`crate::fem::shell9`]) are judged the same way with their own Bloch ratio,
//! computed from the element's matrices on a unit square
//! ([`crate::fem::shell9::square_mesh_frequency_ratio9`]): they read high, most along a mesh
//! line, by O((qh)⁴) (h the element's side, two node spacings).
//!
//! The four-node shell (MITC4 with the lumped mass and the tiles' rotary inertia, see
//! [`crate::fem::shell`]) carries a plane bending wave w = W·exp(i(ax + by)/h) on a mesh of
//! squares of side h with a frequency error that follows in closed form from a Bloch analysis
//! of the thin limit ([`square_mesh_frequency_ratio`]): ω_h/ω − 1 = −(qh)²/8·(13 + ν)/24·sin²2φ +
//! O((qh)⁴), φ the angle between the wave and the mesh lines — almost exact along a mesh line,
//! too low along a diagonal. A simply supported rectangular plate on a uniform mesh has exactly
//! these waves as modes, so its errors are the closed form (plus the plate's own shear
//! flexibility): tests/shell_coarse_mesh.rs.
//!
//! For each mode the bending wavenumber q of each shell follows from the mode's frequency and the
//! plate's flexural dispersion, q⁴ = ρtω²/D = 12(1 − ν²)ρω²/(Et²) (a curved shell whose membrane
//! stiffness raises ω gets a larger q, so the estimate errs on the safe side); h is the element's
//! longest edge; the element's estimate is the closed-form error in the worse of the two
//! directions (along a mesh line, along a diagonal; [`worst_square_mesh_error`], which also
//! corrects q for the computed ω reading low), averaged over the shells with the mode's strain
//! energy as weight. It is an estimate of the discretisation error, not a bound: a mode's error
//! also holds what the shell model has and a reference may not (the simply supported plate's
//! diagonal mode (2,2) at 10×10: estimate 5.39 %, measured −5.57 % against Navier's thin
//! plate, the rest being the Reissner–Mindlin shear flexibility). Meshes of other shapes (skewed, distorted elements) are judged as if
//! they were squares of their longest edge: on the clamped 45° rhombic plate meshed 8×8 and
//! 12×12 every mode's measured error is below its estimate.

use super::{mode_energies_with, RIGID_MODE_TOL};
use crate::fem::modal::ModalResults;
use crate::fem::{Element, Model};

/// Estimated frequency error above which a mode is reported (fraction).
pub const COARSE_SHELL_ERROR: f64 = 0.02;

/// Share of a mode's strain energy in the shells below which the shells are not judged.
const SHELL_SHARE: f64 = 0.1;

/// ω_h/ω of a thin-plate bending wave with phase steps (a, b) = (q_x h, q_y h) per element on a
/// mesh of squares of the four-node shell (thin limit: each edge's mean rotation equals its
/// chord slope, so the rotation amplitudes are 2 tan(a/2)/h and 2 tan(b/2)/h times w; bilinear
/// rotations with 2×2 Gauss bending energy; lumped mass with the tiles' rotary inertia h²/12):
///
/// ω_h²/ω² = [4Tₐ²SₐC_b + 4T_b²S_bCₐ + 2νX + ½(1 − ν)(4Tₐ²S_bCₐ + 4T_b²SₐC_b + 2X)] /
/// ((a² + b²)²·(1 + (Tₐ² + T_b²)/3)), with Tₐ = tan(a/2), Sₐ = 4 sin²(a/2), Cₐ = (2 + cos a)/3,
/// X = 4TₐT_b sin a sin b.
pub fn square_mesh_frequency_ratio(a: f64, b: f64, nu: f64) -> f64 {
    let (ta, tb) = ((a / 2.0).tan(), (b / 2.0).tan());
    let (sa, sb) = (4.0 * (a / 2.0).sin().powi(2), 4.0 * (b / 2.0).sin().powi(2));
    let (ca, cb) = ((2.0 + a.cos()) / 3.0, (2.0 + b.cos()) / 3.0);
    let x = 4.0 * ta * tb * a.sin() * b.sin();
    let energy = 4.0 * ta * ta * sa * cb
        + 4.0 * tb * tb * sb * ca
        + 2.0 * nu * x
        + 0.5 * (1.0 - nu) * (4.0 * ta * ta * sb * ca + 4.0 * tb * tb * sa * cb + 2.0 * x);
    let q2 = a * a + b * b;
    (energy / (q2 * q2 * (1.0 + (ta * ta + tb * tb) / 3.0))).sqrt()
}

/// Worse |ω_h/ω − 1| of a wave along a mesh line and along a diagonal, for `qh_h`, the qh that
/// the computed frequency ω_h gives. The wave's true qh is larger where ω_h reads low
/// (q ∝ √ω): qh = qh_h/√(1 − e), solved for by fixed-point iteration (contracting: e < 0.4).
pub fn worst_square_mesh_error(qh_h: f64, nu: f64) -> f64 {
    let worst = |qh: f64| {
        let d = qh / std::f64::consts::SQRT_2;
        (square_mesh_frequency_ratio(qh, 0.0, nu) - 1.0)
            .abs()
            .max((square_mesh_frequency_ratio(d, d, nu) - 1.0).abs())
    };
    let mut e = worst(qh_h);
    for _ in 0..30 {
        let next = worst(qh_h / (1.0 - e.min(0.5)).sqrt());
        if (next - e).abs() <= 1e-12 {
            return next;
        }
        e = next;
    }
    e
}

/// The nine-node shell's Bloch ratio ω_h/ω ([`crate::fem::shell9::Shell9Bloch`]) along a mesh
/// line and along a diagonal, tabulated for one ν at qh = 0, [`SHELL9_TABLE_STEP`], … up to the
/// largest qh asked for (at most [`SHELL9_TABLE_MAX`]) and interpolated linearly: each entry is
/// an eigenproblem, and a model of many element sizes would otherwise solve one per element,
/// mode and iteration.
#[derive(Debug, Clone)]
pub struct Shell9Dispersion {
    along: Vec<f64>,
    diagonal: Vec<f64>,
}

/// Step in qh of [`Shell9Dispersion`]'s table (linear interpolation of ω_h/ω − 1 ≈ C·(qh)⁴:
/// error below 10⁻⁴ up to qh = 2, 2.2 elements per half-wave).
pub const SHELL9_TABLE_STEP: f64 = 0.05;
/// Largest qh of the table, 3π: one third of an element per half-wave; beyond it the last value.
pub const SHELL9_TABLE_MAX: f64 = 3.0 * std::f64::consts::PI;

impl Shell9Dispersion {
    /// The table for Poisson's ratio `nu` up to `qh_max`. The unit square's mass is positive
    /// definite, so every ratio exists (1, no error, otherwise).
    pub fn new(nu: f64, qh_max: f64) -> Shell9Dispersion {
        let bloch = crate::fem::shell9::Shell9Bloch::new(nu);
        let n = (qh_max.clamp(0.0, SHELL9_TABLE_MAX) / SHELL9_TABLE_STEP).ceil() as usize + 1;
        let qh = |k: usize| k as f64 * SHELL9_TABLE_STEP;
        let ratio = |a: f64, b: f64| bloch.as_ref().and_then(|e| e.ratio(a, b)).unwrap_or(1.0);
        let d = std::f64::consts::FRAC_1_SQRT_2;
        Shell9Dispersion {
            along: (0..=n).map(|k| ratio(qh(k), 0.0)).collect(),
            diagonal: (0..=n).map(|k| ratio(d * qh(k), d * qh(k))).collect(),
        }
    }

    fn at(table: &[f64], qh: f64) -> f64 {
        let x = (qh / SHELL9_TABLE_STEP).clamp(0.0, (table.len() - 1) as f64);
        let k = (x.floor() as usize).min(table.len() - 2);
        let f = x - k as f64;
        table[k] * (1.0 - f) + table[k + 1] * f
    }

    /// ω_h/ω along a mesh line and along a diagonal at `qh`.
    pub fn ratios(&self, qh: f64) -> (f64, f64) {
        (Self::at(&self.along, qh), Self::at(&self.diagonal, qh))
    }
}

/// Worse |ω_h/ω − 1| of the nine-node shell ([`crate::fem::shell9`]) along a mesh line and
/// along a diagonal of a mesh of squares ([`Shell9Dispersion`]), for `qh_h`, the qh that the
/// computed frequency ω_h gives: the true qh = qh_h/√(ω_h/ω) (the element reads high, so the
/// wave is longer than ω_h says), by fixed-point iteration.
pub fn worst_shell9_error(qh_h: f64, table: &Shell9Dispersion) -> f64 {
    let worst = |qh: f64| {
        let (r0, r1) = table.ratios(qh);
        let (r0, r1) = (r0 - 1.0, r1 - 1.0);
        if r0.abs() >= r1.abs() {
            r0
        } else {
            r1
        }
    };
    let mut e = worst(qh_h);
    for _ in 0..30 {
        let next = worst(qh_h / (1.0 + e.clamp(-0.5, 2.0)).sqrt());
        if (next - e).abs() <= 1e-12 {
            return next.abs();
        }
        e = next;
    }
    e.abs()
}

/// Per mode: the strain-energy-weighted estimate of the shells' frequency error (fraction) and
/// of their elements per bending half-wave π/(qh), or `None` for rigid-body modes and modes
/// whose strain energy is mostly outside the shells (see the module docs). One pass over the
/// elements ([`mode_energies_with`]), each element matrix built once for all modes.
pub fn shell_dispersion_estimates(model: &Model, raw: &ModalResults) -> Vec<Option<(f64, f64)>> {
    let n = raw.modes.len();
    // Each shell's qh per ω^½ and ν (its kind); the error estimates computed once per kind and mode.
    let mut kinds: Vec<(f64, f64, bool)> = Vec::new();
    let mut kind_of = std::collections::HashMap::new();
    let shell_kind: Vec<Option<usize>> = model
        .elements
        .iter()
        .map(|el| {
            // The corners and the element's side: a nine-node element's side spans two node
            // spacings.
            let (corners, t, mat, nine) = match el {
                Element::Shell4(sh) => (sh.nodes, sh.t, &sh.material, false),
                Element::Shell9(sh) => (
                    [sh.nodes[0], sh.nodes[1], sh.nodes[2], sh.nodes[3]],
                    sh.t,
                    &sh.material,
                    true,
                ),
                _ => return None,
            };
            let x = corners.map(|nd| model.nodes[nd]);
            let h = (0..4)
                .map(|i| {
                    let (a, b) = (x[i], x[(i + 1) % 4]);
                    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
                })
                .fold(0.0, f64::max);
            let qh_per_sqrt_omega = (12.0 * (1.0 - mat.nu * mat.nu) * mat.density / (mat.e * t * t)).powf(0.25) * h;
            Some(
                *kind_of
                    .entry((qh_per_sqrt_omega.to_bits(), mat.nu.to_bits(), nine))
                    .or_insert_with(|| {
                        kinds.push((qh_per_sqrt_omega, mat.nu, nine));
                        kinds.len() - 1
                    }),
            )
        })
        .collect();
    if kinds.is_empty() {
        return vec![None; n];
    }
    // The nine-node shells' Bloch tables, one per ν, up to the largest qh asked for (the true qh
    // of a wave is below the qh its computed frequency gives where the element reads high).
    let sqrt_omega_max = raw
        .modes
        .iter()
        .map(|m| m.eigenvalue.max(0.0).powf(0.25))
        .fold(0.0, f64::max);
    let mut tables: Vec<(u64, Shell9Dispersion)> = Vec::new();
    for &(_, nu, nine) in &kinds {
        if nine && !tables.iter().any(|(b, _)| *b == nu.to_bits()) {
            let qh_max = kinds
                .iter()
                .filter(|k| k.2 && k.1.to_bits() == nu.to_bits())
                .map(|k| k.0 * sqrt_omega_max)
                .fold(0.0, f64::max);
            tables.push((nu.to_bits(), Shell9Dispersion::new(nu, 1.2 * qh_max)));
        }
    }
    let table_of = |nu: f64| tables.iter().find(|(b, _)| *b == nu.to_bits()).map(|(_, t)| t);
    // Per mode and kind: (error estimate, elements per half-wave).
    let per_kind: Vec<Vec<(f64, f64)>> = raw
        .modes
        .iter()
        .map(|m| {
            let sqrt_omega = m.eigenvalue.max(0.0).powf(0.25);
            kinds
                .iter()
                .map(|&(c, nu, nine)| {
                    let qh = (c * sqrt_omega).max(f64::MIN_POSITIVE);
                    let error = match (nine, table_of(nu)) {
                        (true, Some(table)) => worst_shell9_error(qh, table),
                        _ => worst_square_mesh_error(qh, nu),
                    };
                    (error, std::f64::consts::PI / qh)
                })
                .collect()
        })
        .collect();
    // Per mode: the shells' energy, energy × error estimate, energy × elements per half-wave.
    let mut acc = vec![[0.0f64; 3]; n];
    let totals = mode_energies_with(model, raw, |ie, mode, e| {
        if let Some(kind) = shell_kind[ie] {
            let e = e.max(0.0);
            let (error, per_half_wave) = per_kind[mode][kind];
            let a = &mut acc[mode];
            a[0] += e;
            a[1] += e * error;
            a[2] += e * per_half_wave;
        }
    });
    acc.iter()
        .zip(&totals)
        .map(|(&[shells, error, per_half_wave], &(total, scale))| {
            let deforming = total > RIGID_MODE_TOL * scale;
            (deforming && shells > SHELL_SHARE * total).then(|| (error / shells, per_half_wave / shells))
        })
        .collect()
}

/// One warning naming the modes whose estimated shell frequency error exceeds
/// [`COARSE_SHELL_ERROR`], if any.
pub fn coarse_shell_warnings(model: &Model, raw: &ModalResults) -> Vec<String> {
    let flagged: Vec<(usize, f64, f64)> = shell_dispersion_estimates(model, raw)
        .iter()
        .enumerate()
        .filter_map(|(k, est)| est.filter(|e| e.0 > COARSE_SHELL_ERROR).map(|(e, n)| (k + 1, e, n)))
        .collect();
    if flagged.is_empty() {
        return Vec::new();
    }
    let list = flagged
        .iter()
        .map(|(k, e, n)| format!("mode {k}: {n:.1} elements per half-wave, about {:.1} %", 100.0 * e))
        .collect::<Vec<_>>()
        .join("; ");
    let (shell4, shell9) = model.shell_kinds();
    let what = match (shell4, shell9) {
        (_, false) => "the four-node shell's frequencies can read low by about the figures given ({list}; the element's thin-plate dispersion on a mesh of squares in the worse direction, a wave along a mesh diagonal)",
        (false, true) => "the nine-node shell's frequencies can read high by about the figures given ({list}; the element's thin-plate dispersion on a mesh of squares in the worse of a wave along a mesh line and along a diagonal)",
        (true, true) => "the shells' frequencies can be off by about the figures given ({list}; each element's thin-plate dispersion on a mesh of squares in its worse direction: four-node shells read low, nine-node shells high)",
    }
    .replace("{list}", &list);
    // Flat four-node shells can be solved as nine-node ones on the same mesh, unless they are.
    let promote = if shell4 {
        ", or solve flat four-node shells as nine-node shells on the same corners (`\"shell_elements\": \"shell9\"`)"
    } else {
        ""
    };
    vec![format!(
        "coarse shell mesh: the shells that carry these modes' strain energy have few elements per bending half-wave, and {what}: refine the shell mesh where these modes bend{promote}"
    )]
}
