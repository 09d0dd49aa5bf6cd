//! Velocity analysis of the 3-PRS: the actuation Jacobian ∂s/∂(z, ψ, θ), the 6×6
//! constraint-embedded inverse Jacobian and the leg-plane constraint residuals.

use super::{KinematicsError, Pose, Prs};
use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};

impl Prs {
    /// Actuation Jacobian ∂s/∂(z, ψ, θ) at a pose (mm/mm, mm/rad), parasitic coupling included.
    pub fn actuation_jacobian(&self, z: f64, psi: f64, theta: f64) -> Result<Matrix3<f64>, KinematicsError> {
        let sol = self.ikp(z, psi, theta)?;
        let q = Vector3::new(z, psi, theta);
        let (_, jq) = self.residual(&sol.s, &q);
        // f(s, q) = 0 ⇒ ∂f/∂s · ds + ∂f/∂q · dq = 0, with ∂fᵢ/∂sᵢ = −eᵢ·(Bᵢ − Cᵢ)/L.
        let pose = sol.pose;
        let mut out = Matrix3::zeros();
        for i in 0..3 {
            let w = self.b_point(i, &pose) - self.c_point(i, sol.s[i]);
            let dfds = -self.e(i).dot(&w) / self.l;
            for k in 0..3 {
                out[(i, k)] = -jq[(i, k)] / dfds;
            }
        }
        Ok(out)
    }

    /// The 6×6 constraint-embedded inverse Jacobian G (Nigatu et al. Eqs. 1–2) at a pose:
    /// `[ṡ; 0] = G · [v; ω]` with v the velocity of P and ω the angular velocity (fixed frame).
    ///
    /// Rows 1–3 (actuation): `[lᵢᵀ, (aᵢ × lᵢ)ᵀ] / (lᵢ·eᵢ)`; rows 4–6 (constraints, Bᵢ cannot
    /// leave its leg plane): `[mᵢᵀ, (aᵢ × mᵢ)ᵀ]`, where lᵢ is the unit leg vector C→B,
    /// aᵢ = Bᵢ − P and mᵢ the revolute axis. (Nigatu et al. writes lᵢ × aᵢ for a vector aᵢ from B
    /// to P; the moment is the same.)
    pub fn constraint_jacobian(&self, pose: &Pose) -> Result<Matrix6<f64>, KinematicsError> {
        let sol = self.ikp(pose.z, pose.psi, pose.theta)?;
        let (p, _) = self.placement(&sol.pose);
        let mut g = Matrix6::zeros();
        for i in 0..3 {
            let bi = self.b_point(i, &sol.pose);
            let l = (bi - self.c_point(i, sol.s[i])) / self.l;
            let arm = bi - p;
            let le = l.dot(&self.e(i));
            let m = self.m(i);
            let row_a = Vector6::from_iterator(l.iter().chain(arm.cross(&l).iter()).copied()) / le;
            let row_c = Vector6::from_iterator(m.iter().chain(arm.cross(&m).iter()).copied());
            g.set_row(i, &row_a.transpose());
            g.set_row(i + 3, &row_c.transpose());
        }
        Ok(g)
    }

    /// The constraint residuals Bᵢ × dᵢ · z (mm): zero when every spherical joint lies in its
    /// leg plane.
    pub fn plane_residuals(&self, pose: &Pose) -> [f64; 3] {
        let mut out = [0.0; 3];
        for (i, o) in out.iter_mut().enumerate() {
            *o = self.b_point(i, pose).cross(&self.d(i))[2];
        }
        out
    }
}
