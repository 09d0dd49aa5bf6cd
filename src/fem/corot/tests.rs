//! Unit checks of the co-rotational kinematics: force = energy gradient, tangent = force
//! gradient (finite differences), rigid motions force-free.

use super::*;

fn geom() -> CorotGeometry {
    CorotGeometry {
        x1: Vector3::new(0.0, 0.0, 0.0),
        x2: Vector3::new(10.0, 2.0, -1.0),
        r0: crate::fem::transform::beam_frame([0.0; 3], [10.0, 2.0, -1.0], [0.0, 0.0, 1.0])
            .map(|(l, _)| l.transpose())
            .unwrap_or_else(Matrix3::identity),
        l0: (105.0f64).sqrt(),
    }
}

fn energy(g: &CorotGeometry, k7: &Mat7, a: &NodeState, b: &NodeState) -> f64 {
    let kin = kinematics(g, a, b).unwrap_or_else(|| panic!("degenerate"));
    0.5 * kin.p.dot(&(k7 * kin.p))
}

fn state() -> (NodeState, NodeState) {
    (
        NodeState {
            u: Vector3::new(0.3, -0.2, 0.5),
            r: rot_exp(&Vector3::new(0.4, -0.3, 0.7)),
        },
        NodeState {
            u: Vector3::new(-1.0, 2.0, 0.7),
            r: rot_exp(&Vector3::new(-0.2, 0.5, 0.9)),
        },
    )
}

fn k_local() -> Mat12 {
    let p = crate::fem::Section::Rect { w: 1.0, h: 2.0 }.properties(0.3);
    crate::fem::element::beam_local_stiffness(1000.0, 400.0, &p, 105f64.sqrt(), true)
}

/// f = ∂U/∂d (spin variations) and K = ∂f/∂d, by finite differences of the energy and force.
#[test]
fn force_and_tangent_are_consistent() {
    let g = geom();
    let kl = k_local();
    let k7 = k7_of(&kl);
    let (a, b) = state();
    let r = response(&g, &kl, &a, &b, true).unwrap_or_else(|| panic!("degenerate"));
    let h = 1e-6;
    for j in 0..12 {
        let (node, dof) = (j / 6, j % 6);
        let e = |s: f64| {
            let (x, y) = if node == 0 {
                (perturbed(&a, dof, s), b)
            } else {
                (a, perturbed(&b, dof, s))
            };
            (energy(&g, &k7, &x, &y), response(&g, &kl, &x, &y, false).map(|r| r.f))
        };
        let (ep, fp) = e(h);
        let (em, fm) = e(-h);
        let fd = (ep - em) / (2.0 * h);
        assert!((fd - r.f[j]).abs() < 1e-5 * r.f.amax(), "f[{j}]: {fd} vs {}", r.f[j]);
        let (fp, fm) = (fp.unwrap_or_default(), fm.unwrap_or_default());
        let col = (fp - fm) / (2.0 * h);
        for i in 0..12 {
            assert!(
                (col[i] - r.k[(i, j)]).abs() < 1e-5 * r.k.amax(),
                "K[{i},{j}]: {} vs {}",
                col[i],
                r.k[(i, j)]
            );
        }
    }
}

/// A rigid motion gives no deformation and no force.
#[test]
fn rigid_motion_is_force_free() {
    let g = geom();
    let rot = rot_exp(&Vector3::new(1.0, -2.0, 0.5));
    let t = Vector3::new(3.0, 4.0, -5.0);
    let a = NodeState {
        u: rot * g.x1 + t - g.x1,
        r: rot,
    };
    let b = NodeState {
        u: rot * g.x2 + t - g.x2,
        r: rot,
    };
    let r = response(&g, &k_local(), &a, &b, false).unwrap_or_else(|| panic!("degenerate"));
    assert!(r.f.amax() < 1e-9, "{:?}", r.f);
}
