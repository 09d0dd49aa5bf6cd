//! The `static` analysis on a generic beam model.

use super::{AnalysisError, Report};
use crate::fem::{self, Model};
use crate::report::markdown::Table;
use serde::Serialize;

/// One load case of a `static` result (INTERFACE.md).
#[derive(Debug, Clone, Serialize)]
pub struct StaticCaseRow {
    /// Load-case name.
    pub name: String,
    /// Per node [ux, uy, uz (mm), rx, ry, rz (degrees)], global axes.
    pub displacements: Vec<[f64; 6]>,
    /// Per supported node [Fx, Fy, Fz (N), Mx, My, Mz (N·mm)], in the order of `reaction_nodes`.
    pub reactions: Vec<[f64; 6]>,
    /// The supported nodes, ascending.
    pub reaction_nodes: Vec<usize>,
    /// Largest von Mises stress over all beams, MPa (`null` when no element has a stress).
    pub max_von_mises: Option<f64>,
    /// Largest von Mises stress per element, MPa (`null` for springs).
    pub element_von_mises: Vec<Option<f64>>,
    /// Sum of loads plus reactions (should vanish): [N, N, N, N·mm, N·mm, N·mm].
    pub equilibrium_residual: [f64; 6],
}

/// Result of the `static` analysis.
#[derive(Debug, Clone, Serialize)]
pub struct StaticResult {
    /// Load cases in input order.
    pub load_cases: Vec<StaticCaseRow>,
    /// Units of the output arrays.
    pub units: Units,
    /// Model notes.
    pub model: Vec<String>,
}

/// Units of the `static` result.
#[derive(Debug, Clone, Serialize)]
pub struct Units {
    /// Units of each displacement entry.
    pub displacements: &'static str,
    /// Units of each reaction entry.
    pub reactions: &'static str,
}

/// Solves every load case of the model.
pub fn solve(model: &Model) -> Result<(StaticResult, fem::StaticResults), AnalysisError> {
    let res = fem::solve_static(model).map_err(|e| AnalysisError::new("model", e.to_string()))?;
    let rows = res
        .load_cases
        .iter()
        .map(|c| StaticCaseRow {
            name: c.name.clone(),
            displacements: c
                .displacements
                .iter()
                .map(|d| {
                    [
                        d[0],
                        d[1],
                        d[2],
                        d[3].to_degrees(),
                        d[4].to_degrees(),
                        d[5].to_degrees(),
                    ]
                })
                .collect(),
            reactions: c.reactions.iter().map(|(_, r)| *r).collect(),
            reaction_nodes: c.reactions.iter().map(|(n, _)| *n).collect(),
            max_von_mises: c.max_von_mises,
            element_von_mises: c.elements.iter().map(|e| e.max_von_mises()).collect(),
            equilibrium_residual: c.statics.residual(),
        })
        .collect();
    let notes = vec![
        "linear statics, small displacements".to_string(),
        "beams: 2-node exact Timoshenko (Euler–Bernoulli where \"shear\": false); stresses at section critical points"
            .to_string(),
    ];
    Ok((
        StaticResult {
            load_cases: rows,
            units: Units {
                displacements: "mm, mm, mm, deg, deg, deg",
                reactions: "N, N, N, N·mm, N·mm, N·mm",
            },
            model: notes,
        },
        res,
    ))
}

/// Geometrically nonlinear statics of every load case in `steps` load steps. Rotations in the
/// output are the components of each node's rotation vector (degrees).
pub fn solve_nonlinear(model: &Model, steps: usize) -> Result<StaticResult, AnalysisError> {
    let opts = fem::NonlinearOptions {
        steps,
        ..Default::default()
    };
    let res = fem::solve_nonlinear(model, &opts).map_err(|e| AnalysisError::new("model", e.to_string()))?;
    let rows = res.load_cases.iter().map(|c| row(&c.fe)).collect();
    Ok(StaticResult {
        load_cases: rows,
        units: Units {
            displacements: "mm, mm, mm, deg, deg, deg (rotation vector)",
            reactions: "N, N, N, N·mm, N·mm, N·mm",
        },
        model: vec![
            format!("geometrically nonlinear statics (large displacements and rotations, small strains), Newton-Raphson in {steps} load steps; loads fixed in direction"),
            "beams and flexibility elements: co-rotational, local linear element (exact Timoshenko); rigid links exact under finite rotation; springs linear (small rotations)".to_string(),
            "stresses from the section forces in the deformed element frames".to_string(),
        ],
    })
}

fn row(c: &fem::CaseResult) -> StaticCaseRow {
    StaticCaseRow {
        name: c.name.clone(),
        displacements: c
            .displacements
            .iter()
            .map(|d| {
                [
                    d[0],
                    d[1],
                    d[2],
                    d[3].to_degrees(),
                    d[4].to_degrees(),
                    d[5].to_degrees(),
                ]
            })
            .collect(),
        reactions: c.reactions.iter().map(|(_, r)| *r).collect(),
        reaction_nodes: c.reactions.iter().map(|(n, _)| *n).collect(),
        max_von_mises: c.max_von_mises,
        element_von_mises: c.elements.iter().map(|e| e.max_von_mises()).collect(),
        equilibrium_residual: c.statics.residual(),
    }
}

/// Markdown/CSV views.
pub fn report(r: &StaticResult) -> Report {
    let nonlinear = r
        .model
        .first()
        .is_some_and(|m| m.starts_with("geometrically nonlinear"));
    let mut md = String::from(if nonlinear {
        "# Geometrically nonlinear static analysis\n\n"
    } else {
        "# Linear static analysis\n\n"
    });
    let mut csv = String::from("load_case,node,ux_mm,uy_mm,uz_mm,rx_deg,ry_deg,rz_deg\n");
    for c in &r.load_cases {
        md += &format!("## Load case `{}`\n\n", c.name);
        if let Some(s) = c.max_von_mises {
            md += &format!("Maximum von Mises stress: {s:.3} MPa.\n\n");
        }
        let mut t = Table::new(&["node", "ux (mm)", "uy (mm)", "uz (mm)", "rx (°)", "ry (°)", "rz (°)"]);
        for (i, d) in c.displacements.iter().enumerate() {
            let mut row = vec![i.to_string()];
            row.extend(d.iter().map(|v| format!("{v:.6e}")));
            t.row(row);
            csv += &format!("{},{i},{},{},{},{},{},{}\n", c.name, d[0], d[1], d[2], d[3], d[4], d[5]);
        }
        if c.displacements.len() <= 200 {
            md += &t.render();
        } else {
            md += &format!("({} nodes: see result.csv)\n", c.displacements.len());
        }
        md += "\n";
    }
    Report { markdown: md, csv }
}

/// A `.vtu` of one load case: deformed shape (true scale), displacement and rotation point
/// data, and von Mises per element (`cell_stress` overrides the beam values, e.g. hinge peak
/// stresses; missing values are 0). Ground springs are not drawn.
pub fn vtu(model: &Model, case: &fem::CaseResult, cell_stress: &[(usize, f64)]) -> Result<String, AnalysisError> {
    let mut lines = Vec::new();
    let mut vm = Vec::new();
    for (ie, e) in model.elements.iter().enumerate() {
        let nodes = e.nodes();
        if nodes.len() == 2 {
            lines.push([nodes[0], nodes[1]]);
            let v = cell_stress
                .iter()
                .find(|(i, _)| *i == ie)
                .map(|(_, v)| *v)
                .or_else(|| case.elements.get(ie).and_then(|r| r.max_von_mises()))
                .unwrap_or(0.0);
            vm.push(v);
        }
    }
    let disp: Vec<[f64; 3]> = case.displacements.iter().map(|d| [d[0], d[1], d[2]]).collect();
    let rot: Vec<[f64; 3]> = case.displacements.iter().map(|d| [d[3], d[4], d[5]]).collect();
    let mesh = crate::report::vtk::VtuMesh {
        points: &model.nodes,
        lines: &lines,
        displacement: &disp,
        rotation: &rot,
        cell_scalars: vec![("von_mises", &vm)],
        deform_scale: 1.0,
    };
    crate::report::vtk::to_string(&mesh).map_err(|e| AnalysisError::new("vtu", e.to_string()))
}

/// A file name made of the safe characters of `name`.
pub fn file_stem(name: &str) -> String {
    let s: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect();
    if s.is_empty() {
        "case".into()
    } else {
        s
    }
}
