//! Rigid-body (Jacobian) stiffness of 3-PRS parallel mechanisms with compliant legs.
//!
//! Geometry and orientation follow [`crate::kinematics::prs`]: fixed frame {x, y, z} at the base
//! centre O, `R = Ry(θ)·Rx(ψ)·Rz(φ)`, leg planes at ξᵢ = 0°, 120°, 240°, slider direction
//! `eᵢ = −cos γ·dᵢ + sin γ·z` from `Aᵢ = a·dᵢ`, revolute centre `Cᵢ = Aᵢ + sᵢ·eᵢ`, spherical centre
//! `Bᵢ = p + R·(b dᵢ)`, `|Bᵢ − Cᵢ| = L`. Unlike [`crate::kinematics::Prs`], poses here are
//! **absolute**: `p_z` is the height of the platform centre P above the plane of the Aᵢ (negative
//! when the platform hangs below the base), strokes `sᵢ` are measured from `Aᵢ`, any γ in
//! [−90°, 90°] is allowed and either root of the leg equation (the IKP branch) can be chosen.
//!
//! The stiffness model is the constraint-embedded one of H. Nigatu, L. Jihao, K. Zhu, J. Zhang,
//! H. Guo, G. Lu and D. Kim, "The Stiffness of 3-PRS PM Across Parasitic and Orientational
//! Workspace" (Eqs. 1–2, 16, 23): `K = G·𝒦·Gᵀ` with G the 6×6 wrench matrix whose columns are the
//! unit actuation and constraint wrenches of the legs and `𝒦 = diag(k_a1, k_a2, k_a3, k_c1, k_c2,
//! k_c3)` the leg stiffnesses; the actuation-only special case `K = k·JᵀJ` is the one of
//! L. A. Khan, M. Rameez, K. Nazir, H. Liaquat, A. Raza and T. U. Islam, "Stiffness Analysis of
//! 3-PRS Parallel Kinematic Mechanism", Technical Journal, University of Engineering and
//! Technology (UET) Taxila (Eqs. 14–18), and the screw + link leg model follows X. Han, Y. Wang
//! and J. Shi, "Stiffness Modeling of 3-PRS Mechanism" (Eqs. 1–9).
//!
//! # Conventions
//! - Twists `[v; ω]`: v the velocity (small displacement, mm) of the reference point Q, ω the
//!   angular velocity (small rotation vector, rad), both in the fixed frame.
//! - Wrenches `[f; m]`: force f (N) and moment m (N·mm) **about the reference point Q**, with
//!   `m = r × f` for a force f applied at a point Q + r. Power is `fᵀv + mᵀω`.
//! - The columns of G are unit wrenches about Q: actuation `[lᵢ; rᵢ × lᵢ]/(lᵢ·eᵢ)` (the platform
//!   wrench of a unit axial actuator force), constraint `[mᵢ; rᵢ × mᵢ]` (a unit force along the
//!   revolute axis mᵢ at Bᵢ), with lᵢ the unit leg vector C→B and `rᵢ = Bᵢ − Q`. The joint rates are
//!   `[ṡ; 0] = Gᵀ·[v; ω]` (the second block states that Bᵢ cannot leave its leg plane). Nigatu et
//!   al. print the moment part as `lᵢ × aᵢ` with aᵢ from the platform centre to Bᵢ, which is the
//!   opposite sign: it contradicts their own constraint `mᵢ·v_B = 0` (see
//!   [`parasitic_rate_coupling`]).
//! - Stiffness K (6×6) in N/mm, N (= N·mm/mm) and N·mm/rad blocks; compliance `C = K⁻¹` computed as
//!   `G⁻ᵀ·𝒞·G⁻¹`, which stays finite when a stiffness is rigid (𝒞 entry 0).
//! - Eigenvalues of the mixed matrix are taken in a length-scaled basis: rotations are multiplied
//!   by a characteristic length ℓ (mm), `y = [δp; ℓ·δα]`, so `K̃ = T·K·T` with
//!   `T = diag(1, 1, 1, 1/ℓ, 1/ℓ, 1/ℓ)` has all entries in N/mm; eigenvectors are given in y.
//!   ℓ = 1000 mm (rotations in metres of arc per metre, i.e. SI units) reproduces Khan et al.

use crate::kinematics::prs::{orientation, parasitic_phi, radial, revolute_axis, slider_dir};
use nalgebra::{Matrix3, Matrix6, Vector3};
use thiserror::Error;

mod coupling;
mod legs;
mod map;
mod stiffness;

pub use coupling::{parasitic_rate_coupling, MomentSign};
pub use legs::{LegModel, Link, Screw, ScrewMount};
pub use map::{map, stiffness_limited, Grid, MapCell, MapMetric};
pub use stiffness::{scaled_eigen, PoseStiffness, PrsStiffness, ScaledEigen};

/// Errors of the stiffness model.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum StiffnessError {
    /// The geometry or a leg model is not valid.
    #[error("invalid 3-PRS stiffness input: {0}")]
    Input(String),
    /// A leg cannot reach its spherical joint.
    #[error("pose p_z = {pz} mm, ψ = {psi_deg:.6}°, θ = {theta_deg:.6}° is unreachable: leg {leg} needs {needed:.6} mm in its leg plane, has L = {length} mm")]
    Unreachable {
        /// Absolute platform height, mm.
        pz: f64,
        /// ψ, degrees.
        psi_deg: f64,
        /// θ, degrees.
        theta_deg: f64,
        /// Leg number, 1-based.
        leg: usize,
        /// Distance from the slider line to Bᵢ, mm.
        needed: f64,
        /// Leg length, mm.
        length: f64,
    },
    /// The wrench matrix or an actuator is singular at this pose.
    #[error("singular configuration at p_z = {pz} mm, ψ = {psi_deg:.6}°, θ = {theta_deg:.6}°: {what}")]
    Singular {
        /// Absolute platform height, mm.
        pz: f64,
        /// ψ, degrees.
        psi_deg: f64,
        /// θ, degrees.
        theta_deg: f64,
        /// What is singular.
        what: String,
    },
    /// A leg stiffness model does not apply at this pose (e.g. the nut left the screw).
    #[error("leg {leg} stiffness at p_z = {pz} mm, ψ = {psi_deg:.6}°, θ = {theta_deg:.6}°: {what}")]
    LegModel {
        /// Leg number, 1-based.
        leg: usize,
        /// Absolute platform height, mm.
        pz: f64,
        /// ψ, degrees.
        psi_deg: f64,
        /// θ, degrees.
        theta_deg: f64,
        /// Why.
        what: String,
    },
}

/// Which root of the leg equation `|Aᵢ + sᵢeᵢ − Bᵢ|² = L²` the IKP takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Branch {
    /// `sᵢ = eᵢ·Dᵢ − √disc`: the leg points along +eᵢ from Cᵢ to Bᵢ (`lᵢ·eᵢ > 0`), as in the
    /// usual layouts (the home branch of [`crate::kinematics::Prs`]).
    #[default]
    Minus,
    /// `sᵢ = eᵢ·Dᵢ + √disc`: the slider has passed Bᵢ (`lᵢ·eᵢ < 0`).
    Plus,
}

/// Geometry of a 3-PRS for the stiffness model (lengths mm, angles rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrsLayout {
    /// Base radius a (O to each zero-stroke slider point Aᵢ), mm.
    pub a: f64,
    /// Platform radius b (P to each spherical joint centre), mm.
    pub b: f64,
    /// Leg length L (revolute centre to spherical centre), mm.
    pub l: f64,
    /// Actuator inclination γ, rad: 0 horizontal inward, +90° vertical up, negative = inward-down.
    pub gamma: f64,
    /// IKP branch.
    pub branch: Branch,
}

/// Kinematic state of one pose: parasitic coordinates, strokes, joint points.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PoseState {
    /// Absolute height of P, mm.
    pub pz: f64,
    /// ψ (about x), rad.
    pub psi: f64,
    /// θ (about y), rad.
    pub theta: f64,
    /// Parasitic rotation φ = atan2(sψ·sθ, cψ + cθ), rad.
    pub phi: f64,
    /// Parasitic translation pₓ = (b/2)(uₓ − v_y), mm.
    pub px: f64,
    /// Parasitic translation p_y = −b·u_y, mm.
    pub py: f64,
    /// Platform rotation matrix.
    pub r: Matrix3<f64>,
    /// Strokes sᵢ from Aᵢ along eᵢ, mm.
    pub s: [f64; 3],
    /// Spherical joint centres Bᵢ, mm.
    pub b_pts: [Vector3<f64>; 3],
    /// Revolute joint centres Cᵢ, mm.
    pub c_pts: [Vector3<f64>; 3],
    /// Unit leg vectors lᵢ = (Bᵢ − Cᵢ)/L.
    pub legs: [Vector3<f64>; 3],
}

impl PoseState {
    /// Platform centre P, mm.
    pub fn p(&self) -> Vector3<f64> {
        Vector3::new(self.px, self.py, self.pz)
    }
}

impl PrsLayout {
    /// A validated layout. `gamma` in rad.
    pub fn new(a: f64, b: f64, l: f64, gamma: f64, branch: Branch) -> Result<Self, StiffnessError> {
        for (name, v) in [("a", a), ("b", b), ("L", l)] {
            if !(v.is_finite() && v > 0.0) {
                return Err(StiffnessError::Input(format!(
                    "{name} = {v} mm must be a positive number"
                )));
            }
        }
        if !(gamma.is_finite() && gamma.abs() <= std::f64::consts::FRAC_PI_2 + 1e-12) {
            return Err(StiffnessError::Input(format!(
                "gamma = {}° must lie in [−90°, 90°]",
                gamma.to_degrees()
            )));
        }
        Ok(PrsLayout { a, b, l, gamma, branch })
    }

    /// Unit slider direction eᵢ = −cos γ·dᵢ + sin γ·z (0-based leg; the radial direction dᵢ and
    /// the revolute axis mᵢ, the normal of the leg plane, do not depend on the layout:
    /// [`radial`], [`revolute_axis`]).
    pub fn e(&self, i: usize) -> Vector3<f64> {
        slider_dir(self.gamma, i)
    }

    /// Inverse kinematics at absolute height `pz` (mm) and tilts `psi`, `theta` (rad).
    pub fn pose(&self, pz: f64, psi: f64, theta: f64) -> Result<PoseState, StiffnessError> {
        if !(pz.is_finite() && psi.is_finite() && theta.is_finite()) {
            return Err(StiffnessError::Input(format!(
                "pose (p_z = {pz} mm, ψ = {psi} rad, θ = {theta} rad) must be finite"
            )));
        }
        let phi = parasitic_phi(psi, theta);
        let r = orientation(psi, theta, phi);
        let px = 0.5 * self.b * (r[(0, 0)] - r[(1, 1)]);
        let py = -self.b * r[(1, 0)];
        let p = Vector3::new(px, py, pz);
        let mut s = [0.0; 3];
        let mut b_pts = [Vector3::zeros(); 3];
        let mut c_pts = [Vector3::zeros(); 3];
        let mut legs = [Vector3::zeros(); 3];
        for i in 0..3 {
            let e = self.e(i);
            let bi = p + r * (self.b * radial(i));
            let dv = bi - self.a * radial(i);
            let ed = e.dot(&dv);
            let disc = ed * ed - dv.norm_squared() + self.l * self.l;
            if disc < 0.0 {
                return Err(StiffnessError::Unreachable {
                    pz,
                    psi_deg: psi.to_degrees(),
                    theta_deg: theta.to_degrees(),
                    leg: i + 1,
                    needed: (dv.norm_squared() - ed * ed).max(0.0).sqrt(),
                    length: self.l,
                });
            }
            s[i] = match self.branch {
                Branch::Minus => ed - disc.sqrt(),
                Branch::Plus => ed + disc.sqrt(),
            };
            let ci = self.a * radial(i) + s[i] * e;
            b_pts[i] = bi;
            c_pts[i] = ci;
            legs[i] = (bi - ci) / self.l;
        }
        Ok(PoseState {
            pz,
            psi,
            theta,
            phi,
            px,
            py,
            r,
            s,
            b_pts,
            c_pts,
            legs,
        })
    }

    /// Twist map T (6×3): the platform twist `[v_P; ω]` per unit change of the independent
    /// coordinates q = (p_z, ψ, θ), the parasitic x, y, φ following the constraints
    /// (units: v per mm, v per rad in mm/rad, ω per rad).
    pub fn twist_map(&self, st: &PoseState) -> nalgebra::Matrix6x3<f64> {
        let (sps, cps) = st.psi.sin_cos();
        let (sth, cth) = st.theta.sin_cos();
        let num = sps * sth;
        let den = cps + cth;
        let q = num * num + den * den;
        let dphi_dpsi = (den * cps * sth + num * sps) / q;
        let dphi_dth = (den * sps * cth + num * sth) / q;
        let ry = crate::kinematics::prs::rot_y(st.theta);
        let rx = crate::kinematics::prs::rot_x(st.psi);
        let w_phi = ry * rx * Vector3::z();
        let om_psi = ry * Vector3::x() + dphi_dpsi * w_phi;
        let om_th = Vector3::y() + dphi_dth * w_phi;
        let u = st.r.column(0).into_owned();
        let v = st.r.column(1).into_owned();
        let b = self.b;
        let lin = |om: &Vector3<f64>| {
            let du = om.cross(&u);
            let dv = om.cross(&v);
            Vector3::new(0.5 * b * (du[0] - dv[1]), -b * du[1], 0.0)
        };
        let mut t = nalgebra::Matrix6x3::zeros();
        t[(2, 0)] = 1.0;
        for (k, om) in [(1usize, om_psi), (2, om_th)] {
            let vl = lin(&om);
            for j in 0..3 {
                t[(j, k)] = vl[j];
                t[(j + 3, k)] = om[j];
            }
        }
        t
    }

    /// The 6×6 wrench matrix G about the reference point `q` (mm, fixed frame): columns 1–3 the
    /// unit actuation wrenches `[lᵢ; rᵢ × lᵢ]/(lᵢ·eᵢ)`, columns 4–6 the unit constraint wrenches
    /// `[mᵢ; rᵢ × mᵢ]`, `rᵢ = Bᵢ − q` (see the module conventions).
    pub fn wrench_matrix(&self, st: &PoseState, q: &Vector3<f64>) -> Result<Matrix6<f64>, StiffnessError> {
        let mut g = Matrix6::zeros();
        for i in 0..3 {
            let l = st.legs[i];
            let le = l.dot(&self.e(i));
            if le.abs() < 1e-9 {
                return Err(self.singular(
                    st,
                    format!("leg {} is perpendicular to its slider (lᵢ·eᵢ = {le:.3e})", i + 1),
                ));
            }
            let r = st.b_pts[i] - q;
            let m = revolute_axis(i);
            let fa = l / le;
            let ma = r.cross(&fa);
            let mc = r.cross(&m);
            for j in 0..3 {
                g[(j, i)] = fa[j];
                g[(j + 3, i)] = ma[j];
                g[(j, i + 3)] = m[j];
                g[(j + 3, i + 3)] = mc[j];
            }
        }
        Ok(g)
    }

    /// The 3×3 actuation Jacobian ∂s/∂(p_z, ψ, θ) (mm/mm, mm/rad), parasitic motion included:
    /// `J = G_aᵀ·T` with G_a the actuation columns of G about P.
    pub fn actuation_jacobian(&self, st: &PoseState) -> Result<Matrix3<f64>, StiffnessError> {
        let g = self.wrench_matrix(st, &st.p())?;
        let t = self.twist_map(st);
        let gt = g.transpose() * t;
        Ok(gt.fixed_view::<3, 3>(0, 0).into_owned())
    }

    fn singular(&self, st: &PoseState, what: String) -> StiffnessError {
        StiffnessError::Singular {
            pz: st.pz,
            psi_deg: st.psi.to_degrees(),
            theta_deg: st.theta.to_degrees(),
            what,
        }
    }
}
