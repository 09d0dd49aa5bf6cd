//! Reading a stage result from the FE result: platform pose change, actuator forces, hinge
//! rotations and peak hinge stresses.

use super::*;
use crate::fem::{self};
use nalgebra::Vector3;

impl StageModel {
    /// Reads stage quantities from an FE load-case result driven by `drive`.
    pub fn read(&self, fe: fem::CaseResult, drive: Drive) -> StageCaseResult {
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
                rev[i] = self.stress_tables[0].peak(sf);
            }
            if let Some(el) = leg.sph_element {
                let sf = &fe.elements[el].section_forces;
                sph[i] = self.stress_tables[1].peak(sf);
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
