//! Regression table of the hinge characterisation: 1,000 random designs of every hinge family
//! (5,000 in all, random materials too), each with every number of its [`HingeResult`], must
//! match the values the implementation produced before the section constants were made fast
//! (commit "tests: hinge reference table", the series evaluated term by term with `tanh` at
//! every quadrature point), within 1e-9 relative.
//!
//! Source of the reference: the program's own earlier output (a regression table, not an
//! accuracy claim — accuracy is asserted against published values in the other hinge tests).
//! Stored in `tests/data/hinge_reference_table.json` with 12 significant digits (rounding
//! ≤ 5e-12 relative, 200 times inside the tolerance); of each symmetric 6×6 compliance the upper
//! triangle (the lower one must equal it exactly). The designs come from a seeded SplitMix64
//! generator in this file; the table also stores each design, and the test checks that the
//! generator still reproduces them.
//!
//! Tolerance: |new − ref| ≤ 1e-9 · max(|ref|, floor). The floor is 0 for the stiffnesses,
//! stresses and closed forms (all well away from 0); for a compliance entry C_ij it is
//! 1e-3 · √(C_ii C_jj) — the entry's natural scale — so structurally zero entries must stay
//! below 1e-12 of that scale. The model notes (text with rounded numbers) are compared by a
//! 64-bit FNV-1a hash of their joined text: they must be identical.
//!
//! The table is written, never regenerated after an intended change of numbers, by
//! `FLEXFEM_WRITE_HINGE_REFERENCE=1 cargo test --release --test hinge_reference_table`.

use flexfem::hinge::{characterise, HingeResult, HingeSpec, Stiffness};
use flexfem::material::Material;
use serde_json::Value;
use std::path::PathBuf;

/// Designs per family.
const PER_FAMILY: usize = 1000;
/// Relative tolerance against the reference.
const REL: f64 = 1e-9;

fn table_path() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/hinge_reference_table.json")
}

#[path = "common/rng.rs"]
mod rng;
use rng::Rng;

/// Random parameters, rounded so the JSON of the table stays short and exact in decimal.
trait Draw {
    fn uniform4(&mut self, lo: f64, hi: f64) -> f64;
    fn log(&mut self, lo: f64, hi: f64) -> f64;
    fn chance(&mut self, p: f64) -> bool;
}

impl Draw for Rng {
    /// Uniform in [lo, hi], rounded to 4 decimals (short, exact-in-decimal JSON).
    fn uniform4(&mut self, lo: f64, hi: f64) -> f64 {
        round4(lo + (hi - lo) * self.unit())
    }
    /// Log-uniform in [lo, hi], rounded to 4 significant digits.
    fn log(&mut self, lo: f64, hi: f64) -> f64 {
        sig4((lo.ln() + (hi.ln() - lo.ln()) * self.unit()).exp())
    }
    /// True with probability p.
    fn chance(&mut self, p: f64) -> bool {
        self.unit() < p
    }
}

fn round4(x: f64) -> f64 {
    (x * 1e4).round() / 1e4
}

fn sig4(x: f64) -> f64 {
    let e = x.abs().log10().floor() as i32 - 3;
    let s = 10f64.powi(-e);
    (x * s).round() / s
}

/// One random design of family `fam` (0 circular, 1 elliptical, 2 corner-filleted, 3 leaf,
/// 4 spherical neck) over a wide box: thin and thick waists, notches capped by the blank and
/// notches that step up to it, no blank and long blanks, narrow and wide hinges.
fn design(rng: &mut Rng, fam: usize) -> (HingeSpec, Material) {
    let h = rng.log(1.0, 30.0);
    let t = sig4(h * rng.log(0.02, 0.9));
    let w = sig4(t * rng.log(0.3, 40.0));
    let blank_length = if rng.chance(0.2) {
        0.0
    } else {
        sig4(h * rng.log(0.01, 4.0))
    };
    let spec = match fam {
        0 => HingeSpec::CircularNotch {
            r: sig4(h * rng.log(0.05, 5.0)),
            t,
            w,
            h,
            blank_length,
        },
        1 => HingeSpec::EllipticalNotch {
            ax: sig4(h * rng.log(0.05, 5.0)),
            ay: sig4(h * rng.log(0.05, 5.0)),
            t,
            w,
            h,
            blank_length,
        },
        2 => {
            let l = sig4(h * rng.log(0.1, 5.0));
            HingeSpec::CornerFilleted {
                l,
                r: sig4(0.5 * l * rng.log(0.02, 1.0)),
                t,
                w,
                h,
                blank_length,
            }
        }
        3 => HingeSpec::Leaf {
            l: sig4(h * rng.log(0.05, 5.0)),
            t,
            w,
            h,
            blank_length,
        },
        _ => HingeSpec::SphericalNeck {
            l: if rng.chance(0.1) {
                0.0
            } else {
                sig4(t * rng.log(0.05, 6.0))
            },
            t: sig4(h * rng.log(0.05, 0.95)),
            r: sig4(t * rng.log(0.1, 4.0)),
            h,
            blank_length,
        },
    };
    let material = Material {
        e: rng.log(1e3, 3e5),
        nu: rng.uniform4(0.0, 0.45),
        density: 0.0,
        yield_strength: f64::INFINITY,
        allowable: rng.log(10.0, 1000.0),
        fatigue: None,
    };
    (spec, material)
}

/// The designs of the table: `PER_FAMILY` valid designs per family, in family order (designs
/// the hinge model refuses are drawn again).
fn designs() -> Vec<(HingeSpec, Material)> {
    let mut rng = Rng::new(0x5eed_2026_1124_0021);
    let mut out = Vec::with_capacity(5 * PER_FAMILY);
    for fam in 0..5 {
        let mut n = 0;
        while n < PER_FAMILY {
            let (s, m) = design(&mut rng, fam);
            if characterise(&s, &m).is_ok() {
                out.push((s, m));
                n += 1;
            }
        }
    }
    out
}

/// The numbers of one configuration, in a fixed order, each with its tolerance floor.
fn stiffness_numbers(s: &Stiffness, out: &mut Vec<(f64, f64)>) {
    for v in [s.k_bend, s.k_bend_off, s.k_torsion, s.k_axial] {
        out.push((v, 0.0));
    }
    let c = &s.compliance;
    for i in 0..6 {
        for j in i..6 {
            out.push((c[i][j], 1e-3 * (c[i][i] * c[j][j]).abs().sqrt()));
        }
    }
    // The lower triangle: C is symmetric (C_ji = C_ij exactly, as in the reference).
    for (i, row) in c.iter().enumerate() {
        for (j, v) in row.iter().enumerate().take(i) {
            assert_eq!(*v, c[j][i], "compliance not symmetric");
        }
    }
    for v in [s.stress_per_moment, s.max_rotation_deg, s.k_torsion_saint_venant] {
        out.push((v, 0.0));
    }
}

/// Every number of a result, in a fixed order, with its tolerance floor (module docs).
fn numbers(r: &HingeResult) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    stiffness_numbers(&r.hinge, &mut out);
    stiffness_numbers(&r.notch_only, &mut out);
    for v in r.closed_form.values() {
        out.push((*v, 0.0));
    }
    out.push((r.stress_concentration, 0.0));
    out
}

/// 64-bit FNV-1a of the model notes (each followed by a newline), as hex.
fn notes_hash(r: &HingeResult) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for note in &r.model {
        for b in note.bytes().chain([b'\n']) {
            h ^= u64::from(b);
            h = h.wrapping_mul(0x0000_0100_0000_01b3);
        }
    }
    format!("{h:016x}")
}

/// 12 significant digits, "0" for zero.
fn num(v: f64) -> String {
    if v == 0.0 {
        "0".into()
    } else {
        format!("{v:.11e}")
    }
}

fn write_table(designs: &[(HingeSpec, Material)]) {
    let mut s = String::from("{\"note\":\"tests/hinge_reference_table.rs: every number of characterise() for 5000 random designs, before the fast section constants\",\"designs\":[\n");
    for (k, (spec, m)) in designs.iter().enumerate() {
        let r = characterise(spec, m).unwrap();
        let v: Vec<String> = numbers(&r).iter().map(|(x, _)| num(*x)).collect();
        s += &format!(
            "{{\"hinge\":{},\"material\":[{},{},{}],\"notes\":\"{}\",\"v\":[{}]}}{}\n",
            serde_json::to_string(spec).unwrap(),
            m.e,
            m.nu,
            m.allowable,
            notes_hash(&r),
            v.join(","),
            if k + 1 < designs.len() { "," } else { "" }
        );
    }
    s += "]}\n";
    std::fs::write(table_path(), s).unwrap();
}

#[test]
fn every_number_matches_the_reference_table() {
    let designs = designs();
    if std::env::var_os("FLEXFEM_WRITE_HINGE_REFERENCE").is_some_and(|v| v == "1") {
        write_table(&designs);
    }
    let text = std::fs::read_to_string(table_path()).expect("tests/data/hinge_reference_table.json");
    let table: Value = serde_json::from_str(&text).unwrap();
    let rows = table["designs"].as_array().unwrap();
    assert_eq!(rows.len(), designs.len(), "number of designs");
    let mut worst = (0.0f64, String::new());
    let mut failures = Vec::new();
    for (k, ((spec, m), row)) in designs.iter().zip(rows).enumerate() {
        // The generator still gives the stored design.
        let stored: HingeSpec = serde_json::from_value(row["hinge"].clone()).unwrap();
        assert_eq!(&stored, spec, "design {k}: the generator changed");
        let mat: Vec<f64> = serde_json::from_value(row["material"].clone()).unwrap();
        assert_eq!(mat, [m.e, m.nu, m.allowable], "design {k}: the generator changed");
        let r = characterise(spec, m).unwrap();
        assert_eq!(
            row["notes"].as_str().unwrap(),
            notes_hash(&r),
            "design {k} {spec:?}: model notes differ"
        );
        let want: Vec<f64> = serde_json::from_value(row["v"].clone()).unwrap();
        let got = numbers(&r);
        assert_eq!(want.len(), got.len(), "design {k}: count of numbers");
        for (i, (w, (g, floor))) in want.iter().zip(&got).enumerate() {
            let scale = w.abs().max(*floor);
            let err = (g - w).abs() / scale.max(f64::MIN_POSITIVE);
            // A NaN is never within the tolerance.
            let within = g == w || err <= REL;
            if !within {
                failures.push(format!(
                    "design {k} {spec:?}: number {i}: {g:e} vs reference {w:e} ({err:e})"
                ));
            }
            if err.is_finite() && err > worst.0 {
                worst = (err, format!("design {k}, number {i}"));
            }
        }
    }
    eprintln!(
        "largest relative difference from the reference: {:e} ({})",
        worst.0, worst.1
    );
    assert!(
        failures.is_empty(),
        "{} numbers differ by more than {REL:e}; first: {:#?}",
        failures.len(),
        &failures[..failures.len().min(10)]
    );
}
