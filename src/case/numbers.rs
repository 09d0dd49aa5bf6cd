//! The numbers of `hinge` and `stage` cases by case path (`hinge.t`, `stage.revolute.R`,
//! `load_cases.0.actuator_forces.2`): a sweep sets each design's varied numbers in its worker's
//! parsed case instead of building and parsing the design's JSON. Only `f64` fields a case file
//! gives as numbers are reachable; any other path is `None` (the sweep then takes the JSON route).

use super::hinge::HingeCase;
use super::stage::StageCase;
use crate::hinge::HingeSpec;

/// A number of a hinge spec by its case-file name: a contour dimension or the blank's.
fn hinge_spec_number<'c>(spec: &'c mut HingeSpec, key: &str) -> Option<&'c mut f64> {
    use HingeSpec::*;
    if !matches!(key, "w" | "h" | "blank_length") {
        return spec.contour_number_mut(key);
    }
    let (w, h, blank_length) = match spec {
        CircularNotch { w, h, blank_length, .. }
        | EllipticalNotch { w, h, blank_length, .. }
        | CornerFilleted { w, h, blank_length, .. }
        | Leaf { w, h, blank_length, .. } => (Some(w), h, blank_length),
        // The turned neck's square blank has no width of its own.
        SphericalNeck { h, blank_length, .. } => (None, h, blank_length),
    };
    match key {
        "w" => w,
        "h" => Some(h),
        _ => Some(blank_length),
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
            ["stage", "revolute", key] => s.revolute.number_mut(key),
            ["stage", "spherical", key] => s.spherical.number_mut(key),
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Every number of every hinge family, set through `number_mut`, gives the case parsed from
    /// the JSON with that number changed (names and renames as serde reads them).
    #[test]
    fn every_hinge_number_is_the_parsed_one() {
        use crate::hinge::Contour;
        let contours = [
            Contour::Circular { r: 8.0, t: 2.0 },
            Contour::Elliptical {
                ax: 6.0,
                ay: 3.0,
                t: 2.0,
            },
            Contour::CornerFilleted {
                l: 10.0,
                r: 2.0,
                t: 2.0,
            },
            Contour::Leaf { l: 8.0, t: 1.0 },
            Contour::SphericalNeck { l: 5.0, t: 3.0, r: 4.0 },
        ];
        let specs = contours.map(|c| serde_json::to_string(&HingeSpec::in_blank(c, 10.0, 10.0, 5.0)).unwrap());
        for spec in specs {
            let json: serde_json::Value = serde_json::from_str(&spec).unwrap();
            for key in json.as_object().unwrap().keys().filter(|k| *k != "type") {
                let mut set: HingeSpec = serde_json::from_value(json.clone()).unwrap();
                *hinge_spec_number(&mut set, key).unwrap_or_else(|| panic!("{spec}: {key}")) = 123.5;
                let mut changed = json.clone();
                changed[key] = serde_json::json!(123.5);
                let parsed: HingeSpec = serde_json::from_value(changed).unwrap();
                assert_eq!(set, parsed, "{spec}: {key}");
            }
            let mut set: HingeSpec = serde_json::from_value(json).unwrap();
            assert!(hinge_spec_number(&mut set, "type").is_none() && hinge_spec_number(&mut set, "x").is_none());
        }
    }
}
