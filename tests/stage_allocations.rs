//! Heap allocations per stage design on the sweep's hot path (one worker's solver cache reused,
//! as `flexfem sweep` does), counted with a counting global allocator. Printed with
//! `--nocapture`; the FE-model solve has a ceiling against regressions (measured 2026-11-24,
//! see the test), the full analysis must allocate nothing.

use flexfem::analysis::{self as case, Case};
#[path = "common/counting_alloc.rs"]
mod counting;

/// Allocations of `f` (on this thread).
fn count(f: impl FnOnce()) -> usize {
    let before = counting::allocations();
    f();
    counting::allocations() - before
}

#[test]
fn allocations_per_stage_design() {
    let Case::Stage(c) = case::parse(include_str!("../cases/ruiz2019_stage.json")).expect("parses") else {
        panic!("a stage case")
    };
    let mut cache = flexfem::fem::SolverCache::new();
    flexfem::analysis::stage::run_stage_with(&c, false, &mut cache).expect("runs");
    let (design, drives) = c.validated().expect("valid");
    let mut one: Vec<_> = drives.clone();
    one.truncate(1);
    let s = design.build();
    // Warm up the cache (the first solve builds the symbolic factorisation; the stage analysis
    // above solves the condensed stage without an FE model and leaves the cache untouched).
    s.solve_with(&mut cache, &one).expect("solves");
    let solve = count(|| {
        s.solve_with(&mut cache, &one).expect("solves");
    });
    let full = count(|| {
        flexfem::analysis::stage::run_stage_with(&c, false, &mut cache).expect("runs");
    });
    eprintln!("allocations: linear solve of one load case {solve}; full stage analysis (3 cases) {full}");
    // The linear solve on the FE model: a ceiling at its count measured 2026-11-24 (176: the
    // condensed model, its load cases and the expanded result are built per design), so any new
    // allocation there fails here. The full analysis solves the condensed stage without an FE
    // model and allocates nothing (was 527, then 46: the case's validation with its JSON paths,
    // the result's rows, names and model notes; now the paths are formatted only for an error,
    // the rows inline with shared names, the notes kept as data).
    assert!(solve <= 176, "{solve}");
    assert_eq!(full, 0, "{full}");
}
