//! `flexfem run --export-matrices`: the reduced stiffness and mass of a case's model and its DOF
//! map (`K.mtx`, `M.mtx`, `dofs.csv`; see [`crate::fem::matrices`]); the same matrices and an
//! `frf` case's state-space model as values, for callers that take them as arrays (the Python
//! package).

use crate::analysis::Case;
use crate::analysis::RunError;
use crate::case::CaseError;
use crate::fem::matrices::{reduced_matrices, ReducedMatrices};
use crate::fem::state_space::StateSpace;

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

/// The reduced K and M of `case`'s model with its DOF map: on the equations of its supports
/// (rigid links eliminated, node frames kept; load cases' prescribed displacements and a
/// transient case's prescribed motions are not removed: their DOFs stay equations).
pub fn matrices(case: &Case) -> Result<ReducedMatrices, RunError> {
    let model = match case {
        Case::Static(s) => s.model.build_with_hinges(true, false)?.0,
        Case::Modal(m) => m.model.build_model(false)?,
        Case::Frf(f) => f.model.build_model(false)?,
        Case::Transient(t) => t.model.build_model(false)?,
        _ => return Err(not_exportable(case).into()),
    };
    reduced_matrices(&model).map_err(|e| crate::analysis::AnalysisError::new("model", e.to_string()).into())
}

/// The matrix files of `case`'s model ([`matrices`]).
pub fn matrix_files(case: &Case) -> Result<crate::analysis::Files, RunError> {
    Ok(matrices(case)?
        .files()
        .map_err(|e| crate::analysis::AnalysisError::new("matrices", e.to_string()))?)
}

/// The state-space model (A, B, C, D; time in s) of an `frf` case: the modal solve of its
/// model alone, the matrices its `state_space.json` holds.
pub fn state_space(case: &Case) -> Result<StateSpace, RunError> {
    match case {
        Case::Frf(f) => crate::analysis::frf::state_space_of(&f.validate()?, &mut crate::fem::SolverCache::new()),
        _ => Err(crate::analysis::kind_refused(case, "a state-space model comes from an frf case").into()),
    }
}
