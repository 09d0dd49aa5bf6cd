//! The analysis kinds of case files: the one list every dispatch over kinds is generated from.
//!
//! [`analyses!`] hands the list to a callback macro. `case` expands it into the [`super::Case`]
//! enum (one variant per line, documented by the line's doc comment; the variant order is the
//! order of the JSON Schema's alternatives), [`super::ANALYSES`] (ordered by each line's `#n`,
//! the order messages list the kinds in), [`super::Case::analysis`], the parse dispatch, and
//! [`OfCase`] for each case shape; `analysis` expands it into its registry. The paths of a line
//! are relative to where each side expands them: `case` (the case shape and its parser) and
//! `analysis` (the [`Analysis`](../../analysis/kind/trait.Analysis.html) type).
//!
//! A line `mod NAME` declares the new modules `case::NAME` (`src/case/NAME.rs`, the case
//! shape) and `analysis::NAME` (`src/analysis/NAME.rs`, the analysis) as well.
//!
//! Adding an analysis kind: the case shape (a serde struct deriving `JsonSchema`) in
//! `src/case/NAME.rs`, the `Analysis` implementation in `src/analysis/NAME.rs`, and one line
//! here, e.g.
//!
//! ```text
//! /// What the analysis does (the schema's description of the kind).
//! ```

/// Calls `$callback! { … }` with the list of analysis kinds (see the module docs).
macro_rules! analyses {
    ($callback:ident) => {
        $callback! {
            /// 3-PRS rigid-body kinematics.
            Kinematics = "kinematics" #0, case kinematics::KinematicsCase, parse shape, analysis kinds::Kinematics;
            /// Linear (or nonlinear) statics of a generic beam model.
            Static = "static" #6, case fem_case::StaticCase, parse fem_case::parse_static, analysis kinds::Static;
            /// One flexure hinge in its blank.
            Hinge = "hinge" #1, case hinge::HingeCase, parse shape, analysis kinds::Hinge;
            /// Batch runs over a base case.
            Sweep = "sweep" #8, case sweep::SweepCase, parse shape, analysis kinds::SweepKind;
            /// The monolithic 3-PRS compliant stage.
            Stage = "stage" #2, case stage::StageCase, parse shape, analysis kinds::Stage;
            /// FEM versus rigid-body forward kinematics.
            FemVsFkp = "fem_vs_fkp" #3, case stage::FemVsFkpCase, parse shape, analysis kinds::FemVsFkp;
            /// Sensitivities of the stage design to its hinge parameters (the design guidelines of
            /// Table 1 of Ruiz et al. (2019), 3-PRS compliant parallel stage).
            Sensitivity = "sensitivity" #4, case design::SensitivityCase, parse shape, analysis kinds::Sensitivity;
            /// Requirement-driven sizing of the stage hinges.
            Design = "design" #5, case design::DesignCase, parse shape, analysis kinds::Design;
            /// Natural frequencies and mode shapes of a generic beam/shell model.
            Modal = "modal" #7, case fem_case::ModalCase, parse fem_case::parse_modal, analysis kinds::Modal;
            /// Pseudo-rigid-body model of the 8R compliant parallel pan-tilt (Yu, Lu and Hao (2016)).
            #[serde(rename = "pantilt")]
            PanTilt = "pantilt" #9, mod pantilt, case pantilt::PanTiltCase, parse shape, analysis pantilt::PanTiltKind;
            /// Jacobian stiffness of a 3-PRS with compliant legs.
            PrsStiffness = "prs_stiffness" #10, mod prs_stiffness, case prs_stiffness::PrsStiffnessCase, parse shape, analysis prs_stiffness::PrsStiffnessAnalysis;
            /// Frequency response from nodal loads to nodal DOFs (modal superposition with static
            /// correction, checked by a direct solve) and its state-space model.
            Frf = "frf" #11, mod frf, case frf::FrfCase, parse frf::parse_frf, analysis frf::FrfKind;
        }
    };
}
pub(crate) use analyses;

/// A case shape that is one variant of [`super::Case`] (implemented for every kind's shape).
pub trait OfCase {
    /// The shape inside `case`, if the case is of this kind.
    fn of_case(case: &super::Case) -> Option<&Self>;
}

/// The parser of a plain case shape: serde with unknown fields refused, errors under their
/// JSON path.
pub fn shape<T: serde::de::DeserializeOwned>(
    value: serde_json::Value,
    _base: Option<&std::path::Path>,
) -> Result<T, super::CaseError> {
    super::from_value(value, "")
}

/// Expands [`analyses!`] on the `case` side.
macro_rules! case_side {
    ($($(#[$attr:meta])* $variant:ident = $name:literal #$rank:literal, $(mod $module:ident,)? case $shape:path, parse $parse:path, analysis $analysis:path;)*) => {
        $($(pub mod $module;)?)*

        /// A parsed case file (not yet validated).
        #[derive(Debug, Clone, schemars::JsonSchema)]
        #[serde(tag = "analysis", rename_all = "snake_case")]
        pub enum Case {
            $(
                $(#[$attr])*
                $variant($shape),
            )*
        }

        /// The `analysis` names this build understands.
        pub const ANALYSES: &[&str] = &{
            let mut names = [""; [$($name),*].len()];
            $(names[$rank] = $name;)*
            names
        };

        impl Case {
            /// The `analysis` name.
            pub fn analysis(&self) -> &'static str {
                match self {
                    $(Case::$variant(_) => $name,)*
                }
            }
        }

        $(
            impl kinds::OfCase for $shape {
                fn of_case(case: &Case) -> Option<&Self> {
                    match case {
                        Case::$variant(c) => Some(c),
                        #[allow(unreachable_patterns)]
                        _ => None,
                    }
                }
            }
        )*

        /// The case of kind `analysis` from the rest of its JSON object (`None`: no such kind).
        fn parse_kind(analysis: &str, value: Value, base: Option<&Path>) -> Option<Result<Case, CaseError>> {
            use kinds::shape;
            match analysis {
                $($name => Some($parse(value, base).map(Case::$variant)),)*
                _ => None,
            }
        }
    };
}
pub(crate) use case_side;
