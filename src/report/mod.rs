//! Reports: Markdown, CSV, SVG and VTK views of results (formatting only).

pub mod axis;
pub mod json;
pub mod markdown;
pub mod model_svg;
pub mod numbers;
pub mod projection;
pub mod svg;
pub mod vtk;
