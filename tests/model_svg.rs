//! `model.svg` (issue 33): every `run --out` of a static, modal or stage case draws the model —
//! the undeformed ghost, the deformed shape with its scale stated, hinges as notch symbols
//! coloured by the utilisation the result lists, supports and loads — inside its canvas, and
//! the Markdown report embeds it. The browser check (screenshots in headless Chromium) is
//! `scripts/model_svg_test.sh`, run by `.ci/run`.

mod common;
use common::*;
use std::path::Path;

/// Value of attribute `name` in the tag text `tag`.
fn attr<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let (_, rest) = tag.split_once(&key)?;
    Some(rest.split_once('"')?.0)
}

/// The `<g class="hinge" …>` symbols: (label, utilisation, fill colour).
fn marks(svg: &str) -> Vec<(String, Option<f64>, String)> {
    svg.match_indices("<g class=\"hinge\"")
        .map(|(i, _)| {
            let tag = &svg[i..i + svg[i..].find("</g>").unwrap()];
            let u = attr(tag, "data-utilisation").unwrap();
            (
                attr(tag, "data-label").unwrap().to_string(),
                (u != "none").then(|| u.parse().unwrap()),
                attr(tag, "fill").unwrap().to_string(),
            )
        })
        .collect()
}

/// The colour map of `model.svg` (green 0 → yellow 0.5 → red 1, magenta above 1, grey for none),
/// written out again here from its definition in the README.
fn colour(u: Option<f64>) -> String {
    let c = match u {
        None => [170, 170, 170],
        Some(u) if u > 1.0 => [200, 0, 200],
        Some(u) => [
            (230.0 * (2.0 * u).min(1.0)).round() as u8,
            (200.0 * (2.0 * (1.0 - u)).min(1.0)).round() as u8,
            40,
        ],
    };
    format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2])
}

/// Every coordinate drawn (points, line ends, text anchors) lies inside the canvas.
fn assert_inside(svg: &str, what: &str) {
    let w: f64 = attr(svg, "width").unwrap().parse().unwrap();
    let h: f64 = attr(svg, "height").unwrap().parse().unwrap();
    let mut n = 0;
    for (i, _) in svg.match_indices('<') {
        let tag = &svg[i..i + svg[i..].find('>').unwrap()];
        let mut pts: Vec<(f64, f64)> = Vec::new();
        if let Some(p) = attr(tag, "points") {
            for xy in p.split_whitespace() {
                let (x, y) = xy.split_once(',').unwrap();
                pts.push((x.parse().unwrap(), y.parse().unwrap()));
            }
        }
        for (kx, ky) in [("x1", "y1"), ("x2", "y2"), ("x", "y")] {
            if let (Some(x), Some(y)) = (attr(tag, kx), attr(tag, ky)) {
                pts.push((x.parse().unwrap(), y.parse().unwrap()));
            }
        }
        for (x, y) in pts {
            n += 1;
            assert!(
                (0.0..=w).contains(&x) && (0.0..=h).contains(&y),
                "{what}: ({x}, {y}) outside the {w}×{h} canvas in {tag}"
            );
        }
    }
    assert!(n > 20, "{what}: only {n} coordinates drawn");
}

fn read(dir: &Path, name: &str) -> String {
    std::fs::read_to_string(dir.join(name)).unwrap()
}

#[test]
fn parallelogram_picture_marks_every_hinge_with_its_utilisation() {
    let (out, r) = run_out("cases/parallelogram_guide.json", "model_svg_parallelogram");
    let svg = read(&out, "model.svg");
    assert_inside(&svg, "parallelogram");
    let lc = &r["load_cases"][0];
    let hinges = lc["hinges"].as_array().unwrap();
    let m = marks(&svg);
    assert_eq!(
        m.len(),
        hinges.len(),
        "one notch symbol per hinge of the first load case"
    );
    assert!(m.len() >= 4);
    for h in hinges {
        let label = format!("element {}", h["element"]);
        let u = h["utilisation"].as_f64().unwrap();
        let (_, mu, fill) = m.iter().find(|(l, _, _)| *l == label).expect(&label);
        let mu = mu.unwrap();
        assert!((mu - u).abs() <= 1e-12 * u.abs(), "{label}: {mu} vs result.json {u}");
        assert_eq!(*fill, colour(Some(u)), "{label}");
    }
    // The deformed shape is drawn at a stated, round automatic scale.
    assert_eq!(attr(&svg, "data-load-case"), lc["name"].as_str());
    let scale: f64 = attr(&svg, "data-scale").unwrap().parse().unwrap();
    let mantissa = scale / 10f64.powf(scale.log10().floor());
    assert!(
        [1.0, 2.0, 5.0].iter().any(|m| (mantissa - m).abs() < 1e-9),
        "scale {scale} is not 1, 2 or 5 × 10ⁿ"
    );
    assert!(
        svg.contains(&format!("deformation × {scale} (largest displacement")),
        "scale stated"
    );
    assert!(svg.contains("class=\"ghost\"") && svg.contains("class=\"support\"") && svg.contains("class=\"load\""));
    // The report embeds the picture.
    assert!(read(&out, "report.md").contains("](model.svg)"));
}

#[test]
fn stage_picture_colours_each_leg_hinge_by_stress_over_allowable() {
    let (out, r) = run_out("cases/ruiz2019_stage.json", "model_svg_stage");
    let svg = read(&out, "model.svg");
    assert_inside(&svg, "stage");
    let lc = &r["load_cases"][0];
    let allowable = r["material"]["allowable"].as_f64().unwrap();
    let m = marks(&svg);
    assert_eq!(m.len(), 6, "a revolute and a spherical hinge per leg");
    for kind in ["revolute", "spherical"] {
        for (i, s) in lc["hinge_stress"][kind].as_array().unwrap().iter().enumerate() {
            let u = s.as_f64().unwrap() / allowable;
            let label = format!("leg {} {kind}", i + 1);
            let (_, mu, fill) = m.iter().find(|(l, _, _)| *l == label).expect(&label);
            assert!((mu.unwrap() - u).abs() <= 1e-12 * u, "{label}");
            assert_eq!(*fill, colour(Some(u)), "{label}");
        }
    }
    // The platform and the three sliders are shaded bodies.
    assert!(svg.matches("class=\"body\"").count() >= 4);
    assert!(read(&out, "report.md").contains("](model.svg)"));
}

#[test]
fn shell_plate_and_modal_pictures_are_drawn() {
    let (out, _) = run_out("cases/static_plate_shell.json", "model_svg_plate");
    let svg = read(&out, "model.svg");
    assert_inside(&svg, "plate");
    assert!(svg.matches("class=\"shell\"").count() >= 16);
    let (out, r) = run_out("cases/pantilt_8r_modal.json", "model_svg_modal");
    let svg = read(&out, "model.svg");
    assert_inside(&svg, "pan-tilt mode 1");
    assert_eq!(attr(&svg, "data-load-case"), Some("mode 1"));
    // A mode shape has no stress level: grey symbols, and its size (8 % of the model) is stated.
    let m = marks(&svg);
    assert!(m.len() >= 8, "{} hinge symbols", m.len());
    assert!(m.iter().all(|(_, u, f)| u.is_none() && *f == colour(None)));
    assert!(svg.contains("largest displacement 8.00 % of the model size"), "caption");
    assert!(r["modes"][0]["frequency_hz"].as_f64().unwrap() > 0.0);
}

#[test]
fn picture_options_change_the_view_and_bad_ones_are_refused() {
    let base = std::fs::read_to_string(root().join("cases/parallelogram_guide.json")).unwrap();
    let mut case: serde_json::Value = serde_json::from_str(&base).unwrap();
    case["mesh"] = root().join("meshes/parallelogram_notch.json").to_str().unwrap().into();
    let second = case["load_cases"][1]["name"].as_str().map(String::from);
    case["output"] = serde_json::json!({"picture": {"view": "top", "scale": 10, "numbers": true}});
    if let Some(name) = &second {
        case["output"]["picture"]["load_case"] = name.clone().into();
    }
    let d = tempdir("model_svg_options");
    let p = write(&d, "case.json", &case.to_string());
    let mesh_dir = d.clone();
    let o = run_in(
        &mesh_dir,
        &["run", p.to_str().unwrap(), "--out", d.join("o").to_str().unwrap()],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let svg = read(&d.join("o"), "model.svg");
    assert_eq!(attr(&svg, "data-scale"), Some("10"));
    assert!(svg.contains("class=\"numbers\""));
    if let Some(name) = &second {
        assert_eq!(attr(&svg, "data-load-case"), Some(name.as_str()));
    }
    assert_inside(&svg, "top view");

    for (picture, needles) in [
        (
            serde_json::json!({"view": {"azimuth": 0, "elevation": 100}}),
            &["output.picture.view.elevation", "100"][..],
        ),
        (serde_json::json!({"scale": -1}), &["output.picture.scale", "-1"][..]),
        (
            serde_json::json!({"load_case": "nope"}),
            &["output.picture.load_case", "nope"][..],
        ),
        (serde_json::json!({"view": "diagonal"}), &["output.picture.view"][..]),
    ] {
        case["output"] = serde_json::json!({ "picture": picture });
        let p = write(&d, "bad.json", &case.to_string());
        for cmd in ["run", "check"] {
            exits_2(&run_in(&mesh_dir, &[cmd, p.to_str().unwrap()]), needles);
        }
    }
    cleanup(&d);
}
