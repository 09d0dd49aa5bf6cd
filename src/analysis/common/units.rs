//! Units of the numbers a result (and a case) holds, by JSON path, for the columns of sweep
//! tables: `flexfem sweep --csv` writes a column as `name [unit]`.
//!
//! Units are written in ASCII: `mm`, `N`, `MPa`, `s`, `t` (tonne), `deg`, products with `*`,
//! powers with `^` (`N*mm/rad`, `t/mm^3`), and `-` for a dimensionless number (ratios, factors,
//! counts). Angles are degrees wherever a result holds them; `rad` appears only inside the units of
//! stiffnesses and compliances, which the results give per radian. Each result type declares its
//! units ([`Units`]) next to its fields' meaning, and its analysis kind hands them to sweeps
//! ([`Analysis::column_units`](crate::analysis::Analysis::column_units)); a path the type does not declare has no unit
//! (text, flags and identifiers).

use crate::analysis::hinge::HingeOut;
use crate::analysis::stage::StageResult;

/// The unit of a number by its path in the JSON (object keys and array indices as text).
pub type UnitOf = fn(&[&str]) -> Option<&'static str>;

/// Units of a result type's numbers ([`Self::result_unit`]) and of the numbers of the case it
/// comes from ([`Self::input_unit`], for a sweep's varied paths).
pub trait Units {
    /// The unit of the result's number at `path`.
    fn result_unit(path: &[&str]) -> Option<&'static str>;
    /// The unit of the case's number at `path`.
    fn input_unit(path: &[&str]) -> Option<&'static str>;
}

/// The (result, case) unit functions of a result type, as
/// [`Analysis::column_units`](crate::analysis::Analysis::column_units) gives them.
pub fn of<U: Units>() -> (UnitOf, UnitOf) {
    (U::result_unit, U::input_unit)
}

/// A rotational stiffness (moment per radian).
const K_ROT: &str = "N*mm/rad";

/// Entry (i, j) of a 6×6 compliance, rows/columns (ux, uy, uz, rx, ry, rz).
fn compliance_unit(i: &str, j: &str) -> Option<&'static str> {
    let rot = |k: &str| k.parse::<usize>().ok().filter(|&k| k < 6).map(|k| k >= 3);
    Some(match (rot(i)?, rot(j)?) {
        (false, false) => "mm/N",
        (true, true) => "rad/(N*mm)",
        // mm per N·mm, or rad per N
        (false, true) => "1/N",
        (true, false) => "rad/N",
    })
}

/// The material echoed in a result (`material.E`, …) or given in a case.
fn material_unit(field: &str) -> Option<&'static str> {
    Some(match field {
        "E" | "yield" | "allowable" => "MPa",
        "nu" => "-",
        "density" => "t/mm^3",
        _ => return None,
    })
}

/// A hinge's stiffness set ([`crate::hinge::Stiffness`]): the hinge and its notch alone.
fn stiffness_unit(path: &[&str]) -> Option<&'static str> {
    Some(match path {
        ["k_bend" | "k_bend_off" | "k_torsion" | "k_torsion_saint_venant"] => K_ROT,
        ["k_axial"] => "N/mm",
        ["compliance", i, j] => return compliance_unit(i, j),
        // MPa per N·mm
        ["stress_per_moment"] => "1/mm^3",
        ["max_rotation_deg"] => "deg",
        _ => return None,
    })
}

/// Every number of a hinge specification is a length (R, t, w, h, l, ax, ay, blank_length).
fn hinge_spec_unit(path: &[&str]) -> Option<&'static str> {
    matches!(path, [field] if *field != "type").then_some("mm")
}

impl Units for HingeOut {
    fn result_unit(path: &[&str]) -> Option<&'static str> {
        Some(match path {
            ["notch_only", rest @ ..] => return stiffness_unit(rest),
            // Compliant-axis rotational stiffness of the notch alone.
            ["closed_form", _] => K_ROT,
            ["stress_concentration"] => "-",
            ["calibration", "short_notch_g" | "plane_strain_p"] => "-",
            ["calibration", "load_spreading", "slope"] => "-",
            ["calibration", "load_spreading", "from_mm" | "to_mm"] => "mm",
            ["material", field] => return material_unit(field),
            ["large_rotation", "points", _, field] => match *field {
                "force" => "N",
                "moment" => "N*mm",
                "rotation_deg" | "linear_rotation_deg" => "deg",
                "max_stress" => "MPa",
                _ => return None,
            },
            ["large_rotation", "rotation_at_allowable_deg" | "linear_rotation_at_allowable_deg"] => "deg",
            ["damping", field] => match *field {
                "k_nmm_per_rad" => K_ROT,
                "k_nmm_per_deg" => "N*mm/deg",
                "d_nmm_s_per_rad" => "N*mm*s/rad",
                "d_nmm_s_per_deg" => "N*mm*s/deg",
                "d_over_k_s" | "dt_s" => "s",
                "j_t_mm2" => "t*mm^2",
                "fit_residual" | "steps" => "-",
                _ => return None,
            },
            ["fatigue", field] => match *field {
                "fatigue_utilisation" | "kt" | "notch_sensitivity" | "kf" | "marin_surface" | "marin_size" => "-",
                "life_cycles" => "cycles",
                "infinite_life" => "-",
                "stroke_infinite_life" => "deg",
                "notch_radius_mm" => "mm",
                "endurance_corrected" | "stress_alternating" | "stress_mean" => "MPa",
                "stress_per_rad" => "MPa/rad",
                _ => return None,
            },
            _ => return stiffness_unit(path),
        })
    }

    fn input_unit(path: &[&str]) -> Option<&'static str> {
        match path {
            ["hinge", rest @ ..] => hinge_spec_unit(rest),
            ["material", field] => material_unit(field),
            ["fatigue", "stroke" | "mean"] => Some("deg"),
            ["fatigue", "cycles"] => Some("cycles"),
            _ => None,
        }
    }
}

impl Units for StageResult {
    fn result_unit(path: &[&str]) -> Option<&'static str> {
        Some(match path {
            ["load_cases", _, field, ..] => match (*field, &path[3..]) {
                ("strokes", [_]) => "mm",
                ("forces", [_]) => "N",
                ("platform", ["x" | "y" | "z"]) => "mm",
                ("platform", ["psi_deg" | "theta_deg" | "phi_deg"]) => "deg",
                ("max_von_mises", []) | ("hinge_stress", [_, _]) => "MPa",
                ("T" | "factor_at_allowable", []) | ("critical_load_factor", [_]) => "-",
                _ => return None,
            },
            ["stiffness_z"] => "N/mm",
            ["at_allowable", "allowable"] => "MPa",
            ["at_allowable", "force"] => "N",
            ["at_allowable", "stroke" | "z"] => "mm",
            ["platform_stiffness", "compliance", i, j] => return compliance_unit(i, j),
            ["platform_stiffness", "translational_eigen", _] => "N/mm",
            ["platform_stiffness", "rotational_eigen", _] => K_ROT,
            ["modes", _, "mode"] | ["modes", _, "effective_mass_fraction", _] => "-",
            ["modes", _, "frequency_hz"] => "Hz",
            ["modes", _, "eigenvalue"] => "(rad/s)^2",
            ["material", field] => return material_unit(field),
            _ => return None,
        })
    }

    fn input_unit(path: &[&str]) -> Option<&'static str> {
        Some(match path {
            ["stage", "L" | "b" | "a"] | ["stage", "leg", "w" | "h"] => "mm",
            ["stage", "alpha0_deg" | "gamma_deg"] => "deg",
            ["stage", "leg_elements"] | ["steps" | "modes"] => "-",
            ["stage", "revolute" | "spherical", rest @ ..] => return hinge_spec_unit(rest),
            ["load_cases", _, "actuator_forces", _] => "N",
            ["load_cases", _, "actuator_strokes", _] => "mm",
            ["platform_mass"] => "t",
            ["platform_thickness"] => "mm",
            ["material", field] => return material_unit(field),
            _ => return None,
        })
    }
}
