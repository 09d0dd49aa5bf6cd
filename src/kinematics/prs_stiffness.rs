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
use nalgebra::{Matrix3, Matrix3x2, Matrix6, SymmetricEigen, Vector3, Vector6};
use thiserror::Error;

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

/// Which moment sign the velocity-level parasitic coupling uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MomentSign {
    /// `rᵢ × mᵢ` (arm from P to Bᵢ crossed with the constraint direction): consistent with the
    /// position constraint `mᵢ·(Bᵢ − O) = 0` differentiated, `mᵢ·(v + ω × rᵢ) = 0`.
    Consistent,
    /// `mᵢ × rᵢ`, as printed in Nigatu et al. Eqs. 2, 4–7: the opposite sign.
    Printed,
}

/// Velocity-level parasitic coupling of Nigatu et al. (Eqs. 5–8): `[vₓ; v_y; ω_z] = C₁⁻¹C₂·[ωₓ; ω_y]`
/// from the three constraint rows, with the moment sign chosen by `sign`. Returns the 3×2 map
/// (mm/rad and rad/rad), or a singular error when C₁ is not invertible.
pub fn parasitic_rate_coupling(
    layout: &PrsLayout,
    st: &PoseState,
    sign: MomentSign,
) -> Result<Matrix3x2<f64>, StiffnessError> {
    let p = st.p();
    let mut c1 = Matrix3::zeros();
    let mut c2 = Matrix3x2::zeros();
    for i in 0..3 {
        let m = revolute_axis(i);
        let r = st.b_pts[i] - p;
        let mom = match sign {
            MomentSign::Consistent => r.cross(&m),
            MomentSign::Printed => m.cross(&r),
        };
        c1[(i, 0)] = m[0];
        c1[(i, 1)] = m[1];
        c1[(i, 2)] = mom[2];
        c2[(i, 0)] = -mom[0];
        c2[(i, 1)] = -mom[1];
    }
    let inv = c1
        .try_inverse()
        .ok_or_else(|| layout.singular(st, "the parasitic coupling matrix C₁ is singular".into()))?;
    Ok(inv * c2)
}

/// Axial stiffness of a lead screw at the current nut position (Han et al. Eqs. 6–8).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Screw {
    /// Screw cross-section area, mm².
    pub area: f64,
    /// Young's modulus of the screw, MPa.
    pub e: f64,
    /// Mounting.
    pub mount: ScrewMount,
    /// Nut axial stiffness k_n in series, N/mm (`None` = rigid nut).
    pub nut_k: Option<f64>,
}

/// How the screw is supported. The nut sits at the revolute joint; its distance from the fixed
/// (first) bearing is `nut_at_zero_stroke + sᵢ` (mm), measured along eᵢ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ScrewMount {
    /// Fixed–free (or fixed–supported): `k_s = A·E/a` with a the bearing-to-nut distance.
    FixedFree {
        /// Bearing-to-nut distance at zero stroke, mm.
        nut_at_zero_stroke: f64,
    },
    /// Fixed–fixed over length L_s: `k_s = A·E·L_s/(a·b)`, a + b = L_s.
    FixedFixed {
        /// Distance between the two bearings, mm.
        length: f64,
        /// First-bearing-to-nut distance at zero stroke, mm.
        nut_at_zero_stroke: f64,
    },
}

impl Screw {
    /// Axial compliance of screw (+ nut) at stroke `s` (mm), mm/N; `Err(reason)` when the nut is
    /// not between the bearings.
    pub fn compliance(&self, s: f64) -> Result<f64, String> {
        let ae = self.area * self.e;
        let c = match self.mount {
            ScrewMount::FixedFree { nut_at_zero_stroke } => {
                let a = nut_at_zero_stroke + s;
                if a <= 0.0 {
                    return Err(format!("the nut is {a:.3} mm from the fixed bearing (must be > 0)"));
                }
                a / ae
            }
            ScrewMount::FixedFixed {
                length,
                nut_at_zero_stroke,
            } => {
                let a = nut_at_zero_stroke + s;
                let b = length - a;
                if a <= 0.0 || b <= 0.0 {
                    return Err(format!(
                        "the nut is {a:.3} mm from the first bearing, outside the {length} mm between the bearings"
                    ));
                }
                a * b / (ae * length)
            }
        };
        Ok(c + self.nut_k.map_or(0.0, |k| 1.0 / k))
    }
}

/// A straight link of constant section, clamped at the revolute joint, free (spherical) at Bᵢ
/// (Han et al. Eq. 1 with the end moments zero).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Link {
    /// Cross-section area, mm².
    pub area: f64,
    /// Young's modulus, MPa.
    pub e: f64,
    /// Second moment of area for bending out of the leg plane (force along mᵢ), mm⁴.
    pub i_lateral: f64,
}

/// Per-leg stiffness model (the same for all three legs).
#[derive(Debug, Clone, PartialEq)]
pub enum LegModel {
    /// One actuator stiffness on the stroke coordinate, N/mm; the constraint directions rigid
    /// (Khan et al. Eq. 14).
    Actuator {
        /// k, N/mm.
        k: f64,
    },
    /// Series chains (Nigatu et al. Eqs. 18–19): `1/k_a = Σ 1/kⱼ` of the actuation chain
    /// (carriage, revolute, limb body) acting on the stroke coordinate, N/mm; `1/k_c = Σ 1/kⱼ` of the
    /// constraint chain as lateral stiffnesses along mᵢ at Bᵢ, N/mm (empty = rigid).
    Chain {
        /// Actuation-chain stiffnesses, N/mm.
        actuation: Vec<f64>,
        /// Constraint-chain stiffnesses, N/mm.
        constraint: Vec<f64>,
    },
    /// Lead screw on the stroke coordinate in series with the link's axial compliance L/(EA)
    /// (mapped to the stroke coordinate by 1/(lᵢ·eᵢ)²); constraint: the link's lateral bending
    /// L³/(3·E·I) at Bᵢ along mᵢ (Han et al. Eqs. 1, 6–8).
    ScrewLink {
        /// The lead screw.
        screw: Screw,
        /// The link.
        link: Link,
    },
}

impl LegModel {
    /// Checks the parameters (positive, finite).
    pub fn validate(&self) -> Result<(), StiffnessError> {
        let pos = |name: &str, v: f64| {
            if v.is_finite() && v > 0.0 {
                Ok(())
            } else {
                Err(StiffnessError::Input(format!("{name} = {v} must be a positive number")))
            }
        };
        match self {
            LegModel::Actuator { k } => pos("k", *k),
            LegModel::Chain { actuation, constraint } => {
                if actuation.is_empty() {
                    return Err(StiffnessError::Input(
                        "the actuation chain needs at least one stiffness".into(),
                    ));
                }
                for (j, k) in actuation.iter().enumerate() {
                    pos(&format!("actuation[{j}]"), *k)?;
                }
                for (j, k) in constraint.iter().enumerate() {
                    pos(&format!("constraint[{j}]"), *k)?;
                }
                Ok(())
            }
            LegModel::ScrewLink { screw, link } => {
                pos("screw.area", screw.area)?;
                pos("screw.e", screw.e)?;
                if let Some(k) = screw.nut_k {
                    pos("screw.nut_k", k)?;
                }
                match screw.mount {
                    ScrewMount::FixedFree { nut_at_zero_stroke } => {
                        if !nut_at_zero_stroke.is_finite() {
                            return Err(StiffnessError::Input("screw nut_at_zero_stroke must be finite".into()));
                        }
                    }
                    ScrewMount::FixedFixed {
                        length,
                        nut_at_zero_stroke,
                    } => {
                        pos("screw.length", length)?;
                        if !nut_at_zero_stroke.is_finite() {
                            return Err(StiffnessError::Input("screw nut_at_zero_stroke must be finite".into()));
                        }
                    }
                }
                pos("link.area", link.area)?;
                pos("link.e", link.e)?;
                pos("link.i_lateral", link.i_lateral)
            }
        }
    }

    /// Leg compliances `[c_a, c_c]` of leg `i` at a pose: c_a on the stroke coordinate (mm/N),
    /// c_c along mᵢ at Bᵢ (mm/N; 0 = rigid).
    pub fn compliances(&self, layout: &PrsLayout, st: &PoseState, i: usize) -> Result<[f64; 2], StiffnessError> {
        match self {
            LegModel::Actuator { k } => Ok([1.0 / k, 0.0]),
            LegModel::Chain { actuation, constraint } => Ok([
                actuation.iter().map(|k| 1.0 / k).sum(),
                constraint.iter().map(|k| 1.0 / k).sum(),
            ]),
            LegModel::ScrewLink { screw, link } => {
                let cs = screw.compliance(st.s[i]).map_err(|what| StiffnessError::LegModel {
                    leg: i + 1,
                    pz: st.pz,
                    psi_deg: st.psi.to_degrees(),
                    theta_deg: st.theta.to_degrees(),
                    what,
                })?;
                let le = st.legs[i].dot(&layout.e(i));
                let axial = layout.l / (link.e * link.area) / (le * le);
                let lateral = layout.l.powi(3) / (3.0 * link.e * link.i_lateral);
                Ok([cs + axial, lateral])
            }
        }
    }
}

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

/// A quantity mapped over a (ψ, θ) grid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MapMetric {
    /// Diagonal term K_ii of the 6×6 stiffness (0-based, order x, y, z, rx, ry, rz).
    Diagonal(usize),
    /// Directional stiffness 1/C_ii.
    Directional(usize),
    /// Smallest eigenvalue of the length-scaled 6×6 K̃ (N/mm).
    LambdaMin,
    /// Largest eigenvalue of the length-scaled 6×6 K̃ (N/mm).
    LambdaMax,
    /// Smallest eigenvalue of the length-scaled 3×3 stiffness on (p_z, ψ, θ) (N/mm).
    IndependentLambdaMin,
    /// Largest eigenvalue of the length-scaled 3×3 stiffness on (p_z, ψ, θ) (N/mm).
    IndependentLambdaMax,
}

impl MapMetric {
    /// Evaluates the metric; `None` when it is unbounded (rigid legs).
    pub fn eval(&self, ps: &PoseStiffness, length: f64) -> Option<f64> {
        eval_metrics(std::slice::from_ref(self), ps, length)[0]
    }
}

/// Evaluates up to 8 metrics at one pose, each eigen-decomposition at most once.
fn eval_metrics(metrics: &[MapMetric], ps: &PoseStiffness, length: f64) -> [Option<f64>; 8] {
    let mut out = [None; 8];
    let mut full: Option<(f64, f64)> = None;
    let mut indep: Option<(f64, f64)> = None;
    for (o, m) in out.iter_mut().zip(metrics) {
        *o = match *m {
            MapMetric::Diagonal(i) => ps.stiffness.map(|k| k[(i, i)]),
            MapMetric::Directional(i) => ps.directional(i),
            MapMetric::LambdaMin | MapMetric::LambdaMax => {
                let (lo, hi) = *full.get_or_insert_with(|| {
                    // Eigenvalues of K̃ are the reciprocals of those of C̃ = T⁻¹CT⁻¹; using C
                    // keeps rigid legs (λ = ∞) out.
                    let mut cs = ps.compliance;
                    for j in 0..6 {
                        for k in 0..6 {
                            let f = if j >= 3 { length } else { 1.0 } * if k >= 3 { length } else { 1.0 };
                            cs[(j, k)] *= f;
                        }
                    }
                    let ev = cs.symmetric_eigenvalues();
                    ev.iter()
                        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| (a.min(x), b.max(x)))
                });
                if matches!(m, MapMetric::LambdaMin) {
                    (hi > 0.0).then(|| 1.0 / hi)
                } else {
                    (lo > 1e-300).then(|| 1.0 / lo)
                }
            }
            MapMetric::IndependentLambdaMin | MapMetric::IndependentLambdaMax => {
                let (lo, hi) = *indep.get_or_insert_with(|| {
                    let mut k = ps.independent;
                    for j in 0..3 {
                        for c in 0..3 {
                            let f = if j >= 1 { 1.0 / length } else { 1.0 } * if c >= 1 { 1.0 / length } else { 1.0 };
                            k[(j, c)] *= f;
                        }
                    }
                    let ev = k.symmetric_eigenvalues();
                    ev.iter()
                        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| (a.min(x), b.max(x)))
                });
                Some(if matches!(m, MapMetric::IndependentLambdaMin) {
                    lo
                } else {
                    hi
                })
            }
        };
    }
    out
}

/// One cell of a stiffness map.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapCell {
    /// ψ, rad.
    pub psi: f64,
    /// θ, rad.
    pub theta: f64,
    /// Parasitic pₓ, mm (NaN-free: 0 when unreachable).
    pub px: f64,
    /// Parasitic p_y, mm.
    pub py: f64,
    /// Parasitic φ, rad.
    pub phi: f64,
    /// Metric values in the order of the requested metrics; `None` when the pose is
    /// unreachable/singular or the metric unbounded.
    pub values: [Option<f64>; 8],
    /// Whether the pose was reachable and non-singular.
    pub ok: bool,
}

/// A (ψ, θ) grid at fixed height.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grid {
    /// Absolute platform height, mm.
    pub pz: f64,
    /// ψ range, rad.
    pub psi: [f64; 2],
    /// θ range, rad.
    pub theta: [f64; 2],
    /// Points per axis (≥ 2).
    pub n: usize,
}

impl Grid {
    /// The k-th of n equally spaced values in [lo, hi].
    fn at(range: [f64; 2], k: usize, n: usize) -> f64 {
        range[0] + (range[1] - range[0]) * k as f64 / (n - 1) as f64
    }
}

/// Maps up to 8 metrics over a (ψ, θ) grid (row-major: ψ outer, θ inner), in parallel.
/// `length` is the characteristic length ℓ of the eigenvalue metrics, mm.
pub fn map(
    model: &PrsStiffness,
    grid: &Grid,
    tool: &Vector3<f64>,
    metrics: &[MapMetric],
    length: f64,
) -> Result<Vec<MapCell>, StiffnessError> {
    use rayon::prelude::*;
    if grid.n < 2 || metrics.len() > 8 || metrics.is_empty() {
        return Err(StiffnessError::Input(format!(
            "a map needs n ≥ 2 points per axis (got {}) and 1 to 8 metrics (got {})",
            grid.n,
            metrics.len()
        )));
    }
    let n = grid.n;
    Ok((0..n * n)
        .into_par_iter()
        .map(|idx| {
            let psi = Grid::at(grid.psi, idx / n, n);
            let theta = Grid::at(grid.theta, idx % n, n);
            let mut cell = MapCell {
                psi,
                theta,
                px: 0.0,
                py: 0.0,
                phi: 0.0,
                values: [None; 8],
                ok: false,
            };
            if let Ok(ps) = model.at(grid.pz, psi, theta, tool) {
                cell.px = ps.state.px;
                cell.py = ps.state.py;
                cell.phi = ps.state.phi;
                cell.ok = true;
                cell.values = eval_metrics(metrics, &ps, length);
            }
            cell
        })
        .collect())
}

/// Stiffness-limited workspace: which cells of a map have metric `which` (index into the
/// metrics of [`map`]) above `threshold`. Returns the mask and the fraction of reachable cells kept.
pub fn stiffness_limited(cells: &[MapCell], which: usize, threshold: f64) -> (Vec<bool>, f64) {
    let mask: Vec<bool> = cells
        .iter()
        .map(|c| c.ok && c.values.get(which).copied().flatten().is_some_and(|v| v > threshold))
        .collect();
    let reachable = cells.iter().filter(|c| c.ok).count();
    let kept = mask.iter().filter(|&&b| b).count();
    (
        mask,
        if reachable == 0 {
            0.0
        } else {
            kept as f64 / reachable as f64
        },
    )
}
