//! The generic beam/shell model (`static`, `modal`): inline or from `meshes/*.json`.
//!
//! One way: [`shapes`] and [`load_shapes`] are the plain serde shapes of the JSON (what a case
//! file, a mesh file or the Gmsh reader produces); [`build`] turns them into an [`crate::fem::Model`],
//! validating once and naming JSON paths (named sections and materials are looked up by one
//! helper, [`lookup::Named`]).

pub mod build;
mod build_body_loads;
mod build_loads;
mod conflicts;
pub mod corot_length;
mod frames;
pub mod hinge;
mod hinge_memo;
mod joint;
pub mod load_shapes;
mod lookup;
pub mod metrics;
pub mod path_control;
pub mod promote;
pub mod requests;
pub mod shapes;
pub mod slots;
pub mod superelement;
pub mod superelement_file;

pub use super::fem_case::{ModalCase, StaticCase};
pub use build::unique_load_case_names;
pub use hinge::BuiltHinge;
pub use load_shapes::{
    DisplacementSpec, DofName, EdgeLoadSpec, ForceSpec, GroupForceSpec, LineAxes, LineLoadSpec, LoadCaseSpec,
    PressureSpec,
};
pub use metrics::{MetricKind, MetricRequest};
pub use requests::{ComplianceRequest, PictureRequest, StaticOutput, TrackRequest, ViewRequest};
pub use shapes::{
    ElementSpec, GmshMapping, GroupSpec, JointKind, MeshSpec, PlacementSpec, RigidSpec, SectionSpec, SupportSpec,
};
