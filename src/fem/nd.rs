//! Fill-reducing orderings of the sparse Cholesky factor: the choice between approximate
//! minimum degree (AMD, faer's own) and nested dissection (METIS 5, compiled from the source the
//! `metis-sys` crate vendors).
//!
//! Nested dissection (A. George, "Nested dissection of a regular finite element mesh", SIAM J.
//! Numer. Anal. 10 (1973) 345–363; G. Karypis and V. Kumar, "A fast and high quality multilevel
//! scheme for partitioning irregular graphs", SIAM J. Sci. Comput. 20 (1998) 359–392) splits the
//! graph by small vertex separators and numbers the separators last. On 2-D and 3-D meshes
//! (shells, lattices, frames) its factor is much smaller than AMD's; on small or banded models
//! (a flexure chain, the stage) AMD is as good and cheaper, so [`FillOrdering::Auto`] keeps AMD
//! below [`ND_MIN_N`] equations and above it keeps whichever of the two gives the smaller factor.

use super::error::FemError;

/// Fill-reducing ordering of the sparse Cholesky factor (`"ordering"` in case files).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum FillOrdering {
    /// AMD below [`ND_MIN_N`] equations; above, the one of AMD and nested dissection whose
    /// factor has fewer entries (both symbolic factorisations are computed, once per topology).
    #[default]
    Auto,
    /// Approximate minimum degree.
    Amd,
    /// Nested dissection (METIS).
    Nd,
}

impl FillOrdering {
    /// The case-file name: `auto`, `amd` or `nd`.
    pub fn name(self) -> &'static str {
        match self {
            FillOrdering::Auto => "auto",
            FillOrdering::Amd => "amd",
            FillOrdering::Nd => "nd",
        }
    }
}

/// Smallest number of equations at which [`FillOrdering::Auto`] tries nested dissection. Below
/// it the factorisation takes milliseconds and AMD's ordering is the cheaper one to compute.
pub const ND_MIN_N: usize = 10_000;

/// Nested-dissection ordering (METIS_NodeND, default options) of the symmetric matrix whose lower
/// triangle has the compressed-column pattern `col_ptr`, `row_idx`. Returns `(perm, iperm)`:
/// new equation i is old equation `perm[i]`, and old equation j is new equation `iperm[j]`.
pub fn nested_dissection(col_ptr: &[usize], row_idx: &[usize]) -> Result<(Vec<usize>, Vec<usize>), FemError> {
    let n = col_ptr.len().saturating_sub(1);
    if n < 2 {
        return Ok(((0..n).collect(), (0..n).collect()));
    }
    // Adjacency graph of both triangles without the diagonal (METIS's CSR graph format).
    let mut deg = vec![0usize; n + 1];
    for j in 0..n {
        for &i in &row_idx[col_ptr[j]..col_ptr[j + 1]] {
            if i != j {
                deg[i + 1] += 1;
                deg[j + 1] += 1;
            }
        }
    }
    for k in 0..n {
        deg[k + 1] += deg[k];
    }
    let too_big = || {
        FemError::Solver(format!(
            "nested dissection: a graph of {n} equations and {} edges exceeds METIS's 32-bit indices",
            deg[n] / 2
        ))
    };
    let n_idx = metis_sys::idx_t::try_from(n).map_err(|_| too_big())?;
    let mut xadj: Vec<metis_sys::idx_t> = Vec::with_capacity(n + 1);
    for &d in &deg {
        xadj.push(metis_sys::idx_t::try_from(d).map_err(|_| too_big())?);
    }
    let mut next = deg;
    let mut adjncy: Vec<metis_sys::idx_t> = vec![0; next[n]];
    for j in 0..n {
        for &i in &row_idx[col_ptr[j]..col_ptr[j + 1]] {
            if i != j {
                // Both fit: i, j < n, which fits in idx_t.
                adjncy[next[i]] = j as metis_sys::idx_t;
                next[i] += 1;
                adjncy[next[j]] = i as metis_sys::idx_t;
                next[j] += 1;
            }
        }
    }
    let mut options = [0 as metis_sys::idx_t; metis_sys::METIS_NOPTIONS as usize];
    let mut nvtxs = n_idx;
    let mut perm: Vec<metis_sys::idx_t> = vec![0; n];
    let mut iperm: Vec<metis_sys::idx_t> = vec![0; n];
    // SAFETY: `options` has METIS_NOPTIONS entries; xadj has n + 1 entries ending at
    // adjncy.len(), every adjncy entry is in 0..n, perm and iperm have n entries; METIS reads the
    // graph and writes only perm and iperm (vwgt null: unit weights).
    let status = unsafe {
        metis_sys::METIS_SetDefaultOptions(options.as_mut_ptr());
        options[metis_sys::moptions_et_METIS_OPTION_NUMBERING as usize] = 0;
        metis_sys::METIS_NodeND(
            &mut nvtxs,
            xadj.as_mut_ptr(),
            adjncy.as_mut_ptr(),
            std::ptr::null_mut(),
            options.as_mut_ptr(),
            perm.as_mut_ptr(),
            iperm.as_mut_ptr(),
        )
    };
    if status != metis_sys::rstatus_et_METIS_OK {
        return Err(FemError::Solver(format!(
            "nested dissection: METIS_NodeND failed (status {status}) on {n} equations"
        )));
    }
    let to_usize = |v: Vec<metis_sys::idx_t>| -> Result<Vec<usize>, FemError> {
        let out: Vec<usize> = v.into_iter().filter_map(|x| usize::try_from(x).ok()).collect();
        if out.len() == n && out.iter().all(|&x| x < n) {
            Ok(out)
        } else {
            Err(FemError::Solver(
                "nested dissection: METIS returned an invalid permutation".into(),
            ))
        }
    };
    let (perm, iperm) = (to_usize(perm)?, to_usize(iperm)?);
    if perm.iter().enumerate().any(|(i, &p)| iperm[p] != i) {
        return Err(FemError::Solver(
            "nested dissection: METIS returned an invalid permutation".into(),
        ));
    }
    Ok((perm, iperm))
}
