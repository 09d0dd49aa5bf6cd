//! Craig–Bampton reduction of a model to interface nodes (R. R. Craig, M. C. C. Bampton,
//! "Coupling of substructures for dynamic analyses", AIAA Journal 6 (1968) 1313–1319): the
//! reduced equations ([`super::matrices`]) split into boundary DOFs B (the equations of the
//! interface nodes) and interior DOFs I, with the transformation
//!
//! ```text
//! [u_B; u_I] = [I 0; Ψ Φ] [u_B; η],   Ψ = −K_II⁻¹ K_IB (constraint modes),
//! Φ: the N lowest fixed-interface modes K_II φ = ω² M_II φ, mass-normalised (φᵀ M_II φ = 1)
//! K_cb = Tᵀ K T = [K_BB + K_BI Ψ, 0; 0, diag(ω²)],  M_cb = Tᵀ M T
//! ```
//!
//! With N = 0 it is Guyan's static condensation (R. J. Guyan, AIAA Journal 3 (1965) 380): K_cb
//! is the exact static stiffness of the interface. Dense linear algebra on the interior (at
//! most [`MAX_INTERIOR`] equations).

use super::error::FemError;
use super::matrices::reduced_matrices;
use super::model::Model;
use crate::fem::dof::NodeDof;
use nalgebra::{DMatrix, SymmetricEigen};

/// Largest number of interior equations of the dense reduction.
pub const MAX_INTERIOR: usize = 4000;

/// Largest number of coordinates of the superelement (boundary equations plus modes): its
/// dense K and M, their eigen-decomposition (the frequency check) and the JSON rows grow as
/// the square and cube of it (3000 coordinates: about 1.3 GiB and minutes of dense algebra).
pub const MAX_REDUCED: usize = 3000;

/// Boundary (the equations of the interface nodes) and interior equation indices.
fn split(dofs: &[NodeDof], interface: &[usize]) -> (Vec<usize>, Vec<usize>) {
    (0..dofs.len()).partition(|&i| interface.contains(&dofs[i].node))
}

/// The position in `interface` of the first node without equations (fully supported, or a
/// rigid-link slave), if any.
fn bare_node(dofs: &[NodeDof], interface: &[usize]) -> Option<usize> {
    interface.iter().position(|&nd| !dofs.iter().any(|d| d.node == nd))
}

/// How `interface` splits the equations of `model` (from the DOF numbering alone: nothing is
/// assembled), for checks before the run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Partition {
    /// Boundary equations (those of the interface nodes).
    pub boundary: usize,
    /// Interior equations.
    pub interior: usize,
    /// Position in `interface` of a node without equations, if any (refused by [`craig_bampton`]).
    pub bare: Option<usize>,
}

/// The [`Partition`] of `model`'s equations by `interface`.
pub fn partition(model: &Model, interface: &[usize]) -> Result<Partition, FemError> {
    let map = super::constraints::DofMap::new(model, &[], None)?;
    let dofs: Vec<NodeDof> = (0..map.n_eq()).map(|i| map.describe_eq(i)).collect();
    let (b, i) = split(&dofs, interface);
    Ok(Partition {
        boundary: b.len(),
        interior: i.len(),
        bare: bare_node(&dofs, interface),
    })
}

/// A Craig–Bampton superelement.
#[derive(Debug, Clone, PartialEq)]
pub struct Superelement {
    /// Node and DOF of each boundary coordinate (the first rows of K and M), as in the model's
    /// reduced equations (node frames kept).
    pub boundary: Vec<NodeDof>,
    /// Reduced stiffness on [u_B; η] (symmetric, both triangles).
    pub k: sprs::CsMat<f64>,
    /// Reduced mass on [u_B; η].
    pub m: sprs::CsMat<f64>,
    /// Circular frequencies² of the retained fixed-interface modes (ascending), rad²/s².
    pub fixed_interface_eigenvalues: Vec<f64>,
}

fn dense(m: &sprs::CsMat<f64>) -> DMatrix<f64> {
    let mut d = DMatrix::zeros(m.rows(), m.cols());
    for (v, (i, j)) in m.iter() {
        d[(i, j)] += *v;
    }
    d
}

fn sparse(d: &DMatrix<f64>) -> sprs::CsMat<f64> {
    let mut t = sprs::TriMat::new((d.nrows(), d.ncols()));
    for j in 0..d.ncols() {
        for i in 0..d.nrows() {
            if d[(i, j)] != 0.0 {
                t.add_triplet(i, j, d[(i, j)]);
            }
        }
    }
    t.to_csr()
}

/// Lowest `n` eigenpairs of K x = λ M x (K symmetric positive definite, M symmetric positive
/// semi-definite) by the largest eigenvalues μ = 1/λ of L⁻¹ M L⁻ᵀ (K = L Lᵀ): massless DOFs
/// give μ = 0 and are never among them. Eigenvectors mass-normalised, the largest component
/// of each positive.
pub fn lowest_modes(k: &DMatrix<f64>, m: &DMatrix<f64>, n: usize) -> Result<(Vec<f64>, DMatrix<f64>), FemError> {
    if n == 0 {
        // Guyan (no modes), possibly of an interface without interior: nothing to decompose.
        return Ok((Vec::new(), DMatrix::zeros(k.nrows(), 0)));
    }
    let l = k
        .clone()
        .cholesky()
        .ok_or_else(|| FemError::BadInput("the stiffness is not positive definite (a free motion remains)".into()))?;
    let li = l
        .l()
        .try_inverse()
        .ok_or_else(|| FemError::Solver("singular Cholesky factor".into()))?;
    let a = &li * m * li.transpose();
    let e = SymmetricEigen::new((&a + a.transpose()) * 0.5);
    let mut idx: Vec<usize> = (0..e.eigenvalues.len()).collect();
    idx.sort_by(|&x, &y| e.eigenvalues[y].total_cmp(&e.eigenvalues[x]));
    let scale = e.eigenvalues.iter().fold(0.0f64, |s, v| s.max(v.abs()));
    let mut lam = Vec::with_capacity(n);
    let mut phi = DMatrix::zeros(k.nrows(), n);
    for (c, &i) in idx.iter().take(n).enumerate() {
        let mu = e.eigenvalues[i];
        if mu <= 1e-12 * scale {
            return Err(FemError::BadInput(format!("only {c} modes with mass: {n} asked for")));
        }
        lam.push(1.0 / mu);
        let mut x = li.transpose() * e.eigenvectors.column(i) / mu.sqrt();
        // Sign: the largest component positive (a reproducible superelement).
        if x.iter().fold(0.0f64, |b, v| if v.abs() > b.abs() { *v } else { b }) < 0.0 {
            x = -x;
        }
        phi.set_column(c, &x);
    }
    Ok((lam, phi))
}

/// The Craig–Bampton superelement of `model` with boundary = every equation of the nodes in
/// `interface` and `n_modes` fixed-interface modes.
pub fn craig_bampton(model: &Model, interface: &[usize], n_modes: usize) -> Result<Superelement, FemError> {
    let red = reduced_matrices(model)?;
    let (b, i_) = split(&red.dofs, interface);
    if let Some(node) = bare_node(&red.dofs, interface).map(|k| interface[k]) {
        return Err(FemError::BadInput(format!(
            "interface node {node} has no equations (fully supported, or a rigid-link slave: use its master)"
        )));
    }
    if i_.len() > MAX_INTERIOR {
        return Err(FemError::BadInput(format!(
            "Craig–Bampton: {} interior equations; the dense reduction takes at most {MAX_INTERIOR}",
            i_.len()
        )));
    }
    if b.len() + n_modes > MAX_REDUCED {
        return Err(FemError::BadInput(format!(
            "Craig–Bampton: {} boundary equations and {n_modes} modes; the dense superelement takes at most {MAX_REDUCED} coordinates",
            b.len()
        )));
    }
    if n_modes > i_.len() {
        return Err(FemError::BadInput(format!(
            "{n_modes} fixed-interface modes asked for; the interior has {} equations",
            i_.len()
        )));
    }
    let (k, m) = (dense(&red.k), dense(&red.m));
    let part = |a: &DMatrix<f64>, r: &[usize], c: &[usize]| DMatrix::from_fn(r.len(), c.len(), |x, y| a[(r[x], c[y])]);
    let (kii, kib, kbb) = (part(&k, &i_, &i_), part(&k, &i_, &b), part(&k, &b, &b));
    let (mii, mib, mbb) = (part(&m, &i_, &i_), part(&m, &i_, &b), part(&m, &b, &b));
    let chol = kii.clone().cholesky().ok_or_else(|| {
        FemError::BadInput(
            "with the interface held, the model still has a free motion (K_II is not positive definite)".into(),
        )
    })?;
    let psi = -chol.solve(&kib);
    let (lam, phi) = lowest_modes(&kii, &mii, n_modes)?;
    let (nb, nm) = (b.len(), n_modes);
    let mut kc = DMatrix::zeros(nb + nm, nb + nm);
    let mut mc = DMatrix::zeros(nb + nm, nb + nm);
    let kbb_c = &kbb + kib.transpose() * &psi;
    kc.view_mut((0, 0), (nb, nb))
        .copy_from(&((&kbb_c + kbb_c.transpose()) * 0.5));
    for (j, l) in lam.iter().enumerate() {
        kc[(nb + j, nb + j)] = *l;
    }
    let mpsi = &mii * &psi;
    let mbb_c = &mbb + mib.transpose() * &psi + psi.transpose() * &mib + psi.transpose() * &mpsi;
    mc.view_mut((0, 0), (nb, nb))
        .copy_from(&((&mbb_c + mbb_c.transpose()) * 0.5));
    let mbe = (mib.transpose() + psi.transpose() * &mii) * &phi;
    mc.view_mut((0, nb), (nb, nm)).copy_from(&mbe);
    mc.view_mut((nb, 0), (nm, nb)).copy_from(&mbe.transpose());
    let mee = phi.transpose() * &mii * &phi;
    mc.view_mut((nb, nb), (nm, nm))
        .copy_from(&((&mee + mee.transpose()) * 0.5));
    Ok(Superelement {
        boundary: b.iter().map(|&i| red.dofs[i]).collect(),
        k: sparse(&kc),
        m: sparse(&mc),
        fixed_interface_eigenvalues: lam,
    })
}

impl Superelement {
    /// The lowest `n` eigenvalues ω² of the superelement (its interface held where the model's
    /// supports hold it; K_cb must be positive definite).
    pub fn eigenvalues(&self, n: usize) -> Result<Vec<f64>, FemError> {
        Ok(lowest_modes(&dense(&self.k), &dense(&self.m), n)?.0)
    }
}
