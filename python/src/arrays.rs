//! Matrices as numpy arrays over the Rust buffers: a `Vec` becomes the array's memory (no copy)
//! and column-major nalgebra matrices are viewed in Fortran order.

use flexfem::fem::matrices::ReducedMatrices;
use flexfem::fem::state_space::StateSpace;
use nalgebra::DMatrix;
use numpy::npyffi::NPY_ORDER;
use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// A column-major matrix as a numpy array in Fortran order over its own buffer.
fn dense<'py>(py: Python<'py>, m: DMatrix<f64>) -> PyResult<Bound<'py, PyAny>> {
    let (r, c) = m.shape();
    let flat = PyArray1::from_vec(py, m.data.into());
    Ok(flat.reshape_with_order([r, c], NPY_ORDER::NPY_FORTRANORDER)?.into_any())
}

/// A 6×6 matrix given by rows as a numpy array.
pub fn square6<'py>(py: Python<'py>, m: &[[f64; 6]; 6]) -> PyResult<Bound<'py, PyAny>> {
    let flat: Vec<f64> = m.iter().flatten().copied().collect();
    Ok(PyArray1::from_vec(py, flat).reshape([6, 6])?.into_any())
}

/// A CSR matrix as `(data, indices, indptr, (rows, cols))`: the values are the matrix's own
/// buffer; the index arrays become int64 (scipy's signed indices).
fn csr<'py>(py: Python<'py>, m: sprs::CsMat<f64>) -> PyResult<Bound<'py, PyAny>> {
    let shape = m.shape();
    let (indptr, indices, data) = m.into_raw_storage();
    let index = |v: Vec<usize>| v.into_iter().map(|i| i as i64).collect::<Vec<i64>>();
    let parts = (
        PyArray1::from_vec(py, data),
        PyArray1::from_vec(py, index(indices)),
        PyArray1::from_vec(py, index(indptr)),
        shape,
    );
    Ok(parts.into_pyobject(py)?.into_any())
}

/// `{"K", "M"}` as CSR parts, `"dofs"` as (node, dof name) per equation, `"node_frame"`.
pub fn matrices_dict(py: Python<'_>, mats: ReducedMatrices) -> PyResult<Bound<'_, PyDict>> {
    let d = PyDict::new(py);
    let dofs: Vec<(usize, &str)> = mats.dofs.iter().map(|n| (n.node, n.dof.name())).collect();
    d.set_item("dofs", dofs)?;
    d.set_item("node_frame", mats.node_frame)?;
    d.set_item("K", csr(py, mats.k)?)?;
    d.set_item("M", csr(py, mats.m)?)?;
    Ok(d)
}

/// `{"A", "B", "C", "D"}` (numpy, Fortran order), `"omega"` (rad/s) and `"zeta"`.
pub fn state_space_dict(py: Python<'_>, ss: StateSpace) -> PyResult<Bound<'_, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("A", dense(py, ss.a)?)?;
    d.set_item("B", dense(py, ss.b)?)?;
    d.set_item("C", dense(py, ss.c)?)?;
    d.set_item("D", dense(py, ss.d)?)?;
    d.set_item("omega", PyArray1::from_vec(py, ss.omega))?;
    d.set_item("zeta", PyArray1::from_vec(py, ss.zeta))?;
    Ok(d)
}
