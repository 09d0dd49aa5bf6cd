//! The hinge regions a thread characterised last, reused when a stage design repeats one.
//!
//! A full-factorial sweep over a stage's hinges repeats each hinge in many designs (a sweep
//! over both hinges' dimensions holds every revolute hinge once per spherical one), and the
//! characterisation of a hinge region is most of a stage design's validation. The region is a
//! pure function of the profile and the material, so a remembered region is the one computed
//! afresh; regions are compared by value (`PartialEq` of every field).

use crate::fem::memo::{remembered, Ring};
use crate::hinge::{self, HingeError, HingeRegion, Profile};
use crate::material::Material;
use std::cell::RefCell;

thread_local! {
    /// Regions remembered per thread (replaced oldest first): a sweep cycling through up to
    /// 128 hinges of one joint keeps finding them.
    static MEMO: RefCell<Ring<(Profile, Material), HingeRegion, 128>> = const { RefCell::new(Ring::new()) };
}

/// [`hinge::flex_region`] of `profile` and `material`, remembered (errors are not).
pub(super) fn flex_region(profile: &Profile, material: &Material) -> Result<HingeRegion, HingeError> {
    remembered(&MEMO, (*profile, *material), || hinge::flex_region(profile, material))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hinge::HingeSpec;

    /// A remembered region equals the one computed afresh, and another profile (or material)
    /// is not answered from the memo: 200 distinct notches (more than the slots) twice over.
    #[test]
    fn remembered_region_is_the_computed_one() {
        let (al, steel) = (Material::AL7075, Material::STEEL);
        for round in 0..2 {
            for k in 0..200 {
                let spec = HingeSpec::CircularNotch {
                    r: 4.0 + 0.01 * k as f64,
                    t: 1.0,
                    w: 10.0,
                    h: 10.0,
                    blank_length: 5.0,
                };
                let p = spec.profile().unwrap();
                for m in [&al, &steel] {
                    let fresh = hinge::flex_region(&p, m).unwrap();
                    assert_eq!(flex_region(&p, m).unwrap(), fresh, "round {round}, notch {k}");
                }
            }
        }
    }
}
