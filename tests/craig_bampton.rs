//! Craig–Bampton reduction (`fem::craig_bampton`; R. R. Craig, M. C. C. Bampton, AIAA J. 6
//! (1968) 1313–1319) of a clamped steel cantilever to its tip node:
//! - with 10 fixed-interface modes, the superelement's lowest frequencies converge to the full
//!   model's (shift-invert Lanczos of the modal solver);
//! - with 0 modes it is Guyan's static condensation (R. J. Guyan, AIAA J. 3 (1965) 380): its
//!   stiffness is the inverse of the tip's 6×6 static compliance from the static solver.

use flexfem::fem::craig_bampton::craig_bampton;
use flexfem::fem::modal::{solve_modal, ModalOptions};
use flexfem::fem::{solve_static, Beam, LoadCase, Model, NodalLoad, Section, Support};
use nalgebra::{DMatrix, Matrix6};

mod common;

use common::materials::STEEL;

const NE: usize = 20;

/// Steel cantilever along x, 1000 mm, 10×6 mm (distinct bending planes), 20 Euler–Bernoulli
/// elements, clamped at node 0.
fn cantilever() -> Model {
    let mut m = Model::new();
    m.add_node([0.0; 3]);
    for i in 1..=NE {
        m.add_node([1000.0 * i as f64 / NE as f64, 0.0, 0.0]);
        let section = Section::Rect { w: 10.0, h: 6.0 };
        m.add_beam(Beam::new(i - 1, i, section, STEEL, [0.0, 0.0, 1.0]).euler_bernoulli());
    }
    m.supports.push(Support::clamp(0));
    m
}

/// 10 fixed-interface modes, interface = the tip (6 DOFs): the lowest 3 frequencies (first and
/// second bending in the weak plane, first in the stiff plane) equal the full model's (20
/// elements, 120 equations) within 1e-4 (relative, on ω²); the superelement has 16 coordinates.
#[test]
fn ten_modes_converge_to_the_full_model() {
    let model = cantilever();
    let se = craig_bampton(&model, &[NE], 10).unwrap();
    assert_eq!(se.k.rows(), 16);
    let cb = se.eigenvalues(3).unwrap();
    let full = solve_modal(&model, &ModalOptions::new(3)).unwrap();
    let mut worst: f64 = 0.0;
    assert_eq!(cb.len(), full.modes.len());
    for (a, mode) in cb.iter().zip(&full.modes) {
        worst = worst.max((a - mode.eigenvalue).abs() / mode.eigenvalue);
    }
    let hz: Vec<f64> = cb.iter().map(|l| l.sqrt() / (2.0 * std::f64::consts::PI)).collect();
    eprintln!("CB (6 + 10): {hz:?} Hz; worst relative difference on ω² to the full model {worst:.3e}");
    assert!(worst < 1e-4, "{worst}");
}

/// 0 modes: K_cb equals the inverse of the tip compliance (6 unit load cases at the tip, static
/// solver) entry by entry within 1e-10 of √(K_ii K_jj).
#[test]
fn zero_modes_is_the_static_condensation() {
    let mut model = cantilever();
    let se = craig_bampton(&model, &[NE], 0).unwrap();
    for d in 0..6 {
        let mut f = [0.0; 6];
        f[d] = 1.0;
        let mut lc = LoadCase::new(format!("unit {d}"));
        lc.forces.push(NodalLoad { node: NE, f });
        model.load_cases.push(lc);
    }
    let res = solve_static(&model).unwrap();
    let c = Matrix6::from_fn(|i, j| res.load_cases[j].displacements[NE][i]);
    let k_static = c.try_inverse().unwrap();
    let mut k_cb = DMatrix::zeros(6, 6);
    for (v, (i, j)) in se.k.iter() {
        k_cb[(i, j)] = *v;
    }
    let mut worst: f64 = 0.0;
    for i in 0..6 {
        for j in 0..6 {
            let scale = (k_static[(i, i)] * k_static[(j, j)]).sqrt();
            worst = worst.max((k_cb[(i, j)] - k_static[(i, j)]).abs() / scale);
        }
    }
    eprintln!("Guyan K vs inverse static compliance: worst {worst:.3e}");
    assert!(worst < 1e-10, "{worst}");
}

/// `flexfem run --out DIR` on the bundled `cases/craig_bampton_cantilever.json` (the cantilever
/// above as a case, interface = the tip, 10 modes): `superelement_K.mtx` and
/// `superelement_M.mtx` read back by sprs' Matrix Market reader give the superelement
/// frequencies of result.json to 1e-9, and the first three are the full model's within 1e-4
/// (on ω²). An interface node that does not exist is refused (exit 2, naming the JSON path).
#[test]
fn bundled_case_writes_the_superelement() {
    let (out, r) = common::run_out("cases/craig_bampton_cantilever.json", "cb_case");
    let read = |name: &str| -> sprs::CsMat<f64> {
        let t: sprs::TriMat<f64> = sprs::io::read_matrix_market(out.join(name)).unwrap();
        t.to_csr()
    };
    let se = flexfem::fem::craig_bampton::Superelement {
        boundary: Vec::new(),
        k: read("superelement_K.mtx"),
        m: read("superelement_M.mtx"),
        fixed_interface_eigenvalues: Vec::new(),
    };
    let lam = se.eigenvalues(3).unwrap();
    let w2 = |key: &str, i: usize| (2.0 * std::f64::consts::PI * r[key][i].as_f64().unwrap()).powi(2);
    for (i, l) in lam.iter().enumerate() {
        let (se_w2, full_w2) = (w2("superelement_frequencies_hz", i), w2("full_model_frequencies_hz", i));
        assert!((l - se_w2).abs() < 1e-9 * se_w2, "mode {i}: {l} vs {se_w2}");
        assert!((l - full_w2).abs() < 1e-4 * full_w2, "mode {i}: {l} vs {full_w2}");
    }
    let text = std::fs::read_to_string("cases/craig_bampton_cantilever.json").unwrap();
    let o = common::run_case_text(
        "cb_refused",
        &text.replace("\"interface\": [\n  20\n ]", "\"interface\": [21]"),
    );
    assert_eq!(o.status.code(), Some(2), "{}", common::stderr(&o));
    assert!(common::stderr(&o).contains("interface[0]"), "{}", common::stderr(&o));
}
