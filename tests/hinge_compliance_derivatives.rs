//! Analytic derivatives of the hinge compliance (`flexfem::hinge::tangent`: forward-mode dual
//! numbers through the flexibility integrals, the piece limits and the solid-calibration
//! factors) against sixth-order central differences of the compliance itself, for every hinge
//! family and every dimension, E and ν.

use flexfem::hinge::tangent::{
    half_notch_derivative, region_compliance_derivatives, segment_compliance_derivative, vlasov_compliance_derivative,
    Tangent,
};
use flexfem::hinge::{chain_compliances, profile_stiffness, segment_compliance, HingeSpec, Profile};
use flexfem::material::Material;
use nalgebra::Matrix6;

mod common;
use common::fixtures;

/// Sixth-order central difference [−1, 9, −45, 45, −9, 1]/(60 δ).
const STENCIL: [(f64, f64); 6] = [
    (-3.0, -1.0),
    (-2.0, 9.0),
    (-1.0, -45.0),
    (1.0, 45.0),
    (2.0, -9.0),
    (3.0, 1.0),
];

/// The hinge `spec` with material `m`, moved by `s` along dimension `key` (a contour dimension,
/// `w`, `h`, `blank`, `E` or `nu`).
fn moved(spec: &HingeSpec, m: &Material, key: &str, s: f64) -> (Profile, Material) {
    let (mut w, mut h, mut blank) = spec.blank();
    let mut c = spec.contour();
    let mut mat = *m;
    match key {
        "w" => w += s,
        "h" => h += s,
        "blank" => blank += s,
        "E" => mat.e += s,
        "nu" => mat.nu += s,
        k => *c.number_mut(k).expect("a contour dimension") += s,
    }
    (HingeSpec::in_blank(c, w, h, blank).profile().expect("valid"), mat)
}

/// The unit tangent along `key`.
fn unit(spec: &HingeSpec, key: &str) -> Tangent {
    let mut t = Tangent::zero(&spec.contour());
    match key {
        "w" => t.w = 1.0,
        "h" => t.h = 1.0,
        "blank" => t.blank = 1.0,
        "E" => t.e = 1.0,
        "nu" => t.nu = 1.0,
        k => *t.contour.number_mut(k).expect("a contour dimension") = 1.0,
    }
    t
}

/// The keys every family of `spec` has.
fn keys(spec: &HingeSpec) -> Vec<&'static str> {
    let mut c = spec.contour();
    let mut k: Vec<&'static str> = ["R", "t", "l", "ax", "ay"]
        .into_iter()
        .filter(|k| c.number_mut(k).is_some())
        .collect();
    if !matches!(spec, HingeSpec::SphericalNeck { .. }) {
        k.push("w");
    }
    k.extend(["h", "blank", "E", "nu"]);
    k
}

/// Largest error of `analytic` against `fd` over the entries, relative to each entry's
/// derivative scale √(|dC_ii dC_jj|) (the relative error of each diagonal term), at least
/// 1e-4 √(C_ii C_jj)/x (`c` the compliance, `x` the dimension's size): entries that do not
/// depend on the dimension (the axial compliance on ν) are compared with that floor, not with
/// the round-off of their difference quotient.
fn worst(analytic: &Matrix6<f64>, fd: &Matrix6<f64>, c: &Matrix6<f64>, x: f64) -> f64 {
    let mut e = 0.0f64;
    for i in 0..6 {
        for j in 0..6 {
            let floor = 1e-4 * (c[(i, i)] * c[(j, j)]).abs().sqrt() / x;
            let scale = (fd[(i, i)] * fd[(j, j)]).abs().sqrt().max(floor);
            if scale > 0.0 {
                e = e.max((analytic[(i, j)] - fd[(i, j)]).abs() / scale);
            }
        }
    }
    e
}

/// The families of `fixtures::hinge_families` in 9 mm wide blanks (see inside) plus a thin
/// circular notch (t/R = 0.02) and a neck thin enough that its fillet meets the square's faces
/// and corners.
fn specs() -> Vec<HingeSpec> {
    // The stage's families, in a 9 mm wide blank instead of its 10 × 10 one: at w = h the
    // blank's plane-strain restraint (`solid_effects::blank_restraint`, which vanishes where the
    // effective thickness reaches the width) changes from a jump at the end of the spreading
    // zone (w > h) to a kink inside it (w < h), so the compliance's second derivative jumps
    // there and no central difference across it is a reference.
    let mut s: Vec<HingeSpec> = fixtures::hinge_families()
        .iter()
        .map(|f| {
            let (_, h, blank) = f.blank();
            HingeSpec::in_blank(f.contour(), 9.0, h, blank)
        })
        .collect();
    s.push(HingeSpec::CircularNotch {
        r: 5.0,
        t: 0.1,
        w: 10.0,
        h: 10.0,
        blank_length: 5.0,
    });
    s.push(HingeSpec::SphericalNeck {
        l: 1.0,
        t: 6.0,
        r: 2.0,
        h: 7.0,
        blank_length: 5.0,
    });
    s
}

#[test]
fn compliance_derivatives_match_central_differences_for_every_family() {
    // Reference: sixth-order central differences of the hinge compliance (the same
    // quadrature), step 3e-3 of the dimension (no profile breakpoint changes kind within the
    // stencil: the thin notch's cap t + 2R − h = 0.1 mm stays > 9δ). The analytic derivative
    // is the exact derivative of the same sum.
    let m = Material::AL7075;
    let mut largest = 0.0f64;
    let mut count = 0;
    let mut failures = 0;
    for spec in specs() {
        let p0 = spec.profile().unwrap();
        let half = p0.half_length();
        for key in keys(&spec) {
            let tg = unit(&spec, key);
            let dh = half_notch_derivative(&p0, &tg) + tg.blank;
            let (c, dc) = segment_compliance_derivative(&p0, &m, &tg, (-half, -dh), (half, dh));
            let exact = segment_compliance(&p0, &m, -half, half);
            assert!((c - exact).amax() <= 1e-12 * exact.amax(), "{spec:?}: value differs");
            let x0 = match key {
                "w" | "h" | "blank" => spec.blank().0.min(spec.blank().1),
                "E" => m.e,
                "nu" => 1.0,
                k => *spec.contour().number_mut(k).unwrap(),
            };
            let delta = 3e-3 * x0;
            let mut fd = Matrix6::zeros();
            for (s, w) in STENCIL {
                let (p, mm) = moved(&spec, &m, key, s * delta);
                let hh = p.half_length();
                fd += segment_compliance(&p, &mm, -hh, hh) * (w / (60.0 * delta));
            }
            let e = worst(&dc, &fd, &exact, x0);
            println!("{:?} d/d{key}: {e:e}", spec.contour());
            failures += usize::from(e >= 1e-8);
            largest = largest.max(e);
            count += 1;
        }
    }
    assert_eq!(count, 51, "every family and dimension checked");
    assert_eq!(failures, 0, "derivatives off by 1e-8 or more (listed above)");
    println!("largest relative error over {count} derivatives: {largest:e}");
}

#[test]
fn chain_compliance_derivatives_match_central_differences() {
    // The derivatives the direct method uses for a hinge element split into 4 segments
    // (`region_compliance_derivatives`, with the Vlasov torsion compliance differenced by
    // `vlasov_compliance_derivative`) against sixth-order central differences of
    // `chain_compliances`, which rescale the segments' torsion to the Vlasov compliance.
    let m = Material::AL7075;
    for spec in [fixtures::hinge_families()[0], fixtures::hinge_families()[4]] {
        let p0 = spec.profile().unwrap();
        let single = profile_stiffness(&p0, &m).unwrap();
        for key in ["t", "R"] {
            let tg = unit(&spec, key);
            let x0 = *spec.contour().number_mut(key).unwrap();
            let torsion = vlasov_compliance_derivative(&p0, &m, &tg, 1e-3 * x0).unwrap_or(0.0);
            let d = region_compliance_derivatives(&p0, &m, &single, &tg, torsion, 4);
            assert_eq!(d.len(), 4);
            let delta = 1e-3 * x0;
            let mut fd = vec![Matrix6::<f64>::zeros(); 4];
            for (s, w) in STENCIL {
                let (p, mm) = moved(&spec, &m, key, s * delta);
                let st = profile_stiffness(&p, &mm).unwrap();
                let cs = chain_compliances(&p, &mm, &st, 4);
                assert_eq!(cs.len(), fd.len());
                for (f, c) in fd.iter_mut().zip(&cs) {
                    *f += Matrix6::from_fn(|i, j| c[i][j]) * (w / (60.0 * delta));
                }
            }
            for (k, f) in fd.iter().enumerate() {
                let a = Matrix6::from_fn(|i, j| d[k][i][j]);
                let c = Matrix6::from_fn(|i, j| single.compliance[i][j]);
                let e = worst(&a, f, &c, x0);
                assert!(e < 1e-8, "{spec:?} segment {k} d/d{key}: relative error {e:e}");
                println!("{key} segment {k}: {e:e}");
            }
        }
    }
}
