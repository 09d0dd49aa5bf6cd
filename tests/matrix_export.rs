//! Matrix export: the reduced K and M written by `flexfem::fem::matrices` (and by
//! `flexfem run --export-matrices`) read back by sprs' Matrix Market reader give the modal
//! solver's lowest eigenvalues.

mod common;

use common::fixtures::ruiz2019_stage_design;
use flexfem::fem::matrices::{reduced_matrices, MATRIX_FILES};
use flexfem::fem::modal::{solve_modal, ModalOptions};
use nalgebra::{DMatrix, SymmetricEigen};

fn dense(m: &sprs::CsMat<f64>) -> DMatrix<f64> {
    let mut d = DMatrix::zeros(m.rows(), m.cols());
    for (v, (i, j)) in m.iter() {
        d[(i, j)] += *v;
    }
    d
}

/// The `n` lowest eigenvalues of K φ = λ M φ (K positive definite, M possibly singular): the
/// largest eigenvalues μ = 1/λ of L⁻¹ M L⁻ᵀ with K = L Lᵀ (dense; no massless-DOF trouble).
fn lowest_eigenvalues(k: &DMatrix<f64>, m: &DMatrix<f64>, n: usize) -> Vec<f64> {
    let l = k.clone().cholesky().expect("K positive definite").l();
    let li = l.try_inverse().unwrap();
    let a = &li * m * li.transpose();
    let a = (&a + a.transpose()) * 0.5;
    let mut mu: Vec<f64> = SymmetricEigen::new(a).eigenvalues.iter().copied().collect();
    mu.sort_by(|x, y| y.total_cmp(x));
    mu[..n].iter().map(|v| 1.0 / v).collect()
}

/// The stage (rigid links, slider node frames, flexibility elements, point masses of the legs'
/// consistent mass): K.mtx and M.mtx written through sprs and read back by
/// `sprs::io::read_matrix_market` equal the in-memory matrices exactly (shortest round-trip
/// decimal), and their six lowest eigenvalues (dense, from the files) equal the shift-invert
/// Lanczos eigenvalues of the modal solver to 1e-9 (relative).
#[test]
fn exported_matrices_give_the_modal_eigenvalues() {
    let mut s = ruiz2019_stage_design().build().unwrap();
    s.model.masses.push(flexfem::fem::PointMass {
        node: s.platform,
        mass: 1e-4,
        inertia: [0.1, 0.1, 0.1],
    });
    let mats = reduced_matrices(&s.model).unwrap();
    let dir = common::tempdir("matrix_export");
    mats.write(&dir).unwrap();
    let k: sprs::TriMat<f64> = sprs::io::read_matrix_market(dir.join(MATRIX_FILES[0])).unwrap();
    let m: sprs::TriMat<f64> = sprs::io::read_matrix_market(dir.join(MATRIX_FILES[1])).unwrap();
    let (k, m): (sprs::CsMat<f64>, sprs::CsMat<f64>) = (k.to_csr(), m.to_csr());
    assert_eq!(k, mats.k, "K read back differs");
    assert_eq!(m, mats.m, "M read back differs");
    let csv = std::fs::read_to_string(dir.join(MATRIX_FILES[2])).unwrap();
    assert_eq!(csv.lines().count(), 1 + k.rows(), "dofs.csv: one line per equation");
    let from_files = lowest_eigenvalues(&dense(&k), &dense(&m), 6);
    let modal = solve_modal(&s.model, &ModalOptions::new(6)).unwrap();
    let mut worst: f64 = 0.0;
    assert_eq!(from_files.len(), modal.modes.len());
    for (a, mode) in from_files.iter().zip(&modal.modes) {
        worst = worst.max((a - mode.eigenvalue).abs() / mode.eigenvalue);
    }
    eprintln!("lowest eigenvalues from the files: {from_files:?}; worst relative difference {worst:.3e}");
    assert!(worst < 1e-9, "{worst}");
}

/// `flexfem run --out DIR --export-matrices` on the bundled stage FRF case (the stage as a mesh:
/// hinge elements with lumped masses, slider node frames, the platform rigid link and disc
/// mass): K.mtx and M.mtx read back by sprs give the squared circular frequencies of the six
/// retained modes of result.json to 1e-9 (relative; the JSON frequencies are printed to round
/// trip). A stage case is refused (exit 2) before it is solved.
#[test]
fn cli_export_matrices_of_the_stage_mesh() {
    let dir = common::tempdir("export_cli");
    let out = dir.join("out");
    let o = common::run(&[
        "run",
        "cases/ruiz2019_stage_frf.json",
        "--out",
        out.to_str().unwrap(),
        "--export-matrices",
    ]);
    assert!(o.status.success(), "{}", common::stderr(&o));
    let read = |name: &str| -> sprs::CsMat<f64> {
        let t: sprs::TriMat<f64> = sprs::io::read_matrix_market(out.join(name)).unwrap();
        t.to_csr()
    };
    let (k, m) = (read("K.mtx"), read("M.mtx"));
    let result: serde_json::Value = serde_json::from_slice(&std::fs::read(out.join("result.json")).unwrap()).unwrap();
    let modes = result["modes"].as_array().unwrap();
    let lam = lowest_eigenvalues(&dense(&k), &dense(&m), modes.len());
    let mut worst: f64 = 0.0;
    assert_eq!(lam.len(), modes.len());
    for (l, mode) in lam.iter().zip(modes) {
        let w = 2.0 * std::f64::consts::PI * mode["frequency_hz"].as_f64().unwrap();
        worst = worst.max((l - w * w).abs() / (w * w));
    }
    eprintln!("stage mesh: lowest eigenvalues {lam:?}, worst relative difference {worst:.3e}");
    assert!(worst < 1e-9, "{worst}");
    let csv = std::fs::read_to_string(out.join("dofs.csv")).unwrap();
    // Equations 0-5: the platform centre (node 0, global axes); slider 1 (node 1) has only its
    // stroke free, in its node frame, as equation 6.
    assert!(
        csv.contains("\n6,1,ux,node\n"),
        "slider 1's stroke is equation 6, in its node frame: {csv}"
    );
    assert_eq!(csv.lines().count(), 1 + k.rows());
    let refused = common::run(&[
        "run",
        "cases/ruiz2019_stage.json",
        "--out",
        dir.join("o2").to_str().unwrap(),
        "--export-matrices",
    ]);
    assert_eq!(refused.status.code(), Some(2));
    assert!(
        common::stderr(&refused).contains("--export-matrices takes"),
        "{}",
        common::stderr(&refused)
    );
}

/// `flexfem run --out DIR --export-matrices` on the bundled stage step-response case (a
/// `transient` case: the stage mesh with hinge elements, slider frames and the platform mass;
/// its prescribed slider motions stay equations): the run still writes its result, and K.mtx and
/// M.mtx read back by sprs give the six lowest eigenvalues of the modal solver (shift-invert
/// Lanczos) on the case's model to 1e-9 (relative).
#[test]
fn cli_export_matrices_of_a_transient_case() {
    let case = "cases/ruiz2019_stage_step.json";
    let out = common::tempdir("export_transient").join("out");
    let o = common::run(&["run", case, "--out", out.to_str().unwrap(), "--export-matrices"]);
    assert!(o.status.success(), "{}", common::stderr(&o));
    assert!(
        out.join("result.json").is_file(),
        "the transient run writes its result too"
    );
    let read = |name: &str| -> sprs::CsMat<f64> {
        let t: sprs::TriMat<f64> = sprs::io::read_matrix_market(out.join(name)).unwrap();
        t.to_csr()
    };
    let (k, m) = (read("K.mtx"), read("M.mtx"));
    let flexfem::analysis::Case::Transient(t) = flexfem::analysis::load(std::path::Path::new(case)).unwrap() else {
        panic!("{case} is a transient case")
    };
    let model = t.model.build_model(false).unwrap();
    let modal = solve_modal(&model, &ModalOptions::new(6)).unwrap();
    let lam = lowest_eigenvalues(&dense(&k), &dense(&m), 6);
    let mut worst: f64 = 0.0;
    assert_eq!(lam.len(), modal.modes.len());
    for (l, mode) in lam.iter().zip(&modal.modes) {
        worst = worst.max((l - mode.eigenvalue).abs() / mode.eigenvalue);
    }
    eprintln!("stage step case: lowest eigenvalues {lam:?}, worst relative difference {worst:.3e}");
    assert!(worst < 1e-9, "{worst}");
}
