//! The README's two commands share one build: `cargo test --release` must not compile again the
//! crates `cargo run --release` compiled. Cargo compiles a crate anew whenever its feature set
//! differs between two builds, and dev-dependencies (criterion, proptest) switch features on in
//! crates the program also uses (`either`, `bitflags`: rayon, faer and their dependents then
//! compiled twice, 17 crates). Cargo.toml names those features; this test keeps it so.

use std::collections::BTreeMap;
use std::process::Command;

/// `package version` → feature list, for the dependency graph cargo resolves with or without
/// the dev-dependencies.
fn features(with_dev: bool) -> BTreeMap<String, String> {
    let mut cmd = Command::new(env!("CARGO"));
    cmd.current_dir(env!("CARGO_MANIFEST_DIR")).args([
        "tree",
        "--offline",
        "--locked",
        "--prefix",
        "none",
        "-f",
        "{p}|{f}",
    ]);
    if !with_dev {
        cmd.args(["-e", "no-dev"]);
    }
    let out = cmd.output().expect("cargo runs");
    assert!(
        out.status.success(),
        "cargo tree failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .filter_map(|l| {
            let l = l.trim_end_matches(" (*)");
            let (pkg, feats) = l.split_once('|')?;
            // `name vX.Y.Z (path)` for the root: keep name and version only.
            let key: Vec<&str> = pkg.split_whitespace().take(2).collect();
            Some((key.join(" "), feats.to_string()))
        })
        .collect()
}

#[test]
fn test_build_reuses_the_run_build() {
    let run = features(false);
    let test = features(true);
    assert!(run.len() > 20, "cargo tree listed {} packages", run.len());
    let differ: Vec<String> = run
        .iter()
        .filter(|(pkg, f)| test.get(*pkg).is_some_and(|g| g != *f))
        .map(|(pkg, f)| format!("{pkg}: run [{f}] vs test [{}]", test[pkg]))
        .collect();
    assert!(
        differ.is_empty(),
        "these crates would compile twice (name the features in Cargo.toml [dependencies]):\n{}",
        differ.join("\n")
    );
}
