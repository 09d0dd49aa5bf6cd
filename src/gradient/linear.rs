//! The direct method on one factorisation: for each parameter p, dq/dp = K⁻¹(df/dp − dK/dp q)
//! for every load case (and unit load of a stiffness target), and each target's derivative
//! d m/dp = ∂m/∂p + ∂m/∂q · dq/dp taken along the path (model(p + s), q + s dq/dp).
//!
//! dK/dp and df/dp are the reduced (constrained) stiffness and load: they include the element
//! matrices, the rigid-link transform Aᵀ K A (node coordinates move the links' arms) and loads
//! that depend on the parameters. Each is differenced at element level with the sixth-order
//! central stencil [−1, 9, −45, 45, −9, 1]/(60 h) over models moved along the exact tangent of the case's
//! numbers (expressions differentiated analytically): no solve is differenced. Hinge elements
//! are the exception: their compliance part of dK/dp is analytic ([`super::hinges`]), only their
//! geometry is differenced. Frequencies by [`super::frequency`].

use super::frequency;
use super::hinges;
use super::point::Point;
use super::{GradientError, Gradients, Target};
use crate::analysis::RunError;
use crate::case::mesh::MetricKind;
use crate::case::params::{tangent::Written, Along, Parameters};
use crate::fem::{self, analysis::prescribed_dofs, assembly::MatrixKind, constraints::DofMap, NodeDof, System};
use rayon::prelude::*;

/// Offsets (in steps h) and weights (per 60 h) of the sixth-order central difference. The
/// fourth-order one is not enough: where a node coordinate moves a stiff hinge chain (the
/// pan-tilt's platform height) the reduced stiffness has large high derivatives, and its
/// truncation error at h = 1e-3·p was 2e-6 of the gradient.
const STENCIL: [(f64, f64); 6] = [
    (-3.0, -1.0),
    (-2.0, 9.0),
    (-1.0, -45.0),
    (1.0, 45.0),
    (2.0, -9.0),
    (3.0, 1.0),
];

/// The denominator of [`STENCIL`]'s weights, per h.
const STENCIL_DIVISOR: f64 = 60.0;

/// Step of the element-level differences, relative to max(|p|, 1) in the parameter's units:
/// the stencil's truncation error is O(h⁶) and its round-off ≈ κ/h with κ the relative
/// round-off of the element matrices and the solve. Measured on the pan-tilt's platform height
/// (the worst case met): 8e-5 of the gradient at h = 1e-2, 2.7e-7 at 3e-3, 4e-7 at 1e-3
/// (round-off), 3e-6 at 3e-4.
pub const RELATIVE_STEP: f64 = 3e-3;

/// A parametric linear static case prepared for gradients: the case as written and the
/// targets. Cheap to evaluate repeatedly ([`Linear::evaluate`]): no file is read, and the
/// solver cache passed in keeps the pattern and symbolic factorisation between calls.
#[derive(Debug, Clone)]
pub struct Linear {
    written: std::sync::Arc<Written>,
    targets: Vec<Target>,
    parameters: Option<Vec<String>>,
    step: f64,
}

/// The systems of one evaluation: one per set of prescribed DOFs of the load cases, and the
/// supports-only one for unit loads and modes.
struct Systems {
    keys: Vec<Vec<NodeDof>>,
    systems: Vec<System>,
    /// System of each load case.
    of_case: Vec<usize>,
    /// The supports-only system.
    free: usize,
}

impl Linear {
    /// The targets of `written` (a `static` case as written, see [`Written`]), with respect to
    /// every parameter it declares as a number.
    pub fn new(written: std::sync::Arc<Written>, targets: Vec<Target>) -> Linear {
        Linear {
            written,
            targets,
            parameters: None,
            step: RELATIVE_STEP,
        }
    }

    /// The relative step of the element-level differences (default [`RELATIVE_STEP`]).
    pub fn with_step(mut self, step: f64) -> Linear {
        self.step = step;
        self
    }

    /// Only with respect to `names` (independent parameters of the case).
    pub fn with_parameters(mut self, names: Vec<String>) -> Linear {
        self.parameters = Some(names);
        self
    }

    /// The targets and their gradients at the parameter values `values` (the others as
    /// declared), reusing the symbolic factorisations in `cache`.
    pub fn evaluate(&self, values: &Parameters, cache: &mut fem::SolverCache) -> Result<Gradients, GradientError> {
        let base = Point::new(&self.written, values, None)?;
        let names = match &self.parameters {
            Some(n) => n.clone(),
            None => base.independent.clone(),
        };
        for n in &names {
            if !base.independent.contains(n) {
                return Err(GradientError::case(format!(
                    "`{n}` is not a parameter declared as a number (independent: {})",
                    base.independent.join(", ")
                )));
            }
        }
        let sys = systems(&base, cache)?;
        // A `frequency` metric is its mode's eigenvalue derivative (no modal solve per point).
        let targets = base.eigen_targets(&self.targets);
        let units = unit_loads(&base, &targets);
        let maps: Vec<&DofMap> = sys.of_case.iter().map(|&g| sys.systems[g].dof_map()).collect();
        let free = &sys.systems[sys.free];
        let q = solve_cases(&base, &sys, &maps)?;
        let qu = solve_units(&base, free, &units)?;
        let mut values0 = base.evaluate(&targets, &maps, &q, Some(free.dof_map()), &qu)?;
        let modes = frequency::Modes::new(&base.model, free, &targets)?;
        modes.fill_values(&targets, &mut values0);
        let mut model = vec![format!(
            "gradients: direct method on the factorised stiffness (one extra right-hand side per parameter and load case); dK/dp and df/dp of the reduced system (elements, rigid-link transforms, loads) by 6th-order central differences at element level, step {:e}·max(|p|, 1), along the exact tangent of the case's expressions, except the hinges: hinge compliance analytic (forward-mode derivative of the flexibility integrals with their piece limits and calibration factors, dK = −K dC K on each hinge element; the warping-restrained torsion compliance of rectangular notches from the same stencil of the moved models' Vlasov solves)",
            self.step
        )];
        // The columns are independent: computed in parallel, kept in parameter order.
        let computed: Vec<_> = names
            .par_iter()
            .map(|name| {
                let h = self.step * base.parameters[name].abs().max(1.0);
                self.column(values, &targets, &base, &sys, &q, &units, &qu, &modes, name, h)
            })
            .collect();
        let mut columns = Vec::with_capacity(names.len());
        for (name, result) in names.iter().zip(computed) {
            match result {
                Ok(d) => columns.push((name.clone(), d)),
                // A parameter that is an index or a count (a step along it makes the case
                // invalid) has no gradient: left out when not asked for by name.
                Err(GradientError(RunError::Case(e))) if self.parameters.is_none() => model.push(format!(
                    "no gradient with respect to `{name}`: a step along it makes the case invalid ({e})"
                )),
                Err(e) => return Err(e),
            }
        }
        let jacobian: Vec<Vec<f64>> = (0..self.targets.len())
            .map(|i| columns.iter().map(|(_, d)| d[i]).collect())
            .collect();
        for (t, row) in self.targets.iter().zip(&jacobian) {
            if let Some(j) = row.iter().position(|v| !v.is_finite()) {
                return Err(GradientError(RunError::Analysis(crate::analysis::AnalysisError::new(
                    "gradients",
                    format!(
                        "d {} / d {} is not finite (the metric is unbounded or undefined nearby)",
                        t.name(),
                        columns[j].0
                    ),
                ))));
            }
        }
        let names: Vec<String> = columns.into_iter().map(|(n, _)| n).collect();
        let repeated_mode = !modes.notes.is_empty();
        model.extend(modes.notes);
        Ok(Gradients {
            parameters: names,
            targets: self.targets.iter().map(Target::name).collect(),
            values: values0,
            jacobian,
            model,
            repeated_mode,
        })
    }

    /// The derivatives of every target with respect to parameter `name` (step `h`).
    #[allow(clippy::too_many_arguments)]
    fn column(
        &self,
        values: &Parameters,
        targets: &[Target],
        base: &Point,
        sys: &Systems,
        q: &[Vec<f64>],
        units: &[[usize; 2]],
        qu: &[Vec<f64>],
        modes: &frequency::Modes,
        name: &str,
        h: f64,
    ) -> Result<Vec<f64>, GradientError> {
        let mut dvals: Vec<Vec<f64>> = sys
            .systems
            .iter()
            .map(|s| vec![0.0; s.pattern().n_triplets()])
            .collect();
        let mut dmass = vec![
            0.0;
            if modes.is_empty() {
                0
            } else {
                sys.systems[sys.free].pattern().n_triplets()
            }
        ];
        let mut drhs: Vec<Vec<f64>> = q.iter().map(|x| vec![0.0; x.len()]).collect();
        let mut dunit: Vec<Vec<f64>> = qu.iter().map(|x| vec![0.0; x.len()]).collect();
        let hinge_elements = hinges::hinge_elements(base);
        // The moved models of the stencil are independent: built in parallel, summed in
        // stencil order (the same sums as one after the other).
        let moved: Vec<Result<Moved, GradientError>> = STENCIL
            .par_iter()
            .map(|&(s, w)| {
                self.moved(
                    values,
                    base,
                    sys,
                    &hinge_elements,
                    units,
                    !dmass.is_empty(),
                    name,
                    s * h,
                    w / (STENCIL_DIVISOR * h),
                )
            })
            .collect();
        let mut points = Vec::with_capacity(STENCIL.len());
        for m in moved {
            let m = m?;
            let w = m.weight;
            for (d, v) in dvals.iter_mut().zip(&m.stiffness) {
                d.iter_mut().zip(v).for_each(|(d, x)| *d += w * x);
            }
            dmass.iter_mut().zip(&m.mass).for_each(|(d, x)| *d += w * x);
            for (d, r) in drhs.iter_mut().zip(&m.rhs) {
                d.iter_mut().zip(r).for_each(|(d, x)| *d += w * x);
            }
            for (d, r) in dunit.iter_mut().zip(&m.unit) {
                d.iter_mut().zip(r).for_each(|(d, x)| *d += w * x);
            }
            points.push((m.step, w, m.point, m.maps));
        }
        // The hinges' compliance part of dK, analytic (their geometry part was differenced above).
        let stencil: Vec<(f64, f64, &Point)> = points.iter().map(|(s, w, pt, _)| (*s, *w, pt)).collect();
        let dc = hinges::compliance_derivatives(base, &stencil, &hinge_elements);
        for (g, system) in sys.systems.iter().enumerate() {
            hinges::add_analytic(system.pattern(), system.dof_map(), &base.model, &dc, &mut dvals[g])?;
        }
        let dk: Vec<fem::solve::SparseMatrix> = sys
            .systems
            .iter()
            .zip(&dvals)
            .map(|(s, v)| s.pattern().matrix(v))
            .collect::<Result<_, _>>()?;
        // dq = K⁻¹ (df − dK q), one solve per load case on the factor of its system.
        let mut dq = Vec::with_capacity(q.len());
        for (i, qi) in q.iter().enumerate() {
            let g = sys.of_case[i];
            dq.push(direct(&sys.systems[g], &dk[g], &drhs[i], qi)?);
        }
        let mut dqu = Vec::with_capacity(qu.len());
        for (k, qk) in qu.iter().enumerate() {
            dqu.push(direct(&sys.systems[sys.free], &dk[sys.free], &dunit[k], qk)?);
        }
        // The targets along (model(p + s), q + s dq/dp) at each point, in parallel; summed in order.
        let along: Vec<Result<Vec<f64>, GradientError>> = points
            .par_iter()
            .map(|(s, _, pt, maps)| {
                let along = |x: &[Vec<f64>], dx: &[Vec<f64>]| -> Vec<Vec<f64>> {
                    x.iter()
                        .zip(dx)
                        .map(|(a, b)| a.iter().zip(b).map(|(ai, bi)| ai + s * bi).collect())
                        .collect()
                };
                let m: Vec<&DofMap> = sys.of_case.iter().map(|&g| &maps[g]).collect();
                pt.evaluate(targets, &m, &along(q, &dq), Some(&maps[sys.free]), &along(qu, &dqu))
            })
            .collect();
        let mut out = vec![0.0; targets.len()];
        for ((_, w, ..), v) in points.iter().zip(along) {
            out.iter_mut().zip(&v?).for_each(|(o, x)| *o += w * x);
        }
        if !modes.is_empty() {
            let dm = sys.systems[sys.free].pattern().matrix(&dmass)?;
            modes.fill_derivatives(targets, &dk[sys.free], &dm, &mut out);
        }
        Ok(out)
    }
}

/// One point of the stencil: the model moved by `step` along a parameter, with what the
/// stencil sums (weight `weight`).
struct Moved {
    step: f64,
    weight: f64,
    point: Point,
    maps: Vec<DofMap>,
    /// Stiffness values of each system, hinge compliance frozen at the base ([`hinges::freeze`]).
    stiffness: Vec<Vec<f64>>,
    /// Mass values of the supports-only system (empty when no mode is needed).
    mass: Vec<f64>,
    /// Reduced right-hand side of each load case.
    rhs: Vec<Vec<f64>>,
    /// Reduced unit load of each stiffness target.
    unit: Vec<Vec<f64>>,
}

impl Linear {
    /// The stencil point at `step` along parameter `name`.
    #[allow(clippy::too_many_arguments)]
    fn moved(
        &self,
        values: &Parameters,
        base: &Point,
        sys: &Systems,
        hinge_elements: &[(usize, Vec<usize>)],
        units: &[[usize; 2]],
        with_mass: bool,
        name: &str,
        step: f64,
        weight: f64,
    ) -> Result<Moved, GradientError> {
        let pt = Point::new(&self.written, values, Some(Along { name, step }))?;
        let maps: Vec<DofMap> = sys
            .keys
            .iter()
            .map(|k| DofMap::new(&pt.model, k, None))
            .collect::<Result<_, _>>()?;
        let mut stiffness = Vec::with_capacity(sys.systems.len());
        // Left empty (zero) where the frozen hinges are all the model's stiffness and nothing moved.
        let frozen = hinges::all_frozen(&base.model, &pt.model, hinge_elements);
        for (g, system) in sys.systems.iter().enumerate().filter(|_| !frozen) {
            let mut v = system.pattern().values(&pt.model, &maps[g])?;
            hinges::freeze(
                system.pattern(),
                &maps[g],
                &base.model,
                &pt.model,
                hinge_elements,
                &mut v,
            )?;
            stiffness.push(v);
        }
        let mass = if with_mass {
            sys.systems[sys.free]
                .pattern()
                .values_of(&pt.model, &maps[sys.free], MatrixKind::Mass)?
        } else {
            Vec::new()
        };
        let mut rhs = Vec::with_capacity(pt.load_cases().len());
        for (i, lc) in pt.load_cases().iter().enumerate() {
            let [r, _, _] = pt.rhs(&maps[sys.of_case[i]], lc)?;
            rhs.push(r);
        }
        let nd = base.model.n_dofs();
        let unit = units
            .iter()
            .map(|&[node, dof]| {
                let mut f = vec![0.0; nd];
                f[6 * node + dof] = 1.0;
                maps[sys.free].reduce(&f)
            })
            .collect();
        Ok(Moved {
            step,
            weight,
            point: pt,
            maps,
            stiffness,
            mass,
            rhs,
            unit,
        })
    }
}

/// dq = K⁻¹ (dr − dK q) on the factor of `system`.
fn direct(system: &System, dk: &fem::solve::SparseMatrix, dr: &[f64], q: &[f64]) -> Result<Vec<f64>, GradientError> {
    let kq = dk.mul_vec(q);
    let mut x: Vec<f64> = dr.iter().zip(&kq).map(|(a, b)| a - b).collect();
    system.solve_checked(&mut x, 1)?;
    Ok(x)
}

/// The factorised systems of `base`: one per set of prescribed DOFs of its load cases, and the
/// supports-only one.
fn systems(base: &Point, cache: &mut fem::SolverCache) -> Result<Systems, GradientError> {
    let par = fem::solve::Parallelism::Sequential;
    let mut keys: Vec<Vec<NodeDof>> = Vec::new();
    let mut of_case = Vec::new();
    for lc in base.load_cases() {
        let key = prescribed_dofs(lc);
        let g = keys.iter().position(|k| *k == key).unwrap_or_else(|| {
            keys.push(key);
            keys.len() - 1
        });
        of_case.push(g);
    }
    let free = keys.iter().position(Vec::is_empty).unwrap_or_else(|| {
        keys.push(Vec::new());
        keys.len() - 1
    });
    let systems = keys
        .iter()
        .map(|k| cache.system(&base.model, k, par).cloned())
        .collect::<Result<_, _>>()?;
    Ok(Systems {
        keys,
        systems,
        of_case,
        free,
    })
}

/// The (node, dof) of the unit load of each stiffness or compliance target, in target order.
fn unit_loads(base: &Point, targets: &[Target]) -> Vec<[usize; 2]> {
    targets
        .iter()
        .filter_map(|t| match t {
            Target::Metric(name) => base.case.metrics.iter().find(|m| &m.name == name),
            _ => None,
        })
        .filter(|m| matches!(m.kind, MetricKind::Stiffness | MetricKind::Compliance))
        .filter_map(|m| m.node.zip(m.dof()).map(|(n, d)| [n, d.index()]))
        .collect()
}

/// The equation values of every load case of `base`.
fn solve_cases(base: &Point, sys: &Systems, maps: &[&DofMap]) -> Result<Vec<Vec<f64>>, GradientError> {
    base.load_cases()
        .iter()
        .enumerate()
        .map(|(i, lc)| {
            let [mut r, _, _] = base.rhs(maps[i], lc)?;
            sys.systems[sys.of_case[i]].solve_checked(&mut r, 1)?;
            Ok(r)
        })
        .collect()
}

/// The equation values of each unit load.
fn solve_units(base: &Point, free: &System, units: &[[usize; 2]]) -> Result<Vec<Vec<f64>>, GradientError> {
    units
        .iter()
        .map(|&[node, dof]| {
            let mut f = vec![0.0; base.model.n_dofs()];
            f[6 * node + dof] = 1.0;
            let mut r = free.dof_map().reduce(&f);
            free.solve_checked(&mut r, 1)?;
            Ok(r)
        })
        .collect()
}
