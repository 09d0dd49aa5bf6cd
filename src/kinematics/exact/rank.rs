//! The rank analysis of a constraint Jacobian: independent and redundant rows (in row order,
//! each redundant row written as a combination of the independent ones before it), the null
//! space (the free motions, in a canonical reduced-row-echelon basis) and the singular values
//! as a cross-check of the rank.
//!
//! The rows are processed in order by Gram–Schmidt with reorthogonalisation ("twice is enough",
//! L. Giraud, J. Langou, M. Rozložník, Comput. Math. Appl. 50 (2005) 1069–1075): a row whose
//! residual after projection on the rows accepted so far is below [`DEPENDENT`] (rows are unit
//! vectors) is redundant. This is the rank decision of a QR factorisation of Jᵀ without column
//! pivoting, so the constraints listed first are kept and the later ones named redundant.

use nalgebra::{DMatrix, DVector};

/// Residual norm (rows of unit length) below which a row lies in the span of the rows before
/// it. Rows built from exact geometry give residuals of ~1e-15 when dependent and ≥ 1e-3 when
/// independent in every test model; the singular values cross-check the decision.
pub const DEPENDENT: f64 = 1e-8;

/// The rank structure of a Jacobian.
#[derive(Debug, Clone)]
pub struct RankAnalysis {
    /// Independent rows (in order).
    pub independent: Vec<usize>,
    /// Redundant rows: (row, [(independent row, coefficient)]) with row = Σ coefficient·that row
    /// (unit rows; coefficients below 1e-9 of the largest left out). A zero row has no partners.
    pub redundant: Vec<(usize, Vec<(usize, f64)>)>,
    /// Basis of the null space (the free motions), one vector per motion, reduced row echelon:
    /// each has a leading column equal to 1 that the others do not have.
    pub null_space: Vec<DVector<f64>>,
    /// The min(rows, columns) singular values, largest first: the cross-check of the rank (the
    /// number above [`DEPENDENT`] times the largest) and how close the constraints come to a
    /// dependency (the smallest of the independent part).
    pub singular_values: Vec<f64>,
}

/// Orthonormal basis of the span of the rows accepted so far, with the triangular factor
/// (accepted row j = Σ_{i ≤ j} r[j][i]·q_i).
struct Span {
    q: Vec<DVector<f64>>,
    r: Vec<Vec<f64>>,
}

impl Span {
    /// Projects `x` on the span twice; returns the coefficients and the residual.
    fn project(&self, x: &DVector<f64>) -> (Vec<f64>, DVector<f64>) {
        let mut h = vec![0.0; self.q.len()];
        let mut y = x.clone();
        for _ in 0..2 {
            for (i, q) in self.q.iter().enumerate() {
                let c = q.dot(&y);
                h[i] += c;
                y.axpy(-c, q, 1.0);
            }
        }
        (h, y)
    }

    /// Coefficients c of x = Σ c_j (accepted row j) from its projection coefficients h
    /// (back substitution with the triangular factor).
    fn combination(&self, h: &[f64]) -> Vec<f64> {
        let k = self.q.len();
        let mut c = vec![0.0; k];
        for j in (0..k).rev() {
            let s: f64 = h[j] - ((j + 1)..k).map(|l| self.r[l][j] * c[l]).sum::<f64>();
            c[j] = s / self.r[j][j];
        }
        c
    }
}

/// The rank analysis of `j` (rows are constraints; zero rows allowed, others of unit length).
pub fn analyse(j: &DMatrix<f64>) -> RankAnalysis {
    let (m, n) = j.shape();
    let mut span = Span {
        q: Vec::new(),
        r: Vec::new(),
    };
    let mut independent = Vec::new();
    let mut redundant = Vec::new();
    for row in 0..m {
        let x: DVector<f64> = j.row(row).transpose();
        if x.norm() == 0.0 {
            redundant.push((row, Vec::new()));
            continue;
        }
        let (h, y) = span.project(&x);
        let res = y.norm();
        if res <= DEPENDENT {
            let c = span.combination(&h);
            let big = c.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
            let with = c
                .iter()
                .enumerate()
                .filter(|(_, v)| v.abs() > 1e-9 * big)
                .map(|(i, v)| (independent[i], *v))
                .collect();
            redundant.push((row, with));
        } else {
            let mut rcol = h;
            rcol.push(res);
            span.r.push(rcol);
            span.q.push(y / res);
            independent.push(row);
        }
    }
    let (singular_values, null_space) = svd_null_space(j, n - independent.len());
    RankAnalysis {
        independent,
        redundant,
        null_space,
        singular_values,
    }
}

/// Rank of `j` alone (the greedy decision of [`analyse`], without the null space).
pub fn rank(j: &DMatrix<f64>) -> usize {
    let mut span = Span {
        q: Vec::new(),
        r: Vec::new(),
    };
    for row in 0..j.nrows() {
        let x: DVector<f64> = j.row(row).transpose();
        if x.norm() == 0.0 {
            continue;
        }
        let (_, y) = span.project(&x);
        let res = y.norm();
        if res > DEPENDENT {
            span.q.push(y / res);
        }
    }
    span.q.len()
}

/// The singular values of `j` (largest first) and a basis of its null space of dimension `d`:
/// the right singular vectors of the `d` smallest singular values (J padded with zero rows to
/// at least square, so that every right singular vector is formed), brought to reduced row
/// echelon form.
fn svd_null_space(j: &DMatrix<f64>, d: usize) -> (Vec<f64>, Vec<DVector<f64>>) {
    let (m, n) = j.shape();
    if n == 0 {
        return (Vec::new(), Vec::new());
    }
    let mut padded = DMatrix::zeros(m.max(n), n);
    padded.rows_mut(0, m).copy_from(j);
    let svd = padded.svd(false, true);
    let Some(vt) = svd.v_t else {
        return (Vec::new(), Vec::new());
    };
    let mut order: Vec<usize> = (0..svd.singular_values.len()).collect();
    order.sort_by(|&a, &b| svd.singular_values[b].total_cmp(&svd.singular_values[a]));
    let sigma: Vec<f64> = order.iter().take(m.min(n)).map(|&i| svd.singular_values[i]).collect();
    let null = order.iter().rev().take(d).map(|&i| vt.row(i).transpose()).collect();
    (sigma, echelon(null, n))
}

/// Reduced row echelon form of the vectors (as rows), pivots chosen column by column by the
/// largest entry; entries below 1e-10 of the pivot set to zero.
fn echelon(mut rows: Vec<DVector<f64>>, n: usize) -> Vec<DVector<f64>> {
    let mut top = 0;
    for col in 0..n {
        if top == rows.len() {
            break;
        }
        let (p, v) = (top..rows.len())
            .map(|r| (r, rows[r][col].abs()))
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap_or((top, 0.0));
        if v <= 1e-8 {
            continue;
        }
        rows.swap(top, p);
        let pivot = rows[top][col];
        rows[top] /= pivot;
        let lead = rows[top].clone();
        for (r, row) in rows.iter_mut().enumerate() {
            if r != top {
                let f = row[col];
                row.axpy(-f, &lead, 1.0);
            }
        }
        top += 1;
    }
    for row in &mut rows {
        row.iter_mut().filter(|v| v.abs() < 1e-10).for_each(|v| *v = 0.0);
    }
    rows
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Three unit rows in the xy plane: the third, (e₁ + e₂)/√2, is redundant with the first two
    /// (coefficients 1/√2 each, exact), and the null space is the z axis.
    #[test]
    fn dependent_row_is_named_with_its_partners() {
        let s = 0.5_f64.sqrt();
        let j = DMatrix::from_row_slice(3, 3, &[1.0, 0.0, 0.0, 0.0, 1.0, 0.0, s, s, 0.0]);
        let a = analyse(&j);
        assert_eq!(a.independent, vec![0, 1]);
        assert_eq!(a.redundant.len(), 1);
        let (row, with) = &a.redundant[0];
        assert_eq!(*row, 2);
        assert_eq!(with.len(), 2);
        assert!((with[0].1 - s).abs() < 1e-14 && (with[1].1 - s).abs() < 1e-14);
        // The null space is the z axis.
        assert_eq!(a.null_space.len(), 1);
        assert!((a.null_space[0][2] - 1.0).abs() < 1e-14);
        assert_eq!(rank(&j), 2);
    }
}
