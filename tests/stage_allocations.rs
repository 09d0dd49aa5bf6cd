//! Heap allocations per stage design on the sweep's hot path (one worker's solver cache reused,
//! as `flexfem sweep` does), counted with a counting global allocator. Printed with
//! `--nocapture`; the assertion is a ceiling against regressions (measured 2026-11-24, see
//! the test), not a target.

use flexfem::analysis::{self as case, Case};
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// Allocations of `f` (this test file has one test, so no other thread allocates meanwhile).
fn count(f: impl FnOnce()) -> usize {
    let before = ALLOCATIONS.load(Ordering::Relaxed);
    f();
    ALLOCATIONS.load(Ordering::Relaxed) - before
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
    // Ceilings: the linear solve on the FE model at its count measured 2026-11-24 (176: the
    // condensed model, its load cases and the expanded result are built per design), so any
    // new allocation there fails here; the full analysis, which now solves the condensed stage
    // without an FE model (none per design there: tests/alloc_per_design.rs), at its count
    // measured then (46, was 527: the case's validation with its JSON paths, the result's
    // rows, names and model notes, the calibration warnings).
    assert!(solve <= 176, "{solve}");
    assert!(full <= 46, "{full}");
}
