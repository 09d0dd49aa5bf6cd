//! A hinge as a case file gives it: a family's notch contour in a blank ([`HingeSpec`], declared
//! with [`Contour`] from the one list of hinge families in [`super::contour`]).

pub use super::contour::HingeSpec;
use super::{Contour, HingeError, Profile};

impl HingeSpec {
    /// Blank width, height (the neck's square side for both) and length beyond each end, mm.
    pub fn blank(&self) -> (f64, f64, f64) {
        use HingeSpec::*;
        match *self {
            CircularNotch { w, h, blank_length, .. }
            | EllipticalNotch { w, h, blank_length, .. }
            | CornerFilleted { w, h, blank_length, .. }
            | Leaf { w, h, blank_length, .. } => (w, h, blank_length),
            SphericalNeck { h, blank_length, .. } => (h, h, blank_length),
        }
    }

    /// Validated profile with the given blank length (`None`: the spec's own).
    pub fn profile_with_blank(&self, blank: Option<f64>) -> Result<Profile, HingeError> {
        let (w, h, own) = self.blank();
        let blank = blank.unwrap_or(own);
        match self.contour() {
            Contour::SphericalNeck { l, t, r } => Profile::neck(l, t, r, h, blank),
            c => Profile::rectangular(c, w, h, blank),
        }
    }

    /// Validated profile.
    pub fn profile(&self) -> Result<Profile, HingeError> {
        self.profile_with_blank(None)
    }

    /// Whether the hinge can serve as a revolute joint ([`Contour::fits_revolute`]).
    pub fn fits_revolute(&self) -> bool {
        self.contour().fits_revolute()
    }

    /// Whether the hinge can serve as a spherical joint ([`Contour::fits_spherical`]).
    pub fn fits_spherical(&self) -> bool {
        self.contour().fits_spherical()
    }
}
