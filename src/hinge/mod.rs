//! Flexure hinges.
