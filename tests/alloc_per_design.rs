//! No heap allocation per design on the numerical hot paths of stage and hinge sweeps, counted
//! by a global allocator that wraps the system one (this test binary only).
//!
//! * A linear stage design, as `flexfem sweep` runs it (`analysis::stage` without output
//!   files): the design validated ([`StageDesign::validate`]: hinge regions characterised),
//!   condensed ([`flexfem::stage::ValidStage::linear`]), a user load case, the unit-force and
//!   unit-z cases solved and the platform compliance found.
//! * A hinge characterisation ([`characterise`]: hinge in its blank and notch alone, closed
//!   forms, model notes kept as numbers until written), circular, elliptical, corner-filleted,
//!   leaf and turned-neck hinges.
//!
//! Each runs a few designs to warm up, then N different designs (hinge dimensions, leg
//! lengths, sections, element counts, families), and must allocate nothing at all.
//! Source of the expectation: the code itself (a regression check, not a published value).
//! Before this change a linear stage design allocated 218 times (validation 29, FE model 13,
//! one load-case solve 176) and a hinge characterisation 11 times.

use flexfem::hinge::{characterise, Contour, HingeSpec};
use flexfem::kinematics::Prs;
use flexfem::material::Material;
use flexfem::stage::{Drive, StageDesign};
use std::hint::black_box;

#[path = "common/counting_alloc.rs"]
mod counting;

/// Designs run after the warm-up.
const N: usize = 60;

/// Allocations made by `f(k)` for k = 0..N, after `f` ran for three warm-up designs.
fn allocations(mut f: impl FnMut(usize)) -> usize {
    (N..N + 3).for_each(&mut f);
    let before = counting::allocations();
    (0..N).for_each(f);
    counting::allocations() - before
}

/// Stage design `k`: every revolute family, leg length, section, hinge sizes and element count
/// varied with `k`.
fn stage_design(k: usize) -> StageDesign {
    let x = (k % 7) as f64 / 7.0;
    let (w, h) = (8.0 + 2.0 * x, 10.0 - 2.0 * x);
    let notch = match k % 4 {
        0 => Contour::Circular {
            r: 4.0 + 4.0 * x,
            t: 1.5 + x,
        },
        1 => Contour::Elliptical {
            ax: 5.0 + 2.0 * x,
            ay: 3.0 + x,
            t: 1.5,
        },
        2 => Contour::CornerFilleted {
            l: 8.0 + 2.0 * x,
            r: 2.0,
            t: 1.2 + x,
        },
        _ => Contour::Leaf {
            l: 4.0 + 3.0 * x,
            t: 1.0 + 0.5 * x,
        },
    };
    let neck = Contour::SphericalNeck {
        l: 4.0 + x,
        t: 3.0 + x,
        r: 3.0,
    };
    StageDesign {
        prs: Prs::new(90.0 + 30.0 * x, 40.0, 50f64.to_radians(), 0.1 * x).expect("valid geometry"),
        leg_w: w,
        leg_h: h,
        revolute: HingeSpec::in_blank(notch, w, h, 0.0),
        spherical: HingeSpec::in_blank(neck, w, w.min(h), 0.0),
        material: [Material::AL7075, Material::STEEL, Material::NYLON66][k % 3],
        ideal_joints: false,
        leg_elements: 1 + k % 5,
    }
}

#[test]
fn linear_stage_design_allocates_nothing() {
    let n = allocations(|k| {
        let design = stage_design(k);
        let valid = design.validate().expect("valid design");
        let stage = valid.linear().expect("a linear stage without ideal joints");
        let unit_z = [0.9, 0.9, 0.9];
        for drive in [
            Drive::Forces([10.0, -5.0 * k as f64, 3.0]),
            Drive::Forces([1.0; 3]),
            Drive::Strokes(unit_z),
        ] {
            let r = black_box(stage.response(drive));
            assert!(
                r.max_von_mises.is_finite() && r.max_von_mises > 0.0,
                "design {k}: {r:?}"
            );
        }
        black_box(stage.compliance());
    });
    assert_eq!(n, 0, "{n} allocations in {N} stage designs");
}

/// Hinge design `k` of `family`: dimensions varied with `k`.
fn hinge(family: usize, k: usize) -> HingeSpec {
    let x = (k % 11) as f64 / 11.0;
    let contour = match family {
        0 => Contour::Circular {
            r: 2.0 + 8.0 * x,
            t: 0.5 + 2.0 * x,
        },
        1 => Contour::Elliptical {
            ax: 3.0 + 5.0 * x,
            ay: 2.0 + 2.0 * x,
            t: 0.8 + x,
        },
        2 => Contour::CornerFilleted {
            l: 5.0 + 5.0 * x,
            r: 1.0 + x,
            t: 0.6 + x,
        },
        3 => Contour::Leaf {
            l: 3.0 + 6.0 * x,
            t: 0.4 + x,
        },
        _ => Contour::SphericalNeck {
            l: 2.0 + 5.0 * x,
            t: 1.5 + 2.0 * x,
            r: 2.0 + 3.0 * x,
        },
    };
    HingeSpec::in_blank(contour, 8.0 + 4.0 * x, 10.0, 5.0 + 20.0 * x)
}

#[test]
fn hinge_characterisation_allocates_nothing() {
    for family in 0..5 {
        let m = Material::AL7075;
        let n = allocations(|k| {
            let spec = hinge(family, k);
            let r = black_box(characterise(black_box(&spec), &m).expect("valid hinge"));
            assert!(r.hinge.k_bend > 0.0 && !r.closed_form.is_empty(), "{spec:?}");
        });
        assert_eq!(n, 0, "{:?}: {n} allocations in {N} designs", hinge(family, 0));
    }
}
