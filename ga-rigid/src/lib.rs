//! Rigid-body dynamics in geometric algebra.

/// The glam of ga-rigid's API (glam 0.32, ga-core's `ga_core::glam`, the version ga-core's
/// conversions are built for): name `DMat3` and `DVec3` through it so that they are the
/// types `inertia` takes and returns.
pub use ga_core::glam;

pub mod csv;
pub mod dynamics;
pub mod error;
pub mod exact_flow;
pub mod exact_flow_generic;
pub mod gradients;
pub mod inertia;
mod input;
pub mod integrators;
pub mod limits;
pub mod nd;
pub mod peers;
pub mod registry;
pub mod run;
pub mod scene;
pub mod simulation;
pub mod special;
