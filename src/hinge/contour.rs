//! The hinge families: one list, from which [`Contour`] (a family's notch contour) and
//! [`HingeSpec`] (the contour in a blank, as a case file gives a hinge) are both declared, with
//! the conversions between them.

/// Declares [`Contour`] and [`HingeSpec`] from the list of hinge families. Each entry reads
/// `CONTOUR_DOCS Contour, SPEC_DOCS Spec in BLANK { FIELD_DOCS field, … }`: the contour variant,
/// the hinge-spec variant and its blank (`rectangle`: a w × h section; `square`: the h × h blank
/// of a turned neck), and the contour's dimensions (mm, `f64`), whose docs and schema attributes
/// both enums share.
macro_rules! hinge_families {
    ($(
        $(#[$cm:meta])* $contour:ident,
        $(#[$sm:meta])* $spec:ident in $blank:ident { $($(#[$fm:meta])* $field:ident,)+ }
    )+) => {
        /// The hinge family and its notch contour: the one list of hinge families. A case file's
        /// stage joint is a contour by `type` (its blank comes from the leg); a [`HingeSpec`] is
        /// a contour in a blank; a [`super::Profile`] is a validated contour in a blank. Lengths
        /// in mm.
        #[derive(Debug, Clone, Copy, PartialEq, serde::Deserialize, schemars::JsonSchema)]
        #[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
        #[schemars(
            rename = "StageHinge",
            description = "A hinge of the stage, by `type`; its width and blank come from the leg."
        )]
        pub enum Contour {
            $($(#[$cm])* $contour { $($(#[$fm])* $field: f64,)+ },)+
        }

        hinge_families!(@spec [] $($(#[$sm])* $spec $blank { $($(#[$fm])* $field: f64,)+ })+);

        impl HingeSpec {
            /// The contour `c` in a blank: width `w` and height `h` (the neck's square blank has
            /// side `h`; `w` is ignored), `blank_length` beyond each end of the notch, mm.
            pub fn in_blank(c: Contour, w: f64, h: f64, blank_length: f64) -> HingeSpec {
                match c {
                    $(Contour::$contour { $($field),+ } => {
                        hinge_families!(@in_blank $blank $spec { $($field),+ } w h blank_length)
                    })+
                }
            }

            /// The family and notch contour.
            pub fn contour(&self) -> Contour {
                match *self {
                    $(HingeSpec::$spec { $($field,)+ .. } => Contour::$contour { $($field),+ },)+
                }
            }

            /// A dimension of the contour by its case-file name (`R`, `t`, `l`, `ax`, `ay`), for
            /// sweeps that set numbers in a parsed case; the blank's are not among them.
            pub fn contour_number_mut(&mut self, key: &str) -> Option<&mut f64> {
                match self {
                    $(HingeSpec::$spec { $($field,)+ .. } => {
                        $(if key == json_name(stringify!($field)) {
                            return Some($field);
                        })+
                        None
                    })+
                }
            }
        }

        impl Contour {
            /// A dimension by its case-file name (see [`HingeSpec::contour_number_mut`]).
            pub fn number_mut(&mut self, key: &str) -> Option<&mut f64> {
                match self {
                    $(Contour::$contour { $($field),+ } => {
                        $(if key == json_name(stringify!($field)) {
                            return Some($field);
                        })+
                        None
                    })+
                }
            }
        }
    };
    (@spec [$($done:tt)*] $(#[$sm:meta])* $spec:ident rectangle { $($f:tt)* } $($rest:tt)*) => {
        hinge_families!(@spec [$($done)* $(#[$sm])* $spec {
            $($f)*
            /// Width w (constant).
            #[schemars(extend("exclusiveMinimum" = 0))]
            w: f64,
            /// Blank height h.
            #[schemars(extend("exclusiveMinimum" = 0))]
            h: f64,
            /// Blank length beyond each end of the notch.
            #[schemars(range(min = 0))]
            blank_length: f64,
        },] $($rest)*);
    };
    (@spec [$($done:tt)*] $(#[$sm:meta])* $spec:ident square { $($f:tt)* } $($rest:tt)*) => {
        hinge_families!(@spec [$($done)* $(#[$sm])* $spec {
            $($f)*
            /// Side of the square blank.
            #[schemars(extend("exclusiveMinimum" = 0))]
            h: f64,
            /// Blank length beyond each end of the notch region.
            #[schemars(range(min = 0))]
            blank_length: f64,
        },] $($rest)*);
    };
    (@spec [$($done:tt)*]) => {
        /// A hinge as given in a case file, by `type`: a family's contour in a blank. Lengths in
        /// mm.
        #[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize, schemars::JsonSchema)]
        #[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
        pub enum HingeSpec {
            $($done)*
        }
    };
    (@in_blank rectangle $spec:ident { $($f:ident),+ } $w:ident $h:ident $bl:ident) => {
        HingeSpec::$spec { $($f,)+ w: $w, h: $h, blank_length: $bl }
    };
    (@in_blank square $spec:ident { $($f:ident),+ } $w:ident $h:ident $bl:ident) => {
        HingeSpec::$spec { $($f,)+ h: $h, blank_length: $bl }
    };
}

/// The case-file name of a contour dimension: the radius `r` is `R` (its `serde(rename)`), the
/// others keep their names.
fn json_name(field: &str) -> &str {
    if field == "r" {
        "R"
    } else {
        field
    }
}

hinge_families! {
    /// Circular notch: radius R, minimum thickness t, mm;
    /// t(x) = t + 2(R − √(R² − x²)), |x| ≤ R.
    #[serde(rename = "circular_notch")]
    Circular,
    /// Circular notch of radius R, minimum thickness t, in a w × h blank.
    CircularNotch in rectangle {
        /// Notch radius R, mm, > 0.
        #[serde(rename = "R")]
        #[schemars(extend("exclusiveMinimum" = 0))]
        r,
        /// Minimum thickness t (along h), mm, > 0 and < the blank (leg) height `h`.
        #[schemars(extend("exclusiveMinimum" = 0))]
        t,
    }
    /// Elliptical notch: semi-axes ax (along the hinge), ay (depth), minimum thickness t, mm;
    /// t(x) = t + 2a_y(1 − √(1 − x²/a_x²)), |x| ≤ a_x.
    #[serde(rename = "elliptical_notch")]
    Elliptical,
    /// Elliptical notch, semi-axes ax (along the hinge) and ay (depth).
    EllipticalNotch in rectangle {
        /// Semi-axis along the hinge, mm, > 0.
        #[schemars(extend("exclusiveMinimum" = 0))]
        ax,
        /// Semi-axis across (depth direction), mm, > 0.
        #[schemars(extend("exclusiveMinimum" = 0))]
        ay,
        /// Minimum thickness t, mm, > 0 and < the blank (leg) height `h`.
        #[schemars(extend("exclusiveMinimum" = 0))]
        t,
    }
    /// Corner-filleted notch: length l, fillet radius R, thickness t, mm; a straight part
    /// l − 2R of thickness t, then quarter-circle fillets of radius R.
    CornerFilleted,
    /// Corner-filleted notch: total length l with two fillets of radius R.
    CornerFilleted in rectangle {
        /// Total notch length l (including both fillets), mm, > 0.
        #[schemars(extend("exclusiveMinimum" = 0))]
        l,
        /// Fillet radius R, mm, > 0 and ≤ l/2.
        #[serde(rename = "R")]
        #[schemars(extend("exclusiveMinimum" = 0))]
        r,
        /// Thickness t of the straight part, mm, > 0 and < the blank (leg) height `h`.
        #[schemars(extend("exclusiveMinimum" = 0))]
        t,
    }
    /// Prismatic leaf: length l, thickness t, mm.
    Leaf,
    /// Prismatic leaf of length l.
    Leaf in rectangle {
        /// Length l, mm, > 0.
        #[schemars(extend("exclusiveMinimum" = 0))]
        l,
        /// Thickness t, mm, > 0 and < the blank (leg) height `h`.
        #[schemars(extend("exclusiveMinimum" = 0))]
        t,
    }
    /// Turned neck: diameter t over |x| ≤ l/2, fillets of radius R, inside an h × h blank, mm.
    SphericalNeck,
    /// Turned (spherical) neck: diameter t over length l, fillets of radius R, in an h × h blank.
    SphericalNeck in square {
        /// Straight neck length l, mm, ≥ 0.
        #[schemars(range(min = 0))]
        l,
        /// Neck diameter t, mm, > 0 and < the blank side (the smaller leg side).
        #[schemars(extend("exclusiveMinimum" = 0))]
        t,
        /// Fillet radius R, mm, > 0.
        #[serde(rename = "R")]
        #[schemars(extend("exclusiveMinimum" = 0))]
        r,
    }
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
