//! The stage as a `static` mesh case (`stage_mesh.json`): the same FE model written with the
//! native parts of mesh cases — nodes, a w × h `rect` leg section, `hinge` elements for the
//! revolute notches and spherical necks (each spanning the same hinge region as the stage's own
//! flexibility element, so it gets the same compliance), `beam` legs, a rigid link for the
//! platform, slider supports in the slider frames and the load cases as forces or prescribed
//! strokes along the sliders — so `flexfem run stage_mesh.json` solves the model the stage
//! solves. Nodes and elements are written in the stage model's order, so node and element
//! indices (and with them the solution) are the stage's.

use super::*;
use crate::fem::Element;
use serde_json::{json, Map, Value};

/// Names of the DOFs in case files, in the order ux uy uz rx ry rz.
const DOF_NAMES: [&str; 6] = ["ux", "uy", "uz", "rx", "ry", "rz"];

/// A material as a case-file object (strengths only when finite: "unlimited" has no JSON
/// spelling and is the default).
fn material_json(m: &Material) -> Value {
    let mut o = Map::new();
    o.insert("E".into(), json!(m.e));
    o.insert("nu".into(), json!(m.nu));
    o.insert("density".into(), json!(m.density));
    if m.yield_strength.is_finite() {
        o.insert("yield".into(), json!(m.yield_strength));
    }
    if m.allowable.is_finite() {
        o.insert("allowable".into(), json!(m.allowable));
    }
    Value::Object(o)
}

/// A hinge spec as the `hinge` object of a `hinge` element (no `blank_length`: the element's
/// node distance sets the blank).
fn hinge_json(spec: &HingeSpec) -> Value {
    let mut v = serde_json::to_value(spec).unwrap_or(Value::Null);
    if let Value::Object(m) = &mut v {
        m.remove("blank_length");
    }
    v
}

impl StageModel {
    /// The stage with load cases `cases` as a `static` case (see the module docs); nonlinear
    /// in `steps` load steps when `nonlinear_steps` is given, each hinge then made of
    /// [`super::NONLINEAR_HINGE_SEGMENTS`] co-rotational segments as in
    /// [`StageModel::solve_nonlinear`].
    ///
    /// `None` with ideal joints: their revolute release ties the slider node in its hinge
    /// frame, while the slider guide holds it in the slider frame, and a mesh-case node
    /// carries one frame.
    pub fn mesh_case(&self, cases: &[(String, Drive)], nonlinear_steps: Option<usize>) -> Option<Value> {
        if self.design.ideal_joints {
            return None;
        }
        let model = &self.model;
        let segments = nonlinear_steps.map(|_| super::NONLINEAR_HINGE_SEGMENTS);
        let mut elements = Vec::with_capacity(model.elements.len());
        for (ie, el) in model.elements.iter().enumerate() {
            match el {
                Element::Beam(b) => elements.push(json!({
                    "type": "beam",
                    "nodes": b.nodes,
                    "section": "leg",
                    "material": "stage",
                    "up": b.up,
                })),
                Element::Flex(f) => {
                    let spec = if self.legs.iter().any(|l| l.rev_element == Some(ie)) {
                        &self.design.revolute
                    } else {
                        &self.design.spherical
                    };
                    let mut h = json!({
                        "type": "hinge",
                        "nodes": f.nodes,
                        "hinge": hinge_json(spec),
                        "material": "stage",
                        "up": f.up,
                    });
                    if let Some(n) = segments {
                        h["segments"] = json!(n);
                    }
                    elements.push(h);
                }
                // The stage builds beams and hinges only.
                Element::Spring(_) | Element::Shell4(_) => return None,
            }
        }
        let supports: Vec<Value> = model
            .supports
            .iter()
            .map(|s| {
                let fix: Vec<&str> = (0..6).filter(|&k| s.fix[k]).map(|k| DOF_NAMES[k]).collect();
                let mut o = json!({"node": s.node, "fix": fix});
                if let Some(f) = model.frames.get(&s.node) {
                    o["frame"] = json!(f);
                }
                o
            })
            .collect();
        let rigid: Vec<Value> = model
            .rigid_links
            .iter()
            .map(|r| json!({"master": r.master, "slaves": r.slaves}))
            .collect();
        let load_cases: Vec<Value> = cases
            .iter()
            .map(|(name, drive)| {
                let frame = |i: usize| model.frames.get(&self.legs[i].slider).copied();
                match drive {
                    Drive::Forces(f) => json!({
                        "name": name,
                        "forces": (0..3).map(|i| json!({
                            "node": self.legs[i].slider,
                            "F": [f[i], 0.0, 0.0, 0.0, 0.0, 0.0],
                            "frame": frame(i),
                        })).collect::<Vec<_>>(),
                    }),
                    Drive::Strokes(s) => json!({
                        "name": name,
                        "displacements": (0..3).map(|i| json!({
                            "node": self.legs[i].slider,
                            "dof": "ux",
                            "value": s[i],
                            "frame": frame(i),
                        })).collect::<Vec<_>>(),
                    }),
                }
            })
            .collect();
        let p = &self.design.prs;
        let description = format!(
            "The 3-PRS compliant stage of a `stage` case (Ruiz et al. 2019, §5) as a `static` mesh case, written by flexfem: the same FE model from native parts. Nodes and elements in the stage model's order: node {} is the platform centre P (master of the platform's rigid link); leg i's slider node (nodes {}, {}, {}) carries the slider frame (rows e_i, m_i, e_i x m_i) in which the guide fixes all but ux, the actuator force or stroke acting along e_i. Hinges are `hinge` elements over the notch and its load-spreading zone (the stage's hinge regions); legs are {} w x h = {} x {} mm beams. L = {} mm, b = {} mm, a = {} mm.{}",
            self.platform,
            self.legs[0].slider,
            self.legs[1].slider,
            self.legs[2].slider,
            self.design.leg_elements,
            self.design.leg_w,
            self.design.leg_h,
            p.l,
            p.b,
            p.a,
            match nonlinear_steps {
                Some(_) => format!(
                    " Geometrically nonlinear: each hinge of {} co-rotational segments, as the stage's nonlinear solve; their inner nodes and elements follow the listed ones.",
                    super::NONLINEAR_HINGE_SEGMENTS
                ),
                None => String::new(),
            }
        );
        let mut case = json!({
            "analysis": "static",
            "description": description,
            "materials": {"stage": material_json(&self.design.material)},
            "sections": {"leg": {"shape": "rect", "w": self.design.leg_w, "h": self.design.leg_h}},
            "nodes": model.nodes,
            "elements": elements,
            "rigid_links": rigid,
            "supports": supports,
            "load_cases": load_cases,
        });
        if let Some(steps) = nonlinear_steps {
            case["nonlinear"] = json!(true);
            case["steps"] = json!(steps);
        }
        Some(case)
    }
}
