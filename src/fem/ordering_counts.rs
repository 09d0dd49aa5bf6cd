//! Size and work of a sparse Cholesky factor under a given ordering, without forming it: the
//! elimination tree and the column counts of L in O(nnz(A)·α(n)) time (J. R. Gilbert, E. G. Ng
//! and B. W. Peyton, "An efficient algorithm to compute row and column counts for sparse
//! Cholesky factorization", SIAM J. Matrix Anal. Appl. 15 (1994) 1075–1091; in the form of
//! T. A. Davis, "Direct Methods for Sparse Linear Systems", SIAM 2006, §4.5). Used to choose
//! between candidate fill-reducing orderings by the work of their factorisation.

const NONE: usize = usize::MAX;

/// Column counts of L (diagonal included) summed into nnz(L), and the floating-point work
/// Σ_j c_j² of the factorisation (up to a constant factor), of the symmetric matrix whose lower
/// triangle has the compressed-column pattern `col_ptr`, `row_idx`, ordered so that old equation
/// j is new equation `iperm[j]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FactorCounts {
    /// Entries of L (structural; no explicit zeros of amalgamated supernodes).
    pub nnz_l: usize,
    /// Σ_j c_j² over the column counts c_j of L.
    pub work: f64,
}

/// Counts of the factor of P·A·Pᵀ (see [`FactorCounts`]); `iperm` must be a permutation of
/// 0..n for the n = `col_ptr.len() - 1` columns.
pub fn factor_counts(col_ptr: &[usize], row_idx: &[usize], iperm: &[usize]) -> FactorCounts {
    let n = col_ptr.len().saturating_sub(1);
    // Strict lower triangle of P·A·Pᵀ by columns (`lo`) and by rows (`up`, = upper by columns).
    let mut lo_ptr = vec![0usize; n + 1];
    let mut up_ptr = vec![0usize; n + 1];
    for j in 0..n {
        for &i in &row_idx[col_ptr[j]..col_ptr[j + 1]] {
            let (a, b) = (iperm[i], iperm[j]);
            if a != b {
                lo_ptr[a.min(b) + 1] += 1;
                up_ptr[a.max(b) + 1] += 1;
            }
        }
    }
    for k in 0..n {
        lo_ptr[k + 1] += lo_ptr[k];
        up_ptr[k + 1] += up_ptr[k];
    }
    let (mut lo_next, mut up_next) = (lo_ptr.clone(), up_ptr.clone());
    let mut lo = vec![0usize; lo_ptr[n]];
    let mut up = vec![0usize; up_ptr[n]];
    for j in 0..n {
        for &i in &row_idx[col_ptr[j]..col_ptr[j + 1]] {
            let (a, b) = (iperm[i], iperm[j]);
            if a != b {
                let (hi, low) = (a.max(b), a.min(b));
                lo[lo_next[low]] = hi;
                lo_next[low] += 1;
                up[up_next[hi]] = low;
                up_next[hi] += 1;
            }
        }
    }
    let parent = etree(n, &up_ptr, &up);
    let post = postorder(&parent);
    let counts = column_counts(&parent, &post, &lo_ptr, &lo);
    FactorCounts {
        nnz_l: counts.iter().sum(),
        work: counts.iter().map(|&c| (c as f64) * (c as f64)).sum(),
    }
}

/// Elimination tree from the upper triangle by columns (Liu's algorithm with path compression).
fn etree(n: usize, up_ptr: &[usize], up: &[usize]) -> Vec<usize> {
    let mut parent = vec![NONE; n];
    let mut ancestor = vec![NONE; n];
    for k in 0..n {
        for &i0 in &up[up_ptr[k]..up_ptr[k + 1]] {
            let mut i = i0;
            while i != NONE && i < k {
                let next = ancestor[i];
                ancestor[i] = k;
                if next == NONE {
                    parent[i] = k;
                }
                i = next;
            }
        }
    }
    parent
}

/// Postorder of a forest given by `parent` (children in increasing order).
fn postorder(parent: &[usize]) -> Vec<usize> {
    let n = parent.len();
    let (mut head, mut next) = (vec![NONE; n], vec![NONE; n]);
    for j in (0..n).rev() {
        if parent[j] != NONE {
            next[j] = head[parent[j]];
            head[parent[j]] = j;
        }
    }
    let mut post = Vec::with_capacity(n);
    let mut stack = Vec::new();
    for root in (0..n).filter(|&j| parent[j] == NONE) {
        stack.push(root);
        while let Some(&p) = stack.last() {
            let child = head[p];
            if child == NONE {
                stack.pop();
                post.push(p);
            } else {
                head[p] = next[child];
                stack.push(child);
            }
        }
    }
    post
}

/// Column counts of L (diagonal included) from the strict lower triangle by columns, the
/// elimination tree and its postorder: skeleton-matrix leaves and least common ancestors.
fn column_counts(parent: &[usize], post: &[usize], lo_ptr: &[usize], lo: &[usize]) -> Vec<usize> {
    let n = parent.len();
    let mut first = vec![NONE; n];
    let mut delta = vec![0isize; n];
    for (k, &j0) in post.iter().enumerate() {
        delta[j0] = isize::from(first[j0] == NONE);
        let mut j = j0;
        while j != NONE && first[j] == NONE {
            first[j] = k;
            j = parent[j];
        }
    }
    let (mut max_first, mut prev_leaf) = (vec![NONE; n], vec![NONE; n]);
    let mut ancestor: Vec<usize> = (0..n).collect();
    for &j in post {
        if parent[j] != NONE {
            delta[parent[j]] -= 1;
        }
        for &i in &lo[lo_ptr[j]..lo_ptr[j + 1]] {
            // Is j a leaf of the row subtree of i (a new first descendant)?
            if max_first[i] != NONE && first[j] <= max_first[i] {
                continue;
            }
            max_first[i] = first[j];
            let jprev = prev_leaf[i];
            prev_leaf[i] = j;
            delta[j] += 1;
            if jprev != NONE {
                // Subsequent leaf: subtract at the least common ancestor of jprev and j.
                let mut q = jprev;
                while q != ancestor[q] {
                    q = ancestor[q];
                }
                let mut s = jprev;
                while s != q {
                    let up = ancestor[s];
                    ancestor[s] = q;
                    s = up;
                }
                delta[q] -= 1;
            }
        }
        if parent[j] != NONE {
            ancestor[j] = parent[j];
        }
    }
    for &j in post {
        if parent[j] != NONE {
            delta[parent[j]] += delta[j];
        }
    }
    delta.into_iter().map(|d| d.max(0) as usize).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Column counts by symbolic elimination (the definition: the pattern of column j of L is
    /// that of A's column j below the diagonal united with those of its children in the tree).
    fn brute_counts(n: usize, col_ptr: &[usize], row_idx: &[usize], iperm: &[usize]) -> Vec<usize> {
        let mut cols: Vec<std::collections::BTreeSet<usize>> = vec![Default::default(); n];
        for j in 0..n {
            for &i in &row_idx[col_ptr[j]..col_ptr[j + 1]] {
                let (a, b) = (iperm[i], iperm[j]);
                cols[a.min(b)].insert(a.max(b));
            }
        }
        for j in 0..n {
            cols[j].insert(j);
            let below: Vec<usize> = cols[j].iter().copied().filter(|&i| i > j).collect();
            if let Some(&p) = below.first() {
                for i in below {
                    cols[p].insert(i);
                }
            }
        }
        cols.iter().map(|c| c.len()).collect()
    }

    #[test]
    fn counts_match_symbolic_elimination() {
        // A 7×5 grid graph (5-point stencil), lower triangle with diagonal, under the identity
        // and a scrambled ordering: nnz(L) equal to the symbolic elimination's (the definition).
        let (nx, ny) = (7usize, 5usize);
        let n = nx * ny;
        let (mut col_ptr, mut row_idx) = (vec![0usize], Vec::new());
        for j in 0..n {
            row_idx.push(j);
            if j % nx + 1 < nx {
                row_idx.push(j + 1);
            }
            if j + nx < n {
                row_idx.push(j + nx);
            }
            col_ptr.push(row_idx.len());
        }
        let scrambled: Vec<usize> = (0..n).map(|j| (j * 17 + 5) % n).collect();
        for iperm in [(0..n).collect::<Vec<_>>(), scrambled] {
            let brute = brute_counts(n, &col_ptr, &row_idx, &iperm);
            let c = factor_counts(&col_ptr, &row_idx, &iperm);
            assert_eq!(c.nnz_l, brute.iter().sum::<usize>());
            let work: f64 = brute.iter().map(|&c| (c * c) as f64).sum();
            assert_eq!(c.work, work);
        }
    }
}
