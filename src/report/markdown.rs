//! Markdown formatting helpers (formatting only, no physics).

/// A Markdown table built row by row.
#[derive(Debug, Clone)]
pub struct Table {
    header: Vec<String>,
    rows: Vec<Vec<String>>,
}

impl Table {
    /// A table with these column headings.
    pub fn new(header: &[&str]) -> Self {
        Table {
            header: header.iter().map(|s| s.to_string()).collect(),
            rows: vec![],
        }
    }

    /// A table with the column headings of `header`, separated by ` | `
    /// (`"z (mm) | ψ (°) | x (µm)"`).
    pub fn columns(header: &str) -> Self {
        Table::new(&header.split(" | ").collect::<Vec<_>>())
    }

    /// Appends a row (cells beyond the header are ignored, missing ones left blank).
    pub fn row(&mut self, cells: Vec<String>) {
        self.rows.push(cells);
    }

    /// The table as GitHub-flavoured Markdown.
    pub fn render(&self) -> String {
        let n = self.header.len();
        // A `|` inside a cell would end it: escape it (GitHub-flavoured Markdown).
        let esc = |c: &str| c.replace('|', "\\|");
        let header: Vec<String> = self.header.iter().map(|h| esc(h)).collect();
        let mut out = format!(
            "| {} |\n|---|{}\n",
            header.join(" | "),
            "---:|".repeat(n.saturating_sub(1))
        );
        for r in &self.rows {
            let cells: Vec<String> = (0..n).map(|i| esc(r.get(i).map_or("", String::as_str))).collect();
            out += &format!("| {} |\n", cells.join(" | "));
        }
        out
    }
}

/// An angle in degrees as degrees-minutes-seconds, rounded to the second, like the paper's
/// tables: `8′59″`, `-1′38″`, `1°02′03″`.
pub fn dms(deg: f64) -> String {
    if !deg.is_finite() {
        return "—".into();
    }
    let total = (deg.abs() * 3600.0).round() as u64;
    let (d, m, s) = (total / 3600, (total / 60) % 60, total % 60);
    let sign = if deg < 0.0 && total > 0 { "-" } else { "" };
    if d > 0 {
        format!("{sign}{d}°{m:02}′{s:02}″")
    } else {
        format!("{sign}{m}′{s:02}″")
    }
}

/// `v` with `digits` significant digits, in plain or scientific notation as fits.
pub fn sig(v: f64, digits: usize) -> String {
    if !v.is_finite() {
        return "—".into();
    }
    if v == 0.0 {
        return "0".into();
    }
    let mag = v.abs().log10().floor() as i32;
    if (-3..6).contains(&mag) {
        let decimals = (digits as i32 - 1 - mag).max(0) as usize;
        format!("{v:.decimals$}")
    } else {
        format!("{v:.prec$e}", prec = digits.saturating_sub(1))
    }
}

/// `v` with `digits` significant digits in conventional notation: plain from 0.01 up to 1e5
/// (`1842.7`, `0.012346`), else a mantissa and a signed two-digit exponent (`8.0123e-03`,
/// `1.2000e+05`); exactly 0 as `0`.
pub fn num(v: f64, digits: usize) -> String {
    if !v.is_finite() {
        return "—".into();
    }
    if v == 0.0 {
        return "0".into();
    }
    let digits = digits.max(1);
    // The exponent after rounding to `digits` (0.99999 → 1.0000e0, not 0.99999 plain).
    let s = format!("{v:.prec$e}", prec = digits - 1);
    let Some((m, e)) = s.split_once('e') else { return s };
    let mag: i32 = e.parse().unwrap_or(0);
    if (-2..5).contains(&mag) {
        let decimals = (digits as i32 - 1 - mag).max(0) as usize;
        return format!("{v:.decimals$}");
    }
    let (sign, e) = e.strip_prefix('-').map_or(("+", e), |e| ("-", e));
    format!("{m}e{sign}{e:0>2}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pipes_in_cells_are_escaped() {
        let mut t = Table::new(&["|a − b|", "x"]);
        t.row(vec!["1".into(), "|2|".into()]);
        let md = t.render();
        assert_eq!(md, "| \\|a − b\\| | x |\n|---|---:|\n| 1 | \\|2\\| |\n");
    }

    #[test]
    fn num_is_conventional_notation() {
        assert_eq!(num(8.012266e-3, 5), "8.0123e-03");
        assert_eq!(num(0.0, 5), "0");
        assert_eq!(num(1842.6566, 5), "1842.7");
        assert_eq!(num(-0.0123456, 5), "-0.012346");
        assert_eq!(num(123456.0, 5), "1.2346e+05");
        assert_eq!(num(-4.5e-13, 5), "-4.5000e-13");
        assert_eq!(num(2.5e120, 4), "2.500e+120");
        assert_eq!(num(-0.99999999997, 5), "-1.0000");
        assert_eq!(num(99999.7, 5), "1.0000e+05");
    }

    #[test]
    fn dms_rounds_to_the_second() {
        // Ruiz et al. (2019) Table 4 style: 8′59″, −1′38″.
        assert_eq!(dms(8.0 / 60.0 + 59.0 / 3600.0), "8′59″");
        assert_eq!(dms(-(1.0 / 60.0 + 38.0 / 3600.0)), "-1′38″");
        assert_eq!(dms(1.0 + 2.0 / 60.0 + 3.4 / 3600.0), "1°02′03″");
    }
}
