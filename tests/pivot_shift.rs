//! Pivot shift: where the end of a flexure turns about along a large-rotation path, from the
//! poses of the nonlinear solution ([`flexfem::kinematics::pivot`]), against the exact
//! constant-curvature leaf under a pure moment (C. Iandiorio, P. Salvini, Elasto-kinematics and
//! instantaneous invariants of compliant mechanisms based on flexure hinges, Micromachines 14
//! (2023) 783): the end's tangent crosses the undeformed axis L·tan(θ/2)/θ from the root, and
//! its instantaneous centre of rotation is at (L(1 − cos θ)/θ², L(θ − sin θ)/θ²).

use flexfem::kinematics::pivot::{axis_crossing, rotated_x, screw_between};
use serde_json::{json, Value};

fn run(case: Value) -> Value {
    let c = flexfem::analysis::parse_value(case, None).expect("valid case");
    flexfem::analysis::run(&c).expect("analysis runs").json
}

fn f(v: &Value) -> f64 {
    v.as_f64().expect("number")
}

/// A spring-steel leaf L = 50 mm, 0.5 × 10 mm, along x from a clamped root at the origin, `n`
/// co-rotational beams, under end moments about z giving end angles of about 2.5°, 5°, …,
/// 32.5°, each solved from the undeformed state. Returns the end's pose per level, level 0
/// undeformed: (position mm, rotation vector rad).
fn leaf_poses(n: usize) -> Vec<([f64; 3], [f64; 3])> {
    let l = 50.0;
    let nodes: Vec<[f64; 3]> = (0..=n).map(|i| [l * i as f64 / n as f64, 0.0, 0.0]).collect();
    let elements: Vec<Value> = (0..n)
        .map(|i| json!({"type": "beam", "nodes": [i, i + 1], "section": "leaf", "material": "steel", "up": [0, 0, 1], "shear": false}))
        .collect();
    // EI about z = E·h·w³/12 with the 0.5 mm thickness across the leaf (y).
    let ei = 210000.0 * 10.0 * 0.5f64.powi(3) / 12.0;
    let load_cases: Vec<Value> = (1..=13)
        .map(|k| {
            let th = (2.5 * k as f64).to_radians();
            json!({"name": format!("m{k}"), "forces": [{"node": n, "F": [0, 0, 0, 0, 0, th * ei / l]}]})
        })
        .collect();
    let case = json!({
        "analysis": "static",
        "materials": {"steel": {"E": 210000.0, "nu": 0.3, "density": 7.85e-9, "yield": 1600.0, "allowable": 1200.0}},
        "sections": {"leaf": {"shape": "rect", "w": 0.5, "h": 10.0}},
        "nodes": nodes,
        "elements": elements,
        "supports": [{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}],
        "load_cases": load_cases,
        "nonlinear": true,
        "steps": 10
    });
    let r = run(case);
    let mut poses = vec![([l, 0.0, 0.0], [0.0; 3])];
    for lc in r["load_cases"].as_array().unwrap() {
        let d = &lc["displacements"][n];
        poses.push((
            [l + f(&d[0]), f(&d[1]), f(&d[2])],
            [f(&d[3]).to_radians(), f(&d[4]).to_radians(), f(&d[5]).to_radians()],
        ));
    }
    poses
}

/// Tolerances against the constant-curvature closed forms up to 32.5° (20 beams): the tangent
/// crossing L·tan(θ/2)/θ, relative (measured ≤ 3.4e-5), and the instantaneous centre between
/// consecutive levels (2.5° apart) at the mid angle, distance over L (measured ≤ 1.2e-4: the
/// chord's O(Δθ²)).
const CROSSING_TOL: f64 = 1e-4;
const CENTRE_TOL: f64 = 5e-4;

#[test]
fn leaf_pivot_under_pure_moment_matches_constant_curvature() {
    let l = 50.0;
    let poses = leaf_poses(20);
    assert_eq!(poses.len(), 14);
    let (mut worst_x, mut worst_c) = (0.0f64, 0.0f64);
    for k in 1..poses.len() {
        let (p, r) = poses[k];
        let th = r[2];
        let x = axis_crossing([0.0; 3], [1.0, 0.0, 0.0], p, rotated_x(r)).unwrap();
        let exact = l * (0.5 * th).tan() / th;
        worst_x = worst_x.max(((x - exact) / exact).abs());
        let (p0, r0) = poses[k - 1];
        let s = screw_between(p0, r0, p, r, [0.0; 3]).unwrap();
        let tm = 0.5 * (r0[2] + th);
        let (cx, cy) = (l * (1.0 - tm.cos()) / (tm * tm), l * (tm - tm.sin()) / (tm * tm));
        let e = ((s.point[0] - cx).powi(2) + (s.point[1] - cy).powi(2)).sqrt() / l;
        worst_c = worst_c.max(e);
        eprintln!(
            "θ = {:.2}°: crossing {x:.5} vs {exact:.5}; centre ({:.4}, {:.4}) vs ({cx:.4}, {cy:.4}) at {:.2}°",
            th.to_degrees(),
            s.point[0],
            s.point[1],
            tm.to_degrees()
        );
    }
    eprintln!("worst: crossing {:.3e}, centre {:.3e} of L", worst_x, worst_c);
    assert!(poses[13].1[2].to_degrees() > 30.0);
    assert!(worst_x < CROSSING_TOL, "tangent crossing off by {worst_x}");
    assert!(worst_c < CENTRE_TOL, "instantaneous centre off by {worst_c} L");
}

/// The circular notch of `cases/ruiz2019_hinge_revolute.json` (R = 8, t = 2 mm, Al 7075) with
/// `"nonlinear": true`: `pivot_shift` has one point per level of the large-rotation curve, at
/// its rotations, and the instantaneous centre of the end face sits 1.057–1.059 mm from the notch
/// centre towards the clamped side (the end force's moment grows towards the root) and rises
/// across the axis with the rotation (0.003 mm at 0.15°, 0.066 mm at 1.86°). A pin on the model
/// (regression; the notch under an end force has no closed form here): along within
/// [−1.07, −1.045] mm, across within [0, 0.04 mm per degree].
#[test]
fn circular_notch_pivot_shift_along_the_large_rotation_curve() {
    let r = run(json!({
        "analysis": "hinge",
        "material": "Al7075",
        "hinge": {"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20},
        "nonlinear": true
    }));
    let curve = r["large_rotation"]["points"].as_array().unwrap();
    let pivot = r["pivot_shift"]["points"].as_array().unwrap();
    assert_eq!(curve.len(), pivot.len());
    for (c, p) in curve.iter().zip(pivot) {
        let (along, across) = (f(&p["centre"][0]), f(&p["centre"][1]));
        eprintln!(
            "θ = {:.3}° (curve {:.3}°): centre ({along:.4}, {across:.4}) mm, axis crossing {}",
            f(&p["rotation_deg"]),
            f(&c["rotation_deg"]),
            p["axis_crossing"]
        );
        assert!((f(&p["rotation_deg"]) - f(&c["rotation_deg"])).abs() < 1e-9 * f(&c["rotation_deg"]));
        let th = f(&p["rotation_deg"]);
        assert!((-1.07..-1.045).contains(&along), "centre along {along}");
        assert!(across > 0.0 && across < 0.04 * th, "centre across {across} at {th}°");
    }
    eprintln!("drift {}", r["pivot_shift"]["drift"]);
    assert!(f(&r["pivot_shift"]["drift"]) > 0.0);
}

/// The bundled parallelogram guide (`meshes/parallelogram_notch.json`: four circular notches
/// R 5, t 1 mm, 8 co-rotational segments each; legs and platform `rigid` elements) under a
/// prescribed platform stroke `stroke` (mm, along x), nonlinear in `steps` steps.
fn parallelogram(stroke: f64, steps: usize) -> Value {
    let mesh: Value = serde_json::from_str(
        &std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/meshes/parallelogram_notch.json")).unwrap(),
    )
    .unwrap();
    let mut case = mesh.clone();
    case["analysis"] = json!("static");
    case["nonlinear"] = json!(true);
    case["steps"] = json!(steps);
    case["load_cases"] = json!([{"name": "stroke", "displacements": [{"node": 8, "dof": "ux", "value": stroke}]}]);
    run(case)
}

/// The pose (position mm, rotation vector rad) of node `n` at the end of load case 0.
fn pose(r: &Value, n: usize, x0: [f64; 3]) -> ([f64; 3], [f64; 3]) {
    let d = &r["load_cases"][0]["displacements"][n];
    let v: Vec<f64> = (0..6).map(|i| f(&d[i])).collect();
    (
        [x0[0] + v[0], x0[1] + v[1], x0[2] + v[2]],
        [v[3].to_radians(), v[4].to_radians(), v[5].to_radians()],
    )
}

/// The reported centre of rotation of the left leg (the rigid body of master node 1, from the
/// lower notch at y ∈ [−7.5, 7.5] to the upper one) over the last step of a 2 mm stroke, against
/// finite differences of the FE path: the screw between the leg's poses of two separate runs at
/// strokes s_m ± 1e-3 mm (s_m the middle of the step). The chord of a step is the instantaneous
/// centre at the step's middle to O(Δλ²): with 10 steps the difference is 1.83e-7 mm and with 20
/// steps 4.43e-8 (ratio 4.14; 4 asymptotically), so the test asserts both the size (< 1e-7 mm
/// at 20 steps) and the order (2.5–5.5). At 40 steps the difference (1.4e-8 … 4.5e-8 mm for
/// ε = 5e-4 … 2e-3 mm, not monotonic) is at the floor that the differences' own O(ε²) and the
/// Newton tolerance set, so 40 steps no longer tells the order.
#[test]
fn parallelogram_leg_centre_of_rotation_matches_finite_differences_of_the_path() {
    let x0 = [0.0, 7.5, 0.0];
    let mut errors = Vec::new();
    for steps in [10, 20] {
        let r = parallelogram(2.0, steps);
        let rows = r["load_cases"][0]["centre_of_rotation"]
            .as_array()
            .expect("centre_of_rotation");
        assert_eq!(rows.len(), 3, "two legs and the platform");
        let leg = rows.iter().find(|b| b["body"] == 1).expect("the left leg");
        let pts = leg["points"].as_array().unwrap();
        assert!(pts.len() >= steps, "{} points", pts.len());
        let (last, prev) = (&pts[pts.len() - 1], &pts[pts.len() - 2]);
        let mid = 0.5 * (f(&last["load_factor"]) + f(&prev["load_factor"]));
        let c: Vec<f64> = (0..3).map(|i| f(&last["centre"][i])).collect();
        let eps = 1e-3;
        let (a, b) = (
            parallelogram(2.0 * mid - eps, steps),
            parallelogram(2.0 * mid + eps, steps),
        );
        let ((pa, ra), (pb, rb)) = (pose(&a, 1, x0), pose(&b, 1, x0));
        let fd = screw_between(pa, ra, pb, rb, x0).expect("the leg turns");
        let err = ((c[0] - fd.point[0]).powi(2) + (c[1] - fd.point[1]).powi(2) + (c[2] - fd.point[2]).powi(2)).sqrt();
        eprintln!(
            "{steps} steps: reported {c:?}, finite differences {:?}, |Δ| = {err:.3e} mm",
            fd.point
        );
        // The leg turns about its lower notch (centre at the origin): within the notch's half length.
        assert!(c[0].hypot(c[1]) < 5.0, "centre {c:?}");
        errors.push(err);
    }
    assert!(errors[1] < 1e-7, "20 steps: {:.3e} mm", errors[1]);
    let order = errors[0] / errors[1];
    assert!(
        (2.5..5.5).contains(&order),
        "chord error ratio 10 → 20 steps {order} (O(Δλ²): 4)"
    );
}

/// The platform of the parallelogram nearly translates: it tilts by less than 5e-3° over the
/// 2 mm stroke (measured 1.0e-3° at 1.6 mm), so its instantaneous centre lies more
/// than 10 m away (measured 88 m) — a screw axis far off, not the legs' pivots.
#[test]
fn parallelogram_platform_nearly_translates_so_its_centre_is_far_away() {
    let r = parallelogram(2.0, 20);
    let rows = r["load_cases"][0]["centre_of_rotation"].as_array().unwrap();
    let platform = rows.iter().find(|b| b["body"] == 8).expect("the platform");
    let pts = platform["points"].as_array().unwrap();
    assert_eq!(pts.len(), 20);
    // Planar motion: the axes are parallel, so no common point is reported.
    assert!(platform.get("fixed_point").is_none(), "{platform}");
    for p in pts {
        assert!(f(&p["rotation_deg"]) < 5e-3, "{p}");
        if !p["centre"].is_null() {
            let d = f(&p["centre"][0]).hypot(f(&p["centre"][1]) - 107.5);
            assert!(d > 1e4, "{p}");
        }
    }
}

/// One circular notch (R 5, t 1, w = h = 10 mm, Al, 8 segments) from a clamp at y = −7.5 to
/// y = 7.5 mm, carrying a rigid arm to y = 50 mm pushed along x by `force` (N) at its tip.
fn notch_arm(force: f64, steps: usize) -> Value {
    run(json!({
        "analysis": "static",
        "nonlinear": true,
        "steps": steps,
        "materials": {"al": "Al7075"},
        "nodes": [[0, -7.5, 0], [0, 7.5, 0], [0, 50, 0]],
        "elements": [
            {"type": "hinge", "nodes": [0, 1], "hinge": {"type": "circular_notch", "R": 5.0, "t": 1.0, "w": 10.0, "h": 10.0},
             "material": "al", "up": [1, 0, 0], "segments": 8},
            {"type": "rigid", "master": 1, "slaves": [2]}
        ],
        "supports": [{"node": 0, "fix": ["ux", "uy", "uz", "rx", "ry", "rz"]}],
        "load_cases": [{"name": "push", "forces": [{"node": 2, "F": [force, 0, 0, 0, 0, 0]}]}]
    }))
}

/// The circular notch's arm: its reported centre of rotation over the last step (at 7.2°;
/// measured 8.9e-6 mm at 10 steps, 2.2e-6 at 20, ratio 4.0; the centre drifts 0.095 mm along
/// the path)
/// against finite differences of the FE path (separate runs at the step's middle force ± 1e-3
/// of it), the same O(Δλ²) chord argument as the parallelogram's leg; and the centre lies on
/// the notch's loaded side of its centre, within its half length R.
#[test]
fn circular_notch_centre_of_rotation_matches_finite_differences_of_the_path() {
    let x0 = [0.0, 7.5, 0.0];
    let force = 60.0;
    let mut errors = Vec::new();
    for steps in [10, 20] {
        let r = notch_arm(force, steps);
        let rows = r["load_cases"][0]["centre_of_rotation"]
            .as_array()
            .expect("centre_of_rotation");
        assert_eq!(rows.len(), 1);
        let pts = rows[0]["points"].as_array().unwrap();
        let (last, prev) = (&pts[pts.len() - 1], &pts[pts.len() - 2]);
        let mid = 0.5 * (f(&last["load_factor"]) + f(&prev["load_factor"]));
        let c: Vec<f64> = (0..3).map(|i| f(&last["centre"][i])).collect();
        let eps = 1e-3;
        let (a, b) = (
            notch_arm(force * (mid - eps), steps),
            notch_arm(force * (mid + eps), steps),
        );
        let ((pa, ra), (pb, rb)) = (pose(&a, 1, x0), pose(&b, 1, x0));
        let fd = screw_between(pa, ra, pb, rb, x0).expect("the arm turns");
        let err = ((c[0] - fd.point[0]).powi(2) + (c[1] - fd.point[1]).powi(2) + (c[2] - fd.point[2]).powi(2)).sqrt();
        eprintln!(
            "{steps} steps: rotation {:.3}°, reported {c:?}, finite differences {:?}, |Δ| = {err:.3e} mm, drift {}",
            f(&last["rotation_deg"]),
            fd.point,
            rows[0]["drift"]
        );
        assert!(c[0].hypot(c[1]) < 5.0, "centre {c:?}");
        errors.push(err);
    }
    assert!(errors[1] < 5e-6, "20 steps: {:.3e} mm", errors[1]);
    let order = errors[0] / errors[1];
    assert!(
        (2.5..5.5).contains(&order),
        "chord error ratio 10 → 20 steps {order} (O(Δλ²): 4)"
    );
}

/// A motion about a fixed point: screw axes in six directions spread over 40°, each through
/// the point c = (3, −7, 120) mm, given by points shifted along themselves. Their least-squares
/// common point is c exactly and the scatter zero; parallel axes (planar motion) and a single
/// axis have none. (Closed form: every line passes through c.)
#[test]
fn fixed_point_of_axes_through_one_point_is_that_point() {
    use flexfem::analysis::fem_static::pivot::fixed_point;
    let c = [3.0, -7.0, 120.0];
    let lines: Vec<([f64; 3], [f64; 3])> = (0..6)
        .map(|k| {
            let (a, b) = ((k as f64 * 8.0).to_radians(), (k as f64 * 47.0).to_radians());
            let n = [a.sin() * b.cos(), a.sin() * b.sin(), a.cos()];
            let s = 10.0 * k as f64 - 25.0;
            ([c[0] + s * n[0], c[1] + s * n[1], c[2] + s * n[2]], n)
        })
        .collect();
    assert_eq!(lines.len(), 6);
    let fp = fixed_point(&lines).expect("the axes spread by 40°");
    // zip-checked: both are [f64; 3].
    for (p, q) in fp.point.iter().zip(&c) {
        assert!((p - q).abs() < 1e-9, "{:?}", fp.point);
    }
    assert!(fp.scatter < 1e-9, "{}", fp.scatter);
    let parallel: Vec<([f64; 3], [f64; 3])> = (0..4).map(|k| ([k as f64, 0.0, 0.0], [0.0, 0.0, 1.0])).collect();
    assert!(fixed_point(&parallel).is_none());
    assert!(fixed_point(&lines[..1]).is_none());
}

/// The bundled 8R pan-tilt (`cases/pantilt_8r.json`: nonlinear, the platform pitched 10° at
/// 45° phase in 4 steps). Its pseudo-rigid-body model (`flexfem::kinematics::pantilt`) has all
/// joint axes meeting at the origin, the spherical centre, about which the platform turns. The
/// compliant platform's screw axis along the path stays within 2 mm of that centre (measured
/// 1.71, 1.60, 1.51, 1.44 mm over the four steps, 1.82 … 1.57 before the corner hinges' fillets
/// got the short-notch factor: the hinges bend and stretch, 40–60 mm from the
/// centre), and turns by about 1° over the path, too little to place a common point along it:
/// `fixed_point` is left out (see `AXIS_SPREAD_BELOW`).
#[test]
fn pantilt_platform_turns_about_the_spherical_centre() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("cases/pantilt_8r.json");
    let c = flexfem::analysis::load(&path).expect("bundled case");
    let r = flexfem::analysis::run(&c).expect("runs").json;
    let rows = r["load_cases"][0]["centre_of_rotation"].as_array().unwrap();
    assert_eq!(rows.len(), 1);
    assert!(rows[0].get("fixed_point").is_none(), "{}", rows[0]);
    let points = rows[0]["points"].as_array().unwrap();
    assert_eq!(points.len(), 4);
    let distances: Vec<f64> = points
        .iter()
        .map(|p| {
            let c: Vec<f64> = p["centre"].as_array().unwrap().iter().map(f).collect();
            let n: Vec<f64> = p["axis"].as_array().unwrap().iter().map(f).collect();
            // Distance of the origin from the line through c along n.
            let along = -(c[0] * n[0] + c[1] * n[1] + c[2] * n[2]);
            let d = [-c[0] - along * n[0], -c[1] - along * n[1], -c[2] - along * n[2]];
            (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
        })
        .collect();
    eprintln!("pan-tilt: the platform's screw axes pass {distances:?} mm from the spherical centre");
    for d in &distances {
        assert!((1.4..2.0).contains(d), "{distances:?}");
    }
}
