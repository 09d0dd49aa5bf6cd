pub mod vtk;
