//! Published mechanisms and tables that more than one test file checks against, written once.
#![allow(dead_code)]

use flexfem::kinematics::prs_stiffness::{Branch, LegModel, Link, PrsLayout, PrsStiffness, Screw, ScrewMount};

/// The 3-PRS of X. Han, Y. Wang, J. Shi, "Stiffness Modeling of 3-PRS Mechanism" (Tables I–III),
/// with the out-of-plane (constraint) bending `i_lateral` of the link (mm⁴; the paper's
/// I_y = 8.64e6). Readings we had to choose (not published): vertical rails with the platform
/// hanging below the revolutes (γ = −90°), the screw fixed–fixed over its 600 mm with the first
/// bearing at the zero-stroke point Aᵢ, no nut or joint compliance.
pub fn han(i_lateral: f64) -> PrsStiffness {
    let layout = PrsLayout::new(470.0, 315.0, 185.0, (-90f64).to_radians(), Branch::Minus).unwrap();
    PrsStiffness::new(
        layout,
        LegModel::ScrewLink {
            screw: Screw {
                area: 183.5,
                e: 231_000.0,
                mount: ScrewMount::FixedFixed {
                    length: 600.0,
                    nut_at_zero_stroke: 0.0,
                },
                nut_k: None,
            },
            link: Link {
                area: 7200.0,
                e: 210_000.0,
                i_lateral,
            },
        },
    )
    .unwrap()
}

/// Yu, Lu and Hao (2016) Table 4: the largest rotation of each of the eight joints J1 … J8 over
/// the circular path (deg) as printed, 10.00, 9.998, 9.998, 11.57, 11.56, 11.56, 10.84, 10.84°,
/// each with half a unit of its last printed digit as tolerance (deg).
pub const PT_TABLE4_MAX_ROTATION_DEG: [(f64, f64); 8] = [
    (10.00, 0.005),
    (9.998, 0.0005),
    (9.998, 0.0005),
    (11.57, 0.005),
    (11.56, 0.005),
    (11.56, 0.005),
    (10.84, 0.005),
    (10.84, 0.005),
];
