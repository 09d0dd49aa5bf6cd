//! Geometrically nonlinear solves of the stage: the hinge regions subdivided into co-rotational
//! elements.

use super::*;
use crate::fem::{self, Dof, FemError, Model};
use crate::hinge::{self, Profile};
use nalgebra::Matrix3;

/// Co-rotational elements per hinge region in the nonlinear stage solve: the region (notch +
/// load-spreading zone, ~14–25 mm for the paper's hinges) bends through up to ~2° at the paper's
/// strokes; 4 elements put Δz within 0.1 µm of 16 (tests/nonlinear.rs `stage_hinge_subdivision`).
pub const NONLINEAR_HINGE_SEGMENTS: usize = 4;

impl StageModel {
    /// Geometrically nonlinear solve of load cases (co-rotational hinges and legs, rigid
    /// platform exact under finite rotation; see [`crate::fem::nonlinear`]) in `steps` load
    /// steps. The model is the linear one (one flexibility element per hinge, same
    /// compliances), so small strokes reproduce [`StageModel::solve`]. The platform angles are
    /// extracted from its rotation matrix R = Ry(θ)·Rx(ψ)·Rz(φ) ([`pose_angles`]); hinge
    /// stresses come from the section forces in the hinges' deformed frames.
    pub fn solve_nonlinear(&self, cases: &[(String, Drive)], steps: usize) -> Result<Vec<StageCaseResult>, StageError> {
        self.solve_nonlinear_with(cases, &self.nonlinear_options(steps))
    }

    /// Default nonlinear options for the stage: `steps` load steps, sequential solver.
    pub fn nonlinear_options(&self, steps: usize) -> fem::NonlinearOptions {
        fem::NonlinearOptions {
            steps: steps.max(1),
            track: vec![fem::NodeDof {
                node: self.platform,
                dof: Dof::Uz,
            }],
            ..Default::default()
        }
    }

    /// [`StageModel::solve_nonlinear`] with explicit solver options (each hinge region split
    /// into [`NONLINEAR_HINGE_SEGMENTS`] co-rotational elements).
    pub fn solve_nonlinear_with(
        &self,
        cases: &[(String, Drive)],
        opts: &fem::NonlinearOptions,
    ) -> Result<Vec<StageCaseResult>, StageError> {
        self.solve_nonlinear_segments(cases, opts, NONLINEAR_HINGE_SEGMENTS)
    }

    /// Nonlinear solve with each hinge split into `segments` co-rotational flexibility elements
    /// (compliances of the sub-intervals of the notch from [`hinge::segment_compliance`]; their
    /// Saint-Venant torsion compliance scaled so the chain keeps the warping-restrained torsion
    /// of the single-element hinge, so the linear response is unchanged). `segments = 1` is the
    /// linear model's single element. Hinge stresses use the end sections of the first and last
    /// segment.
    pub fn solve_nonlinear_segments(
        &self,
        cases: &[(String, Drive)],
        opts: &fem::NonlinearOptions,
        segments: usize,
    ) -> Result<Vec<StageCaseResult>, StageError> {
        let (model, chains) = self.nonlinear_model(cases, segments)?;
        let res = fem::solve_nonlinear(&model, opts)?;
        Ok(res
            .load_cases
            .into_iter()
            .zip(cases)
            .map(|(nl, (_, d))| {
                let r = nl.rotations[self.platform];
                let rm = Matrix3::from_fn(|i, j| r[i][j]);
                let (psi, theta, phi) = pose_angles(&rm);
                let mut fe = nl.fe;
                for &(first, last) in &chains {
                    let end = fe.elements[last].section_forces[1];
                    fe.elements[first].section_forces[1] = end;
                }
                let mut out = self.read(fe, *d);
                out.stability = Some((nl.stable, nl.critical_load_factor));
                out.platform.psi = psi;
                out.platform.theta = theta;
                out.platform.phi = phi;
                out
            })
            .collect())
    }

    /// The model of [`StageModel::solve_nonlinear_segments`]: each hinge split into `segments`
    /// co-rotational flexibility elements, the load cases of `cases`; with the first and last
    /// element of each hinge chain.
    pub fn nonlinear_model(
        &self,
        cases: &[(String, Drive)],
        segments: usize,
    ) -> Result<(Model, Vec<(usize, usize)>), StageError> {
        let mut model = self.model.clone();
        let mut chains: Vec<(usize, usize)> = Vec::new();
        if segments > 1 {
            for leg in &self.legs {
                for (el, profile, single) in [
                    (leg.rev_element, &self.revolute.profile, &self.revolute.stiffness),
                    (leg.sph_element, &self.spherical.profile, &self.spherical.stiffness),
                ] {
                    if let Some(el) = el {
                        let last = self.split_hinge(&mut model, el, profile, single, segments)?;
                        chains.push((el, last));
                    }
                }
            }
        }
        model.load_cases = cases.iter().map(|(n, d)| self.load_case(n, *d)).collect();
        Ok((model, chains))
    }

    /// Replaces hinge element `el` by a chain of `n` flexibility elements; returns the index of
    /// the last one (the first keeps index `el`).
    pub(super) fn split_hinge(
        &self,
        model: &mut Model,
        el: usize,
        profile: &Profile,
        single: &hinge::Stiffness,
        n: usize,
    ) -> Result<usize, StageError> {
        hinge::split_flex(model, el, profile, &self.design.material, single, n).ok_or_else(|| {
            StageError::Fem(FemError::BadInput(format!(
                "element {el} is not a hinge flexibility element"
            )))
        })
    }
}
