//! Reading a stage result from the FE result: platform pose change, actuator forces, hinge
//! rotations and peak hinge stresses.

use super::*;
use crate::fem::{self};
use crate::hinge::Profile;
use nalgebra::Vector3;

/// Peak von Mises stress along a hinge element from its end section forces (linear moment
/// variation: no loads act inside the hinge). Bending stress at the extreme fibres times the
/// notch factor K_t, plus axial stress; torsional shear τ = T·c/J (exact for thin sections,
/// conservative for thick ones); σ_vm = √(σ² + 3τ²) combining both peaks (conservative).
pub fn hinge_peak_stress(profile: &Profile, nu: f64, kt: f64, sf: &[[f64; 6]; 2], neck: bool) -> f64 {
    let half = profile.half_length();
    const N: usize = 41;
    let mut peak: f64 = 0.0;
    for k in 0..N {
        let s = k as f64 / (N - 1) as f64;
        let x = -half + 2.0 * half * s;
        let f: [f64; 6] = std::array::from_fn(|j| sf[0][j] * (1.0 - s) + sf[1][j] * s);
        let sec = profile.section(x, nu);
        let (sigma, tau) = if neck {
            let r = profile.effective_half_size(x);
            let c = r.min(0.5 * profile.h);
            let m = (f[4] * f[4] + f[5] * f[5]).sqrt();
            (f[0].abs() / sec.area + kt * m * c / sec.i_bend, f[3].abs() * c / sec.j)
        } else {
            let t = profile.effective_thickness(x);
            let w = profile.w;
            let sig =
                f[0].abs() / sec.area + kt * f[4].abs() * 0.5 * t / sec.i_bend + f[5].abs() * 0.5 * w / sec.i_bend_off;
            (sig, f[3].abs() * t.min(w) / sec.j)
        };
        peak = peak.max((sigma * sigma + 3.0 * tau * tau).sqrt());
    }
    peak
}

impl StageModel {
    /// Reads stage quantities from an FE load-case result driven by `drive`.
    pub fn read(&self, fe: fem::CaseResult, drive: Drive) -> StageCaseResult {
        let nu = self.design.material.nu;
        let mut strokes = [0.0; 3];
        let mut forces = [0.0; 3];
        let mut rev = [0.0; 3];
        let mut sph = [0.0; 3];
        for (i, leg) in self.legs.iter().enumerate() {
            let u = &fe.displacements[leg.slider];
            strokes[i] = leg.e.dot(&Vector3::new(u[0], u[1], u[2]));
            // Actuator force along eᵢ: the applied force, or with a prescribed stroke the
            // reaction of the stroke DOF (the guide's other reactions are normal to eᵢ).
            forces[i] = match drive {
                Drive::Forces(f) => f[i],
                Drive::Strokes(_) => fe
                    .reactions
                    .iter()
                    .find(|(n, _)| *n == leg.slider)
                    .map_or(0.0, |(_, r)| leg.e.dot(&Vector3::new(r[0], r[1], r[2]))),
            };
            if let Some(el) = leg.rev_element {
                let sf = &fe.elements[el].section_forces;
                rev[i] = hinge_peak_stress(&self.rev_profile, nu, self.kt[0], sf, false);
            }
            if let Some(el) = leg.sph_element {
                let sf = &fe.elements[el].section_forces;
                sph[i] = hinge_peak_stress(&self.sph_profile, nu, self.kt[1], sf, true);
            }
        }
        let up = fe.displacements[self.platform];
        let beams = fe.max_von_mises.unwrap_or(0.0);
        let max_vm = rev.iter().chain(sph.iter()).cloned().fold(beams, f64::max);
        StageCaseResult {
            name: fe.name.clone(),
            strokes,
            forces,
            platform: PoseChange {
                x: up[0],
                y: up[1],
                z: up[2],
                psi: up[3],
                theta: up[4],
                phi: up[5],
            },
            revolute_stress: rev,
            spherical_stress: sph,
            max_von_mises: max_vm,
            fe,
            stability: None,
        }
    }
}
