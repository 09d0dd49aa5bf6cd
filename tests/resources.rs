//! Input sizes are bounded with clear messages, overridable with `FLEXFEM_LIMITS` (issue 12,
//! "Resources"): `"mesh": "/dev/zero"` used to read until memory ran out, a 10⁷-node mesh
//! aborted at 10 GiB even in `check`, 1,000 modes of a 120k-DOF model ran for more than ten
//! minutes with no estimate.

mod common;

use common::{bin, tempdir};
use std::path::Path;
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

/// Runs `flexfem ARGS` in `dir` with `FLEXFEM_LIMITS` = `limits` (if any); kills it after
/// 60 s (a regression would read /dev/zero forever).
fn run_limited(dir: &Path, args: &[&str], limits: Option<&str>) -> Output {
    let mut cmd = Command::new(bin());
    cmd.args(args)
        .current_dir(dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .env_remove("FLEXFEM_LIMITS");
    if let Some(l) = limits {
        cmd.env("FLEXFEM_LIMITS", l);
    }
    let mut child = cmd.spawn().unwrap();
    let start = Instant::now();
    loop {
        if child.try_wait().unwrap().is_some() {
            return child.wait_with_output().unwrap();
        }
        if start.elapsed() > Duration::from_secs(60) {
            child.kill().unwrap();
            let _ = child.wait();
            panic!("flexfem {args:?} still running after 60 s");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn static_case(mesh: &str) -> String {
    format!(
        r#"{{"analysis": "static", "mesh": "{mesh}", "load_cases": [{{"name": "a", "forces": [{{"node": 0, "F": [1, 0, 0, 0, 0, 0]}}]}}]}}"#
    )
}

/// `flexfem check FILE` in `dir` (with `FLEXFEM_LIMITS=limits`) refuses the case (exit 2);
/// returns its stderr.
fn check_refused(dir: &Path, file: &str, limits: Option<&str>) -> String {
    let o = run_limited(dir, &["check", file], limits);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    stderr(&o)
}

/// `/dev/zero` is not a regular file: refused at once (exit 2, path `mesh`).
#[test]
fn dev_zero_mesh_is_refused() {
    let d = tempdir("res_dev_zero");
    std::fs::write(d.join("case.json"), static_case("/dev/zero")).unwrap();
    for cmd in ["check", "run"] {
        let o = run_limited(&d, &[cmd, "case.json"], None);
        assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
        let e = stderr(&o);
        assert!(e.contains("`mesh`") && e.contains("not a regular file"), "{e}");
    }
    // The case file itself, too.
    let o = run_limited(&d, &["check", "/dev/zero"], None);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("not a regular file"));
}

/// A mesh file larger than the file-size limit is refused from its size, without reading it
/// (a 300 MiB sparse file costs no disk), and the limit can be raised or lowered.
#[test]
fn oversized_mesh_file_is_refused() {
    let d = tempdir("res_big_file");
    let f = std::fs::File::create(d.join("big.json")).unwrap();
    f.set_len(300 << 20).unwrap();
    std::fs::write(d.join("case.json"), static_case("big.json")).unwrap();
    let e = check_refused(&d, "case.json", None);
    assert!(
        e.contains("`mesh`") && e.contains("300.0 MiB") && e.contains("256.0 MiB"),
        "{e}"
    );
    assert!(e.contains("FLEXFEM_LIMITS=file_mib="), "{e}");
    // A 2 KiB mesh under a 1 KiB limit (file_mib = 1/1024).
    let nodes: Vec<String> = (0..100).map(|i| format!("[{i}, 0, 0]")).collect();
    std::fs::write(d.join("small.json"), format!(r#"{{"nodes": [{}]}}"#, nodes.join(", "))).unwrap();
    std::fs::write(d.join("case2.json"), static_case("small.json")).unwrap();
    let o = run_limited(&d, &["check", "case2.json"], Some("file_mib=0.0009765625"));
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("over the file-size limit of 0.0 MiB"),
        "{}",
        stderr(&o)
    );
    let _ = std::fs::remove_dir_all(&d);
}

/// A .msh file whose `$Nodes` header claims 10⁷ nodes is refused from the header (before any
/// node is read or allocated); with the node limit raised, reading goes on (and finds the
/// file truncated).
#[test]
fn msh_node_count_is_refused_from_the_header() {
    let d = tempdir("res_msh_nodes");
    let msh = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n2 1 \"plate\"\n$EndPhysicalNames\n$Nodes\n1 10000000 1 10000000\n2 1 0 10000000\n1\n";
    std::fs::write(d.join("m.msh"), msh).unwrap();
    let case = r#"{"analysis": "static", "mesh": "m.msh", "gmsh": {"groups": {"plate": {"section": "s", "material": "al"}}},
      "materials": {"al": "Al7075"}, "sections": {"s": {"shape": "shell", "t": 1}},
      "load_cases": [{"name": "a", "forces": [{"node": 0, "F": [1, 0, 0, 0, 0, 0]}]}]}"#;
    std::fs::write(d.join("case.json"), case).unwrap();
    let e = check_refused(&d, "case.json", None);
    assert!(e.contains("10000000 nodes") && e.contains("limit of 2000000"), "{e}");
    let o = run_limited(&d, &["check", "case.json"], Some("nodes=2e7"));
    assert_eq!(o.status.code(), Some(2));
    assert!(!stderr(&o).contains("limit of"), "{}", stderr(&o));
}

/// A JSON model with more nodes than the limit is refused before its nodes are built.
#[test]
fn json_node_count_is_refused() {
    let d = tempdir("res_json_nodes");
    let nodes: Vec<String> = (0..1001).map(|i| format!("[{i}, 0, 0]")).collect();
    std::fs::write(d.join("mesh.json"), format!(r#"{{"nodes": [{}]}}"#, nodes.join(", "))).unwrap();
    std::fs::write(d.join("case.json"), static_case("mesh.json")).unwrap();
    let e = check_refused(&d, "case.json", Some("nodes=1000"));
    assert!(
        e.contains("`mesh`") && e.contains("1001 nodes") && e.contains("limit of 1000"),
        "{e}"
    );
    // Inline nodes, same limit.
    let inline = format!(
        r#"{{"analysis": "static", "nodes": [{}], "load_cases": [{{"name": "a", "forces": [{{"node": 0, "F": [1, 0, 0, 0, 0, 0]}}]}}]}}"#,
        nodes.join(", ")
    );
    std::fs::write(d.join("inline.json"), inline).unwrap();
    let o = run_limited(&d, &["check", "inline.json"], Some("nodes=1000"));
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("`nodes`"), "{}", stderr(&o));
}

/// 1,000 modes of a 20,000-node (120,000-DOF) beam chain: the memory estimate (Lanczos basis
/// 2 × 2006 vectors + 1,000 Ritz vectors of 120,000 numbers, 8 bytes each = 4.8 GB, plus the
/// JSON shapes ≈ 6.7 GB) exceeds the 8 GiB default: `check` refuses with the estimate; with
/// 10 modes it passes.
#[test]
fn modal_memory_estimate_refuses_1000_modes_of_120k_dofs() {
    let d = tempdir("res_modal");
    let n = 20_000;
    let nodes: Vec<String> = (0..n).map(|i| format!("[{i}, 0, 0]")).collect();
    let elements: Vec<String> = (0..n - 1)
        .map(|i| {
            format!(
                r#"{{"type": "beam", "nodes": [{i}, {}], "section": "s", "material": "al", "up": [0, 0, 1]}}"#,
                i + 1
            )
        })
        .collect();
    let case = |modes: usize| {
        format!(
            r#"{{"analysis": "modal", "modes": {modes}, "materials": {{"al": "Al7075"}}, "sections": {{"s": {{"shape": "rect", "w": 1, "h": 1}}}},
              "nodes": [{}], "elements": [{}], "supports": [{{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}}]}}"#,
            nodes.join(", "),
            elements.join(", ")
        )
    };
    std::fs::write(d.join("big.json"), case(1000)).unwrap();
    let e = check_refused(&d, "big.json", None);
    assert!(
        e.contains("`modes`") && e.contains("120000 DOFs") && e.contains("GiB"),
        "{e}"
    );
    assert!(e.contains("FLEXFEM_LIMITS=memory_gib="), "{e}");
    // The estimate itself: 8·n·(2k + m) + 16k² + 56·n·m with n = 120000, m = 1000, k = 2006.
    let est = flexfem::case::limits::modal_memory(1000, n);
    let by_hand = 8.0 * 120_000.0 * (2.0 * 2006.0 + 1000.0) + 16.0 * 2006.0f64.powi(2) + 56.0 * 120_000.0 * 1000.0;
    assert!((est as f64 / by_hand - 1.0).abs() < 1e-9);
    std::fs::write(d.join("small.json"), case(10)).unwrap();
    let o = run_limited(&d, &["check", "small.json"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}

/// A malformed `FLEXFEM_LIMITS` is an error that names the variable.
#[test]
fn bad_limits_variable_is_reported() {
    let d = tempdir("res_bad_env");
    std::fs::write(
        d.join("case.json"),
        r#"{"analysis": "hinge", "hinge": {"type": "leaf", "l": 5, "t": 1, "w": 5, "h": 8, "blank_length": 5}}"#,
    )
    .unwrap();
    let o = run_limited(&d, &["check", "case.json"], Some("nodes=lots"));
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("FLEXFEM_LIMITS"), "{}", stderr(&o));
}
