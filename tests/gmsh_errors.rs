//! Gmsh import errors name what the user wrote (issue 12, "Schema"): a section error names
//! `gmsh.groups.NAME.section`, not an element the user never wrote; second-order elements are
//! refused by name at `check` (they used to pass `check` and fail later with an 11.8 KB
//! mechanism message); binary MSH is said to be unsupported (it used to give a UTF-8 error).

mod common;

use common::{run_in, tempdir};

/// A one-element MSH 4.1 ASCII mesh of the surface physical group "plate": `kind` is the Gmsh
/// element type, `nodes` its node count (all nodes in the unit square, z = 0).
fn one_element_msh(kind: usize, nodes: usize) -> String {
    let coords = [
        [0.0, 0.0],
        [1.0, 0.0],
        [0.0, 1.0],
        [1.0, 1.0],
        [0.5, 0.0],
        [0.5, 0.5],
        [0.0, 0.5],
        [1.0, 0.5],
        [0.5, 1.0],
    ];
    let mut s = String::from(
        "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n2 1 \"plate\"\n$EndPhysicalNames\n$Entities\n0 0 1 0\n1 0 0 0 1 1 0 1 1 0\n$EndEntities\n",
    );
    s += &format!("$Nodes\n1 {nodes} 1 {nodes}\n2 1 0 {nodes}\n");
    for i in 1..=nodes {
        s += &format!("{i}\n");
    }
    for c in coords.iter().take(nodes) {
        s += &format!("{} {} 0\n", c[0], c[1]);
    }
    s += "$EndNodes\n$Elements\n1 1 1 1\n";
    s += &format!("2 1 {kind} 1\n1");
    for i in 1..=nodes {
        s += &format!(" {i}");
    }
    s += "\n$EndElements\n";
    s
}

fn case(section: &str, sections: &str) -> String {
    format!(
        r#"{{"analysis": "static", "mesh": "m.msh",
  "gmsh": {{"groups": {{"plate": {{"section": "{section}", "material": "al"}}}}}},
  "materials": {{"al": "Al7075"}},
  "sections": {sections},
  "supports": [],
  "load_cases": [{{"name": "a", "forces": [{{"node": 1, "F": [0, 0, 1, 0, 0, 0]}}]}}]}}"#
    )
}

fn check(name: &str, msh: &[u8], case_text: &str) -> (Option<i32>, String) {
    let d = tempdir(name);
    std::fs::write(d.join("m.msh"), msh).unwrap();
    std::fs::write(d.join("case.json"), case_text).unwrap();
    let o = run_in(&d, &["check", "case.json"]);
    (o.status.code(), String::from_utf8_lossy(&o.stderr).into_owned())
}

/// `check` of a one-quadrangle mesh with `case` exits 2 naming `gmsh.groups.plate.section`; the
/// message.
fn refused(name: &str, case: &str) -> String {
    let (code, err) = check(name, one_element_msh(3, 4).as_bytes(), case);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("`gmsh.groups.plate.section`"), "{err}");
    err
}

/// An unknown section in the mapping: the error is at `gmsh.groups.plate.section`.
#[test]
fn unknown_section_names_the_group() {
    let err = refused(
        "gmsh_unknown_section",
        &case("nope", r#"{"s": {"shape": "shell", "t": 1}}"#),
    );
    assert!(!err.contains("elements[0]"), "{err}");
}

/// A beam section given to a group of quadrangles: also at `gmsh.groups.plate.section`.
#[test]
fn wrong_section_kind_names_the_group() {
    refused(
        "gmsh_beam_section",
        &case("bar", r#"{"bar": {"shape": "rect", "w": 1, "h": 1}}"#),
    );
}

/// Second-order elements other than nine-node quadrangles (6-node triangles, 8-node
/// quadrangles, 3-node lines) are refused at `check`, by name, in a short message. Nine-node
/// quadrangles become `shell9` (`tests/shell9_cases.rs`); one whose nodes fold it (this file's
/// node order is not Gmsh's) is refused by its geometry.
#[test]
fn second_order_elements_are_refused_by_name() {
    let (code, err) = check(
        "gmsh_quad9_folded",
        one_element_msh(10, 9).as_bytes(),
        &case("s", r#"{"s": {"shape": "shell", "t": 1}}"#),
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("`gmsh.groups.plate`") && err.contains("valid quadrilateral"),
        "{err}"
    );
    for (kind, nodes, name) in [
        (9, 6, "6-node second-order triangle"),
        (16, 8, "8-node second-order quadrangle"),
        (8, 3, "3-node second-order line"),
    ] {
        let (code, err) = check(
            "gmsh_second_order",
            one_element_msh(kind, nodes).as_bytes(),
            &case("s", r#"{"s": {"shape": "shell", "t": 1}}"#),
        );
        assert_eq!(code, Some(2), "type {kind}: {err}");
        assert!(
            err.contains(name) && err.contains(&format!("Gmsh type {kind}")),
            "{err}"
        );
        assert!(err.contains("`gmsh.groups.plate`"), "{err}");
        assert!(err.contains("Mesh.ElementOrder = 1"), "{err}");
        assert!(err.len() < 1000, "short message: {} bytes", err.len());
    }
}

/// A binary MSH file (file-type 1 in `$MeshFormat`, then raw bytes) is refused as binary.
#[test]
fn binary_msh_is_said_to_be_unsupported() {
    let mut bytes = b"$MeshFormat\n4.1 1 8\n".to_vec();
    bytes.extend_from_slice(&[1, 0, 0, 0, 0xff, 0xfe, 0x80, 0x81]);
    bytes.extend_from_slice(b"\n$EndMeshFormat\n");
    let (code, err) = check(
        "gmsh_binary",
        &bytes,
        &case("s", r#"{"s": {"shape": "shell", "t": 1}}"#),
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("binary MSH files are not supported"), "{err}");
    assert!(err.contains("`mesh`"), "{err}");
    assert!(!err.contains("UTF-8"), "{err}");
}

/// The first-order version of the same mesh passes `check` (the refusals above are about the
/// element type, not the file).
#[test]
fn first_order_triangle_passes_check() {
    let (code, err) = check(
        "gmsh_first_order",
        one_element_msh(2, 3).as_bytes(),
        &case("s", r#"{"s": {"shape": "shell", "t": 1}}"#),
    );
    assert_eq!(code, Some(0), "{err}");
}
