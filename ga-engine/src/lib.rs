//! A rotation step an engine can call once per body per frame: glam types in and out,
//! `f32` or `f64`, no allocation in any step, no `std`, the same bits on every machine.
//!
//! ```
//! use ga_engine::f32::{step, Body};
//! use ga_engine::glam::{Mat3, Quat, Vec3};
//!
//! // A T-handle's tensor in its own frame; any symmetric tensor will do.
//! let body = Body::from_tensor(Mat3::from_diagonal(Vec3::new(1.0, 2.0, 3.0))).unwrap();
//! let (mut q, mut l) = (Quat::IDENTITY, Vec3::new(0.01, 2.0, 0.0)); // world momentum
//! for _ in 0..600 {
//!     (q, l) = step(&body, q, l, Vec3::ZERO, 1.0 / 60.0); // 60 Hz, no torque
//! }
//! assert_eq!(l, Vec3::new(0.01, 2.0, 0.0)); // |L| kept to the bit without torque
//! ```
//!
//! # What is here
//! - [`f32`](mod@f32) and [`f64`](mod@f64) (glam 0.32, feature `glam`; `glam_0_29` ...
//!   `glam_0_33` for the glam a project pins, features `glam-0-29` ...): a [`f32::Body`]
//!   from an inertia tensor in the body frame or from principal moments and their frame,
//!   diagonalised once; [`f32::step`] (free flow plus kick, second order; the free flow
//!   split around the Casimir `|L|^2` into three corrected axis turns, derived in the
//!   repository's `docs/derivations/corrected-splitting.md`) and [`f32::step_order4`]
//!   (its fourth-order composition) on the orientation and the world angular momentum;
//!   the engines' baselines [`f32::explicit_gyroscopic_euler`] and
//!   [`f32::implicit_gyroscopic_euler`] on the world angular velocity; the slice forms
//!   [`f32::step_slice`] and, with feature `rayon`, `par_step_slice`.
//! - `f32::BodyColumns` (feature `columns`): many bodies kept column by column, the way the
//!   slice step's lanes take them, and stepped all at once (`BodyColumns::step`): faster a
//!   body than [`f32::step_slice`] on `BodyState`s, which spends much of its time gathering
//!   each component from eight structs and scattering the results back (the repository's
//!   BENCHMARKS.md, "The engine step", has the figures). For an engine that steps the same
//!   bodies every frame and can keep their rotation there. Off by default: its code makes
//!   the crate's release build much longer.
//! - The state is the world angular momentum, not the velocity: a world torque changes
//!   it exactly, and the free flow does not change it at all, so `|L|` of a free body is
//!   kept to the bit. [`f32::Body::angular_velocity`] and
//!   [`f32::Body::angular_momentum`] convert for engines that store the velocity (each
//!   conversion rounds, so storing the momentum is better).
//!
//! # Torques: which call
//! Every step takes `(body, orientation, momentum, torque, dt)` in that order.
//! - A torque that depends on the orientation (gravity on a body turning about a pivot,
//!   a spring or a magnet pulling an axis toward a direction): [`f32::step_with`] with
//!   the torque as a function of the orientation, read at both ends of the step. This
//!   keeps the energy of such a torque bounded; passing its value at the step's start
//!   to [`f32::step`] holds it over the step and lets the energy drift (the heavy top in
//!   the repository's `ga-engine/examples/t_handle.rs` shows both).
//! - A torque that is given for the frame (a motor, a player's push, a damper the engine
//!   computed): [`f32::step`], which holds it over the step.
//! - Gravity on a free body acts at its centre of mass and gives no torque: the engine's
//!   linear step handles it, and the rotation step takes `torque = 0`.
//!
//! # Engines that store the angular velocity
//! The steps keep the world angular momentum, because that is what a free body keeps:
//! converting to the velocity and back every frame rounds twice a frame and loses the
//! bit-for-bit `|L|`. An engine whose bodies store the velocity keeps a
//! [`f32::BodyState`] beside each body instead, made once from the velocity
//! ([`f32::BodyState::from_angular_velocity`]), steps it ([`f32::BodyState::step`] or
//! [`f32::step_slice`]), reads the velocity where its solver needs one
//! ([`f32::BodyState::angular_velocity`]), and hands contact and joint impulses back as
//! momentum ([`f32::BodyState::apply_angular_impulse`], exact) or, where its solver writes
//! velocities, as a changed velocity ([`f32::BodyState::set_angular_velocity`], one
//! rounding, only when the velocity really changed). `f32::BodyColumns` (feature `columns`)
//! holds the same state column by column, with the same calls on each body (`get_mut`).
//!
//! # The same bits everywhere: what is promised
//! The steps use only IEEE-754 `+ - * /` and `sqrt` (each correctly rounded), in a fixed
//! order: no fused multiply-add (Rust never contracts `a * b + c`, with or without
//! `-C target-cpu=native`), no `sin`/`cos` at all (rational turns), no reassociation. The
//! one run-time CPU check is the slice forms': with AVX an f32 slice steps eight bodies in
//! one register instead of four, an f64 slice four in one register instead of two in an
//! SSE2 register, each lane doing the scalar's operations in the scalar's order, so the
//! bits are the same either way (unit tests compare every form with one body at a time). So
//! on every target where `f32`/`f64` are IEEE binary32/binary64 with round-to-nearest and
//! no flush of subnormals (x86-64 with SSE2, AVX2 or AVX-512; AArch64; wasm32), the same
//! inputs give the same bits, in the one-body, slice and parallel forms alike
//! (`tests/engine.rs` compares golden bit patterns of 10^4 steps; CI runs it on x86-64,
//! built for the baseline and for the CPU's own instructions, and as AArch64 code under
//! qemu). Not promised: 32-bit x86 without SSE2 (x87 keeps extra precision), a
//! flush-to-zero mode set by the caller, and NaN payloads. glam's own operations (which may
//! round differently between its SIMD and scalar builds) are used only to move values in
//! and out. Building the body description ([`f32::Body::from_tensor`]) uses `libm`'s
//! `sqrt`, also correctly rounded, in f64.
//!
//! # Errors and panics
//! Bodies are checked once ([`BodyError`]). The steps never panic and never allocate
//! (only `BodyColumns` allocates, as it grows; an index past its end gives `None`);
//! finite input gives finite output unless the numbers overflow (a momentum near
//! `f32::MAX`). A step so long that its products overflow (`dt` near `f32::MAX`; for
//! [`f32::step_order4`], whose substeps are 1.35 `dt`, above `f32::MAX / 1.35`) still
//! returns a finite unit orientation and the kicked momentum, but the orientation is
//! then not the flow's, except that a body without momentum (and torque) stays put in
//! [`f32::step`].
//!
//! # Orientations
//! Every step, and [`f32::Body::angular_velocity`], [`f32::Body::angular_momentum`] and
//! [`f32::Body::kinetic_energy`], takes any non-zero finite quaternion and works on it
//! normalised: a scaled orientation (`2 q`, `1e-30 q`, `1e30 q`) gives the result of the
//! unit one to rounding (not to the bit: an orientation whose squared norm is within 16
//! ulps of 1, as the steps return and glam's `normalize` gives, is used as it is, so a
//! unit input keeps its bits; any other is divided by its norm first, which rounds). A
//! zero or non-finite orientation gives a NaN orientation (and the energy and velocity
//! NaN), never a panic; the momentum is still kicked by the torque.

#![cfg_attr(not(feature = "std"), no_std)]

// `BodyColumns` grows in a `Vec`; nothing else allocates.
extern crate alloc;

#[cfg(feature = "columns")]
#[macro_use]
mod columns;
#[macro_use]
mod api;
#[cfg(all(target_arch = "x86_64", any(feature = "std", target_feature = "avx")))]
mod avx;
#[cfg(all(target_arch = "x86_64", any(feature = "std", target_feature = "avx")))]
mod avx64;
#[cfg(feature = "columns")]
mod blocks;
mod dispatch;
mod divided;
mod eigen;
mod error;
mod euler;
mod free_flow;
mod inertia;
#[cfg(feature = "rayon")]
mod parallel;
mod parts;
mod projective;
mod range;
mod rates;
mod real;
mod rotation;
mod slice;
mod split;
mod splitting;
#[cfg(target_arch = "x86_64")]
mod sse;
#[cfg(target_arch = "x86_64")]
mod sse64;
mod turning;

pub use error::BodyError;

// Without a glam the steps have no types to take: one error that says which features to
// turn on, not a crate of unused items (a `default-features = false` that dropped `glam`
// with `std`).
#[cfg(not(any(
    feature = "glam-0-29",
    feature = "glam-0-30",
    feature = "glam-0-31",
    feature = "glam-0-32",
    feature = "glam-0-33"
)))]
compile_error!(
    "ga-engine needs one of its glam features: `glam` (glam 0.32, at `ga_engine::f32` and \
     `ga_engine::f64`) or `glam-0-29` ... `glam-0-33`; its steps take and return glam's types"
);

// The README's example, run as a doctest so that it stays true.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;

/// The engine on glam 0.29 (feature `glam-0-29`).
#[cfg(feature = "glam-0-29")]
pub mod glam_0_29 {
    engine_api!(glam_0_29);
}

/// The engine on glam 0.30 (feature `glam-0-30`).
#[cfg(feature = "glam-0-30")]
pub mod glam_0_30 {
    engine_api!(glam_0_30);
}

/// The engine on glam 0.31 (feature `glam-0-31`).
#[cfg(feature = "glam-0-31")]
pub mod glam_0_31 {
    engine_api!(glam_0_31);
}

/// The engine on glam 0.32 (feature `glam-0-32`, or `glam`), also at [`f32`](mod@f32) and
/// [`f64`](mod@f64).
#[cfg(feature = "glam-0-32")]
pub mod glam_0_32 {
    engine_api!(glam_0_32);
}

/// The engine on glam 0.33 (feature `glam-0-33`), the glam of rapier3d 0.36.
#[cfg(feature = "glam-0-33")]
pub mod glam_0_33 {
    engine_api!(glam_0_33);
}

#[cfg(feature = "glam-0-32")]
pub use self::glam_0_32::{f32, f64};

/// glam 0.32, the glam of [`f32`](mod@f32) and [`f64`](mod@f64): name its `Quat`, `Vec3` and
/// `Mat3` through it to be sure they are the engine's.
#[cfg(feature = "glam-0-32")]
pub use ::glam_0_32 as glam;
