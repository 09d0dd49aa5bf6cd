//! Recording of a transient run: the histories of chosen DOFs, displacement snapshots and
//! energies (see [`super::solve_transient`]).

use super::{Energy, TransientOptions, TransientResults};
use crate::fem::constraints::DofMap;
use crate::fem::dof::NodeDof;
use crate::fem::error::FemError;
use crate::fem::model::Model;
use crate::fem::solve::FullSymmetric;

/// Collects the recorded series.
pub(super) struct Recorder<'a> {
    opts: &'a TransientOptions,
    map: &'a DofMap,
    prescribed: &'a [NodeDof],
    n_nodes: usize,
    res: TransientResults,
}

impl<'a> Recorder<'a> {
    pub(super) fn new(opts: &'a TransientOptions, model: &Model, map: &'a DofMap, prescribed: &'a [NodeDof]) -> Self {
        let nr = opts.record.len();
        Recorder {
            opts,
            map,
            prescribed,
            n_nodes: model.nodes.len(),
            res: TransientResults {
                time: Vec::with_capacity(opts.steps + 1),
                displacement: vec![Vec::with_capacity(opts.steps + 1); nr],
                velocity: vec![Vec::with_capacity(opts.steps + 1); nr],
                acceleration: vec![Vec::with_capacity(opts.steps + 1); nr],
                snapshots: Vec::new(),
                energy: Vec::new(),
                n_eq: 0,
                warnings: Vec::new(),
                equilibrium: None,
            },
        }
    }

    /// Full vector (6 per node, global axes) from equation values and prescribed values.
    fn expand(&self, q: &[f64], pstate: &[[f64; 3]], which: usize) -> Vec<f64> {
        let mut uc = vec![0.0; 6 * self.n_nodes];
        for (p, s) in self.prescribed.iter().zip(pstate) {
            uc[p.global()] = s[which];
        }
        self.map.expand(q, &uc)
    }

    #[allow(clippy::too_many_arguments)]
    pub(super) fn push(
        &mut self,
        t: f64,
        u: &[f64],
        v: &[f64],
        a: &[f64],
        pstate: &[[f64; 3]],
        kf: &FullSymmetric,
        mf: &FullSymmetric,
    ) -> Result<(), FemError> {
        let step = self.res.time.len();
        self.res.time.push(t);
        if !self.opts.record.is_empty() {
            for (which, q) in [u, v, a].into_iter().enumerate() {
                let full = self.expand(q, pstate, which);
                let target = match which {
                    0 => &mut self.res.displacement,
                    1 => &mut self.res.velocity,
                    _ => &mut self.res.acceleration,
                };
                for (s, r) in target.iter_mut().zip(&self.opts.record) {
                    s.push(full[r.global()]);
                }
            }
        }
        let every = self.opts.snapshot_every;
        if every > 0 && step.is_multiple_of(every) {
            let full = self.expand(u, pstate, 0);
            let nodes = full.chunks(6).map(|c| std::array::from_fn(|d| c[d])).collect();
            self.res.snapshots.push((t, nodes));
        }
        if self.opts.energy {
            let dot = |x: &[f64], y: &[f64]| x.iter().zip(y).map(|(p, q)| p * q).sum::<f64>();
            self.res.energy.push(Energy {
                kinetic: 0.5 * dot(v, &mf.mul_vec(v)),
                strain: 0.5 * dot(u, &kf.mul_vec(u)),
            });
        }
        Ok(())
    }

    pub(super) fn finish(self) -> TransientResults {
        self.res
    }
}
