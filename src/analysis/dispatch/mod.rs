//! The list of analysis kinds and what is generated from it: the [`Case`](case_file::Case) enum,
//! the registry, the wiring of the built-in kinds, the case-file reader.

pub mod case_file;
pub mod entry;
pub mod export;
pub mod kinds;
pub mod kinds_list;
pub mod registry;
