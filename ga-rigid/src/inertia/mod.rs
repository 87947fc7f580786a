//! Inertia on bivectors: the map, its constructors (principal moments, solids, point
//! masses, closed meshes) and the symmetric eigen-solver behind them.

mod eigen;
#[allow(clippy::module_inception)] // the module is named after the one type it holds
mod inertia;
mod mesh;
mod point_masses;
mod solids;

pub use eigen::{matrix_from_rotor, rotor_from_matrix, symmetric_eigen, SymmetricEigen};
pub(crate) use inertia::normalize_rotor;
pub use inertia::Inertia;
pub use mesh::{
    Mesh, MeshMoments, MAX_MESH_BYTES, MAX_MESH_SHELLS, MAX_MESH_TRIANGLES, MAX_MESH_VERTICES,
};
pub use solids::Solid;
