//! The `buckling` analysis on a generic beam model (hinges, joints, springs, rigid links):
//! the case shape (a model as for `static`, inline or from a mesh file, with exactly one load
//! case, the reference load, and the number of modes), load multipliers λ of the reference load
//! and their mode shapes, reports, VTK file of the shapes.

use crate::case::fields::case_struct;
use crate::analysis::common::kind::{Analysis, Ctx, UsedMaterial};
use crate::analysis::common::kind::named_materials;
use super::{AnalysisError, Report, RunError};
use crate::case::fem_case::{modes_of, read_model, shapes_default, split, ModalOptions};
use crate::case::mesh::MeshSpec;
use crate::case::{from_value, CaseError};
use crate::fem::buckling::{solve_buckling, BucklingOptions, BucklingResults};
use crate::fem::{Element, Model};
use crate::report::markdown::Table;
use serde::Serialize;
use serde_json::Value;

case_struct! {
    /// `"analysis": "buckling"`: the `modes` smallest load multipliers λ (by magnitude) of the
    /// reference load (the case's one `load_cases` entry) at which the linear structure bifurcates,
    /// (K + λ K_G) φ = 0, with their mode shapes. λ < 0: buckling under the reversed load.
    #[derive(Debug, Clone, schemars::JsonSchema)]
    #[serde(deny_unknown_fields)]
    pub struct BucklingCase {
        include model_source {
            /// Free text saying what the model is (not used by the analysis).
            description,
            /// Mesh file, as for `static`: a JSON mesh file or a Gmsh `.msh` file.
            mesh,
            /// Physical-group mapping of a Gmsh `.msh` mesh (only with a `.msh` mesh, which needs it).
            gmsh,
            /// The model; its `load_cases` holds exactly one entry, the reference load.
            model,
        }
        /// Number of buckling modes (smallest |λ|), 1 … 1000.
        #[schemars(range(min = 1, max = 1000))]
        pub modes: usize,
        /// Mode shapes in the JSON result (default true); `buckling_modes.vtu` (with `--out`)
        /// always holds them.
        #[serde(default = "shapes_default")]
        pub shapes: bool,
    }
}

const OWN: [&str; 6] = ["analysis", "description", "mesh", "gmsh", "modes", "shapes"];

/// Parses a `buckling` case; files it names resolve against `base` first.
pub fn parse_buckling(value: Value, base: &crate::case::Source<'_>) -> Result<BucklingCase, CaseError> {
    if let Some(k) = ["nonlinear", "steps", "shift_hz", "compliance", "output"]
        .iter()
        .find(|k| value.get(**k).is_some())
    {
        return Err(CaseError::new(
            *k,
            format!("a buckling case does not take `{k}` (it takes {}, and the model's fields)", OWN[1..].join(", ")),
        ));
    }
    let (options, model) = split(value, &OWN);
    let o: ModalOptions = from_value(options, "")?;
    let modes = modes_of(o.modes, "buckling modes")?;
    let model = read_model(model, o.mesh.as_deref(), o.gmsh.as_ref(), base)?;
    match model.load_cases.len() {
        1 => {}
        0 => {
            return Err(CaseError::new(
                "load_cases",
                "a buckling case needs one load case, the reference load (its multipliers λ are the results)",
            ))
        }
        n => {
            return Err(CaseError::value(
                "load_cases",
                format!("{n} load cases"),
                "a buckling case takes exactly one load case (the reference load); run one case per load",
            ))
        }
    }
    Ok(BucklingCase {
        description: o.description,
        mesh: o.mesh,
        gmsh: o.gmsh,
        modes,
        shapes: o.shapes.unwrap_or(true),
        model,
    })
}

/// One buckling mode of the result.
#[derive(Debug, Clone, Serialize)]
pub struct BucklingRow {
    /// 1-based mode number (by increasing |λ|).
    pub mode: usize,
    /// Load multiplier λ: the reference load times λ buckles the structure.
    pub load_factor: f64,
    /// λ < 0: the structure buckles under the reversed reference load (at |λ| times it).
    pub reversed: bool,
    /// Shape per node [ux, uy, uz (mm), rx, ry, rz (degrees)], global axes, scaled so that the
    /// largest translation is +1 mm (the largest rotation 1 rad if nothing translates).
    /// Omitted with `"shapes": false` (the shapes are in `buckling_modes.vtu`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shape: Option<Vec<[f64; 6]>>,
}

/// Result of the `buckling` analysis.
#[derive(Debug, Clone, Serialize)]
pub struct BucklingResult {
    /// Modes by increasing |λ|.
    pub buckling: Vec<BucklingRow>,
    /// The reference load case.
    pub load_case: String,
    /// Largest translation of the linear reference solution, mm.
    pub reference_max_displacement: f64,
    /// Model notes (method, equations, solves).
    pub model: Vec<String>,
}

/// `buckling`: linear buckling load multipliers and mode shapes.
pub struct Buckling;

fn build(case: &BucklingCase) -> Result<(Model, Vec<crate::case::mesh::BuiltHinge>), CaseError> {
    crate::case::mesh::superelement::refuse_in(&case.model, "linear buckling")?;
    crate::case::limits::check_modal(case.modes, case.model.nodes.len())?;
    let (model, hinges) = case.model.build_with_hinges(true, false)?;
    if let Some(ie) = model
        .elements
        .iter()
        .position(|e| matches!(e, Element::Shell4(_) | Element::Shell9(_)))
    {
        let kind = if matches!(model.elements[ie], Element::Shell9(_)) { "shell9" } else { "shell4" };
        return Err(CaseError::new(
            format!("elements[{}]", shell_case_element(case, ie)),
            format!(
                "element {ie} is a shell ({kind}): linear buckling has the geometric stiffness of beams, hinge (flexibility) elements, joints, springs and rigid links only; model the part with beams"
            ),
        ));
    }
    Ok((model, hinges))
}

/// The first case element that is a shell.
fn shell_case_element(case: &BucklingCase, ie: usize) -> usize {
    case.model
        .elements
        .iter()
        .position(|e| {
            matches!(
                e,
                crate::case::mesh::ElementSpec::Shell4 { .. } | crate::case::mesh::ElementSpec::Shell9 { .. }
            )
        })
        .unwrap_or(ie)
}

/// Solves the buckling problem of `model` under its load case 0 into the typed result.
pub fn solve(model: &Model, modes: usize, shapes: bool) -> Result<(BucklingResult, BucklingResults), AnalysisError> {
    let r = solve_buckling(model, 0, &BucklingOptions::new(modes))
        .map_err(|e| AnalysisError::new("load_cases[0]", e.to_string()))?;
    let rows = r
        .modes
        .iter()
        .enumerate()
        .map(|(i, m)| BucklingRow {
            mode: i + 1,
            load_factor: m.load_factor,
            reversed: m.load_factor < 0.0,
            shape: shapes.then(|| m.shape.iter().map(crate::report::numbers::mm_deg).collect()),
        })
        .collect();
    let umax = r
        .reference
        .displacements
        .iter()
        .map(|d| (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt())
        .fold(0.0, f64::max);
    let notes = vec![
        "geometric stiffness of the linear reference solution: co-rotational chord and end-moment terms of beams and hinge (flexibility) elements (symmetrised: semitangential moments), Hermite bowing and Wagner terms of the axial force in beams, rigid-link arms; springs none".to_string(),
        format!(
            "(K + λK_G)φ = 0 by block shift-invert Lanczos on K⁻¹K_G in the K inner product, {} equations, {} solves",
            r.n_eq, r.lanczos_steps
        ),
    ];
    Ok((
        BucklingResult {
            buckling: rows,
            load_case: r.reference.name.clone(),
            reference_max_displacement: umax,
            model: notes,
        },
        r,
    ))
}

/// Warnings: reversed multipliers; single-element hinges (chord-only geometric stiffness).
fn warnings(model: &Model, r: &BucklingResult) -> Vec<String> {
    let mut w = Vec::new();
    let reversed: Vec<String> = r
        .buckling
        .iter()
        .filter(|m| m.reversed)
        .map(|m| format!("{} (λ = {:.6e})", m.mode, m.load_factor))
        .collect();
    if !reversed.is_empty() {
        w.push(format!(
            "modes {} have negative load factors: the structure buckles there under the reversed reference load, at |λ| times it",
            reversed.join(", ")
        ));
    }
    if model.elements.iter().any(|e| matches!(e, Element::Flex(_))) {
        w.push("hinge (flexibility) elements carry the co-rotational geometric stiffness of their chord only (no bowing inside the notch: +1.7 % on a notch-hinge column with one element against 48 segments); give hinges \"segments\" to refine".to_string());
    }
    w
}

/// VTK file of the mode shapes (`load_factor` per mode).
pub fn vtu(model: &Model, r: &BucklingResults) -> Result<Vec<u8>, AnalysisError> {
    let modes: Vec<(f64, &[[f64; 6]])> = r.modes.iter().map(|m| (m.load_factor, m.shape.as_slice())).collect();
    crate::analysis::common::vtu::modes_vtu_named(model, &modes, &Default::default(), "load_factor")
}

/// Markdown/CSV views.
pub fn report(r: &BucklingResult) -> Report {
    let mut md = String::from("# Linear buckling\n\n");
    md += &format!(
        "Load multipliers λ of the reference load case \"{}\" (largest reference displacement {:.4e} mm):\n\n",
        r.load_case, r.reference_max_displacement
    );
    let mut csv = String::from("mode,load_factor,reversed\n");
    let mut t = Table::new(&["mode", "λ", "reversed load"]);
    for m in &r.buckling {
        t.row(vec![
            m.mode.to_string(),
            format!("{:.6e}", m.load_factor),
            if m.reversed { "yes" } else { "no" }.to_string(),
        ]);
        csv += &format!("{},{},{}\n", m.mode, m.load_factor, m.reversed);
    }
    md += &t.render();
    md += "\n";
    for n in &r.model {
        md += &format!("- {n}\n");
    }
    Report { markdown: md, csv }
}

impl Analysis for Buckling {
    type Case = BucklingCase;
    type Result = BucklingResult;

    fn check(case: &Self::Case) -> Result<(), CaseError> {
        build(case).map(|_| ())
    }
    fn run(case: &Self::Case, ctx: &mut Ctx) -> Result<Self::Result, RunError> {
        let (model, hinges) = build(case)?;
        let (mut r, raw) = solve(&model, case.modes, case.shapes)?;
        let shapes = r.buckling.iter_mut().filter_map(|row| row.shape.as_mut());
        let user = case.model.nodes.len();
        r.model.extend(super::fem_static::hide_in_shapes(shapes, &model, &hinges, user));
        ctx.warnings = warnings(&model, &r);
        ctx.warnings.extend(crate::analysis::common::warn::fewer_modes(case.modes, raw.modes.len(), Some(raw.n_eq)));
        if ctx.with_files {
            ctx.files = vec![("buckling_modes.vtu".to_string(), vtu(&model, &raw)?)];
        }
        Ok(r)
    }
    fn report(r: &Self::Result) -> Report {
        report(r)
    }
    fn materials(case: &Self::Case) -> Vec<UsedMaterial> {
        named_materials(&case.model.materials)
    }
    fn mesh_model(case: &Self::Case) -> Option<&MeshSpec> {
        Some(&case.model)
    }
}
