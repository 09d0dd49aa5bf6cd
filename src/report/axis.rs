//! Plot axes: round ("nice") tick values and their labels, linear or logarithmic (formatting
//! only; used by every plot of [`super::svg`]).
//!
//! Linear ticks follow the loose labelling of Heckbert, "Nice numbers for graph labels",
//! in A. S. Glassner (ed.), *Graphics Gems*, Academic Press, 1990, pp. 61–63: the step is 1, 2
//! or 5 × 10ᵏ and the axis runs from the tick at or below the data to the tick at or above it.
//! Logarithmic axes are labelled in decades (ticks at the powers of ten).

/// How an axis maps values.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scale {
    /// Logarithmic when every value is positive and they span more than two decades, else linear.
    Auto,
    /// Linear with 1–2–5 steps.
    Linear,
    /// Logarithmic in decades (non-positive values are left out).
    Log,
    /// Linear in degrees with steps of 90° (180° or 360° over more than two turns; phase angles).
    Degrees,
}

/// An axis: its drawn range (in `log₁₀` of the value on a log axis) and its ticks.
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    /// Logarithmic (positions are `log₁₀` of the values).
    pub log: bool,
    /// Drawn range, in positions (values, or their `log₁₀`).
    pub range: [f64; 2],
    /// Tick values (not positions), ascending.
    pub ticks: Vec<f64>,
    /// Tick step (of the values; of the exponents on a log axis).
    pub step: f64,
}

impl Axis {
    /// The axis over `values` (non-finite ones ignored) with about `target` ticks.
    pub fn new(values: &[f64], scale: Scale, target: usize) -> Axis {
        let fin = values.iter().copied().filter(|v| v.is_finite());
        let pos = fin.clone().filter(|&v| v > 0.0);
        let (lo, hi) = min_max(fin.clone());
        let (plo, phi) = min_max(pos.clone());
        let all_positive = fin.clone().all(|v| v > 0.0) && plo.is_finite();
        let log = match scale {
            Scale::Log => plo.is_finite(),
            Scale::Auto => all_positive && phi / plo > 100.0,
            Scale::Linear | Scale::Degrees => false,
        };
        if log {
            return log_axis(plo, phi);
        }
        let (lo, hi) = if lo.is_finite() { (lo, hi) } else { (0.0, 1.0) };
        if scale == Scale::Degrees {
            return degree_axis(lo, hi);
        }
        let (ticks, step) = nice_ticks(lo, hi, target);
        Axis {
            log: false,
            range: [ticks[0], ticks[ticks.len() - 1]],
            ticks,
            step,
        }
    }

    /// Position of a value on the axis (`log₁₀` on a log axis; `None` for a non-positive value there).
    pub fn pos(&self, v: f64) -> Option<f64> {
        match (self.log, v.is_finite()) {
            (_, false) => None,
            (true, _) if v <= 0.0 => None,
            (true, _) => Some(v.log10()),
            (false, _) => Some(v),
        }
    }

    /// The label of tick `v`.
    pub fn label(&self, v: f64) -> String {
        if self.log {
            decade_label(v.log10().round() as i32)
        } else {
            tick_label(v, self.step)
        }
    }

    /// Minor grid values between the ticks of a log axis (2…9 × 10ᵏ, when the axis spans at
    /// most six decades); empty on a linear axis.
    pub fn minor(&self) -> Vec<f64> {
        if !self.log || self.range[1] - self.range[0] > 6.0 {
            return Vec::new();
        }
        let (k0, k1) = (self.range[0].round() as i32, self.range[1].round() as i32);
        (k0..k1)
            .flat_map(|k| (2..10).map(move |m| m as f64 * 10f64.powi(k)))
            .collect()
    }
}

fn min_max(it: impl Iterator<Item = f64>) -> (f64, f64) {
    it.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)))
}

/// Heckbert's nice number near `x > 0`: 1, 2, 5 or 10 × 10ᵏ, rounded to the nearest or taken
/// at or above `x` (`round = false`).
pub fn nice_number(x: f64, round: bool) -> f64 {
    let e = x.log10().floor();
    let f = x / 10f64.powf(e);
    let nf = if round {
        match f {
            f if f < 1.5 => 1.0,
            f if f < 3.0 => 2.0,
            f if f < 7.0 => 5.0,
            _ => 10.0,
        }
    } else {
        match f {
            f if f <= 1.0 => 1.0,
            f if f <= 2.0 => 2.0,
            f if f <= 5.0 => 5.0,
            _ => 10.0,
        }
    };
    nf * 10f64.powf(e)
}

/// Loose nice ticks over `[lo, hi]`, about `target` of them: the values `i · step` (step 1, 2
/// or 5 × 10ᵏ) from the one at or below `lo` to the one at or above `hi`; the step.
pub fn nice_ticks(lo: f64, hi: f64, target: usize) -> (Vec<f64>, f64) {
    let (lo, hi) = if hi - lo > 1e-12 * hi.abs().max(lo.abs()).max(1e-300) {
        (lo, hi)
    } else if lo == 0.0 {
        (0.0, 1.0)
    } else {
        // A constant series: a span of one step around it.
        let d = nice_number(lo.abs() * 0.1, true);
        (lo - d, hi + d)
    };
    let range = nice_number(hi - lo, false);
    let step = nice_number(range / (target.max(2) - 1) as f64, true);
    let (i0, i1) = ((lo / step).floor() as i64, (hi / step).ceil() as i64);
    let ticks = (i0..=i1).map(|i| round_to_step(i as f64 * step, step)).collect();
    (ticks, step)
}

/// `v` with the roundoff of `i · step` removed (so 3 × 0.1 is 0.3, not 0.30000000000000004).
fn round_to_step(v: f64, step: f64) -> f64 {
    let decimals = (-step.log10().floor()).max(0.0) as i32 + 1;
    if decimals > 15 {
        return v;
    }
    let s = 10f64.powi(decimals);
    (v * s).round() / s
}

fn log_axis(lo: f64, hi: f64) -> Axis {
    let k0 = lo.log10().floor();
    let k1 = hi.log10().ceil().max(k0 + 1.0);
    // At most ~10 labelled decades: a step of several decades when the data spans more.
    let step = ((k1 - k0) / 10.0).ceil().max(1.0);
    let k0 = (k0 / step).floor() * step;
    let k1 = (k1 / step).ceil() * step;
    let n = ((k1 - k0) / step).round() as i64;
    let ticks = (0..=n).map(|i| 10f64.powi((k0 + i as f64 * step) as i32)).collect();
    Axis {
        log: true,
        range: [k0, k1],
        ticks,
        step,
    }
}

fn degree_axis(lo: f64, hi: f64) -> Axis {
    let span = (hi - lo).max(1.0);
    let step = [90.0, 180.0, 360.0]
        .into_iter()
        .find(|s| span / s <= 8.0)
        .unwrap_or(720.0);
    let (i0, i1) = ((lo / step).floor() as i64, (hi / step).ceil() as i64);
    let i1 = i1.max(i0 + 1);
    let ticks: Vec<f64> = (i0..=i1).map(|i| i as f64 * step).collect();
    Axis {
        log: false,
        range: [ticks[0], ticks[ticks.len() - 1]],
        ticks,
        step,
    }
}

/// A linear tick's label: as many decimals as the step needs; exponent notation (`2e-5`) for
/// very small or large values.
pub fn tick_label(v: f64, step: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    let k = step.log10().floor() as i32;
    let big = v.abs().log10().floor() as i32;
    if k < -4 || big >= 6 {
        let digits = (big - k).max(0) as usize;
        format!("{v:.digits$e}")
    } else {
        let decimals = (-k).max(0) as usize;
        format!("{v:.decimals$}")
    }
}

/// A decade's label: `0.01` … `1000` written out, other powers as `10ᵏ` with a superscript.
pub fn decade_label(k: i32) -> String {
    if (-2..=3).contains(&k) {
        return tick_label(10f64.powi(k), 10f64.powi(k));
    }
    const SUP: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let mut s = String::from("10");
    if k < 0 {
        s.push('⁻');
    }
    for c in k.unsigned_abs().to_string().chars() {
        s.push(SUP[c.to_digit(10).unwrap_or(0) as usize]);
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    // Heckbert (1990)'s loose labelling: the axis covers the data with 1–2–5 steps.
    #[test]
    fn nice_ticks_of_the_plots_in_the_issue() {
        let (t, s) = nice_ticks(-672.0, 104.0, 5);
        assert_eq!(s, 200.0);
        assert_eq!(t, vec![-800.0, -600.0, -400.0, -200.0, 0.0, 200.0]);
        let (t, s) = nice_ticks(0.0, 1.05, 6);
        assert_eq!(s, 0.5);
        assert_eq!(t, vec![0.0, 0.5, 1.0, 1.5]);
        let (t, s) = nice_ticks(-0.135, 1.05, 8);
        assert_eq!(s, 0.2);
        assert_eq!(t, vec![-0.2, 0.0, 0.2, 0.4, 0.6, 0.8, 1.0, 1.2]);
        let labels: Vec<String> = t.iter().map(|&v| tick_label(v, s)).collect();
        assert_eq!(labels, ["-0.2", "0", "0.2", "0.4", "0.6", "0.8", "1.0", "1.2"]);
    }

    #[test]
    fn small_and_large_ticks_are_labelled_in_exponent_notation() {
        let (t, s) = nice_ticks(1.3e-5, 7.9e-5, 6);
        assert!((s / 2e-5 - 1.0).abs() < 1e-12, "{s}");
        let labels: Vec<String> = t.iter().map(|&v| tick_label(v, s)).collect();
        assert_eq!(labels, ["0", "2e-5", "4e-5", "6e-5", "8e-5"]);
        assert_eq!(tick_label(2.5e6, 5e5), "2.5e6");
    }

    #[test]
    fn log_axis_in_decades() {
        let a = Axis::new(&[3.0, 20.0, 4000.0], Scale::Auto, 6);
        assert!(a.log);
        assert_eq!(a.ticks, vec![1.0, 10.0, 100.0, 1000.0, 10000.0]);
        assert_eq!(decade_label(-5), "10⁻⁵");
        assert_eq!(decade_label(1), "10");
        // Two decades or less, or a non-positive value: linear.
        assert!(!Axis::new(&[3.0, 200.0], Scale::Auto, 6).log);
        assert!(!Axis::new(&[0.0, 3.0, 4000.0], Scale::Auto, 6).log);
    }

    #[test]
    fn phase_axis_in_right_angles() {
        let a = Axis::new(&[-178.0, 3.0], Scale::Degrees, 6);
        assert_eq!(a.ticks, vec![-180.0, -90.0, 0.0, 90.0]);
    }
}
