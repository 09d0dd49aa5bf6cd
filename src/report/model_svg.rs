//! The picture of a mechanism (`model.svg`): the undeformed model as a light ghost and the
//! deformed shape on top, in a parallel projection (isometric by default). Formatting only — it
//! takes points, drawn items and marks and knows nothing about the physics.
//!
//! Every element a script may want to read back carries a class: `ghost`, `beam`, `hinge-line`,
//! `spring`, `shell`, `rigid`, `body`, `support`, `load`, `prescribed`, `hinge` (a notch symbol:
//! a `<g>` with `data-label`, `data-utilisation` and `data-sample`, the point in pixels where its
//! fill colour can be read), `legend`, `caption`. The root carries `data-scale` (the
//! deformation scale) and `data-load-case`.
//!
//! Utilisation colours ([`utilisation_colour`]): green (0) → yellow (0.5) → red (1), magenta
//! above 1; grey where a hinge has no utilisation (no allowable stress).

pub use super::projection::View;
use super::projection::{hull, Projector};
use std::fmt::Write as _;

/// What an item draws.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    /// A beam: a line of the given section width, mm (drawn to scale, within 1.2–10 px).
    Beam { width: f64 },
    /// A flexure-hinge element drawn as a plain line (its notch symbol is a [`Mark`]).
    HingeLine,
    /// A two-node spring.
    Spring,
    /// A shell facet, filled with a utilisation colour where one is given.
    Shell { utilisation: Option<f64> },
    /// A rigid body: the shaded hull of its points.
    Rigid,
    /// A drawn rigid body that is no element (a stage slider, a platform face).
    Body,
}

/// One drawn item over point indices.
#[derive(Debug, Clone, PartialEq)]
pub struct Item {
    /// What it draws.
    pub shape: Shape,
    /// Its points (indices into [`Picture::points`]).
    pub points: Vec<usize>,
}

/// A flexure hinge's notch symbol, at the middle of its two points, coloured by utilisation.
#[derive(Debug, Clone, PartialEq)]
pub struct Mark {
    /// What the result calls the hinge (e.g. `element 3`, `leg 1 revolute`).
    pub label: String,
    /// Its end points (indices into [`Picture::points`]).
    pub points: [usize; 2],
    /// Peak stress over allowable (−); `None` when the material has no allowable.
    pub utilisation: Option<f64>,
}

/// An arrow at a point: a force (pointing at the point) or a prescribed motion (from it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Arrow {
    /// The point (index into [`Picture::points`]).
    pub point: usize,
    /// Direction (global, any length).
    pub direction: [f64; 3],
    /// `true` for a prescribed displacement, `false` for a force.
    pub prescribed: bool,
}

/// Everything one `model.svg` shows.
#[derive(Debug, Clone, Default)]
pub struct Picture<'a> {
    /// Undeformed coordinates, mm.
    pub points: &'a [[f64; 3]],
    /// Deformed coordinates (already scaled by [`Picture::scale`]), mm; `None`: undeformed only.
    pub deformed: Option<&'a [[f64; 3]]>,
    /// Deformation scale of [`Picture::deformed`] (stated in the caption).
    pub scale: f64,
    /// Drawn items.
    pub items: &'a [Item],
    /// Notch symbols.
    pub marks: &'a [Mark],
    /// Supported points.
    pub supports: &'a [usize],
    /// Loads and prescribed motions.
    pub arrows: &'a [Arrow],
    /// The title line.
    pub title: &'a str,
    /// The caption (what is deformed, and how much).
    pub caption: &'a str,
    /// The load case (or mode) shown, echoed as `data-load-case`.
    pub load_case: &'a str,
    /// Viewing direction.
    pub view: Option<View>,
    /// Write node numbers next to the nodes and item numbers at the items' middles.
    pub numbers: bool,
}

/// Canvas width, px.
const WIDTH: f64 = 900.0;
/// Margin around the drawing, px.
const MARGIN: f64 = 50.0;
/// Room above the drawing for the title and the caption, px.
const TOP: f64 = 56.0;
/// Room right of the drawing for the utilisation legend, px.
const LEGEND: f64 = 110.0;
/// Half size of a notch symbol, px.
const NOTCH: f64 = 9.0;

/// The fill colour of a hinge or shell of utilisation `u`: green (0) → yellow (0.5) → red (1),
/// magenta above 1, grey for `None`. Returned as (r, g, b), 0–255.
pub fn utilisation_colour(u: Option<f64>) -> [u8; 3] {
    match u {
        None => [170, 170, 170],
        Some(u) if u > 1.0 => [200, 0, 200],
        Some(u) => {
            let u = u.max(0.0);
            let r = (230.0 * (2.0 * u).min(1.0)).round() as u8;
            let g = (200.0 * (2.0 * (1.0 - u)).min(1.0)).round() as u8;
            [r, g, 40]
        }
    }
}

fn hex(c: [u8; 3]) -> String {
    format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2])
}

fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

fn points_attr(pts: &[(f64, f64)]) -> String {
    pts.iter()
        .map(|(x, y)| format!("{x:.1},{y:.1}"))
        .collect::<Vec<_>>()
        .join(" ")
}

/// The SVG text of `pic`.
pub fn render(pic: &Picture) -> String {
    let view = pic.view.unwrap_or(View::ISO);
    let mut all: Vec<[f64; 3]> = pic.points.to_vec();
    if let Some(d) = pic.deformed {
        all.extend_from_slice(d);
    }
    let draw_w = WIDTH - 2.0 * MARGIN - LEGEND;
    // Height follows the drawing's aspect, within 300 … 700 px of drawing.
    let probe = Projector::new(view, &all, draw_w, 1e9, MARGIN, TOP + 0.5 * MARGIN);
    let aspect_h = {
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for p in &all {
            let y = probe.at(*p).1;
            lo = lo.min(y);
            hi = hi.max(y);
        }
        if lo.is_finite() {
            hi - lo
        } else {
            draw_w
        }
    };
    let draw_h = aspect_h.clamp(300.0, 700.0);
    let height = TOP + draw_h + 1.5 * MARGIN;
    let proj = Projector::new(view, &all, draw_w, draw_h, MARGIN, TOP + 0.5 * MARGIN);
    let shown = pic.deformed.unwrap_or(pic.points);

    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH:.0}" height="{height:.0}" viewBox="0 0 {WIDTH:.0} {height:.0}" data-scale="{}" data-load-case="{}" font-family="sans-serif">"#,
        pic.scale,
        esc(pic.load_case)
    );
    let _ = writeln!(
        s,
        r##"<rect x="0" y="0" width="{WIDTH:.0}" height="{height:.0}" fill="#ffffff"/>"##
    );
    let _ = writeln!(
        s,
        r#"<text class="title" x="{MARGIN}" y="24" font-size="16">{}</text>"#,
        esc(pic.title)
    );
    let _ = writeln!(
        s,
        r##"<text class="caption" x="{MARGIN}" y="44" font-size="12" fill="#444444">{}</text>"##,
        esc(pic.caption)
    );

    // The ghost: every item undeformed, thin and light.
    if pic.deformed.is_some() {
        let _ = writeln!(
            s,
            r##"<g class="ghost" stroke="#c8c8c8" fill="none" stroke-width="1">"##
        );
        for it in pic.items {
            let pts: Vec<(f64, f64)> = it.points.iter().map(|&i| proj.at(pic.points[i])).collect();
            draw_outline(&mut s, &pts, matches!(it.shape, Shape::Shell { .. } | Shape::Rigid));
        }
        let _ = writeln!(s, "</g>");
    }

    // The deformed (or undeformed) model, far items first.
    let mut order: Vec<(f64, usize)> = pic
        .items
        .iter()
        .enumerate()
        .map(|(k, it)| {
            let d = it.points.iter().map(|&i| proj.depth(shown[i])).sum::<f64>() / it.points.len().max(1) as f64;
            (d, k)
        })
        .collect();
    order.sort_by(|a, b| a.0.total_cmp(&b.0));
    for &(_, k) in &order {
        draw_item(&mut s, &pic.items[k], shown, &proj);
    }
    for &p in pic.supports {
        draw_support(&mut s, proj.at(shown[p]));
    }
    for a in pic.arrows {
        draw_arrow(&mut s, a, shown, &proj);
    }
    for m in pic.marks {
        draw_mark(&mut s, m, shown, &proj);
    }
    if pic.numbers {
        draw_numbers(&mut s, pic, shown, &proj);
    }
    draw_legend(&mut s);
    let _ = writeln!(s, "</svg>");
    s
}

fn draw_outline(s: &mut String, pts: &[(f64, f64)], closed: bool) {
    if closed && pts.len() >= 3 {
        let _ = writeln!(s, r#"<polygon points="{}"/>"#, points_attr(pts));
    } else {
        let _ = writeln!(s, r#"<polyline points="{}"/>"#, points_attr(pts));
    }
}

fn draw_item(s: &mut String, it: &Item, shown: &[[f64; 3]], proj: &Projector) {
    let pts: Vec<(f64, f64)> = it.points.iter().map(|&i| proj.at(shown[i])).collect();
    match it.shape {
        Shape::Beam { width } => {
            let w = (width * proj.px_per_mm).clamp(1.2, 10.0);
            let _ = writeln!(
                s,
                r##"<polyline class="beam" points="{}" stroke="#3c3c3c" stroke-width="{w:.1}" stroke-linecap="round" fill="none"/>"##,
                points_attr(&pts)
            );
        }
        Shape::HingeLine => {
            let _ = writeln!(
                s,
                r##"<polyline class="hinge-line" points="{}" stroke="#3c3c3c" stroke-width="2" fill="none"/>"##,
                points_attr(&pts)
            );
        }
        Shape::Spring => {
            let _ = writeln!(
                s,
                r##"<polyline class="spring" points="{}" stroke="#8c564b" stroke-width="1.5" stroke-dasharray="4 3" fill="none"/>"##,
                points_attr(&pts)
            );
        }
        Shape::Shell { utilisation } => {
            let fill = match utilisation {
                Some(_) => hex(utilisation_colour(utilisation)),
                None => "#dbe4ee".to_string(),
            };
            let _ = writeln!(
                s,
                r##"<polygon class="shell" points="{}" fill="{fill}" fill-opacity="0.9" stroke="#6b7b8c" stroke-width="0.6"/>"##,
                points_attr(&pts)
            );
        }
        Shape::Rigid | Shape::Body => {
            let class = if it.shape == Shape::Rigid { "rigid" } else { "body" };
            let h = hull(pts.clone());
            if h.len() >= 3 {
                let _ = writeln!(
                    s,
                    r##"<polygon class="{class}" points="{}" fill="#9ec1e6" fill-opacity="0.55" stroke="#4a78a8" stroke-width="1.2"/>"##,
                    points_attr(&h)
                );
            } else {
                let _ = writeln!(
                    s,
                    r##"<polyline class="{class}" points="{}" stroke="#6f98c4" stroke-width="5" stroke-linecap="round" fill="none"/>"##,
                    points_attr(&pts)
                );
            }
        }
    }
}

fn draw_support(s: &mut String, (x, y): (f64, f64)) {
    let a = 8.0;
    let _ = writeln!(
        s,
        r##"<g class="support"><polygon points="{x:.1},{y:.1} {:.1},{:.1} {:.1},{:.1}" fill="#555555"/><line x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="#555555" stroke-width="2"/></g>"##,
        x - a,
        y + 1.6 * a,
        x + a,
        y + 1.6 * a,
        x - 1.5 * a,
        y + 1.6 * a + 3.0,
        x + 1.5 * a,
        y + 1.6 * a + 3.0
    );
}

fn draw_arrow(s: &mut String, a: &Arrow, shown: &[[f64; 3]], proj: &Projector) {
    let Some((dx, dy)) = proj.direction(a.direction) else {
        return;
    };
    let (px, py) = proj.at(shown[a.point]);
    let len = 42.0;
    // A force points at its node; a prescribed motion leaves it.
    let (tail, head) = if a.prescribed {
        ((px, py), (px + len * dx, py + len * dy))
    } else {
        ((px - len * dx, py - len * dy), (px - 3.0 * dx, py - 3.0 * dy))
    };
    let (class, colour, dash) = if a.prescribed {
        ("prescribed", "#1f62b4", r#" stroke-dasharray="5 3""#)
    } else {
        ("load", "#c81e1e", "")
    };
    let (nx, ny) = (-dy, dx);
    let h = 9.0;
    let _ = writeln!(
        s,
        r#"<g class="{class}"><line x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="{colour}" stroke-width="2"{dash}/><polygon points="{:.1},{:.1} {:.1},{:.1} {:.1},{:.1}" fill="{colour}"/></g>"#,
        tail.0,
        tail.1,
        head.0 - 0.8 * h * dx,
        head.1 - 0.8 * h * dy,
        head.0,
        head.1,
        head.0 - h * dx + 0.45 * h * nx,
        head.1 - h * dy + 0.45 * h * ny,
        head.0 - h * dx - 0.45 * h * nx,
        head.1 - h * dy - 0.45 * h * ny,
    );
}

/// The notch symbol: two triangles meeting at the hinge's middle across its axis (a neck), filled
/// with the utilisation colour; `data-sample` is a point well inside the first triangle.
fn draw_mark(s: &mut String, m: &Mark, shown: &[[f64; 3]], proj: &Projector) {
    let (a, b) = (proj.at(shown[m.points[0]]), proj.at(shown[m.points[1]]));
    let mid = (0.5 * (a.0 + b.0), 0.5 * (a.1 + b.1));
    let (mut tx, mut ty) = (b.0 - a.0, b.1 - a.1);
    let n = tx.hypot(ty);
    if n > 1e-6 {
        (tx, ty) = (tx / n, ty / n);
    } else {
        (tx, ty) = (1.0, 0.0);
    }
    let (nx, ny) = (-ty, tx);
    let c = NOTCH;
    let p = |u: f64, v: f64| (mid.0 + u * tx + v * nx, mid.1 + u * ty + v * ny);
    let t1 = [p(-c, c), p(c, c), mid];
    let t2 = [p(-c, -c), p(c, -c), mid];
    let sample = p(0.0, 0.7 * c);
    let fill = hex(utilisation_colour(m.utilisation));
    let u = m.utilisation.map_or("none".to_string(), |u| format!("{u}"));
    let _ = writeln!(
        s,
        r##"<g class="hinge" data-label="{}" data-utilisation="{u}" data-sample="{:.1} {:.1}"><polygon points="{}" fill="{fill}" stroke="#222222" stroke-width="0.8"/><polygon points="{}" fill="{fill}" stroke="#222222" stroke-width="0.8"/></g>"##,
        esc(&m.label),
        sample.0,
        sample.1,
        points_attr(&t1),
        points_attr(&t2),
    );
}

fn draw_numbers(s: &mut String, pic: &Picture, shown: &[[f64; 3]], proj: &Projector) {
    let _ = writeln!(s, r##"<g class="numbers" font-size="10" fill="#1f62b4">"##);
    for (i, p) in shown.iter().enumerate().take(pic.points.len()) {
        let (x, y) = proj.at(*p);
        let _ = writeln!(s, r#"<text x="{:.1}" y="{:.1}">{i}</text>"#, x + 4.0, y - 4.0);
    }
    let _ = writeln!(s, "</g>");
}

fn draw_legend(s: &mut String) {
    let x = WIDTH - LEGEND + 10.0;
    let (top, h) = (TOP + 30.0, 160.0);
    let _ = writeln!(s, r#"<g class="legend" font-size="11">"#);
    let _ = writeln!(s, r#"<text x="{x}" y="{:.1}">hinge utilisation</text>"#, top - 10.0);
    let steps = 20;
    for k in 0..steps {
        let u = 1.0 - (k as f64 + 0.5) / steps as f64;
        let _ = writeln!(
            s,
            r#"<rect x="{x}" y="{:.1}" width="18" height="{:.2}" fill="{}"/>"#,
            top + h * k as f64 / steps as f64,
            h / steps as f64 + 0.3,
            hex(utilisation_colour(Some(u)))
        );
    }
    for (u, label) in [(1.0, "1"), (0.5, "0.5"), (0.0, "0")] {
        let _ = writeln!(
            s,
            r#"<text x="{:.1}" y="{:.1}">{label}</text>"#,
            x + 24.0,
            top + h * (1.0 - u) + 4.0
        );
    }
    let over = top + h + 12.0;
    let _ = writeln!(
        s,
        r#"<rect x="{x}" y="{over:.1}" width="18" height="12" fill="{}"/><text x="{:.1}" y="{:.1}">&gt; 1</text>"#,
        hex(utilisation_colour(Some(2.0))),
        x + 24.0,
        over + 10.0
    );
    let none = over + 20.0;
    let _ = writeln!(
        s,
        r#"<rect x="{x}" y="{none:.1}" width="18" height="12" fill="{}"/><text x="{:.1}" y="{:.1}">no allowable</text>"#,
        hex(utilisation_colour(None)),
        x + 24.0,
        none + 10.0
    );
    let ghost = none + 26.0;
    let _ = writeln!(
        s,
        r##"<line x1="{x}" y1="{ghost:.1}" x2="{:.1}" y2="{ghost:.1}" stroke="#c8c8c8" stroke-width="2"/><text x="{:.1}" y="{:.1}">undeformed</text>"##,
        x + 18.0,
        x + 24.0,
        ghost + 4.0
    );
    let _ = writeln!(s, "</g>");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colour_map_ends() {
        assert_eq!(utilisation_colour(Some(0.0)), [0, 200, 40]);
        assert_eq!(utilisation_colour(Some(0.5)), [230, 200, 40]);
        assert_eq!(utilisation_colour(Some(1.0)), [230, 0, 40]);
        assert_eq!(utilisation_colour(Some(1.01)), [200, 0, 200]);
        assert_eq!(utilisation_colour(None), [170, 170, 170]);
    }
}
