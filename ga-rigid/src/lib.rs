//! Rigid-body dynamics in geometric algebra.
//!
//! Without the default `std` feature the crate is `#![no_std]` and holds only [`engine`]
//! (with a glam feature on); everything else uses the standard library.
#![cfg_attr(not(feature = "std"), no_std)]
/// The glam of ga-rigid's API outside `engine` (glam 0.32, ga-core's `ga_core::glam`, the
/// version ga-core's conversions are built for): name `DMat3` and `DVec3` through it so that
/// they are the types `inertia` takes and returns. `engine` also serves older glam versions
/// through its `glam-0-29` ... features.
#[cfg(any(feature = "std", feature = "glam"))]
pub use ga_core::glam;

#[cfg(feature = "cli")]
pub mod cli;
#[cfg(feature = "std")]
pub mod csv;
#[cfg(feature = "std")]
pub mod dynamics;
#[cfg(any(
    feature = "glam-0-29",
    feature = "glam-0-30",
    feature = "glam-0-31",
    feature = "glam-0-32"
))]
pub mod engine;
#[cfg(feature = "std")]
pub mod error;
#[cfg(feature = "std")]
pub mod exact_flow;
#[cfg(feature = "std")]
pub mod exact_flow_generic;
#[cfg(feature = "std")]
pub mod gradients;
#[cfg(feature = "std")]
pub mod inertia;
#[cfg(feature = "std")]
mod input;
#[cfg(feature = "std")]
pub mod integrators;
#[cfg(feature = "std")]
pub mod peers;
#[cfg(feature = "std")]
pub mod report;
#[cfg(feature = "std")]
pub mod scene;
#[cfg(feature = "std")]
pub mod simulation;
#[cfg(feature = "std")]
pub mod special;
