//! An explicit solver cache: the factorised systems of the last model solved, kept so that the
//! next model of the same topology (another design of a sweep, another point of a design
//! loop) reuses the DOF numbering's sparsity pattern and symbolic factorisation and only
//! assembles and factorises numerically.
//!
//! A cache belongs to one worker: batch drivers create one per rayon worker (e.g. with
//! `map_init`) and pass it down; a single run uses a fresh one. Reuse is checked, never
//! assumed: a cached system is reused only when its prescribed DOFs are the same and its
//! pattern matches the new model (element node lists, equation numbering); otherwise the
//! system is built afresh and replaces the cached one.
//!
//! Also the static solve of a whole model ([`solve_static`]), which goes through a cache.

use super::analysis::{prescribed_dofs, StaticResults, System};
use super::assembly::Pattern;
use super::constraints::DofMap;
use super::dof::NodeDof;
use super::error::FemError;
use super::model::{LoadCase, Model};
use super::recovery::CaseResult;
use super::solve::{FillOrdering, Parallelism, SymbolicFactor};

/// Systems kept per cache (one per set of prescribed DOFs, most recent last): a stage uses
/// two (force-driven and stroke-driven load cases), a static model one per constraint set.
const MAX_SYSTEMS: usize = 4;

/// Per-worker solver cache (see the module notes).
#[derive(Debug, Clone, Default)]
pub struct SolverCache {
    systems: Vec<System>,
    /// The pattern and symbolic factorisation of the last modal model, with its equation
    /// numbering.
    modal: Option<(Vec<usize>, Pattern, Option<SymbolicFactor>)>,
    reused: usize,
    built: usize,
}

impl SolverCache {
    /// An empty cache.
    pub fn new() -> Self {
        SolverCache::default()
    }

    /// How many systems were (reused, built afresh) so far.
    pub fn counts(&self) -> (usize, usize) {
        (self.reused, self.built)
    }

    /// The factorised system of `model` with `prescribed` (sorted) DOFs held: the cached one's
    /// pattern and symbolic factorisation when the topology matches, else a fresh system.
    pub fn system(&mut self, model: &Model, prescribed: &[NodeDof], par: Parallelism) -> Result<&System, FemError> {
        if let Some(i) = self.systems.iter().position(|s| s.prescribed() == prescribed) {
            // A failure here (a mismatching pattern, or a model error) is decided afresh below,
            // so the error reported is that of a fresh system.
            if let Ok(s) = System::with_topology_of(&self.systems[i], model, par) {
                self.reused += 1;
                self.systems.remove(i);
                self.systems.push(s);
                return Ok(self.systems.last().expect("just pushed"));
            }
            self.systems.remove(i);
        }
        let s = System::new(model, prescribed, par)?;
        self.built += 1;
        if self.systems.len() >= MAX_SYSTEMS {
            self.systems.remove(0);
        }
        self.systems.push(s);
        Ok(self.systems.last().expect("just pushed"))
    }

    /// The stiffness/mass pattern of a modal model: the cached one when it matches `model`
    /// and `map`, else built afresh (and cached, replacing the cached one).
    pub fn modal_pattern(&mut self, model: &Model, map: &DofMap) -> Result<Pattern, FemError> {
        if let Some((eq, pattern, _)) = &self.modal {
            if *eq == map.eq_dof && pattern.matches(model, map) {
                return Ok(pattern.clone());
            }
        }
        let pattern = Pattern::new(model, map)?;
        self.modal = Some((map.eq_dof.clone(), pattern.clone(), None));
        Ok(pattern)
    }

    /// The symbolic factorisation of the pattern last returned by [`Self::modal_pattern`]:
    /// cached after its first computation (with the fill-reducing `ordering` asked for then).
    pub fn modal_symbolic(&mut self, pattern: &Pattern, ordering: FillOrdering) -> Result<SymbolicFactor, FemError> {
        if let Some((_, cached, Some(symbolic))) = &self.modal {
            if cached.sparse().nnz() == pattern.sparse().nnz() && cached.sparse().n() == pattern.sparse().n() {
                self.reused += 1;
                return Ok(symbolic.clone());
            }
        }
        let symbolic = SymbolicFactor::with_ordering(pattern.sparse(), ordering)?;
        self.built += 1;
        if let Some((_, _, slot)) = &mut self.modal {
            *slot = Some(symbolic.clone());
        }
        Ok(symbolic)
    }
}

/// Solves every load case of the model. Cases are grouped by their set of prescribed DOFs;
/// each group shares one factorisation.
pub fn solve_static(model: &Model) -> Result<StaticResults, FemError> {
    solve_static_with(model, Parallelism::Rayon)
}

/// [`solve_static`] with explicit solver parallelism.
pub fn solve_static_with(model: &Model, par: Parallelism) -> Result<StaticResults, FemError> {
    solve_static_cached(model, par, &mut SolverCache::new())
}

/// [`solve_static_with`] reusing the systems of `cache` where the topology matches (see
/// the module notes).
pub fn solve_static_cached(
    model: &Model,
    par: Parallelism,
    cache: &mut SolverCache,
) -> Result<StaticResults, FemError> {
    model.validate()?;
    let mut groups: Vec<(Vec<NodeDof>, Vec<usize>)> = Vec::new();
    for (i, case) in model.load_cases.iter().enumerate() {
        let key = prescribed_dofs(case);
        match groups.iter_mut().find(|(k, _)| *k == key) {
            Some((_, v)) => v.push(i),
            None => groups.push((key, vec![i])),
        }
    }
    let mut out: Vec<Option<CaseResult>> = vec![None; model.load_cases.len()];
    for (key, idx) in groups {
        // Check the constraint set with the case name for a precise message.
        if let Some(&first) = idx.first() {
            DofMap::new(model, &key, Some(&model.load_cases[first].name))?;
        }
        let sys = cache.system(model, &key, par)?;
        let cases: Vec<&LoadCase> = idx.iter().map(|&i| &model.load_cases[i]).collect();
        for (i, r) in idx.iter().zip(sys.solve_cases(model, &cases)?) {
            out[*i] = Some(r);
        }
    }
    Ok(StaticResults {
        load_cases: out.into_iter().flatten().collect(),
    })
}
