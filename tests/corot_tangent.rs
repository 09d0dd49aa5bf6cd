//! The closed-form consistent tangent of the co-rotational beam (`fem::corot`, after
//! J.-M. Battini & C. Pacoste, CMAME 191 (2002) 1755–1789, with the variation of G in full)
//! against central differences of the closed-form internal force, for random element states
//! with large rotations, exact Timoshenko beams and hinge flexibility elements; and Newton's
//! quadratic convergence on the stage's nonlinear load steps with every tangent option.
//!
//! Source of the reference: the definition K = ∂f/∂d (spin variations of the nodal rotations,
//! R ← exp([δw×])R), evaluated by central differences. Their error is O(h²) truncation plus
//! O(ε/h) round-off; with h = 1e-5 (rotations, rad) and 1e-5·L (translations) both stay below
//! ~1e-8 of the entries' natural scale √(K_ii K_jj) (the rest stiffness's diagonal) on these
//! states (measured ≤ 8e-9), so a tolerance of 1e-7 separates a consistent tangent from an
//! inconsistent one: dropping the variation of η, ηᵢⱼ (Battini & Pacoste's E G a r term alone)
//! errs by 1e-7 to 1 on the same states (measured).

#[path = "common/fixtures.rs"]
mod fixtures;
#[path = "common/rng.rs"]
mod rng;

use flexfem::fem::corot::{
    self, geometric_tangent, geometric_tangent_fd, perturbed, rot_exp, CorotGeometry, NodeState, Vec7,
};
use flexfem::fem::element::{beam_local_stiffness, cantilever_compliance, flex_local_stiffness};
use flexfem::fem::transform::{beam_frame, Mat12};
use flexfem::fem::{self, Section, Tangent};
use flexfem::stage::Drive;
use nalgebra::{Matrix6, Vector3};
use rng::Rng;

const E: f64 = 72000.0;
const G: f64 = 27000.0;

fn vec3(r: &mut Rng, s: f64) -> Vector3<f64> {
    Vector3::new(r.uniform(-s, s), r.uniform(-s, s), r.uniform(-s, s))
}

/// A random element: length 5–50 mm in a random direction, random `up`; the local stiffness
/// of an exact Timoshenko beam (rectangle 1–4 mm) or of a flexibility element with a fully
/// coupled symmetric positive definite compliance (a notch-like cantilever compliance, every
/// pair of its DOFs coupled).
fn element(r: &mut Rng, flex: bool) -> (CorotGeometry, Mat12) {
    let l = r.uniform(5.0, 50.0);
    let dir = vec3(r, 1.0).normalize();
    let x1 = vec3(r, 100.0);
    let x2 = x1 + dir * l;
    let up = vec3(r, 1.0);
    let (lam, l0) = beam_frame(x1.into(), x2.into(), up.into()).expect("random axis not along up");
    let props = Section::Rect {
        w: r.uniform(1.0, 4.0),
        h: r.uniform(1.0, 4.0),
    }
    .properties(0.33);
    let k = if flex {
        let c0 = cantilever_compliance(E, G, &props, l0, true);
        let d = Matrix6::from_diagonal(&c0.diagonal().map(f64::sqrt));
        let a = Matrix6::from_fn(|_, _| r.uniform(-1.0, 1.0));
        let c = d * (a * a.transpose() / 6.0 + Matrix6::identity() * 0.5) * d;
        flex_local_stiffness(&c, l0).expect("SPD compliance")
    } else {
        beam_local_stiffness(E, G, &props, l0, true)
    };
    let geom = CorotGeometry {
        x1,
        x2,
        r0: lam.transpose(),
        l0,
    };
    (geom, k)
}

/// A random deformed state: a large rigid rotation (up to 3 rad) and translation of the whole
/// element, then nodal deformations of `def` (relative rotations up to `def` rad, stretch and
/// transverse motion up to 0.2·def·L).
fn state(r: &mut Rng, g: &CorotGeometry, def: f64) -> (NodeState, NodeState) {
    let rig = rot_exp(&vec3(r, 3.0 / 3f64.sqrt()));
    let t = vec3(r, g.l0);
    let node = |r: &mut Rng, x: &Vector3<f64>| NodeState {
        u: rig * x + t - x + vec3(r, 0.2 * def * g.l0),
        r: rot_exp(&vec3(r, def)) * rig,
    };
    (node(r, &g.x1), node(r, &g.x2))
}

/// Central differences of `f` (12 outputs) over the 12 DOFs (spin variations for rotations).
fn central(g: &CorotGeometry, a: &NodeState, b: &NodeState, f: impl Fn(&NodeState, &NodeState) -> [f64; 12]) -> Mat12 {
    let mut k = Mat12::zeros();
    for j in 0..12 {
        let (node, dof) = (j / 6, j % 6);
        let h = if dof < 3 { 1e-5 * g.l0 } else { 1e-5 };
        let at = |s: f64| {
            if node == 0 {
                f(&perturbed(a, dof, s), b)
            } else {
                f(a, &perturbed(b, dof, s))
            }
        };
        let (p, m) = (at(h), at(-h));
        for i in 0..12 {
            k[(i, j)] = (p[i] - m[i]) / (2.0 * h);
        }
    }
    k
}

/// max |A − B|ᵢⱼ / √(S_ii S_jj): the error on the scale of a positive diagonal `s`.
fn scaled_error(a: &Mat12, b: &Mat12, s: &Mat12) -> f64 {
    let mut e = 0.0f64;
    for i in 0..12 {
        for j in 0..12 {
            e = e.max((a[(i, j)] - b[(i, j)]).abs() / (s[(i, i)] * s[(j, j)]).sqrt());
        }
    }
    e
}

/// The element's material stiffness at rest, rotated to global axes: the positive diagonal
/// that sets the scale of each DOF.
fn scale(g: &CorotGeometry, k: &Mat12) -> Mat12 {
    let rest = NodeState::default();
    let r = corot::response(g, k, &rest, &rest, true).expect("rest state");
    let mut s = r.k;
    for i in 0..12 {
        s[(i, i)] = s[(i, i)].abs().max(1e-300);
    }
    s
}

#[test]
fn closed_form_tangent_is_the_derivative_of_the_internal_force() {
    let mut rng = Rng::new(0x5EED_C0A7);
    let mut worst = [0.0f64; 2];
    let mut n = 0;
    for case in 0..120 {
        let flex = case % 2 == 1;
        let (g, k) = element(&mut rng, flex);
        // Deformations from nearly none (the Taylor branch of Ts⁻¹, |θ̄| < 0.05) to 0.8 rad.
        let def = [1e-3, 0.05, 0.3, 0.8][case % 4];
        let (a, b) = state(&mut rng, &g, def);
        let Some(resp) = corot::response(&g, &k, &a, &b, true) else {
            continue;
        };
        let fd = central(&g, &a, &b, |x, y| {
            let f = corot::response(&g, &k, x, y, false).expect("near a valid state").f;
            std::array::from_fn(|i| f[i])
        });
        let err = scaled_error(&resp.k, &fd, &scale(&g, &k));
        worst[flex as usize] = worst[flex as usize].max(err);
        n += 1;
        assert!(
            err < 1e-7,
            "case {case} (flex {flex}, deformation {def}): tangent error {err:e}"
        );
    }
    println!(
        "{n} states; worst scaled error: beam {:.1e}, flexibility element {:.1e}",
        worst[0], worst[1]
    );
    assert!(n >= 110, "only {n} of 120 states were valid");
}

/// The closed-form geometric part at fixed local forces against the finite-difference one the
/// solver used before (central differences of B, h = 1e-6).
#[test]
fn closed_form_geometric_part_matches_differences_of_b() {
    let mut rng = Rng::new(0xB_A771);
    for case in 0..40 {
        let (g, _) = element(&mut rng, case % 2 == 1);
        let (a, b) = state(&mut rng, &g, [1e-3, 0.3, 0.8, 1.2][case % 4]);
        let f7 = Vec7::from_fn(|i, _| rng.uniform(-1.0, 1.0) * if i == 0 { 100.0 } else { 100.0 * g.l0 });
        let (Some(cf), Some(fd)) = (
            geometric_tangent(&g, &a, &b, &f7),
            geometric_tangent_fd(&g, &a, &b, &f7),
        ) else {
            continue;
        };
        let err = (cf - fd).amax() / cf.amax();
        assert!(err < 1e-6, "case {case}: {err:e}");
    }
}

/// Residuals of each step relative to its first: once below 1e-3, r_{k+1} ≤ 100 r_k² down to
/// the round-off floor (a linear rate r_{k+1} ~ c r_k stays above it); returns how often the
/// rate was seen. The floor: the stage's residuals stop at ~5e-13 of the step's first (forces
/// of the stiff legs, EA ~ 7e6 N, at round-off relative error), so ratios below 1e-11 are not
/// judged.
fn quadratic_steps(path: &[fem::nonlinear::PathPoint], what: &str) -> usize {
    let mut shown = 0;
    for p in &path[1..] {
        let r = &p.residuals;
        for w in r.windows(2) {
            let (a, b) = (w[0] / r[0], w[1] / r[0]);
            if a < 1e-3 && b > 1e-11 {
                assert!(
                    b <= 100.0 * a * a,
                    "{what}, λ {}: {a:e} → {b:e} is not quadratic ({r:?})",
                    p.lambda
                );
                shown += 1;
            }
        }
    }
    shown
}

/// The stage (Ruiz et al. 2019, Table 4 row 1 strokes; 4 co-rotational segments per hinge)
/// converges quadratically in every step with the symmetric (Cholesky, the default here) and
/// the full non-symmetric (LU) tangent, to the same answer.
#[test]
fn newton_is_quadratic_on_the_stage_steps() {
    let s = fixtures::ruiz2019_stage_design().build().expect("builds");
    let cases = vec![("row1".to_string(), Drive::Strokes([1.395, 1.531, 1.306]))];
    let (model, _) = s.nonlinear_model(&cases, 4).expect("model");
    let mut z = Vec::new();
    for tangent in [Tangent::Auto, Tangent::Symmetric, Tangent::Full] {
        let opts = fem::NonlinearOptions {
            tangent,
            ..s.nonlinear_options(5)
        };
        let res = fem::solve_nonlinear(&model, &opts).expect("solves");
        let c = &res.load_cases[0];
        let shown = quadratic_steps(&c.path, &format!("{tangent:?}"));
        println!(
            "{tangent:?}: {} steps, {} iterations, quadratic rate seen {shown} times",
            c.steps, c.iterations
        );
        for p in &c.path[1..] {
            println!(
                "  λ {:.2}: {:?}",
                p.lambda,
                p.residuals.iter().map(|v| format!("{v:.1e}")).collect::<Vec<_>>()
            );
        }
        assert!(
            shown >= c.steps,
            "{tangent:?}: quadratic rate seen {shown} times in {} steps",
            c.steps
        );
        z.push(c.fe.displacements[s.platform][2]);
    }
    // The tangent changes the iterates, not the converged state (tolerance 1e-8 of the load).
    assert!((z[1] - z[2]).abs() < 1e-9 * z[1].abs(), "{z:?}");
}
