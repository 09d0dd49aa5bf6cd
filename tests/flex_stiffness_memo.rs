//! A flex element's stiffnesses are remembered per thread by the exact bits of its compliance
//! (and length): every answer must equal, to the last bit, the stiffness computed afresh by
//! `flex_local_stiffness` / `flex_tip_stiffness`, however many other compliances were asked in
//! between, and a compliance that is not positive definite stays an error.

use flexfem::fem::element::{flex_local_stiffness, flex_tip_stiffness};
use flexfem::fem::elements::FlexElement;
use nalgebra::Matrix6;

fn element(k: usize) -> FlexElement {
    let s = 1.0 + 0.01 * k as f64;
    let mut c = [[0.0; 6]; 6];
    for (i, row) in c.iter_mut().enumerate() {
        row[i] = s * 1e-4 * (i + 1) as f64;
    }
    // A coupling term (bending–shear) as in a hinge's compliance.
    c[1][5] = 2e-6 * s;
    c[5][1] = 2e-6 * s;
    FlexElement {
        nodes: [0, 1],
        compliance: c,
        up: [0.0, 0.0, 1.0],
    }
}

#[test]
fn remembered_flex_stiffness_equals_the_fresh_one() {
    // 30 compliances at two lengths (more than the memo's 48 slots), twice over.
    for round in 0..2 {
        for k in 0..30 {
            let e = element(k);
            let c = Matrix6::from_fn(|i, j| e.compliance[i][j]);
            for l in [5.0, 7.5] {
                let fresh = flex_local_stiffness(&c, l).unwrap();
                assert_eq!(
                    e.local_stiffness(k, l).unwrap(),
                    fresh,
                    "round {round}, element {k}, l {l}"
                );
            }
            assert_eq!(e.tip_stiffness(k).unwrap(), flex_tip_stiffness(&c).unwrap());
        }
    }
    let mut bad = element(3);
    bad.compliance[2][2] = -1.0;
    assert!(bad.local_stiffness(7, 5.0).is_err());
    assert!(bad.tip_stiffness(7).is_err());
}
