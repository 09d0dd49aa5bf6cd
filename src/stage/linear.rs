//! The linear stage solved directly on its condensed form, without building an FE model: each
//! leg is a serial chain (revolute notch, leg beams, spherical neck) from its slider to the
//! platform, exactly one 6×6 flexibility ([`crate::fem::chain`], Przemieniecki 1968 §6.5/§9.6);
//! with the platform rigid and each slider free only along eᵢ, the stage has nine unknowns
//! (the platform motion u_P and the three strokes sᵢ). Leg i's end force at its neck top Tᵢ is
//! f = K (u_T − R(x_T − x_S) u_S), with u_T = R(x_T − x_P) u_P and u_S = (sᵢ eᵢ, 0); the
//! stiffness is the sum of those energies (the same equations as the FE path's condensed model,
//! to roundoff). Element forces then follow from statics along each chain, as in
//! [`crate::fem::chain::Chain::element_results`].
//!
//! Everything is fixed-size (nalgebra static matrices, arrays): a design costs no heap
//! allocation. Ideal joints (exact releases) are not covered: [`ValidStage::linear`] returns
//! `None` and the caller uses the FE model.

use super::build::arr;
use super::*;
use crate::fem::element::cantilever_compliance;
use crate::fem::recovery::point_von_mises;
use crate::fem::section::{rect_stress_points, Section, SectionProps, StressPoint};
use crate::fem::transform::{beam_frame, rigid_arm, t6};
use crate::hinge;
use nalgebra::Vector3;
use nalgebra::{Matrix6, SMatrix, SVector, Vector6};

/// What one linear load case gives: the numbers of a [`StageCaseResult`] (same names, units
/// and meaning), without its name, FE result and stability.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StageResponse {
    /// Strokes, mm, and actuator forces, N, along each eᵢ.
    pub strokes: [f64; 3],
    pub forces: [f64; 3],
    /// Platform pose change (small-rotation components).
    pub platform: PoseChange,
    /// Peak von Mises stress in each hinge, MPa: [revolute, spherical][leg].
    pub hinge_stress: [[f64; 3]; 2],
    /// The largest von Mises stress (hinges and leg beams), MPa.
    pub max_von_mises: f64,
}

impl StageCaseResult {
    /// The response part of the result.
    pub fn response(&self) -> StageResponse {
        StageResponse {
            strokes: self.strokes,
            forces: self.forces,
            platform: self.platform,
            hinge_stress: [self.revolute_stress, self.spherical_stress],
            max_von_mises: self.max_von_mises,
        }
    }
}

impl StageResponse {
    /// T = max σ_sph / max σ_rev (Ruiz et al. (2019) §5).
    pub fn t_ratio(&self) -> f64 {
        let [r, s] = self.hinge_stress.map(|h| h.iter().cloned().fold(0.0, f64::max));
        s / r
    }
}

/// One element of a leg chain: its end points p → q (towards the platform) and its frame's
/// `up` (its compliance: [`LinearStage::local_compliance`]).
struct Piece {
    p: Vector3<f64>,
    q: Vector3<f64>,
    up: Vector3<f64>,
    /// A leg beam (else a hinge: `hinge` 0 revolute, 1 spherical).
    beam: bool,
    hinge: usize,
}

/// One leg condensed: end points, stiffness of the chain and its couplings.
#[derive(Debug, Clone, Copy)]
struct Leg {
    i: usize,
    e: Vector3<f64>,
    /// Slider node, neck top (platform side).
    xs: Vector3<f64>,
    xt: Vector3<f64>,
    /// C_b⁻¹ of the chain (global axes).
    k: Matrix6<f64>,
    /// R(x_T − x_P): platform motion → neck-top motion.
    a: Matrix6<f64>,
    /// R(x_T − x_S)·(eᵢ, 0): unit stroke → neck-top motion carried rigidly.
    g: Vector6<f64>,
}

/// A linear stage ready to solve load cases: the three legs condensed, the platform stiffness
/// factorised (see the module notes). Built by [`ValidStage::linear`].
#[derive(Debug, Clone)]
pub struct LinearStage<'a> {
    stage: &'a ValidStage,
    legs: [Leg; 3],
    /// The full 9×9 stiffness (u_P, s₁, s₂, s₃) and its Cholesky factor.
    k: SMatrix<f64, 9, 9>,
    k_all: nalgebra::Cholesky<f64, nalgebra::Const<9>>,
    /// Cholesky factor of the platform block (sliders held).
    k_pp: nalgebra::Cholesky<f64, nalgebra::Const<6>>,
    /// Leg beam section properties, E, G and stress points.
    props: SectionProps,
    young: f64,
    shear: f64,
    points: [StressPoint; 8],
    tables: [hinge::PeakStressTable; 2],
    /// Compliances of the (revolute, spherical) hinge elements, hinge axes.
    flex: [Matrix6<f64>; 2],
}

/// The compliance of a flexibility element, if it is finite, symmetric and positive definite
/// (the FE element's own check; otherwise the FE path reports the error).
fn flex(c: [[f64; 6]; 6]) -> Option<Matrix6<f64>> {
    let c = Matrix6::from_fn(|i, j| c[i][j]);
    let scale = c.amax();
    let ok = scale > 0.0 && scale.is_finite() && (c - c.transpose()).amax() <= 1e-9 * scale;
    (ok && c.cholesky().is_some()).then_some(c)
}

impl ValidStage {
    /// The stage condensed for linear load cases ([`LinearStage`], no heap allocation); `None`
    /// with ideal joints, or when a hinge flexibility, a leg chain or the stage stiffness is not
    /// positive definite (the FE model then reports the error in its own terms).
    pub fn linear(&self) -> Option<LinearStage<'_>> {
        if self.ideal_joints {
            return None;
        }
        let section = Section::Rect {
            w: self.leg_w,
            h: self.leg_h,
        };
        section.validate().ok()?;
        let rev = flex(self.revolute.compliance())?;
        let sph = flex(self.spherical.compliance())?;
        let mut s = LinearStage {
            stage: self,
            legs: [0, 1, 2].map(|i| Leg {
                i,
                e: Vector3::zeros(),
                xs: Vector3::zeros(),
                xt: Vector3::zeros(),
                k: Matrix6::zeros(),
                a: Matrix6::zeros(),
                g: Vector6::zeros(),
            }),
            k: SMatrix::zeros(),
            k_all: SMatrix::<f64, 9, 9>::identity().cholesky()?,
            k_pp: Matrix6::identity().cholesky()?,
            props: section.properties(self.material.nu),
            young: self.material.e,
            shear: self.material.shear_modulus(),
            points: rect_stress_points(self.leg_w, self.leg_h),
            tables: [self.revolute.peak_stress_table(), self.spherical.peak_stress_table()],
            flex: [rev, sph],
        };
        let xp = self.prs.p_home();
        for i in 0..3 {
            let (mut c_b, mut xs, mut xt) = (Matrix6::zeros(), Vector3::zeros(), Vector3::zeros());
            // The neck top first (C_b sums the pieces carried to it).
            s.pieces(i, |pc| xt = pc.q);
            let mut ok = true;
            s.pieces(i, |pc| {
                if !pc.beam && pc.hinge == 0 {
                    xs = pc.p;
                }
                match beam_frame(arr(pc.p), arr(pc.q), arr(pc.up)) {
                    Some((lam, _)) => {
                        let t = t6(&lam);
                        let r = rigid_arm(&(xt - pc.q));
                        c_b += r * (t.transpose() * s.local_compliance(&pc) * t) * r.transpose();
                    }
                    None => ok = false,
                }
            });
            if !ok {
                return None;
            }
            let c_b = (c_b + c_b.transpose()) * 0.5;
            let k = c_b.cholesky()?.inverse();
            let e = self.prs.e(i);
            let mut ue = Vector6::zeros();
            ue.fixed_rows_mut::<3>(0).copy_from(&e);
            s.legs[i] = Leg {
                i,
                e,
                xs,
                xt,
                k,
                a: rigid_arm(&(xt - xp)),
                g: rigid_arm(&(xt - xs)) * ue,
            };
        }
        for leg in &s.legs {
            let ka = leg.k * leg.a;
            let kg = leg.k * leg.g;
            let mut pp = s.k.fixed_view_mut::<6, 6>(0, 0);
            pp += leg.a.transpose() * ka;
            let b = -(leg.a.transpose() * kg);
            s.k.fixed_view_mut::<6, 1>(0, 6 + leg.i).copy_from(&b);
            s.k.fixed_view_mut::<1, 6>(6 + leg.i, 0).copy_from(&b.transpose());
            s.k[(6 + leg.i, 6 + leg.i)] = leg.g.dot(&kg);
        }
        s.k_pp = s.k.fixed_view::<6, 6>(0, 0).into_owned().cholesky()?;
        // Positive definite whenever the platform block and the chains are.
        s.k_all = s.k.cholesky()?;
        Some(s)
    }
}

impl LinearStage<'_> {
    /// The pieces of leg `i` from the slider to the neck top, in order (as
    /// [`ValidStage::build`] meshes them).
    fn pieces(&self, i: usize, mut f: impl FnMut(Piece)) {
        let d = self.stage;
        let prs = &d.prs;
        let (hr, hs) = (d.revolute.half_length(), d.spherical.half_length());
        let c = prs.a_point(i);
        let b = prs.b_home(i);
        let l = (b - c) / prs.l;
        let n = l.cross(&prs.m(i));
        let start = c + hr * l;
        let end = b - hs * l;
        f(Piece {
            p: c - hr * l,
            q: start,
            up: n,
            beam: false,
            hinge: 0,
        });
        let mut prev = start;
        for k in 1..=d.leg_elements {
            let x = start + (end - start) * (k as f64 / d.leg_elements as f64);
            f(Piece {
                p: prev,
                q: x,
                up: n,
                beam: true,
                hinge: 0,
            });
            prev = x;
        }
        f(Piece {
            p: prev,
            q: b + hs * l,
            up: n,
            beam: false,
            hinge: 1,
        });
    }

    /// The cantilever compliance at q of a piece, local axes (the hinge's, or the leg beam's).
    fn local_compliance(&self, pc: &Piece) -> Matrix6<f64> {
        if pc.beam {
            let len = (pc.q - pc.p).norm();
            cantilever_compliance(self.young, self.shear, &self.props, len, true)
        } else {
            self.flex[pc.hinge]
        }
    }

    /// The platform-centre compliance with the sliders held, mm, N, rad.
    pub fn compliance(&self) -> Matrix6<f64> {
        let c = self.k_pp.inverse();
        (c + c.transpose()) * 0.5
    }

    /// The response to one drive.
    pub fn response(&self, drive: Drive) -> StageResponse {
        let (u_p, strokes, applied) = match drive {
            Drive::Forces(f) => {
                let mut rhs = SVector::<f64, 9>::zeros();
                (0..3).for_each(|i| rhs[6 + i] = f[i]);
                let u = self.k_all.solve(&rhs);
                (u.fixed_rows::<6>(0).into_owned(), [u[6], u[7], u[8]], Some(f))
            }
            Drive::Strokes(s) => {
                let mut rhs = Vector6::zeros();
                for (leg, &si) in self.legs.iter().zip(&s) {
                    rhs -= self.k.fixed_view::<6, 1>(0, 6 + leg.i) * si;
                }
                (self.k_pp.solve(&rhs), s, None)
            }
        };
        let mut r = StageResponse {
            strokes: [0.0; 3],
            forces: [0.0; 3],
            platform: PoseChange {
                x: u_p[0],
                y: u_p[1],
                z: u_p[2],
                psi: u_p[3],
                theta: u_p[4],
                phi: u_p[5],
            },
            hinge_stress: [[0.0; 3]; 2],
            max_von_mises: 0.0,
        };
        let mut beams: Option<f64> = None;
        for leg in &self.legs {
            let i = leg.i;
            let slider = leg.e * strokes[i];
            r.strokes[i] = leg.e.dot(&slider);
            let mut u_s = Vector6::zeros();
            u_s.fixed_rows_mut::<3>(0).copy_from(&slider);
            let delta = leg.a * u_p - rigid_arm(&(leg.xt - leg.xs)) * u_s;
            let f_b = leg.k * delta;
            // Reaction of the stroke DOF: the chain's force on the slider along eᵢ.
            r.forces[i] = applied.map_or(-leg.e.dot(&f_b.fixed_rows::<3>(0)), |f| f[i]);
            self.pieces(i, |pc| {
                let f_q = rigid_arm(&(leg.xt - pc.q)).transpose() * f_b;
                let f_p = -(rigid_arm(&(pc.q - pc.p)).transpose() * f_q);
                let Some((lam, _)) = beam_frame(arr(pc.p), arr(pc.q), arr(pc.up)) else {
                    return;
                };
                let t = t6(&lam);
                let (l_p, l_q) = (t * f_p, t * f_q);
                let s1: [f64; 6] = std::array::from_fn(|k| -l_p[k]);
                let s2: [f64; 6] = std::array::from_fn(|k| l_q[k]);
                if pc.beam {
                    for s in [&s1, &s2] {
                        for pt in &self.points {
                            let v = point_von_mises(&self.props, pt, s);
                            beams = Some(beams.map_or(v, |m| m.max(v)));
                        }
                    }
                } else {
                    r.hinge_stress[pc.hinge][i] = self.tables[pc.hinge].peak(&[s1, s2]);
                }
            });
        }
        let beams = beams.unwrap_or(0.0);
        r.max_von_mises = r.hinge_stress.iter().flatten().cloned().fold(beams, f64::max);
        r
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fem::chain::Condensed;
    use crate::hinge::{Contour, HingeSpec};
    use crate::kinematics::Prs;

    /// The stage's legs condensed without a model ([`ValidStage::linear`], its own fixed-size
    /// copy of the chain arithmetic) and the same legs found as serial chains of the stage's FE
    /// model and condensed by [`crate::fem::chain`] (J. S. Przemieniecki, Theory of Matrix
    /// Structural Analysis, 1968, §6.5 and §9.6): the same C_b⁻¹ to roundoff (1e-12 of its
    /// largest entry, per leg), for 1 and 4 leg beams and two notch families.
    #[test]
    fn stage_leg_and_mesh_chain_have_the_same_stiffness() {
        for (leg_elements, notch) in [
            (1, Contour::Circular { r: 5.0, t: 1.5 }),
            (4, Contour::Leaf { l: 8.0, t: 1.0 }),
        ] {
            let design = StageDesign {
                prs: Prs::new(100.0, 45.0, 50f64.to_radians(), 10f64.to_radians()).unwrap(),
                leg_w: 8.0,
                leg_h: 9.0,
                revolute: HingeSpec::in_blank(notch, 8.0, 9.0, 0.0),
                spherical: HingeSpec::in_blank(Contour::SphericalNeck { l: 4.0, t: 3.0, r: 2.0 }, 8.0, 8.0, 0.0),
                material: crate::material::Material::AL7075,
                ideal_joints: false,
                leg_elements,
            };
            let valid = design.validate().unwrap();
            let lin = valid.linear().unwrap();
            let stage = valid.build();
            let c = Condensed::new(&stage.model, &[], &[stage.platform]).unwrap();
            assert_eq!(c.chains.len(), 3, "one chain per leg");
            // zip-checked: both are [_; 3].
            for (leg, ids) in lin.legs.iter().zip(&stage.legs) {
                let chain = c.chains.iter().find(|ch| ch.nodes[0] == ids.slider).unwrap();
                assert_eq!(*chain.nodes.last().unwrap(), ids.sph_top, "leg {}: chain ends", leg.i);
                assert_eq!(
                    chain.elements.len(),
                    leg_elements + 2,
                    "leg {}: hinge, beams, neck",
                    leg.i
                );
                let (mesh, own) = (chain.ends().k_b, leg.k);
                let diff = (mesh - own).amax();
                eprintln!(
                    "leg {} ({leg_elements} beams): |ΔK_b| {diff:e} of {:e}",
                    leg.i,
                    own.amax()
                );
                assert!(
                    diff <= 1e-12 * own.amax(),
                    "leg {} ({leg_elements} beams): |ΔK_b| {diff:e} of {:e}",
                    leg.i,
                    own.amax()
                );
            }
        }
    }
}
