//! The stage as a `static` mesh case (`stage_mesh.json`): the same FE model written with the
//! native parts of mesh cases — nodes, a w × h `rect` leg section, `hinge` elements for the
//! revolute notches and spherical necks (each spanning the same hinge region as the stage's own
//! flexibility element, so it gets the same compliance), `beam` legs, a rigid link for the
//! platform, slider supports in the slider frames and the load cases as forces or prescribed
//! strokes along the sliders — so `flexfem run stage_mesh.json` solves the model the stage
//! solves. Nodes and elements are written in the stage model's order, so node and element
//! indices (and with them the solution) are the stage's.
//!
//! With ideal joints the releases become `joint` elements (after the beams: they build no FE
//! element): a revolute joint between each slider node and the coincident foot of the leg, in
//! the frame (mᵢ, eᵢ × mᵢ, eᵢ) — joint axis mᵢ as local x, the slider direction as local z, so
//! the slider guide (all fixed but uz) and the strokes act in the same node frame — and a
//! spherical joint at each platform point; legs and platform links stay the stiff beams.

use super::*;
use crate::fem::{self, Element};
use serde_json::{json, Map, Value};

/// Names of the DOFs in case files, in the order ux uy uz rx ry rz.
/// Stiffening of legs and platform links with ideal joints (as the stage builder).
const STIFF: f64 = 1e6;

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
    /// `None` only if the model holds elements the stage does not build (springs, shells).
    pub fn mesh_case(&self, cases: &[(String, Drive)], nonlinear_steps: Option<usize>) -> Option<Value> {
        let ideal = self.design.ideal_joints;
        let model = &self.model;
        let segments = nonlinear_steps.map(|_| super::NONLINEAR_HINGE_SEGMENTS);
        let mut elements = Vec::with_capacity(model.elements.len() + 6);
        let mut materials = Map::new();
        materials.insert("stage".into(), material_json(&self.design.material));
        let mut sections = Map::new();
        sections.insert(
            "leg".into(),
            json!({"shape": "rect", "w": self.design.leg_w, "h": self.design.leg_h}),
        );
        // Slider frames: the stage's (eᵢ, mᵢ, eᵢ × mᵢ), or with ideal joints the revolute
        // joint's (mᵢ, eᵢ × mᵢ, eᵢ), whose DOF k is the stage frame's `dof[k]`.
        let slider_frame = |i: usize| -> Option<[[f64; 3]; 3]> {
            let leg = &self.legs[i];
            if ideal {
                Some(build::rows(leg.m, leg.e.cross(&leg.m), leg.e))
            } else {
                model.frames.get(&leg.slider).copied()
            }
        };
        let dof = |k: usize| if ideal { [1, 2, 0][k % 3] + 3 * (k / 3) } else { k };
        let stroke_dof = dof_index_of(0, &dof);
        for (ie, el) in model.elements.iter().enumerate() {
            match el {
                Element::Beam(b) => {
                    let section = match b.section {
                        fem::Section::Rect { .. } => "leg",
                        fem::Section::Circle { d } => {
                            sections.insert("platform_link".into(), json!({"shape": "circle", "d": d}));
                            "platform_link"
                        }
                        _ => return None,
                    };
                    let material = if b.material == self.design.material {
                        "stage"
                    } else {
                        materials.insert("stiff".into(), material_json(&b.material));
                        "stiff"
                    };
                    elements.push(json!({
                        "type": "beam",
                        "nodes": b.nodes,
                        "section": section,
                        "material": material,
                        "up": b.up,
                    }))
                }
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
                Element::Spring(_) | Element::Shell4(_) | Element::Shell9(_) | Element::Matrix(_) => return None,
            }
        }
        if ideal {
            for (i, leg) in self.legs.iter().enumerate() {
                elements.push(json!({
                    "type": "joint", "kind": "revolute", "nodes": [leg.slider, leg.rev_top], "frame": slider_frame(i),
                }));
                elements.push(json!({
                    "type": "joint", "kind": "spherical", "nodes": [leg.sph_top, leg.sph_bottom],
                }));
            }
        }
        let supports: Vec<Value> = model
            .supports
            .iter()
            .map(|s| {
                let leg = self.legs.iter().position(|l| l.slider == s.node);
                let frame = match leg {
                    Some(i) => slider_frame(i),
                    None => model.frames.get(&s.node).copied(),
                };
                let mut fix: Vec<usize> = (0..6).filter(|&k| s.fix[k]).collect();
                if leg.is_some() {
                    fix = fix.into_iter().map(|k| dof_index_of(k, &dof)).collect();
                    fix.sort();
                }
                let names: Vec<&str> = fix.iter().map(|&k| DOF_NAMES[k]).collect();
                let mut o = json!({"node": s.node, "fix": names});
                if let Some(f) = frame {
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
                let frame = slider_frame;
                match drive {
                    Drive::Forces(f) => json!({
                        "name": name,
                        "forces": (0..3).map(|i| {
                            let mut v = [0.0; 6];
                            v[stroke_dof] = f[i];
                            json!({"node": self.legs[i].slider, "F": v, "frame": frame(i)})
                        }).collect::<Vec<_>>(),
                    }),
                    Drive::Strokes(s) => json!({
                        "name": name,
                        "displacements": (0..3).map(|i| json!({
                            "node": self.legs[i].slider,
                            "dof": DOF_NAMES[stroke_dof],
                            "value": s[i],
                            "frame": frame(i),
                        })).collect::<Vec<_>>(),
                    }),
                }
            })
            .collect();
        let p = &self.design.prs;
        let joints = if ideal {
            format!(
                "Ideal joints (a consistency check): the hinges are exact releases, `joint` elements listed after the beams (revolute at each slider in the frame (m_i, e_i x m_i, e_i), spherical at each platform point); legs and the links from P to the platform points are beams of the stage material {}x stiffer. Leg i's slider node (nodes {}, {}, {}) carries that frame, in which the guide fixes all but uz, the actuator force or stroke acting along e_i = local z.",
                STIFF, self.legs[0].slider, self.legs[1].slider, self.legs[2].slider
            )
        } else {
            format!(
                "Hinges are `hinge` elements over the notch and its load-spreading zone (the stage's hinge regions); the platform is a rigid link from P to the neck tops. Leg i's slider node (nodes {}, {}, {}) carries the slider frame (rows e_i, m_i, e_i x m_i), in which the guide fixes all but ux, the actuator force or stroke acting along e_i = local x.",
                self.legs[0].slider, self.legs[1].slider, self.legs[2].slider
            )
        };
        let description = format!(
            "The 3-PRS compliant stage of a `stage` case (Ruiz et al. 2019, sec. 5) as a `static` mesh case, written by flexfem: the same FE model from native parts, nodes and elements in the stage model's order. Node {} is the platform centre P. {joints} Legs: {} beams each, w x h = {} x {} mm. L = {} mm, b = {} mm, a = {} mm.{}",
            self.platform,
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
            "materials": materials,
            "sections": sections,
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

/// The index of the stage-frame DOF `k` in the written frame (`dof` maps written → stage).
fn dof_index_of(k: usize, dof: &impl Fn(usize) -> usize) -> usize {
    (0..6).find(|&j| dof(j) == k).unwrap_or(k)
}
