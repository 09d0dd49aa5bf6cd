//! Two-node 3D beam: data and local stiffness (see [`crate::fem::element::beam_local_stiffness`]).

use super::check_material;
use crate::fem::element::beam_local_stiffness;
use crate::fem::error::FemError;
use crate::fem::section::{Section, SectionProps};
use crate::fem::transform::Mat12;
use crate::material::Material;

/// Two-node 3D beam (Timoshenko unless `shear` is false).
#[derive(Debug, Clone, PartialEq)]
pub struct Beam {
    /// First and second node; local x runs from `nodes[0]` to `nodes[1]`.
    pub nodes: [usize; 2],
    pub section: Section,
    pub material: Material,
    /// Orientation vector (global): local z is its component normal to the axis.
    pub up: [f64; 3],
    /// Include shear deformation (Timoshenko). `false` = Euler–Bernoulli.
    pub shear: bool,
}

impl Beam {
    /// Timoshenko beam from `n1` to `n2`.
    pub fn new(n1: usize, n2: usize, section: Section, material: Material, up: [f64; 3]) -> Beam {
        Beam {
            nodes: [n1, n2],
            section,
            material,
            up,
            shear: true,
        }
    }

    /// Same beam, Euler–Bernoulli.
    pub fn euler_bernoulli(mut self) -> Beam {
        self.shear = false;
        self
    }

    /// Section properties, E and G, after checking section and material (`ie`: the element's
    /// index, for errors).
    pub fn props(&self, ie: usize) -> Result<(SectionProps, f64, f64), FemError> {
        self.section
            .validate()
            .map_err(|reason| FemError::BadElement { element: ie, reason })?;
        let m = &self.material;
        check_material(ie, m)?;
        Ok((self.section.properties(m.nu), m.e, m.shear_modulus()))
    }

    /// Local 12×12 stiffness for length `l` (mm).
    pub fn local_stiffness(&self, ie: usize, l: f64) -> Result<Mat12, FemError> {
        let (p, e, g) = self.props(ie)?;
        Ok(beam_local_stiffness(e, g, &p, l, self.shear))
    }
}
