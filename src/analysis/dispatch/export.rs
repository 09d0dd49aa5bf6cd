//! `flexfem run --export-matrices`: the reduced stiffness and mass of a case's model and its DOF
//! map (`K.mtx`, `M.mtx`, `dofs.csv`; see [`crate::fem::matrices`]).

use crate::analysis::Case;
use crate::analysis::RunError;
use crate::case::CaseError;
use crate::fem::matrices::reduced_matrices;

/// The error of `--export-matrices` on a case of another kind.
fn not_exportable(case: &Case) -> CaseError {
    crate::analysis::kind_refused(
        case,
        "--export-matrices takes a static, modal, transient or frf case (for the stage: its stage_mesh.json, a static case)",
    )
}

/// Refuses `--export-matrices` on a case of another kind (before anything is solved).
pub fn check_exportable(case: &Case) -> Result<(), CaseError> {
    match case {
        Case::Static(_) | Case::Modal(_) | Case::Transient(_) | Case::Frf(_) => Ok(()),
        _ => Err(not_exportable(case)),
    }
}

/// The matrix files of `case`'s model: K and M on the equations of its supports (rigid links
/// eliminated, node frames kept; load cases' prescribed displacements and a transient case's
/// prescribed motions are not removed: their DOFs stay equations).
pub fn matrix_files(case: &Case) -> Result<crate::analysis::Files, RunError> {
    let model = match case {
        Case::Static(s) => s.model.build_with_hinges(true, false)?.0,
        Case::Modal(m) => m.model.build_model(false)?,
        Case::Frf(f) => f.model.build_model(false)?,
        Case::Transient(t) => t.model.build_model(false)?,
        _ => return Err(not_exportable(case).into()),
    };
    let mats = reduced_matrices(&model).map_err(|e| crate::analysis::AnalysisError::new("model", e.to_string()))?;
    Ok(mats
        .files()
        .map_err(|e| crate::analysis::AnalysisError::new("matrices", e.to_string()))?)
}
