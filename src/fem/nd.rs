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
use super::ordering_counts::factor_counts;
use metis_sys::idx_t;

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

/// METIS_NodeND balance factors (UFACTOR) tried by [`nested_dissection`]: UFACTOR u allows the
/// parts split off by a separator a load imbalance of 1 + u/1000 (200 is METIS's default for
/// orderings). Looser balance can buy much smaller separators: on the 31³-cell beam lattice
/// (190 464 equations) the work Σc_j² of the factor is 7.99·10¹¹ with the default and 5.81·10¹¹
/// with 400 (5.73–5.85·10¹¹ over four random seeds, against 7.2–8.1·10¹¹ at 200), on other
/// meshes the default may stay the best. The four METIS calls with their column counts take
/// about 2.6 s of CPU there, against 0.8 s for one call and 17–23 s for the factorisation.
pub const ND_UFACTORS: [i32; 4] = [200, 300, 400, 500];

/// METIS keeps its random number generator in a global: calls from several threads at once
/// would draw from one sequence and make the orderings depend on timing.
static METIS_LOCK: std::sync::Mutex<()> = std::sync::Mutex::new(());

/// Nested-dissection ordering (METIS_NodeND) of the symmetric matrix whose lower triangle has the
/// compressed-column pattern `col_ptr`, `row_idx`: of the orderings for the balance factors
/// [`ND_UFACTORS`] (other options METIS's defaults), the one whose factor needs the least work
/// (column counts from [`factor_counts`]; ties keep the earlier one). Returns `(perm, iperm)`: new equation i is old equation
/// `perm[i]`, and old equation j is new equation `iperm[j]`.
pub fn nested_dissection(col_ptr: &[usize], row_idx: &[usize]) -> Result<(Vec<usize>, Vec<usize>), FemError> {
    let n = col_ptr.len().saturating_sub(1);
    if n < 2 {
        return Ok(((0..n).collect(), (0..n).collect()));
    }
    let (xadj, adjncy) = metis_graph(col_ptr, row_idx)?;
    let mut best = metis_node_nd(&xadj, &adjncy, ND_UFACTORS[0])?;
    let mut best_work = factor_counts(col_ptr, row_idx, &best.1).work;
    for ufactor in &ND_UFACTORS[1..] {
        let order = metis_node_nd(&xadj, &adjncy, *ufactor)?;
        let work = factor_counts(col_ptr, row_idx, &order.1).work;
        if work < best_work {
            (best, best_work) = (order, work);
        }
    }
    Ok(best)
}

/// Adjacency graph of both triangles without the diagonal, in METIS's CSR format.
fn metis_graph(col_ptr: &[usize], row_idx: &[usize]) -> Result<(Vec<idx_t>, Vec<idx_t>), FemError> {
    let n = col_ptr.len().saturating_sub(1);
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
    idx_t::try_from(n).map_err(|_| too_big())?;
    let mut xadj: Vec<idx_t> = Vec::with_capacity(n + 1);
    for &d in &deg {
        xadj.push(idx_t::try_from(d).map_err(|_| too_big())?);
    }
    let mut next = deg;
    let mut adjncy: Vec<idx_t> = vec![0; next[n]];
    for j in 0..n {
        for &i in &row_idx[col_ptr[j]..col_ptr[j + 1]] {
            if i != j {
                // Both fit: i, j < n, which fits in idx_t.
                adjncy[next[i]] = j as idx_t;
                next[i] += 1;
                adjncy[next[j]] = i as idx_t;
                next[j] += 1;
            }
        }
    }
    Ok((xadj, adjncy))
}

/// METIS_NodeND on a graph from [`metis_graph`] with the given UFACTOR (see [`ND_UFACTORS`]),
/// other options METIS's defaults.
fn metis_node_nd(xadj: &[idx_t], adjncy: &[idx_t], ufactor: i32) -> Result<(Vec<usize>, Vec<usize>), FemError> {
    let n = xadj.len() - 1;
    let (mut xadj, mut adjncy) = (xadj.to_vec(), adjncy.to_vec());
    let mut options = [0 as idx_t; metis_sys::METIS_NOPTIONS as usize];
    let mut nvtxs = n as idx_t;
    let mut perm: Vec<idx_t> = vec![0; n];
    let mut iperm: Vec<idx_t> = vec![0; n];
    let status = {
        let _guard = METIS_LOCK.lock().unwrap_or_else(|e| e.into_inner());
        // SAFETY: `options` has METIS_NOPTIONS entries; xadj has n + 1 entries ending at
        // adjncy.len(), every adjncy entry is in 0..n, perm and iperm have n entries; METIS
        // reads the graph and writes only perm and iperm (vwgt null: unit weights).
        unsafe {
            metis_sys::METIS_SetDefaultOptions(options.as_mut_ptr());
            options[metis_sys::moptions_et_METIS_OPTION_NUMBERING as usize] = 0;
            options[metis_sys::moptions_et_METIS_OPTION_UFACTOR as usize] = ufactor;
            metis_sys::METIS_NodeND(
                &mut nvtxs,
                xadj.as_mut_ptr(),
                adjncy.as_mut_ptr(),
                std::ptr::null_mut(),
                options.as_mut_ptr(),
                perm.as_mut_ptr(),
                iperm.as_mut_ptr(),
            )
        }
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
