//! Units of the numbers of a `stage` result and case, for the columns of sweep tables
//! (see [`crate::analysis::common::units`]).

use super::StageResult;
use crate::analysis::common::units::{compliance_unit, hinge_spec_unit, material_unit, Units, K_ROT};

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
                ("fatigue", ["utilisation", _, _] | ["max_utilisation" | "factor_at_fatigue_limit"]) => "-",
                ("fatigue", ["life_cycles", _, _]) => "cycles",
                _ => return None,
            },
            ["stiffness_z"] => "N/mm",
            ["at_allowable", "allowable"] => "MPa",
            ["at_allowable", "force"] => "N",
            ["at_allowable", "stroke" | "z"] => "mm",
            ["at_fatigue_limit", "cycles"] => "cycles",
            ["at_fatigue_limit", "force"] => "N",
            ["at_fatigue_limit", "stroke" | "z" | "stroke_infinite_life"] => "mm",
            ["at_fatigue_limit", "load_ratio" | "leg"] => "-",
            ["at_fatigue_limit", "revolute" | "spherical", "notch_radius_mm"] => "mm",
            ["at_fatigue_limit", "revolute" | "spherical", "endurance_corrected" | "strength_at_cycles"] => "MPa",
            ["at_fatigue_limit", "revolute" | "spherical", _] => "-",
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
            ["fatigue", "cycles"] => "cycles",
            ["fatigue", "load_ratio"] => "-",
            ["material", field] => return material_unit(field),
            _ => return None,
        })
    }
}
