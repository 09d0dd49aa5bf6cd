//! The hinge regions and segment chains a thread characterised last, reused when a design of a
//! mesh sweep repeats a hinge.
//!
//! A sweep over a parameterised mesh case repeats each hinge in many designs (a sweep over the
//! hinges' dimensions and the platform height holds every hinge once per height), and the
//! integration of the hinge profile is the largest single cost of a small model's build. A
//! region is a pure function of the hinge spec, the material and the node distance, a chain of
//! segment compliances of the region, the material and the segment count, so a remembered value
//! is the one computed afresh; keys are compared by value (`PartialEq` of every field, so a NaN
//! is never found and is computed again).

use crate::fem::memo::{remembered, Ring};
use crate::hinge::{self, HingeError, HingeRegion, HingeSpec, Profile};
use crate::material::Material;
use std::cell::RefCell;

/// A chain's compliances per segment (hinge axes, mm/N, rad/(N·mm)).
type Chain = Vec<[[f64; 6]; 6]>;

thread_local! {
    /// Regions remembered per thread (replaced oldest first).
    static REGIONS: RefCell<Ring<(HingeSpec, Material, u64), HingeRegion, 16>> = const { RefCell::new(Ring::new()) };
    /// Region volumes remembered per thread (replaced oldest first).
    static VOLUMES: RefCell<Ring<Profile, f64, 16>> = const { RefCell::new(Ring::new()) };
    /// Segment chains remembered per thread (replaced oldest first).
    static CHAINS: RefCell<Ring<(HingeRegion, Material, usize), Chain, 16>> = const { RefCell::new(Ring::new()) };
}

/// [`hinge::hinge_element`] of `spec` and `material` over the node distance `length` (mm),
/// remembered (errors are not). The length is compared bit for bit.
pub(super) fn region(spec: &HingeSpec, material: &Material, length: f64) -> Result<HingeRegion, HingeError> {
    remembered(&REGIONS, (*spec, *material, length.to_bits()), || {
        hinge::hinge_element(spec, material, length)
    })
}

/// [`HingeRegion::volume`] (mm³), remembered.
pub(super) fn volume(region: &HingeRegion) -> f64 {
    let computed: Result<f64, std::convert::Infallible> = remembered(&VOLUMES, region.profile, || Ok(region.volume()));
    match computed {
        Ok(v) => v,
        Err(never) => match never {},
    }
}

/// [`hinge::chain_compliances`] of `region` split into `segments`, remembered.
pub(super) fn chain(region: &HingeRegion, material: &Material, segments: usize) -> Chain {
    let key = (region.clone(), *material, segments);
    let computed: Result<Chain, std::convert::Infallible> = remembered(&CHAINS, key, || {
        Ok(hinge::chain_compliances(
            &region.profile,
            material,
            &region.stiffness,
            segments,
        ))
    });
    match computed {
        Ok(c) => c,
        Err(never) => match never {},
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A remembered region and chain equal the ones computed afresh, and another spec, length
    /// or segment count is not answered from the memo: 40 distinct hinges (more than the
    /// slots) at two lengths, twice over.
    #[test]
    fn remembered_equals_computed() {
        let m = Material::AL7075;
        for round in 0..2 {
            for k in 0..40 {
                let spec = HingeSpec::CircularNotch {
                    r: 4.0 + 0.05 * k as f64,
                    t: 1.0,
                    w: 10.0,
                    h: 10.0,
                    blank_length: 0.0,
                };
                for length in [20.0, 24.0] {
                    let fresh = hinge::hinge_element(&spec, &m, length).unwrap();
                    let got = region(&spec, &m, length).unwrap();
                    assert_eq!(got, fresh, "round {round}, hinge {k}, length {length}");
                    assert_eq!(volume(&got).to_bits(), fresh.volume().to_bits());
                    for n in [2, 4] {
                        let cs = hinge::chain_compliances(&fresh.profile, &m, &fresh.stiffness, n);
                        assert_eq!(cs.len(), n);
                        assert_eq!(chain(&got, &m, n), cs, "round {round}, hinge {k}, {n} segments");
                    }
                }
            }
        }
    }
}
