//! Segmented hinge elements (`"segments"` > 1) add inner nodes after the case's own. They are
//! hidden from a `static` result's displacements unless asked for (one row per node of the
//! case), and the hinge's mass is lumped on every node of its chain with rotary inertia, so a
//! transient no longer meets a singular mass matrix.

mod common;
use common::*;
use flexfem::analysis::{parse, run, Case};
use serde_json::{json, Value};

/// Aluminium: ρ = 2.7e-9 t/mm³.
const RHO: f64 = 2.7e-9;

/// A sharp leaf hinge (l 10, t 1, w 5, h 8 mm) along x from a clamp at node 0 to node 1
/// (20 mm: 5 mm of blank each side) in `segments`, with a 1 g tip mass at node 1.
fn leaf_case(analysis: &str, segments: usize, extra: Value) -> Value {
    let mut c = json!({
        "analysis": analysis,
        "materials": {"al": {"E": 70000, "nu": 0.33, "density": RHO}},
        "nodes": [[0, 0, 0], [20, 0, 0]],
        "elements": [
            {"type": "hinge", "nodes": [0, 1], "segments": segments, "material": "al", "up": [0, 0, 1],
             "hinge": {"type": "leaf", "l": 10, "t": 1, "w": 5, "h": 8}},
            {"type": "mass", "node": 1, "mass": 1e-6, "inertia": [1e-6, 1e-6, 1e-6]}
        ],
        "supports": [{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}]
    });
    for (k, v) in extra.as_object().unwrap() {
        c[k] = v.clone();
    }
    c
}

#[test]
fn static_displacements_list_the_case_nodes_unless_inner_nodes_are_asked_for() {
    // The bundled parallelogram guide: 9 nodes, four hinges of 8 segments (28 inner nodes).
    let (_, r) = run_out("cases/parallelogram_guide.json", "segment_rows");
    for c in r["load_cases"].as_array().unwrap() {
        assert_eq!(c["displacements"].as_array().unwrap().len(), 9, "{}", c["name"]);
    }
    assert!(r["model"].to_string().contains("28 inner nodes"), "{}", r["model"]);
    // Asked for: all 37, the first 9 rows the same numbers.
    let mut case: Value =
        serde_json::from_str(&std::fs::read_to_string(root().join("cases/parallelogram_guide.json")).unwrap()).unwrap();
    case["mesh"] = json!(root().join("meshes/parallelogram_notch.json").to_str().unwrap());
    case["output"] = json!({"internal_nodes": true});
    let full = run(&parse(&case.to_string()).unwrap()).unwrap().json;
    for (a, b) in r["load_cases"]
        .as_array()
        .unwrap()
        .iter()
        .zip(full["load_cases"].as_array().unwrap())
    {
        let (a, b) = (
            a["displacements"].as_array().unwrap(),
            b["displacements"].as_array().unwrap(),
        );
        assert_eq!((a.len(), b.len()), (9, 37));
        assert_eq!(a[..], b[..9]);
    }
}

#[test]
fn hinge_mass_is_lumped_on_every_chain_node_with_rotary_inertia() {
    // Volume of the sharp leaf: w (t l + h (L − l)) = 5 (1·10 + 8·10) = 450 mm³; mass ρV. Each
    // node takes its share of the length as a box of the blank section w × h: about the axis
    // m (w² + h²)/12 (J. L. Meriam, L. G. Kraige, Engineering Mechanics: Dynamics, Table D/4),
    // so the chain's total about x is ρV (25 + 64)/12 whatever the lumping.
    let c = leaf_case("transient", 4, json!({"dt": 1e-5, "steps": 1}));
    let Case::Transient(t) = parse(&c.to_string()).unwrap() else {
        panic!("a transient case")
    };
    let model = t.model.build_model(false).unwrap();
    assert_eq!(model.nodes.len(), 5, "two case nodes and three inner nodes");
    let hinge: Vec<_> = model.masses.iter().filter(|m| m.mass != 1e-6).collect();
    assert_eq!(hinge.len(), 5, "one lumped mass per chain node");
    let mass = RHO * 450.0;
    let total: f64 = hinge.iter().map(|m| m.mass).sum();
    assert!((total - mass).abs() < 1e-12 * mass, "{total} vs {mass}");
    let axial: f64 = hinge.iter().map(|m| m.inertia[0]).sum();
    let exact = mass * 89.0 / 12.0;
    assert!((axial - exact).abs() < 1e-12 * exact, "{axial} vs {exact}");
    // An inner node (a quarter of the mass, ℓ = 5 mm centred on it) about y and z:
    // m (ℓ²/12 + (w² + h²)/24) = ρV/4 (25/12 + 89/24).
    let inner = hinge.iter().find(|m| m.node == 2).unwrap();
    let about_y = mass / 4.0 * (25.0 / 12.0 + 89.0 / 24.0);
    for i in [1, 2] {
        assert!(
            (inner.inertia[i] - about_y).abs() < 1e-12 * about_y,
            "{:?}",
            inner.inertia
        );
    }
    assert!(hinge.iter().all(|m| m.inertia.iter().all(|v| *v > 0.0)));
}

#[test]
fn transient_of_a_segmented_hinge_has_a_regular_mass_matrix() {
    // A step load at t = 0 needs the initial acceleration M⁻¹F: the inner nodes were massless
    // ("the mass matrix is singular" and a zero initial acceleration).
    let c = leaf_case(
        "transient",
        4,
        json!({"dt": 1e-5, "steps": 20,
               "loads": [{"node": 1, "force": [0, 0, 0.01, 0, 0, 0], "history": {"type": "step"}}]}),
    );
    let out = run(&parse(&c.to_string()).unwrap()).unwrap();
    assert!(
        out.warnings.iter().all(|w| !w.contains("singular")),
        "{:?}",
        out.warnings
    );
}

#[test]
fn a_mechanism_through_inner_nodes_names_their_hinge() {
    // Node 0 held in translation only: the hinge chain spins about it, and the solver's message
    // lists the inner nodes 2, 3, 4 the user never wrote. (Which DOFs of node 2 the lowest mode
    // names depends on roundoff: the three rotations are one null space, and its lowest mode is
    // any mix of them; the exact-constraint check names all three.)
    let mut c = leaf_case(
        "static",
        4,
        json!({"load_cases": [{"name": "push", "forces": [{"node": 1, "F": [0, 0, 1, 0, 0, 0]}]}]}),
    );
    c["supports"] = json!([{"node": 0, "fix": ["ux", "uy", "uz"]}]);
    c["elements"].as_array_mut().unwrap().truncate(1);
    let d = tempdir("inner_mechanism");
    let p = d.join("case.json");
    std::fs::write(&p, c.to_string()).unwrap();
    let o = run_in(&d, &["run", p.to_str().unwrap()]);
    exits(
        &o,
        1,
        &[
            "mechanism",
            "node 2 ",
            "rotation about [0, 0, 1] through [0, 0, 0]",
            "rotation about [0, 1, 0] through [0, 0, 0]",
            "nodes 2, 3, 4 are inner nodes of the segmented hinge elements[0]",
        ],
    );
}

#[test]
fn modal_and_buckling_shapes_list_the_case_nodes() {
    // 4 segments: 3 inner nodes after the case's 2. The first mode's tip row is the same number
    // whether the inner rows are listed or not (they are cut off, not renumbered).
    let c = leaf_case("modal", 4, json!({"modes": 2}));
    let r = run(&parse(&c.to_string()).unwrap()).unwrap().json;
    let modes = r["modes"].as_array().unwrap();
    assert_eq!(modes.len(), 2);
    for m in modes {
        assert_eq!(m["shape"].as_array().unwrap().len(), 2, "{m}");
    }
    assert!(r["model"].to_string().contains("3 inner nodes"), "{}", r["model"]);
    // Buckling of the same hinge under an axial tip push: shapes by case node too.
    let mut b = leaf_case("buckling", 4, json!({"modes": 1}));
    b["load_cases"] = json!([{"name": "push", "forces": [{"node": 1, "F": [-1, 0, 0, 0, 0, 0]}]}]);
    let r = run(&parse(&b.to_string()).unwrap()).unwrap().json;
    let rows = r["buckling"].as_array().unwrap();
    assert_eq!(rows.len(), 1);
    assert_eq!(rows[0]["shape"].as_array().unwrap().len(), 2, "{}", rows[0]);
    assert!(r["model"].to_string().contains("3 inner nodes"), "{}", r["model"]);
}
