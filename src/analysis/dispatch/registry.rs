//! The analysis kinds this build runs, generated from the one list of kinds,
//! [`super::kinds_list`] (a line there registers a kind for parsing and running).

use super::entry::{DynAnalysis, Entry};
#[allow(unused_imports)]
use crate::analysis::*;

/// Expands the list of kinds on the `analysis` side: the registry.
macro_rules! analysis_side {
    ($($(#[$attr:meta])* $variant:ident = $name:literal #$rank:literal, $(mod $module:ident,)? analysis $analysis:path $(, parse $parse:path)?;)*) => {
        /// Every analysis kind, in the order of the list of kinds (the order of
        /// [`super::Case`]'s variants).
        pub static REGISTRY: &[&dyn DynAnalysis] = &[$(&Entry::<$analysis>::new()),*];
    };
}

/// Expands the list of kinds into the declarations of the analysis modules its `mod` lines
/// name (`src/analysis/NAME.rs`).
macro_rules! analysis_modules {
    ($($(#[$attr:meta])* $variant:ident = $name:literal #$rank:literal, $(mod $module:ident,)? analysis $analysis:path $(, parse $parse:path)?;)*) => {
        $($(pub mod $module;)?)*
    };
}
pub(crate) use analysis_modules;

super::kinds_list::analyses!(analysis_side);

/// The registered analysis of `kind`, if any.
pub fn find(kind: &str) -> Option<&'static dyn DynAnalysis> {
    REGISTRY.iter().copied().find(|a| a.kind() == kind)
}

#[cfg(test)]
mod tests {
    /// Every `analysis` name a case file may give has exactly one registered analysis.
    #[test]
    fn every_case_kind_is_registered_once() {
        for name in super::ANALYSES {
            let n = super::REGISTRY.iter().filter(|a| a.kind() == *name).count();
            assert_eq!(n, 1, "analysis `{name}` registered {n} times");
        }
        assert_eq!(super::REGISTRY.len(), super::ANALYSES.len());
    }
}
