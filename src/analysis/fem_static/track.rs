//! `"track"` of a nonlinear `static` case: natural frequencies and node compliances (support
//! stiffness) at every accepted load step, with the tangent stiffness of the deformed state
//! ([`crate::fem::StepTrack`]); their JSON rows, Markdown table, CSV and SVG plot.

use super::compliance::{compliance_row, ComplianceRow};
use crate::case::mesh::TrackRequest;
use crate::fem::{self, Dof, LoadCase, Model, NodeDof};
use crate::report::markdown::{sig, Table};
use crate::report::svg;
use serde::Serialize;

/// The tracked quantities of one load case.
#[derive(Debug, Clone, Serialize)]
pub struct TrackRow {
    /// What `stroke` measures: a node DOF (global axes; mm, or degrees for rotations) — the
    /// load case's first prescribed displacement, else the first loaded node along its
    /// largest load component — or the load factor when the load case has neither.
    pub stroke: String,
    /// One entry per accepted load step, from the undeformed state (λ = 0) to λ = 1.
    pub steps: Vec<TrackStep>,
}

/// The tracked quantities at one accepted load step.
#[derive(Debug, Clone, Serialize)]
pub struct TrackStep {
    /// Load factor λ.
    pub lambda: f64,
    /// The stroke (see [`TrackRow::stroke`]): mm, degrees, or λ.
    pub stroke: f64,
    /// Whether the state is stable (positive definite tangent stiffness, reached without a
    /// jump).
    pub stable: bool,
    /// The lowest natural frequencies about the deformed state, Hz, ascending (negative:
    /// −√(−ω²)/2π, an unstable state).
    pub frequencies_hz: Vec<f64>,
    /// Per tracked node: its compliance with the tangent stiffness of the deformed state (DOFs
    /// the load case prescribes are held: their rows and columns are zero).
    pub compliance: Vec<TrackCompliance>,
}

/// The compliance of one node at one step, and its support stiffness.
#[derive(Debug, Clone, Serialize)]
pub struct TrackCompliance {
    #[serde(flatten)]
    pub compliance: ComplianceRow,
    /// The support stiffness 1/C[i][i] per axis of `frame`: the stiffness against a load along
    /// one axis with the other load components zero.
    pub stiffness: AxisStiffness,
}

/// 1/C[i][i] per axis of a frame, in the order x, y, z (N/mm), rx, ry, rz (N·mm/rad);
/// serialised as an object of the axes whose DOF is free (a held DOF, supported or prescribed,
/// has unbounded stiffness and is left out).
#[derive(Debug, Clone)]
pub struct AxisStiffness(pub [Option<f64>; 6]);

impl AxisStiffness {
    /// From the diagonal of a compliance matrix (zero: held).
    fn of(c: &[[f64; 6]; 6]) -> AxisStiffness {
        AxisStiffness(std::array::from_fn(|i| (c[i][i] > 0.0).then(|| 1.0 / c[i][i])))
    }

    /// In the order x, y, z, rx, ry, rz.
    pub fn values(&self) -> [Option<f64>; 6] {
        self.0
    }
}

impl Serialize for AxisStiffness {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut m = s.serialize_map(None)?;
        for (axis, k) in AXES.iter().zip(self.0) {
            if let Some(k) = k {
                m.serialize_entry(axis, &k)?;
            }
        }
        m.end()
    }
}

/// The DOF whose value is a load case's stroke (see [`TrackRow::stroke`]).
fn stroke_dof(lc: &LoadCase) -> Option<NodeDof> {
    if let Some(p) = lc.displacements.first() {
        return Some(NodeDof {
            node: p.node,
            dof: p.dof,
        });
    }
    let f = lc.forces.first()?;
    let (i, _) = f.f.iter().enumerate().fold(
        (0, 0.0),
        |(bi, bv), (i, v)| if v.abs() > bv { (i, v.abs()) } else { (bi, bv) },
    );
    Some(NodeDof {
        node: f.node,
        dof: Dof::from_index(i)?,
    })
}

/// The solver's tracking options for `req`, and the stroke DOFs of every load case (added to
/// the options' tracked values).
pub fn options(model: &Model, req: &TrackRequest) -> (fem::StepTrack, Vec<NodeDof>) {
    let strokes = model.load_cases.iter().filter_map(stroke_dof).collect();
    (
        fem::StepTrack {
            modes: req.modes,
            compliance: req.compliance.iter().map(|c| c.node).collect(),
        },
        strokes,
    )
}

/// The [`TrackRow`] of one solved load case (`strokes`: the tracked values of
/// [`options`]).
pub fn row(req: &TrackRequest, lc: &LoadCase, c: &fem::NonlinearCase, strokes: &[NodeDof]) -> TrackRow {
    let which = stroke_dof(lc).and_then(|d| strokes.iter().position(|s| *s == d).map(|i| (d, i)));
    let stroke = match which {
        Some((d, _)) => format!(
            "node {} {} ({})",
            d.node,
            d.dof.name(),
            if d.dof.index() < 3 { "mm" } else { "°" }
        ),
        None => "load factor λ".to_string(),
    };
    let steps = c
        .step_quantities
        .iter()
        .map(|q| {
            let p = &c.path[q.point];
            let stroke = match which {
                Some((d, i)) if d.dof.index() < 3 => p.values[i],
                Some((_, i)) => p.values[i].to_degrees(),
                None => q.lambda,
            };
            TrackStep {
                lambda: q.lambda,
                stroke,
                stable: p.stable,
                frequencies_hz: q.frequencies_hz(),
                compliance: req
                    .compliance
                    .iter()
                    .zip(&q.compliance)
                    .map(|(r, m)| {
                        let row = compliance_row(r.node, r.frame, &nalgebra::Matrix6::from_fn(|i, j| m[i][j]));
                        TrackCompliance {
                            stiffness: AxisStiffness::of(&row.matrix),
                            compliance: row,
                        }
                    })
                    .collect(),
            }
        })
        .collect();
    TrackRow { stroke, steps }
}

const AXES: [&str; 6] = ["x", "y", "z", "rx", "ry", "rz"];

/// Column headers and cells of one step (shared by the Markdown table and the CSV).
fn columns(t: &TrackRow, csv: bool) -> (Vec<String>, Vec<Vec<String>>) {
    let first = t.steps.first();
    let n_modes = first.map_or(0, |s| s.frequencies_hz.len());
    let mut head = vec![
        "lambda".to_string(),
        if csv {
            "stroke".to_string()
        } else {
            format!("stroke: {}", t.stroke)
        },
        "stable".to_string(),
    ];
    head.extend((1..=n_modes).map(|k| if csv { format!("f{k}_hz") } else { format!("f{k} (Hz)") }));
    for c in first.map(|s| s.compliance.as_slice()).unwrap_or_default() {
        for (i, a) in AXES.iter().enumerate() {
            let n = c.compliance.node;
            head.push(match (csv, i < 3) {
                (true, true) => format!("node{n}_k{a}_n_per_mm"),
                (true, false) => format!("node{n}_k{a}_nmm_per_rad"),
                (false, true) => format!("node {n} k_{a} (N/mm)"),
                (false, false) => format!("node {n} k_{a} (N·mm/rad)"),
            });
        }
    }
    let num = |v: f64| if csv { format!("{v:e}") } else { sig(v, 5) };
    let rows = t
        .steps
        .iter()
        .map(|s| {
            let mut r = vec![num(s.lambda), num(s.stroke), s.stable.to_string()];
            r.extend(s.frequencies_hz.iter().map(|f| num(*f)));
            for c in &s.compliance {
                r.extend(c.stiffness.values().iter().map(|k| match k {
                    Some(k) => num(*k),
                    None if csv => String::new(),
                    None => "held".to_string(),
                }));
            }
            r
        })
        .collect();
    (head, rows)
}

/// The Markdown section of one load case's tracking.
pub fn markdown(t: &TrackRow) -> String {
    let (head, rows) = columns(t, false);
    let refs: Vec<&str> = head.iter().map(String::as_str).collect();
    let mut table = Table::new(&refs);
    for r in rows {
        table.row(r);
    }
    format!(
        "### Along the path\n\nAt every accepted load step, with the tangent stiffness of the deformed state (geometric stiffness included) and the DOFs the load case prescribes held: natural frequencies, and the support stiffness k = 1/C[i][i] of the tracked nodes (frame axes).\n\n{}\n",
        table.render()
    )
}

/// The CSV table of one load case's tracking.
pub fn csv(t: &TrackRow) -> String {
    let (head, rows) = columns(t, true);
    let mut out = head.join(",") + "\n";
    for r in rows {
        out += &(r.join(",") + "\n");
    }
    out
}

/// SVG: support stiffness relative to the first step (top) and natural frequencies (bottom)
/// against the stroke.
pub fn plot(name: &str, t: &TrackRow) -> String {
    let mut stiff: Vec<(String, Vec<(f64, f64)>)> = Vec::new();
    if let Some(first) = t.steps.first() {
        for (ci, c) in first.compliance.iter().enumerate() {
            for (i, k0) in c.stiffness.values().iter().enumerate() {
                let Some(k0) = k0 else { continue };
                let pts = t
                    .steps
                    .iter()
                    .filter_map(|s| s.compliance[ci].stiffness.values()[i].map(|k| (s.stroke, k / k0)))
                    .collect();
                let unit = if i < 3 { "N/mm" } else { "N·mm/rad" };
                stiff.push((
                    format!("node {} k_{} (k₀ = {} {unit})", c.compliance.node, AXES[i], sig(*k0, 4)),
                    pts,
                ));
            }
        }
    }
    let n_modes = t.steps.first().map_or(0, |s| s.frequencies_hz.len());
    let freq: Vec<(String, Vec<(f64, f64)>)> = (0..n_modes)
        .map(|k| {
            (
                format!("f{}", k + 1),
                t.steps.iter().map(|s| (s.stroke, s.frequencies_hz[k])).collect(),
            )
        })
        .collect();
    let panel = |title: &str, ylabel: &str, series: &[(String, Vec<(f64, f64)>)]| {
        let s: Vec<(&str, &[(f64, f64)])> = series.iter().map(|(n, p)| (n.as_str(), p.as_slice())).collect();
        // The stroke is a node's displacement with its unit, or the dimensionless load factor.
        let xlabel = if t.stroke.ends_with(')') {
            t.stroke.clone()
        } else {
            format!("{} (–)", t.stroke)
        };
        svg::scatter(title, &xlabel, ylabel, &s)
    };
    let mut panels = Vec::new();
    if !stiff.is_empty() {
        panels.push(panel(
            &format!("{name}: support stiffness along the path"),
            "k / k at λ = 0 (–)",
            &stiff,
        ));
    }
    if !freq.is_empty() {
        panels.push(panel(
            &format!("{name}: natural frequencies along the path"),
            "frequency (Hz)",
            &freq,
        ));
    }
    svg::stack(&panels)
}

/// The CSV and SVG files of the tracked load cases `(name, rows)` (`track_<case>.csv`,
/// `.svg`).
pub fn files<'a>(cases: impl Iterator<Item = (&'a str, &'a TrackRow)>) -> crate::analysis::Files {
    let mut out = Vec::new();
    for (name, t) in cases {
        let stem = crate::report::vtk::file_stem(name);
        out.push((format!("track_{stem}.csv"), csv(t).into_bytes()));
        out.push((format!("track_{stem}.svg"), plot(name, t).into_bytes()));
    }
    out
}
