//! VTK output.
