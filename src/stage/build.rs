//! Building the stage FE model from a design: the design checked once into a [`ValidStage`],
//! then legs, hinges (as flexibility elements or ideal joints), sliders and platform.

use super::*;
use crate::fem::{self, Dof, Model};
use crate::hinge;
use crate::material::Material;
use nalgebra::Vector3;

pub(super) fn geometry_err(field: &str, message: impl Into<String>) -> StageError {
    StageError::Geometry {
        field: field.into(),
        message: message.into(),
    }
}

/// Frame rows (local x, y, z in global coordinates) as the array the FE model takes.
pub(super) fn rows(x: Vector3<f64>, y: Vector3<f64>, z: Vector3<f64>) -> [[f64; 3]; 3] {
    [[x[0], x[1], x[2]], [y[0], y[1], y[2]], [z[0], z[1], z[2]]]
}

pub(super) fn arr(v: Vector3<f64>) -> [f64; 3] {
    [v[0], v[1], v[2]]
}

impl StageDesign {
    /// Checks the design before anything is built: leg section and element count, the hinge
    /// families the joints allow ([`HingeSpec::fits_revolute`], [`HingeSpec::fits_spherical`]),
    /// hinge geometry and material, and that both hinge regions fit in the leg length.
    /// Errors name the design parameter ([`StageError`]); case files map them to JSON paths.
    pub fn validate(&self) -> Result<ValidStage, StageError> {
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
        if !self.revolute.fits_revolute() {
            return Err(geometry_err(
                "revolute.type",
                "the revolute joint needs a notch with one compliant axis: circular_notch, elliptical_notch, corner_filleted or leaf",
            ));
        }
        if !self.spherical.fits_spherical() {
            return Err(geometry_err(
                "spherical.type",
                "the spherical joint must be a spherical_neck (turned neck)",
            ));
        }
        // Each hinge element spans its notch plus the stretch of leg over which load still
        // spreads out of it (hinge::spreading_region): the leg beams start beyond.
        let hinge_err = |joint: Joint| move |source: HingeError| StageError::Hinge { joint, source };
        let rp = hinge::spreading_region(self.revolute.profile().map_err(hinge_err(Joint::Revolute))?);
        let sp = hinge::spreading_region(self.spherical.profile().map_err(hinge_err(Joint::Spherical))?);
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
        // Remembered per thread: a sweep's designs repeat their hinges (super::hinge_memo).
        let revolute = super::hinge_memo::flex_region(&rp, &self.material).map_err(hinge_err(Joint::Revolute))?;
        let spherical = super::hinge_memo::flex_region(&sp, &self.material).map_err(hinge_err(Joint::Spherical))?;
        Ok(ValidStage {
            design: self.clone(),
            revolute,
            spherical,
        })
    }

    /// Validates ([`StageDesign::validate`]) and builds the FE model (no load cases): the
    /// library entry; a caller holding a [`ValidStage`] calls [`ValidStage::build`].
    pub fn build(&self) -> Result<StageModel, StageError> {
        Ok(self.validate()?.build())
    }
}

impl ValidStage {
    /// Builds the FE model (no load cases) of the validated design.
    pub fn build(&self) -> StageModel {
        let (rp, sp) = (&self.revolute.profile, &self.spherical.profile);
        let prs = &self.prs;
        let mut model = Model::new();
        let stiff = if self.ideal_joints { 1e6 } else { 1.0 };
        let leg_material = Material {
            e: self.material.e * stiff,
            ..self.material
        };
        let p = model.add_node(arr(prs.p_home()));
        let rev_c = (!self.ideal_joints).then(|| self.revolute.compliance());
        let sph_c = (!self.ideal_joints).then(|| self.spherical.compliance());
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
        StageModel {
            design: self.design.clone(),
            model,
            platform: p,
            legs,
            revolute: self.revolute.clone(),
            spherical: self.spherical.clone(),
            stress_tables: [self.revolute.peak_stress_table(), self.spherical.peak_stress_table()],
        }
    }
}
