//! Linear solves of the stage: load cases by drive kind (one factorisation each, reused across
//! stages of the same topology through the caller's [`fem::SolverCache`]), the platform
//! compliance, the z stiffness.

use super::*;
use crate::fem::{self, Dof};
use nalgebra::Matrix6;

impl StageModel {
    /// An FE load case for a drive.
    pub fn load_case(&self, name: &str, drive: Drive) -> fem::LoadCase {
        let mut lc = fem::LoadCase::new(name);
        for (i, leg) in self.legs.iter().enumerate() {
            match drive {
                Drive::Forces(f) => {
                    let v = leg.e * f[i];
                    lc = lc.force(leg.slider, [v[0], v[1], v[2], 0.0, 0.0, 0.0]);
                }
                Drive::Strokes(s) => lc = lc.displacement(leg.slider, Dof::Ux, s[i]),
            }
        }
        lc
    }

    /// Solves load cases (grouped by drive kind so each group shares one factorisation).
    pub fn solve(&self, cases: &[(String, Drive)]) -> Result<Vec<StageCaseResult>, StageError> {
        Ok(self.analyse(cases, false)?.cases)
    }

    /// [`Self::solve`] with the caller's solver cache.
    pub fn solve_with(
        &self,
        cache: &mut fem::SolverCache,
        cases: &[(String, Drive)],
    ) -> Result<Vec<StageCaseResult>, StageError> {
        Ok(self.analyse_with(cache, cases, false)?.cases)
    }

    /// Slider stroke DOFs (local ux of each slider frame), sorted.
    pub(super) fn stroke_dofs(&self) -> Vec<fem::NodeDof> {
        let mut v: Vec<fem::NodeDof> = self
            .legs
            .iter()
            .map(|l| fem::NodeDof {
                node: l.slider,
                dof: Dof::Ux,
            })
            .collect();
        v.sort();
        v
    }

    /// Solves load cases and, if asked, the 6×6 compliance of the platform centre with the
    /// sliders held. Force-driven cases share one factorisation, stroke-driven cases (and the
    /// compliance) another. A fresh solver cache: see [`Self::analyse_with`].
    pub fn analyse(&self, cases: &[(String, Drive)], compliance: bool) -> Result<StageAnalysis, StageError> {
        self.analyse_with(&mut fem::SolverCache::new(), cases, compliance)
    }

    /// [`Self::analyse`] with the caller's solver cache: the pattern and symbolic factorisation
    /// of the last stage of the same topology solved with `cache` are reused (sweeps and the
    /// design loop refactor numerically only).
    pub fn analyse_with(
        &self,
        cache: &mut fem::SolverCache,
        cases: &[(String, Drive)],
        compliance: bool,
    ) -> Result<StageAnalysis, StageError> {
        // The legs are serial chains: solved condensed (exact, fem::chain), with the model as
        // meshed only to report a failure in its own node numbers.
        let lcs: Vec<fem::LoadCase> = cases.iter().map(|(n, d)| self.load_case(n, *d)).collect();
        let refs: Vec<&fem::LoadCase> = lcs.iter().collect();
        let condensed = fem::chain::Condensed::new(&self.model, &refs, &[self.platform]);
        match condensed.map(|c| self.analyse_on(cache, Some(&c), cases, &lcs, compliance)) {
            Ok(Ok(a)) => Ok(a),
            _ => self.analyse_on(cache, None, cases, &lcs, compliance),
        }
    }

    /// [`Self::analyse_with`] on the condensed model `c`, or without one on the model as meshed.
    fn analyse_on(
        &self,
        cache: &mut fem::SolverCache,
        c: Option<&fem::chain::Condensed>,
        cases: &[(String, Drive)],
        lcs: &[fem::LoadCase],
        compliance: bool,
    ) -> Result<StageAnalysis, StageError> {
        let model = c.map_or(&self.model, |c| &c.model);
        let mut out: Vec<Option<StageCaseResult>> = vec![None; cases.len()];
        let mut platform_compliance = None;
        let kept = |n: usize| {
            c.map_or(Some(n), |c| c.node(n))
                .ok_or_else(|| FemError::BadInput(format!("stage node {n} condensed away")))
        };
        for strokes in [false, true] {
            let idx: Vec<usize> = (0..cases.len())
                .filter(|&i| matches!(cases[i].1, Drive::Strokes(_)) == strokes)
                .collect();
            if idx.is_empty() && !(strokes && compliance) {
                continue;
            }
            let prescribed = if strokes { self.stroke_dofs() } else { Vec::new() };
            let prescribed = prescribed
                .iter()
                .map(|p| {
                    Ok(fem::NodeDof {
                        node: kept(p.node)?,
                        dof: p.dof,
                    })
                })
                .collect::<Result<Vec<_>, FemError>>()?;
            let sys = cache.system(model, &prescribed, fem::solve::Parallelism::Sequential)?;
            let reduced: Vec<fem::LoadCase> = match c {
                Some(c) => idx.iter().map(|&i| c.case(&lcs[i])).collect(),
                None => idx.iter().map(|&i| lcs[i].clone()).collect(),
            };
            let refs: Vec<&fem::LoadCase> = reduced.iter().collect();
            let res = sys.solve_cases(model, &refs)?;
            for (&i, r) in idx.iter().zip(res) {
                let r = match c {
                    Some(c) => c.expand(&self.model, r)?,
                    None => r,
                };
                out[i] = Some(self.read(r, cases[i].1));
            }
            if strokes && compliance {
                platform_compliance = Some(sys.node_compliance(model, kept(self.platform)?)?);
            }
        }
        Ok(StageAnalysis {
            cases: out.into_iter().flatten().collect(),
            compliance: platform_compliance,
        })
    }
}

/// Results of [`StageModel::analyse`].
#[derive(Debug, Clone)]
pub struct StageAnalysis {
    /// Load-case results in input order.
    pub cases: Vec<StageCaseResult>,
    /// Platform-centre compliance with the sliders held, if asked.
    pub compliance: Option<Matrix6<f64>>,
}

/// Total actuator force per mm of stroke for a pure-z motion, N/mm: the sum of the actuator
/// forces when every stroke follows the linearised IKP of a unit z lift.
pub fn stiffness_z(stage: &StageModel) -> Result<(f64, StageCaseResult), StageError> {
    let j = stage
        .design
        .prs
        .actuation_jacobian(0.0, 0.0, 0.0)
        .map_err(|e| geometry_err("L", e.to_string()))?;
    let s = [j[(0, 0)], j[(1, 0)], j[(2, 0)]];
    let mut r = stage.solve(&[("unit_z".to_string(), Drive::Strokes(s))])?;
    let r = r.remove(0);
    let total: f64 = r.forces.iter().sum();
    Ok((total / (s.iter().sum::<f64>() / 3.0), r))
}
