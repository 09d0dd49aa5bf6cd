//! Building the stage FE model from a design: the hinge profiles checked, legs, hinges (as
//! flexibility elements or ideal joints), sliders and platform.

use super::*;
use crate::fem::{self, Dof, Model};
use crate::hinge::{self, Profile};
use crate::material::Material;
use nalgebra::Vector3;

pub(super) fn geometry_err(field: &str, message: impl Into<String>) -> StageError {
    StageError::Geometry {
        field: field.into(),
        message: message.into(),
    }
}

pub(super) fn hinge_err(prefix: &str, e: hinge::HingeError) -> StageError {
    match e {
        hinge::HingeError::InvalidGeometry { param, value, allowed } => geometry_err(
            &format!("{prefix}.{param}"),
            format!("value {value} is not allowed: {allowed}"),
        ),
        hinge::HingeError::InvalidMaterial { param, value, allowed } => geometry_err(
            &format!("material.{param}"),
            format!("value {value} is not allowed: {allowed}"),
        ),
    }
}

/// Frame rows (local x, y, z in global coordinates) as the array the FE model takes.
pub(super) fn rows(x: Vector3<f64>, y: Vector3<f64>, z: Vector3<f64>) -> [[f64; 3]; 3] {
    [[x[0], x[1], x[2]], [y[0], y[1], y[2]], [z[0], z[1], z[2]]]
}

pub(super) fn arr(v: Vector3<f64>) -> [f64; 3] {
    [v[0], v[1], v[2]]
}

/// The 6×6 compliance of a hinge region (notch + load-spreading zone) with the
/// warping-restrained torsion of [`hinge::characterise`], in hinge axes (x along the hinge,
/// y compliant axis, z across).
pub(super) fn hinge_region(
    profile: &Profile,
    material: &Material,
    prefix: &str,
) -> Result<hinge::Stiffness, StageError> {
    hinge::profile_stiffness(profile, material).map_err(|e| hinge_err(prefix, e))
}

impl StageDesign {
    /// Checks the design before anything is built.
    pub fn validate(&self) -> Result<(Profile, Profile), StageError> {
        for (f, v) in [("leg.w", self.leg_w), ("leg.h", self.leg_h)] {
            if !(v.is_finite() && v > 0.0) {
                return Err(geometry_err(
                    f,
                    format!("value {v} is not allowed: must be a positive length (mm)"),
                ));
            }
        }
        if self.leg_elements == 0 || self.leg_elements > 1000 {
            return Err(geometry_err(
                "leg_elements",
                format!("value {} is not allowed: must be in 1..=1000", self.leg_elements),
            ));
        }
        // Each hinge element spans its notch plus the stretch of leg over which load still
        // spreads out of it (Profile::spread_reach): the leg beams start beyond.
        let region = |p: Profile| Profile {
            blank: (p.spread_reach() - p.half_notch).max(0.0),
            ..p
        };
        let rp = region(self.revolute.profile().map_err(|e| hinge_err("revolute", e))?);
        let sp = region(self.spherical.profile().map_err(|e| hinge_err("spherical", e))?);
        let used = rp.half_length() + sp.half_length();
        if used >= self.prs.l {
            return Err(geometry_err(
                "L",
                format!(
                    "value {} is not allowed: the revolute notch (half-length {:.3} mm with its load-spreading zone) and the spherical neck (half-length {:.3} mm) must fit in the leg length",
                    self.prs.l, rp.half_length(), sp.half_length()
                ),
            ));
        }
        let clearance = self.prs.a_point(0).norm() - self.prs.b;
        let _ = clearance;
        Ok((rp, sp))
    }

    /// Builds the FE model (no load cases).
    pub fn build(&self) -> Result<StageModel, StageError> {
        let (rp, sp) = self.validate()?;
        let prs = &self.prs;
        let mut model = Model::new();
        let stiff = if self.ideal_joints { 1e6 } else { 1.0 };
        let leg_material = Material {
            e: self.material.e * stiff,
            ..self.material
        };
        let p = model.add_node(arr(prs.p_home()));
        let rev_h = hinge_region(&rp, &self.material, "revolute")?;
        let sph_h = hinge_region(&sp, &self.material, "spherical")?;
        let rev_c = if self.ideal_joints {
            None
        } else {
            Some(rev_h.compliance)
        };
        let sph_c = if self.ideal_joints {
            None
        } else {
            Some(sph_h.compliance)
        };
        let (hr, hs) = if self.ideal_joints {
            (0.0, 0.0)
        } else {
            (rp.half_length(), sp.half_length())
        };
        let mut legs = Vec::with_capacity(3);
        let mut platform_slaves = Vec::with_capacity(3);
        for i in 0..3 {
            let c = prs.a_point(i);
            let b = prs.b_home(i);
            let l = (b - c) / prs.l;
            let m = prs.m(i);
            let n = l.cross(&m);
            let e = prs.e(i);
            let slider = model.add_node(arr(c - hr * l));
            model.set_frame(slider, rows(e, m, e.cross(&m)));
            model.supports.push(fem::Support::dofs(
                slider,
                &[Dof::Uy, Dof::Uz, Dof::Rx, Dof::Ry, Dof::Rz],
            ));
            let rev_top = if self.ideal_joints {
                let top = model.add_node(arr(c));
                model.set_frame(top, rows(e, m, e.cross(&m)));
                // Revolute: everything tied but the rotation about mᵢ (local y of the frame).
                model.ties.push(fem::Tie {
                    a: slider,
                    b: top,
                    dofs: [true, true, true, true, false, true],
                });
                top
            } else {
                model.add_node(arr(c + hr * l))
            };
            let rev_element = rev_c.map(|cmp| {
                model.add_element(fem::Element::Flex(fem::FlexElement {
                    nodes: [slider, rev_top],
                    compliance: cmp,
                    up: arr(n),
                }))
            });
            // The leg beam from the top of the notch to the bottom of the neck.
            let start = c + hr * l;
            let end = b - hs * l;
            let mut prev = rev_top;
            for k in 1..=self.leg_elements {
                let x = start + (end - start) * (k as f64 / self.leg_elements as f64);
                let node = model.add_node(arr(x));
                // Section h along local z = nᵢ, w along local y = mᵢ (`up` = nᵢ).
                model.add_beam(fem::Beam::new(
                    prev,
                    node,
                    fem::Section::Rect {
                        w: self.leg_w,
                        h: self.leg_h,
                    },
                    leg_material,
                    arr(n),
                ));
                prev = node;
            }
            let sph_bottom = prev;
            let (sph_top, sph_element) = match sph_c {
                Some(cmp) => {
                    let top = model.add_node(arr(b + hs * l));
                    let el = model.add_element(fem::Element::Flex(fem::FlexElement {
                        nodes: [sph_bottom, top],
                        compliance: cmp,
                        up: arr(n),
                    }));
                    (top, Some(el))
                }
                None => {
                    // Spherical: translations tied, rotations free; the platform point is an
                    // independent node joined to P by a stiff beam (see the module docs).
                    let top = model.add_node(arr(b));
                    model.ties.push(fem::Tie {
                        a: top,
                        b: sph_bottom,
                        dofs: [true, true, true, false, false, false],
                    });
                    (top, None)
                }
            };
            platform_slaves.push(sph_top);
            legs.push(LegIds {
                slider,
                rev_top,
                sph_bottom,
                sph_top,
                rev_element,
                sph_element,
                e,
                m,
                l,
            });
        }
        if self.ideal_joints {
            let d = 2.0 * self.leg_w.max(self.leg_h);
            for &s in &platform_slaves {
                let axis = Vector3::from(model.nodes[s]) - Vector3::from(model.nodes[p]);
                let up = if axis.cross(&Vector3::z()).norm() > 1e-9 * axis.norm() {
                    Vector3::z()
                } else {
                    Vector3::x()
                };
                model.add_beam(fem::Beam::new(p, s, fem::Section::Circle { d }, leg_material, arr(up)));
            }
        } else {
            model.rigid_links.push(fem::RigidLink {
                master: p,
                slaves: platform_slaves,
            });
        }
        let legs = [legs[0], legs[1], legs[2]];
        let kt = [
            hinge::stress::stress_factor(&rp, self.material.nu),
            hinge::stress::stress_factor(&sp, self.material.nu),
        ];
        Ok(StageModel {
            design: self.clone(),
            model,
            platform: p,
            legs,
            rev_profile: rp,
            sph_profile: sp,
            kt,
            rev_hinge: rev_h,
            sph_hinge: sph_h,
        })
    }
}
