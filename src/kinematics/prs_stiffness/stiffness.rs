//! The 6×6 platform stiffness and compliance at one pose (`K = G·𝒦·Gᵀ`) and its length-scaled
//! eigen-decomposition.

use super::{LegModel, PoseState, PrsLayout, StiffnessError};
use nalgebra::{Matrix3, Matrix6, SymmetricEigen, Vector3, Vector6};

/// Stiffness results at one pose and reference point.
#[derive(Debug, Clone, PartialEq)]
pub struct PoseStiffness {
    /// Kinematic state.
    pub state: PoseState,
    /// Reference point Q, mm (fixed frame).
    pub point: Vector3<f64>,
    /// Actuation Jacobian ∂s/∂(p_z, ψ, θ), mm/mm and mm/rad.
    pub jacobian: Matrix3<f64>,
    /// Wrench matrix G about Q.
    pub g: Matrix6<f64>,
    /// Leg compliances `[c_a1, c_a2, c_a3, c_c1, c_c2, c_c3]`, mm/N.
    pub leg_compliance: [f64; 6],
    /// Compliance about Q, `C = G⁻ᵀ𝒞G⁻¹` (mm/N, rad/N, rad/(N·mm)).
    pub compliance: Matrix6<f64>,
    /// Stiffness `K = G𝒦Gᵀ` about Q; `None` when a leg stiffness is rigid (K unbounded).
    pub stiffness: Option<Matrix6<f64>>,
    /// Stiffness on the independent coordinates (p_z, ψ, θ): `Jᵀ·diag(k_a)·J`
    /// (N/mm, N·mm/rad·mm⁻¹ = N, N·mm/rad); the constraint stiffness does no work there.
    pub independent: Matrix3<f64>,
}

/// Symmetric eigen-decomposition in the length-scaled basis (see the module conventions).
#[derive(Debug, Clone, PartialEq)]
pub struct ScaledEigen {
    /// Characteristic length ℓ, mm.
    pub length: f64,
    /// Eigenvalues ascending, N/mm.
    pub values: Vec<f64>,
    /// Unit eigenvectors (columns match `values`) in `[δp (mm); ℓ·δα (mm)]` coordinates.
    pub vectors: Vec<Vec<f64>>,
}

/// Eigenvalues/vectors of a symmetric stiffness with the first `n_lin` coordinates translations
/// (mm) and the rest rotations (rad), scaled by ℓ = `length` (mm).
pub fn scaled_eigen<const N: usize>(k: &nalgebra::SMatrix<f64, N, N>, n_lin: usize, length: f64) -> ScaledEigen {
    let mut t = nalgebra::SMatrix::<f64, N, N>::identity();
    for j in n_lin..N {
        t[(j, j)] = 1.0 / length;
    }
    let ks = t * k * t;
    let ks = 0.5 * (ks + ks.transpose());
    let dm = nalgebra::DMatrix::from_iterator(N, N, ks.iter().copied());
    let eig = SymmetricEigen::new(dm);
    let mut idx: Vec<usize> = (0..N).collect();
    idx.sort_by(|&x, &y| eig.eigenvalues[x].total_cmp(&eig.eigenvalues[y]));
    ScaledEigen {
        length,
        values: idx.iter().map(|&j| eig.eigenvalues[j]).collect(),
        vectors: idx
            .iter()
            .map(|&j| {
                let c = eig.eigenvectors.column(j);
                // Sign convention: the largest component positive.
                let big = c
                    .iter()
                    .copied()
                    .fold(0.0f64, |m, x| if x.abs() > m.abs() { x } else { m });
                let sg = if big < 0.0 { -1.0 } else { 1.0 };
                c.iter().map(|x| sg * x).collect()
            })
            .collect(),
    }
}

/// The 3-PRS stiffness model: layout + leg model.
#[derive(Debug, Clone, PartialEq)]
pub struct PrsStiffness {
    /// Geometry.
    pub layout: PrsLayout,
    /// Leg stiffness model (all three legs alike).
    pub leg: LegModel,
}

impl PrsStiffness {
    /// A validated model.
    pub fn new(layout: PrsLayout, leg: LegModel) -> Result<Self, StiffnessError> {
        leg.validate()?;
        Ok(PrsStiffness { layout, leg })
    }

    /// Stiffness at pose (p_z mm absolute, ψ, θ rad) about the point `tool` given in the platform
    /// frame {u, v, w} relative to P (mm).
    pub fn at(&self, pz: f64, psi: f64, theta: f64, tool: &Vector3<f64>) -> Result<PoseStiffness, StiffnessError> {
        let st = self.layout.pose(pz, psi, theta)?;
        let point = st.p() + st.r * tool;
        let g = self.layout.wrench_matrix(&st, &point)?;
        let t = self.layout.twist_map(&st);
        // Gᵀ·T is invariant of the reference point only through G; the actuation Jacobian is
        // the actuation block of G_Pᵀ·T (twist map about P).
        let gp = if tool.norm() == 0.0 {
            g
        } else {
            self.layout.wrench_matrix(&st, &st.p())?
        };
        let jac = gp.fixed_columns::<3>(0).transpose() * t;
        let mut cl = [0.0; 6];
        for i in 0..3 {
            let [ca, cc] = self.leg.compliances(&self.layout, &st, i)?;
            cl[i] = ca;
            cl[i + 3] = cc;
        }
        let ginv = g.try_inverse().ok_or_else(|| {
            self.layout.singular(
                &st,
                "the 6×6 wrench matrix G is singular (constraint or actuation singularity)".into(),
            )
        })?;
        // C = G⁻ᵀ·diag(c)·G⁻¹ and K = G·diag(1/c)·Gᵀ, the diagonal applied by scaling rows/columns.
        let mut scaled = ginv;
        for (k, c) in cl.iter().enumerate() {
            scaled.row_mut(k).scale_mut(*c);
        }
        let mut compliance = ginv.transpose() * scaled;
        compliance = 0.5 * (compliance + compliance.transpose());
        let stiffness = if cl.iter().all(|&c| c > 0.0) {
            let mut gs = g;
            for (k, c) in cl.iter().enumerate() {
                gs.column_mut(k).scale_mut(1.0 / c);
            }
            let k = gs * g.transpose();
            Some(0.5 * (k + k.transpose()))
        } else {
            None
        };
        let ka = Matrix3::from_diagonal(&Vector3::new(1.0 / cl[0], 1.0 / cl[1], 1.0 / cl[2]));
        let independent = jac.transpose() * ka * jac;
        Ok(PoseStiffness {
            state: st,
            point,
            jacobian: jac,
            g,
            leg_compliance: cl,
            compliance,
            stiffness,
            independent: 0.5 * (independent + independent.transpose()),
        })
    }
}

impl PoseStiffness {
    /// Deformation twist `[δp (mm); δα (rad)]` at the reference point for a wrench
    /// `[f (N); m (N·mm)]` applied there (both fixed frame).
    pub fn deformation(&self, wrench: &Vector6<f64>) -> Vector6<f64> {
        self.compliance * wrench
    }

    /// Directional stiffness 1/C_ii (N/mm for i < 3, N·mm/rad for i ≥ 3); `None` if C_ii = 0 (rigid).
    pub fn directional(&self, i: usize) -> Option<f64> {
        let c = self.compliance[(i, i)];
        (c > 0.0).then(|| 1.0 / c)
    }
}
