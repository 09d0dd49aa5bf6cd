//! The numbers of `hinge` and `stage` cases by case path (`hinge.t`, `stage.revolute.R`,
//! `load_cases.0.actuator_forces.2`): a sweep sets each design's varied numbers in its worker's
//! parsed case instead of building and parsing the design's JSON. Only `f64` fields a case file
//! gives as numbers are reachable; any other path is `None` (the sweep then takes the JSON route).

use super::hinge::HingeCase;
use super::stage::StageCase;
use crate::hinge::{Contour, HingeSpec};

/// A dimension of a notch contour by its case-file name.
fn contour_number<'c>(c: &'c mut Contour, key: &str) -> Option<&'c mut f64> {
    use Contour::*;
    match (c, key) {
        (Circular { r, .. } | CornerFilleted { r, .. } | SphericalNeck { r, .. }, "R") => Some(r),
        (
            Circular { t, .. }
            | Elliptical { t, .. }
            | CornerFilleted { t, .. }
            | Leaf { t, .. }
            | SphericalNeck { t, .. },
            "t",
        ) => Some(t),
        (Elliptical { ax, .. }, "ax") => Some(ax),
        (Elliptical { ay, .. }, "ay") => Some(ay),
        (CornerFilleted { l, .. } | Leaf { l, .. } | SphericalNeck { l, .. }, "l") => Some(l),
        _ => None,
    }
}

/// A number of a hinge spec by its case-file name: a contour dimension or the blank's.
fn hinge_spec_number<'c>(h: &'c mut HingeSpec, key: &str) -> Option<&'c mut f64> {
    use HingeSpec::*;
    match (h, key) {
        (CircularNotch { w, .. } | EllipticalNotch { w, .. } | CornerFilleted { w, .. } | Leaf { w, .. }, "w") => {
            Some(w)
        }
        (
            CircularNotch { h, .. }
            | EllipticalNotch { h, .. }
            | CornerFilleted { h, .. }
            | Leaf { h, .. }
            | SphericalNeck { h, .. },
            "h",
        ) => Some(h),
        (
            CircularNotch { blank_length, .. }
            | EllipticalNotch { blank_length, .. }
            | CornerFilleted { blank_length, .. }
            | Leaf { blank_length, .. }
            | SphericalNeck { blank_length, .. },
            "blank_length",
        ) => Some(blank_length),
        (CircularNotch { r, .. } | CornerFilleted { r, .. } | SphericalNeck { r, .. }, "R") => Some(r),
        (
            CircularNotch { t, .. }
            | EllipticalNotch { t, .. }
            | CornerFilleted { t, .. }
            | Leaf { t, .. }
            | SphericalNeck { t, .. },
            "t",
        ) => Some(t),
        (EllipticalNotch { ax, .. }, "ax") => Some(ax),
        (EllipticalNotch { ay, .. }, "ay") => Some(ay),
        (CornerFilleted { l, .. } | Leaf { l, .. } | SphericalNeck { l, .. }, "l") => Some(l),
        _ => None,
    }
}

impl HingeCase {
    /// The number at `path` (see the module docs).
    pub fn number_mut(&mut self, path: &[&str]) -> Option<&mut f64> {
        match path {
            ["hinge", key] => hinge_spec_number(&mut self.hinge, key),
            _ => None,
        }
    }
}

impl StageCase {
    /// The number at `path` (see the module docs).
    pub fn number_mut(&mut self, path: &[&str]) -> Option<&mut f64> {
        let s = &mut self.stage;
        match path {
            ["stage", "L"] => Some(&mut s.l),
            ["stage", "b"] => Some(&mut s.b),
            ["stage", "gamma_deg"] => Some(&mut s.gamma_deg),
            ["stage", "alpha0_deg"] => s.alpha0_deg.as_mut(),
            ["stage", "a"] => s.a.as_mut(),
            ["stage", "leg", "w"] => Some(&mut s.leg.w),
            ["stage", "leg", "h"] => Some(&mut s.leg.h),
            ["stage", "revolute", key] => contour_number(&mut s.revolute, key),
            ["stage", "spherical", key] => contour_number(&mut s.spherical, key),
            ["platform_mass"] => self.platform_mass.as_mut(),
            ["platform_thickness"] => self.platform_thickness.as_mut(),
            ["load_cases", i, drive, k] => {
                let lc = self.load_cases.get_mut(i.parse::<usize>().ok()?)?;
                let v = match *drive {
                    "actuator_forces" => lc.actuator_forces.as_mut()?,
                    "actuator_strokes" => lc.actuator_strokes.as_mut()?,
                    _ => return None,
                };
                v.get_mut(k.parse::<usize>().ok()?)
            }
            _ => None,
        }
    }
}
