//! Finite-element core: 3D Timoshenko/Euler–Bernoulli beams, flexibility (compliance) elements,
//! 6-DOF springs, rigid links by master–slave elimination, supports and prescribed displacements,
//! sparse Cholesky (faer, behind [`solve`]), stress recovery and node compliance.
//!
//! Units: mm, N, MPa, tonne; rotations in radians. Every node carries six DOFs
//! `ux uy uz rx ry rz` in global axes.
//!
//! Flow: [`model::Model`] (plain data) → [`constraints::DofMap`] (validated DOF numbering,
//! rigid links eliminated) → [`assembly::Pattern`] (sparsity once per topology) + values →
//! [`solve::SymbolicFactor`] / [`solve::Factor`] → [`analysis::System`] solves load cases →
//! [`recovery`] (end forces, stresses, reactions) → [`results`] (typed results).

pub mod analysis;
pub mod assembly;
pub mod buckling;
pub mod cache;
pub mod chain;
pub mod constraints;
pub mod corot;
pub mod craig_bampton;
pub mod diagnose;
pub mod dof;
pub mod element;
pub mod elements;
pub mod error;
pub mod frf;
pub mod history;
pub mod inline_vec;
pub mod lanczos;
pub mod lattice;
pub mod loads;
pub mod mass;
pub mod matrices;
pub mod memo;
pub mod modal;
pub mod model;
pub mod nd;
pub mod nonlinear;
pub mod ordering_counts;
pub mod recovery;
pub mod results;
pub mod section;
pub mod shell;
pub mod shell9;
pub mod shell_loads;
pub mod shell_recovery;
pub mod shell_spr;
pub mod solve;
pub mod state_space;
pub mod superelement;
pub mod transform;
pub mod transient;

pub use analysis::{CaseResult, StaticResults, System};
pub use cache::SolverCache;
pub use cache::{solve_static, solve_static_cached, solve_static_with};
pub use dof::{Dof, NodeDof};
pub use error::FemError;
pub use model::{
    Beam, Element, FlexElement, LoadCase, Model, NodalLoad, PointMass, Prescribed, RigidLink, Shell4, Shell9, Spring,
    SpringAxes, Support, Tie,
};
pub use nonlinear::{
    solve_nonlinear, solve_nonlinear_each, ArcLength, CriticalKind, CriticalPoint, NonlinearCase, NonlinearOptions,
    NonlinearResults, PathPoint, StepQuantities, StepTrack, Tangent,
};
pub use section::{Section, SectionProps};

/// Result alias for the FEM core.
pub type Result<T> = std::result::Result<T, FemError>;
