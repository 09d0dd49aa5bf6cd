//! Number conventions of results: rotations in degrees ([`mm_deg`]), and serialisers for result
//! fields whose non-finite values have a documented meaning.
//!
//! Every number in a result must be finite (`analysis::to_checked_json` refuses NaN and ±∞ with
//! their JSON path). A few fields are legitimately unbounded or undefined — the rotation at the
//! allowable stress of a material that has no allowable, the load factor of a load case that
//! stresses nothing — and are written as `null` with that meaning stated in the field's docs.

use serde::Serializer;

/// ±∞ ("unbounded") as `null`; finite values as numbers. NaN stays NaN, so the finite check
/// still refuses it.
pub fn unbounded_as_null<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
    if v.is_infinite() {
        s.serialize_none()
    } else {
        s.serialize_f64(*v)
    }
}

/// A ratio that is undefined (0/0 → NaN) or unbounded (x/0 → ±∞) as `null`; finite values as
/// numbers. Only for ratios whose terms are written (and checked) elsewhere in the result.
pub fn ratio_or_null<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
    if v.is_finite() {
        s.serialize_f64(*v)
    } else {
        s.serialize_none()
    }
}

/// A node's six displacement components as written in every output: translations in mm,
/// rotations converted from radians (inside the library) to degrees.
pub fn mm_deg(d: &[f64; 6]) -> [f64; 6] {
    [
        d[0],
        d[1],
        d[2],
        d[3].to_degrees(),
        d[4].to_degrees(),
        d[5].to_degrees(),
    ]
}
