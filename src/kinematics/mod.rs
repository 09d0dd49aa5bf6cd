//! Rigid-body kinematics of the 3-PRS parallel mechanism: IKP, FKP, parasitic motion, passive
//! joint rotations, Jacobians and the requirement sweep.

pub mod exact;
pub mod pantilt;
pub mod pivot;
pub mod prs;
pub mod prs_stiffness;
pub mod workspace;

pub use prs::{FkpSolution, IkpSolution, KinematicsError, Pose, Prs};
pub use workspace::{PoseBox, WorkspaceRanges};
