//! Result types of the FE core: per-element results, the statics check, the results of a load
//! case and of all load cases. Plain data; built by [`super::recovery`] (linear) and the
//! nonlinear solver's recovery.

use super::shell::ShellStress;
use nalgebra::Vector3;

/// Per-element results of a load case, local axes.
#[derive(Debug, Clone, PartialEq)]
pub struct ElementResult {
    /// Forces the nodes exert on the element, f = k·d, at node 1 and node 2:
    /// [Fx, Fy, Fz (N), Mx, My, Mz (N·mm)] in element local axes (spring axes for springs;
    /// for a ground spring the first entry is the spring force k·δ, the second is zero).
    pub end_forces: [[f64; 6]; 2],
    /// Internal section forces [N, Vy, Vz (N), T, My, Mz (N·mm)] at end 1 and end 2
    /// (positive-face convention: N > 0 in tension; s₁ = −f₁, s₂ = f₂).
    pub section_forces: [[f64; 6]; 2],
    /// Largest von Mises stress at end 1 and end 2, MPa (`None` without stress points).
    /// For unloaded prismatic beams the section forces vary linearly, so the ends bound the
    /// element.
    pub von_mises: Option<[f64; 2]>,
    /// Strain energy ½ dᵀ k d, N·mm.
    pub strain_energy: f64,
    /// Shells: centre stresses (von Mises top/mid/bottom, membrane forces, moments; local
    /// axes). `None` for other elements.
    pub shell: Option<ShellStress>,
}

impl ElementResult {
    /// Largest von Mises stress of the element, MPa.
    pub fn max_von_mises(&self) -> Option<f64> {
        self.von_mises.map(|v| v[0].max(v[1]))
    }
}

/// Resultant about the global origin of the force/moment `f` = [Fx, Fy, Fz, Mx, My, Mz] acting
/// at `x`: [F, x × F + M] (N, N·mm).
pub fn resultant(x: Vector3<f64>, f: &[f64]) -> [f64; 6] {
    let fv = Vector3::new(f[0], f[1], f[2]);
    let m = x.cross(&fv);
    [f[0], f[1], f[2], m.x + f[3], m.y + f[4], m.z + f[5]]
}

/// Resultants about the global origin: [Fx, Fy, Fz, Mx, My, Mz] (N, N·mm).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Statics {
    /// Sum of applied nodal loads.
    pub loads: [f64; 6],
    /// Sum of support reactions and ground-spring reactions.
    pub reactions: [f64; 6],
}

impl Statics {
    /// Adds the resultant of an applied load `f` at `x` to [`Statics::loads`].
    pub fn add_load(&mut self, x: Vector3<f64>, f: &[f64]) {
        add(&mut self.loads, resultant(x, f));
    }

    /// Adds the resultant of a reaction `r` at `x` to [`Statics::reactions`].
    pub fn add_reaction(&mut self, x: Vector3<f64>, r: &[f64]) {
        add(&mut self.reactions, resultant(x, r));
    }

    /// loads + reactions (zero for a balanced structure).
    pub fn residual(&self) -> [f64; 6] {
        std::array::from_fn(|i| self.loads[i] + self.reactions[i])
    }

    /// Is the residual below `rel` times the load/reaction scale (forces and moments checked
    /// separately; moments scaled by the model size `length`, mm)?
    pub fn is_balanced(&self, rel: f64, length: f64) -> bool {
        let r = self.residual();
        let fscale = (0..3)
            .map(|i| self.loads[i].abs() + self.reactions[i].abs())
            .fold(0.0, f64::max);
        let mscale = (3..6)
            .map(|i| self.loads[i].abs() + self.reactions[i].abs())
            .fold(0.0, f64::max)
            .max(fscale * length);
        let tiny = f64::MIN_POSITIVE;
        (0..3).all(|i| r[i].abs() <= rel * fscale.max(mscale / length.max(tiny)) + tiny)
            && (3..6).all(|i| r[i].abs() <= rel * mscale + tiny)
    }
}

/// Results of one load case.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseResult {
    pub name: String,
    /// Per node [ux, uy, uz (mm), rx, ry, rz (rad)], global axes.
    pub displacements: Vec<[f64; 6]>,
    /// Support reactions (force the support exerts on the structure) per constrained node,
    /// sorted by node: [Fx, Fy, Fz (N), Mx, My, Mz (N·mm)], global axes, zero on free DOFs.
    /// Includes the loads of rigid-link slaves carried by a supported master.
    pub reactions: Vec<(usize, [f64; 6])>,
    /// Per element (model order): end forces, section forces, stresses, energy.
    pub elements: Vec<ElementResult>,
    /// Largest von Mises stress over all elements with stress points, MPa (`None` if no
    /// element has stress points).
    pub max_von_mises: Option<f64>,
    /// Statics check (sums about the global origin).
    pub statics: Statics,
}

impl CaseResult {
    /// Assembles the result of a load case; [`CaseResult::max_von_mises`] is taken over
    /// `elements`.
    pub fn new(
        name: &str,
        displacements: Vec<[f64; 6]>,
        reactions: Vec<(usize, [f64; 6])>,
        elements: Vec<ElementResult>,
        statics: Statics,
    ) -> CaseResult {
        let max_von_mises = elements
            .iter()
            .filter_map(|e| e.max_von_mises())
            .fold(None, |m: Option<f64>, v| Some(m.map_or(v, |m| m.max(v))));
        CaseResult {
            name: name.to_string(),
            displacements,
            reactions,
            elements,
            max_von_mises,
            statics,
        }
    }
}

/// Results of all load cases of a model, in model order.
#[derive(Debug, Clone, PartialEq)]
pub struct StaticResults {
    pub load_cases: Vec<CaseResult>,
}

fn add(acc: &mut [f64; 6], v: [f64; 6]) {
    for (a, b) in acc.iter_mut().zip(v) {
        *a += b;
    }
}
