//! Plots a person reads at a glance (issue 33): every SVG plot written by a bundled case has
//! round ticks (consecutive ticks one 1, 2 or 5 × 10ᵏ step apart — the "nice numbers" of
//! Heckbert, Graphics Gems, 1990 — or powers of ten on a log axis), a log axis wherever the
//! data spans more than two decades, a unit on every axis label, markers on sparse series and
//! a legend that covers no data.

mod common;
use common::*;
use std::path::{Path, PathBuf};

/// Value of attribute `name` in the tag text `tag`.
fn attr<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let (_, rest) = tag.split_once(&key)?;
    Some(rest.split_once('"')?.0)
}

fn num(tag: &str, name: &str) -> f64 {
    attr(tag, name).and_then(|v| v.parse().ok()).unwrap_or(f64::NAN)
}

/// The elements `<NAME …>` of `svg` with their tag text and the text up to the next `<`.
fn elements<'a>(svg: &'a str, name: &str) -> Vec<(&'a str, &'a str)> {
    let open = format!("<{name} ");
    svg.match_indices(&open)
        .map(|(i, _)| {
            let rest = &svg[i..];
            let end = rest.find('>').unwrap();
            let body = &rest[end + 1..];
            (&rest[..end], &body[..body.find('<').unwrap_or(body.len())])
        })
        .collect()
}

/// A tick label's value: a plain number, or `10` with a superscript exponent.
fn parse_label(s: &str) -> f64 {
    if let Ok(v) = s.parse() {
        return v;
    }
    let exp: String = s
        .strip_prefix("10")
        .unwrap_or("")
        .chars()
        .map(|c| match c {
            '⁻' => '-',
            c => "⁰¹²³⁴⁵⁶⁷⁸⁹"
                .chars()
                .position(|d| d == c)
                .map_or('x', |d| char::from(b'0' + d as u8)),
        })
        .collect();
    exp.parse::<i32>().map_or(f64::NAN, |k| 10f64.powi(k))
}

/// Is `step` 1, 2 or 5 × 10ᵏ?
fn is_125(step: f64) -> bool {
    let k = step.log10().floor();
    let m = step / 10f64.powf(k);
    [1.0, 2.0, 5.0, 10.0].iter().any(|&n| (m - n).abs() < 1e-6)
}

/// The ticks of one axis (`"x"` or `"y"`) of a panel: (screen position, value), and whether log.
fn check_axis(panel: &str, axis: &str, what: &str) -> (Vec<(f64, f64)>, bool) {
    let ticks: Vec<(&str, &str)> = elements(panel, "text")
        .into_iter()
        .filter(|(t, _)| attr(t, "class") == Some(&format!("tick-{axis}")))
        .collect();
    assert!(ticks.len() >= 2, "{what}: {} {axis} ticks", ticks.len());
    let line = elements(panel, "line")
        .into_iter()
        .find(|(t, _)| attr(t, "class") == Some(&format!("axis-{axis}")))
        .unwrap_or_else(|| panic!("{what}: no {axis} axis line"));
    let log = attr(line.0, "data-scale") == Some("log");
    let label = elements(panel, "text")
        .into_iter()
        .find(|(t, _)| attr(t, "class") == Some(&format!("label-{axis}")))
        .unwrap_or_else(|| panic!("{what}: no {axis} label"))
        .1
        .trim()
        .to_string();
    // A unit in brackets or parentheses at the end of the label ("(–)" when dimensionless).
    assert!(
        (label.ends_with(')') && label.contains('(')) || (label.ends_with(']') && label.contains('[')),
        "{what}: {axis} label {label:?} has no unit"
    );
    let mut out = Vec::new();
    for (tag, text) in &ticks {
        let v = num(tag, "data-value");
        let shown = parse_label(text.trim());
        let pos = if axis == "x" {
            num(tag, "x")
        } else {
            num(tag, "y") - 4.0
        };
        out.push((pos, v));
        if log {
            assert!(
                (v.log10() - v.log10().round()).abs() < 1e-9,
                "{what}: {axis} tick {v} not a power of ten"
            );
            assert!(
                (shown / v - 1.0).abs() < 1e-9,
                "{what}: {axis} tick label {text:?} ≠ {v}"
            );
        }
    }
    let steps: Vec<f64> = out.windows(2).map(|w| w[1].1 - w[0].1).collect();
    assert_eq!(steps.len(), ticks.len() - 1);
    if !log {
        let step = steps[0];
        let phase = label.starts_with("phase") && label.ends_with("(°)");
        assert!(
            is_125(step) || (phase && [90.0, 180.0, 360.0].contains(&step)),
            "{what}: {axis} step {step} is not 1, 2 or 5 × 10^k"
        );
        for (s, (tag, text)) in steps.iter().zip(&ticks) {
            assert!(
                (s / step - 1.0).abs() < 1e-9,
                "{what}: {axis} ticks unevenly spaced: {steps:?}"
            );
            let v = num(tag, "data-value");
            assert!(
                ((v / step) - (v / step).round()).abs() < 1e-6,
                "{what}: {axis} tick {v} off the step {step}"
            );
            assert!(
                (parse_label(text.trim()) - v).abs() < 1e-6 * step,
                "{what}: {axis} label {text:?} ≠ {v}"
            );
        }
    } else {
        assert!(steps.iter().all(|&s| s > 0.0), "{what}: {axis} log ticks not ascending");
    }
    (out, log)
}

/// Data value at screen position `p` on an axis with `ticks` (screen, value).
fn value_at(ticks: &[(f64, f64)], log: bool, p: f64) -> f64 {
    let f = |v: f64| if log { v.log10() } else { v };
    let ((p0, v0), (p1, v1)) = (ticks[0], ticks[ticks.len() - 1]);
    let u = f(v0) + (p - p0) / (p1 - p0) * (f(v1) - f(v0));
    if log {
        10f64.powf(u)
    } else {
        u
    }
}

/// The drawn polylines (screen points per series) and markers (centre, radius).
type Drawn = (Vec<Vec<(f64, f64)>>, Vec<(f64, f64, f64)>);

/// The series polylines and the markers of a panel.
fn drawn(panel: &str) -> Drawn {
    let lines = elements(panel, "polyline")
        .into_iter()
        .filter(|(t, _)| attr(t, "class") == Some("series"))
        .map(|(t, _)| {
            attr(t, "points")
                .unwrap_or("")
                .split_whitespace()
                .map(|p| {
                    let (x, y) = p.split_once(',').unwrap();
                    (x.parse().unwrap(), y.parse().unwrap())
                })
                .collect()
        })
        .collect();
    let marks = elements(panel, "circle")
        .into_iter()
        .filter(|(t, _)| attr(t, "class") == Some("marker"))
        .map(|(t, _)| (num(t, "cx"), num(t, "cy"), num(t, "r")))
        .collect();
    (lines, marks)
}

fn check_panel(panel: &str, what: &str) -> bool {
    let (xt, xlog) = check_axis(panel, "x", what);
    let (yt, ylog) = check_axis(panel, "y", what);
    let (lines, marks) = drawn(panel);
    assert!(!lines.is_empty() || !marks.is_empty(), "{what}: nothing drawn");
    // Markers on sparse series: every vertex of a polyline of at most 12 points has one.
    for l in lines.iter().filter(|l| l.len() <= 12) {
        for &(x, y) in l {
            assert!(
                marks.iter().any(|m| (m.0 - x).abs() < 0.05 && (m.1 - y).abs() < 0.05),
                "{what}: sparse series ({} points) without a marker at ({x}, {y})",
                l.len()
            );
        }
    }
    // Log axes where the data spans more than two decades (one pixel resolves zero).
    let vertices: Vec<(f64, f64)> = lines
        .iter()
        .flatten()
        .copied()
        .chain(marks.iter().map(|m| (m.0, m.1)))
        .collect();
    for (ticks, log, screen, axis) in [(&xt, xlog, 0, "x"), (&yt, ylog, 1, "y")] {
        let vals: Vec<f64> = vertices
            .iter()
            .map(|p| value_at(ticks, log, if screen == 0 { p.0 } else { p.1 }))
            .collect();
        let px = (value_at(ticks, false, ticks[0].0 + 1.0) - ticks[0].1).abs();
        let (lo, hi) = vals
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
        if !log {
            assert!(
                !(lo > px && hi / lo > 100.0),
                "{what}: {axis} data {lo}..{hi} spans more than two decades on a linear axis"
            );
        }
    }
    // The legend covers no point of any line and no marker.
    if let Some((t, _)) = elements(panel, "rect")
        .into_iter()
        .find(|(t, _)| attr(t, "class") == Some("legend-box"))
    {
        let (x, y, w, h) = (num(t, "x"), num(t, "y"), num(t, "width"), num(t, "height"));
        let inside = |px: f64, py: f64, r: f64| px > x - r && px < x + w + r && py > y - r && py < y + h + r;
        for l in &lines {
            for s in l.windows(2) {
                let n = (s[1].0 - s[0].0).hypot(s[1].1 - s[0].1).ceil().max(1.0) as usize;
                for k in 0..=n {
                    let a = k as f64 / n as f64;
                    let (px, py) = (s[0].0 + a * (s[1].0 - s[0].0), s[0].1 + a * (s[1].1 - s[0].1));
                    assert!(
                        !inside(px, py, 0.0),
                        "{what}: legend box covers the line at ({px:.1}, {py:.1})"
                    );
                }
            }
            for &(px, py) in l {
                assert!(
                    !inside(px, py, 0.0),
                    "{what}: legend box covers the point ({px:.1}, {py:.1})"
                );
            }
        }
        for m in &marks {
            assert!(
                !inside(m.0, m.1, m.2),
                "{what}: legend box covers the marker at ({}, {})",
                m.0,
                m.1
            );
        }
    }
    xlog || ylog
}

fn svgs(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap().flatten() {
        let p = e.path();
        if p.is_dir() {
            svgs(&p, out);
        } else if p.extension().is_some_and(|x| x == "svg") && !p.ends_with("model.svg") {
            // model.svg is the picture of the mechanism (tests/model_svg.rs), not a plot.
            out.push(p);
        }
    }
}

#[test]
fn every_bundled_plot_has_round_ticks_units_and_a_clear_legend() {
    let d = tempdir("plot_axes");
    let mut cases: Vec<PathBuf> = std::fs::read_dir(root().join("cases"))
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    cases.sort();
    let mut files = Vec::new();
    for c in &cases {
        let name = c.file_stem().unwrap().to_str().unwrap();
        let dir = d.join(name);
        std::fs::create_dir_all(&dir).unwrap();
        if name.ends_with("_sweep") {
            run_ok_in(&dir, &["sweep", c.to_str().unwrap(), "--out", "s.jsonl"]);
        } else {
            run_ok_in(&dir, &["run", c.to_str().unwrap(), "--out", "o"]);
        }
        svgs(&dir, &mut files);
    }
    // Bundled cases with plots: track, hinge damping, pan-tilt, transients, PRS stiffness maps,
    // FEM vs FKP, FRF, arc length and the stage sweep.
    assert!(files.len() >= 45, "{} SVG plots", files.len());
    let (mut panels, mut logs) = (0, 0);
    for f in &files {
        let svg = std::fs::read_to_string(f).unwrap();
        let what = f.strip_prefix(&d).unwrap().display().to_string();
        // Stacked plots hold one nested <svg> per panel.
        let parts: Vec<&str> = svg.split("<svg ").filter(|p| p.contains("class=\"tick-x\"")).collect();
        assert!(!parts.is_empty(), "{what}: no axes");
        for p in parts {
            panels += 1;
            logs += usize::from(check_panel(p, &what));
        }
    }
    // The Bode magnitude is on log axes (frequency and |H| span decades); its phase in 90° steps.
    let bode = std::fs::read_to_string(d.join("ruiz2019_stage_frf/o/bode_magnitude.svg")).unwrap();
    assert!(
        bode.contains("class=\"axis-x\" data-scale=\"log\"") && bode.contains("class=\"axis-y\" data-scale=\"log\"")
    );
    let phase = std::fs::read_to_string(d.join("ruiz2019_stage_frf/o/bode_phase.svg")).unwrap();
    assert!(
        phase.contains("class=\"tick-y\" data-value=\"9e1\""),
        "phase ticks not at multiples of 90°"
    );
    assert!(
        panels >= files.len() && logs >= 2,
        "{panels} panels, {logs} with a log axis"
    );
    cleanup(&d);
}

/// A panel in the writer's markup with the given y tick values/labels, a polyline and a
/// legend box at (`lx`, `ly`).
fn synthetic(yticks: &[(f64, &str)], ylabel: &str, lx: f64, ly: f64) -> String {
    let mut s = String::from("xmlns=\"http://www.w3.org/2000/svg\">\n");
    s += "<line class=\"axis-x\" data-scale=\"linear\" x1=\"75\" y1=\"365\" x2=\"620\" y2=\"365\"/>\n";
    s += "<line class=\"axis-y\" data-scale=\"linear\" x1=\"75\" y1=\"40\" x2=\"75\" y2=\"365\"/>\n";
    for (i, v) in [0.0, 0.5, 1.0].iter().enumerate() {
        s += &format!(
            "<text class=\"tick-x\" data-value=\"{v}\" x=\"{}\" y=\"383\">{v}</text>\n",
            75.0 + 272.5 * i as f64
        );
    }
    let n = yticks.len() as f64 - 1.0;
    for (i, (v, l)) in yticks.iter().enumerate() {
        s += &format!(
            "<text class=\"tick-y\" data-value=\"{v}\" x=\"69\" y=\"{}\">{l}</text>\n",
            369.0 - 325.0 * i as f64 / n
        );
    }
    s += "<text class=\"label-x\" x=\"347\" y=\"405\">time (s)</text>\n";
    s += &format!("<text class=\"label-y\" x=\"16\" y=\"200\">{ylabel}</text>\n");
    s += "<polyline class=\"series\" points=\"75,365 347.5,200 620,40\"/>\n";
    for (x, y) in [(75.0, 365.0), (347.5, 200.0), (620.0, 40.0)] {
        s += &format!("<circle class=\"marker\" cx=\"{x}\" cy=\"{y}\" r=\"4\"/>\n");
    }
    s += &format!("<rect class=\"legend-box\" x=\"{lx}\" y=\"{ly}\" width=\"100\" height=\"24\"/>\n");
    s
}

// The checks above refuse what issue 33 shows: unrounded ticks (−0.135, 0.459, 1.05), a label
// without a unit and a legend over the data; they pass the same panel drawn right.
#[test]
fn the_plot_checks_refuse_the_plots_of_the_issue() {
    let round = [(0.0, "0"), (0.5, "0.5"), (1.0, "1.0")];
    assert!(!check_panel(&synthetic(&round, "uz (mm)", 80.0, 45.0), "round"));
    let fails = |svg: String| std::panic::catch_unwind(|| check_panel(&svg, "bad")).is_err();
    assert!(fails(synthetic(
        &[(-0.135, "-0.135"), (0.459, "0.459"), (1.05, "1.05")],
        "uz (mm)",
        80.0,
        45.0
    )));
    assert!(fails(synthetic(&round, "uz", 80.0, 45.0)));
    // Legend box over the middle of the line.
    assert!(fails(synthetic(&round, "uz (mm)", 300.0, 190.0)));
}
