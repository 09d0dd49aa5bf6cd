//! Per-step tracking along a nonlinear path (`NonlinearOptions::step_track`) on the classic
//! parallel leaf-spring guide: two identical leaves (length L, thickness t along the motion,
//! width b) clamped at one end and joined at the other by a rigid bar carrying a point mass;
//! the bar is moved transversely (along the leaves' thickness) by up to ±20 % of L.
//!
//! References:
//! * Support stiffness (along the leaves, with the stroke held): S. Awtar, A. H. Slocum,
//!   E. Sevincer, "Characteristics of beam-based flexure modules", J. Mech. Des. 129(6) (2007)
//!   625–639, beam constraint model: a clamped–guided beam with transverse end displacement y
//!   (normalised by L) and axial force p (normalised by EI/L²) has the axial end displacement
//!   x = p/d − (3/5)·y² + (1/700)·p·y² (d = AL²/I), so its axial compliance at fixed y is
//!   L/(EA) + L·δ²/(700·EI) (δ = yL, the elastokinematic term). In the parallelogram the two
//!   leaves share the axial load, so k_x(δ) = 1 / (L/(2EA) + L·δ²/(1400·EI)), and for a
//!   rectangular leaf k_x(δ)/k_x(0) = 1 / (1 + 12·δ²/(700·t²)). (The 1/700 checked here by
//!   hand: with w₀ = δ(3ξ² − 2ξ³) and the first-order tension correction w₁, ∂s/∂p =
//!   −∫(w₁″)² dξ = −δ²/700 for the shortening s = ½∫w′².)
//! * First frequency at zero stroke: two clamped–guided leaves in parallel have the lateral
//!   stiffness 2·12EI/L³ = 24EI/L³ (e.g. W. C. Young, R. G. Budynas, Roark's Formulas for
//!   Stress and Strain, 7th ed., Table 8.1 case 1e); in series with it the bar tilts: the
//!   leaves' end moments, F·L/2 in all, are carried by an axial force couple of the leaves
//!   (rotational stiffness EA·W²/(2L) for leaves W apart), and a tilt θ adds θ·L/2 to the
//!   motion, so 1/k = L³/(24EI) + L³/(2·EA·W²) (+0.06 % here). With the bar mass m and the
//!   leaves' mass m_l moving in the static deflection shape (kinetic-energy share
//!   ∫(3ξ² − 2ξ³)²dξ = 13/35 per leaf), Rayleigh's quotient gives f = √(k/(m + 2·(13/35)·m_l))/2π,
//!   an upper bound exceeding the exact value by O((m_l/m)²), here ~1e-4 relative.

use flexfem::fem::{
    self, Beam, Dof, LoadCase, Model, NonlinearCase, NonlinearOptions, PointMass, RigidLink, Section, StepTrack,
    Support,
};
use flexfem::material::Material;

const L: f64 = 50.0;
const T: f64 = 0.5;
const B: f64 = 10.0;
const W: f64 = 20.0;
const E: f64 = 210_000.0;
const RHO: f64 = 7.85e-9;
const M_BAR: f64 = 5e-5;
const N_EL: usize = 10;

/// The guide: leaves along x at y = 0 and y = W, the bar at x = L with its centre node
/// (returned) the master of the leaf ends.
fn guide(cases: Vec<LoadCase>) -> (Model, usize) {
    let mat = Material {
        e: E,
        nu: 0.3,
        density: RHO,
        yield_strength: 1e9,
        allowable: 1e9,
        fatigue: None,
    };
    let mut m = Model::new();
    let mut ends = Vec::new();
    for y in [0.0, W] {
        let first = m.add_node([0.0, y, 0.0]);
        m.supports.push(Support::clamp(first));
        let mut prev = first;
        for i in 1..=N_EL {
            let n = m.add_node([L * i as f64 / N_EL as f64, y, 0.0]);
            m.add_beam(Beam::new(prev, n, Section::Rect { w: T, h: B }, mat, [0.0, 0.0, 1.0]).euler_bernoulli());
            prev = n;
        }
        ends.push(prev);
    }
    let c = m.add_node([L, W / 2.0, 0.0]);
    m.rigid_links.push(RigidLink {
        master: c,
        slaves: ends,
    });
    m.masses.push(PointMass {
        node: c,
        mass: M_BAR,
        inertia: [1e-3, 1e-3, 1e-3],
    });
    m.load_cases = cases;
    (m, c)
}

fn track(model: &Model, c: usize, modes: usize, steps: usize) -> Vec<NonlinearCase> {
    let opts = NonlinearOptions {
        steps,
        track: vec![fem::NodeDof { node: c, dof: Dof::Uy }],
        step_track: StepTrack {
            modes,
            compliance: vec![c],
        },
        ..Default::default()
    };
    fem::solve_nonlinear(model, &opts).expect("solves").load_cases
}

#[test]
fn support_stiffness_drop_matches_the_beam_constraint_model() {
    let stroke = 0.2 * L;
    let (model, c) = {
        let (m, c) = guide(vec![]);
        let cases = [stroke, -stroke]
            .iter()
            .map(|s| LoadCase::new(format!("stroke {s}")).displacement(c, Dof::Uy, *s))
            .collect();
        let mut m = m;
        m.load_cases = cases;
        (m, c)
    };
    let cases = track(&model, c, 3, 20);
    let (a, i) = (B * T, B * T.powi(3) / 12.0);
    let k0 = 2.0 * E * a / L;
    let mut worst: f64 = 0.0;
    for case in &cases {
        assert_eq!(case.step_quantities.len(), case.path.len());
        for q in &case.step_quantities {
            let delta = case.path[q.point].values[0];
            let kx = 1.0 / q.compliance[0][0][0];
            // Awtar et al. (2007): k_x(δ) = 1/(L/(2EA) + Lδ²/(1400EI)).
            let awtar = 1.0 / (L / (2.0 * E * a) + L * delta * delta / (1400.0 * E * i));
            let err = (kx / awtar - 1.0).abs();
            worst = worst.max(err);
            let f = q.frequencies_hz();
            println!(
                "δ = {delta:7.3} mm  k_x = {kx:10.1} N/mm  Awtar {awtar:10.1}  ratio {:.4} (closed form {:.4})  f = {:.1} {:.1} {:.1} Hz",
                kx / k0,
                awtar / k0,
                f[0],
                f[1],
                f[2]
            );
            if q.lambda == 0.0 {
                // Zero stroke: both leaves in pure tension/compression, k = 2EA/L exactly.
                assert!((kx / k0 - 1.0).abs() < 1e-6, "k_x(0) = {kx}, 2EA/L = {k0}");
            }
            // The motion DOF is held: its row of the compliance is zero.
            assert_eq!(q.compliance[0][1][1], 0.0);
        }
        // Path end at the full stroke: the stiffness has dropped to ~13 % of 2EA/L.
        let last = case.step_quantities.last().unwrap();
        assert_eq!(last.lambda, 1.0);
        let ratio = 1.0 / last.compliance[0][0][0] / k0;
        let closed = 1.0 / (1.0 + 12.0 * stroke * stroke / (700.0 * T * T));
        assert!(ratio < 0.2, "ratio {ratio}");
        assert!((ratio / closed - 1.0).abs() < 0.05, "ratio {ratio} vs {closed}");
    }
    // Within 5 % of the beam constraint model over the whole stroke ±0.2 L.
    assert!(worst < 0.05, "largest deviation from Awtar et al. (2007): {worst}");
    println!("largest deviation from Awtar et al. (2007): {:.3} %", 100.0 * worst);
}

#[test]
fn first_frequency_at_zero_stroke_matches_rayleigh() {
    let (mut model, c) = guide(vec![]);
    // Force-driven (motion DOF free): the first mode is the lateral motion of the bar.
    let f_y = 24.0 * E * (B * T.powi(3) / 12.0) / L.powi(3) * 0.2 * L;
    model.load_cases = vec![LoadCase::new("push").force(c, [0.0, f_y, 0.0, 0.0, 0.0, 0.0])];
    let cases = track(&model, c, 2, 10);
    let q0 = &cases[0].step_quantities[0];
    assert_eq!(q0.lambda, 0.0);
    let i = B * T.powi(3) / 12.0;
    let a = B * T;
    let k = 1.0 / (L.powi(3) / (24.0 * E * i) + L.powi(3) / (2.0 * E * a * W * W));
    let m_leaf = RHO * B * T * L;
    let f = (k / (M_BAR + 2.0 * 13.0 / 35.0 * m_leaf)).sqrt() / (2.0 * std::f64::consts::PI);
    let fe = q0.frequencies_hz()[0];
    println!("f1(0) = {fe:.4} Hz, Rayleigh {f:.4} Hz ({:+.2e})", fe / f - 1.0);
    // Measured −8.8e-6.
    assert!((fe / f - 1.0).abs() < 2.5e-5, "f1 = {fe} Hz, closed form {f} Hz");
    // Lateral compliance at zero stroke: 1/k (Euler–Bernoulli leaves: exact).
    let cyy = q0.compliance[0][1][1];
    assert!((cyy * k - 1.0).abs() < 1e-6, "C_yy = {cyy}, closed form {}", 1.0 / k);
    for q in &cases[0].step_quantities {
        println!(
            "λ = {:.3}  uy = {:.3} mm  f = {:?} Hz  k_x = {:.1} N/mm",
            q.lambda,
            cases[0].path[q.point].values[0],
            q.frequencies_hz(),
            1.0 / q.compliance[0][0][0]
        );
    }
}
