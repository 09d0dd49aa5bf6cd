//! Design sensitivities (gradients with respect to case parameters).

pub mod nonlinear;
