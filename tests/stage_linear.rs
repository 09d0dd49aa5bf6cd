//! The stage solved on its condensed form without an FE model ([`ValidStage::linear`]) against
//! the FE model of the same design ([`flexfem::stage::StageModel::analyse`]): every number of
//! every load case (strokes, actuator forces, platform motion, hinge peak stresses, largest von
//! Mises stress) and the platform compliance, for 300 random designs (every revolute family,
//! materials, 1…8 leg elements, force and stroke drives).
//!
//! Source: both solve the same equations exactly (the legs are serial chains, condensed
//! exactly: J. S. Przemieniecki, Theory of Matrix Structural Analysis, 1968, §6.5 and §9.6), so
//! they agree to roundoff: 1e-10 relative, with an absolute floor of 1e-10 × the largest
//! magnitude among the same quantity's siblings (a pose, a compliance row: entries zero by
//! symmetry are roundoff of their siblings).

use flexfem::hinge::{Contour, HingeSpec};
use flexfem::kinematics::Prs;
use flexfem::material::Material;
use flexfem::stage::{Drive, StageDesign, ValidStage};

#[path = "common/rng.rs"]
mod rng;
use rng::Rng;

const REL: f64 = 1e-10;

fn random_design(r: &mut Rng) -> Option<StageDesign> {
    let (w, h) = (r.uniform(5.0, 14.0), r.uniform(5.0, 14.0));
    let t = r.uniform(0.1, 0.45) * h;
    let notch = match r.below(4) {
        0 => Contour::Circular {
            r: r.uniform(2.0, 12.0),
            t,
        },
        1 => Contour::Elliptical {
            ax: r.uniform(2.0, 12.0),
            ay: r.uniform(2.0, 10.0),
            t,
        },
        2 => {
            let l = r.uniform(4.0, 16.0);
            Contour::CornerFilleted {
                l,
                r: r.uniform(0.1, 0.5) * l,
                t,
            }
        }
        _ => Contour::Leaf {
            l: r.uniform(2.0, 12.0),
            t,
        },
    };
    let d = w.min(h);
    let neck = Contour::SphericalNeck {
        l: r.uniform(1.0, 9.0),
        t: r.uniform(0.2, 0.6) * d,
        r: r.uniform(1.0, 6.0),
    };
    let alpha = r.uniform(25.0, 70.0).to_radians();
    let gamma = r.uniform(-30.0, 30.0).to_radians();
    // Geometry the kinematics refuses (legs crossing the axis): refused alike by both paths.
    let prs = Prs::new(r.uniform(70.0, 150.0), r.uniform(25.0, 70.0), alpha, gamma).ok()?;
    Some(StageDesign {
        prs,
        leg_w: w,
        leg_h: h,
        revolute: HingeSpec::in_blank(notch, w, h, 0.0),
        spherical: HingeSpec::in_blank(neck, w, d, 0.0),
        material: *r.pick(&[Material::AL7075, Material::STEEL, Material::NYLON66]),
        ideal_joints: false,
        leg_elements: 1 + r.below(8),
    })
}

/// `a` equals `b` entry by entry within REL, floor REL × the largest |b|.
fn close(what: &str, a: &[f64], b: &[f64]) {
    let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    assert_eq!(a.len(), b.len(), "{what}: lengths");
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).abs() <= REL * y.abs().max(scale), "{what}: {a:?} vs FE {b:?}");
    }
}

#[test]
fn condensed_stage_equals_the_fe_model() {
    let mut r = Rng::new(0x5eed_57a6e);
    let mut solved = 0;
    while solved < 300 {
        let Some(design) = random_design(&mut r) else {
            continue;
        };
        let Ok(valid): Result<ValidStage, _> = design.validate() else {
            continue; // hinges that do not fit the leg: refused alike by both paths
        };
        let v = [r.uniform(-30.0, 60.0), r.uniform(-30.0, 60.0), r.uniform(-30.0, 60.0)];
        let drives = [
            ("F".to_string(), Drive::Forces(v)),
            ("S".to_string(), Drive::Strokes(v.map(|x| x / 30.0))),
        ];
        let fe = valid.build().analyse(&drives, true).expect("FE solve");
        let lin = valid.linear().expect("condensed");
        assert_eq!(fe.cases.len(), drives.len());
        for (c, (_, d)) in fe.cases.iter().zip(&drives) {
            let l = lin.response(*d);
            let p = |p: &flexfem::stage::PoseChange| [p.x, p.y, p.z, p.psi, p.theta, p.phi];
            let ctx = format!("{design:?} {d:?}");
            close(&format!("strokes {ctx}"), &l.strokes, &c.strokes);
            close(&format!("forces {ctx}"), &l.forces, &c.forces);
            let (lp, cp) = (p(&l.platform), p(&c.platform));
            close(&format!("translation {ctx}"), &lp[..3], &cp[..3]);
            close(&format!("rotation {ctx}"), &lp[3..], &cp[3..]);
            close(
                &format!("revolute stress {ctx}"),
                &l.hinge_stress[0],
                &c.revolute_stress,
            );
            close(
                &format!("spherical stress {ctx}"),
                &l.hinge_stress[1],
                &c.spherical_stress,
            );
            close(&format!("max von Mises {ctx}"), &[l.max_von_mises], &[c.max_von_mises]);
        }
        let (cl, cf) = (lin.compliance(), fe.compliance.expect("compliance"));
        for i in 0..6 {
            let row = |m: &nalgebra::Matrix6<f64>| (0..6).map(|j| m[(i, j)]).collect::<Vec<_>>();
            close(&format!("compliance row {i} {design:?}"), &row(&cl), &row(&cf));
        }
        solved += 1;
    }
}
