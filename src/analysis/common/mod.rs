//! The shared floor of the analyses: services every analysis kind may use, naming no kind.

pub(crate) mod case_shape;
pub mod fatigue;
pub mod finite;
pub mod kind;
pub mod line;
pub mod outcome;
pub mod picture;
pub mod units;
pub mod vtu;
pub mod warn;
