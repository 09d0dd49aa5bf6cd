//! The result rows of a nonlinear path ([`super::nonlinear_path`]): the traced load–displacement
//! curve and the located critical points, and their Markdown section.

use crate::report::markdown::Table;
use serde::Serialize;

/// The traced DOF along the path of one load case.
#[derive(Debug, Clone, Serialize)]
pub struct TraceRow {
    /// The node.
    pub node: usize,
    /// The DOF (`ux` … `rz`, global; rotations: rotation-vector component).
    pub dof: String,
    /// Unit of `value`: `mm` or `deg`.
    pub unit: &'static str,
    /// Load factor λ of each converged point, from 0 (loads = λ × the case's loads).
    pub load_factor: Vec<f64>,
    /// The DOF's value at each point.
    pub value: Vec<f64>,
    /// Whether each point is stable (positive definite tangent stiffness).
    pub stable: Vec<bool>,
}

/// A located change of stability along the path.
#[derive(Debug, Clone, Serialize)]
pub struct CriticalPointRow {
    /// Middle of `bracket`.
    pub load_factor: f64,
    /// Load factors [lo, hi] bracketing the critical point, hi − lo ≤ 1e-4·|λ|.
    pub bracket: [f64; 2],
    /// `limit` (the load has an extremum: snap-through under load control) or `bifurcation`
    /// (another branch crosses the path: buckling).
    pub kind: &'static str,
    /// `lost` or `regained` along the path.
    pub stability: &'static str,
    /// |φ·f|/(‖φ‖‖f‖): work of the critical mode φ on the load f (≈ 0 at a bifurcation).
    pub load_work: f64,
    /// The traced DOF at the critical point (`trace` units), when the load case traces one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub trace_value: Option<f64>,
    /// Critical mode per node [ux, uy, uz, rx, ry, rz], global, largest translation 1
    /// (rotations in degrees per unit translation).
    pub mode: Vec<[f64; 6]>,
}

/// The Markdown section of a load case's critical points and traced path (empty without).
pub fn markdown(name: &str, critical_points: &[CriticalPointRow], trace: Option<&TraceRow>) -> String {
    let mut md = String::new();
    if !critical_points.is_empty() {
        md += "Critical points along the path (load factor bracketed to 1e-4):\n\n";
        let mut t = Table::new(&["load factor", "bracket", "kind", "stability", "mode work on load"]);
        for p in critical_points {
            t.row(vec![
                format!("{:.6}", p.load_factor),
                format!("[{:.6}, {:.6}]", p.bracket[0], p.bracket[1]),
                p.kind.to_string(),
                p.stability.to_string(),
                format!("{:.2e}", p.load_work),
            ]);
        }
        md += &t.render();
        md += "\n";
    }
    if let Some(t) = trace {
        let lo = t.load_factor.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = t.load_factor.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        md += &format!(
            "Traced path: {} points, {} of node {} from {:.6} to {:.6} {}, load factor between {lo:.6} and {hi:.6} (`{}_path.csv`, `{}_path.svg` with `--out`).\n\n",
            t.value.len(),
            t.dof,
            t.node,
            t.value.first().copied().unwrap_or(0.0),
            t.value.last().copied().unwrap_or(0.0),
            t.unit,
            crate::report::vtk::file_stem(name),
            crate::report::vtk::file_stem(name)
        );
    }
    md
}
