//! The fields several case shapes share, declared once with their serde and schema attributes.
//!
//! [`case_struct!`] writes a case struct from its usual declaration, where a line
//! `include GROUP;` (or `include GROUP { … }`) stands for a group of shared fields, in that place
//! of the field list (so the JSON Schema lists them in the same order). The groups:
//! - `material;`: `material`, the material (default Al7075).
//! - `prs_geometry;`: the 3-PRS geometry `L`, `b`, `alpha0_deg` or `a`, `gamma_deg` (the struct
//!   carries the schema rule [`super::kinematics::alpha0_or_a`] and validates the choice).
//! - `rayleigh;`: the Rayleigh damping coefficients `alpha` (of M) and `beta` (of K), default 0.
//! - `nonlinear_steps { /// doc nonlinear, /// doc steps, }`: `nonlinear` (default false) and
//!   `steps` (1 … 10000 load steps, optional), each with the doc comment saying what it means for
//!   the kind.
//! - `model_source { /// doc description, /// doc mesh, /// doc gmsh, /// doc model, }`:
//!   `description`, `mesh`, `gmsh` and the model (the fields of
//!   [`MeshSpec`](super::mesh::MeshSpec), flattened) of a case whose model is inline or read from
//!   a JSON or Gmsh mesh file, each with its doc comment.
//!
//! Field names and JSON shapes are those of the case files; the group only writes them once.

/// Declares a case struct whose field list may hold `include GROUP;` lines (see the module
/// docs). Every field ends with a comma.
macro_rules! case_struct {
    (@fields $head:tt [$($done:tt)*] include material; $($rest:tt)*) => {
        $crate::case::fields::case_struct!(@fields $head [$($done)*
            /// Material (default Al7075).
            #[serde(default)]
            pub material: $crate::case::MaterialSpec,
        ] $($rest)*);
    };
    (@fields $head:tt [$($done:tt)*] include prs_geometry; $($rest:tt)*) => {
        $crate::case::fields::case_struct!(@fields $head [$($done)*
            /// Leg length L between the revolute and spherical joint centres, mm.
            #[serde(rename = "L")]
            #[schemars(extend("exclusiveMinimum" = 0))]
            pub l: f64,
            /// Platform radius b (centre to spherical joints), mm.
            #[schemars(extend("exclusiveMinimum" = 0))]
            pub b: f64,
            /// Leg angle to the horizontal at home α₀, degrees, in (0, 90) (then a = b + L·cos α₀).
            #[serde(default)]
            #[schemars(extend("exclusiveMinimum" = 0, "exclusiveMaximum" = 90))]
            pub alpha0_deg: Option<f64>,
            /// Base radius a (O to the zero-stroke slider points), mm; alternative to `alpha0_deg`.
            #[serde(default)]
            #[schemars(extend("exclusiveMinimum" = 0))]
            pub a: Option<f64>,
            /// Actuator inclination γ, degrees, in [−90, 90] (0 = horizontal radially inward, 90 =
            /// vertical).
            #[serde(default)]
            #[schemars(range(min = -90, max = 90))]
            pub gamma_deg: f64,
        ] $($rest)*);
    };
    (@fields $head:tt [$($done:tt)*] include rayleigh; $($rest:tt)*) => {
        $crate::case::fields::case_struct!(@fields $head [$($done)*
            /// Mass-proportional Rayleigh coefficient α ≥ 0, 1/s (default 0).
            #[serde(default)]
            pub alpha: f64,
            /// Stiffness-proportional Rayleigh coefficient β ≥ 0, s (default 0).
            #[serde(default)]
            pub beta: f64,
        ] $($rest)*);
    };
    (@fields $head:tt [$($done:tt)*]
        include nonlinear_steps { $(#[$n:meta])* nonlinear, $(#[$s:meta])* steps, } $($rest:tt)*) => {
        $crate::case::fields::case_struct!(@fields $head [$($done)*
            $(#[$n])*
            #[serde(default)]
            pub nonlinear: bool,
            $(#[$s])*
            #[serde(default)]
            #[schemars(range(min = 1, max = 10000))]
            pub steps: Option<usize>,
        ] $($rest)*);
    };
    (@fields $head:tt [$($done:tt)*]
        include model_source {
            $(#[$d:meta])* description, $(#[$m:meta])* mesh, $(#[$g:meta])* gmsh, $(#[$o:meta])* model,
        }
        $($rest:tt)*) => {
        $crate::case::fields::case_struct!(@fields $head [$($done)*
            $(#[$d])*
            pub description: Option<String>,
            $(#[$m])*
            pub mesh: Option<String>,
            $(#[$g])*
            pub gmsh: Option<$crate::case::gmsh::GmshMapping>,
            $(#[$o])*
            #[serde(flatten)]
            pub model: $crate::case::mesh::MeshSpec,
        ] $($rest)*);
    };
    (@fields $head:tt [$($done:tt)*] $(#[$fm:meta])* $fv:vis $field:ident: $ty:ty, $($rest:tt)*) => {
        $crate::case::fields::case_struct!(@fields $head [$($done)* $(#[$fm])* $fv $field: $ty,] $($rest)*);
    };
    (@fields [$($head:tt)*] [$($done:tt)*]) => {
        $($head)* { $($done)* }
    };
    ($(#[$meta:meta])* $vis:vis struct $name:ident { $($body:tt)* }) => {
        $crate::case::fields::case_struct!(@fields [$(#[$meta])* $vis struct $name] [] $($body)*);
    };
}
pub(crate) use case_struct;
