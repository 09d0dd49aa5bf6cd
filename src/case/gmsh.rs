//! Gmsh `.msh` version 4 ASCII import (format 4.1, <https://gmsh.info/doc/texinfo/gmsh.html#MSH-file-format>):
//! nodes, 2-node lines, 3-node triangles and 4-node quadrangles, plus points, mapped through
//! their physical groups to sections, materials and supports by a JSON mapping:
//!
//! ```json
//! "mesh": "meshes/plate.msh",
//! "gmsh": {"groups": {"skin":  {"section": "plate", "material": "al"},
//!                     "rib":   {"section": "rib", "material": "al", "up": [0, 0, 1]},
//!                     "clamp": {"fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}}}
//! ```
//! Lines become beams, quads `shell4`, triangles `shell4` with the third node repeated (a
//! degenerate quadrilateral: conforming, but stiffer than a real triangle — prefer quads).
//! A group with `fix` supports every node of its entities. Elements of groups not in the
//! mapping, and points, are skipped (counted in the notes); any other element type in a group
//! with a section (second-order lines, triangles and quadrangles, volume elements) is refused
//! by name. Binary `.msh` files are refused (save as ASCII). Gmsh node tags are renumbered
//! densely in file order.

use super::error::CaseError;
use super::mesh::load_shapes::DofName;
use super::mesh::shapes::{ElementSpec, MeshSpec, SupportSpec};
use std::collections::{BTreeMap, HashMap};

pub use super::mesh::shapes::{GmshMapping, GroupSpec};

struct Lines<'a> {
    it: std::iter::Enumerate<std::str::Lines<'a>>,
    line: usize,
}

impl<'a> Lines<'a> {
    fn next(&mut self) -> Result<&'a str, CaseError> {
        for (i, l) in self.it.by_ref() {
            self.line = i + 1;
            let t = l.trim();
            if !t.is_empty() {
                return Ok(t);
            }
        }
        Err(CaseError::new("mesh", "unexpected end of the .msh file"))
    }
}

fn nums<T: std::str::FromStr>(s: &str, line: usize) -> Result<Vec<T>, CaseError> {
    s.split_whitespace()
        .map(|w| {
            w.parse::<T>()
                .map_err(|_| CaseError::new("mesh", format!(".msh line {line}: cannot read number {w:?}")))
        })
        .collect()
}

fn need<T: Copy>(v: &[T], k: usize, line: usize) -> Result<T, CaseError> {
    v.get(k)
        .copied()
        .ok_or_else(|| CaseError::new("mesh", format!(".msh line {line}: too few values")))
}

/// One element read from the file: its Gmsh type, node tags and (dim, entity tag).
struct RawElement {
    kind: usize,
    nodes: Vec<usize>,
    entity: (usize, i64),
}

/// Name of a Gmsh element type (Gmsh reference manual, "MSH file format", element types).
pub fn element_type_name(kind: usize) -> String {
    let name = match kind {
        1 => "2-node line",
        2 => "3-node triangle",
        3 => "4-node quadrangle",
        4 => "4-node tetrahedron",
        5 => "8-node hexahedron",
        6 => "6-node prism",
        7 => "5-node pyramid",
        8 => "3-node second-order line",
        9 => "6-node second-order triangle",
        10 => "9-node second-order quadrangle",
        11 => "10-node second-order tetrahedron",
        12 => "27-node second-order hexahedron",
        13 => "18-node second-order prism",
        14 => "14-node second-order pyramid",
        15 => "1-node point",
        16 => "8-node second-order quadrangle",
        17 => "20-node second-order hexahedron",
        18 => "15-node second-order prism",
        19 => "13-node second-order pyramid",
        20 => "9-node third-order triangle (incomplete)",
        21 => "10-node third-order triangle",
        26 => "4-node third-order line",
        27 => "5-node fourth-order line",
        28 => "6-node fifth-order line",
        29 => "20-node third-order tetrahedron",
        36 => "16-node third-order quadrangle",
        _ => "higher-order or special element",
    };
    format!("{name} (Gmsh type {kind})")
}

/// The text of a `.msh` file: refuses binary files (Gmsh's binary MSH, file-type 1 in
/// `$MeshFormat`) and anything that is not UTF-8 text, saying which.
pub fn msh_text(bytes: &[u8]) -> Result<&str, CaseError> {
    // The header is ASCII even in binary files: "$MeshFormat\nversion file-type data-size\n".
    let head = &bytes[..bytes.len().min(256)];
    let head = String::from_utf8_lossy(head);
    let mut lines = head.lines().map(str::trim).filter(|l| !l.is_empty());
    if lines.next() == Some("$MeshFormat") {
        if let Some(l) = lines.next() {
            if l.split_whitespace().nth(1) == Some("1") {
                return Err(CaseError::value(
                    "mesh",
                    format!("\"{l}\""),
                    "binary MSH files are not supported: save the mesh as ASCII (Gmsh: Mesh.Binary = 0, Mesh.MshFileVersion = 4.1)",
                ));
            }
        }
    }
    std::str::from_utf8(bytes).map_err(|e| {
        CaseError::new(
            "mesh",
            format!("the .msh file is not text ({e}); flexfem reads Gmsh MSH 4.1 ASCII files"),
        )
    })
}

/// Maps an error in the model built from a `.msh` file to the user's mapping: an error at
/// `elements[k].FIELD` of an element built from physical group G becomes
/// `gmsh.groups.G.FIELD` (the user wrote the section and material there, not per element).
pub fn group_error(e: CaseError, origin: &[String], file: &str) -> CaseError {
    let Some(rest) = e.path.strip_prefix("elements[") else {
        return e;
    };
    let Some((idx, field)) = rest.split_once(']') else {
        return e;
    };
    let Some(group) = idx.parse::<usize>().ok().and_then(|k| origin.get(k)) else {
        return e;
    };
    let field = field.trim_start_matches('.');
    let key = field.split(['.', '[']).next().unwrap_or("");
    if matches!(key, "section" | "material" | "up") {
        CaseError::new(format!("gmsh.groups.{group}.{field}"), e.message)
    } else {
        CaseError::new(
            format!("gmsh.groups.{group}"),
            format!("element {idx} of {file} (group \"{group}\"), `{field}`: {}", e.message),
        )
    }
}

/// Parses the text of a `.msh` 4.x ASCII file and builds the model part of a case.
pub fn parse_msh(text: &str, mapping: &GmshMapping) -> Result<(MeshSpec, Vec<String>), CaseError> {
    parse_msh_traced(text, mapping).map(|(spec, notes, _)| (spec, notes))
}

/// [`parse_msh`], plus the physical group each built element comes from (for error paths).
pub fn parse_msh_traced(text: &str, mapping: &GmshMapping) -> Result<(MeshSpec, Vec<String>, Vec<String>), CaseError> {
    let mut lines = Lines {
        it: text.lines().enumerate(),
        line: 0,
    };
    let mut names: HashMap<(usize, i64), String> = HashMap::new();
    let mut entity_groups: HashMap<(usize, i64), Vec<i64>> = HashMap::new();
    let mut node_tags: Vec<usize> = Vec::new();
    let mut coords: Vec<[f64; 3]> = Vec::new();
    let mut elements: Vec<RawElement> = Vec::new();
    let mut version_ok = false;
    while let Ok(head) = lines.next() {
        match head {
            "$MeshFormat" => {
                let l = lines.next()?;
                let v: Vec<&str> = l.split_whitespace().collect();
                let ver: f64 = v.first().and_then(|s| s.parse().ok()).unwrap_or(0.0);
                if !(4.0..5.0).contains(&ver) || v.get(1) != Some(&"0") {
                    return Err(CaseError::value(
                        "mesh",
                        format!("\"{l}\""),
                        "only Gmsh MSH version 4 ASCII files are read (save with Mesh.MshFileVersion = 4.1, binary off)",
                    ));
                }
                version_ok = true;
            }
            "$PhysicalNames" => {
                let n: usize = need(&nums::<usize>(lines.next()?, lines.line)?, 0, lines.line)?;
                for _ in 0..n {
                    let l = lines.next()?;
                    let mut parts = l.splitn(3, char::is_whitespace);
                    let dim: usize = parts.next().and_then(|s| s.parse().ok()).unwrap_or(9);
                    let tag: i64 = parts.next().and_then(|s| s.trim().parse().ok()).unwrap_or(0);
                    let name = parts.next().unwrap_or("").trim().trim_matches('"').to_string();
                    names.insert((dim, tag), name);
                }
            }
            "$Entities" => {
                let counts: Vec<usize> = nums(lines.next()?, lines.line)?;
                for dim in 0..4 {
                    for _ in 0..need(&counts, dim, lines.line)? {
                        let v: Vec<f64> = nums(lines.next()?, lines.line)?;
                        // points: tag x y z nPhys phys…; others: tag minx miny minz maxx maxy maxz nPhys phys… nBound …
                        let at = if dim == 0 { 4 } else { 7 };
                        let tag = need(&v, 0, lines.line)? as i64;
                        let np = need(&v, at, lines.line)? as usize;
                        let phys: Vec<i64> = (0..np)
                            .map(|k| need(&v, at + 1 + k, lines.line).map(|x| x as i64))
                            .collect::<Result<_, _>>()?;
                        entity_groups.insert((dim, tag), phys);
                    }
                }
            }
            "$Nodes" => {
                let h: Vec<usize> = nums(lines.next()?, lines.line)?;
                let blocks = need(&h, 0, lines.line)?;
                // numEntityBlocks numNodes minNodeTag maxNodeTag: refuse before reading.
                super::limits::check_nodes("mesh", need(&h, 1, lines.line)?)?;
                for _ in 0..blocks {
                    let b: Vec<i64> = nums(lines.next()?, lines.line)?;
                    if need(&b, 2, lines.line)? != 0 {
                        return Err(CaseError::new(
                            "mesh",
                            format!(".msh line {}: parametric nodes are not supported", lines.line),
                        ));
                    }
                    let n = need(&b, 3, lines.line)? as usize;
                    let start = node_tags.len();
                    for _ in 0..n {
                        let t: Vec<usize> = nums(lines.next()?, lines.line)?;
                        node_tags.push(need(&t, 0, lines.line)?);
                    }
                    for k in 0..n {
                        let x: Vec<f64> = nums(lines.next()?, lines.line)?;
                        if x.len() < 3 || x.iter().any(|v| !v.is_finite()) {
                            return Err(CaseError::new(
                                "mesh",
                                format!(
                                    ".msh line {}: node {} needs three finite coordinates",
                                    lines.line,
                                    node_tags[start + k]
                                ),
                            ));
                        }
                        coords.push([x[0], x[1], x[2]]);
                    }
                }
            }
            "$Elements" => {
                let h: Vec<usize> = nums(lines.next()?, lines.line)?;
                for _ in 0..need(&h, 0, lines.line)? {
                    let b: Vec<i64> = nums(lines.next()?, lines.line)?;
                    let (dim, tag, kind, n) = (
                        need(&b, 0, lines.line)? as usize,
                        need(&b, 1, lines.line)?,
                        need(&b, 2, lines.line)? as usize,
                        need(&b, 3, lines.line)? as usize,
                    );
                    for _ in 0..n {
                        let v: Vec<usize> = nums(lines.next()?, lines.line)?;
                        elements.push(RawElement {
                            kind,
                            nodes: v.get(1..).map(|s| s.to_vec()).unwrap_or_default(),
                            entity: (dim, tag),
                        });
                    }
                }
            }
            _ => {
                if let Some(name) = head.strip_prefix('$') {
                    if !name.starts_with("End") {
                        // Unknown section: skip to its end.
                        let end = format!("$End{name}");
                        while lines.next()? != end {}
                    }
                }
            }
        }
    }
    if !version_ok {
        return Err(CaseError::new("mesh", "not a Gmsh .msh file (no $MeshFormat section)"));
    }
    for (gname, _) in mapping.groups.iter() {
        if !names.values().any(|n| n == gname) {
            let known: Vec<&String> = names.values().collect();
            return Err(CaseError::value(
                format!("gmsh.groups.{gname}"),
                format!("\"{gname}\""),
                format!("no physical group of that name in the .msh file; it has {known:?}"),
            ));
        }
    }
    let mut index: HashMap<usize, usize> = HashMap::with_capacity(node_tags.len());
    for (i, &t) in node_tags.iter().enumerate() {
        if let Some(first) = index.insert(t, i) {
            return Err(CaseError::new(
                "mesh",
                format!(
                    ".msh $Nodes defines node tag {t} twice (the {}th and the {}th node): each node tag must be unique",
                    first + 1,
                    i + 1
                ),
            ));
        }
    }
    let mut spec = MeshSpec {
        nodes: coords,
        ..Default::default()
    };
    let mut skipped = 0usize;
    let mut origin: Vec<String> = Vec::new();
    let mut fixed: BTreeMap<usize, Vec<DofName>> = BTreeMap::new();
    for (ie, e) in elements.iter().enumerate() {
        let groups: Vec<(&String, &GroupSpec)> = entity_groups
            .get(&e.entity)
            .map(|ps| {
                ps.iter()
                    .filter_map(|p| {
                        names
                            .get(&(e.entity.0, *p))
                            .or_else(|| names.get(&(e.entity.0, p.abs())))
                    })
                    .filter_map(|n| mapping.groups.get_key_value(n))
                    .collect()
            })
            .unwrap_or_default();
        let mut nodes = Vec::with_capacity(e.nodes.len());
        for t in &e.nodes {
            nodes.push(*index.get(t).ok_or_else(|| {
                CaseError::new(
                    "mesh",
                    format!(".msh element {ie} refers to node tag {t}, which is not in $Nodes"),
                )
            })?);
        }
        if groups.is_empty() {
            skipped += 1;
            continue;
        }
        if matches!((e.kind, nodes.len()), (15, 1) | (1, 2) | (2, 3) | (3, 4)) {
            for &(gname, _) in &groups {
                spec.group_cells.entry(gname.clone()).or_default().push(nodes.clone());
            }
        }
        for &(gname, g) in &groups {
            if !g.fix.is_empty() {
                for &n in &nodes {
                    fixed.entry(n).or_default().extend(g.fix.iter().copied());
                }
            }
            let (Some(section), Some(material)) = (&g.section, &g.material) else {
                continue;
            };
            let el = match (e.kind, nodes.len()) {
                (1, 2) => ElementSpec::Beam {
                    nodes: [nodes[0], nodes[1]],
                    section: section.clone(),
                    material: material.clone(),
                    up: g.up.unwrap_or([0.0, 0.0, 1.0]),
                    shear: true,
                },
                (2, 3) => ElementSpec::Shell4 {
                    nodes: [nodes[0], nodes[1], nodes[2], nodes[2]],
                    section: section.clone(),
                    material: material.clone(),
                },
                (3, 4) => ElementSpec::Shell4 {
                    nodes: [nodes[0], nodes[1], nodes[2], nodes[3]],
                    section: section.clone(),
                    material: material.clone(),
                },
                // Gmsh's nine-node quadrangle has the node order of `shell9`.
                (10, 9) => ElementSpec::Shell9 {
                    nodes: std::array::from_fn(|k| nodes[k]),
                    section: section.clone(),
                    material: material.clone(),
                },
                (15, _) => {
                    skipped += 1;
                    continue;
                }
                (kind, n) => {
                    let what = if [1, 2, 3].contains(&kind) {
                        format!("a {} with {n} nodes", element_type_name(kind))
                    } else {
                        format!("{}s", element_type_name(kind))
                    };
                    return Err(CaseError::new(
                        format!("gmsh.groups.{gname}"),
                        format!(
                            "the group has {what} (.msh element {ie}); flexfem builds beams from 2-node lines and shells from 3-node triangles, 4-node quadrangles (shell4) and 9-node quadrangles (shell9) only: mesh this group with first-order elements (Gmsh: Mesh.ElementOrder = 1) or second-order quadrangles (Mesh.ElementOrder = 2, Mesh.RecombineAll = 1, Mesh.SecondOrderIncomplete = 0), and no volume elements in a group with a section"
                        ),
                    ));
                }
            };
            spec.elements.push(el);
            spec.element_groups
                .push(groups.iter().map(|(n, _)| (*n).clone()).collect());
            origin.push(gname.clone());
        }
    }
    for (node, mut fix) in fixed {
        fix.sort_by_key(|d| *d as u8);
        fix.dedup();
        spec.supports.push(SupportSpec {
            node,
            fix,
            frame: None,
            axis: None,
        });
    }
    let notes = vec![format!(
        "gmsh: {} nodes, {} elements built, {} skipped (no mapped group, or points); triangles as degenerate quads",
        spec.nodes.len(),
        spec.elements.len(),
        skipped
    )];
    Ok((spec, notes, origin))
}
