//! Generators of the bundled mechanism meshes and cases (`meshes/parallelogram_notch.json`,
//! `cases/parallelogram_guide.json`, `cases/lever_amplifier.json`, `meshes/pantilt_8r.json`,
//! `cases/pantilt_8r.json`): the single source of their geometry, with every assumed dimension
//! documented here. `tests/mechanisms.rs` checks the bundled files equal what these functions
//! write (and rewrites them with `FLEXFEM_BLESS=1`); `benches/mechanisms.rs` builds the
//! hinge-parameter variants of the pan-tilt from the same code.
#![allow(dead_code)]

use serde_json::{json, Value};

/// A small model builder: nodes, elements, supports, in file order.
#[derive(Default)]
pub struct Builder {
    /// `segments` of every hinge element (co-rotational chain for nonlinear runs), if set.
    pub segments: Option<usize>,
    pub nodes: Vec<[f64; 3]>,
    pub elements: Vec<Value>,
    pub supports: Vec<Value>,
}

/// Rounds a coordinate to 1e-9 mm so the bundled files read cleanly (the geometry is exact to
/// far below any tolerance).
fn r9(x: f64) -> f64 {
    let y = (x * 1e9).round() / 1e9;
    if y == 0.0 {
        0.0
    } else {
        y
    }
}

impl Builder {
    pub fn node(&mut self, x: [f64; 3]) -> usize {
        self.nodes.push([r9(x[0]), r9(x[1]), r9(x[2])]);
        self.nodes.len() - 1
    }

    /// A `hinge` element a→b (compliant axis = local y; the notch thins along local z = `up`).
    pub fn hinge(&mut self, a: usize, b: usize, spec: &Value, material: &str, up: [f64; 3]) -> usize {
        let mut e = json!({"type": "hinge", "nodes": [a, b], "hinge": spec, "material": material, "up": rounded(up)});
        if let Some(n) = self.segments {
            e["segments"] = json!(n);
        }
        self.elements.push(e);
        self.elements.len() - 1
    }

    pub fn beam(&mut self, a: usize, b: usize, section: &str, material: &str, up: [f64; 3]) -> usize {
        self.elements.push(
            json!({"type": "beam", "nodes": [a, b], "section": section, "material": material, "up": rounded(up)}),
        );
        self.elements.len() - 1
    }

    pub fn rigid(&mut self, master: usize, slaves: &[usize]) -> usize {
        self.elements
            .push(json!({"type": "rigid", "master": master, "slaves": slaves}));
        self.elements.len() - 1
    }

    pub fn clamp(&mut self, node: usize) {
        self.supports
            .push(json!({"node": node, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}));
    }

    /// The model part of a mesh file (materials and sections given by the caller).
    pub fn mesh(&self, materials: Value, sections: Value) -> Value {
        json!({
            "materials": materials,
            "sections": sections,
            "nodes": self.nodes,
            "elements": self.elements,
            "supports": self.supports,
        })
    }
}

fn rounded(v: [f64; 3]) -> [f64; 3] {
    [r9(v[0]), r9(v[1]), r9(v[2])]
}

pub fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
pub fn add(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
pub fn scale(a: [f64; 3], s: f64) -> [f64; 3] {
    [a[0] * s, a[1] * s, a[2] * s]
}
pub fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
pub fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
pub fn unit(a: [f64; 3]) -> [f64; 3] {
    scale(a, 1.0 / dot(a, a).sqrt())
}

// ---------------------------------------------------------------------------------------------
// Parallelogram guide
// ---------------------------------------------------------------------------------------------

/// Dimensions of the parallelogram guide (all assumed, a textbook flexure guide in Al 7075-T6):
/// circular notches R = 5, t = 1 in a w = 10 (out of plane, global z) × h = 10 (in plane) bar;
/// each hinge element is `HINGE_LEN` = 15 mm long (the 10 mm notch plus 2.5 mm of bar on each
/// side); leg length between the notch centres `LEG` = 100 mm; legs `SPAN` = 40 mm apart.
/// (With 50 mm legs the point-pivot linkage misses the parasitic drop by 2.6 %: the notch turns
/// the leg over a few millimetres, not at a point — see `tests/mechanisms.rs`.)
pub const PARA_R: f64 = 5.0;
pub const PARA_T: f64 = 1.0;
pub const PARA_W: f64 = 10.0;
pub const PARA_H: f64 = 10.0;
pub const PARA_HINGE_LEN: f64 = 15.0;
pub const PARA_LEG: f64 = 100.0;
/// Co-rotational segments of each hinge element of the parallelogram.
pub const PARA_SEGMENTS: usize = 8;
pub const PARA_SPAN: f64 = 40.0;

/// The circular notch of the parallelogram, as in a `hinge` element (no blank length).
pub fn parallelogram_hinge() -> Value {
    json!({"type": "circular_notch", "R": PARA_R, "t": PARA_T, "w": PARA_W, "h": PARA_H})
}

/// Node of the moving bar's centre (the loaded / prescribed node) in `parallelogram_mesh`.
pub const PARA_BAR_NODE: usize = 8;

/// The parallelogram guide in the x–y plane: two vertical legs (along +y) at x = 0 and x =
/// `SPAN`; each leg is a hinge element at its foot (centred at y = 0), a rigid link, and a
/// hinge element at its head (centred at y = `LEG`). The feet are clamped; the heads carry the
/// moving bar, a rigid body whose master node `PARA_BAR_NODE` sits at (SPAN/2, LEG + 7.5, 0).
/// The guided motion is along x; the compliant axes are global z (up = [1, 0, 0]: the notches
/// thin along x).
pub fn parallelogram_mesh() -> Value {
    parallelogram_mesh_with(PARA_LEG)
}

/// `parallelogram_mesh` with legs of `leg` mm between the notch centres.
pub fn parallelogram_mesh_with(leg: f64) -> Value {
    // 8 co-rotational segments per hinge: the parasitic drop within 2 % of the linkage's (one
    // segment: 7.6 % short, see tests/mechanisms.rs).
    let mut b = Builder {
        segments: Some(PARA_SEGMENTS),
        ..Builder::default()
    };
    let half = PARA_HINGE_LEN / 2.0;
    let spec = parallelogram_hinge();
    let mut heads = Vec::new();
    for &x in &[0.0, PARA_SPAN] {
        let n0 = b.node([x, -half, 0.0]);
        let n1 = b.node([x, half, 0.0]);
        let n2 = b.node([x, leg - half, 0.0]);
        let n3 = b.node([x, leg + half, 0.0]);
        b.hinge(n0, n1, &spec, "al", [1.0, 0.0, 0.0]);
        b.rigid(n1, &[n2]);
        b.hinge(n2, n3, &spec, "al", [1.0, 0.0, 0.0]);
        b.clamp(n0);
        heads.push(n3);
    }
    let bar = b.node([PARA_SPAN / 2.0, leg + half, 0.0]);
    assert_eq!(bar, PARA_BAR_NODE);
    b.rigid(bar, &heads);
    let mut mesh = b.mesh(json!({"al": "Al7075"}), json!({}));
    mesh.as_object_mut().unwrap().shift_remove("sections");
    mesh
}

/// `cases/parallelogram_guide.json`: the guide pushed 1 mm along x at the bar centre (the other
/// DOFs of the bar free), linear and — in a second file of the test — nonlinear.
pub fn parallelogram_case() -> Value {
    json!({
        "analysis": "static",
        "mesh": "../meshes/parallelogram_notch.json",
        "load_cases": [
            {"name": "push_x_1N", "forces": [{"node": PARA_BAR_NODE, "F": [1, 0, 0, 0, 0, 0]}]},
            {"name": "stroke_1mm", "displacements": [{"node": PARA_BAR_NODE, "dof": "ux", "value": 1}]}
        ]
    })
}

// ---------------------------------------------------------------------------------------------
// Yu, Lu and Hao (2016): 8R pan-tilt
// ---------------------------------------------------------------------------------------------

/// How the links of the pan-tilt are modelled.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Links {
    /// Rigid bodies (rigid links between the hinge ends).
    Rigid,
    /// Nylon 66 beams of the hinge blank section (w × h), straight between the hinge ends.
    Nylon,
}

/// The corner-filleted hinge of the pan-tilt and the options of the model. Paper notation
/// (Yu, Lu and Hao (2016), Fig. 2 and Table 3): blank height h, width t, notch length l, fillet radius R,
/// minimum thickness δ. In the `hinge` element: `w` = paper t, `t` = paper δ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PanTilt {
    pub h: f64,
    pub width: f64,
    pub l: f64,
    pub r: f64,
    pub delta: f64,
    pub links: Links,
    /// Include the passive limb J3–J6–J8.
    pub passive_limb: bool,
}

impl PanTilt {
    /// The paper's standard hinge: h = 15, t = 10, l = 5, R = 1.75, δ = 0.6 mm.
    pub fn standard() -> PanTilt {
        PanTilt {
            h: 15.0,
            width: 10.0,
            l: 5.0,
            r: 1.75,
            delta: 0.6,
            links: Links::Nylon,
            passive_limb: true,
        }
    }

    /// Table 3 of Yu, Lu and Hao (2016): (label, hinge, paper's FEM pitch (deg), paper's FEM phase (deg)).
    pub fn table3() -> Vec<(&'static str, PanTilt, f64, f64)> {
        let s = PanTilt::standard();
        vec![
            ("standard", s, 9.195, 47.68),
            ("variant 1: t = 15", PanTilt { width: 15.0, ..s }, 9.399, 46.84),
            ("variant 2: l = 8", PanTilt { l: 8.0, ..s }, 9.248, 47.58),
            ("variant 3: R = 2", PanTilt { r: 2.0, ..s }, 9.070, 48.20),
            ("variant 4: delta = 1", PanTilt { delta: 1.0, ..s }, 8.253, 51.13),
            ("variant 5: h = 10", PanTilt { h: 10.0, ..s }, 8.710, 48.98),
            (
                "no passive limb",
                PanTilt {
                    passive_limb: false,
                    ..s
                },
                9.155,
                47.38,
            ),
        ]
    }

    pub fn hinge_spec(&self) -> Value {
        json!({"type": "corner_filleted", "l": self.l, "R": self.r, "t": self.delta, "w": self.width, "h": self.h})
    }
}

/// Length of every pan-tilt hinge element (the paper's hinge block "L = 15 mm" of its §4.1):
/// the notch l plus (15 − l)/2 of blank on each side.
pub const PT_HINGE_LEN: f64 = 15.0;
/// Positions of the joints along their axes from the centre of the sphere, a1 … a8 (Yu, Lu and Hao (2016)
/// §2.1): a1 = a2 = a3 = 40, a4 = a5 = 65, a6 = 55, a7 = 70, a8 = 48 mm.
pub const PT_A: [f64; 8] = [40.0, 40.0, 40.0, 65.0, 65.0, 55.0, 70.0, 48.0];
/// The PRBM inverse kinematics of Yu, Lu and Hao (2016) for pitch 10°, phase 45° (its §3).
pub const PT_THETA: [f64; 2] = [7.36, 3.09];
/// Azimuths βj of the middle-joint axes (deg): 270° and 150° reproduce the paper's
/// θ₁ = 7.36°, θ₂ = 3.09°; the passive limb's 30° completes the 120° pattern (assumed).
pub const PT_BETA: [f64; 3] = [270.0, 150.0, 30.0];
/// Elevation of the middle-joint axes at home, αj = 30° (θ0 = 60° from the top axis).
pub const PT_ALPHA: f64 = 30.0;

/// Joint axes at home: r1, r2, r3 (base, horizontal), r4, r5, r6 (middle), r7 = r8 = z (top).
pub fn pantilt_axes() -> [[f64; 3]; 8] {
    let mut r = [[0.0; 3]; 8];
    let al = PT_ALPHA.to_radians();
    for j in 0..3 {
        let b = PT_BETA[j].to_radians();
        // Base axis k = d × z, d = (cos β, sin β, 0): a positive rotation raises the middle axis.
        r[j] = [b.sin(), -b.cos(), 0.0];
        r[j + 3] = [al.cos() * b.cos(), al.cos() * b.sin(), al.sin()];
    }
    r[6] = [0.0, 0.0, 1.0];
    r[7] = [0.0, 0.0, 1.0];
    r
}

/// Indices (0-based joint numbers, J1 = 0) of the bodies' hinges in the chains: (joint, the
/// previous joint on its limb or `None` at the base, the next joint for base joints).
const PT_CHAIN: [(usize, Option<usize>, usize); 8] = [
    (0, None, 3),    // J1 base of limb 1 → J4
    (1, None, 4),    // J2 base of limb 2 → J5
    (2, None, 5),    // J3 base of the passive limb → J6
    (3, Some(0), 6), // J4: link A (J1–J4) | link B (J4–J7)
    (4, Some(1), 6), // J5: link C (J2–J5) | platform
    (5, Some(2), 7), // J6: link D (J3–J6) | link E (J6–J8)
    (6, Some(3), 6), // J7: link B | platform
    (7, Some(5), 7), // J8: link E | platform
];

/// Hinge-end nodes (proximal a, distal b) per joint, and the node whose rotation is the
/// platform's (the distal end of J7), returned with the mesh.
pub struct PanTiltMesh {
    pub mesh: Value,
    /// Proximal and distal node of each joint's hinge element, J1 … J8.
    pub ends: [[usize; 2]; 8],
    /// The platform node (distal end of J7, on the platform).
    pub platform: usize,
}

/// Yu, Lu and Hao's (2016) 8R spherical pan-tilt (RRR–RR–RRR), every joint a corner-filleted hinge element:
///
/// * Every joint axis passes through the centre O of the sphere (origin); joint Ji's hinge is
///   centred on its axis at a_i (`PT_A`) from O. Axes at home (`pantilt_axes`): base axes r1,
///   r2, r3 horizontal, normal to the vertical planes at azimuths βj (`PT_BETA`); middle axes
///   r4, r5, r6 at 30° elevation in those planes (90° from the base axis of the limb, 60° from
///   the top axis); top axes r7 = r8 = z (coaxial at home, as the paper's Fig. 1a).
/// * Topology: limb 1 = J1 (ground|link A), J4 (A|B), J7 (B|platform); limb 2 = J2
///   (ground|link C), J5 (C|platform); passive limb 3 = J3 (ground|D), J6 (D|E), J8
///   (E|platform). The platform carries J5, J7 and J8 (r5·r7 = cos 60° stays fixed, as in
///   the paper's Eq. (6)).
/// * Each hinge element is 15 mm long (`PT_HINGE_LEN`), its local y (compliant axis) the joint
///   axis, its local x (along the notch) normal to the axis and pointing along the chain: for
///   a base joint along the projection of (next joint centre − own centre), for the others
///   along the projection of (own centre − previous joint centre), both projected normal to
///   the joint axis (assumed: the paper's Fig. 3 shows curved links whose exact shape is not
///   given).
/// * Links: straight between the distal end of one hinge and the proximal end of the next,
///   rigid or nylon beams of the hinge blank section (width along the proximal joint's axis);
///   the platform is a rigid body (master: the distal end of J7).
/// * Supports: the proximal ends of J1, J2, J3 clamped (the base).
pub fn pantilt_mesh(p: &PanTilt) -> PanTiltMesh {
    let r = pantilt_axes();
    let centre: Vec<[f64; 3]> = (0..8).map(|i| scale(r[i], PT_A[i])).collect();
    // 4 co-rotational segments per hinge, as the stage uses for its nonlinear runs.
    let mut b = Builder {
        segments: Some(4),
        ..Builder::default()
    };
    let spec = p.hinge_spec();
    let mut ends = [[0usize; 2]; 8];
    let mut ex = [[0.0; 3]; 8];
    for &(j, prev, next) in &PT_CHAIN {
        if !p.passive_limb && matches!(j, 2 | 5 | 7) {
            continue;
        }
        let along = match prev {
            None => sub(centre[next], centre[j]),
            Some(q) => sub(centre[j], centre[q]),
        };
        let e = unit(sub(along, scale(r[j], dot(along, r[j]))));
        ex[j] = e;
        let a = b.node(sub(centre[j], scale(e, PT_HINGE_LEN / 2.0)));
        let d = b.node(add(centre[j], scale(e, PT_HINGE_LEN / 2.0)));
        // local z = x × y with y the joint axis: the notch thins along e × r.
        b.hinge(a, d, &spec, "nylon", cross(e, r[j]));
        ends[j] = [a, d];
    }
    // Links between consecutive hinges: (from joint's distal end, to joint's proximal end).
    let mut links = vec![(0usize, 3usize), (3, 6), (1, 4)];
    if p.passive_limb {
        links.extend([(2, 5), (5, 7)]);
    }
    for &(i, j) in &links {
        let (from, to) = (ends[i][1], ends[j][0]);
        match p.links {
            Links::Rigid => {
                b.rigid(from, &[to]);
            }
            Links::Nylon => {
                let x = unit(sub(b.nodes[to], b.nodes[from]));
                // Width (w) along the proximal joint's axis: local z = x × r_i.
                b.beam(from, to, "link", "nylon", unit(cross(x, r[i])));
            }
        }
    }
    let platform = ends[6][1];
    let mut slaves = vec![ends[4][1]];
    if p.passive_limb {
        slaves.push(ends[7][1]);
    }
    b.rigid(platform, &slaves);
    let bases = if p.passive_limb { 3 } else { 2 };
    for end in &ends[..bases] {
        b.clamp(end[0]);
    }
    let mut sections = json!({});
    if p.links == Links::Nylon {
        sections = json!({"link": {"shape": "rect", "w": p.width, "h": p.h}});
    }
    PanTiltMesh {
        mesh: b.mesh(json!({"nylon": "nylon66"}), sections),
        ends,
        platform,
    }
}

/// The load case driving the base joints J1, J2 to θ₁, θ₂ (deg): the distal end of each base
/// hinge gets the rotation θ·r about the joint's fixed axis (all three rotation components
/// prescribed, so the rotation stays about the axis at any size); its translations are free.
pub fn pantilt_drive(m: &PanTiltMesh, theta: [f64; 2]) -> Value {
    let r = pantilt_axes();
    let mut disp = Vec::new();
    for j in 0..2 {
        for (k, dof) in ["rx", "ry", "rz"].iter().enumerate() {
            disp.push(json!({"node": m.ends[j][1], "dof": dof, "value": r9(theta[j] * r[j][k])}));
        }
    }
    json!({"name": "prbm_pitch10_phase45", "displacements": disp})
}

/// `cases/pantilt_8r.json`: the standard pan-tilt driven to the PRBM angles, nonlinear.
pub fn pantilt_case(m: &PanTiltMesh) -> Value {
    json!({
        "analysis": "static",
        "mesh": "../meshes/pantilt_8r.json",
        "nonlinear": true,
        "steps": 4,
        "load_cases": [pantilt_drive(m, PT_THETA)]
    })
}

/// `cases/pantilt_8r_modal.json`: the six lowest modes of the undriven pan-tilt (base hinges
/// clamped at their proximal ends only; masses of the hinges and nylon links, no platform or
/// camera mass — the paper gives none).
pub fn pantilt_modal_case() -> Value {
    json!({"analysis": "modal", "mesh": "../meshes/pantilt_8r.json", "modes": 6, "shapes": false})
}

/// Pitch and phase (deg) of the platform from its rotation vector (deg): the platform normal
/// (top axis r7, z at home) after the rotation, n = R·z; pitch = angle of n from z, phase =
/// azimuth of n.
pub fn pitch_phase(rot_deg: [f64; 3]) -> (f64, f64) {
    let w = scale(rot_deg, std::f64::consts::PI / 180.0);
    let th = dot(w, w).sqrt();
    let z = [0.0, 0.0, 1.0];
    let n = if th < 1e-300 {
        z
    } else {
        let k = scale(w, 1.0 / th);
        // Rodrigues: R z = z cos θ + (k × z) sin θ + k (k·z)(1 − cos θ).
        add(
            add(scale(z, th.cos()), scale(cross(k, z), th.sin())),
            scale(k, dot(k, z) * (1.0 - th.cos())),
        )
    };
    (n[2].acos().to_degrees(), n[1].atan2(n[0]).to_degrees())
}

/// Yu, Lu and Hao's (2016) PRBM inverse kinematics (its Eqs. (1)–(11), restated for the geometry above):
/// the base rotations θ₁, θ₂ (deg) that give the top axis r7 = (sin γ cos φ, sin γ sin φ,
/// cos γ) — the root of r_{j+3}(θj)·r7 = cos 60° nearest zero, r_{j+3}(θ) = (cos(α+θ) cos βj,
/// cos(α+θ) sin βj, sin(α+θ)).
pub fn pantilt_ikp(pitch_deg: f64, phase_deg: f64) -> [f64; 2] {
    let (g, f) = (pitch_deg.to_radians(), phase_deg.to_radians());
    let r7 = [g.sin() * f.cos(), g.sin() * f.sin(), g.cos()];
    let al = PT_ALPHA.to_radians();
    let mut out = [0.0; 2];
    for j in 0..2 {
        let b = PT_BETA[j].to_radians();
        // cos(α+θ)·c + sin(α+θ)·s = 1/2 with c = r7·(cos β, sin β, 0), s = r7z:
        // ρ cos(α + θ − ψ) = 1/2, ψ = atan2(s, c), ρ = √(c² + s²).
        let c = r7[0] * b.cos() + r7[1] * b.sin();
        let s = r7[2];
        let (rho, psi) = ((c * c + s * s).sqrt(), s.atan2(c));
        let d = (0.5 / rho).acos();
        let cands = [psi + d - al, psi - d - al];
        let best = if cands[0].abs() < cands[1].abs() {
            cands[0]
        } else {
            cands[1]
        };
        out[j] = best.to_degrees();
    }
    out
}

// ---------------------------------------------------------------------------------------------
// Lever amplifier
// ---------------------------------------------------------------------------------------------

/// Lever amplifier (assumed dimensions, Al 7075-T6, the parallelogram's circular notch R = 5,
/// t = 1 in a 10 × 10 bar, hinge elements 15 mm long): a rigid lever along x at y = 0 on a
/// fulcrum hinge (vertical, centred at (0, −7.5), foot clamped); the input strut is a vertical
/// hinge element centred at (`LEVER_IN`, −7.5) whose foot (the actuator) is pushed up along y
/// (its other five DOFs held); the output is the lever's end at x = `LEVER_OUT`. Ideal
/// (rigid-linkage) ratio `LEVER_OUT` / `LEVER_IN` = 5.
pub const LEVER_IN: f64 = 10.0;
pub const LEVER_OUT: f64 = 50.0;
/// Actuator (input) node and output node of `lever_case`.
pub const LEVER_ACTUATOR_NODE: usize = 2;
pub const LEVER_OUTPUT_NODE: usize = 4;
/// Input stroke, mm (a piezo stack's 10 µm).
pub const LEVER_STROKE: f64 = 0.01;

pub fn lever_case() -> Value {
    let mut b = Builder::default();
    let spec = parallelogram_hinge();
    let h = PARA_HINGE_LEN;
    let foot = b.node([0.0, -h, 0.0]);
    let top = b.node([0.0, 0.0, 0.0]);
    let act = b.node([LEVER_IN, -h, 0.0]);
    let inp = b.node([LEVER_IN, 0.0, 0.0]);
    let out = b.node([LEVER_OUT, 0.0, 0.0]);
    assert_eq!((act, out), (LEVER_ACTUATOR_NODE, LEVER_OUTPUT_NODE));
    b.hinge(foot, top, &spec, "al", [1.0, 0.0, 0.0]);
    b.hinge(act, inp, &spec, "al", [1.0, 0.0, 0.0]);
    b.rigid(top, &[inp, out]);
    b.clamp(foot);
    b.supports
        .push(json!({"node": act, "fix": ["ux", "uz", "rx", "ry", "rz"]}));
    let mut case = b.mesh(json!({"al": "Al7075"}), json!({}));
    let obj = case.as_object_mut().unwrap();
    obj.shift_remove("sections");
    let mut out_case = serde_json::Map::new();
    out_case.insert("analysis".into(), json!("static"));
    out_case.extend(obj.clone());
    out_case.insert(
        "load_cases".into(),
        json!([{"name": "stroke_10um", "displacements": [{"node": act, "dof": "uy", "value": LEVER_STROKE}]}]),
    );
    Value::Object(out_case)
}

// ---------------------------------------------------------------------------------------------
// Han, Wang and Shi: 3-PRS friction-stir-welding head (Han, Wang and Shi)
// ---------------------------------------------------------------------------------------------

/// Link length, base and platform radii (Han, Wang and Shi, Tables I and III), mm.
pub const PRS_LINK: f64 = 185.0;
pub const PRS_BASE_R: f64 = 470.0;
pub const PRS_PLATFORM_R: f64 = 315.0;
/// Lead screw: 600 mm between its fixed-fixed mounts, A = 183.5 mm², E = 231 GPa, nut at
/// mid-length (a = b = 300 mm, the pose z = −0.4 m the paper calls the poorest):
/// k = A·E·L/(a·b) (Han, Wang and Shi, Eq. (8)), N/mm.
pub fn prs_screw_stiffness() -> f64 {
    183.5 * 231_000.0 * 600.0 / (300.0 * 300.0)
}
/// Platform centre height (the paper's z = −0.4 m), mm.
pub const PRS_Z: f64 = -400.0;
/// Node of the platform centre (the tool point) in `prs_head_case`.
pub const PRS_TOOL_NODE: usize = 0;

/// Han, Wang and Shi's 3-PRS head at tilt β (deg, about the base y axis; the paper's α = 0 read as the
/// tilt axis' azimuth): vertical actuators (sliders) at radius 470 mm, 120° apart; ideal
/// joints — a revolute joint (axis tangential, the slider's mᵢ) between each slider and its
/// link, a spherical joint between each link and the platform (radius 315 mm; three arms
/// from its centre, 5 orders stiffer than the links, stand for the rigid platform);
/// links 185 mm steel Euler–Bernoulli beams of a 60 × 120 mm rectangle (the paper's A = 7200
/// mm², I = 8.64e6 mm⁴ for bending out of the leg plane, 2.16e6 mm⁴ in it; its polar moment
/// 1.296e6 mm⁴ is below the rectangle's torsion constant, which is used — the links carry no
/// torque to first order; E = 210 GPa, G = 82.4 GPa → ν = 0.2743; yield 355 and allowable 235
/// MPa assumed, S355 steel); each slider guided along z
/// (its other five DOFs held by the guide) and held along z by its lead screw as an axial
/// spring `prs_screw_stiffness`. The pose (slider strokes, platform placement) is the 3-PRS
/// inverse kinematics of `flexfem::kinematics` with γ = 90° (vertical actuators). Load: the
/// paper's F = [100, 50, 50] kN in the platform frame, at the platform centre (assumed to be
/// the tool tip; the paper gives no tool length).
pub fn prs_head_case(beta_deg: f64) -> Value {
    prs_head_case_with(beta_deg, 0.0)
}

/// `prs_head_case` with the tool tip `tool` mm below the platform centre along the platform
/// normal (a stiff arm; the load acts at the tip and the tip is node `PRS_TOOL_NODE`).
pub fn prs_head_case_with(beta_deg: f64, tool: f64) -> Value {
    use flexfem::kinematics::prs::Prs;
    let prs = Prs::with_base_radius(PRS_LINK, PRS_PLATFORM_R, PRS_BASE_R, 90f64.to_radians()).unwrap();
    let z0 = prs.p_home()[2];
    let ik = prs.ikp(z0, 0.0, beta_deg.to_radians()).unwrap();
    let (p, rot) = prs.placement(&ik.pose);
    // Shift so the platform centre sits at the paper's z = −400 mm.
    let dz = PRS_Z - p[2];
    let at = |v: [f64; 3]| [v[0], v[1], v[2] + dz];
    let mut b = Builder::default();
    let w = [rot[(0, 2)], rot[(1, 2)], rot[(2, 2)]];
    let tip = b.node(at(sub([p[0], p[1], p[2]], scale(w, tool))));
    assert_eq!(tip, PRS_TOOL_NODE);
    let tool_node = if tool > 0.0 {
        b.node(at([p[0], p[1], p[2]]))
    } else {
        tip
    };
    if tool > 0.0 {
        b.beam(
            tool_node,
            tip,
            "platform_arm",
            "steel",
            [rot[(0, 0)], rot[(1, 0)], rot[(2, 0)]],
        );
    }
    let tool = tool_node;
    let mut platform_points = Vec::new();
    let mut springs = Vec::new();
    for i in 0..3 {
        let c = prs.c_point(i, ik.s[i]);
        let bp = prs.b_point(i, &ik.pose);
        let m = prs.m(i);
        let (c, bp, m) = ([c[0], c[1], c[2]], [bp[0], bp[1], bp[2]], [m[0], m[1], m[2]]);
        // The slider: guided along z at its nut, 50 mm below the revolute joint, joined to
        // the joint node by a stiff arm (a joint node carries the joint frame: it takes no
        // partial support).
        let nut = b.node(at(sub(c, [0.0, 0.0, 50.0])));
        let slider = b.node(at(c));
        b.beam(nut, slider, "platform_arm", "steel", m);
        let link_foot = b.node(at(c));
        let link_head = b.node(at(bp));
        let plat = b.node(at(bp));
        b.elements
            .push(json!({"type": "joint", "nodes": [slider, link_foot], "kind": "revolute", "axis": rounded(m)}));
        // Euler–Bernoulli, as the paper's link compliance (its Eq. (1)).
        let link = b.beam(link_foot, link_head, "link", "steel", m);
        b.elements[link]["shear"] = json!(false);
        b.elements
            .push(json!({"type": "joint", "nodes": [link_head, plat], "kind": "spherical"}));
        b.supports
            .push(json!({"node": nut, "fix": ["ux", "uy", "rx", "ry", "rz"]}));
        springs.push(nut);
        platform_points.push(plat);
    }
    // The platform: stiff arms from its centre to the three spherical joints (a joint cannot
    // tie a rigid-link slave; the arms are 5 orders stiffer than the links).
    for &q in &platform_points {
        let x = unit(sub(b.nodes[q], b.nodes[tool]));
        b.beam(tool, q, "platform_arm", "steel", unit(cross(x, [0.0, 0.0, 1.0])));
    }
    let k = prs_screw_stiffness();
    for s in springs {
        b.elements
            .push(json!({"type": "spring", "nodes": [s], "k": [0, 0, r9(k), 0, 0, 0]}));
    }
    let f_local = [100_000.0, 50_000.0, 50_000.0];
    let f: Vec<f64> = (0..3)
        .map(|r| r9(rot[(r, 0)] * f_local[0] + rot[(r, 1)] * f_local[1] + rot[(r, 2)] * f_local[2]))
        .collect();
    let mesh = b.mesh(
        json!({"steel": {"E": 210000, "nu": 0.2743, "density": 7.85e-9, "yield": 355, "allowable": 235}}),
        json!({
            "link": {"shape": "rect", "w": 60, "h": 120},
            "platform_arm": {"shape": "general", "A": 1e6, "Iy": 1e11, "Iz": 1e11, "J": 1e11}
        }),
    );
    let mut case = serde_json::Map::new();
    case.insert("analysis".into(), json!("static"));
    case.extend(mesh.as_object().unwrap().clone());
    case.insert(
        "load_cases".into(),
        json!([{"name": format!("fsw_beta{beta_deg}"), "forces": [{"node": tip, "F": [f[0], f[1], f[2], 0, 0, 0]}]}]),
    );
    Value::Object(case)
}
