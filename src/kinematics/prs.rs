//! Rigid-body kinematics of the 3-PRS parallel mechanism (Ruiz et al. 2019, §3).
//!
//! Fixed frame {x, y, z} at the base centre O, z up; moving frame {u, v, w} at the platform
//! centre P. Orientation `R = Ry(θ)·Rx(ψ)·Rz(φ)`. Leg i lies in the vertical plane through O
//! and `dᵢ = [cos ξᵢ, sin ξᵢ, 0]`, ξᵢ = 0°, 120°, 240°. The slider moves along
//! `eᵢ = −cos γ·dᵢ + sin γ·z` from `Aᵢ = a·dᵢ` (zero stroke); the revolute joint centre is
//! `Cᵢ = Aᵢ + sᵢ·eᵢ`, the spherical joint `Bᵢ = p + R·(b dᵢ)`, and `|Bᵢ − Cᵢ| = L`.
//!
//! The revolute joints keep each `Bᵢ` in its leg plane; this fixes the parasitic motions
//! `φ = atan2(sψ·sθ, cψ + cθ)`, `pₓ = (b/2)(uₓ − v_y)`, `p_y = −b·u_y` (Ruiz et al. (2019) Eqs. 13–15).
//!
//! All poses in this module's public API are measured from the home pose (ψ = θ = φ = 0,
//! `p = [0, 0, z₀]`): `z` is the platform's vertical displacement from home, in mm.

use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};
use thiserror::Error;

/// Leg plane angles ξᵢ, rad.
pub(crate) const XI: [f64; 3] = [
    0.0,
    2.0 * std::f64::consts::FRAC_PI_3,
    4.0 * std::f64::consts::FRAC_PI_3,
];

/// Unit radial direction dᵢ = Rz(ξᵢ)·[1, 0, 0] of leg `i` (0-based).
pub fn radial(i: usize) -> Vector3<f64> {
    Vector3::new(XI[i].cos(), XI[i].sin(), 0.0)
}

/// Unit slider direction eᵢ = −cos γ·dᵢ + sin γ·z of leg `i` for actuator inclination `gamma` (rad).
pub(crate) fn slider_dir(gamma: f64, i: usize) -> Vector3<f64> {
    -gamma.cos() * radial(i) + gamma.sin() * Vector3::z()
}

/// Revolute axis mᵢ = Rz(ξᵢ)·[0, 1, 0] of leg `i` (normal of the leg plane).
pub fn revolute_axis(i: usize) -> Vector3<f64> {
    Vector3::new(-XI[i].sin(), XI[i].cos(), 0.0)
}

/// Errors of the rigid-body kinematics.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum KinematicsError {
    /// The geometry is not a valid 3-PRS.
    #[error("invalid 3-PRS geometry: {0}")]
    Geometry(String),
    /// A pose that no stroke can reach (a leg is too short).
    #[error("pose unreachable: leg {leg} cannot reach its spherical joint (needs {needed:.6} mm of leg in the slider plane, has L = {length} mm)")]
    Unreachable {
        /// Leg number, 1-based.
        leg: usize,
        /// Distance needed, mm.
        needed: f64,
        /// Leg length L, mm.
        length: f64,
    },
    /// The forward kinematics did not converge.
    #[error("forward kinematics did not converge for strokes {strokes:?} mm after {iterations} Newton iterations (residual {residual:.3e} mm): {reason}")]
    NoConvergence {
        /// Actuator strokes, mm.
        strokes: [f64; 3],
        /// Iterations performed.
        iterations: usize,
        /// Final residual of the leg-length equations, mm.
        residual: f64,
        /// Why it stopped.
        reason: String,
    },
    /// The Jacobian is singular (a singular configuration of the mechanism).
    #[error("singular configuration at z = {z:.6} mm, ψ = {psi_deg:.6}°, θ = {theta_deg:.6}°: the actuation Jacobian has determinant {det:.3e}")]
    Singular {
        /// Platform z displacement from home, mm.
        z: f64,
        /// ψ, degrees.
        psi_deg: f64,
        /// θ, degrees.
        theta_deg: f64,
        /// Determinant of ∂f/∂(z, ψ, θ).
        det: f64,
    },
}

/// Geometry of a 3-PRS mechanism.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Prs {
    /// Leg length L (revolute centre to spherical centre), mm.
    pub l: f64,
    /// Platform radius b (P to each spherical joint centre), mm.
    pub b: f64,
    /// Base radius a (O to each slider's zero-stroke point Aᵢ), mm.
    pub a: f64,
    /// Actuator inclination γ, rad (0 = horizontal radially inward, π/2 = vertical).
    pub gamma: f64,
    /// Home height z₀ of the platform centre above the plane of the Aᵢ, mm.
    pub z0: f64,
}

/// A platform pose measured from home: displacements in mm, angles in rad.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Pose {
    /// x displacement of P, mm.
    pub x: f64,
    /// y displacement of P, mm.
    pub y: f64,
    /// z displacement of P from home, mm.
    pub z: f64,
    /// Rotation ψ about x, rad.
    pub psi: f64,
    /// Rotation θ about y, rad.
    pub theta: f64,
    /// Rotation φ about z, rad.
    pub phi: f64,
}

/// Inverse kinematics solution at one pose.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IkpSolution {
    /// Actuator strokes sᵢ, mm (0 at home).
    pub s: [f64; 3],
    /// Full pose including the parasitic x, y, φ.
    pub pose: Pose,
    /// Revolute angles αᵢ = arccos(eᵢ·lᵢ), rad.
    pub alpha: [f64; 3],
    /// Spherical joint angles [βm, βn, βl] per leg, rad (intrinsic m-n-l sequence).
    pub spherical: [[f64; 3]; 3],
}

/// Forward kinematics solution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FkpSolution {
    /// Platform pose (parasitic components included).
    pub pose: Pose,
    /// Newton iterations used.
    pub iterations: usize,
}

/// Rotation about x by `a` rad.
pub fn rot_x(a: f64) -> Matrix3<f64> {
    let (s, c) = a.sin_cos();
    Matrix3::new(1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c)
}
/// Rotation about y by `a` rad.
pub fn rot_y(a: f64) -> Matrix3<f64> {
    let (s, c) = a.sin_cos();
    Matrix3::new(c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c)
}
/// Rotation about z by `a` rad.
pub fn rot_z(a: f64) -> Matrix3<f64> {
    let (s, c) = a.sin_cos();
    Matrix3::new(c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0)
}
fn drot_x(a: f64) -> Matrix3<f64> {
    let (s, c) = a.sin_cos();
    Matrix3::new(0.0, 0.0, 0.0, 0.0, -s, -c, 0.0, c, -s)
}
fn drot_y(a: f64) -> Matrix3<f64> {
    let (s, c) = a.sin_cos();
    Matrix3::new(-s, 0.0, c, 0.0, 0.0, 0.0, -c, 0.0, -s)
}
fn drot_z(a: f64) -> Matrix3<f64> {
    let (s, c) = a.sin_cos();
    Matrix3::new(-s, -c, 0.0, c, -s, 0.0, 0.0, 0.0, 0.0)
}

/// Platform orientation `R = Ry(θ)·Rx(ψ)·Rz(φ)`.
pub fn orientation(psi: f64, theta: f64, phi: f64) -> Matrix3<f64> {
    rot_y(theta) * rot_x(psi) * rot_z(phi)
}

/// Parasitic rotation φ = atan2(sψ·sθ, cψ + cθ), rad (Ruiz et al. (2019) Eq. 13).
pub fn parasitic_phi(psi: f64, theta: f64) -> f64 {
    (psi.sin() * theta.sin()).atan2(psi.cos() + theta.cos())
}

/// Angles [a, b, c] of the intrinsic x-y-z sequence `M = Rx(a)·Ry(b)·Rz(c)`, rad.
pub fn intrinsic_xyz(m: &Matrix3<f64>) -> [f64; 3] {
    let b = m[(0, 2)].clamp(-1.0, 1.0).asin();
    let a = (-m[(1, 2)]).atan2(m[(2, 2)]);
    let c = (-m[(0, 1)]).atan2(m[(0, 0)]);
    [a, b, c]
}

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
    /// The 3-PRS of Ruiz et al. (2019) §3 with `a = b + L·cos α₀`, home height `z₀ = L·sin α₀`.
    ///
    /// `l`, `b` in mm; `alpha0` (leg angle to the horizontal at home) and `gamma` in rad.
    pub fn new(l: f64, b: f64, alpha0: f64, gamma: f64) -> Result<Self, KinematicsError> {
        Self::check_common(l, b, gamma)?;
        if !(alpha0 > 0.0 && alpha0 < std::f64::consts::FRAC_PI_2) {
            return Err(KinematicsError::Geometry(format!(
                "alpha0 = {}° must lie in (0°, 90°)",
                alpha0.to_degrees()
            )));
        }
        let prs = Prs {
            l,
            b,
            a: b + l * alpha0.cos(),
            gamma,
            z0: l * alpha0.sin(),
        };
        prs.check_actuation()?;
        Ok(prs)
    }

    /// A 3-PRS given the base radius `a` instead of α₀: home height `z₀ = √(L² − (a − b)²)`.
    pub fn with_base_radius(l: f64, b: f64, a: f64, gamma: f64) -> Result<Self, KinematicsError> {
        Self::check_common(l, b, gamma)?;
        if !(a.is_finite() && a > 0.0) {
            return Err(KinematicsError::Geometry(format!("a = {a} mm must be positive")));
        }
        let h2 = l * l - (a - b) * (a - b);
        if h2 <= 0.0 {
            return Err(KinematicsError::Geometry(format!(
                "L = {l} mm is too short to reach from the base circle (a = {a} mm) to the platform circle (b = {b} mm): L must exceed |a − b| = {} mm",
                (a - b).abs()
            )));
        }
        let prs = Prs {
            l,
            b,
            a,
            gamma,
            z0: h2.sqrt(),
        };
        prs.check_actuation()?;
        Ok(prs)
    }

    fn check_common(l: f64, b: f64, gamma: f64) -> Result<(), KinematicsError> {
        if !(l.is_finite() && l > 0.0) {
            return Err(KinematicsError::Geometry(format!("L = {l} mm must be positive")));
        }
        if !(b.is_finite() && b > 0.0) {
            return Err(KinematicsError::Geometry(format!("b = {b} mm must be positive")));
        }
        if !(gamma.is_finite() && gamma.abs() <= std::f64::consts::FRAC_PI_2 + 1e-12) {
            return Err(KinematicsError::Geometry(format!(
                "gamma = {}° must lie in [−90°, 90°]",
                gamma.to_degrees()
            )));
        }
        Ok(())
    }

    /// Refuses layouts where the slider is (nearly) perpendicular to the leg at home:
    /// there the actuator cannot move the platform (an actuation singularity).
    fn check_actuation(&self) -> Result<(), KinematicsError> {
        let c = self.e(0).dot(&self.leg_home(0)) / self.l;
        if c < 0.05 {
            return Err(KinematicsError::Geometry(format!(
                "the slider direction is within {:.1}° of perpendicular to the leg at home (α₀ − γ ≈ ±90°): actuation singularity",
                90.0 - c.clamp(-1.0, 1.0).acos().to_degrees()
            )));
        }
        Ok(())
    }

    /// The leg angle to the horizontal at home, α₀, rad.
    pub fn alpha0(&self) -> f64 {
        self.z0.atan2(self.a - self.b)
    }

    /// Unit radial direction dᵢ of leg `i` (0-based).
    pub fn d(&self, i: usize) -> Vector3<f64> {
        radial(i)
    }

    /// Unit slider direction eᵢ = −cos γ·dᵢ + sin γ·z.
    pub fn e(&self, i: usize) -> Vector3<f64> {
        slider_dir(self.gamma, i)
    }

    /// Revolute axis mᵢ = Rz(ξᵢ)·[0, 1, 0].
    pub fn m(&self, i: usize) -> Vector3<f64> {
        revolute_axis(i)
    }

    /// Zero-stroke slider point Aᵢ = a·dᵢ, mm.
    pub fn a_point(&self, i: usize) -> Vector3<f64> {
        self.a * self.d(i)
    }

    /// Revolute joint centre Cᵢ = Aᵢ + sᵢ·eᵢ, mm.
    pub fn c_point(&self, i: usize, s: f64) -> Vector3<f64> {
        self.a_point(i) + s * self.e(i)
    }

    /// Spherical joint centre Bᵢ at the home pose, mm.
    pub fn b_home(&self, i: usize) -> Vector3<f64> {
        self.b * self.d(i) + self.z0 * Vector3::z()
    }

    /// Platform centre P at the home pose, mm.
    pub fn p_home(&self) -> Vector3<f64> {
        self.z0 * Vector3::z()
    }

    fn leg_home(&self, i: usize) -> Vector3<f64> {
        self.b_home(i) - self.a_point(i)
    }

    /// Leg frame Fᵢ₀ = [mᵢ₀ nᵢ₀ lᵢ₀] for a leg direction `l` (unit, C→B).
    fn leg_frame(&self, i: usize, l: &Vector3<f64>) -> Matrix3<f64> {
        let m = self.m(i);
        let n = l.cross(&m);
        Matrix3::from_columns(&[m, n, *l])
    }

    /// Full pose (with parasitic x, y, φ) for independent coordinates measured from home.
    pub fn complete_pose(&self, z: f64, psi: f64, theta: f64) -> Pose {
        let phi = parasitic_phi(psi, theta);
        let r = orientation(psi, theta, phi);
        Pose {
            x: 0.5 * self.b * (r[(0, 0)] - r[(1, 1)]),
            y: -self.b * r[(1, 0)],
            z,
            psi,
            theta,
            phi,
        }
    }

    /// Absolute platform centre and rotation of a pose.
    pub fn placement(&self, pose: &Pose) -> (Vector3<f64>, Matrix3<f64>) {
        (
            Vector3::new(pose.x, pose.y, self.z0 + pose.z),
            orientation(pose.psi, pose.theta, pose.phi),
        )
    }

    /// Spherical joint centre Bᵢ = p + R·(b dᵢ) for a full pose, mm.
    pub fn b_point(&self, i: usize, pose: &Pose) -> Vector3<f64> {
        let (p, r) = self.placement(pose);
        p + r * (self.b * self.d(i))
    }

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
    fn residual(&self, s: &[f64; 3], q: &Vector3<f64>) -> (Vector3<f64>, Matrix3<f64>) {
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

    /// Parasitic rotation φ of the platform for given ψ, θ (rad); exposed for completeness.
    pub fn phi(&self, psi: f64, theta: f64) -> f64 {
        self.platform(0.0, psi, theta).phi
    }
}
