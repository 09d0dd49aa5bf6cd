//! Minimal SVG plots (formatting only).

use super::markdown::sig;

fn esc(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}

/// A plot area: canvas size, margins and the data ranges mapped onto it.
struct Frame {
    w: f64,
    h: f64,
    l: f64,
    r: f64,
    t: f64,
    b: f64,
    x: [f64; 2],
    y: [f64; 2],
}

impl Frame {
    /// A frame over the data `pts` (and `extra_y` values), padded by `pad` of each span; the
    /// y range starts at 0 when `y_from_zero`.
    fn new(w: f64, h: f64, right_margin: f64, pts: &[(f64, f64)], extra_y: &[f64], y_from_zero: bool) -> Frame {
        let fin: Vec<(f64, f64)> = pts
            .iter()
            .copied()
            .filter(|(x, y)| x.is_finite() && y.is_finite())
            .collect();
        let mut x = [f64::INFINITY, f64::NEG_INFINITY];
        let mut y = if y_from_zero {
            [0.0, f64::NEG_INFINITY]
        } else {
            [f64::INFINITY, f64::NEG_INFINITY]
        };
        for &(px, py) in &fin {
            x = [x[0].min(px), x[1].max(px)];
            y = [y[0].min(py), y[1].max(py)];
        }
        for &v in extra_y {
            y = [y[0].min(v), y[1].max(v)];
        }
        if !x[0].is_finite() {
            x = [0.0, 1.0];
        }
        if !(y[0].is_finite() && y[1].is_finite()) {
            y = [0.0, 1.0];
        }
        if x[1] - x[0] < 1e-12 {
            x[1] = x[0] + 1.0;
        }
        if y[1] - y[0] < 1e-12 {
            y[1] = y[0] + 1.0;
        }
        let (px, py) = (0.05 * (x[1] - x[0]), 0.06 * (y[1] - y[0]));
        let y = if y_from_zero && y[0] >= 0.0 {
            [y[0], y[1] + py]
        } else {
            [y[0] - py, y[1] + py]
        };
        Frame {
            w,
            h,
            l: 75.0,
            r: right_margin,
            t: 40.0,
            b: 55.0,
            x: [x[0] - px, x[1] + px],
            y,
        }
    }

    fn sx(&self, v: f64) -> f64 {
        self.l + (v - self.x[0]) / (self.x[1] - self.x[0]) * (self.w - self.l - self.r)
    }

    fn sy(&self, v: f64) -> f64 {
        self.h - self.b - (v - self.y[0]) / (self.y[1] - self.y[0]) * (self.h - self.t - self.b)
    }

    /// SVG header, title, axes with five ticks each, grid lines and axis labels.
    fn open(&self, title: &str, xlabel: &str, ylabel: &str) -> String {
        let (w, h, l, r, t, b) = (self.w, self.h, self.l, self.r, self.t, self.b);
        let mut out = format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<text x=\"{}\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">{}</text>\n",
            (l + w - r) / 2.0,
            esc(title)
        );
        out += &format!(
            "<line x1=\"{l}\" y1=\"{0}\" x2=\"{1}\" y2=\"{0}\" stroke=\"black\"/>\n",
            h - b,
            w - r
        );
        out += &format!(
            "<line x1=\"{l}\" y1=\"{t}\" x2=\"{l}\" y2=\"{}\" stroke=\"black\"/>\n",
            h - b
        );
        for k in 0..=5 {
            let xv = self.x[0] + (self.x[1] - self.x[0]) * k as f64 / 5.0;
            let yv = self.y[0] + (self.y[1] - self.y[0]) * k as f64 / 5.0;
            out += &format!(
                "<text x=\"{:.1}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n",
                self.sx(xv),
                h - b + 18.0,
                sig(xv, 3)
            );
            out += &format!(
                "<text x=\"{}\" y=\"{:.1}\" text-anchor=\"end\">{}</text>\n",
                l - 6.0,
                self.sy(yv) + 4.0,
                sig(yv, 3)
            );
            out += &format!(
                "<line x1=\"{l}\" y1=\"{0:.1}\" x2=\"{1}\" y2=\"{0:.1}\" stroke=\"#ddd\"/>\n",
                self.sy(yv),
                w - r
            );
        }
        out += &format!(
            "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n",
            (l + w - r) / 2.0,
            h - 12.0,
            esc(xlabel)
        );
        out += &format!(
            "<text x=\"16\" y=\"{0}\" text-anchor=\"middle\" transform=\"rotate(-90 16 {0})\">{1}</text>\n",
            (t + h - b) / 2.0,
            esc(ylabel)
        );
        out
    }
}

/// A scatter plot with connecting lines per series, axes with ticks, title and labels.
pub fn scatter(title: &str, xlabel: &str, ylabel: &str, series: &[(&str, &[(f64, f64)])]) -> String {
    plot(title, xlabel, ylabel, series, true)
}

/// Like [`scatter`] without point markers (long time histories).
pub fn lines(title: &str, xlabel: &str, ylabel: &str, series: &[(&str, &[(f64, f64)])]) -> String {
    plot(title, xlabel, ylabel, series, false)
}

fn plot(title: &str, xlabel: &str, ylabel: &str, series: &[(&str, &[(f64, f64)])], markers: bool) -> String {
    let all: Vec<(f64, f64)> = series.iter().flat_map(|(_, p)| p.iter().copied()).collect();
    let f = Frame::new(640.0, 420.0, 20.0, &all, &[], true);
    let mut out = f.open(title, xlabel, ylabel);
    let colours = [
        "#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf",
    ];
    for (si, (name, p)) in series.iter().enumerate() {
        let c = colours[si % colours.len()];
        let mut sorted: Vec<(f64, f64)> = p
            .iter()
            .copied()
            .filter(|(x, y)| x.is_finite() && y.is_finite())
            .collect();
        sorted.sort_by(|a, b| a.0.total_cmp(&b.0));
        let path: Vec<String> = sorted
            .iter()
            .map(|&(x, y)| format!("{:.1},{:.1}", f.sx(x), f.sy(y)))
            .collect();
        out += &format!(
            "<polyline fill=\"none\" stroke=\"{c}\" points=\"{}\"/>\n",
            path.join(" ")
        );
        for &(x, y) in sorted.iter().filter(|_| markers) {
            out += &format!(
                "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"4\" fill=\"{c}\"/>\n",
                f.sx(x),
                f.sy(y)
            );
        }
        out += &format!(
            "<text x=\"{}\" y=\"{}\" fill=\"{c}\">{}</text>\n",
            f.l + 10.0,
            f.t + 16.0 + 16.0 * si as f64,
            esc(name)
        );
    }
    out += "</svg>\n";
    out
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

/// A scatter plot of points coloured by a value (blue = low, red = high) with a colour-bar
/// legend; `marked` points are drawn filled, the others hollow; optional horizontal line `hline`
/// (value, label).
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
    let f = Frame::new(720.0, 460.0, 120.0, &xy, &extra, false);
    let (c0, c1) = pts
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.2), b.max(p.2)));
    let colour = |c: f64| {
        let s = if c1 > c0 {
            ((c - c0) / (c1 - c0)).clamp(0.0, 1.0)
        } else {
            0.5
        };
        format!(
            "rgb({},{},{})",
            (40.0 + 215.0 * s) as u8,
            (80.0 + 60.0 * (1.0 - (2.0 * s - 1.0).abs())) as u8,
            (255.0 - 215.0 * s) as u8
        )
    };
    let mut out = f.open(title, xlabel, ylabel);
    if let Some((v, label)) = hline {
        out += &format!(
            "<line x1=\"{0}\" y1=\"{1:.1}\" x2=\"{2}\" y2=\"{1:.1}\" stroke=\"#444\" stroke-dasharray=\"6,4\"/>\n<text x=\"{3}\" y=\"{4:.1}\">{5}</text>\n",
            f.l,
            f.sy(v),
            f.w - f.r,
            f.l + 6.0,
            f.sy(v) - 5.0,
            esc(label)
        );
    }
    for &(x, y, c, marked) in &pts {
        let col = colour(c);
        out += &if marked {
            format!(
                "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"3.5\" fill=\"{col}\"/>\n",
                f.sx(x),
                f.sy(y)
            )
        } else {
            format!(
                "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"3\" fill=\"none\" stroke=\"{col}\"/>\n",
                f.sx(x),
                f.sy(y)
            )
        };
    }
    let (bx, span) = (f.w - f.r + 30.0, f.h - f.t - f.b);
    for k in 0..20 {
        let c = c0 + (c1 - c0) * k as f64 / 19.0;
        let y = f.h - f.b - span * (k + 1) as f64 / 20.0;
        out += &format!(
            "<rect x=\"{bx}\" y=\"{y:.1}\" width=\"16\" height=\"{:.1}\" fill=\"{}\"/>\n",
            span / 20.0 + 0.5,
            colour(c)
        );
    }
    out += &format!("<text x=\"{}\" y=\"{}\">{}</text>\n", bx + 20.0, f.h - f.b, sig(c0, 3));
    out += &format!("<text x=\"{}\" y=\"{}\">{}</text>\n", bx + 20.0, f.t + 10.0, sig(c1, 3));
    out += &format!(
        "<text x=\"{}\" y=\"{}\">{}</text>\n",
        bx - 4.0,
        f.t - 6.0,
        esc(colour_label)
    );
    out += &format!(
        "<text x=\"{}\" y=\"{}\" font-size=\"11\">filled: meets the requirements; hollow: does not</text>\n",
        f.l + 6.0,
        f.h - f.b - 8.0
    );
    out += "</svg>\n";
    out
}
