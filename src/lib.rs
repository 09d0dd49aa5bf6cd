//! flexfem — a fast, validated 3D beam/shell finite-element solver for compliant mechanisms.
//!
//! Units throughout: mm, N, MPa, s, tonne; angles in radians inside the library, degrees in
//! case files and results.

pub mod analysis;
pub mod case;
pub mod cli;
pub mod design;
pub mod fatigue;
pub mod fem;
pub mod gradient;
pub mod hinge;
pub mod kinematics;
pub mod material;
pub mod output;
pub mod problem;
pub mod report;
pub mod stage;
