//! VTK unstructured-grid output (`.vtu`, ASCII XML) for beam/shell models: points, line and
//! quad cells, point vectors (displacement, rotation, mode shapes) and cell scalars (e.g. von
//! Mises). Formatting only — it takes
//! plain arrays and knows nothing about the physics.

use std::fmt::Write as _;
use std::io::Write;

/// Data for one `.vtu` file.
#[derive(Debug, Clone, Default)]
pub struct VtuMesh<'a> {
    /// Undeformed point coordinates, mm.
    pub points: &'a [[f64; 3]],
    /// Line cells as pairs of point indices.
    pub lines: &'a [[usize; 2]],
    /// Quad cells (shells), four point indices; written after the lines.
    pub quads: &'a [[usize; 4]],
    /// Further named point vectors (e.g. mode shapes), one per point.
    pub point_vectors: Vec<(&'a str, &'a [[f64; 3]])>,
    /// Point displacements, mm (`"displacement"`; empty = none).
    pub displacement: &'a [[f64; 3]],
    /// Point rotations, rad (`"rotation"`; empty = none).
    pub rotation: &'a [[f64; 3]],
    /// Named cell scalars, one value per cell (lines, then quads) (e.g. `("von_mises", …)` in MPa).
    pub cell_scalars: Vec<(&'a str, &'a [f64])>,
    /// Point coordinates written: undeformed + `deform_scale`·displacement (0 = undeformed).
    pub deform_scale: f64,
}

/// Errors of the writer: inconsistent array lengths or I/O.
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

/// Renders the `.vtu` XML.
pub fn to_string(mesh: &VtuMesh) -> Result<String, VtkError> {
    let np = mesh.points.len();
    let nc = mesh.lines.len() + mesh.quads.len();
    let mut named: Vec<(&str, usize)> = vec![
        ("displacement", mesh.displacement.len()),
        ("rotation", mesh.rotation.len()),
    ];
    named.extend(mesh.point_vectors.iter().map(|(n, v)| (*n, v.len())));
    for (name, len) in named {
        if len != 0 && len != np {
            return Err(VtkError::Shape(format!("{name} has {len} entries for {np} points")));
        }
    }
    if mesh.deform_scale != 0.0 && mesh.displacement.len() != np {
        return Err(VtkError::Shape("deformed output needs displacements".into()));
    }
    for (name, v) in &mesh.cell_scalars {
        if v.len() != nc {
            return Err(VtkError::Shape(format!(
                "cell data {name} has {} entries for {nc} cells",
                v.len()
            )));
        }
    }
    if let Some(l) = mesh.lines.iter().find(|l| l[0] >= np || l[1] >= np) {
        return Err(VtkError::Shape(format!(
            "line {l:?} refers to a missing point ({np} points)"
        )));
    }
    if let Some(q) = mesh.quads.iter().find(|q| q.iter().any(|&i| i >= np)) {
        return Err(VtkError::Shape(format!(
            "quad {q:?} refers to a missing point ({np} points)"
        )));
    }
    let mut out = String::new();
    out.push_str("<?xml version=\"1.0\"?>\n");
    out.push_str("<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n");
    out.push_str("  <UnstructuredGrid>\n");
    let _ = writeln!(out, "    <Piece NumberOfPoints=\"{np}\" NumberOfCells=\"{nc}\">");
    out.push_str("      <Points>\n");
    let pts: Vec<[f64; 3]> = mesh
        .points
        .iter()
        .enumerate()
        .map(|(i, p)| {
            if mesh.deform_scale != 0.0 {
                let d = mesh.displacement[i];
                std::array::from_fn(|k| p[k] + mesh.deform_scale * d[k])
            } else {
                *p
            }
        })
        .collect();
    vec3_array(&mut out, "Points", &pts);
    out.push_str("      </Points>\n      <Cells>\n");
    out.push_str("        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
    for l in mesh.lines {
        let _ = writeln!(out, "          {} {}", l[0], l[1]);
    }
    for q in mesh.quads {
        let _ = writeln!(out, "          {} {} {} {}", q[0], q[1], q[2], q[3]);
    }
    out.push_str("        </DataArray>\n");
    out.push_str("        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    let nl = mesh.lines.len();
    for i in 0..nc {
        let off = if i < nl { 2 * (i + 1) } else { 2 * nl + 4 * (i + 1 - nl) };
        let _ = writeln!(out, "          {off}");
    }
    out.push_str("        </DataArray>\n");
    out.push_str("        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
    for i in 0..nc {
        out.push_str(if i < nl { "          3\n" } else { "          9\n" }); // VTK_LINE, VTK_QUAD
    }
    out.push_str("        </DataArray>\n      </Cells>\n");
    out.push_str("      <PointData>\n");
    if !mesh.displacement.is_empty() {
        vec3_array(&mut out, "displacement", mesh.displacement);
    }
    if !mesh.rotation.is_empty() {
        vec3_array(&mut out, "rotation", mesh.rotation);
    }
    for (name, v) in &mesh.point_vectors {
        vec3_array(&mut out, name, v);
    }
    out.push_str("      </PointData>\n      <CellData>\n");
    for (name, v) in &mesh.cell_scalars {
        let _ = writeln!(
            out,
            "        <DataArray type=\"Float64\" Name=\"{name}\" format=\"ascii\">"
        );
        for x in v.iter() {
            let _ = writeln!(out, "          {x:e}");
        }
        out.push_str("        </DataArray>\n");
    }
    out.push_str("      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
    Ok(out)
}

/// Writes the `.vtu` XML to `w`.
pub fn write(w: &mut impl Write, mesh: &VtuMesh) -> Result<(), VtkError> {
    w.write_all(to_string(mesh)?.as_bytes())?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_lines_with_data() {
        let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]];
        let lines = [[0, 1], [1, 2]];
        let disp = [[0.0; 3], [0.0, 0.0, 0.5], [0.0, 0.0, 1.0]];
        let vm = [10.0, 5.0];
        let mesh = VtuMesh {
            points: &pts,
            lines: &lines,
            quads: &[],
            point_vectors: vec![],
            displacement: &disp,
            rotation: &[],
            cell_scalars: vec![("von_mises", &vm)],
            deform_scale: 2.0,
        };
        let s = to_string(&mesh).unwrap();
        assert!(s.contains("NumberOfPoints=\"3\" NumberOfCells=\"2\""));
        assert!(s.contains("2e0 0e0 2e0"), "deformed point: {s}");
        assert!(s.contains("Name=\"von_mises\""));
        let bad = VtuMesh {
            cell_scalars: vec![("von_mises", &vm[..1])],
            ..mesh
        };
        assert!(to_string(&bad).is_err());
    }

    #[test]
    fn quads_after_lines() {
        let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
        let mode = [[0.0, 0.0, 1.0]; 4];
        let mesh = VtuMesh {
            points: &pts,
            lines: &[[0, 1]],
            quads: &[[0, 1, 2, 3]],
            point_vectors: vec![("mode_1", &mode)],
            ..Default::default()
        };
        let s = to_string(&mesh).unwrap();
        assert!(s.contains("NumberOfCells=\"2\""));
        assert!(s.contains("          6\n"), "offset of the quad: {s}");
        assert!(s.contains("          9\n"));
        assert!(s.contains("Name=\"mode_1\""));
    }
}
