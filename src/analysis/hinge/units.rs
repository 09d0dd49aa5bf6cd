//! Units of the numbers of a `hinge` result and case, for the columns of sweep tables
//! (see [`crate::analysis::common::units`]).

use super::HingeOut;
use crate::analysis::common::units::{hinge_spec_unit, material_unit, stiffness_unit, Units, K_ROT};

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
            ["pivot_shift", "points", _, "rotation_deg"] => "deg",
            ["pivot_shift", "points", _, "centre", _] | ["pivot_shift", "points", _, "axis_crossing"] => "mm",
            ["pivot_shift", "drift"] => "mm",
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
