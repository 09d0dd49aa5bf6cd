//! VTK unstructured-grid output (`.vtu`, ASCII XML) for beam/shell models: the undeformed
//! points, line, triangle and quad cells, named point vectors (displacements, rotations, mode
//! shapes), cell scalars (e.g. von Mises) and field scalars (e.g. natural frequencies).
//! Formatting only — it takes plain arrays and knows nothing about the physics.
//!
//! Points are always the undeformed coordinates: ParaView's "Warp By Vector" filter adds a
//! displacement array itself, so writing deformed points as well would double the deformation.
//! Array names carry their unit (`displacement_mm`, `rotation_deg`, `von_mises_MPa`).

use std::fmt::Write as _;
use std::io::Write;

/// One cell, by VTK type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cell {
    /// `VTK_LINE` (3): two point indices.
    Line([usize; 2]),
    /// `VTK_TRIANGLE` (5): three point indices.
    Triangle([usize; 3]),
    /// `VTK_QUAD` (9): four point indices, listed around the quadrilateral.
    Quad([usize; 4]),
}

impl Cell {
    /// The point indices of the cell.
    pub fn points(&self) -> &[usize] {
        match self {
            Cell::Line(p) => p,
            Cell::Triangle(p) => p,
            Cell::Quad(p) => p,
        }
    }

    /// The VTK cell type number.
    pub fn vtk_type(&self) -> u8 {
        match self {
            Cell::Line(_) => 3,
            Cell::Triangle(_) => 5,
            Cell::Quad(_) => 9,
        }
    }
}

/// Data for one `.vtu` file.
#[derive(Debug, Clone, Default)]
pub struct VtuMesh<'a> {
    /// Undeformed point coordinates, mm.
    pub points: &'a [[f64; 3]],
    /// Cells, in the order the cell data lists them.
    pub cells: &'a [Cell],
    /// Named point vectors, one per point; the name carries the unit (`"displacement_mm"`).
    pub point_vectors: Vec<(&'a str, &'a [[f64; 3]])>,
    /// Named cell scalars, one per cell (e.g. `("von_mises_MPa", …)`).
    pub cell_scalars: Vec<(&'a str, &'a [f64])>,
    /// Named field scalars (any length), e.g. `("frequency_hz", …)` of the modes in the file.
    pub field_scalars: Vec<(&'a str, &'a [f64])>,
    /// Named point arrays of any number of components (name, components, values point by
    /// point): e.g. a symmetric stress tensor with 6 components in ParaView's order
    /// XX, YY, ZZ, XY, YZ, XZ.
    pub point_arrays: Vec<(&'a str, usize, &'a [f64])>,
    /// Named cell arrays of any number of components (name, components, values cell by cell).
    pub cell_arrays: Vec<(&'a str, usize, &'a [f64])>,
}

/// Errors of the writer: inconsistent arrays or I/O.
#[derive(Debug, thiserror::Error)]
pub enum VtkError {
    #[error("vtu: {0}")]
    Shape(String),
    #[error("vtu i/o: {0}")]
    Io(#[from] std::io::Error),
}

fn vec3_array(out: &mut String, name: &str, v: &[[f64; 3]]) {
    let _ = writeln!(
        out,
        "        <DataArray type=\"Float64\" Name=\"{name}\" NumberOfComponents=\"3\" format=\"ascii\">"
    );
    for p in v {
        let _ = writeln!(out, "          {:e} {:e} {:e}", p[0], p[1], p[2]);
    }
    out.push_str("        </DataArray>\n");
}

fn multi_array(out: &mut String, name: &str, ncomp: usize, v: &[f64]) {
    let _ = writeln!(
        out,
        "        <DataArray type=\"Float64\" Name=\"{name}\" NumberOfComponents=\"{ncomp}\" format=\"ascii\">"
    );
    for row in v.chunks(ncomp.max(1)) {
        let items: Vec<String> = row.iter().map(|x| format!("{x:e}")).collect();
        let _ = writeln!(out, "          {}", items.join(" "));
    }
    out.push_str("        </DataArray>\n");
}

fn check_multi(name: &str, ncomp: usize, v: &[f64], n: usize, what: &str) -> Result<(), VtkError> {
    if ncomp == 0 || v.len() != ncomp * n {
        return Err(VtkError::Shape(format!(
            "{name} has {} values for {n} {what} × {ncomp} components",
            v.len()
        )));
    }
    check_finite(name, v.iter())
}

fn scalar_array(out: &mut String, name: &str, v: &[f64], tuples: bool) {
    let n = if tuples {
        format!(" NumberOfTuples=\"{}\"", v.len())
    } else {
        String::new()
    };
    let _ = writeln!(
        out,
        "        <DataArray type=\"Float64\" Name=\"{name}\"{n} format=\"ascii\">"
    );
    for x in v {
        let _ = writeln!(out, "          {x:e}");
    }
    out.push_str("        </DataArray>\n");
}

fn check_name(name: &str, seen: &mut Vec<String>) -> Result<(), VtkError> {
    if name.is_empty() || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return Err(VtkError::Shape(format!(
            "array name {name:?}: only ASCII letters, digits and `_` are written"
        )));
    }
    if seen.iter().any(|s| s == name) {
        return Err(VtkError::Shape(format!("array name {name} is used twice")));
    }
    seen.push(name.to_string());
    Ok(())
}

fn check_finite<'a>(name: &str, values: impl Iterator<Item = &'a f64>) -> Result<(), VtkError> {
    for (i, v) in values.enumerate() {
        if !v.is_finite() {
            return Err(VtkError::Shape(format!("{name}: value {i} is {v} (not finite)")));
        }
    }
    Ok(())
}

/// Renders the `.vtu` XML.
pub fn to_string(mesh: &VtuMesh) -> Result<String, VtkError> {
    let np = mesh.points.len();
    let nc = mesh.cells.len();
    let mut seen = Vec::new();
    check_finite("points", mesh.points.iter().flatten())?;
    for (name, v) in &mesh.point_vectors {
        check_name(name, &mut seen)?;
        check_multi(name, 3, v.as_flattened(), np, "points")?;
    }
    for (name, v) in &mesh.cell_scalars {
        check_name(name, &mut seen)?;
        check_multi(name, 1, v, nc, "cells")?;
    }
    for (name, v) in &mesh.field_scalars {
        check_name(name, &mut seen)?;
        check_finite(name, v.iter())?;
    }
    for (name, k, v) in &mesh.point_arrays {
        check_name(name, &mut seen)?;
        check_multi(name, *k, v, np, "points")?;
    }
    for (name, k, v) in &mesh.cell_arrays {
        check_name(name, &mut seen)?;
        check_multi(name, *k, v, nc, "cells")?;
    }
    if let Some(c) = mesh.cells.iter().find(|c| c.points().iter().any(|&i| i >= np)) {
        return Err(VtkError::Shape(format!(
            "cell {c:?} refers to a missing point ({np} points)"
        )));
    }
    let mut out = String::new();
    out.push_str("<?xml version=\"1.0\"?>\n");
    out.push_str("<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n");
    out.push_str("  <UnstructuredGrid>\n");
    if !mesh.field_scalars.is_empty() {
        out.push_str("    <FieldData>\n");
        for (name, v) in &mesh.field_scalars {
            scalar_array(&mut out, name, v, true);
        }
        out.push_str("    </FieldData>\n");
    }
    let _ = writeln!(out, "    <Piece NumberOfPoints=\"{np}\" NumberOfCells=\"{nc}\">");
    out.push_str("      <Points>\n");
    vec3_array(&mut out, "Points", mesh.points);
    out.push_str("      </Points>\n      <Cells>\n");
    out.push_str("        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
    for c in mesh.cells {
        let ids: Vec<String> = c.points().iter().map(usize::to_string).collect();
        let _ = writeln!(out, "          {}", ids.join(" "));
    }
    out.push_str("        </DataArray>\n");
    out.push_str("        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    let mut off = 0;
    for c in mesh.cells {
        off += c.points().len();
        let _ = writeln!(out, "          {off}");
    }
    out.push_str("        </DataArray>\n");
    out.push_str("        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
    for c in mesh.cells {
        let _ = writeln!(out, "          {}", c.vtk_type());
    }
    out.push_str("        </DataArray>\n      </Cells>\n");
    out.push_str("      <PointData>\n");
    for (name, v) in &mesh.point_vectors {
        vec3_array(&mut out, name, v);
    }
    for (name, k, v) in &mesh.point_arrays {
        multi_array(&mut out, name, *k, v);
    }
    out.push_str("      </PointData>\n      <CellData>\n");
    for (name, v) in &mesh.cell_scalars {
        scalar_array(&mut out, name, v, false);
    }
    for (name, k, v) in &mesh.cell_arrays {
        multi_array(&mut out, name, *k, v);
    }
    out.push_str("      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
    Ok(out)
}

/// Writes the `.vtu` XML to `w`.
pub fn write(w: &mut impl Write, mesh: &VtuMesh) -> Result<(), VtkError> {
    w.write_all(to_string(mesh)?.as_bytes())?;
    Ok(())
}

/// A file name made of the safe characters of `name` (others become `_`; empty → `case`).
pub fn file_stem(name: &str) -> String {
    stem_chars(name).collect()
}

/// The characters of [`file_stem`], without building it.
fn stem_chars(name: &str) -> impl Iterator<Item = char> + '_ {
    let name = if name.is_empty() { "case" } else { name };
    name.chars().map(|c| {
        if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
            c
        } else {
            '_'
        }
    })
}

/// Whether two names give the same [`file_stem`] (compared without allocating).
pub fn same_file_stem(a: &str, b: &str) -> bool {
    stem_chars(a).eq(stem_chars(b))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A mesh of these points and cells with no data yet.
    fn geometry<'a>(points: &'a [[f64; 3]], cells: &'a [Cell]) -> VtuMesh<'a> {
        VtuMesh {
            points,
            cells,
            ..Default::default()
        }
    }

    #[test]
    fn points_stay_undeformed_with_displacement_data() {
        let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]];
        let cells = [Cell::Line([0, 1]), Cell::Line([1, 2])];
        let disp = [[0.0; 3], [0.0, 0.0, 0.5], [0.0, 0.0, 1.0]];
        let vm = [10.0, 5.0];
        let mesh = VtuMesh {
            point_vectors: vec![("displacement_mm", &disp)],
            cell_scalars: vec![("von_mises_MPa", &vm)],
            ..geometry(&pts, &cells)
        };
        let s = to_string(&mesh).unwrap();
        assert!(s.contains("NumberOfPoints=\"3\" NumberOfCells=\"2\""));
        assert!(s.contains("          2e0 0e0 0e0\n"), "undeformed point: {s}");
        assert!(!s.contains("2e0 0e0 1e0"), "deformed point written: {s}");
        assert!(s.contains("Name=\"von_mises_MPa\""));
        let bad = VtuMesh {
            cell_scalars: vec![("von_mises_MPa", &vm[..1])],
            ..mesh.clone()
        };
        assert!(to_string(&bad).is_err());
        let nan = [f64::NAN, 1.0];
        let bad = VtuMesh {
            cell_scalars: vec![("von_mises_MPa", &nan)],
            ..mesh.clone()
        };
        assert!(to_string(&bad).unwrap_err().to_string().contains("von_mises_MPa"));
        let twice = VtuMesh {
            point_vectors: vec![("d", &disp), ("d", &disp)],
            ..mesh
        };
        assert!(to_string(&twice).is_err());
    }

    #[test]
    fn lines_triangles_quads_and_field_data() {
        let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
        let mode = [[0.0, 0.0, 1.0]; 4];
        let f = [12.5];
        let cells = [Cell::Line([0, 1]), Cell::Triangle([0, 1, 2]), Cell::Quad([0, 1, 2, 3])];
        let mut mesh = geometry(&pts, &cells);
        mesh.point_vectors.push(("mode_1_translation_mm", &mode));
        mesh.field_scalars.push(("frequency_hz", &f));
        let s = to_string(&mesh).unwrap();
        assert!(s.contains("NumberOfCells=\"3\""));
        // Offsets 2, 5, 9; types line, triangle, quad.
        assert!(s.contains("          2\n          5\n          9\n"), "offsets: {s}");
        assert!(s.contains("          3\n          5\n          9\n"), "types: {s}");
        assert!(s.contains("Name=\"frequency_hz\" NumberOfTuples=\"1\""));
        assert!(s.contains("Name=\"mode_1_translation_mm\""));
    }
}
