//! The analysis kinds of case files: the one list every dispatch over kinds is generated from.
//!
//! [`analyses!`] hands the list to a callback macro. [`super::case_file`] expands it into the
//! [`Case`](crate::analysis::Case) enum (one variant per line, documented by the line's doc comment; the
//! variant order is the order of the JSON Schema's alternatives), [`ANALYSES`](crate::analysis::ANALYSES)
//! (ordered by each line's `#n`, the order messages list the kinds in), the parse dispatch and
//! [`CaseOf`](super::case_file::CaseOf) for each kind; [`super::registry`] expands it into the
//! registry; [`crate::analysis`] into the declarations of the modules the `mod` lines name.
//!
//! A line reads `Variant = "name" #n, [mod NAME,] analysis PATH [, parse PATH];`:
//! - `analysis PATH`: the [`Analysis`](crate::analysis::Analysis) implementation; its `Case` type is the
//!   case shape of the kind (the `Variant`'s payload).
//! - `mod NAME` declares the module `analysis::NAME` (`src/analysis/NAME/mod.rs`, the kind's folder).
//! - `parse PATH`: a parser `fn(Value, Option<&Path>) -> Result<Shape, CaseError>` for shapes
//!   that read other files (meshes); without it the shape is read by serde with unknown fields
//!   refused and errors under their JSON path.
//!
//! Paths are relative to the `analysis` module.
//!
//! # Adding an analysis kind
//!
//! One module and one line. Write `src/analysis/NAME/mod.rs` (its folder: see [`crate::analysis`]) with the case shape (a serde struct
//! deriving `Debug, Clone, Deserialize, JsonSchema` with `#[serde(deny_unknown_fields)]`,
//! validated with [`CaseError`](crate::case::CaseError)s that name JSON paths), the typed
//! result, and the [`Analysis`](crate::analysis::Analysis) implementation; then add its line here, e.g.
//!
//! ```text
//! /// What the analysis does (the schema's description of the kind).
//! Example = "example" #11, mod example, analysis example::ExampleKind;
//! ```
//!
//! The case shapes of the kinds that predate this list live in [`crate::case`], since the stage
//! sizing and the sweeps use them too.

/// Calls `$callback! { … }` with the list of analysis kinds (see the module docs).
macro_rules! analyses {
    ($callback:ident) => {
        $callback! {
            /// 3-PRS rigid-body kinematics.
            Kinematics = "kinematics" #0, analysis kinds::Kinematics;
            /// Linear (or nonlinear) statics of a generic beam model.
            Static = "static" #6, analysis kinds::Static, parse crate::case::fem_case::parse_static;
            /// One flexure hinge in its blank.
            Hinge = "hinge" #1, analysis kinds::Hinge;
            /// Batch runs over a base case.
            Sweep = "sweep" #8, analysis kinds::SweepKind;
            /// The monolithic 3-PRS compliant stage.
            Stage = "stage" #2, analysis kinds::Stage;
            /// FEM versus rigid-body forward kinematics.
            FemVsFkp = "fem_vs_fkp" #3, analysis kinds::FemVsFkp;
            /// Sensitivities of the stage design to its hinge parameters (the design guidelines of
            /// Table 1 of Ruiz et al. (2019), 3-PRS compliant parallel stage), or of the metrics
            /// of any static mesh case to its parameters (`case`).
            Sensitivity = "sensitivity" #4, analysis kinds::Sensitivity, parse crate::case::design_mesh::parse_sensitivity;
            /// Requirement-driven sizing of the stage hinges, or of the parameters of any static
            /// mesh case against requirements on its metrics (`case`).
            Design = "design" #5, analysis kinds::Design, parse crate::case::design_mesh::parse_design;
            /// Natural frequencies and mode shapes of a generic beam/shell model.
            Modal = "modal" #7, analysis kinds::Modal, parse crate::case::fem_case::parse_modal;
            /// Pseudo-rigid-body model of the 8R compliant parallel pan-tilt (Yu, Lu and Hao (2016)).
            #[serde(rename = "pantilt")]
            PanTilt = "pantilt" #9, mod pantilt, analysis pantilt::PanTiltKind;
            /// Jacobian stiffness of a 3-PRS with compliant legs.
            PrsStiffness = "prs_stiffness" #10, mod prs_stiffness, analysis prs_stiffness::PrsStiffnessAnalysis;
            /// Linear transient response of a beam/shell model to load and motion histories.
            Transient = "transient" #11, mod transient, analysis transient::TransientKind, parse transient::parse_transient;
            /// Linear buckling: load multipliers and mode shapes of a reference load on a generic beam model.
            Buckling = "buckling" #12, mod buckling, analysis buckling::Buckling, parse buckling::parse_buckling;
            /// Exact-constraint check of a mesh model: redundant constraints and free motions of its
            /// bodies taken rigid (Grübler–Kutzbach by rank; Blanding, Exact Constraint, 1999).
            Constraints = "constraints" #13, mod constraints, analysis constraints::ConstraintsAnalysis, parse constraints::parse;
            /// Frequency response from nodal loads to nodal DOFs (modal superposition with static
            /// correction, checked by a direct solve) and its state-space model.
            Frf = "frf" #14, mod frf, analysis frf::FrfKind, parse frf::parse_frf;
            /// Craig–Bampton reduction of a beam model to interface nodes: a superelement (K, M on
            /// the interface DOFs plus fixed-interface modes).
            CraigBampton = "craig_bampton" #15, mod craig_bampton, analysis craig_bampton::CraigBamptonKind, parse craig_bampton::parse;
        }
    };
}
pub(crate) use analyses;
