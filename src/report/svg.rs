//! Minimal SVG plots (formatting only). Axes and their round ticks come from [`super::axis`];
//! the elements carry classes (`tick-x`, `tick-y`, `label-x`, `label-y`, `legend-box`,
//! `series`, `marker`) and log axes `data-scale="log"`, so tests and scripts can read a plot back.

use super::axis::{Axis, Scale};

fn esc(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}

/// Series colours (matplotlib's "tab10").
const COLOURS: [&str; 8] = [
    "#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf",
];

/// Series of at most this many points are drawn with markers (sparse data).
const SPARSE: usize = 12;

/// A plot area: canvas size, margins and the axes mapped onto it.
struct Frame {
    w: f64,
    h: f64,
    l: f64,
    r: f64,
    t: f64,
    b: f64,
    x: Axis,
    y: Axis,
}

impl Frame {
    /// A frame over the data `pts` (and `extra_y` values) with round ticks; the y range
    /// includes 0 when `y_from_zero` (and the y axis is linear).
    #[allow(clippy::too_many_arguments)]
    fn new(
        w: f64,
        h: f64,
        right_margin: f64,
        pts: &[(f64, f64)],
        extra_y: &[f64],
        scales: (Scale, Scale),
        y_from_zero: bool,
    ) -> Frame {
        let fin = pts.iter().filter(|(x, y)| x.is_finite() && y.is_finite());
        let xs: Vec<f64> = fin.clone().map(|p| p.0).collect();
        let mut ys: Vec<f64> = fin.map(|p| p.1).chain(extra_y.iter().copied()).collect();
        let y = Axis::new(&ys, scales.1, 6);
        let y = if y_from_zero && !y.log {
            ys.push(0.0);
            Axis::new(&ys, scales.1, 6)
        } else {
            y
        };
        Frame {
            w,
            h,
            l: 75.0,
            r: right_margin,
            t: 40.0,
            b: 55.0,
            x: Axis::new(&xs, scales.0, 7),
            y,
        }
    }

    fn sx(&self, v: f64) -> Option<f64> {
        let p = self.x.pos(v)?;
        Some(self.l + (p - self.x.range[0]) / (self.x.range[1] - self.x.range[0]) * (self.w - self.l - self.r))
    }

    fn sy(&self, v: f64) -> Option<f64> {
        let p = self.y.pos(v)?;
        Some(self.h - self.b - (p - self.y.range[0]) / (self.y.range[1] - self.y.range[0]) * (self.h - self.t - self.b))
    }

    /// Screen position of a data point (`None` if it cannot be drawn, e.g. ≤ 0 on a log axis).
    fn pt(&self, (x, y): (f64, f64)) -> Option<(f64, f64)> {
        Some((self.sx(x)?, self.sy(y)?))
    }

    /// SVG header, title, axes with their ticks, grid lines and axis labels.
    fn open(&self, title: &str, xlabel: &str, ylabel: &str) -> String {
        let (w, h, l, r, t, b) = (self.w, self.h, self.l, self.r, self.t, self.b);
        let scale = |a: &Axis| if a.log { "log" } else { "linear" };
        let mut out = format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<text x=\"{}\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">{}</text>\n",
            (l + w - r) / 2.0,
            esc(title)
        );
        for v in self.x.minor() {
            if let Some(x) = self.sx(v) {
                out += &format!(
                    "<line x1=\"{x:.1}\" y1=\"{t}\" x2=\"{x:.1}\" y2=\"{}\" stroke=\"#f0f0f0\"/>\n",
                    h - b
                );
            }
        }
        for v in self.y.minor() {
            if let Some(y) = self.sy(v) {
                out += &format!(
                    "<line x1=\"{l}\" y1=\"{y:.1}\" x2=\"{}\" y2=\"{y:.1}\" stroke=\"#f0f0f0\"/>\n",
                    w - r
                );
            }
        }
        for &v in &self.x.ticks {
            let Some(x) = self.sx(v) else { continue };
            out += &format!(
                "<line x1=\"{x:.1}\" y1=\"{t}\" x2=\"{x:.1}\" y2=\"{}\" stroke=\"#ddd\"/>\n<text class=\"tick-x\" data-value=\"{v:e}\" x=\"{x:.1}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n",
                h - b,
                h - b + 18.0,
                self.x.label(v)
            );
        }
        for &v in &self.y.ticks {
            let Some(y) = self.sy(v) else { continue };
            out += &format!(
                "<line x1=\"{l}\" y1=\"{y:.1}\" x2=\"{}\" y2=\"{y:.1}\" stroke=\"#ddd\"/>\n<text class=\"tick-y\" data-value=\"{v:e}\" x=\"{}\" y=\"{:.1}\" text-anchor=\"end\">{}</text>\n",
                w - r,
                l - 6.0,
                y + 4.0,
                self.y.label(v)
            );
        }
        out += &format!(
            "<line class=\"axis-x\" data-scale=\"{sc}\" x1=\"{l}\" y1=\"{y0}\" x2=\"{x1}\" y2=\"{y0}\" stroke=\"black\"/>\n",
            sc = scale(&self.x),
            y0 = h - b,
            x1 = w - r,
        );
        out += &format!(
            "<line class=\"axis-y\" data-scale=\"{}\" x1=\"{l}\" y1=\"{t}\" x2=\"{l}\" y2=\"{}\" stroke=\"black\"/>\n",
            scale(&self.y),
            h - b
        );
        out += &format!(
            "<text class=\"label-x\" x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n",
            (l + w - r) / 2.0,
            h - b + 40.0,
            esc(xlabel)
        );
        out += &format!(
            "<text class=\"label-y\" x=\"16\" y=\"{0}\" text-anchor=\"middle\" transform=\"rotate(-90 16 {0})\">{1}</text>\n",
            (t + h - b) / 2.0,
            esc(ylabel)
        );
        out
    }
}

/// A scatter plot with connecting lines per series (points sorted by x, markers on every
/// point, y from zero), axes with round ticks, title, labels and a legend.
pub fn scatter(title: &str, xlabel: &str, ylabel: &str, series: &[(&str, &[(f64, f64)])]) -> String {
    plot(
        title,
        xlabel,
        ylabel,
        series,
        Style {
            all_markers: true,
            sort: true,
            y_from_zero: true,
        },
        (Scale::Auto, Scale::Auto),
    )
}

/// Like [`scatter`] for long time histories: lines, markers only on sparse series (at most
/// twelve points), y over the data.
pub fn lines(title: &str, xlabel: &str, ylabel: &str, series: &[(&str, &[(f64, f64)])]) -> String {
    lines_scaled(title, xlabel, ylabel, series, (Scale::Auto, Scale::Auto))
}

/// [`lines`] with the x and y [`Scale`]s given (e.g. Bode plots: log frequency, log magnitude,
/// phase in degrees).
pub fn lines_scaled(
    title: &str,
    xlabel: &str,
    ylabel: &str,
    series: &[(&str, &[(f64, f64)])],
    scales: (Scale, Scale),
) -> String {
    plot(
        title,
        xlabel,
        ylabel,
        series,
        Style {
            all_markers: false,
            sort: true,
            y_from_zero: false,
        },
        scales,
    )
}

/// Curves through each series' points in their given order (a path that may turn back in x),
/// axes with ticks, title, labels and a legend.
pub fn curve(title: &str, xlabel: &str, ylabel: &str, series: &[(&str, &[(f64, f64)])]) -> String {
    plot(
        title,
        xlabel,
        ylabel,
        series,
        Style {
            all_markers: true,
            sort: false,
            y_from_zero: true,
        },
        (Scale::Auto, Scale::Auto),
    )
}

/// How [`plot`] draws its series.
#[derive(Clone, Copy)]
struct Style {
    /// Markers on every point (else only on series of at most [`SPARSE`] points).
    all_markers: bool,
    /// Points sorted by x.
    sort: bool,
    /// The y range includes 0.
    y_from_zero: bool,
}

/// The plot of [`scatter`], [`lines`] and [`curve`].
fn plot(
    title: &str,
    xlabel: &str,
    ylabel: &str,
    series: &[(&str, &[(f64, f64)])],
    style: Style,
    scales: (Scale, Scale),
) -> String {
    let all: Vec<(f64, f64)> = series.iter().flat_map(|(_, p)| p.iter().copied()).collect();
    let mut f = Frame::new(640.0, 420.0, 20.0, &all, &[], scales, style.y_from_zero);
    let drawn: Vec<Vec<(f64, f64)>> = series
        .iter()
        .map(|(_, p)| {
            let mut s: Vec<(f64, f64)> = p.iter().filter_map(|&q| f.pt(q).map(|_| q)).collect();
            if style.sort {
                s.sort_by(|a, b| a.0.total_cmp(&b.0));
            }
            s
        })
        .collect();
    // The legend goes into the plot corner that holds no data, else to the right of the plot.
    let names: Vec<&str> = series.iter().map(|s| s.0).collect();
    let (lw, lh) = legend_size(&names);
    let screen: Vec<Vec<(f64, f64)>> = drawn
        .iter()
        .map(|s| s.iter().filter_map(|&q| f.pt(q)).collect())
        .collect();
    let (lx, ly) = match free_corner(&f, &screen, lw, lh) {
        Some(c) => c,
        None => {
            f.w += lw + 16.0;
            f.r += lw + 16.0;
            (f.w - lw - 10.0, f.t)
        }
    };
    let mut out = f.open(title, xlabel, ylabel);
    for (si, s) in screen.iter().enumerate() {
        let c = COLOURS[si % COLOURS.len()];
        let path: Vec<String> = s.iter().map(|(x, y)| format!("{x:.1},{y:.1}")).collect();
        out += &format!(
            "<polyline class=\"series\" fill=\"none\" stroke=\"{c}\" points=\"{}\"/>\n",
            path.join(" ")
        );
        if style.all_markers || s.len() <= SPARSE {
            for (x, y) in s {
                out += &format!("<circle class=\"marker\" cx=\"{x:.1}\" cy=\"{y:.1}\" r=\"4\" fill=\"{c}\"/>\n");
            }
        }
    }
    out += &legend(&names, lx, ly, lw, lh);
    out += "</svg>\n";
    out
}

/// Width and height (px) of the legend box of `names`.
fn legend_size(names: &[&str]) -> (f64, f64) {
    let chars = names.iter().map(|n| n.chars().count()).max().unwrap_or(0);
    (7.0 * chars as f64 + 38.0, 16.0 * names.len() as f64 + 8.0)
}

/// The top-left corner of a `lw` × `lh` legend box in a corner of the plot area that no
/// drawn point or line (`screen`, per series) passes through; `None` if every corner is taken.
fn free_corner(f: &Frame, screen: &[Vec<(f64, f64)>], lw: f64, lh: f64) -> Option<(f64, f64)> {
    const INSET: f64 = 6.0;
    const CLEAR: f64 = 6.0;
    let (x0, x1, y0, y1) = (f.l + INSET, f.w - f.r - INSET - lw, f.t + INSET, f.h - f.b - INSET - lh);
    if x1 < x0 || y1 < y0 {
        return None;
    }
    // Points along every segment, at most 2 px apart.
    let mut dense = Vec::new();
    for s in screen {
        dense.extend(s.first().copied());
        for w in s.windows(2) {
            let n = ((w[1].0 - w[0].0).hypot(w[1].1 - w[0].1) / 2.0).ceil().min(2000.0) as usize;
            for k in 1..=n {
                let a = k as f64 / n as f64;
                dense.push((w[0].0 + a * (w[1].0 - w[0].0), w[0].1 + a * (w[1].1 - w[0].1)));
            }
        }
    }
    [(x1, y0), (x0, y0), (x1, y1), (x0, y1)].into_iter().find(|&(x, y)| {
        !dense
            .iter()
            .any(|&(px, py)| px > x - CLEAR && px < x + lw + CLEAR && py > y - CLEAR && py < y + lh + CLEAR)
    })
}

/// The legend: a box at (`x`, `y`) of size `w` × `h` with a coloured line and the name of
/// each series.
fn legend(names: &[&str], x: f64, y: f64, w: f64, h: f64) -> String {
    let mut out = format!(
        "<g class=\"legend\">\n<rect class=\"legend-box\" x=\"{x:.1}\" y=\"{y:.1}\" width=\"{w:.1}\" height=\"{h:.1}\" fill=\"white\" fill-opacity=\"0.9\" stroke=\"#999\"/>\n"
    );
    for (i, n) in names.iter().enumerate() {
        let c = COLOURS[i % COLOURS.len()];
        let yy = y + 16.0 + 16.0 * i as f64;
        out += &format!(
            "<line x1=\"{:.1}\" y1=\"{:.1}\" x2=\"{:.1}\" y2=\"{:.1}\" stroke=\"{c}\" stroke-width=\"2\"/>\n<text x=\"{:.1}\" y=\"{yy:.1}\">{}</text>\n",
            x + 6.0,
            yy - 4.0,
            x + 26.0,
            yy - 4.0,
            x + 32.0,
            esc(n)
        );
    }
    out + "</g>\n"
}

/// Plots (each a whole `<svg>` document from this module) stacked vertically into one SVG.
pub fn stack(panels: &[String]) -> String {
    let size = |p: &str, attr: &str| -> f64 {
        p.split_once(&format!("{attr}=\""))
            .and_then(|(_, rest)| rest.split_once('"'))
            .and_then(|(v, _)| v.parse().ok())
            .unwrap_or(0.0)
    };
    let w = panels.iter().map(|p| size(p, "width")).fold(0.0, f64::max);
    let h: f64 = panels.iter().map(|p| size(p, "height")).sum();
    let mut out = format!("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\">\n");
    let mut y = 0.0;
    for p in panels {
        out += &p.replacen("<svg ", &format!("<svg y=\"{y}\" "), 1);
        y += size(p, "height");
    }
    out += "</svg>\n";
    out
}

/// A scatter plot of points coloured by a value (blue = low, red = high) with a colour bar
/// with round ticks; `marked` points are drawn filled, the others hollow (explained under the
/// x-axis label); optional horizontal line `hline` (value, label).
pub fn scatter_coloured(
    title: &str,
    xlabel: &str,
    ylabel: &str,
    points: &[(f64, f64, f64, bool)],
    colour_label: &str,
    hline: Option<(f64, &str)>,
) -> String {
    let pts: Vec<(f64, f64, f64, bool)> = points
        .iter()
        .copied()
        .filter(|p| p.0.is_finite() && p.1.is_finite() && p.2.is_finite())
        .collect();
    let xy: Vec<(f64, f64)> = pts.iter().map(|p| (p.0, p.1)).collect();
    let extra: Vec<f64> = hline.iter().map(|h| h.0).collect();
    let mut f = Frame::new(720.0, 480.0, 130.0, &xy, &extra, (Scale::Auto, Scale::Auto), false);
    f.b = 75.0;
    let cs: Vec<f64> = pts.iter().map(|p| p.2).collect();
    let ca = Axis::new(&cs, Scale::Linear, 6);
    let [c0, c1] = ca.range;
    let frac = |c: f64| {
        if c1 > c0 {
            ((c - c0) / (c1 - c0)).clamp(0.0, 1.0)
        } else {
            0.5
        }
    };
    let colour = |c: f64| {
        let s = frac(c);
        format!(
            "rgb({},{},{})",
            (40.0 + 215.0 * s) as u8,
            (80.0 + 60.0 * (1.0 - (2.0 * s - 1.0).abs())) as u8,
            (255.0 - 215.0 * s) as u8
        )
    };
    let mut out = f.open(title, xlabel, ylabel);
    if let Some((label, y)) = hline.and_then(|(v, label)| Some((label, f.sy(v)?))) {
        out += &format!(
            "<line x1=\"{0}\" y1=\"{1:.1}\" x2=\"{2}\" y2=\"{1:.1}\" stroke=\"#444\" stroke-dasharray=\"6,4\"/>\n<text x=\"{3}\" y=\"{4:.1}\">{5}</text>\n",
            f.l,
            y,
            f.w - f.r,
            f.l + 6.0,
            y - 5.0,
            esc(label)
        );
    }
    for &(x, y, c, marked) in &pts {
        let Some((x, y)) = f.pt((x, y)) else { continue };
        let col = colour(c);
        out += &if marked {
            format!("<circle class=\"marker\" cx=\"{x:.1}\" cy=\"{y:.1}\" r=\"3.5\" fill=\"{col}\"/>\n")
        } else {
            format!("<circle class=\"marker\" cx=\"{x:.1}\" cy=\"{y:.1}\" r=\"3\" fill=\"none\" stroke=\"{col}\"/>\n")
        };
    }
    let (bx, span) = (f.w - f.r + 30.0, f.h - f.t - f.b);
    for k in 0..20 {
        let c = c0 + (c1 - c0) * (k as f64 + 0.5) / 20.0;
        let y = f.h - f.b - span * (k + 1) as f64 / 20.0;
        out += &format!(
            "<rect x=\"{bx}\" y=\"{y:.1}\" width=\"16\" height=\"{:.1}\" fill=\"{}\"/>\n",
            span / 20.0 + 0.5,
            colour(c)
        );
    }
    for &c in &ca.ticks {
        out += &format!(
            "<text class=\"tick-c\" data-value=\"{c:e}\" x=\"{}\" y=\"{:.1}\">{}</text>\n",
            bx + 20.0,
            f.h - f.b - span * frac(c) + 4.0,
            ca.label(c)
        );
    }
    // The colour's name runs up the right edge, beside the bar's ticks.
    out += &format!(
        "<text x=\"{0}\" y=\"{1}\" text-anchor=\"middle\" transform=\"rotate(-90 {0} {1})\">{2}</text>\n",
        f.w - 12.0,
        f.t + span / 2.0,
        esc(colour_label)
    );
    out += &format!(
        "<text x=\"{}\" y=\"{}\" font-size=\"11\" text-anchor=\"middle\">filled: meets the requirements; hollow: does not</text>\n",
        (f.l + f.w - f.r) / 2.0,
        f.h - 10.0
    );
    out += "</svg>\n";
    out
}
