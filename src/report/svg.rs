//! Minimal SVG scatter/line plots (formatting only).

/// A scatter plot with connecting lines per series, axes with ticks, title and labels.
pub fn scatter(title: &str, xlabel: &str, ylabel: &str, series: &[(&str, &[(f64, f64)])]) -> String {
    let (w, h) = (640.0, 420.0);
    let (l, r, t, b) = (70.0, 20.0, 40.0, 55.0);
    let pts: Vec<(f64, f64)> = series
        .iter()
        .flat_map(|(_, p)| p.iter().copied())
        .filter(|(x, y)| x.is_finite() && y.is_finite())
        .collect();
    let (mut x0, mut x1, mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY, 0.0f64, f64::NEG_INFINITY);
    for &(x, y) in &pts {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    if !x0.is_finite() {
        (x0, x1, y1) = (0.0, 1.0, 1.0);
    }
    if x1 - x0 < 1e-12 {
        x1 = x0 + 1.0;
    }
    if y1 - y0 < 1e-12 {
        y1 = y0 + 1.0;
    }
    let pad = 0.05 * (x1 - x0);
    let (x0, x1) = (x0 - pad, x1 + pad);
    let y1 = y1 + 0.08 * (y1 - y0);
    let sx = |x: f64| l + (x - x0) / (x1 - x0) * (w - l - r);
    let sy = |y: f64| h - b - (y - y0) / (y1 - y0) * (h - t - b);
    let esc = |s: &str| s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;");
    let mut out = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<text x=\"{}\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">{}</text>\n",
        w / 2.0,
        esc(title)
    );
    out += &format!(
        "<line x1=\"{l}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"black\"/>\n",
        h - b,
        w - r,
        h - b
    );
    out += &format!(
        "<line x1=\"{l}\" y1=\"{t}\" x2=\"{l}\" y2=\"{}\" stroke=\"black\"/>\n",
        h - b
    );
    for k in 0..=5 {
        let xv = x0 + (x1 - x0) * k as f64 / 5.0;
        let yv = y0 + (y1 - y0) * k as f64 / 5.0;
        out += &format!(
            "<text x=\"{:.1}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n",
            sx(xv),
            h - b + 18.0,
            super::markdown::sig(xv, 3)
        );
        out += &format!(
            "<text x=\"{}\" y=\"{:.1}\" text-anchor=\"end\">{}</text>\n",
            l - 6.0,
            sy(yv) + 4.0,
            super::markdown::sig(yv, 3)
        );
        out += &format!(
            "<line x1=\"{l}\" y1=\"{:.1}\" x2=\"{}\" y2=\"{:.1}\" stroke=\"#ddd\"/>\n",
            sy(yv),
            w - r,
            sy(yv)
        );
    }
    out += &format!(
        "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n",
        (l + w - r) / 2.0,
        h - 12.0,
        esc(xlabel)
    );
    out += &format!(
        "<text x=\"16\" y=\"{}\" text-anchor=\"middle\" transform=\"rotate(-90 16 {})\">{}</text>\n",
        (t + h - b) / 2.0,
        (t + h - b) / 2.0,
        esc(ylabel)
    );
    let colours = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd"];
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
            .map(|&(x, y)| format!("{:.1},{:.1}", sx(x), sy(y)))
            .collect();
        out += &format!(
            "<polyline fill=\"none\" stroke=\"{c}\" points=\"{}\"/>\n",
            path.join(" ")
        );
        for &(x, y) in &sorted {
            out += &format!(
                "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"4\" fill=\"{c}\"/>\n",
                sx(x),
                sy(y)
            );
        }
        out += &format!(
            "<text x=\"{}\" y=\"{}\" fill=\"{c}\">{}</text>\n",
            l + 10.0,
            t + 16.0 + 16.0 * si as f64,
            esc(name)
        );
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
    let (w, h) = (720.0, 460.0);
    let (l, r, t, b) = (75.0, 120.0, 40.0, 55.0);
    let pts: Vec<(f64, f64, f64, bool)> = points
        .iter()
        .copied()
        .filter(|p| p.0.is_finite() && p.1.is_finite() && p.2.is_finite())
        .collect();
    let fold = |f: fn(&(f64, f64, f64, bool)) -> f64| {
        pts.iter()
            .map(f)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)))
    };
    let (mut x0, mut x1) = fold(|p| p.0);
    let (mut y0, mut y1) = fold(|p| p.1);
    let (c0, c1) = fold(|p| p.2);
    if let Some((v, _)) = hline {
        y0 = y0.min(v);
        y1 = y1.max(v);
    }
    if !x0.is_finite() {
        (x0, x1, y0, y1) = (0.0, 1.0, 0.0, 1.0);
    }
    if x1 - x0 < 1e-12 {
        x1 = x0 + 1.0;
    }
    if y1 - y0 < 1e-12 {
        y1 = y0 + 1.0;
    }
    let (px, py) = (0.05 * (x1 - x0), 0.05 * (y1 - y0));
    let (x0, x1, y0, y1) = (x0 - px, x1 + px, y0 - py, y1 + py);
    let sx = |x: f64| l + (x - x0) / (x1 - x0) * (w - l - r);
    let sy = |y: f64| h - b - (y - y0) / (y1 - y0) * (h - t - b);
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
    let esc = |s: &str| s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;");
    let sig = super::markdown::sig;
    let mut out = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<text x=\"{}\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">{}</text>\n",
        (l + w - r) / 2.0,
        esc(title)
    );
    out += &format!(
        "<line x1=\"{l}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"black\"/>\n",
        h - b,
        w - r,
        h - b
    );
    out += &format!(
        "<line x1=\"{l}\" y1=\"{t}\" x2=\"{l}\" y2=\"{}\" stroke=\"black\"/>\n",
        h - b
    );
    for k in 0..=5 {
        let xv = x0 + (x1 - x0) * k as f64 / 5.0;
        let yv = y0 + (y1 - y0) * k as f64 / 5.0;
        out += &format!(
            "<text x=\"{:.1}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n",
            sx(xv),
            h - b + 18.0,
            sig(xv, 3)
        );
        out += &format!(
            "<text x=\"{}\" y=\"{:.1}\" text-anchor=\"end\">{}</text>\n",
            l - 6.0,
            sy(yv) + 4.0,
            sig(yv, 3)
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
    if let Some((v, label)) = hline {
        out += &format!(
            "<line x1=\"{l}\" y1=\"{0:.1}\" x2=\"{1}\" y2=\"{0:.1}\" stroke=\"#444\" stroke-dasharray=\"6,4\"/>\n<text x=\"{2}\" y=\"{3:.1}\">{4}</text>\n",
            sy(v),
            w - r,
            l + 6.0,
            sy(v) - 5.0,
            esc(label)
        );
    }
    for &(x, y, c, marked) in &pts {
        let col = colour(c);
        if marked {
            out += &format!(
                "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"3.5\" fill=\"{col}\"/>\n",
                sx(x),
                sy(y)
            );
        } else {
            out += &format!(
                "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"3\" fill=\"none\" stroke=\"{col}\"/>\n",
                sx(x),
                sy(y)
            );
        }
    }
    let bx = w - r + 30.0;
    for k in 0..20 {
        let c = c0 + (c1 - c0) * k as f64 / 19.0;
        let y = h - b - (h - t - b) * k as f64 / 20.0;
        out += &format!(
            "<rect x=\"{bx}\" y=\"{:.1}\" width=\"16\" height=\"{:.1}\" fill=\"{}\"/>\n",
            y - (h - t - b) / 20.0,
            (h - t - b) / 20.0 + 0.5,
            colour(c)
        );
    }
    out += &format!("<text x=\"{}\" y=\"{}\">{}</text>\n", bx + 20.0, h - b, sig(c0, 3));
    out += &format!("<text x=\"{}\" y=\"{}\">{}</text>\n", bx + 20.0, t + 10.0, sig(c1, 3));
    out += &format!(
        "<text x=\"{}\" y=\"{}\">{}</text>\n",
        bx - 4.0,
        t - 6.0,
        esc(colour_label)
    );
    out += &format!(
        "<text x=\"{l}\" y=\"{}\" font-size=\"11\">filled: meets the requirements; hollow: does not</text>\n",
        t + 12.0
    );
    out += "</svg>\n";
    out
}
