//! Validation of `"metrics"` against the model (paths `metrics[i].…`): everything a metric
//! needs to be evaluated is refused here, before any solve.

use super::{MetricKind, MetricRequest};
use crate::case::error::CaseError;
use crate::case::mesh::shapes::{ElementSpec, MeshSpec};
use crate::fem::Dof;

/// Validates `"metrics"`: unique names (given or default), the fields each kind needs (and no
/// others), nodes, DOFs, load cases and hinge elements that exist, modes ≥ 1, a load case that
/// drives the DOF of a `stroke_at_allowable` and leaves the DOF of a `parasitic` free, and a
/// model that has a linear buckling analysis for `buckling_margin`.
/// Every kind is evaluated in linear and nonlinear runs alike (`_nonlinear`).
pub fn check_metrics(reqs: &[MetricRequest], model: &MeshSpec, _nonlinear: bool) -> Result<(), CaseError> {
    (0..reqs.len()).try_for_each(|i| check_one(reqs, i, model))
}

/// A `fatigue_stroke` metric needs the case's `"fatigue"` block (`fatigue`: given) and a
/// linear run (`nonlinear`: the run is geometrically nonlinear).
pub fn check_fatigue_metrics(reqs: &[MetricRequest], fatigue: bool, nonlinear: bool) -> Result<(), CaseError> {
    let Some(i) = reqs.iter().position(|m| m.kind == MetricKind::FatigueStroke) else {
        return Ok(());
    };
    if !fatigue {
        return Err(CaseError::value(
            format!("metrics[{i}].kind"),
            "\"fatigue_stroke\"",
            "needs the case's \"fatigue\" block {\"cycles\", \"load_ratio\", \"method\"}",
        ));
    }
    if nonlinear {
        return Err(CaseError::value(
            format!("metrics[{i}].kind"),
            "\"fatigue_stroke\"",
            "is evaluated in linear runs only (the load factor to the fatigue limit scales the stress); nonlinear runs report each hinge's fatigue at the solved load case: drop the metric or \"nonlinear\"",
        ));
    }
    Ok(())
}

fn check_one(reqs: &[MetricRequest], i: usize, model: &MeshSpec) -> Result<(), CaseError> {
    let m = &reqs[i];
    let at = |f: &str| format!("metrics[{i}].{f}");
    let key = m.key();
    if let Some(j) = reqs[..i].iter().position(|o| o.key() == key) {
        return Err(CaseError::value(
            at("name"),
            format!("\"{key}\""),
            format!("metrics[{j}] has the same name; metric names must be unique (give \"name\")"),
        ));
    }
    let given = [
        m.node.is_some(),
        m.dof.is_some(),
        m.load_case.is_some(),
        m.element.is_some(),
        m.mode.is_some(),
    ];
    for (k, field) in ["node", "dof", "load_case", "element", "mode"].into_iter().enumerate() {
        let kind = m.kind.name();
        match (m.kind.fields()[k], given[k]) {
            (true, false) => return Err(CaseError::new(at(field), format!("is required by kind \"{kind}\""))),
            (false, true) => return Err(CaseError::new(at(field), format!("is not used by kind \"{kind}\""))),
            _ => {}
        }
    }
    if let Some(n) = m.node {
        if n >= model.nodes.len() {
            let rule = format!("must be a node index below {}", model.nodes.len());
            return Err(CaseError::value(at("node"), n, rule));
        }
    }
    if let Some(d) = &m.dof {
        if Dof::parse(d).is_none() {
            return Err(CaseError::value(
                at("dof"),
                format!("\"{d}\""),
                "must be one of ux, uy, uz, rx, ry, rz",
            ));
        }
    }
    if let Some(lc) = &m.load_case {
        if !model.load_cases.iter().any(|c| &c.name == lc) {
            let names: Vec<&str> = model.load_cases.iter().map(|c| c.name.as_str()).collect();
            let rule = format!("must name a load case: {}", names.join(", "));
            return Err(CaseError::value(at("load_case"), format!("\"{lc}\""), rule));
        }
    }
    if let Some(mode) = m.mode {
        let most = 6 * model.nodes.len();
        if !(1..=most).contains(&mode) {
            let rule = format!("must be a mode number from 1 (the lowest) to {most} (6 per node)");
            return Err(CaseError::value(at("mode"), mode, rule));
        }
        crate::case::limits::check_modal(mode, model.nodes.len()).map_err(|e| CaseError {
            path: at("mode"),
            message: e.message,
        })?;
    }
    let under = |e: CaseError| e.under(&format!("metrics[{i}]"));
    match m.kind {
        MetricKind::StrokeAtAllowable | MetricKind::FatigueStroke => check_stroke(m, model).map_err(under)?,
        MetricKind::Parasitic => check_parasitic(m, model).map_err(under)?,
        MetricKind::BucklingMargin => check_buckling(model).map_err(under)?,
        _ => {}
    }
    if let Some(e) = m.element {
        if !matches!(model.elements.get(e), Some(ElementSpec::Hinge { .. })) {
            return Err(CaseError::value(
                at("element"),
                e,
                "must be the index of a hinge element in elements",
            ));
        }
    }
    Ok(())
}

/// How the load case named by `m` acts on `m.node` along `m.dof`: (prescribes it to a
/// non-zero value in global axes, applies a non-zero global force component along it,
/// prescribes or loads it at all in any frame).
fn drive(m: &MetricRequest, model: &MeshSpec) -> Option<(bool, bool, bool)> {
    let (node, dof, name) = (m.node?, m.dof()?, m.load_case.as_deref()?);
    let lc = model.load_cases.iter().find(|c| c.name == name)?;
    let prescribed = lc
        .displacements
        .iter()
        .any(|d| d.node == node && d.dof.dof() == dof && d.frame.is_none() && d.axis.is_none() && d.value != 0.0);
    let forced = lc
        .forces
        .iter()
        .any(|f| f.node == node && f.frame.is_none() && f.axis.is_none() && f.f[dof.index()] != 0.0);
    // In a frame (or along an axis) any component may act along the global DOF.
    let touched = lc
        .displacements
        .iter()
        .any(|d| d.node == node && (d.frame.is_some() || d.axis.is_some() || d.dof.dof() == dof))
        || lc
            .forces
            .iter()
            .any(|f| f.node == node && (f.frame.is_some() || f.axis.is_some() || f.f[dof.index()] != 0.0));
    Some((prescribed, forced, touched))
}

/// A `stroke_at_allowable` request: a load case that drives `node` along `dof` (a prescribed
/// displacement or a force component, both in global axes).
fn check_stroke(m: &MetricRequest, model: &MeshSpec) -> Result<(), CaseError> {
    let Some((prescribed, forced, _)) = drive(m, model) else {
        return Ok(());
    };
    if prescribed || forced {
        return Ok(());
    }
    let (node, dof) = (m.node.unwrap_or(0), m.dof.as_deref().unwrap_or(""));
    Err(CaseError::value(
        "load_case",
        format!("\"{}\"", m.load_case.as_deref().unwrap_or("")),
        format!("must prescribe a non-zero {dof} of node {node} or apply a force (moment) along it there, in global axes (no frame or axis)"),
    ))
}

/// A `parasitic` request: the load case must leave `node`'s `dof` free (neither prescribe nor
/// load it: that is the driven motion, not the parasitic one) and a support must not fix it.
fn check_parasitic(m: &MetricRequest, model: &MeshSpec) -> Result<(), CaseError> {
    let (Some(node), Some(dof)) = (m.node, m.dof()) else {
        return Ok(());
    };
    let dof_name = m.dof.as_deref().unwrap_or("");
    if let Some((_, _, true)) = drive(m, model) {
        return Err(CaseError::value(
            "dof",
            format!("\"{dof_name}\""),
            format!(
                "is driven at node {node} by load case \"{}\" (prescribed or loaded there): a parasitic motion is one the load case does not drive; name another DOF, or use kind \"displacement\"",
                m.load_case.as_deref().unwrap_or("")
            ),
        ));
    }
    let fixed = model
        .supports
        .iter()
        .any(|s| s.node == node && s.frame.is_none() && s.axis.is_none() && s.fix.iter().any(|d| d.dof() == dof));
    if fixed {
        return Err(CaseError::value(
            "dof",
            format!("\"{dof_name}\""),
            format!("is fixed at node {node} by a support: its motion is zero; name a free DOF"),
        ));
    }
    Ok(())
}

/// A `buckling_margin` request: the model must have a linear buckling analysis (no shells, no
/// superelements: they carry no geometric stiffness).
fn check_buckling(model: &MeshSpec) -> Result<(), CaseError> {
    crate::case::mesh::superelement::refuse_in(model, "linear buckling (kind \"buckling_margin\")")
        .map_err(|e| CaseError::new("kind", format!("\"buckling_margin\": {}: {}", e.path, e.message)))?;
    if let Some(i) = model
        .elements
        .iter()
        .position(|e| matches!(e, ElementSpec::Shell4 { .. } | ElementSpec::Shell9 { .. }))
    {
        let kind = if matches!(model.elements[i], ElementSpec::Shell9 { .. }) {
            "shell9"
        } else {
            "shell4"
        };
        return Err(CaseError::value(
            "kind",
            "\"buckling_margin\"",
            format!("needs linear buckling, which has the geometric stiffness of beams, hinges, springs and rigid links only; elements[{i}] is a shell ({kind})"),
        ));
    }
    Ok(())
}
