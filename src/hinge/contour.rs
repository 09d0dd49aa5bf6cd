//! The hinge families: one enum of notch contours.

/// The hinge family and its notch contour: the one list of hinge families. A case file's
/// stage joint is a contour by `type` (its blank comes from the leg); a [`super::HingeSpec`] is
/// a contour in a blank; a [`super::Profile`] is a validated contour in a blank. Lengths in mm.
#[derive(Debug, Clone, Copy, PartialEq, serde::Deserialize, schemars::JsonSchema)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
#[schemars(
    rename = "StageHinge",
    description = "A hinge of the stage, by `type`; its width and blank come from the leg."
)]
pub enum Contour {
    /// Circular notch: radius R, minimum thickness t, mm;
    /// t(x) = t + 2(R − √(R² − x²)), |x| ≤ R.
    #[serde(rename = "circular_notch")]
    Circular {
        /// Notch radius, mm, > 0.
        #[serde(rename = "R")]
        #[schemars(extend("exclusiveMinimum" = 0))]
        r: f64,
        /// Minimum thickness, mm, > 0 and < the blank (leg) height `h`.
        #[schemars(extend("exclusiveMinimum" = 0))]
        t: f64,
    },
    /// Elliptical notch: semi-axes ax (along the hinge), ay (depth), minimum thickness t, mm;
    /// t(x) = t + 2a_y(1 − √(1 − x²/a_x²)), |x| ≤ a_x.
    #[serde(rename = "elliptical_notch")]
    Elliptical {
        /// Semi-axis along the hinge, mm, > 0.
        #[schemars(extend("exclusiveMinimum" = 0))]
        ax: f64,
        /// Semi-axis across (depth direction), mm, > 0.
        #[schemars(extend("exclusiveMinimum" = 0))]
        ay: f64,
        /// Minimum thickness, mm, > 0 and < the blank (leg) height `h`.
        #[schemars(extend("exclusiveMinimum" = 0))]
        t: f64,
    },
    /// Corner-filleted notch: length l, fillet radius R, thickness t, mm; a straight part
    /// l − 2R of thickness t, then quarter-circle fillets of radius R.
    CornerFilleted {
        /// Total notch length, mm, > 0.
        #[schemars(extend("exclusiveMinimum" = 0))]
        l: f64,
        /// Fillet radius, mm, > 0 and ≤ l/2.
        #[serde(rename = "R")]
        #[schemars(extend("exclusiveMinimum" = 0))]
        r: f64,
        /// Thickness, mm, > 0 and < the blank (leg) height `h`.
        #[schemars(extend("exclusiveMinimum" = 0))]
        t: f64,
    },
    /// Prismatic leaf: length l, thickness t, mm.
    Leaf {
        /// Length, mm, > 0.
        #[schemars(extend("exclusiveMinimum" = 0))]
        l: f64,
        /// Thickness, mm, > 0 and < the blank (leg) height `h`.
        #[schemars(extend("exclusiveMinimum" = 0))]
        t: f64,
    },
    /// Turned neck: diameter t over |x| ≤ l/2, fillets of radius R, inside an h × h blank, mm.
    SphericalNeck {
        /// Straight neck length, mm, ≥ 0.
        #[schemars(range(min = 0))]
        l: f64,
        /// Neck diameter, mm, > 0 and < the blank side (the smaller leg side).
        #[schemars(extend("exclusiveMinimum" = 0))]
        t: f64,
        /// Fillet radius, mm, > 0.
        #[serde(rename = "R")]
        #[schemars(extend("exclusiveMinimum" = 0))]
        r: f64,
    },
}

impl Contour {
    /// Whether the contour is a turned neck (circular waist, compliant about every axis across
    /// it) rather than a flat notch (one compliant axis).
    pub fn is_neck(&self) -> bool {
        matches!(self, Contour::SphericalNeck { .. })
    }

    /// Whether the hinge can serve as a revolute joint: a notch with one compliant axis
    /// (circular, elliptical, corner-filleted, leaf).
    pub fn fits_revolute(&self) -> bool {
        !self.is_neck()
    }

    /// Whether the hinge can serve as a spherical joint: a turned neck.
    pub fn fits_spherical(&self) -> bool {
        self.is_neck()
    }
}
