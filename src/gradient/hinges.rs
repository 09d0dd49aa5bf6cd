//! Hinge elements in the direct method: dK/dp of a hinge's flexibility elements through the
//! analytic derivative of its compliance ([`crate::hinge::tangent`]) rather than a difference
//! of its flexibility integrals.
//!
//! A flexibility element has k = Bᵀ C⁻¹ B in its local axes (B the equilibrium matrix of its
//! length L, [`fem::element::flex_b`]) and K = Tᵀ k T globally. Along a parameter p both the
//! compliance C (hinge dimensions, material, blank length = node distance/2 − notch
//! half-length) and the geometry (L, T, rigid-link arms: node coordinates) may move:
//!
//! dK/dp = Tᵀ Bᵀ (−C⁻¹ (dC/dp) C⁻¹) B T  +  ∂K/∂(geometry) · d(geometry)/dp.
//!
//! The first term is assembled here from dC/dp: every entry analytic but the warping-restrained
//! torsion compliance of rectangular notches (a Vlasov finite-element solve), whose derivative
//! is the sixth-order difference of the moved models' regions already built by the stencil
//! (no extra solve). The second term stays a difference at element level, with each hinge's
//! compliance held at its value at p ([`freeze`]): it is zero unless the parameter moves the
//! hinge's nodes.

use super::point::Point;
use crate::fem::{self, assembly::Pattern, constraints::DofMap, element::flex_b, transform::rotate12, Element, Model};
use crate::hinge::tangent::{half_notch_derivative, region_compliance_derivatives, Tangent};
use nalgebra::Matrix6;

/// The flexibility elements of every hinge of `base` (each segment of a chain), with the hinge
/// they belong to (index in `base.hinges`).
pub(super) fn hinge_elements(base: &Point) -> Vec<(usize, Vec<usize>)> {
    base.hinges
        .iter()
        .enumerate()
        .map(|(k, h)| {
            let mut els = vec![h.element];
            if h.segments > 1 {
                els.extend(h.last + 2 - h.segments..=h.last);
            }
            (k, els)
        })
        .collect()
}

/// Replaces, in `values` (the stiffness values of the moved model `moved` on `map`), the range
/// of every hinge element by the values it takes with its compliance at `base` (geometry of
/// `moved`): the stencil then differences the geometry only. Where no node of the model moved
/// (rigid-link arms included), the range is zeroed instead (the frozen values equal the base
/// ones, which the stencil's weights sum to zero).
pub(super) fn freeze(
    pattern: &Pattern,
    map: &DofMap,
    base: &Model,
    moved: &Model,
    hinges: &[(usize, Vec<usize>)],
    values: &mut [f64],
) -> Result<(), fem::FemError> {
    let still = moved.nodes == base.nodes;
    for &ie in hinges.iter().flat_map(|(_, els)| els) {
        let range = pattern.element_values(ie);
        let (Some(Element::Flex(b)), Some(Element::Flex(m))) = (base.elements.get(ie), moved.elements.get(ie)) else {
            continue;
        };
        if still && m.up == b.up {
            values[range].fill(0.0);
            continue;
        }
        let (lam, l) = moved.element_frame(ie)?;
        let frozen = fem::FlexElement {
            compliance: b.compliance,
            ..m.clone()
        };
        let em = fem::model::ElementMatrix {
            nodes: m.nodes,
            n_nodes: 2,
            k: rotate12(&frozen.local_stiffness(ie, l)?, &lam),
        };
        pattern.element_values_of(map, &em, &mut values[range]);
    }
    Ok(())
}

/// True when [`freeze`] zeroes the range of every element of `moved`: no node moved and every
/// element is a hinge's flexibility element with its `up` unchanged. The stencil's stiffness
/// values are then zero and need not be computed.
pub(super) fn all_frozen(base: &Model, moved: &Model, hinges: &[(usize, Vec<usize>)]) -> bool {
    if moved.nodes != base.nodes || moved.elements.len() != base.elements.len() {
        return false;
    }
    let mut hinge = vec![false; moved.elements.len()];
    for &ie in hinges.iter().flat_map(|(_, els)| els) {
        if let Some(h) = hinge.get_mut(ie) {
            *h = true;
        }
    }
    moved
        .elements
        .iter()
        .zip(&base.elements)
        .zip(&hinge)
        .all(|((m, b), &h)| h && matches!((m, b), (Element::Flex(m), Element::Flex(b)) if m.up == b.up))
}

/// A hinge (index in `Point::hinges`), its tangent and its elements' dC/dp, for the hinges that
/// repeat it.
type Shared = (usize, Tangent, Vec<[[f64; 6]; 6]>);

/// dC/dp of every hinge element of `base` (in the order of `hinges`' elements), from the points
/// of the stencil: `points[i]` = (step s_i, weight w_i, point), Σ wᵢ f(sᵢ) ≈ df/dp. The
/// dimensions and material move on a straight path (the case's numbers do), so their
/// derivatives are read from the point at the smallest positive step; the blank length follows
/// the node distance.
pub(super) fn compliance_derivatives(
    base: &Point,
    points: &[(f64, f64, &Point)],
    hinges: &[(usize, Vec<usize>)],
) -> Vec<(usize, [[f64; 6]; 6])> {
    let mut out = Vec::new();
    // Identical hinges moving identically (a mechanism's repeated hinge type) share one result.
    let mut done: Vec<Shared> = Vec::new();
    let Some(&(step, _, ahead)) = points
        .iter()
        .filter(|(s, ..)| *s > 0.0)
        .min_by(|a, b| a.0.total_cmp(&b.0))
    else {
        return out;
    };
    for (k, els) in hinges {
        let (h0, h1) = (&base.hinges[*k], &ahead.hinges[*k]);
        let (p0, p1) = (&h0.region.profile, &h1.region.profile);
        let Some(mut tangent) = Tangent::between((p0, &h0.material), (p1, &h1.material), step) else {
            continue;
        };
        // Blank per side = node distance/2 − notch half-length (hinge::hinge_element).
        let ends = |m: &Model| -> Option<[[f64; 3]; 2]> {
            let first = match m.elements.get(h0.element)? {
                Element::Flex(f) => f.nodes[0],
                _ => return None,
            };
            let last = match m.elements.get(h0.last)? {
                Element::Flex(f) => f.nodes[1],
                _ => return None,
            };
            Some([m.nodes[first], m.nodes[last]])
        };
        let (Some([a0, b0]), Some([a1, b1])) = (ends(&base.model), ends(&ahead.model)) else {
            continue;
        };
        let axis: [f64; 3] = std::array::from_fn(|i| b0[i] - a0[i]);
        let len = axis.iter().map(|x| x * x).sum::<f64>().sqrt();
        let d_len: f64 = (0..3).map(|i| axis[i] / len * ((b1[i] - a1[i]) - axis[i]) / step).sum();
        tangent.blank = if p0.blank > 0.0 {
            0.5 * d_len - half_notch_derivative(p0, &tangent)
        } else {
            0.0
        };
        if tangent.is_zero() {
            continue;
        }
        let same = |(j, t, _): &&Shared| {
            let g = &base.hinges[*j];
            *t == tangent && g.region == h0.region && g.material == h0.material && g.segments == h0.segments
        };
        let dc = match done.iter().find(same) {
            Some((.., dc)) => dc.clone(),
            None => {
                let torsion: f64 = points
                    .iter()
                    .map(|(_, w, pt)| w * pt.hinges[*k].region.stiffness.compliance[3][3])
                    .sum();
                let dc = region_compliance_derivatives(
                    p0,
                    &h0.material,
                    &h0.region.stiffness,
                    &tangent,
                    torsion,
                    h0.segments,
                );
                done.push((*k, tangent, dc.clone()));
                dc
            }
        };
        out.extend(els.iter().copied().zip(dc)); // zip-checked: one derivative per segment
    }
    out
}

/// Adds Tᵀ Bᵀ (−C⁻¹ dC C⁻¹) B T of every hinge element (dC from [`compliance_derivatives`])
/// to `dvalues`, the derivative of the stiffness values of `base` on `map`.
pub(super) fn add_analytic(
    pattern: &Pattern,
    map: &DofMap,
    base: &Model,
    derivatives: &[(usize, [[f64; 6]; 6])],
    dvalues: &mut [f64],
) -> Result<(), fem::FemError> {
    let mut chunk = Vec::new();
    for (ie, dc) in derivatives {
        let (lam, l) = base.element_frame(*ie)?;
        let kc = base.flex_tip_stiffness(*ie)?;
        let dc = Matrix6::from_fn(|i, j| dc[i][j]);
        let dkc = -(kc * dc * kc);
        let b = flex_b(l);
        let dk = b.transpose() * dkc * b;
        let em = fem::model::ElementMatrix {
            nodes: base.elements[*ie].end_nodes(),
            n_nodes: 2,
            k: rotate12(&((dk + dk.transpose()) * 0.5), &lam),
        };
        let range = pattern.element_values(*ie);
        chunk.clear();
        chunk.resize(range.len(), 0.0);
        pattern.element_values_of(map, &em, &mut chunk);
        dvalues[range].iter_mut().zip(&chunk).for_each(|(d, x)| *d += x); // zip-checked: chunk has the range's length
    }
    Ok(())
}
