//! Position analysis of the 3-PRS: inverse kinematics ([`Prs::ikp`]: strokes, parasitic
//! motion, passive joint angles) and forward kinematics ([`Prs::fkp`], Newton's method on the
//! leg-length residuals with their analytic Jacobian).

use super::rotation::{drot_x, drot_y, drot_z, intrinsic_xyz, rot_x, rot_y, rot_z};
use super::{FkpSolution, IkpSolution, KinematicsError, Pose, Prs};
use nalgebra::{Matrix3, Vector3};

/// Pose-dependent quantities and their derivatives with respect to the independent
/// coordinates q = (p_z, ψ, θ), with φ, pₓ, p_y eliminated by the constraints.
struct Platform {
    p: Vector3<f64>,
    r: Matrix3<f64>,
    phi: f64,
    /// dp/dq columns.
    dp: [Vector3<f64>; 3],
    /// dR/dq (total, through φ).
    dr: [Matrix3<f64>; 3],
}

impl Prs {
    fn platform(&self, z: f64, psi: f64, theta: f64) -> Platform {
        let (sps, cps) = psi.sin_cos();
        let (sth, cth) = theta.sin_cos();
        let num = sps * sth;
        let den = cps + cth;
        let phi = num.atan2(den);
        let q = num * num + den * den;
        let dphi_dpsi = (den * cps * sth + num * sps) / q;
        let dphi_dth = (den * sps * cth + num * sth) / q;
        let (ry, rx, rz) = (rot_y(theta), rot_x(psi), rot_z(phi));
        let r = ry * rx * rz;
        let r_phi = ry * rx * drot_z(phi);
        let dr_psi = ry * drot_x(psi) * rz + r_phi * dphi_dpsi;
        let dr_th = drot_y(theta) * rx * rz + r_phi * dphi_dth;
        let b = self.b;
        let dpar = |d: &Matrix3<f64>| Vector3::new(0.5 * b * (d[(0, 0)] - d[(1, 1)]), -b * d[(1, 0)], 0.0);
        Platform {
            p: Vector3::new(0.5 * b * (r[(0, 0)] - r[(1, 1)]), -b * r[(1, 0)], self.z0 + z),
            r,
            phi,
            dp: [Vector3::z(), dpar(&dr_psi), dpar(&dr_th)],
            dr: [Matrix3::zeros(), dr_psi, dr_th],
        }
    }

    /// Inverse kinematics (Ruiz et al. (2019) §3.2–3.3): strokes, parasitic motion and passive joint
    /// angles for the independent coordinates `z` (mm from home), `psi`, `theta` (rad).
    pub fn ikp(&self, z: f64, psi: f64, theta: f64) -> Result<IkpSolution, KinematicsError> {
        let pose = self.complete_pose(z, psi, theta);
        let (p, r) = self.placement(&pose);
        let mut s = [0.0; 3];
        let mut alpha = [0.0; 3];
        let mut spherical = [[0.0; 3]; 3];
        for i in 0..3 {
            let bi = p + r * (self.b * self.d(i));
            let e = self.e(i);
            let dvec = bi - self.a_point(i);
            let ed = e.dot(&dvec);
            // |D − s e|² = L²  ⇒  s² − 2 s (e·D) + |D|² − L² = 0; the root that is 0 at home
            // is the one with the minus sign, since e·D > 0 there (checked in `check_actuation`).
            let disc = ed * ed - dvec.norm_squared() + self.l * self.l;
            if disc < 0.0 {
                return Err(KinematicsError::Unreachable {
                    leg: i + 1,
                    needed: (dvec.norm_squared() - ed * ed).sqrt(),
                    length: self.l,
                });
            }
            s[i] = ed - disc.sqrt();
            let li = (bi - self.c_point(i, s[i])) / self.l;
            alpha[i] = e.dot(&li).clamp(-1.0, 1.0).acos();
            let f0 = self.leg_frame(i, &(self.leg_home(i) / self.l));
            let fi = self.leg_frame(i, &li);
            // R_S = Fᵢ₀ᵀ · R · R_im with R_im = Fᵢ₀(home).
            spherical[i] = intrinsic_xyz(&(fi.transpose() * r * f0));
        }
        Ok(IkpSolution {
            s,
            pose,
            alpha,
            spherical,
        })
    }

    /// Leg-length residuals fᵢ = (|Bᵢ − Cᵢ|² − L²)/(2L), mm, and their Jacobian with respect to
    /// q = (z, ψ, θ).
    pub(super) fn residual(&self, s: &[f64; 3], q: &Vector3<f64>) -> (Vector3<f64>, Matrix3<f64>) {
        let pl = self.platform(q[0], q[1], q[2]);
        let mut f = Vector3::zeros();
        let mut j = Matrix3::zeros();
        for i in 0..3 {
            let bd = self.b * self.d(i);
            let w = pl.p + pl.r * bd - self.c_point(i, s[i]);
            f[i] = (w.norm_squared() - self.l * self.l) / (2.0 * self.l);
            for k in 0..3 {
                j[(i, k)] = w.dot(&(pl.dp[k] + pl.dr[k] * bd)) / self.l;
            }
        }
        (f, j)
    }

    /// Forward kinematics: the pose reached with strokes `s` (mm), by Newton's method with
    /// the analytic Jacobian, starting from `start` (home if `None`).
    pub fn fkp(&self, s: [f64; 3], start: Option<&Pose>) -> Result<FkpSolution, KinematicsError> {
        const MAX_ITER: usize = 50;
        let tol = 1e-12 * self.l.max(1.0);
        if s.iter().any(|v| !v.is_finite()) {
            return Err(KinematicsError::NoConvergence {
                strokes: s,
                iterations: 0,
                residual: f64::NAN,
                reason: "strokes must be finite numbers".into(),
            });
        }
        let mut q = start.map_or(Vector3::zeros(), |p| Vector3::new(p.z, p.psi, p.theta));
        let (mut f, mut j) = self.residual(&s, &q);
        let mut fnorm = f.norm();
        for it in 1..=MAX_ITER {
            let det = j.determinant();
            let jinv = match j.try_inverse() {
                Some(m) if det.abs() > 1e-14 => m,
                _ => {
                    return Err(KinematicsError::Singular {
                        z: q[0],
                        psi_deg: q[1].to_degrees(),
                        theta_deg: q[2].to_degrees(),
                        det,
                    })
                }
            };
            let dq = -(jinv * f);
            // Backtracking line search on |f| keeps far starts from diverging.
            let mut step = 1.0;
            let (mut qn, mut fn_, mut jn);
            loop {
                qn = q + step * dq;
                (fn_, jn) = self.residual(&s, &qn);
                if fn_.norm() < fnorm || step < 1e-4 || fn_.norm() <= tol {
                    break;
                }
                step *= 0.5;
            }
            let converged_step = (step * dq).norm() <= 1e-13 * (1.0 + qn.norm());
            q = qn;
            f = fn_;
            j = jn;
            fnorm = f.norm();
            if !fnorm.is_finite() || q.iter().any(|v| !v.is_finite()) {
                break;
            }
            if fnorm <= tol || (converged_step && fnorm <= 1e3 * tol) {
                return self.finish_fkp(s, q, it);
            }
        }
        Err(KinematicsError::NoConvergence {
            strokes: s,
            iterations: MAX_ITER,
            residual: fnorm,
            reason: "the strokes may be outside the reachable workspace".into(),
        })
    }

    fn finish_fkp(&self, s: [f64; 3], q: Vector3<f64>, iterations: usize) -> Result<FkpSolution, KinematicsError> {
        let pose = self.complete_pose(q[0], q[1], q[2]);
        // Reject other assembly modes: every leg must keep its home branch (e·(B − C) > 0).
        for (i, &si) in s.iter().enumerate() {
            let w = self.b_point(i, &pose) - self.c_point(i, si);
            if self.e(i).dot(&w) <= 0.0
                || q[1].abs() > std::f64::consts::FRAC_PI_2
                || q[2].abs() > std::f64::consts::FRAC_PI_2
            {
                return Err(KinematicsError::NoConvergence {
                    strokes: s,
                    iterations,
                    residual: 0.0,
                    reason: format!("Newton converged to another assembly mode (leg {} flipped)", i + 1),
                });
            }
        }
        Ok(FkpSolution { pose, iterations })
    }

    /// Parasitic rotation φ of the platform for given ψ, θ (rad); exposed for completeness.
    pub fn phi(&self, psi: f64, theta: f64) -> f64 {
        self.platform(0.0, psi, theta).phi
    }
}
