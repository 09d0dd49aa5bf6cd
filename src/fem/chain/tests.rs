//! The chain condensation against closed forms.

use super::*;
use crate::fem::{Beam, Section, Support};
use crate::material::Material;
use std::f64::consts::PI;

/// An L-shaped Euler–Bernoulli cantilever of round bar: clamped at the origin, leg 1 along x
/// (length a), leg 2 along y (length b), each in two elements, one of them numbered against
/// the chain's direction. The tip compliance in global axes (Castigliano, bending and torsion
/// of each leg; e.g. W. C. Young, R. G. Budynas, Roark's Formulas for Stress and Strain, 7th
/// ed., 2002, Table 8.1 case 1a and §10.2):
///
/// ```text
/// w/F_z = a³/(3EI) + b³/(3EI) + a b²/(GJ)      (both legs bend, leg 1 twists by F_z b)
/// u/F_x = a/(EA) + b³/(3EI) + a b²/(EI)        (leg 1 stretches and bends under F_x b)
/// θ_z/M_z = (a + b)/(EI)
/// ```
#[test]
fn l_shaped_cantilever_chain_matches_closed_form() {
    let (a, b, d) = (60.0, 40.0, 5.0);
    let m = Material::STEEL;
    let mut model = Model::new();
    let n: Vec<usize> = [[0.0, 0.0], [a / 2.0, 0.0], [a, 0.0], [a, b / 2.0], [a, b]]
        .iter()
        .map(|&[x, y]| model.add_node([x, y, 0.0]))
        .collect();
    for (p, q) in [(n[0], n[1]), (n[2], n[1]), (n[2], n[3]), (n[3], n[4])] {
        let mut beam = Beam::new(p, q, Section::Circle { d }, m, [0.0, 0.0, 1.0]);
        beam.shear = false;
        model.add_beam(beam);
    }
    model.supports.push(Support::clamp(n[0]));
    let c = Condensed::new(&model, &[], &[n[4]]).unwrap();
    assert_eq!(c.chains.len(), 1, "one chain");
    let chain = &c.chains[0];
    assert_eq!((chain.nodes[0], *chain.nodes.last().unwrap()), (n[0], n[4]));
    let (e, g) = (m.e, m.shear_modulus());
    let i = PI * d.powi(4) / 64.0;
    let (area, j) = (PI * d * d / 4.0, 2.0 * i);
    let cases = [
        (
            "w/Fz",
            2,
            a.powi(3) / (3.0 * e * i) + b.powi(3) / (3.0 * e * i) + a * b * b / (g * j),
        ),
        (
            "u/Fx",
            0,
            a / (e * area) + b.powi(3) / (3.0 * e * i) + a * b * b / (e * i),
        ),
        ("θz/Mz", 5, (a + b) / (e * i)),
    ];
    for (what, k, expected) in cases {
        let got = chain.ends().c_b[(k, k)];
        eprintln!(
            "{what}: chain {got:e}, closed form {expected:e}, relative {:e}",
            (got - expected).abs() / expected
        );
        assert!(
            (got - expected).abs() <= 1e-12 * expected,
            "{what}: chain {got:e}, closed form {expected:e}"
        );
    }
}

/// The inner nodes recovered from the end motions satisfy the same closed form: the tip of the
/// L-shaped cantilever under F_z moves w (above) and the corner a³/(3EI)·F_z (leg 1 as a
/// cantilever with F_z and the torque F_z b, which does not move its tip along z).
#[test]
fn recovered_corner_of_l_shaped_cantilever_matches_closed_form() {
    let (a, b, d, f) = (60.0, 40.0, 5.0, 2.0);
    let m = Material::STEEL;
    let mut model = Model::new();
    let n: Vec<usize> = [[0.0, 0.0], [a, 0.0], [a, b]]
        .iter()
        .map(|&[x, y]| model.add_node([x, y, 0.0]))
        .collect();
    for (p, q) in [(n[0], n[1]), (n[1], n[2])] {
        let mut beam = Beam::new(p, q, Section::Circle { d }, m, [0.0, 0.0, 1.0]);
        beam.shear = false;
        model.add_beam(beam);
    }
    model.supports.push(Support::clamp(n[0]));
    let c = Condensed::new(&model, &[], &[n[2]]).unwrap();
    let chain = &c.chains[0];
    // The tip moves C_b f_b with the root clamped.
    let f_b = Vector6::new(0.0, 0.0, f, 0.0, 0.0, 0.0);
    let mut u = vec![0.0; 18];
    let tip = chain.ends().c_b * f_b;
    u[12..18].copy_from_slice(tip.as_slice());
    let back = chain.recover(&mut u);
    let i = PI * d.powi(4) / 64.0;
    let expected = f * a.powi(3) / (3.0 * m.e * i);
    eprintln!(
        "corner w {:e} vs {expected:e}; end force back {:e}",
        u[8],
        (back - f_b).amax()
    );
    assert!(
        (u[8] - expected).abs() <= 1e-12 * expected,
        "corner w {} vs {expected}",
        u[8]
    );
    assert!((back - f_b).amax() <= 1e-12 * f, "end force {back:?} vs {f_b:?}");
}
