//! Jacobian stiffness of 3-PRS mechanisms against the published examples and against
//! independent (finite-difference, energy) reconstructions.
//!
//! Sources:
//! - L. A. Khan, M. Rameez, K. Nazir, H. Liaquat, A. Raza, T. U. Islam, "Stiffness Analysis of 3-PRS
//!   Parallel Kinematic Mechanism", Technical Journal, University of Engineering and Technology
//!   (UET) Taxila — Table 1 and the maximum stiffness 156.448 at p_z = −0.59, ψ = −0.751, θ = −0.089.
//! - H. Nigatu, L. Jihao, K. Zhu, J. Zhang, H. Guo, G. Lu, D. Kim, "The Stiffness of 3-PRS PM Across
//!   Parasitic and Orientational Workspace" — Sprint Z3 geometry (Table III), Eqs. 2–8, 18–23,
//!   Tables I–II.
//! - X. Han, Y. Wang, J. Shi, "Stiffness Modeling of 3-PRS Mechanism" — Tables I–IV.

#[path = "common/references.rs"]
mod references;

use flexfem::kinematics::prs::{orientation, radial, revolute_axis};
use flexfem::kinematics::prs_stiffness::{
    map, parasitic_rate_coupling, scaled_eigen, stiffness_limited, Branch, Grid, LegModel, MapMetric, MomentSign,
    PrsLayout, PrsStiffness,
};
use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};
use references::han;

fn deg(x: f64) -> f64 {
    x.to_radians()
}

/// Khan et al. Table 1: a = 400, b = 200, l = 550 mm, actuators 30° inward-down, k = 19 500 N/mm.
fn khan() -> PrsStiffness {
    let layout = PrsLayout::new(400.0, 200.0, 550.0, deg(-30.0), Branch::Minus).unwrap();
    PrsStiffness::new(layout, LegModel::Actuator { k: 19_500.0 }).unwrap()
}

/// Khan et al. §III: the published maximum stiffness "156.448 kN/m" at p_z = −0.59 m, ψ = −0.751,
/// θ = −0.089. It follows (to 0.6 %) only under this reading: ψ, θ in radians, the Jacobian in SI
/// units (strokes and p_z in m, angles in rad — i.e. rotations scaled by ℓ = 1000 mm), k in N/mm,
/// so that k·λ_max comes out in kN/mm (printed "kN/m"). The independent reconstruction gives
/// k·λ_max = 155.49 kN/mm; we match it to 0.01 %. Other readings are far off (degrees: 127.05).
#[test]
fn khan_maximum_stiffness_reading() {
    let m = khan();
    let ps = m.at(-590.0, -0.751, -0.089, &Vector3::zeros()).unwrap();
    let e = scaled_eigen(&ps.independent, 1, 1000.0);
    let kmax_kn_per_mm = e.values[2] / 1000.0;
    assert!(
        (kmax_kn_per_mm / 155.49 - 1.0).abs() < 1e-4,
        "k·λ_max = {kmax_kn_per_mm} kN/mm"
    );
    // The printed 156.448 is 0.6 % above: within 0.7 %, not within 0.5 %.
    let dev = kmax_kn_per_mm / 156.448 - 1.0;
    assert!(dev < -0.005 && dev > -0.007, "deviation from the paper {dev}");
    // Degrees reading of ψ, θ: 127.05 kN/mm, nowhere near the paper.
    let ps_deg = m.at(-590.0, deg(-0.751), deg(-0.089), &Vector3::zeros()).unwrap();
    let kd = scaled_eigen(&ps_deg.independent, 1, 1000.0).values[2] / 1000.0;
    assert!((kd - 127.05).abs() < 0.01, "degree reading {kd}");
    // Millimetre units for the rotation columns (ℓ = 1 mm) give a meaningless 2.0e6 kN/mm.
    let kmm = scaled_eigen(&ps.independent, 1, 1.0).values[2] / 1000.0;
    assert!(kmm > 1e6);
}

/// Strokes by the IKP at (p_z, ψ, θ).
fn strokes(m: &PrsStiffness, q: [f64; 3]) -> Vector3<f64> {
    let st = m.layout.pose(q[0], q[1], q[2]).unwrap();
    Vector3::from(st.s)
}

/// Fourth-order central differences of the IKP strokes.
fn fd_jacobian(m: &PrsStiffness, q: [f64; 3]) -> Matrix3<f64> {
    let mut j = Matrix3::zeros();
    for k in 0..3 {
        let h = 1e-4;
        let at = |t: f64| {
            let mut qq = q;
            qq[k] += t;
            strokes(m, qq)
        };
        let col = (-at(2.0 * h) + 8.0 * at(h) - 8.0 * at(-h) + at(-2.0 * h)) / (12.0 * h);
        j.set_column(k, &col);
    }
    j
}

fn layouts() -> Vec<(PrsLayout, f64)> {
    // (layout, a reachable p_z): Khan et al. (inward-down, platform below), Nigatu et al. vertical
    // rails, a horizontal layout, an upward-inclined one, and the other IKP branch.
    vec![
        (
            PrsLayout::new(400.0, 200.0, 550.0, deg(-30.0), Branch::Minus).unwrap(),
            -590.0,
        ),
        (
            PrsLayout::new(326.923, 250.0, 500.0, deg(90.0), Branch::Minus).unwrap(),
            250.0,
        ),
        (
            PrsLayout::new(470.0, 315.0, 185.0, deg(-90.0), Branch::Minus).unwrap(),
            -400.0,
        ),
        (PrsLayout::new(157.0, 47.91, 109.215, 0.0, Branch::Minus).unwrap(), 77.2),
        (
            PrsLayout::new(300.0, 120.0, 250.0, deg(35.0), Branch::Minus).unwrap(),
            250.0,
        ),
        (
            PrsLayout::new(400.0, 200.0, 550.0, deg(-30.0), Branch::Plus).unwrap(),
            -590.0,
        ),
    ]
}

/// Khan et al. Eqs. 15, 19–30: the actuation Jacobian is the derivative of the IKP; ours (analytic,
/// G_aᵀ·T) agrees with fourth-order finite differences of the IKP to 1e-7 (relative to max(1, |J|)).
#[test]
fn actuation_jacobian_matches_ikp_differences() {
    for (layout, pz) in layouts() {
        let m = PrsStiffness::new(layout, LegModel::Actuator { k: 1.0 }).unwrap();
        for (psi, theta) in [(0.0, 0.0), (0.1, -0.05), (-0.2, 0.15), (-0.751 * 0.3, -0.089)] {
            let q = [pz, psi, theta];
            let ps = m.at(q[0], q[1], q[2], &Vector3::zeros()).unwrap();
            let fd = fd_jacobian(&m, q);
            // zip-checked: two Matrix3<f64>.
            for (a, b) in ps.jacobian.iter().zip(fd.iter()) {
                assert!(
                    (a - b).abs() <= 1e-7 * a.abs().max(1.0),
                    "γ = {}: {a} vs {b}",
                    layout.gamma
                );
            }
        }
    }
}

/// The constraint block of Gᵀ·T vanishes (the parasitic twist respects the constraints), and the
/// twist map matches finite differences of the closed-form pose.
#[test]
fn twist_map_respects_constraints_and_matches_pose_differences() {
    for (layout, pz) in layouts() {
        let st = layout.pose(pz, 0.2, -0.3).unwrap();
        let g = layout.wrench_matrix(&st, &st.p()).unwrap();
        let t = layout.twist_map(&st);
        let gt = g.transpose() * t;
        for r in 3..6 {
            for c in 0..3 {
                assert!(
                    gt[(r, c)].abs() < 1e-12 * layout.b,
                    "constraint row {r}: {}",
                    gt[(r, c)]
                );
            }
        }
        let fd = fd_twist(&layout, [pz, 0.2, -0.3]);
        // zip-checked: two Matrix6x3<f64>.
        for (a, b) in t.iter().zip(fd.iter()) {
            assert!((a - b).abs() <= 1e-7 * a.abs().max(1.0), "{a} vs {b}");
        }
    }
}

/// Twist [v; ω] per unit (p_z, ψ, θ) by central differences of the closed-form pose.
fn fd_twist(layout: &PrsLayout, q: [f64; 3]) -> nalgebra::Matrix6x3<f64> {
    let mut out = nalgebra::Matrix6x3::zeros();
    let h = 1e-5;
    for k in 0..3 {
        let mut qp = q;
        let mut qm = q;
        qp[k] += h;
        qm[k] -= h;
        let (sp, sm) = (
            layout.pose(qp[0], qp[1], qp[2]).unwrap(),
            layout.pose(qm[0], qm[1], qm[2]).unwrap(),
        );
        let v = (sp.p() - sm.p()) / (2.0 * h);
        let w = sp.r * sm.r.transpose();
        let om = Vector3::new(w[(2, 1)] - w[(1, 2)], w[(0, 2)] - w[(2, 0)], w[(1, 0)] - w[(0, 1)]) / (4.0 * h);
        for j in 0..3 {
            out[(j, k)] = v[j];
            out[(j + 3, k)] = om[j];
        }
    }
    out
}

/// Nigatu et al. Table III: the Sprint Z3, vertical rails, r_b = 326.923 mm, r_a = 250 mm. The leg
/// length is not published; 500 mm is our reading (the parasitic motion does not depend on it; with
/// 300 mm a singularity of the actuation Jacobian lies inside ±40°, near ψ = ±40°, θ = −30°).
fn sprint() -> PrsLayout {
    PrsLayout::new(326.923, 250.0, 500.0, deg(90.0), Branch::Minus).unwrap()
}

/// An FKP that does not use the closed-form parasitic motion: Newton on all six pose coordinates
/// (x, y, z, ψ, θ, φ) with the three leg lengths and the three leg-plane constraints mᵢ·Bᵢ = 0.
fn fkp6(layout: &PrsLayout, s: [f64; 3], start: [f64; 6]) -> [f64; 6] {
    let res = |x: &[f64; 6]| {
        let r = orientation(x[3], x[4], x[5]);
        let p = Vector3::new(x[0], x[1], x[2]);
        let mut f = Vector6::zeros();
        for i in 0..3 {
            let b = p + r * (layout.b * radial(i));
            let c = layout.a * radial(i) + s[i] * layout.e(i);
            f[i] = ((b - c).norm_squared() - layout.l * layout.l) / (2.0 * layout.l);
            f[i + 3] = revolute_axis(i).dot(&b);
        }
        f
    };
    let mut x = start;
    for _ in 0..60 {
        let f = res(&x);
        if f.norm() < 1e-12 {
            break;
        }
        let mut j = Matrix6::zeros();
        for k in 0..6 {
            let h = 1e-7 * (1.0 + x[k].abs());
            let (mut xp, mut xm) = (x, x);
            xp[k] += h;
            xm[k] -= h;
            j.set_column(k, &((res(&xp) - res(&xm)) / (2.0 * h)));
        }
        let dx = j.lu().solve(&(-f)).expect("FKP Jacobian singular");
        for k in 0..6 {
            x[k] += dx[k];
        }
    }
    assert!(res(&x).norm() < 1e-11, "FKP did not converge: {}", res(&x).norm());
    x
}

/// Nigatu et al. Fig. 3 (parasitic x, y over ±40°): the closed form pₓ = (b/2)(uₓ − v_y),
/// p_y = −b·u_y, φ = atan2(sψsθ, cψ + cθ) agrees with the six-coordinate FKP to 1e-9 mm (and rad).
#[test]
fn sprint_parasitic_closed_form_matches_independent_fkp() {
    let layout = sprint();
    let pz = 250.0;
    let mut worst: f64 = 0.0;
    for ip in -4..=4 {
        for it in -4..=4 {
            let (psi, theta) = (deg(10.0 * ip as f64), deg(10.0 * it as f64));
            let st = layout.pose(pz, psi, theta).unwrap();
            // Continuation from home (where x = y = φ = 0) along the strokes of (tψ, tθ).
            let mut x = [0.0, 0.0, pz, 0.0, 0.0, 0.0];
            for step in 1..=40 {
                let t = step as f64 / 40.0;
                x = fkp6(&layout, layout.pose(pz, t * psi, t * theta).unwrap().s, x);
            }
            for (a, b) in [
                (x[0], st.px),
                (x[1], st.py),
                (x[2], pz),
                (x[3], psi),
                (x[4], theta),
                (x[5], st.phi),
            ] {
                worst = worst.max((a - b).abs());
            }
        }
    }
    assert!(worst < 1e-9, "closed form vs FKP: {worst:e}");
}

/// Nigatu et al. Eqs. 5–8: the velocity-level coupling [vₓ, v_y, ω_z] = C₁⁻¹C₂[ωₓ, ω_y]. With the
/// moment sign consistent with the position constraint (rᵢ × mᵢ) it equals finite differences of the
/// position-level parasitic motion to 1e-7; with the printed sign (mᵢ × rᵢ) it does not (errors of
/// the order of the coupling itself).
#[test]
fn sprint_velocity_coupling_sign() {
    let layout = sprint();
    for (psi, theta) in [(deg(20.0), deg(-30.0)), (deg(-35.0), deg(10.0)), (deg(40.0), deg(40.0))] {
        let st = layout.pose(250.0, psi, theta).unwrap();
        let tw = fd_twist(&layout, [250.0, psi, theta]);
        let ok = parasitic_rate_coupling(&layout, &st, MomentSign::Consistent).unwrap();
        let bad = parasitic_rate_coupling(&layout, &st, MomentSign::Printed).unwrap();
        for k in 1..3 {
            let om = nalgebra::Vector2::new(tw[(3, k)], tw[(4, k)]);
            let want = Vector3::new(tw[(0, k)], tw[(1, k)], tw[(5, k)]);
            let scale = want.norm().max(1e-3);
            let e_ok = (ok * om - want).norm();
            let e_bad = (bad * om - want).norm();
            assert!(e_ok < 1e-7 * scale.max(1.0), "consistent sign: error {e_ok}");
            assert!(
                e_bad > 0.1 * scale,
                "printed sign unexpectedly consistent: {e_bad} vs {scale}"
            );
        }
    }
}

/// Nigatu et al. Tables I–II as series chains (Eqs. 18–19): axial 3.8e7, 3.2e9, 976e6 N/m; torsional
/// 8.9e5 and 7.8e5 N·m/deg, read as a lateral stiffness at Bᵢ through the leg length (k_t/L²).
fn sprint_model() -> PrsStiffness {
    let l = 500.0;
    let nm_per_deg_to_lat = |k: f64| k * 1000.0 * 180.0 / std::f64::consts::PI / (l * l);
    PrsStiffness::new(
        sprint(),
        LegModel::Chain {
            actuation: vec![3.8e4, 3.2e6, 9.76e5],
            constraint: vec![nm_per_deg_to_lat(8.9e5), nm_per_deg_to_lat(7.8e5)],
        },
    )
    .unwrap()
}

/// For vertical rails the actuation wrenches have a unit z force and the constraint wrenches none,
/// so K_zz = 3·k_a at every pose (Nigatu et al. Eq. 23); checked over the ±40° map to 1e-12.
#[test]
fn sprint_kzz_is_three_ka_everywhere() {
    let m = sprint_model();
    let ka = 1.0 / (1.0 / 3.8e4 + 1.0 / 3.2e6 + 1.0 / 9.76e5);
    let grid = Grid {
        pz: 250.0,
        psi: [deg(-40.0), deg(40.0)],
        theta: [deg(-40.0), deg(40.0)],
        n: 21,
    };
    let cells = map(
        &m,
        &grid,
        &Vector3::zeros(),
        &[MapMetric::Diagonal(2), MapMetric::LambdaMin],
        1000.0,
    )
    .unwrap();
    assert_eq!(cells.len(), 441);
    for c in &cells {
        assert!(c.ok);
        let kzz = c.values[0].unwrap();
        assert!(
            (kzz / (3.0 * ka) - 1.0).abs() < 1e-12,
            "K_zz = {kzz} at ψ = {}, θ = {}",
            c.psi,
            c.theta
        );
    }
    // The stiffness-limited workspace keeps the centre and loses cells as the threshold rises.
    let (_, all) = stiffness_limited(&cells, 1, 0.0);
    assert_eq!(all, 1.0);
    // λ_min (ℓ = 1 m) is largest at the untilted centre (Nigatu et al. Figs. 4–9: stiffness peaks at
    // zero orientation): a threshold just below it keeps only the centre cell.
    let centre = cells[220].values[1].unwrap();
    let (mask, frac) = stiffness_limited(&cells, 1, 0.999 * centre);
    assert!(mask[220], "the centre cell must pass");
    assert_eq!(
        mask.iter().filter(|&&b| b).count(),
        1,
        "only the centre cell, fraction {frac}"
    );
    let (_, half) = stiffness_limited(&cells, 1, 0.5 * centre);
    assert!(half > 1.0 / 441.0 && half < 1.0, "half-threshold fraction {half}");
}

// Han et al. Tables I–III (`references::han`). Readings we had to choose (not published): vertical rails with the
// platform hanging below the revolutes (γ = −90°), the screw fixed–fixed over its 600 mm with the
// first bearing at the zero-stroke point Aᵢ (at p_z = −400 mm the nut is then 299 mm from it, the
// "poorest posture" a = b of the paper), the load applied at P, I_y = 8.64e6 mm⁴ as the
// out-of-plane (constraint) bending, no nut or joint compliance, (α, β) = (0, β) read as ψ = 0,
// θ = β.

/// Platform compliance from the energy of the leg springs, with the leg deflections differentiated
/// numerically from the exact geometry (no wrench matrix): δsᵢ from the leg equation with Bᵢ projected
/// into its plane, δcᵢ = mᵢ·Bᵢ.
fn energy_compliance(m: &PrsStiffness, pz: f64, psi: f64, theta: f64, cl: &[f64; 6]) -> Matrix6<f64> {
    let lay = m.layout;
    let st = lay.pose(pz, psi, theta).unwrap();
    let defl = |x: &Vector6<f64>| {
        let rot = nalgebra::Rotation3::new(Vector3::new(x[3], x[4], x[5])).into_inner() * st.r;
        let p = st.p() + Vector3::new(x[0], x[1], x[2]);
        let mut q = Vector6::zeros();
        for i in 0..3 {
            let b = p + rot * (lay.b * radial(i));
            let mi = revolute_axis(i);
            let bp = b - mi * mi.dot(&b);
            let dv = bp - lay.a * radial(i);
            let e = lay.e(i);
            let ed = e.dot(&dv);
            let s = ed - (ed * ed - dv.norm_squared() + lay.l * lay.l).sqrt();
            q[i] = s - st.s[i];
            q[i + 3] = mi.dot(&b);
        }
        q
    };
    let mut jq = Matrix6::zeros();
    for k in 0..6 {
        let h = 1e-6;
        let mut xp = Vector6::zeros();
        xp[k] = h;
        jq.set_column(k, &((defl(&xp) - defl(&(-xp))) / (2.0 * h)));
    }
    let kd = Matrix6::from_diagonal(&Vector6::from_iterator(cl.iter().map(|c| 1.0 / c)));
    (jq.transpose() * kd * jq).try_inverse().unwrap()
}

/// Han et al. Table IV: F = [100, 50, 50] kN in the platform frame at z = −400 mm, β = 0/5/10°. Our
/// deformation |δp| beside the paper's analytic 0.25/0.47/0.69 mm and FEA 0.21/0.42/0.61 mm. The
/// paper's numbers cannot be derived from its published inputs (missing: actuator/rail direction,
/// screw bearing positions relative to the stroke, tool length (load point), which bending inertia
/// is out of plane, the meaning of precession/nutation, nut and joint stiffness); under our readings
/// the deformation is 0.109/0.105/0.101 mm (I_y out of plane) or 0.353/0.353/0.356 mm (I_z out of
/// plane): nowhere near the paper's near-tripling from β = 0° to 10°. Checked here: the
/// wrench-matrix compliance equals the energy (finite-difference) compliance to 1e-6, the screw
/// stiffness at β = 0 equals A·E·L/(a·b) with a = 299.0 mm, and the values are pinned.
#[test]
fn han_deformation_table_iv() {
    let m = han(8.64e6);
    let f_body = Vector3::new(100e3, 50e3, 50e3);
    let mut out = Vec::new();
    for beta in [0.0, 5.0, 10.0] {
        let ps = m.at(-400.0, 0.0, deg(beta), &Vector3::zeros()).unwrap();
        let f = ps.state.r * f_body;
        let w = Vector6::new(f[0], f[1], f[2], 0.0, 0.0, 0.0);
        let d = ps.deformation(&w);
        let ce = energy_compliance(&m, -400.0, 0.0, deg(beta), &ps.leg_compliance);
        let de = ce * w;
        assert!((d - de).norm() < 1e-6 * de.norm(), "β = {beta}: {d} vs {de}");
        let k = ps.stiffness.unwrap();
        let ke = ce.try_inverse().unwrap();
        assert!((k - ke).norm() < 1e-6 * ke.norm(), "β = {beta}: K differs");
        out.push(d.fixed_rows::<3>(0).norm());
        if beta == 0.0 {
            let a = ps.state.s[0];
            assert!((a - (400.0 - (185f64.powi(2) - 155f64.powi(2)).sqrt())).abs() < 1e-9);
            let ks = 183.5 * 231_000.0 * 600.0 / (a * (600.0 - a));
            let le = ps.state.legs[0].dot(&m.layout.e(0));
            let ca = 1.0 / ks + 185.0 / (210_000.0 * 7200.0) / (le * le);
            assert!((ps.leg_compliance[0] / ca - 1.0).abs() < 1e-12);
        }
    }
    eprintln!("Han et al. Table IV, our deformation |δp| at P: {out:?} mm (paper 0.25/0.47/0.69 analytic, 0.21/0.42/0.61 FEA)");
    assert_eq!(out.len(), PIN_HAN.len());
    for (a, b) in out.iter().zip(PIN_HAN) {
        assert!((a / b - 1.0).abs() < 1e-6, "{a} vs pinned {b}");
    }
    // The other reading of the bending inertia (I_z = 2.16e6 mm⁴ out of plane).
    let mz = han(2.16e6);
    let other: Vec<f64> = [0.0, 5.0, 10.0]
        .iter()
        .map(|&beta| {
            let ps = mz.at(-400.0, 0.0, deg(beta), &Vector3::zeros()).unwrap();
            let f = ps.state.r * f_body;
            ps.deformation(&Vector6::new(f[0], f[1], f[2], 0.0, 0.0, 0.0))
                .fixed_rows::<3>(0)
                .norm()
        })
        .collect();
    eprintln!("with I_z = 2.16e6 mm⁴ out of plane: {other:?} mm");
    assert_eq!(other.len(), PIN_HAN_IZ.len());
    for (a, b) in other.iter().zip(PIN_HAN_IZ) {
        assert!((a / b - 1.0).abs() < 1e-6, "{a} vs pinned {b}");
    }
}

/// The same with I_z = 2.16e6 mm⁴ as the out-of-plane inertia.
const PIN_HAN_IZ: [f64; 3] = [0.35299517204290703, 0.35343316604005526, 0.3564104007047643];

/// Our Han et al. deformations (mm) for β = 0, 5, 10° under the readings of `han`.
const PIN_HAN: [f64; 3] = [0.10885477998706646, 0.10503016898976353, 0.10109718806903639];

/// The stiffness about a tool point Q = P + R·t is the rigid-body transfer of the one about P
/// (Nigatu et al. §VI: "adjusted through the 6×6 adjoint"): a wrench [f; m] at Q is [f; m + r × f]
/// at P, and the twist at Q is [δp_P + δα × r; δα], r = Q − P.
#[test]
fn tool_point_compliance_is_the_rigid_transfer_of_the_centre_one() {
    let m = han(8.64e6);
    let tool = Vector3::new(20.0, -35.0, -150.0);
    let (pz, psi, theta) = (-400.0, deg(3.0), deg(7.0));
    let at_p = m.at(pz, psi, theta, &Vector3::zeros()).unwrap();
    let at_q = m.at(pz, psi, theta, &tool).unwrap();
    let r = at_q.point - at_p.state.p();
    assert!((r - at_p.state.r * tool).norm() < 1e-12);
    let (f, mq) = (Vector3::new(1e3, -2e3, 5e3), Vector3::new(3e4, 1e4, -2e4));
    let wp = Vector6::from_iterator(f.iter().chain((mq + r.cross(&f)).iter()).copied());
    let dp = at_p.deformation(&wp);
    let da = Vector3::new(dp[3], dp[4], dp[5]);
    let want = Vector3::new(dp[0], dp[1], dp[2]) + da.cross(&r);
    let dq = at_q.deformation(&Vector6::from_iterator(f.iter().chain(mq.iter()).copied()));
    assert!((Vector3::new(dq[0], dq[1], dq[2]) - want).norm() < 1e-9 * want.norm());
    assert!((Vector3::new(dq[3], dq[4], dq[5]) - da).norm() < 1e-9 * da.norm());
    // The actuation Jacobian does not depend on the reference point.
    assert!((at_q.jacobian - at_p.jacobian).norm() < 1e-12 * at_p.jacobian.norm());
}
