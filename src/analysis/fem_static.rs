//! The `static` analysis on a generic beam model.

use super::{AnalysisError, Report};
use crate::fem::{self, Model};
use crate::report::markdown::Table;
use serde::Serialize;

pub use super::compliance::{compliance_row, ComplianceRow};

/// One load case of a `static` result.
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
    /// Shells only: von Mises at the element centre on the top, mid and bottom surfaces, MPa
    /// (omitted for models without shells).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub shell_von_mises: Vec<ShellVonMises>,
    /// Sum of loads plus reactions (should vanish): [N, N, N, N·mm, N·mm, N·mm].
    pub equilibrium_residual: [f64; 6],
    /// Nonlinear only: whether every converged point of the equilibrium path was stable
    /// (positive definite tangent stiffness, no jump over a limit point).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stable: Option<bool>,
    /// Nonlinear and not stable: load factors [lo, hi] bracketing the first loss of stability.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub critical_load_factor: Option<[f64; 2]>,
    /// Nonlinear: the located changes of stability along the path (omitted when none).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub critical_points: Vec<super::path_rows::CriticalPointRow>,
    /// Nonlinear with `trace`: the load–displacement curve of the traced DOF.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub trace: Option<super::path_rows::TraceRow>,
    /// Shells only: nodal surface stresses (omitted for models without shells).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shell_stress: Option<ShellStressRow>,
    /// Shells only: stress resultants at each shell element's centre, element axes (omitted
    /// for models without shells).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub shell_forces: Vec<ShellForcesRow>,
    /// Per `hinge` element: rotation, end forces, peak stress and margin (omitted for models
    /// without hinge elements).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub hinges: Vec<HingeRow>,
    /// With `"output": {"section_forces": true}`: section forces of every beam element
    /// (omitted otherwise).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub beam_forces: Vec<BeamForcesRow>,
    /// Nonlinear with `"track"`: frequencies and node compliances at every accepted load step
    /// (omitted otherwise).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub track: Option<super::track::TrackRow>,
}

/// Section forces of one beam element in one load case.
#[derive(Debug, Clone, Serialize)]
pub struct BeamForcesRow {
    /// Index of the element in the FE model (the order of `element_von_mises`).
    pub element: usize,
    /// [N, Vy, Vz (N), T, My, Mz (N·mm)] at end a (first node) and end b, element axes
    /// (deformed element axes in nonlinear runs); positive-face convention: N > 0 in tension,
    /// the forces the part beyond the section exerts on the part before it.
    pub section_forces: [[f64; 6]; 2],
}

/// Results of one `hinge` element in one load case.
#[derive(Debug, Clone, Serialize)]
pub struct HingeRow {
    /// Index of the element in the case's `elements`.
    pub element: usize,
    /// Index of the element in the FE model (the order of `element_von_mises`).
    pub model_element: usize,
    /// Rotation about the compliant axis (element local y), degrees: the relative rotation of
    /// node b with respect to node a about the element's local y. Linear: (θ_b − θ_a)·e_y.
    /// Nonlinear: the local-y component of the rotation vector of R_aᵀ·R_b (finite rotations,
    /// in the undeformed element axes).
    pub rotation_deg: f64,
    /// Section forces [N, Vy, Vz (N), T, My, Mz (N·mm)] at end a and end b, element axes
    /// (deformed element axes in nonlinear runs; N > 0 in tension).
    pub end_forces: [[f64; 6]; 2],
    /// Peak von Mises stress along the hinge with the notch factor, MPa (the stress model of the
    /// `hinge` analysis and the `stage`).
    pub peak_von_mises: f64,
    /// peak_von_mises / allowable of the element's material (0 without an allowable).
    pub utilisation: f64,
    /// Rotation left until the peak stress reaches the allowable, degrees, by linear
    /// extrapolation of the load case (stress proportional to rotation):
    /// rotation_deg · (allowable/peak_von_mises − 1). Signed like rotation_deg (further rotation
    /// in the same sense); of the opposite sign when the allowable is already exceeded; `null`
    /// when unbounded (no allowable, or no stress).
    #[serde(serialize_with = "crate::report::numbers::ratio_or_null")]
    pub remaining_rotation_deg: f64,
}

/// Nodal stresses of the shells: per node [sxx, syy, szz, sxy, syz, szx] (MPa, global axes),
/// integration-point values extrapolated to the nodes and averaged over the shells at the
/// node; `null` for nodes without shells. Top and bottom follow each element's normal (right-hand
/// rule over its node order): mesh every shell in the same sense (a warning names edges shared
/// by oppositely oriented shells).
#[derive(Debug, Clone, Serialize)]
pub struct ShellStressRow {
    /// Top surface (z = +t/2 along the element normal).
    pub top: Vec<Option<[f64; 6]>>,
    /// Mid-surface (membrane stress; transverse shear as the parabolic peak 1.5·Q/t).
    pub mid: Vec<Option<[f64; 6]>>,
    /// Bottom surface (z = −t/2).
    pub bottom: Vec<Option<[f64; 6]>>,
}

/// Stress resultants at the centre of one shell element, in its axes.
#[derive(Debug, Clone, Serialize)]
pub struct ShellForcesRow {
    /// Element index (model order).
    pub element: usize,
    /// Element axes: local x, y, z (normal) as unit vectors in global coordinates.
    pub axes: [[f64; 3]; 3],
    /// Membrane forces [Nxx, Nyy, Nxy], N/mm.
    #[serde(rename = "N")]
    pub n: [f64; 3],
    /// Moments [Mxx, Myy, Mxy], N·mm/mm (Mxx > 0 stretches the top surface).
    #[serde(rename = "M")]
    pub m: [f64; 3],
    /// Transverse shear forces [Qx, Qy], N/mm.
    #[serde(rename = "Q")]
    pub q: [f64; 2],
}

/// Surface stresses of one shell element.
#[derive(Debug, Clone, Serialize)]
pub struct ShellVonMises {
    /// Element index (model order).
    pub element: usize,
    /// Von Mises at z = +t/2, MPa.
    pub top: f64,
    /// Von Mises at the mid-surface, MPa.
    pub mid: f64,
    /// Von Mises at z = −t/2, MPa.
    pub bottom: f64,
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
    /// Node compliances the case asked for (`"compliance"`), linear, with the model's supports
    /// (DOFs prescribed in load cases are free here); omitted when none was asked.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub compliance: Vec<ComplianceRow>,
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
    solve_with(model, &mut fem::SolverCache::new())
}

/// [`solve`] reusing the systems of the worker's solver cache where the topology matches.
pub fn solve_with(
    model: &Model,
    cache: &mut fem::SolverCache,
) -> Result<(StaticResult, fem::StaticResults), AnalysisError> {
    let res = fem::solve_static_cached(model, fem::solve::Parallelism::Rayon, cache)
        .map_err(|e| AnalysisError::new("model", e.to_string()))?;
    let rows = res
        .load_cases
        .iter()
        .map(|c| {
            let mut r = row(c);
            let field = fem::shell_recovery::shell_field(model, &c.displacements)
                .map_err(|e| AnalysisError::new(format!("load case `{}`", c.name), e.to_string()))?;
            add_shell_field(&mut r, field);
            Ok(r)
        })
        .collect::<Result<_, AnalysisError>>()?;
    let mut notes = vec![
        "linear statics, small displacements".to_string(),
        "beams: 2-node exact Timoshenko (Euler–Bernoulli where \"shear\": false); stresses at section critical points"
            .to_string(),
        "shells: 4-node flat shell (membrane with drilling rotation, MITC4 bending with stabilized shear); von Mises at the element centre, max of top/mid/bottom"
            .to_string(),
    ];
    notes.extend(fem::superelement::notes(model));
    Ok((
        StaticResult {
            load_cases: rows,
            units: Units {
                displacements: "mm, mm, mm, deg, deg, deg",
                reactions: "N, N, N, N·mm, N·mm, N·mm",
            },
            model: notes,
            compliance: Vec::new(),
        },
        res,
    ))
}

/// Geometrically nonlinear statics of every load case in `steps` load steps. Rotations in the
/// output are the components of each node's rotation vector (degrees). Also returns the final
/// state of each load case in the linear result's shape (for the `.vtu` files).
pub fn solve_nonlinear(model: &Model, steps: usize) -> Result<(StaticResult, fem::StaticResults), AnalysisError> {
    solve_nonlinear_tracked(model, steps, None)
}

/// [`solve_nonlinear`] with the quantities `track` asks for at every accepted load step.
pub fn solve_nonlinear_tracked(
    model: &Model,
    steps: usize,
    track: Option<&crate::case::mesh::TrackRequest>,
) -> Result<(StaticResult, fem::StaticResults), AnalysisError> {
    let (step_track, strokes) = track.map(|t| super::track::options(model, t)).unwrap_or_default();
    let opts = fem::NonlinearOptions {
        steps,
        track: strokes.clone(),
        step_track,
        ..Default::default()
    };
    solve_nonlinear_each(model, &vec![opts; model.load_cases.len()], track).map(|(r, raw, _)| (r, raw))
}

/// The path and critical points of each load case of a nonlinear solve.
pub type Paths = Vec<(Vec<fem::PathPoint>, Vec<fem::CriticalPoint>)>;

/// [`solve_nonlinear`] with options per load case (their `step_track` and `track` as
/// [`super::track::options`] gives them when `track` is asked for; the stroke DOFs may follow
/// other tracked DOFs); also returns each case's path and critical points.
pub fn solve_nonlinear_each(
    model: &Model,
    opts: &[fem::NonlinearOptions],
    track: Option<&crate::case::mesh::TrackRequest>,
) -> Result<(StaticResult, fem::StaticResults, Paths), AnalysisError> {
    let steps = opts.first().map_or(0, |o| o.steps);
    let res = fem::solve_nonlinear_each(model, opts).map_err(|e| AnalysisError::new("model", e.to_string()))?;
    let rows = res
        .load_cases
        .iter()
        .zip(&model.load_cases)
        .zip(opts)
        .map(|((c, lc), o)| StaticCaseRow {
            stable: Some(c.stable),
            critical_load_factor: c.critical_load_factor,
            track: track.map(|t| super::track::row(t, lc, c, &o.track)),
            ..row(&c.fe)
        })
        .collect();
    let mut paths = Paths::new();
    let raw = fem::StaticResults {
        load_cases: res
            .load_cases
            .into_iter()
            .map(|c| {
                paths.push((c.path, c.critical_points));
                c.fe
            })
            .collect(),
    };
    let result = StaticResult {
        load_cases: rows,
        units: Units {
            displacements: "mm, mm, mm, deg, deg, deg (rotation vector)",
            reactions: "N, N, N, N·mm, N·mm, N·mm",
        },
        model: vec![
            format!("geometrically nonlinear statics (large displacements and rotations, small strains), Newton-Raphson in adaptive load steps (at most 1/{steps} of the load each); loads fixed in direction; every state checked for equilibrium and stability"),
            "beams and flexibility elements: co-rotational, local linear element (exact Timoshenko); rigid links exact under finite rotation; springs linear (small rotations)".to_string(),
            "stresses from the section forces in the deformed element frames".to_string(),
        ],
        compliance: Vec::new(),
    };
    Ok((result, raw, paths))
}

/// A warning when shells sharing an edge have opposite normals (their top/bottom stresses mix
/// in the nodal averages; see [`fem::shell_recovery::orientation_conflicts`]).
pub fn shell_orientation_warnings(model: &Model) -> Vec<String> {
    let c = fem::shell_recovery::orientation_conflicts(model);
    let Some((a, b, e)) = c.first() else {
        return Vec::new();
    };
    vec![format!(
        "{} shell edge(s) are shared by elements with opposite normals (first: elements {a} and {b} along nodes {}–{}): `shell_stress` top/bottom follow each element's normal, so the nodal averages there mix the two surfaces; list the nodes of every shell in the same sense",
        c.len(),
        e[0],
        e[1]
    )]
}

/// Puts a model's shell stresses into its load-case row (nothing without shells).
fn add_shell_field(r: &mut StaticCaseRow, f: fem::shell_recovery::ShellField) {
    if f.forces.is_empty() {
        return;
    }
    r.shell_forces = f
        .forces
        .iter()
        .map(|(element, s)| ShellForcesRow {
            element: *element,
            axes: s.axes,
            n: s.n,
            m: s.m,
            q: s.q,
        })
        .collect();
    r.shell_stress = Some(ShellStressRow {
        top: f.top,
        mid: f.mid,
        bottom: f.bottom,
    });
}

fn row(c: &fem::CaseResult) -> StaticCaseRow {
    StaticCaseRow {
        name: c.name.clone(),
        displacements: c.displacements.iter().map(crate::report::numbers::mm_deg).collect(),
        reactions: c.reactions.iter().map(|(_, r)| *r).collect(),
        reaction_nodes: c.reactions.iter().map(|(n, _)| *n).collect(),
        max_von_mises: c.max_von_mises,
        element_von_mises: c.elements.iter().map(|e| e.max_von_mises()).collect(),
        shell_von_mises: c
            .elements
            .iter()
            .enumerate()
            .filter_map(|(element, e)| {
                e.shell.map(|s| ShellVonMises {
                    element,
                    top: s.von_mises[0],
                    mid: s.von_mises[1],
                    bottom: s.von_mises[2],
                })
            })
            .collect(),
        equilibrium_residual: c.statics.residual(),
        stable: None,
        critical_load_factor: None,
        critical_points: Vec::new(),
        trace: None,
        shell_stress: None,
        shell_forces: Vec::new(),
        hinges: Vec::new(),
        beam_forces: Vec::new(),
        track: None,
    }
}

/// Adds the section forces of every beam element to each load case (`raw` in the order of
/// `r.load_cases`).
pub fn add_beam_forces(r: &mut StaticResult, model: &Model, raw: &fem::StaticResults) {
    for (row, c) in r.load_cases.iter_mut().zip(&raw.load_cases) {
        row.beam_forces = model
            .elements
            .iter()
            .enumerate()
            .filter(|(_, e)| matches!(e, fem::Element::Beam(_)))
            .map(|(ie, _)| BeamForcesRow {
                element: ie,
                section_forces: c.elements[ie].section_forces,
            })
            .collect();
    }
}

/// The node compliances `reqs` asks for (linear, undeformed model, its supports only).
pub fn node_compliances(
    model: &Model,
    reqs: &[crate::case::mesh::ComplianceRequest],
) -> Result<Vec<ComplianceRow>, AnalysisError> {
    if reqs.is_empty() {
        return Ok(Vec::new());
    }
    let sys = fem::System::new(model, &[], fem::solve::Parallelism::Rayon)
        .map_err(|e| AnalysisError::new("compliance", e.to_string()))?;
    reqs.iter()
        .enumerate()
        .map(|(i, q)| {
            let c = sys
                .node_compliance(model, q.node)
                .map_err(|e| AnalysisError::new(format!("compliance[{i}]"), e.to_string()))?;
            Ok(compliance_row(q.node, q.frame, &c))
        })
        .collect()
}

/// Adds the per-hinge results of every load case (`raw`: the solver's results in the order
/// of `r.load_cases`; `nonlinear`: rotations are finite rotation vectors).
pub fn add_hinges(
    r: &mut StaticResult,
    model: &Model,
    raw: &fem::StaticResults,
    hinges: &[crate::case::mesh::BuiltHinge],
    nonlinear: bool,
) -> Result<(), AnalysisError> {
    if hinges.is_empty() {
        return Ok(());
    }
    for (row, c) in r.load_cases.iter_mut().zip(&raw.load_cases) {
        row.hinges = hinges
            .iter()
            .map(|h| hinge_row(model, c, h, nonlinear))
            .collect::<Result<_, _>>()?;
    }
    Ok(())
}

/// The results of hinge element `h` in load case `c`.
pub fn hinge_row(
    model: &Model,
    c: &fem::CaseResult,
    h: &crate::case::mesh::BuiltHinge,
    nonlinear: bool,
) -> Result<HingeRow, AnalysisError> {
    use nalgebra::Vector3;
    let err = |e: fem::FemError| AnalysisError::new(format!("elements[{}]", h.case_element), e.to_string());
    let (lam, _) = model.element_frame(h.element).map_err(err)?;
    // A hinge of several segments runs from the first segment's node a to the last one's b.
    let nodes = match (&model.elements[h.element], &model.elements[h.last]) {
        (fem::Element::Flex(f), fem::Element::Flex(g)) => [f.nodes[0], g.nodes[1]],
        _ => {
            return Err(AnalysisError::new(
                format!("elements[{}]", h.case_element),
                "not a hinge element",
            ))
        }
    };
    let rot = |n: usize| {
        let d = &c.displacements[n];
        Vector3::new(d[3], d[4], d[5])
    };
    let (ta, tb) = (rot(nodes[0]), rot(nodes[1]));
    let rel = if nonlinear {
        let ra = fem::corot::rot_exp(&ta);
        let rb = fem::corot::rot_exp(&tb);
        fem::corot::rot_log(&(ra.transpose() * rb))
    } else {
        tb - ta
    };
    let ey = Vector3::new(lam[(1, 0)], lam[(1, 1)], lam[(1, 2)]);
    let rotation_deg = ey.dot(&rel).to_degrees();
    let sf = [
        c.elements[h.element].section_forces[0],
        c.elements[h.last].section_forces[1],
    ];
    let peak = h.region.peak_stress(&sf);
    Ok(HingeRow {
        element: h.case_element,
        model_element: h.element,
        rotation_deg,
        end_forces: sf,
        peak_von_mises: peak,
        utilisation: peak / h.allowable,
        remaining_rotation_deg: rotation_deg * (h.allowable / peak - 1.0),
    })
}

/// The warning (plain text, for the result's `warnings`) for a nonlinear load case whose path
/// lost stability.
pub fn stability_text(name: &str, stable: Option<bool>, bracket: Option<[f64; 2]>) -> Option<String> {
    match (stable, bracket) {
        (Some(false), Some([lo, hi])) => Some(format!(
            "load case `{name}`: the equilibrium path lost stability between load factors {lo:.4} and {hi:.4} (the tangent stiffness stopped being positive definite, or the solution jumped over a limit point). The reported state may be unstable or reached by a snap; check for buckling or snap-through (arc length, an imperfection)."
        )),
        (Some(false), None) => Some(format!("load case `{name}`: the equilibrium path is not stable.")),
        _ => None,
    }
}

/// The Markdown callout of [`stability_text`], shown at the load case.
pub fn stability_warning(name: &str, stable: Option<bool>, bracket: Option<[f64; 2]>) -> Option<String> {
    stability_text(name, stable, bracket).map(|w| format!("> **Warning** ({w})\n\n"))
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
        if let Some(w) = stability_warning(&c.name, c.stable, c.critical_load_factor) {
            md += &w;
        }
        if let Some(s) = c.max_von_mises {
            md += &format!("Maximum von Mises stress: {s:.3} MPa.\n\n");
        }
        md += &principal_extremes(c);
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
        md += &hinge_table(c);
        if let Some(t) = &c.track {
            md += &super::track::markdown(t);
        }
        md += &super::path_rows::markdown(&c.name, &c.critical_points, c.trace.as_ref());
    }
    md += &compliance_section(&r.compliance);
    Report { markdown: md, csv }
}

/// The Markdown section of the requested node compliances (empty without).
fn compliance_section(rows: &[ComplianceRow]) -> String {
    if rows.is_empty() {
        return String::new();
    }
    let mut md = String::from(
        "## Node compliance\n\nLinear, undeformed model with its supports; C[i][j] = displacement i per unit load j, [ux, uy, uz, rx, ry, rz] × [Fx, Fy, Fz, Mx, My, Mz] in the given frame: mm/N, mm/(N·mm), rad/N, rad/(N·mm).\n\n",
    );
    for c in rows {
        md += &format!(
            "### Node {}\n\nFrame rows (local x, y, z): {:?}. Translational eigenvalues {:.6e} … {:.6e} mm/N; rotational {:.6e} … {:.6e} rad/(N·mm).\n\n",
            c.node,
            c.frame,
            c.translational_eigen[0],
            c.translational_eigen[1],
            c.rotational_eigen[0],
            c.rotational_eigen[1]
        );
        let mut t = Table::new(&["", "Fx", "Fy", "Fz", "Mx", "My", "Mz"]);
        for (i, name) in ["ux", "uy", "uz", "rx", "ry", "rz"].iter().enumerate() {
            let mut row = vec![name.to_string()];
            row.extend(c.matrix[i].iter().map(|v| format!("{v:.6e}")));
            t.row(row);
        }
        md += &t.render();
        md += "\n";
    }
    md
}

/// The Markdown table of a load case's hinge elements (empty without hinges).
fn hinge_table(c: &StaticCaseRow) -> String {
    if c.hinges.is_empty() {
        return String::new();
    }
    let mut t = Table::columns("element | rotation (°) | peak von Mises (MPa) | utilisation | remaining rotation (°) | My a (N·mm) | My b (N·mm)");
    for h in &c.hinges {
        let rem = if h.remaining_rotation_deg.is_finite() {
            format!("{:.4}", h.remaining_rotation_deg)
        } else {
            "unbounded".to_string()
        };
        t.row(vec![
            h.element.to_string(),
            format!("{:.6}", h.rotation_deg),
            format!("{:.4}", h.peak_von_mises),
            format!("{:.4}", h.utilisation),
            rem,
            format!("{:.6e}", h.end_forces[0][4]),
            format!("{:.6e}", h.end_forces[1][4]),
        ]);
    }
    format!(
        "Hinge elements (rotation about the compliant axis, local y; remaining rotation to the allowable stress by linear extrapolation):\n\n{}\n",
        t.render()
    )
}

/// Markdown lines with the largest and smallest principal shell stresses of a load case and
/// where they occur (node, surface); empty without shells.
fn principal_extremes(c: &StaticCaseRow) -> String {
    let Some(ss) = &c.shell_stress else {
        return String::new();
    };
    let mut hi: Option<(f64, usize, &str)> = None;
    let mut lo: Option<(f64, usize, &str)> = None;
    for (name, list) in [("top", &ss.top), ("mid", &ss.mid), ("bottom", &ss.bottom)] {
        for (node, s) in list.iter().enumerate() {
            let Some(s) = s else { continue };
            let p = fem::shell_recovery::principal(s);
            if hi.is_none_or(|h| p[2] > h.0) {
                hi = Some((p[2], node, name));
            }
            if lo.is_none_or(|l| p[0] < l.0) {
                lo = Some((p[0], node, name));
            }
        }
    }
    match (hi, lo) {
        (Some(h), Some(l)) => format!(
            "Shells, extreme principal stresses (nodal averages): largest σ₁ = {:.4} MPa at node {} ({} surface); smallest σ₃ = {:.4} MPa at node {} ({} surface).\n\n",
            h.0, h.1, h.2, l.0, l.1, l.2
        ),
        _ => String::new(),
    }
}

/// A `.vtu` of one load case (see [`super::vtu`]): the undeformed model with displacement and
/// rotation point data, shell stresses and stress resultants
/// ([`super::vtu::static_vtu_with_shells`]) and von Mises per cell (the element's maximum over its ends / shell
/// surfaces; `cell_stress` overrides it for given elements, e.g. hinge peak stresses; 0 where
/// none).
pub fn vtu(model: &Model, case: &fem::CaseResult, cell_stress: &[(usize, f64)]) -> Result<String, AnalysisError> {
    let shells = fem::shell_recovery::shell_field(model, &case.displacements)
        .map_err(|e| AnalysisError::new(format!("load case `{}`", case.name), e.to_string()))?;
    super::vtu::static_vtu_with_shells(
        model,
        &case.displacements,
        &von_mises_of(case, cell_stress),
        &Default::default(),
        Some(&shells),
    )
}

/// Von Mises of element `ie` (MPa): `cell_stress` if it lists the element, else the element's
/// own maximum, else 0.
pub fn von_mises_of<'a>(case: &'a fem::CaseResult, cell_stress: &'a [(usize, f64)]) -> impl Fn(usize) -> f64 + 'a {
    move |ie| {
        cell_stress
            .iter()
            .find(|(i, _)| *i == ie)
            .map(|(_, v)| *v)
            .or_else(|| case.elements.get(ie).and_then(|r| r.max_von_mises()))
            .unwrap_or(0.0)
    }
}

/// One `.vtu` per load case, named after the load case (names are unique as file names: the
/// case validation refuses duplicates).
pub fn vtu_files(model: &Model, res: &fem::StaticResults) -> Result<super::Files, AnalysisError> {
    res.load_cases
        .iter()
        .map(|c| Ok((format!("{}.vtu", file_stem(&c.name)), vtu(model, c, &[])?.into_bytes())))
        .collect()
}

/// A file name made of the safe characters of `name`.
pub fn file_stem(name: &str) -> String {
    crate::report::vtk::file_stem(name)
}
