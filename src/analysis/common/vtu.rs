//! `.vtu` files (ParaView) of FE models: static load cases and mode shapes.
//!
//! Points are the undeformed node coordinates; displacements go in as point data
//! (`displacement_mm`, `rotation_deg`), so ParaView's "Warp By Vector" shows the deformed shape
//! at any scale. Cells: one line per beam, flexure-hinge (flexibility) element and two-node
//! spring, one triangle or quad per shell (a shell given as `[a, b, c, c]` is a triangle), and
//! one line from the master to each slave of every rigid link. Cell data: `von_mises_MPa`,
//! `element` (index in the model's element list; −1 for rigid links and drawn parts) and `part`
//! ([`Part`]). Rigid bodies that are no elements (e.g. the stage's platform and sliders)
//! may be drawn as extra cells ([`Drawn`]).

use super::outcome::AnalysisError;
use crate::fem::{Element, Model};
use crate::report::vtk::{self, Cell, VtuMesh};

/// The `part` cell data of a `.vtu`: what a cell draws (its code, 1 … 6, is the variant's
/// discriminant).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Part {
    /// A beam element.
    Beam = 1,
    /// A flexure-hinge (flexibility) element.
    Hinge,
    /// A two-node spring.
    Spring,
    /// A shell element.
    Shell,
    /// A rigid-link line (master → slave).
    Rigid,
    /// A drawn rigid body that is no element of the model (e.g. a stage slider).
    Body,
}

impl Part {
    /// The code written as cell data.
    pub fn code(self) -> f64 {
        f64::from(self as u8)
    }
}

/// A line drawn from a model node to an extra point that belongs to the same rigid body and
/// has no rotational freedom relative to the ground (it translates with the node: e.g. a slider
/// guided along its rail with its rotations fixed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyLine {
    /// The node the body moves with.
    pub node: usize,
    /// The other end of the line, undeformed, mm.
    pub point: [f64; 3],
}

/// Rigid bodies drawn in addition to the model's elements (`part` = [`Part::Body`]).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Drawn {
    /// Lines from a node to an extra point moving with it.
    pub lines: Vec<BodyLine>,
    /// Cells among the model's nodes (e.g. a rigid platform's face through its joint nodes).
    pub cells: Vec<Cell>,
}

/// The cells of a model with their `element` and `part` cell data.
#[derive(Debug, Clone, Default)]
pub struct ModelCells {
    /// Cells in element order, then the rigid-link lines.
    pub cells: Vec<Cell>,
    /// Element index of each cell (−1 for rigid-link lines).
    pub element: Vec<f64>,
    /// Part code of each cell.
    pub part: Vec<f64>,
}

impl ModelCells {
    fn push(&mut self, cell: Cell, element: f64, part: Part) {
        self.cells.push(cell);
        self.element.push(element);
        self.part.push(part.code());
    }
}

/// Cells of `model` (see the module docs); point masses and one-node springs have none.
pub fn model_cells(model: &Model) -> ModelCells {
    let mut c = ModelCells::default();
    for (ie, e) in model.elements.iter().enumerate() {
        let ie = ie as f64;
        match e {
            Element::Beam(b) => c.push(Cell::Line(b.nodes), ie, Part::Beam),
            Element::Flex(f) => c.push(Cell::Line(f.nodes), ie, Part::Hinge),
            Element::Spring(s) => {
                if let Some(b) = s.b {
                    c.push(Cell::Line([s.a, b]), ie, Part::Spring);
                }
            }
            // Superelement pieces: matrices, no geometry to draw.
            Element::Matrix(_) => {}
            Element::Shell4(s) => {
                let n = s.nodes;
                let cell = if n[3] == n[2] {
                    Cell::Triangle([n[0], n[1], n[2]])
                } else {
                    Cell::Quad(n)
                };
                c.push(cell, ie, Part::Shell);
            }
            // Four bilinear cells through the edge midpoints and the centre, each tagged with
            // the element.
            Element::Shell9(s) => {
                let n = s.nodes;
                for q in [[0, 4, 8, 7], [4, 1, 5, 8], [8, 5, 2, 6], [7, 8, 6, 3]] {
                    c.push(Cell::Quad(q.map(|k| n[k])), ie, Part::Shell);
                }
            }
        }
    }
    for r in &model.rigid_links {
        for &s in &r.slaves {
            c.push(Cell::Line([r.master, s]), -1.0, Part::Rigid);
        }
    }
    c
}

/// Model cells plus the drawn bodies (extra points of body lines follow their nodes).
fn cells_with_bodies(model: &Model, drawn: &Drawn) -> (Vec<[f64; 3]>, ModelCells) {
    let mut points = model.nodes.clone();
    let mut c = model_cells(model);
    for cell in &drawn.cells {
        c.push(*cell, -1.0, Part::Body);
    }
    for b in &drawn.lines {
        points.push(b.point);
        c.push(Cell::Line([b.node, points.len() - 1]), -1.0, Part::Body);
    }
    (points, c)
}

/// Translations (mm) and rotations (degrees) of the points of [`cells_with_bodies`] from nodal
/// [ux, uy, uz, rx, ry, rz] (mm, rad); body points take their node's values.
fn point_data(n_nodes: usize, u: &[[f64; 6]], bodies: &[BodyLine]) -> (Vec<[f64; 3]>, Vec<[f64; 3]>) {
    let nodes = u[..n_nodes].iter().chain(bodies.iter().map(|b| &u[b.node]));
    nodes
        .map(|d| {
            (
                [d[0], d[1], d[2]],
                [d[3].to_degrees(), d[4].to_degrees(), d[5].to_degrees()],
            )
        })
        .unzip()
}

fn err(e: vtk::VtkError) -> AnalysisError {
    AnalysisError::new("vtu", e.to_string())
}

/// One static load case: `u` holds at least one row per model node ([ux, uy, uz (mm), rx, ry,
/// rz (rad)], global axes; rows beyond the model's nodes — e.g. nodes a nonlinear solve added
/// inside hinges — are not drawn); `von_mises(element)` gives the cell stress, MPa.
pub fn static_vtu(
    model: &Model,
    u: &[[f64; 6]],
    von_mises: &dyn Fn(usize) -> f64,
    drawn: &Drawn,
) -> Result<String, AnalysisError> {
    static_vtu_with_shells(model, u, von_mises, drawn, None)
}

/// [`static_vtu`] plus the shell stresses of the load case: point data
/// `shell_stress_top_MPa`, `shell_stress_mid_MPa`, `shell_stress_bottom_MPa` (symmetric
/// tensors, 6 components XX YY ZZ XY YZ XZ, global axes; 0 at points without shells) and cell
/// data `shell_N_N_per_mm` [Nxx, Nyy, Nxy], `shell_M_Nmm_per_mm` [Mxx, Myy, Mxy],
/// `shell_Q_N_per_mm` [Qx, Qy, 0] at the element centre in element axes, and those axes as
/// `shell_axis_x`, `shell_axis_y`, `shell_axis_z` (unit vectors, global; 0 for other cells).
pub fn static_vtu_with_shells(
    model: &Model,
    u: &[[f64; 6]],
    von_mises: &dyn Fn(usize) -> f64,
    drawn: &Drawn,
    shells: Option<&crate::fem::shell_recovery::ShellField>,
) -> Result<String, AnalysisError> {
    let n = model.nodes.len();
    if u.len() < n {
        return Err(AnalysisError::new(
            "vtu",
            format!("{} displacement rows for {n} nodes", u.len()),
        ));
    }
    let (points, c) = cells_with_bodies(model, drawn);
    let (disp, rot) = point_data(n, u, &drawn.lines);
    let vm: Vec<f64> = c
        .element
        .iter()
        .map(|&e| if e >= 0.0 { von_mises(e as usize) } else { 0.0 })
        .collect();
    let mut point_data: Vec<(&str, Vec<f64>)> = Vec::new();
    let mut cell_data: Vec<(&str, Vec<f64>)> = Vec::new();
    if let Some(f) = shells.filter(|f| !f.forces.is_empty()) {
        for (name, list) in [
            ("shell_stress_top_MPa", &f.top),
            ("shell_stress_mid_MPa", &f.mid),
            ("shell_stress_bottom_MPa", &f.bottom),
        ] {
            let mut v = vec![0.0; 6 * points.len()];
            for (i, s) in list.iter().enumerate().take(n) {
                if let Some(s) = s {
                    v[6 * i..6 * i + 6].copy_from_slice(s);
                }
            }
            point_data.push((name, v));
        }
        let mut by_element = vec![None; model.elements.len()];
        for (ie, sf) in &f.forces {
            if let Some(slot) = by_element.get_mut(*ie) {
                *slot = Some(*sf);
            }
        }
        type Pick = fn(&crate::fem::shell_recovery::ShellForces) -> [f64; 3];
        let picks: [(&str, Pick); 6] = [
            ("shell_N_N_per_mm", |s| s.n),
            ("shell_M_Nmm_per_mm", |s| s.m),
            ("shell_Q_N_per_mm", |s| [s.q[0], s.q[1], 0.0]),
            ("shell_axis_x", |s| s.axes[0]),
            ("shell_axis_y", |s| s.axes[1]),
            ("shell_axis_z", |s| s.axes[2]),
        ];
        for (name, pick) in picks {
            let v: Vec<f64> = c
                .element
                .iter()
                .flat_map(|&e| {
                    let sf = (e >= 0.0)
                        .then(|| by_element.get(e as usize).copied().flatten())
                        .flatten();
                    sf.map_or([0.0; 3], |s| pick(&s))
                })
                .collect();
            cell_data.push((name, v));
        }
    }
    vtk::to_string(&VtuMesh {
        points: &points,
        cells: &c.cells,
        point_vectors: vec![("displacement_mm", &disp), ("rotation_deg", &rot)],
        cell_scalars: vec![("von_mises_MPa", &vm), ("element", &c.element), ("part", &c.part)],
        point_arrays: point_data.iter().map(|(k, v)| (*k, 6, v.as_slice())).collect(),
        cell_arrays: cell_data.iter().map(|(k, v)| (*k, 3, v.as_slice())).collect(),
        ..Default::default()
    })
    .map_err(err)
}

/// Mode shapes: per mode its frequency (Hz) and shape (one [ux, uy, uz, rx, ry, rz] row per
/// node, mm and rad, global axes) → point vectors `mode_K_translation_mm` and
/// `mode_K_rotation_deg` (K from 1) and the field array `frequency_hz`.
pub fn modes_vtu(model: &Model, modes: &[(f64, &[[f64; 6]])], drawn: &Drawn) -> Result<Vec<u8>, AnalysisError> {
    modes_vtu_named(model, modes, drawn, "frequency_hz")
}

/// As [`modes_vtu`], the per-mode value under the field name `value` (e.g. `load_factor`).
pub fn modes_vtu_named(
    model: &Model,
    modes: &[(f64, &[[f64; 6]])],
    drawn: &Drawn,
    value: &str,
) -> Result<Vec<u8>, AnalysisError> {
    let n = model.nodes.len();
    let (points, c) = cells_with_bodies(model, drawn);
    let mut names = Vec::with_capacity(2 * modes.len());
    let mut data = Vec::with_capacity(2 * modes.len());
    for (k, (_, shape)) in modes.iter().enumerate() {
        if shape.len() < n {
            return Err(AnalysisError::new(
                "vtu",
                format!("mode {} has {} rows for {n} nodes", k + 1, shape.len()),
            ));
        }
        let (t, r) = point_data(n, shape, &drawn.lines);
        names.push(format!("mode_{}_translation_mm", k + 1));
        names.push(format!("mode_{}_rotation_deg", k + 1));
        data.push(t);
        data.push(r);
    }
    let freq: Vec<f64> = modes.iter().map(|m| m.0).collect();
    vtk::to_string(&VtuMesh {
        points: &points,
        cells: &c.cells,
        point_vectors: names
            .iter()
            .map(String::as_str)
            .zip(data.iter().map(Vec::as_slice))
            .collect(),
        cell_scalars: vec![("element", &c.element), ("part", &c.part)],
        field_scalars: vec![(value, &freq)],
        ..Default::default()
    })
    .map(String::into_bytes)
    .map_err(err)
}
