//! A hinge region as a chain of co-rotational flexibility elements, for geometrically
//! nonlinear solves: the region bends through degrees, which one co-rotational element
//! represents only to first order in the rotation.

use super::{segment_compliance, Profile, Stiffness};
use crate::fem::{self, Model};
use crate::material::Material;
use nalgebra::{Matrix6, Vector3};

/// Co-rotational segments a hinge element is split into in a geometrically nonlinear run when
/// its case gives no `segments`. Chosen by measurement against 16 segments (circular notch
/// R = 5, t = 1 mm in a 10 × 10 mm Al 7075 bar): the parallelogram guide of
/// `cases/parallelogram_guide.json` at a 1 mm stroke (0.57° per hinge) drops 4.908 µm with 4
/// segments against 4.920 µm (−0.24 %; one segment: 4.620 µm, −6.1 %), the lever of
/// `cases/lever_amplifier.json` driven 1 mm (5.7°) peaks at 1533 MPa against 1537 MPa (−0.22 %;
/// one segment −5.6 %; odd counts put no node at the notch centre and do worse: 3 segments
/// −1.1 %); at 17° the peak stress is −0.55 %. Rotations agree to 1e-5 at every count. The
/// error of a fixed count is nearly independent of the rotation (the lost shortening is a fixed
/// fraction of ½∫θ² ds), so the count is fixed; the stage's nonlinear solve uses the same.
pub const NONLINEAR_SEGMENTS: usize = 4;

/// Replaces the flexibility element `el` of `model` (spanning the hinge region `profile`, one
/// element of compliance `single`) by a chain of `n` flexibility elements over equal
/// sub-intervals of the region; returns the index of the last one (the first keeps index `el`,
/// the others and the `n − 1` inner nodes are appended to the model).
///
/// Segment compliances from [`chain_compliances`]. `None` when `el` is not a flexibility
/// element.
pub fn split_flex(
    model: &mut Model,
    el: usize,
    profile: &Profile,
    material: &Material,
    single: &Stiffness,
    n: usize,
) -> Option<usize> {
    let cs = chain_compliances(profile, material, single, n);
    split_flex_with(model, el, &cs)
}

/// The 6×6 compliances (hinge axes, mm/N, rad/(N·mm)) of `n` flexibility elements over equal
/// sub-intervals of the hinge region `profile` (one element of compliance `single`), from
/// [`segment_compliance`]; their Saint-Venant torsion compliance is scaled so the chain keeps
/// the torsion compliance of the single element (warping-restrained for rectangular notches),
/// so the linear response is that of the single element.
pub fn chain_compliances(profile: &Profile, material: &Material, single: &Stiffness, n: usize) -> Vec<[[f64; 6]; 6]> {
    let half = profile.half_length();
    let xs: Vec<f64> = (0..=n).map(|k| -half + 2.0 * half * k as f64 / n as f64).collect();
    let cs: Vec<Matrix6<f64>> = xs
        .windows(2)
        .map(|w| segment_compliance(profile, material, w[0], w[1]))
        .collect();
    let sv: f64 = cs.iter().map(|c| c[(3, 3)]).sum();
    let scale = single.compliance[3][3] / sv;
    cs.iter()
        .map(|c| {
            let mut cm = [[0.0; 6]; 6];
            for (i, row) in cm.iter_mut().enumerate() {
                for (j, v) in row.iter_mut().enumerate() {
                    *v = c[(i, j)] * if i == 3 && j == 3 { scale } else { 1.0 };
                }
            }
            cm
        })
        .collect()
}

/// [`split_flex`] with the chain's compliances given ([`chain_compliances`]: one element per
/// entry, in order from the element's first node).
pub fn split_flex_with(model: &mut Model, el: usize, compliances: &[[[f64; 6]; 6]]) -> Option<usize> {
    let Some(fem::Element::Flex(f)) = model.elements.get(el).cloned() else {
        return None;
    };
    let (a, b) = (
        Vector3::from(model.nodes[f.nodes[0]]),
        Vector3::from(model.nodes[f.nodes[1]]),
    );
    let n = compliances.len();
    let mut prev = f.nodes[0];
    let mut last = el;
    for (k, cm) in compliances.iter().enumerate() {
        let next = if k + 1 == n {
            f.nodes[1]
        } else {
            let x = a + (b - a) * ((k + 1) as f64 / n as f64);
            model.add_node([x[0], x[1], x[2]])
        };
        let e = fem::Element::Flex(fem::FlexElement {
            nodes: [prev, next],
            compliance: *cm,
            up: f.up,
        });
        if k == 0 {
            model.elements[el] = e;
        } else {
            last = model.add_element(e);
        }
        prev = next;
    }
    Some(last)
}
