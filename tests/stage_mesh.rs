//! `stage --out` writes `stage_mesh.json`, the stage as a `static` mesh case (hinge elements,
//! slider frames, rigid platform). Run as-is through `static` it must give the stage's platform
//! pose, strokes and hinge stresses to 1e-9 relative, linear and nonlinear: it is the same FE
//! model (same nodes, elements, compliances and solver), written from native mesh parts, so
//! only rounding separates the two (the reference is the `stage` analysis itself). Hinge
//! stresses are compared both from the `static` result's per-hinge `peak_von_mises` and from the
//! library (the hinge elements' end section forces through `HingeRegion::peak_stress`).

mod common;
use common::*;
use flexfem::analysis::{self, Case};
use flexfem::case;
use flexfem::fem;
use flexfem::hinge::{self, HingeSpec};
use flexfem::stage::{StageModel, NONLINEAR_HINGE_SEGMENTS};
use nalgebra::{Matrix3, Rotation3, Vector3};
use serde_json::Value;
use std::path::{Path, PathBuf};

const TOL: f64 = 1e-9;

fn read(p: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap()
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// Runs `flexfem run CASE --out DIR` in the crate root; returns DIR.
fn run_out(case: &Path, name: &str) -> PathBuf {
    let d = tempdir(name);
    let out = run(&["run", case.to_str().unwrap(), "--out", d.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "{}: {}", case.display(), stderr(&out));
    d
}

/// The stage model of a bundled stage case (node and element indices, slider directions).
fn stage_model(case_file: &str) -> StageModel {
    let Case::Stage(c) = analysis::load(&root().join(case_file)).unwrap() else {
        panic!("{case_file} is not a stage case")
    };
    c.validated().unwrap().0.build()
}

/// Peak von Mises stress of each hinge element of the mesh case (spec element order), from its
/// own FE solve through the library: the element region of [`hinge::hinge_element`] at the node
/// distance, stress model [`hinge::HingeRegion::peak_stress`] on the end section forces (of the
/// first and last segment of a chain: its inner elements come after the case's own, in order).
fn mesh_hinge_stresses(mesh_file: &Path) -> Vec<Vec<(usize, f64)>> {
    let Case::Static(sc) = analysis::load(mesh_file).unwrap() else {
        panic!("stage_mesh.json is not a static case")
    };
    let model = sc.model.build().unwrap();
    let cases: Vec<fem::CaseResult> = match sc.steps.filter(|_| sc.nonlinear) {
        Some(steps) => {
            let opts = fem::NonlinearOptions {
                steps,
                ..Default::default()
            };
            fem::solve_nonlinear(&model, &opts)
                .unwrap()
                .load_cases
                .into_iter()
                .map(|c| c.fe)
                .collect()
        }
        None => fem::solve_static(&model).unwrap().load_cases,
    };
    let material = sc.model.materials["stage"].resolve("materials.stage").unwrap();
    let n_spec = sc.model.elements.len();
    let mut hinges = Vec::new();
    let mut chain_next = n_spec;
    for (ie, e) in sc.model.elements.iter().enumerate() {
        let case::mesh::ElementSpec::Hinge {
            nodes,
            hinge: h,
            segments,
            ..
        } = e
        else {
            continue;
        };
        let mut hv = h.clone();
        hv["blank_length"] = 0.0.into();
        let spec: HingeSpec = serde_json::from_value(hv).unwrap();
        let (a, b) = (
            Vector3::from(sc.model.nodes[nodes[0]]),
            Vector3::from(sc.model.nodes[nodes[1]]),
        );
        let region = hinge::hinge_element(&spec, &material, (b - a).norm()).unwrap();
        let n = segments.unwrap_or(1);
        let last = if n > 1 {
            chain_next += n - 1;
            chain_next - 1
        } else {
            ie
        };
        hinges.push((ie, last, region));
    }
    cases
        .iter()
        .map(|c| {
            hinges
                .iter()
                .map(|(first, last, region)| {
                    let sf = [
                        c.elements[*first].section_forces[0],
                        c.elements[*last].section_forces[1],
                    ];
                    (*first, region.peak_stress(&sf))
                })
                .collect()
        })
        .collect()
}

/// Largest |entry| of a list.
fn amax(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |m, x| m.max(x.abs()))
}

/// Relative difference of `got` to `want`, both lists, relative to `scale`.
fn worst(got: &[f64], want: &[f64], scale: f64) -> f64 {
    assert_eq!(got.len(), want.len());
    got.iter().zip(want).fold(0.0, |m, (g, w)| m.max((g - w).abs() / scale))
}

/// The must-show comparison for one bundled stage case; returns the worst relative differences
/// (pose, strokes, hinge stresses) over its load cases.
fn compare(case_file: &str, name: &str) -> [f64; 3] {
    let s = stage_model(case_file);
    let stage_dir = run_out(&root().join(case_file), &format!("{name}-stage"));
    let mesh_file = stage_dir.join("stage_mesh.json");
    let mesh = read(&mesh_file);
    let nonlinear = mesh["nonlinear"].as_bool().unwrap_or(false);
    // The written model: six hinge elements, one rigid platform, three framed slider guides.
    let elements = mesh["elements"].as_array().unwrap();
    let n_hinges = elements.iter().filter(|e| e["type"] == "hinge").count();
    assert_eq!(n_hinges, 6, "{case_file}: hinge elements");
    assert_eq!(mesh["rigid_links"].as_array().unwrap().len(), 1);
    let supports = mesh["supports"].as_array().unwrap();
    assert_eq!(supports.len(), 3);
    assert!(supports.iter().all(|s| s["frame"].is_array()));
    assert!(mesh["description"].as_str().unwrap().contains("static"));
    if nonlinear {
        assert!(elements
            .iter()
            .filter(|e| e["type"] == "hinge")
            .all(|e| e["segments"] == NONLINEAR_HINGE_SEGMENTS));
    }

    let stage = read(&stage_dir.join("result.json"));
    let mesh_dir = run_out(&mesh_file, &format!("{name}-mesh"));
    let stat = read(&mesh_dir.join("result.json"));
    let srows = stage["load_cases"].as_array().unwrap();
    let mrows = stat["load_cases"].as_array().unwrap();
    assert_eq!(srows.len(), mrows.len());
    let stresses = mesh_hinge_stresses(&mesh_file);
    let l = s.design.prs.l;
    let mut w = [0.0f64; 3];
    for (ic, (sr, mr)) in srows.iter().zip(mrows).enumerate() {
        assert_eq!(sr["name"], mr["name"]);
        let d = &mr["displacements"];
        // Platform pose: translations of P; rotations as the stage reports them (small
        // rotation components when linear, the angles of R = Ry(θ)·Rx(ψ)·Rz(φ) when nonlinear).
        let up: Vec<f64> = (0..6).map(|k| f(&d[s.platform][k])).collect();
        let rot = if nonlinear {
            let rv = Vector3::new(up[3], up[4], up[5]).map(f64::to_radians);
            let r: Matrix3<f64> = *Rotation3::from_scaled_axis(rv).matrix();
            let (psi, theta, phi) = flexfem::stage::pose_angles(&r);
            [psi, theta, phi].map(f64::to_degrees).to_vec()
        } else {
            up[3..].to_vec()
        };
        let p = &sr["platform"];
        let want_t: Vec<f64> = ["x", "y", "z"].iter().map(|k| f(&p[*k])).collect();
        let want_r: Vec<f64> = ["psi_deg", "theta_deg", "phi_deg"].iter().map(|k| f(&p[*k])).collect();
        let t_scale = amax(&want_t);
        // Rotations relative to the larger of their own size and the translation over the leg
        // length (a symmetric case has no rotation but rounding noise).
        let r_scale = amax(&want_r).max((t_scale / l).to_degrees());
        let pose = worst(&up[..3], &want_t, t_scale).max(worst(&rot, &want_r, r_scale));
        // Strokes: slider displacement along eᵢ.
        let strokes: Vec<f64> = s
            .legs
            .iter()
            .map(|leg| (0..3).map(|k| leg.e[k] * f(&d[leg.slider][k])).sum())
            .collect();
        let want_s: Vec<f64> = (0..3).map(|i| f(&sr["strokes"][i])).collect();
        let stroke = worst(&strokes, &want_s, amax(&want_s));
        // Hinge stresses per leg.
        let by_el = |el: Option<usize>| {
            let el = el.unwrap();
            stresses[ic].iter().find(|(e, _)| *e == el).unwrap().1
        };
        // Revolute hinges of the three legs, then spherical ones.
        let per_hinge = |of: &dyn Fn(Option<usize>) -> f64| -> Vec<f64> {
            let rev = s.legs.iter().map(|leg| of(leg.rev_element));
            rev.chain(s.legs.iter().map(|leg| of(leg.sph_element))).collect()
        };
        let got_h = per_hinge(&by_el);
        let hs = &sr["hinge_stress"];
        let want_h: Vec<f64> = (0..3)
            .map(|i| f(&hs["revolute"][i]))
            .chain((0..3).map(|i| f(&hs["spherical"][i])))
            .collect();
        // The same from the `static` result's per-hinge peak von Mises (`hinges[k].element`
        // is the case element, the stage model's element index).
        let from_result = |el: Option<usize>| {
            let el = el.unwrap();
            let h = mr["hinges"].as_array().unwrap();
            f(&h.iter().find(|h| h["element"] == el).unwrap()["peak_von_mises"])
        };
        let got_r = per_hinge(&from_result);
        let stress = worst(&got_h, &want_h, amax(&want_h)).max(worst(&got_r, &want_h, amax(&want_h)));
        eprintln!(
            "{case_file} `{}`: pose {pose:.2e}, strokes {stroke:.2e}, hinge stresses {stress:.2e}",
            sr["name"]
        );
        w = [w[0].max(pose), w[1].max(stroke), w[2].max(stress)];
    }
    w
}

#[test]
fn stage_mesh_reproduces_the_linear_stage() {
    let w = compare("cases/ruiz2019_stage.json", "lin");
    assert!(w.iter().all(|&x| x <= TOL), "worst [pose, strokes, stresses] {w:?}");
}

#[test]
fn stage_mesh_reproduces_the_nonlinear_stage() {
    let w = compare("cases/ruiz2019_stage_nonlinear.json", "nl");
    assert!(w.iter().all(|&x| x <= TOL), "worst [pose, strokes, stresses] {w:?}");
}

/// With ideal joints (exact releases, stiff legs; the `stage` analysis itself refuses this
/// model under forces, a mechanism, so only the library writes it) the mesh case holds `joint`
/// elements — a revolute joint at each slider in the frame (mᵢ, eᵢ × mᵢ, eᵢ), the slider guide
/// and stroke in the same frame, a spherical joint at each platform point — and through
/// `static` gives the stage's stroke-driven platform pose to 1e-9 of its translation (the
/// stage's slider frame is (eᵢ, mᵢ, eᵢ × mᵢ): the frames differ, so only rounding of the
/// rotated constraint rows separates the two solves).
#[test]
fn ideal_joint_stage_mesh_has_joint_elements_and_the_same_pose() {
    let Case::Stage(mut c) = analysis::load(&root().join("cases/ruiz2019_stage.json")).unwrap() else {
        panic!()
    };
    c.stage.ideal_joints = true;
    // With ideal joints the sliders are free: load cases give strokes (forces are refused).
    for lc in &mut c.load_cases {
        lc.actuator_forces = None;
        lc.actuator_strokes = Some([0.1; 3]);
    }
    let s = c.validated().unwrap().0.build();
    let strokes = [1.0, 0.5, -0.3];
    let cases = vec![("s".to_string(), flexfem::stage::Drive::Strokes(strokes))];
    let want = s.solve(&cases).unwrap().remove(0);
    let mesh = s.mesh_case(&cases, None).unwrap();
    let joints: Vec<&Value> = mesh["elements"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|e| e["type"] == "joint")
        .collect();
    assert_eq!(joints.len(), 6);
    assert_eq!(joints.iter().filter(|j| j["kind"] == "revolute").count(), 3);
    let Case::Static(sc) = analysis::parse_value(mesh, None).unwrap() else {
        panic!()
    };
    let got = &fem::solve_static(&sc.model.build().unwrap()).unwrap().load_cases[0];
    let up = got.displacements[s.platform];
    let p = want.platform;
    let w = [p.x, p.y, p.z, p.psi, p.theta, p.phi];
    let t_scale = amax(&w[..3]);
    let r_scale = amax(&w[3..]).max(t_scale / s.design.prs.l);
    let dt = worst(&up[..3], &w[..3], t_scale);
    let dr = worst(&up[3..], &w[3..], r_scale);
    let stroke: Vec<f64> = s
        .legs
        .iter()
        .map(|leg| (0..3).map(|k| leg.e[k] * got.displacements[leg.slider][k]).sum())
        .collect();
    let ds = worst(&stroke, &strokes, 1.0);
    eprintln!("ideal joints: pose {w:?}; translation {dt:.2e}, rotation {dr:.2e}, strokes {ds:.2e}");
    assert!(
        t_scale > 0.1 && amax(&w[3..]) > 1e-3,
        "the strokes move the platform: {w:?}"
    );
    assert!(dt <= TOL && dr <= TOL && ds <= TOL, "{dt:e} {dr:e} {ds:e}");
}

/// A small mesh: a circular-notch hinge between node 0 (clamped) and node 1, plus `extra`
/// fields on the hinge element and a joint at node 1 with `joint` fields.
fn hinge_case(extra: &str, joint: &str) -> String {
    format!(
        r#"{{"analysis": "static", "description": "test", "materials": {{"m": "Al7075"}},
        "nodes": [[0, 0, 0], [20, 0, 0], [20, 0, 0]],
        "elements": [
          {{"type": "hinge", "nodes": [0, 1], "hinge": {{"type": "circular_notch", "R": 5, "t": 1, "w": 10, "h": 8}},
            "material": "m", "up": [0, 0, 1]{extra}}},
          {{"type": "joint", "kind": "revolute", "nodes": [1, 2]{joint}}}
        ],
        "supports": [{{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}},
                     {{"node": 2, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}}],
        "load_cases": [{{"name": "m", "forces": [{{"node": 1, "F": [0, 0, 0, 0, 100, 0]}}]}}]}}"#
    )
}

/// Bad `segments` and a joint `frame` given with `axis` are refused naming the JSON path
/// (exit 2); a valid chain of segments keeps the linear response of one element (the segment
/// compliances sum to the whole region's up to the quadrature; measured 6e-14, asserted 1e-9).
#[test]
fn segments_and_joint_frame_are_checked() {
    let x_frame = r#", "frame": [[0, 1, 0], [0, 0, 1], [1, 0, 0]]"#;
    for (extra, joint, path) in [
        (r#", "segments": 0"#, x_frame, "elements[0].segments"),
        (r#", "segments": 65"#, x_frame, "elements[0].segments"),
        (
            "",
            r#", "frame": [[0, 1, 0], [0, 0, 1], [1, 0, 0]], "axis": [0, 1, 0]"#,
            "elements[1].axis",
        ),
        (
            "",
            r#", "frame": [[0, 1, 0], [0, 0, 1], [0, 1, 0]]"#,
            "elements[1].frame",
        ),
    ] {
        let out = run_case_text("stagemesh-bad", &hinge_case(extra, joint));
        assert_eq!(out.status.code(), Some(2), "{extra} {joint}: {}", stderr(&out));
        assert!(stderr(&out).contains(path), "{path}: {}", stderr(&out));
    }
    // The joint about local x = global y, the moment about y: the hinge is free to turn (the
    // revolute joint releases it), so node 1 turns by M·c_yy of the hinge.
    let rot = |extra: &str| {
        let Case::Static(sc) = analysis::parse(&hinge_case(extra, x_frame)).unwrap() else {
            panic!()
        };
        let m = sc.model.build().unwrap();
        fem::solve_static(&m).unwrap().load_cases[0].displacements[1][4]
    };
    let (one, four) = (rot(""), rot(r#", "segments": 4"#));
    eprintln!("hinge rotation: one element {one:e} rad, 4 segments {four:e} rad");
    assert!(one > 0.0 && ((four - one) / one).abs() < 1e-9, "{one} vs {four}");
}
