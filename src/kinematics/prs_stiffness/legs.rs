//! Leg stiffness models: lead screw, link and their series combinations (Han et al. Eqs. 1–9).

use super::{PoseState, PrsLayout, StiffnessError};

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
