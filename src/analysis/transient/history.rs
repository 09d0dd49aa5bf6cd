//! Input shapes of a `transient` case: the time histories of its loads and motions, its damping.

use crate::case::CaseError;
use crate::fem::transient::History;
use serde::Deserialize;

/// A time history g(t) by `type` (times in s).
#[derive(Debug, Clone, PartialEq, Deserialize, schemars::JsonSchema)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum HistorySpec {
    /// 0 before `start` (default 0), 1 from `start` on.
    Step {
        #[serde(default)]
        start: f64,
    },
    /// 0 before `start` (default 0), linear to 1 at `end`, 1 after.
    Ramp {
        #[serde(default)]
        start: f64,
        end: f64,
    },
    /// sin(2π f (t − start) + phase) from `start` (default 0) on; `phase_deg` default 0.
    Sine {
        frequency_hz: f64,
        #[serde(default)]
        phase_deg: f64,
        #[serde(default)]
        start: f64,
    },
    /// Piecewise linear through `[time, value]` points (times strictly increasing).
    Table { points: Vec<[f64; 2]> },
}

impl HistorySpec {
    pub(super) fn history(&self, path: &str) -> Result<History, CaseError> {
        let h = match self {
            HistorySpec::Step { start } => History::Step { start: *start },
            HistorySpec::Ramp { start, end } => History::Ramp { start: *start, end: *end },
            HistorySpec::Sine {
                frequency_hz,
                phase_deg,
                start,
            } => History::Sine {
                frequency_hz: *frequency_hz,
                phase_rad: phase_deg.to_radians(),
                start: *start,
            },
            HistorySpec::Table { points } => History::Table {
                points: points.iter().map(|p| (p[0], p[1])).collect(),
            },
        };
        h.validate().map_err(|e| CaseError::new(path, e.to_string()))?;
        Ok(h)
    }
}

/// Extra stiffness-proportional damping of one case element.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ElementDampingSpec {
    /// Index in `elements` (every segment of a hinge element).
    pub element: usize,
    /// Coefficient, s (C gets beta × the element's stiffness).
    pub beta: f64,
}
