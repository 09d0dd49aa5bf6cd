//! Reading a case stays linear in its size: the checks that walk the whole JSON value before
//! the typed parse (the array-for-object check against the schema, the parameter and hinge-type
//! resolution) allocate nothing per value, counted by a global allocator wrapping the system
//! one (this test binary only).
//!
//! Source of the expectation: the code itself (a regression check, not a published value).
//! Before this change the array check expanded the schema nodes of every child of every value
//! into a new vector (with SipHash lookups of each field in the schema): at least one
//! allocation per array item and object field, and `flexfem check` of a 10 000-equation lattice
//! took 0.32 s of CPU (0.03 s after).

use flexfem::analysis::case_file::check_shape;
use flexfem::case::params::resolve_case;
use serde_json::json;

#[path = "common/counting_alloc.rs"]
mod counting;
#[path = "common/lattice_case.rs"]
mod lattice;
use lattice::lattice_case;

/// Allocations made by `f`.
fn allocations(f: impl FnOnce()) -> usize {
    let before = counting::allocations();
    f();
    counting::allocations() - before
}

/// The array check of a valid case allocates nothing per value, whatever its size: only its
/// JSON-path stack (at most 4 allocations as it grows to the depth of the case), the same for a
/// 3×3×3 and a 7×7×7 lattice (the schema is compiled once, by the first check).
#[test]
fn array_check_allocates_nothing_per_value() {
    let small = lattice_case(2);
    check_shape(&small).unwrap();
    let counts: Vec<usize> = [3, 7]
        .into_iter()
        .map(|n| {
            let case = lattice_case(n);
            assert_eq!(case["elements"].as_array().unwrap().len(), 3 * n * (n + 1) * (n + 1));
            allocations(|| check_shape(&case).unwrap())
        })
        .collect();
    assert_eq!(counts.len(), 2);
    assert_eq!(counts[0], counts[1], "allocations grow with the case: {counts:?}");
    assert!(counts[0] <= 4, "allocations: {counts:?}");
    // It still refuses an object given as an array, naming the path.
    let mut bad = lattice_case(2);
    bad["sections"]["strut"] = json!(["circle", 2]);
    let e = check_shape(&bad).unwrap_err();
    assert_eq!(e.path, "sections.strut");
}

/// Resolving a case without parameters walks it without allocating per value: the same few
/// allocations (the growing JSON-path buffer) for a 3×3×3 and a 7×7×7 lattice, at most 8.
#[test]
fn parameter_resolution_allocates_nothing_per_value() {
    let counts: Vec<usize> = [3, 7]
        .into_iter()
        .map(|n| {
            let mut case = lattice_case(n);
            allocations(|| {
                resolve_case(&mut case, None).unwrap();
            })
        })
        .collect();
    assert_eq!(counts.len(), 2);
    assert!(counts.iter().all(|&c| c <= 8), "allocations: {counts:?}");
}
