//! The one copy of the compliant 3-PRS stage design of A. Ruiz, F. J. Campa, C.
//! Roldán-Paraponiaris, O. Altuzarra, C. Pinto, *Experimental validation of the kinematic design
//! of 3PRS compliant parallel mechanisms* (2019), §4–5: L = 109.215 mm, b = 47.91 mm, α₀ = 45°,
//! 10 × 10 mm legs, circular-notch revolutes (R = 8, t = 2 mm) and spherical necks (l = 5, t = 3,
//! R = 4 mm) in Al 7075. Its values are those of the bundled `cases/ruiz2019_stage.json`, read
//! here at compile time; tests and benches (by `#[path]`) take the design from this file instead
//! of pasting the numbers.
#![allow(dead_code)]

use flexfem::analysis::{self, Case};
use flexfem::hinge::HingeSpec;
use flexfem::kinematics::Prs;
use flexfem::stage::{Drive, StageDesign};
use serde_json::Value;

/// The bundled stage case file, as text.
pub const RUIZ2019_STAGE: &str = include_str!("../../cases/ruiz2019_stage.json");

/// The bundled stage case as JSON.
pub fn ruiz2019_stage_json() -> Value {
    serde_json::from_str(RUIZ2019_STAGE).unwrap_or_else(|e| panic!("cases/ruiz2019_stage.json: {e}"))
}

/// The bundled stage case with `edit` applied, as case-file text.
pub fn ruiz2019_stage_with(edit: impl FnOnce(&mut Value)) -> String {
    let mut v = ruiz2019_stage_json();
    edit(&mut v);
    v.to_string()
}

/// The bundled stage case with its load cases replaced by `load_cases`, as case-file text.
pub fn ruiz2019_stage_loaded(load_cases: Value) -> String {
    ruiz2019_stage_with(|v| v["load_cases"] = load_cases)
}

/// The validated design and drives of a stage case file's text.
pub fn stage_case(text: &str) -> (StageDesign, Vec<(String, Drive)>) {
    let Case::Stage(c) = analysis::parse(text).unwrap_or_else(|e| panic!("{e}")) else {
        panic!("not a stage case")
    };
    c.validate().unwrap_or_else(|e| panic!("{e}"))
}

/// The validated design of the bundled stage case.
pub fn ruiz2019_stage_design() -> StageDesign {
    stage_case(RUIZ2019_STAGE).0
}

/// The bundled stage design with ideal joints (exact revolute and spherical releases, stiff legs
/// and platform) and the actuator axes rotated by `gamma_deg`.
pub fn ruiz2019_ideal_stage_design(gamma_deg: f64) -> StageDesign {
    let text = ruiz2019_stage_with(|v| {
        v["stage"]["gamma_deg"] = Value::from(gamma_deg);
        v["stage"]["ideal_joints"] = Value::Bool(true);
        // Free sliders: an ideal-joint stage takes strokes, not actuator forces.
        v["load_cases"] = serde_json::json!([{"name": "s", "actuator_strokes": [0.01, 0.01, 0.01]}]);
    });
    stage_case(&text).0
}

/// The stage's revolute joint as a characterisation case (cases/ruiz2019_hinge_revolute.json):
/// circular notch R = 8, t = 2 in the 10 × 10 leg, 20 mm blank each side.
pub fn ruiz2019_revolute_hinge() -> HingeSpec {
    hinge_of(include_str!("../../cases/ruiz2019_hinge_revolute.json"))
}

/// The stage's spherical joint as a characterisation case (cases/ruiz2019_hinge_spherical.json):
/// spherical neck l = 5, t = 3, R = 4 in the 10 mm leg, 20 mm blank each side.
pub fn ruiz2019_spherical_hinge() -> HingeSpec {
    hinge_of(include_str!("../../cases/ruiz2019_hinge_spherical.json"))
}

/// The `hinge` of a hinge case file's text.
fn hinge_of(text: &str) -> HingeSpec {
    let v: Value = serde_json::from_str(text).unwrap_or_else(|e| panic!("{e}"));
    serde_json::from_value(v["hinge"].clone()).unwrap_or_else(|e| panic!("{e}"))
}

/// The stage's rigid-body 3-PRS geometry (L, b, α₀ of the bundled case) with the actuator axes
/// rotated by `gamma_deg`.
pub fn ruiz2019_prs(gamma_deg: f64) -> Prs {
    let v = ruiz2019_stage_json();
    let num = |k: &str| v["stage"][k].as_f64().unwrap_or_else(|| panic!("stage.{k}"));
    Prs::new(
        num("L"),
        num("b"),
        num("alpha0_deg").to_radians(),
        gamma_deg.to_radians(),
    )
    .unwrap_or_else(|e| panic!("{e}"))
}

/// The corner-filleted nylon 66 hinge of the 8R pan-tilt platform
/// (cases/pantilt_hinge_corner_filleted.json): l = 5, R = 1.75, t = 0.6, width 10, blank height
/// 15, 15 mm blank each side.
pub fn pantilt_corner_filleted_hinge() -> HingeSpec {
    hinge_of(include_str!("../../cases/pantilt_hinge_corner_filleted.json"))
}

/// One hinge of every family in the stage's 10 × 10 leg blank, 20 mm each side: the Ruiz et al.
/// (2019) revolute notch (R 8, t 2) and spherical neck (l 5, t 3, R 4), and comparable
/// elliptical (ax 6, ay 3, t 1.2), corner-filleted (l 8, R 2, t 1) and leaf (l 6, t 0.8) notches.
pub fn hinge_families() -> [HingeSpec; 5] {
    use flexfem::hinge::Contour;
    [
        Contour::Circular { r: 8.0, t: 2.0 },
        Contour::Elliptical {
            ax: 6.0,
            ay: 3.0,
            t: 1.2,
        },
        Contour::CornerFilleted { l: 8.0, r: 2.0, t: 1.0 },
        Contour::Leaf { l: 6.0, t: 0.8 },
        Contour::SphericalNeck { l: 5.0, t: 3.0, r: 4.0 },
    ]
    .map(|c| HingeSpec::in_blank(c, 10.0, 10.0, 20.0))
}
