//! Time histories g(t) (dimensionless factors) of transient loads and prescribed motions: step,
//! ramp, sine and tabulated (piecewise linear). A load or motion is its spatial value times g(t).

use super::error::FemError;

/// A scalar time function (times in s).
#[derive(Debug, Clone, PartialEq)]
pub enum History {
    /// 0 before `start`, 1 from `start` on (right-continuous: g(start) = 1).
    Step { start: f64 },
    /// 0 before `start`, rising linearly to 1 at `end`, 1 after.
    Ramp { start: f64, end: f64 },
    /// sin(2π f (t − start) + phase) from `start` on, 0 before.
    Sine {
        frequency_hz: f64,
        phase_rad: f64,
        start: f64,
    },
    /// Piecewise linear through (time, value) points with increasing times; the first value
    /// before the first time, the last after the last.
    Table { points: Vec<(f64, f64)> },
}

impl History {
    /// Checks the parameters: finite, ramp end after start, table times strictly increasing.
    pub fn validate(&self) -> Result<(), FemError> {
        let bad = |s: String| Err(FemError::BadInput(s));
        match self {
            History::Step { start } if !start.is_finite() => bad(format!("step start {start} is not finite")),
            History::Ramp { start, end } if !(start.is_finite() && end.is_finite() && end > start) => bad(format!(
                "ramp from {start} s to {end} s: the end must come after the start"
            )),
            History::Sine {
                frequency_hz,
                phase_rad,
                start,
            } if !(frequency_hz.is_finite() && *frequency_hz > 0.0 && phase_rad.is_finite() && start.is_finite()) => {
                bad(format!(
                    "sine of {frequency_hz} Hz: the frequency must be > 0 and every value finite"
                ))
            }
            History::Table { points } => {
                if points.is_empty() {
                    return bad("a table history needs at least one point".into());
                }
                if points.iter().any(|(t, v)| !(t.is_finite() && v.is_finite())) {
                    return bad("table history: every time and value must be finite".into());
                }
                if points.windows(2).any(|w| w[1].0 <= w[0].0) {
                    return bad("table history: times must be strictly increasing".into());
                }
                Ok(())
            }
            _ => Ok(()),
        }
    }

    /// g(t).
    pub fn value(&self, t: f64) -> f64 {
        match self {
            History::Step { start } => f64::from(u8::from(t >= *start)),
            History::Ramp { start, end } => ((t - start) / (end - start)).clamp(0.0, 1.0),
            History::Sine {
                frequency_hz,
                phase_rad,
                start,
            } => {
                if t < *start {
                    0.0
                } else {
                    (2.0 * std::f64::consts::PI * frequency_hz * (t - start) + phase_rad).sin()
                }
            }
            History::Table { points } => {
                let i = points.partition_point(|p| p.0 <= t);
                if i == 0 {
                    return points[0].1;
                }
                if i == points.len() {
                    return points[i - 1].1;
                }
                let ((t0, v0), (t1, v1)) = (points[i - 1], points[i]);
                v0 + (v1 - v0) * (t - t0) / (t1 - t0)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Values at break points and between them (closed forms of the definitions above).
    #[test]
    fn values() {
        assert_eq!(History::Step { start: 0.1 }.value(0.0999), 0.0);
        assert_eq!(History::Step { start: 0.1 }.value(0.1), 1.0);
        let r = History::Ramp { start: 1.0, end: 3.0 };
        assert_eq!((r.value(0.0), r.value(2.0), r.value(9.0)), (0.0, 0.5, 1.0));
        let s = History::Sine {
            frequency_hz: 2.0,
            phase_rad: 0.0,
            start: 0.0,
        };
        assert!((s.value(0.125) - 1.0).abs() < 1e-15);
        let t = History::Table {
            points: vec![(0.0, 0.0), (1.0, 2.0), (2.0, 0.0)],
        };
        assert_eq!(
            (t.value(-1.0), t.value(0.5), t.value(1.5), t.value(5.0)),
            (0.0, 1.0, 1.0, 0.0)
        );
        assert!(History::Table {
            points: vec![(0.0, 0.0), (0.0, 1.0)]
        }
        .validate()
        .is_err());
    }
}
