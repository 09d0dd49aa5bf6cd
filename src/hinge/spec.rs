//! A hinge as a case file gives it: a family's notch contour in a blank.

use super::{Contour, HingeError, Profile};
use serde::{Deserialize, Serialize};

/// A hinge as given in a case file, by `type`. Lengths in mm.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum HingeSpec {
    /// Circular notch of radius R, minimum thickness t, in a w × h blank.
    CircularNotch {
        /// Notch radius R.
        #[serde(rename = "R")]
        #[schemars(extend("exclusiveMinimum" = 0))]
        r: f64,
        /// Minimum thickness t (along h).
        #[schemars(extend("exclusiveMinimum" = 0))]
        t: f64,
        /// Width w (constant).
        #[schemars(extend("exclusiveMinimum" = 0))]
        w: f64,
        /// Blank height h.
        #[schemars(extend("exclusiveMinimum" = 0))]
        h: f64,
        /// Blank length beyond each end of the notch.
        #[schemars(range(min = 0))]
        blank_length: f64,
    },
    /// Elliptical notch, semi-axes ax (along the hinge) and ay (depth).
    EllipticalNotch {
        /// Semi-axis along the hinge.
        #[schemars(extend("exclusiveMinimum" = 0))]
        ax: f64,
        /// Semi-axis across.
        #[schemars(extend("exclusiveMinimum" = 0))]
        ay: f64,
        /// Minimum thickness t.
        #[schemars(extend("exclusiveMinimum" = 0))]
        t: f64,
        /// Width w.
        #[schemars(extend("exclusiveMinimum" = 0))]
        w: f64,
        /// Blank height h.
        #[schemars(extend("exclusiveMinimum" = 0))]
        h: f64,
        /// Blank length beyond each end of the notch.
        #[schemars(range(min = 0))]
        blank_length: f64,
    },
    /// Corner-filleted notch: total length l with two fillets of radius R.
    CornerFilleted {
        /// Total notch length l (including both fillets).
        #[schemars(extend("exclusiveMinimum" = 0))]
        l: f64,
        /// Fillet radius R.
        #[serde(rename = "R")]
        #[schemars(extend("exclusiveMinimum" = 0))]
        r: f64,
        /// Thickness t of the straight part.
        #[schemars(extend("exclusiveMinimum" = 0))]
        t: f64,
        /// Width w.
        #[schemars(extend("exclusiveMinimum" = 0))]
        w: f64,
        /// Blank height h.
        #[schemars(extend("exclusiveMinimum" = 0))]
        h: f64,
        /// Blank length beyond each end of the notch.
        #[schemars(range(min = 0))]
        blank_length: f64,
    },
    /// Prismatic leaf of length l.
    Leaf {
        /// Length l.
        #[schemars(extend("exclusiveMinimum" = 0))]
        l: f64,
        /// Thickness t.
        #[schemars(extend("exclusiveMinimum" = 0))]
        t: f64,
        /// Width w.
        #[schemars(extend("exclusiveMinimum" = 0))]
        w: f64,
        /// Blank height h.
        #[schemars(extend("exclusiveMinimum" = 0))]
        h: f64,
        /// Blank length beyond each end of the leaf.
        #[schemars(range(min = 0))]
        blank_length: f64,
    },
    /// Turned (spherical) neck: diameter t over length l, fillets of radius R, in an h × h blank.
    SphericalNeck {
        /// Straight neck length l.
        #[schemars(range(min = 0))]
        l: f64,
        /// Neck diameter t.
        #[schemars(extend("exclusiveMinimum" = 0))]
        t: f64,
        /// Fillet radius R.
        #[serde(rename = "R")]
        #[schemars(extend("exclusiveMinimum" = 0))]
        r: f64,
        /// Side of the square blank.
        #[schemars(extend("exclusiveMinimum" = 0))]
        h: f64,
        /// Blank length beyond each end of the notch region.
        #[schemars(range(min = 0))]
        blank_length: f64,
    },
}

impl HingeSpec {
    /// The contour `c` in a blank: width `w` and height `h` (the neck's square blank has side
    /// `h`; `w` is ignored), `blank_length` beyond each end of the notch, mm.
    pub fn in_blank(c: Contour, w: f64, h: f64, blank_length: f64) -> HingeSpec {
        match c {
            Contour::Circular { r, t } => HingeSpec::CircularNotch {
                r,
                t,
                w,
                h,
                blank_length,
            },
            Contour::Elliptical { ax, ay, t } => HingeSpec::EllipticalNotch {
                ax,
                ay,
                t,
                w,
                h,
                blank_length,
            },
            Contour::CornerFilleted { l, r, t } => HingeSpec::CornerFilleted {
                l,
                r,
                t,
                w,
                h,
                blank_length,
            },
            Contour::Leaf { l, t } => HingeSpec::Leaf {
                l,
                t,
                w,
                h,
                blank_length,
            },
            Contour::SphericalNeck { l, t, r } => HingeSpec::SphericalNeck {
                l,
                t,
                r,
                h,
                blank_length,
            },
        }
    }

    /// The family and notch contour.
    pub fn contour(&self) -> Contour {
        use HingeSpec::*;
        match *self {
            CircularNotch { r, t, .. } => Contour::Circular { r, t },
            EllipticalNotch { ax, ay, t, .. } => Contour::Elliptical { ax, ay, t },
            CornerFilleted { l, r, t, .. } => Contour::CornerFilleted { l, r, t },
            Leaf { l, t, .. } => Contour::Leaf { l, t },
            SphericalNeck { l, t, r, .. } => Contour::SphericalNeck { l, t, r },
        }
    }

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
