//! Markdown and CSV views of a `stage` result.

use super::StageResult;
use crate::analysis::Report;
use crate::report::markdown::{dms, sig, Table};

/// Markdown/CSV of a stage result.
pub fn stage_report(r: &StageResult) -> Report {
    let mut md = format!(
        "# 3-PRS compliant stage ({} FEM)\n\n",
        if r.nonlinear {
            "geometrically nonlinear"
        } else {
            "linear"
        }
    );
    for c in &r.load_cases {
        if let Some(w) = crate::analysis::fem_static::stability_warning(&c.name, c.stable, c.critical_load_factor) {
            md += &w;
        }
    }
    let mut t = Table::columns(
        "load case | F₁, F₂, F₃ (N) | s₁, s₂, s₃ (mm) | Δz (µm) | ψ | θ | σ_rev (MPa) | σ_sph (MPa) | σ_max (MPa) | T",
    );
    // Platform translations in µm in the CSV as in the Markdown table; `kind` = load_case or
    // mode (natural frequencies, when the case asks for `modes`).
    let mut csv = String::from(
        "kind,name,F1_N,F2_N,F3_N,s1_mm,s2_mm,s3_mm,x_um,y_um,z_um,psi_deg,theta_deg,phi_deg,max_von_mises_MPa,T,frequency_hz\n",
    );
    let f3 = |v: [f64; 3], d: usize| format!("{:.d$}, {:.d$}, {:.d$}", v[0], v[1], v[2]);
    for c in &r.load_cases {
        let mx = |v: [f64; 3]| v.iter().cloned().fold(0.0, f64::max);
        t.row(vec![
            c.name.to_string(),
            f3(c.forces, 2),
            f3(c.strokes, 4),
            format!("{:.1}", c.platform.z * 1000.0),
            dms(c.platform.psi_deg),
            dms(c.platform.theta_deg),
            format!("{:.2}", mx(c.hinge_stress.revolute)),
            format!("{:.2}", mx(c.hinge_stress.spherical)),
            format!("{:.2}", c.max_von_mises),
            finite_or_dash(c.t, |t| format!("{t:.3}")),
        ]);
        let p = &c.platform;
        csv += &format!(
            "load_case,{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},\n",
            c.name,
            c.forces[0],
            c.forces[1],
            c.forces[2],
            c.strokes[0],
            c.strokes[1],
            c.strokes[2],
            p.x * 1000.0,
            p.y * 1000.0,
            p.z * 1000.0,
            p.psi_deg,
            p.theta_deg,
            p.phi_deg,
            c.max_von_mises,
            finite_or_dash(c.t, |t| t.to_string()).replace('—', "")
        );
    }
    md += &t.render();
    let a = &r.at_allowable;
    let reach = if [a.allowable, a.force, a.stroke, a.z].iter().all(|v| v.is_finite()) {
        format!(
            "At the allowable stress {} MPa under equal forces: F = {} N per actuator, stroke {} mm, Δz = {} mm.",
            a.allowable,
            sig(a.force, 5),
            sig(a.stroke, 5),
            sig(a.z, 5)
        )
    } else {
        "No allowable stress bounds the stroke (the material has none, or equal forces stress no hinge).".to_string()
    };
    let reach = match &r.at_fatigue_limit {
        Some(f) => format!(
            "{reach}\n\nAt the fatigue limit ({:e} cycles, R = {}) under equal forces: F = {} N per actuator, stroke {} mm, Δz = {} mm (first: {} hinge of leg {}); infinite life: stroke {} mm.",
            f.cycles,
            f.load_ratio,
            sig(f.force, 5),
            sig(f.stroke, 5),
            sig(f.z, 5),
            f.hinge,
            f.leg,
            sig(f.stroke_infinite_life, 5)
        ),
        None => reach,
    };
    md += &format!(
        "\nStructural stiffness (total actuator force per mm of pure-z stroke): **{} N/mm**.\n\n{reach}\n\nPlatform stiffness at P (sliders held): translational eigenvalues {}…{} N/mm, rotational {}…{} N·mm/rad.\n",
        sig(r.stiffness_z, 5),
        sig(r.platform_stiffness.translational_eigen[0], 4),
        sig(r.platform_stiffness.translational_eigen[1], 4),
        sig(r.platform_stiffness.rotational_eigen[0], 4),
        sig(r.platform_stiffness.rotational_eigen[1], 4),
    );
    if let Some(modes) = &r.modes {
        md += "\n## Natural frequencies (actuators locked)\n\n";
        let mut t = Table::new(&["mode", "f (Hz)", "x", "y", "z", "rx", "ry", "rz"]);
        for m in modes {
            let e = m.effective_mass_fraction;
            let mut row = vec![m.mode.to_string(), format!("{:.2}", m.frequency_hz)];
            row.extend([e.x, e.y, e.z, e.rx, e.ry, e.rz].iter().map(|v| format!("{v:.4}")));
            t.row(row);
            csv += &format!("mode,mode_{},,,,,,,,,,,,,,,{}\n", m.mode, m.frequency_hz);
        }
        md += "Effective mass fractions per direction after the frequency.\n\n";
        md += &t.render();
        md += "\nMode shapes: `modes.vtu` (with `--out`).\n";
    }
    md += "\n## Model\n\n";
    for n in &r.model {
        md += &format!("- {n}\n");
    }
    Report { markdown: md, csv }
}

/// `f(v)` for a finite `v`, "—" for an undefined or unbounded value (documented `null`s).
fn finite_or_dash(v: f64, f: impl Fn(f64) -> String) -> String {
    if v.is_finite() {
        f(v)
    } else {
        "—".to_string()
    }
}
