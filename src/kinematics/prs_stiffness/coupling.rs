//! Velocity-level parasitic coupling of the 3-PRS platform (Nigatu et al. Eqs. 5–8).

use super::{PoseState, PrsLayout, StiffnessError};
use crate::kinematics::prs::revolute_axis;
use nalgebra::{Matrix3, Matrix3x2};

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
