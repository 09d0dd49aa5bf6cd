//! The `superelement` element of mesh cases: a reduced superelement written by a
//! `craig_bampton` analysis (R. R. Craig, M. C. C. Bampton, "Coupling of substructures for
//! dynamic analyses", AIAA Journal 6 (1968) 1313–1319) attached to host nodes.
//!
//! ```json
//! {"type": "superelement", "file": "outer_half/result.json", "nodes": [10, 20],
//!  "placement": {"translation": [0, 0, 0], "axis": [0, 0, 1], "angle": 0}}
//! ```
//!
//! The file is the `result.json` of a `craig_bampton` run (`flexfem run CASE --out DIR`),
//! resolved against the case file's folder like a `mesh` file. Its stiffness (N/mm, N,
//! N·mm/rad; modal rows 1/s²) and mass (tonne, tonne·mm, tonne·mm²; modal rows mass-normalised)
//! act on the six DOFs `ux uy uz rx ry rz` (mm, rad) of each of its `interface_nodes`, in the
//! global axes of the model it was reduced from (or the node frames it records), followed by its
//! modal coordinates. `nodes` names one host node per interface node, in the file's order; after
//! `placement` (x_host = R·x + translation, R the rotation by `angle` degrees about `axis`)
//! each must coincide with its interface node to 1e-6 of the host model's size, else the case
//! is refused. The matrices are rotated into host axes and attached with
//! [`crate::fem::superelement::attach`] (its modal coordinates ride on auxiliary modal nodes
//! after the case's own nodes; the result notes list them). Every interface node must carry all
//! six DOFs in the file (none supported in the reduced model).

use super::joint::{model_size, COINCIDENT};
use super::lookup::{norm, unit_direction, Ctx};
use super::shapes::{ElementSpec, MeshSpec, PlacementSpec};
pub use super::superelement_file::{read, FileDof, FileNode, SuperelementFile};
use crate::case::error::CaseError;
use crate::fem::{self, Dof};
use nalgebra::{DMatrix, Matrix3, Vector3};
use std::path::Path;
use std::sync::Arc;

/// Reads the file of every `superelement` element of `spec` (paths relative to `base`).
pub fn load_files(spec: &mut MeshSpec, base: Option<&Path>) -> Result<(), CaseError> {
    for (i, e) in spec.elements.iter_mut().enumerate() {
        if let ElementSpec::Superelement { file, loaded, .. } = e {
            *loaded = Some(Arc::new(read(&format!("elements[{i}].file"), file, base)?));
        }
    }
    Ok(())
}

/// Builds a `superelement` element at JSON path `p` (a file not loaded with the case is read
/// relative to the working directory).
pub(super) fn superelement_element(
    cx: &mut Ctx,
    p: &str,
    file: &str,
    nodes: &[usize],
    placement: Option<&PlacementSpec>,
    loaded: Option<&Arc<SuperelementFile>>,
) -> Result<(), CaseError> {
    let data = match loaded {
        Some(d) => d.clone(),
        None => Arc::new(read(&format!("{p}.file"), file, None)?),
    };
    let f = &*data;
    let at_file = format!("{p}.file");
    let bad = |why: String| CaseError::value(&at_file, format!("\"{file}\""), why);
    let ni = f.interface_nodes.len();
    if nodes.len() != ni {
        let ids: Vec<usize> = f.interface_nodes.iter().map(|n| n.node).collect();
        return Err(CaseError::value(
            format!("{p}.nodes"),
            format!("{nodes:?}"),
            format!("the superelement has {ni} interface nodes (its nodes {ids:?}): give {ni} host node indices, in that order"),
        ));
    }
    let mut host = Vec::with_capacity(ni);
    for (j, &n) in nodes.iter().enumerate() {
        let n = cx.node(format!("{p}.nodes[{j}]"), n)?;
        if host.contains(&n) {
            return Err(CaseError::value(format!("{p}.nodes[{j}]"), n, "is named twice"));
        }
        host.push(n);
    }
    let order = boundary_rows(f).map_err(bad)?;
    let n = f.modes.saturating_add(6 * ni);
    for (name, a) in [("k", &f.k), ("m", &f.m)] {
        if a.len() != n || a.iter().any(|r| r.len() != n) || a.iter().flatten().any(|v| !v.is_finite()) {
            return Err(bad(format!(
                "`{name}` must be {n}×{n} finite numbers (6 DOFs × {ni} interface nodes + {} modes)",
                f.modes
            )));
        }
    }
    let (r, t) = rotation(p, placement)?;
    let tol = COINCIDENT * model_size(&cx.spec.nodes);
    for (j, (fnode, &h)) in f.interface_nodes.iter().zip(&host).enumerate() {
        let x = r * Vector3::from(fnode.x) + t;
        let xh = Vector3::from(cx.spec.nodes[h]);
        let d = (x - xh).norm();
        if d.is_nan() || d > tol {
            return Err(CaseError::value(
                format!("{p}.nodes[{j}]"),
                h,
                format!(
                    "host node {h} at {:?} mm is {d:.6e} mm from the superelement's interface node {} at {:?} (placed: [{:.6}, {:.6}, {:.6}]); they must coincide within {tol:.3e} mm ({COINCIDENT} of the model size): name the matching host node or give `placement`",
                    cx.spec.nodes[h], fnode.node, fnode.x, x[0], x[1], x[2]
                ),
            ));
        }
    }
    // T maps [host DOFs of the interface nodes (global axes); η] to the file's rows.
    let mut tm = DMatrix::zeros(n, n);
    for (j, fnode) in f.interface_nodes.iter().enumerate() {
        let frame = match fnode.frame {
            Some(rows) => match super::frames::local(&at_file, Some(rows), None) {
                Ok(_) => Matrix3::from_fn(|a, b| rows[a][b]),
                Err(e) => return Err(bad(format!("interface node {}: {}", fnode.node, e.message))),
            },
            None => Matrix3::identity(),
        };
        // u_file = F·Rᵀ·u_host for both the translations and the rotations.
        let a = frame * r.transpose();
        for blk in [0, 3] {
            for x in 0..3 {
                for y in 0..3 {
                    tm[(order[6 * j + blk + x], 6 * j + blk + y)] = a[(x, y)];
                }
            }
        }
    }
    for q in 0..f.modes {
        tm[(6 * ni + q, 6 * ni + q)] = 1.0;
    }
    let dense = |a: &Vec<Vec<f64>>| DMatrix::from_fn(n, n, |x, y| a[x][y]);
    let (k, m) = (tm.transpose() * dense(&f.k) * &tm, tm.transpose() * dense(&f.m) * &tm);
    let sym = |a: DMatrix<f64>| (&a + a.transpose()) * 0.5;
    fem::superelement::attach(&mut cx.model, format!("{p} (\"{file}\")"), &host, &sym(k), &sym(m))
        .map(|_| ())
        .map_err(|e| CaseError::new(p, e.to_string()))
}

/// Row of each (interface node j, DOF d) at index 6j + d: every interface node must have its six
/// DOFs, each once, and the file's boundary must list nothing else.
fn boundary_rows(f: &SuperelementFile) -> Result<Vec<usize>, String> {
    let ni = f.interface_nodes.len();
    if ni == 0 {
        return Err("it lists no interface nodes".into());
    }
    let mut row = vec![usize::MAX; 6 * ni];
    for (i, b) in f.boundary.iter().enumerate() {
        let j = f.interface_nodes.iter().position(|n| n.node == b.node).ok_or_else(|| {
            format!(
                "boundary[{i}] is on node {}, which is not among its interface nodes",
                b.node
            )
        })?;
        let d = Dof::parse(&b.dof).ok_or_else(|| format!("boundary[{i}].dof \"{}\" is not ux … rz", b.dof))?;
        let slot = &mut row[6 * j + d.index()];
        if *slot != usize::MAX {
            return Err(format!("boundary[{i}] (node {} {}) is listed twice", b.node, b.dof));
        }
        *slot = i;
    }
    if let Some(s) = row.iter().position(|&r| r == usize::MAX) {
        let node = f.interface_nodes[s / 6].node;
        return Err(format!(
            "interface node {node} has no {} boundary DOF (supported in the reduced model?); a superelement attaches by all six DOFs of each interface node",
            Dof::ALL[s % 6]
        ));
    }
    Ok(row)
}

/// R and translation of `placement` (identity and zero without one).
fn rotation(p: &str, placement: Option<&PlacementSpec>) -> Result<(Matrix3<f64>, Vector3<f64>), CaseError> {
    let Some(pl) = placement else {
        return Ok((Matrix3::identity(), Vector3::zeros()));
    };
    let at = format!("{p}.placement");
    for (k, v) in pl.translation.iter().enumerate() {
        crate::case::error::check::finite(format_args!("{at}.translation[{k}]"), *v)?;
    }
    crate::case::error::check::finite(format_args!("{at}.angle"), pl.angle)?;
    let axis = match pl.axis {
        Some(a) if norm(a) > 0.0 => unit_direction(format!("{at}.axis"), a)?,
        Some(a) => {
            return Err(CaseError::value(
                format!("{at}.axis"),
                format!("{a:?}"),
                "must be a non-zero direction",
            ));
        }
        None => [0.0, 0.0, 1.0],
    };
    let r = nalgebra::Rotation3::from_axis_angle(
        &nalgebra::Unit::new_normalize(Vector3::from(axis)),
        pl.angle.to_radians(),
    );
    Ok((*r.matrix(), Vector3::from(pl.translation)))
}

/// Refuses four- and nine-node shells in an analysis that cannot take them (`what` names it),
/// at the first one's JSON path.
pub fn refuse_shells_in(spec: &MeshSpec, what: &str) -> Result<(), CaseError> {
    let kind = |e: &ElementSpec| match e {
        ElementSpec::Shell4 { .. } => Some("shell4"),
        ElementSpec::Shell9 { .. } => Some("shell9"),
        _ => None,
    };
    match spec.elements.iter().enumerate().find_map(|(i, e)| kind(e).map(|k| (i, k))) {
        Some((i, k)) => Err(CaseError::new(
            format!("elements[{i}]"),
            format!("a shell element ({k}) is not available in {what}, which handles beams, hinges, joints, springs, masses and rigid links; use a linear analysis, or model the part with beams"),
        )),
        None => Ok(()),
    }
}

/// Refuses a `superelement` element of `spec` in an analysis it cannot take (`what`: e.g.
/// "geometrically nonlinear analyses"): its matrices are linear and carry no geometric
/// stiffness. The error names the element's JSON path.
pub fn refuse_in(spec: &MeshSpec, what: &str) -> Result<(), CaseError> {
    match spec.elements.iter().position(|e| matches!(e, ElementSpec::Superelement { .. })) {
        Some(i) => Err(CaseError::new(
            format!("elements[{i}]"),
            format!("a superelement (reduced linear stiffness and mass, no geometric stiffness) is not available in {what}; use a linear static, modal, transient or frf analysis, or model the part with elements"),
        )),
        None => Ok(()),
    }
}
