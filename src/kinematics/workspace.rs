//! Requirement sweep: ranges of strokes and passive joint rotations over a box of poses
//! (Ruiz et al. (2019) §4, Figs. 6–7).

use super::prs::{KinematicsError, Prs};

/// A box of poses: every combination of `steps` equally spaced values of z, ψ and θ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PoseBox {
    /// z range from home, mm.
    pub z: [f64; 2],
    /// ψ range, rad.
    pub psi: [f64; 2],
    /// θ range, rad.
    pub theta: [f64; 2],
    /// Values per axis (≥ 2; the ends are included).
    pub steps: usize,
}

/// Extremes over the pose box. Angles in rad, strokes in mm; each is `[min, max]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WorkspaceRanges {
    /// Actuator strokes sᵢ over all legs, mm.
    pub s: [f64; 2],
    /// Revolute rotation αᵢ − α₀ᵢ over all legs, rad.
    pub revolute_delta: [f64; 2],
    /// Spherical bending βm (in the leg plane), rad.
    pub spherical_m: [f64; 2],
    /// Spherical bending βn (out of plane), rad.
    pub spherical_n: [f64; 2],
    /// Spherical torsion βl, rad.
    pub spherical_l: [f64; 2],
    /// Number of poses evaluated.
    pub poses: usize,
}

fn grid(r: [f64; 2], steps: usize) -> impl Iterator<Item = f64> {
    (0..steps).map(move |k| r[0] + (r[1] - r[0]) * k as f64 / (steps - 1) as f64)
}

fn widen(range: &mut [f64; 2], v: f64) {
    range[0] = range[0].min(v);
    range[1] = range[1].max(v);
}

/// Sweeps the inverse kinematics over every pose of `bx`.
pub fn sweep(prs: &Prs, bx: &PoseBox) -> Result<WorkspaceRanges, KinematicsError> {
    let steps = bx.steps.max(2);
    let home = prs.ikp(0.0, 0.0, 0.0)?;
    let empty = [f64::INFINITY, f64::NEG_INFINITY];
    let mut out = WorkspaceRanges {
        s: empty,
        revolute_delta: empty,
        spherical_m: empty,
        spherical_n: empty,
        spherical_l: empty,
        poses: 0,
    };
    for z in grid(bx.z, steps) {
        for psi in grid(bx.psi, steps) {
            for theta in grid(bx.theta, steps) {
                let sol = prs.ikp(z, psi, theta)?;
                for i in 0..3 {
                    widen(&mut out.s, sol.s[i]);
                    widen(&mut out.revolute_delta, sol.alpha[i] - home.alpha[i]);
                    widen(&mut out.spherical_m, sol.spherical[i][0]);
                    widen(&mut out.spherical_n, sol.spherical[i][1]);
                    widen(&mut out.spherical_l, sol.spherical[i][2]);
                }
                out.poses += 1;
            }
        }
    }
    Ok(out)
}
