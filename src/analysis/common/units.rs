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
pub const K_ROT: &str = "N*mm/rad";

/// Entry (i, j) of a 6×6 compliance, rows/columns (ux, uy, uz, rx, ry, rz).
pub fn compliance_unit(i: &str, j: &str) -> Option<&'static str> {
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
pub fn material_unit(field: &str) -> Option<&'static str> {
    Some(match field {
        "E" | "yield" | "allowable" => "MPa",
        "nu" => "-",
        "density" => "t/mm^3",
        _ => return None,
    })
}

/// A hinge's stiffness set ([`crate::hinge::Stiffness`]): the hinge and its notch alone.
pub fn stiffness_unit(path: &[&str]) -> Option<&'static str> {
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
pub fn hinge_spec_unit(path: &[&str]) -> Option<&'static str> {
    matches!(path, [field] if *field != "type").then_some("mm")
}
