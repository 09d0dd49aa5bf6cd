//! The analysis kinds this build runs: one line each.

use super::kind::{DynAnalysis, Entry};
use super::kinds;

/// Every analysis kind, in the order of [`crate::case::ANALYSES`].
pub static REGISTRY: &[&dyn DynAnalysis] = &[
    &Entry::<kinds::Kinematics>::new(),
    &Entry::<kinds::Hinge>::new(),
    &Entry::<kinds::Stage>::new(),
    &Entry::<kinds::FemVsFkp>::new(),
    &Entry::<kinds::Sensitivity>::new(),
    &Entry::<kinds::Design>::new(),
    &Entry::<kinds::Static>::new(),
    &Entry::<kinds::Modal>::new(),
    &Entry::<kinds::SweepKind>::new(),
    &Entry::<super::pantilt::PanTiltKind>::new(),
    &Entry::<super::prs_stiffness::PrsStiffnessAnalysis>::new(),
];

/// The registered analysis of `kind`, if any.
pub fn find(kind: &str) -> Option<&'static dyn DynAnalysis> {
    REGISTRY.iter().copied().find(|a| a.kind() == kind)
}

#[cfg(test)]
mod tests {
    /// Every `analysis` name a case file may give has exactly one registered analysis.
    #[test]
    fn every_case_kind_is_registered_once() {
        for name in crate::case::ANALYSES {
            let n = super::REGISTRY.iter().filter(|a| a.kind() == *name).count();
            assert_eq!(n, 1, "analysis `{name}` registered {n} times");
        }
        assert_eq!(super::REGISTRY.len(), crate::case::ANALYSES.len());
    }
}
