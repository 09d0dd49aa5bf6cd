//! The compliant 3-PRS stage of Ruiz et al. (A. Ruiz, F. J. Campa, C. Roldán-Paraponiaris,
//! O. Altuzarra, "Experimental validation of the kinematic design of 3-PRS compliant parallel
//! mechanisms", Mechatronics 2019; cases/ruiz2019_stage.json): its rigid-body stiffness model
//! (`prs_stiffness`, series chains of Nigatu et al.) with chain stiffnesses derived from the
//! stage's own compliances against the stage FE's 6×6 platform compliance (sliders held).
//!
//! Chain stiffnesses per leg, from the clamped slider to the spherical centre Bᵢ: the revolute
//! hinge region's 6×6 compliance, the leg beam (Timoshenko cantilever, the FE leg's section and
//! length between the hinge regions), the spherical neck region's 6×6 compliance, each moved to
//! Bᵢ (wrench/twist transfer) and summed. Actuation chain: the axial compliance lᵢᵀC lᵢ mapped to
//! the stroke coordinate, k_a = (lᵢ·eᵢ)²/(lᵢᵀC lᵢ); constraint chain: k_c = 1/(mᵢᵀC mᵢ), the
//! lateral compliance along the revolute axis at Bᵢ. What the rigid-body model leaves out: the
//! rotational stiffness of the hinges about their compliant axes (revolute about mᵢ, the neck in
//! all three rotations), which the FE carries in parallel with the leg chains, and the in-plane
//! lateral and cross couplings of the legs, which the model takes as rigid/absent. The rigid-body
//! model is bundled as cases/prs_stiffness_ruiz2019_stage.json (home pose, a tilted pose, a ±5° map).

use flexfem::analysis::{self, Case};
use flexfem::kinematics::prs_stiffness::{Branch, LegModel, PrsLayout, PrsStiffness};
use flexfem::stage::Drive;
use nalgebra::{Matrix3, Matrix6, Vector3};

fn skew(r: Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(0.0, -r[2], r[1], r[2], 0.0, -r[0], -r[1], r[0], 0.0)
}

/// Compliance at `b` (global axes) of a segment whose tip compliance is `c` (local axes `rows`:
/// x along the leg, y = mᵢ, z = nᵢ) at its tip point `tip`.
fn at_point(c: &Matrix6<f64>, rows: &Matrix3<f64>, tip: Vector3<f64>, b: Vector3<f64>) -> Matrix6<f64> {
    let mut rg = Matrix6::zeros();
    rg.fixed_view_mut::<3, 3>(0, 0).copy_from(&rows.transpose());
    rg.fixed_view_mut::<3, 3>(3, 3).copy_from(&rows.transpose());
    let mut tw = Matrix6::identity();
    tw.fixed_view_mut::<3, 3>(3, 0).copy_from(&skew(b - tip));
    tw.transpose() * rg * c * rg.transpose() * tw
}

/// Timoshenko cantilever tip compliance, local axes (x along).
fn beam_compliance(l: f64, e: f64, nu: f64, w: f64, h: f64) -> Matrix6<f64> {
    let p = flexfem::fem::Section::Rect { w, h }.properties(nu);
    let g = e / (2.0 * (1.0 + nu));
    let mut c = Matrix6::zeros();
    c[(0, 0)] = l / (e * p.a);
    c[(1, 1)] = l.powi(3) / (3.0 * e * p.iz) + p.asy.map_or(0.0, |a| l / (g * a));
    c[(1, 5)] = l * l / (2.0 * e * p.iz);
    c[(5, 1)] = c[(1, 5)];
    c[(5, 5)] = l / (e * p.iz);
    c[(2, 2)] = l.powi(3) / (3.0 * e * p.iy) + p.asz.map_or(0.0, |a| l / (g * a));
    c[(2, 4)] = -l * l / (2.0 * e * p.iy);
    c[(4, 2)] = c[(2, 4)];
    c[(4, 4)] = l / (e * p.iy);
    c[(3, 3)] = l / (g * p.j);
    c
}

struct Cross {
    layout: (f64, f64, f64, f64, f64),
    c_fe: Matrix6<f64>,
    c_rb: Matrix6<f64>,
    actuation: Vec<f64>,
    constraint: Vec<f64>,
}

/// `release`: add this compliance (rad/(N·mm)) to the hinges' rotations about their compliant
/// axes (revolute: about mᵢ; neck: all three), i.e. make them (nearly) ideal joints in the FE.
/// `at_neck_top`: put the rigid-body spherical centre where the FE platform attaches, at the
/// neck top Bᵢ + h_s·lᵢ (layout b, L and home height moved accordingly), instead of at Bᵢ.
fn cross_check(release: f64) -> Cross {
    cross_check_at(release, false)
}

fn cross_check_at(release: f64, at_neck_top: bool) -> Cross {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/cases/ruiz2019_stage.json");
    let Case::Stage(sc) = analysis::load(std::path::Path::new(path)).unwrap() else {
        panic!("not a stage case")
    };
    let (vs, _) = sc.validated().unwrap();
    let mut sm = vs.build();
    for leg in sm.legs {
        for (el, dofs) in [(leg.rev_element, &[4][..]), (leg.sph_element, &[3, 4, 5][..])] {
            let Some(flexfem::fem::Element::Flex(f)) = sm.model.elements.get_mut(el.unwrap()) else {
                panic!("hinge element expected")
            };
            for &k in dofs {
                f.compliance[k][k] += release;
            }
        }
    }
    let c_fe = sm
        .analyse(&[("held".to_string(), Drive::Strokes([0.0; 3]))], true)
        .unwrap()
        .compliance
        .unwrap();
    let d = vs.design();
    let prs = d.prs;
    let (hr, hs) = (sm.revolute.half_length(), sm.spherical.half_length());
    // Leg 0 (all alike): chain compliance at B.
    let (c, b) = (prs.a_point(0), prs.b_home(0));
    let l = (b - c) / prs.l;
    let m = prs.m(0);
    let n = l.cross(&m);
    let rows = Matrix3::from_rows(&[l.transpose(), m.transpose(), n.transpose()]);
    let cr = Matrix6::from_fn(|i, j| sm.revolute.compliance()[i][j]);
    let cs = Matrix6::from_fn(|i, j| sm.spherical.compliance()[i][j]);
    let lb = prs.l - hr - hs;
    let cb = beam_compliance(lb, d.material.e, d.material.nu, d.leg_w, d.leg_h);
    let (b0, b) = (b, if at_neck_top { b + hs * l } else { b });
    let parts = [
        at_point(&cr, &rows, c + hr * l, b),
        at_point(&cb, &rows, b0 - hs * l, b),
        at_point(&cs, &rows, b0 + hs * l, b),
    ];
    let le = l.dot(&prs.e(0));
    // Per segment (revolute, leg beam, neck): actuation on the stroke, constraint along mᵢ at Bᵢ.
    let actuation: Vec<f64> = parts
        .iter()
        .map(|p| le * le / (l.transpose() * p.fixed_view::<3, 3>(0, 0) * l)[0])
        .collect();
    let constraint: Vec<f64> = parts
        .iter()
        .map(|p| 1.0 / (m.transpose() * p.fixed_view::<3, 3>(0, 0) * m)[0])
        .collect();
    let (radius, length, height) = ((b - b[2] * Vector3::z()).norm(), (b - c).norm(), b[2]);
    let layout = PrsLayout::new(prs.a, radius, length, prs.gamma, Branch::Minus).unwrap();
    let model = PrsStiffness::new(
        layout,
        LegModel::Chain {
            actuation: actuation.clone(),
            constraint: constraint.clone(),
        },
    )
    .unwrap();
    // Compliance at the FE platform node (the home P), above the spherical-centre plane.
    let ps = model
        .at(height, 0.0, 0.0, &Vector3::new(0.0, 0.0, prs.z0 - height))
        .unwrap();
    assert!(
        ps.state.s.iter().all(|s| s.abs() < 1e-9),
        "home strokes {:?}",
        ps.state.s
    );
    Cross {
        layout: (prs.a, prs.b, prs.l, prs.gamma.to_degrees(), prs.z0),
        c_fe,
        c_rb: ps.compliance,
        actuation,
        constraint,
    }
}

/// Model/FE ratio of the diagonal compliances (x, y, z, rx, ry, rz).
fn ratios(x: &Cross, fe: &Matrix6<f64>) -> [f64; 6] {
    std::array::from_fn(|i| x.c_rb[(i, i)] / fe[(i, i)])
}

/// Measured (this file, Al7075 stage of cases/ruiz2019_stage.json): chains (revolute, leg, neck)
/// actuation [7.35e4, 4.25e4, 2.20e4] N/mm on the stroke, constraint [102, 183, 2976] N/mm along
/// mᵢ. Model/FE diagonal compliance: z 1.0005; x, y 2.254; rx, ry 2.260; rz 1.409.
/// - z within 0.1 %: a z load compresses the three legs alike, which is what the actuation chain
///   models; the 0.05 % is the hinges' bending stiffness about their compliant axes (in the FE, not
///   in the ideal joints) — released in the FE it drops to below 1e-5 (next test).
/// - x, y, rx, ry, rz: the rigid-body model is 2.25× (rz 1.41×) more compliant than the FE. These
///   directions load the constraint chains, which are soft (lateral cantilever of the leg: 64 N/mm
///   in series), so the moments the real hinges carry — the neck's bending and torsion stiffness,
///   the revolute's stiffness about mᵢ, which act in parallel with the constraint chains — stiffen
///   the FE a lot; the ideal joints carry none. Bands: the measured ratio ± 2 %.
#[test]
fn stage_prs_stiffness_against_stage_fe() {
    let x = cross_check(0.0);
    eprintln!("layout (a, b, L, γ°, z0) {:?}", x.layout);
    eprintln!(
        "actuation chain {:?} N/mm, constraint chain {:?} N/mm",
        x.actuation, x.constraint
    );
    let r = ratios(&x, &x.c_fe);
    let names = ["x", "y", "z", "rx", "ry", "rz"];
    for i in 0..6 {
        eprintln!(
            "C_{0}{0}: FE {1:.6e}, prs_stiffness {2:.6e}, model/FE = {3:.5}",
            names[i],
            x.c_fe[(i, i)],
            x.c_rb[(i, i)],
            r[i]
        );
    }
    assert!((r[2] - 1.0).abs() < 1e-3, "z: model/FE = {}", r[2]);
    for (i, want) in [(0, 2.2538), (1, 2.2538), (3, 2.2596), (4, 2.2596), (5, 1.4094)] {
        assert!(
            (r[i] / want - 1.0).abs() < 0.02,
            "{}: model/FE = {} (measured {want})",
            names[i],
            r[i]
        );
    }
}

/// Asserts each ratio `r[i]` (model/FE, per direction) within 2 % of its measured value.
fn within_2_percent(r: &[f64], measured: [(usize, f64); 5]) {
    for (i, want) in measured {
        assert!(
            (r[i] / want - 1.0).abs() < 0.02,
            "direction {i}: model/FE = {} (measured {want})",
            r[i]
        );
    }
}

/// With the hinges' compliant rotations released in the FE (0.1 rad/(N·mm) added: revolute about
/// mᵢ, neck about all three axes — nearly ideal joints), z agrees to 1e-5 (the remaining
/// difference in z was the hinges' rotational stiffness). The other directions flip: the FE is
/// then 2.85× softer than the model (model/FE 0.351 … 0.350): the FE platform attaches at the
/// neck top Bᵢ + h_s·lᵢ (h_s = 14.6 mm, 13 % of L), where the released rotation sits, so its
/// pivots lie 10 mm further in (radius 37.6 mm, not 47.9 mm) at the end of a longer cantilever —
/// the next test moves the model's pivots there and the gap closes to 0.1 %. Band: measured ± 2 %.
#[test]
fn stage_with_released_hinges_matches_in_z() {
    let x = cross_check(0.0);
    let y = cross_check(1e-1);
    let r = ratios(&x, &y.c_fe);
    eprintln!("released: model/FE = {r:.5?}");
    assert!((r[2] - 1.0).abs() < 1e-5, "z: model/FE = {}", r[2]);
    within_2_percent(&r, [(0, 0.3505), (1, 0.3505), (3, 0.3514), (4, 0.3514), (5, 0.3504)]);
}

/// The bundled case cases/prs_stiffness_ruiz2019_stage.json is this cross-check's rigid-body
/// model: the stage's layout (a, b, L, γ, home height) and the chain stiffnesses derived above,
/// to 1e-12 relative.
#[test]
fn bundled_stage_case_holds_the_derived_chains() {
    let x = cross_check(0.0);
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/cases/prs_stiffness_ruiz2019_stage.json");
    let v: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let close = |got: &serde_json::Value, want: f64, what: &str| {
        let g = got.as_f64().unwrap_or(f64::NAN);
        assert!(
            (g - want).abs() <= 1e-12 * want.abs().max(1.0),
            "{what}: case {g}, derived {want}"
        );
    };
    let (a, b, l, gamma_deg, z0) = x.layout;
    close(&v["mechanism"]["a"], a, "a");
    close(&v["mechanism"]["b"], b, "b");
    close(&v["mechanism"]["L"], l, "L");
    close(&v["mechanism"]["gamma_deg"], gamma_deg, "gamma_deg");
    close(&v["poses"][0]["pz"], z0, "pz");
    for k in 0..3 {
        close(&v["legs"]["actuation"][k], x.actuation[k], "actuation");
        close(&v["legs"]["constraint"][k], x.constraint[k], "constraint");
    }
}

/// The released FE against the rigid-body model with its spherical centres where the FE platform
/// attaches, at the neck tops Bᵢ + h_s·lᵢ (platform radius 37.6 mm instead of b = 47.91 mm, leg
/// 123.8 mm instead of L, compliance taken at the FE platform node): all six directions agree to
/// 0.11 % (measured: x, y, rx, ry 1.0010; z 1.00000; rz 1.0006). So the released-FE gap above is
/// the pivot geometry (the FE's spherical joint turns at the neck top, not at its centre), and
/// what remains (≤ 0.11 %) is what the scalar chains drop: the off-diagonal terms of the segment
/// compliances and their compliance along nᵢ. Against the real FE (hinges not released) the same
/// model is 6.44× (x, y, rx, ry) and 4.02× (rz) more compliant: the hinges' rotational stiffness
/// dominates the constraint directions of this stage; z stays within 0.05 %. Bands: < 0.2 % for the
/// released comparison; the measured ratios ± 2 % for the real one.
#[test]
fn neck_top_model_matches_released_fe_in_all_directions() {
    let x = cross_check_at(0.0, true);
    let released = ratios(&x, &cross_check_at(1e-1, true).c_fe);
    let real = ratios(&x, &x.c_fe);
    eprintln!("neck-top model / released FE: {released:.5?}; / FE: {real:.5?}");
    for (i, r) in released.iter().enumerate() {
        assert!((r - 1.0).abs() < 2e-3, "direction {i}: model/released FE = {r}");
    }
    assert!((real[2] - 1.0).abs() < 1e-3, "z: {}", real[2]);
    within_2_percent(&real, [(0, 6.4365), (1, 6.4365), (3, 6.4375), (4, 6.4375), (5, 4.0245)]);
}
