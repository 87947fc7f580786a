//! G2, G3 and G4 in `f32` and `f64`, every product written out at compile time by
//! [`ga_macros::algebra!`] as straight-line code specialised to the Euclidean sign table.
//!
//! ```
//! use ga_core::f64::g3::*;
//! // A quarter turn in the e12 plane: R = exp(-B theta / 2) turns e1 toward e2.
//! let r = (Bivector::E12 * (-std::f64::consts::FRAC_PI_4)).exp();
//! let y = r.sandwich(Vector::E1);
//! assert!((y - Vector::E2).norm() < 1e-15);
//! ```
//!
//! Conventions: components in canonical order (grade first, then lexicographic on the
//! index list); a rotor acts as `y = R x ~R`; `*` geometric, `^` outer, `|` the lecture's
//! inner product (lowest grade, |r - s|); contractions and the commutator are trait
//! methods (`use ga_core::f64::g3::*`).
#![deny(missing_docs)]
#![cfg_attr(not(feature = "std"), no_std)]

/// The `libm` this crate calls without its `std` feature: a `no_std` crate can name it in
/// its own algebras with `math: libm(::ga_core::libm)`.
pub use libm;

#[cfg(feature = "glam")]
mod glam_interop;
// The slice kernels ask the CPU what it has, which needs the standard library.
#[cfg(feature = "std")]
pub mod kernels;
mod precision;
mod rotor;

pub use rotor::RotationMatrix;

/// Double-precision algebras.
pub mod f64 {
    ga_macros::algebra! {
        /// The Euclidean plane, G(2, 0, 0), in `f64`.
        pub mod g2 { metric: [1, 1], scalar: f64, math: auto }
    }
    ga_macros::algebra! {
        /// Euclidean space, G(3, 0, 0), in `f64`.
        pub mod g3 { metric: [1, 1, 1], scalar: f64, lanes: [4], math: auto }
    }
    ga_macros::algebra! {
        /// Euclidean four-space, G(4, 0, 0), in `f64`.
        pub mod g4 { metric: [1, 1, 1, 1], scalar: f64, math: auto }
    }
}

/// Single-precision algebras.
pub mod f32 {
    ga_macros::algebra! {
        /// The Euclidean plane, G(2, 0, 0), in `f32`.
        pub mod g2 { metric: [1, 1], scalar: f32, math: auto }
    }
    ga_macros::algebra! {
        /// Euclidean space, G(3, 0, 0), in `f32`.
        pub mod g3 { metric: [1, 1, 1], scalar: f32, lanes: [4, 8], math: auto }
    }
    ga_macros::algebra! {
        /// Euclidean four-space, G(4, 0, 0), in `f32`.
        pub mod g4 { metric: [1, 1, 1, 1], scalar: f32, lanes: [4], math: auto }
    }
}

/// The README's examples, compiled and run as doctests.
#[cfg(all(doctest, feature = "glam"))]
#[doc = include_str!("../../README.md")]
struct ReadmeDoctests;
