//! Rigid-body dynamics in geometric algebra.
#[cfg(feature = "cli")]
pub mod cli;
pub mod csv;
pub mod dynamics;
pub mod error;
pub mod exact_flow;
pub mod exact_flow_generic;
pub mod gradients;
pub mod inertia;
mod input;
pub mod integrators;
pub mod peers;
pub mod report;
pub mod scene;
pub mod simulation;
pub mod special;
