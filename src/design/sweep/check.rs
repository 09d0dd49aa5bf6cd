//! Loading a sweep case and `flexfem check` of a sweep.

use crate::analysis::{self, Case};
use crate::case::sweep::Sweep;
use crate::case::CaseError;
use std::path::Path;

pub use crate::output::with_suffix;

/// Loads and builds the sweep of a case file (errors are bad-case errors, exit 2).
pub fn load(path: &Path) -> Result<Sweep, CaseError> {
    match analysis::load(path)? {
        Case::Sweep(s) => s.build(),
        other => Err(CaseError::value(
            "analysis",
            format!("\"{}\"", other.analysis()),
            "`flexfem sweep` needs a sweep case (\"analysis\": \"sweep\"); run other cases with `flexfem run`",
        )),
    }
}

/// `flexfem check` of a sweep: the axes and design count ([`crate::case::sweep::SweepCase::build`]),
/// then design 0 and, for each varied path, the design with that path at its last value (the
/// others at their first) resolved and validated like a case of their own. Errors name the
/// JSON path in the sweep file: `vary.PATH` for a varied path, `base.PATH` otherwise.
pub fn check(sweep: &Sweep, base_dir: Option<&Path>) -> Result<usize, CaseError> {
    let mut indices = vec![0usize];
    let mut stride = 1usize;
    let mut per_axis = Vec::with_capacity(sweep.axes.len());
    for (_, vals) in sweep.axes.iter().rev() {
        per_axis.push((vals.len() - 1) * stride);
        stride = stride.saturating_mul(vals.len());
    }
    per_axis.reverse();
    indices.extend(per_axis.into_iter().filter(|&i| i != 0));
    for &i in &indices {
        let located = |e: CaseError| -> CaseError {
            let dotted = e.path.replace('[', ".").replace(']', "");
            let varied = sweep
                .axes
                .iter()
                .any(|(p, _)| dotted == *p || dotted.starts_with(&format!("{p}.")));
            let params = sweep
                .params(i)
                .iter()
                .map(|(p, v)| format!("{p} = {v}"))
                .collect::<Vec<_>>()
                .join(", ");
            let path = if varied {
                format!("vary.{dotted}")
            } else if e.path == "." {
                "base".to_string()
            } else {
                format!("base.{}", e.path)
            };
            CaseError::new(path, format!("design {i} ({params}): {}", e.message))
        };
        let design = sweep.design(i)?;
        let parsed = analysis::case_file::parse_resolved(design, base_dir, true).map_err(located)?;
        if let Case::Sweep(_) = parsed.case {
            return Err(CaseError::value(
                "base.analysis",
                "\"sweep\"",
                "a sweep cannot vary another sweep",
            ));
        }
        analysis::check(&parsed.case).map_err(|e| located(parsed.locate(e)))?;
    }
    Ok(indices.len())
}
