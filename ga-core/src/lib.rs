//! G2, G3 and G4 in `f32` and `f64`, every product written out at compile time by
//! [`ga_macros::algebra!`] as straight-line code specialised to the Euclidean sign table.
//!
//! ```
//! # #[cfg(all(feature = "f64", feature = "g3"))] {
//! use ga_core::f64::g3::*;
//! // A quarter turn in the e12 plane: R = exp(-B theta / 2) turns e1 toward e2.
//! let r = (Bivector::E12 * (-std::f64::consts::FRAC_PI_4)).exp();
//! let y = r.sandwich(Vector::E1);
//! assert!((y - Vector::E2).norm() < 1e-15);
//! # }
//! ```
//!
//! Conventions: components in canonical order (grade first, then lexicographic on the
//! index list); a rotor acts as `y = R x ~R`; `*` geometric, `^` outer, `|` the lecture's
//! inner product (lowest grade, |r - s|); contractions and the commutator are trait
//! methods (`use ga_core::f64::g3::*`).
//!
//! Cargo features (see the README): `g2`, `g3`, `g4` and `f32`, `f64` choose the modules
//! (`f64::g3` needs both `f64` and `g3`; default `g3`, `f32`, `f64`); `batch` adds the
//! structure-of-arrays modules on `wide`; `serde`, `bytemuck`, `approx`, `mint` add those
//! crates' traits to every type (re-exported here under the same names); `glam` (glam
//! 0.32, re-exported as `ga_core::glam`) and `glam-0-29` to `glam-0-33` add glam conversions.
#![deny(missing_docs)]
#![cfg_attr(not(feature = "std"), no_std)]

/// The `libm` this crate calls without its `std` feature (feature `libm`): a `no_std`
/// crate can name it in its own algebras with `math: libm(::ga_core::libm)`.
#[cfg(feature = "libm")]
pub use libm;

#[cfg(not(any(feature = "std", feature = "libm")))]
compile_error!(
    "ga-core needs its feature `std` or, in a `no_std` crate, its feature `libm`: \
     square roots and the trigonometric functions come from one of them"
);

/// Stands in for libm when neither `std` nor `libm` is on, so that the build stops at the
/// one `compile_error!` above rather than at every call of a float function.
#[cfg(not(any(feature = "std", feature = "libm")))]
#[doc(hidden)]
pub mod libm {
    macro_rules! stand_ins {
        ($($unary:ident)*; $($binary:ident)*; $($pair:ident)*) => {
            $(pub fn $unary<T>(x: T) -> T { x })*
            $(pub fn $binary<T>(x: T, _: T) -> T { x })*
            $(pub fn $pair<T: Copy>(x: T) -> (T, T) { (x, x) })*
        };
    }
    stand_ins!(
        sqrt sin cos cosh sinh asinh log1p acos sqrtf sinf cosf coshf sinhf asinhf log1pf acosf
        floor ceil round trunc exp exp2 log log2 floorf ceilf roundf truncf expf exp2f logf log2f;
        atan2 hypot atan2f hypotf pow powf;
        sincos sincosf
    );
    /// `fma`'s stand-in.
    pub fn fma<T>(x: T, _: T, _: T) -> T {
        x
    }
    /// `fmaf`'s stand-in.
    pub fn fmaf<T>(x: T, _: T, _: T) -> T {
        x
    }
}

// The generated modules name `::ga_core::Scalar`; this lets ga-core's own do so too.
extern crate self as ga_core;

mod scalar;
#[doc(hidden)]
pub use scalar::checked as __checked_scalar;
pub use scalar::Scalar;

/// num-dual, whose `Dual64` and `HyperDual64` implement [`Scalar`] (feature `dual`).
#[cfg(feature = "dual")]
pub use num_dual;

/// Algebras over `num_dual::Dual64`: every product, norm, inverse, exp and log carries
/// first derivatives (feature `dual`).
///
/// ```
/// use ga_core::dual64::g3::*;
/// use ga_core::num_dual::Dual64;
/// // d/dt of the rotation of e1 by t in the e12 plane, at t = 0: e2.
/// let t = Dual64::new(0.0, 1.0);
/// let r = (Bivector::E12 * (t * -0.5)).exp();
/// let y = r.sandwich(Vector::E1);
/// assert!((y.e2.eps - 1.0).abs() < 1e-15);
/// ```
#[cfg(feature = "dual")]
pub mod dual64 {
    ga_macros::algebra! {
        /// Euclidean space, G(3, 0, 0), over `num_dual::Dual64`.
        pub mod g3 { metric: [1, 1, 1], scalar: ::num_dual::Dual64 }
    }
}

#[cfg(feature = "g3")]
mod euler;
#[cfg(feature = "g3")]
mod glam_componentwise;
#[cfg(feature = "g3")]
mod glam_interop;
#[cfg(feature = "g3")]
mod glam_vocabulary;
/// glam's `x`, `y`, `z` view of G3's `Vector` (`v.x` reads and writes `v.e1`).
#[cfg(all(feature = "g3", any(feature = "f32", feature = "f64")))]
pub use glam_vocabulary::Xyz;
// The slice kernels ask the CPU what it has, which needs the standard library.
#[cfg(all(feature = "std", feature = "g3", any(feature = "f32", feature = "f64")))]
pub mod kernels;
#[cfg(all(feature = "f32", feature = "f64"))]
mod precision;
#[cfg(any(feature = "g2", feature = "g3"))]
mod rotor;

#[cfg(feature = "g3")]
pub use euler::EulerRot;
#[cfg(feature = "g3")]
pub use rotor::RotationMatrix;

/// serde, as the `serde` feature's impls use it.
#[cfg(feature = "serde")]
pub use serde;

/// bytemuck, as the `bytemuck` feature's impls use it.
#[cfg(feature = "bytemuck")]
pub use bytemuck;

/// approx, as the `approx` feature's impls use it.
#[cfg(feature = "approx")]
pub use approx;

/// mint, as the `mint` feature's conversions use it.
#[cfg(feature = "mint")]
pub use mint;

/// The glam the `glam` feature converts to and from (0.32): name its types through this
/// path so that they are the same version.
#[cfg(feature = "glam")]
pub use glam_0_32 as glam;

/// glam 0.29 (feature `glam-0-29`).
#[cfg(feature = "glam-0-29")]
pub use glam_0_29;

/// glam 0.30 (feature `glam-0-30`).
#[cfg(feature = "glam-0-30")]
pub use glam_0_30;

/// glam 0.31 (feature `glam-0-31`).
#[cfg(feature = "glam-0-31")]
pub use glam_0_31;

/// glam 0.32 (feature `glam-0-32`; `glam` turns it on).
#[cfg(feature = "glam-0-32")]
pub use glam_0_32;

/// glam 0.33 (feature `glam-0-33`), for a project on the newest glam (rapier 0.36 is on it).
#[cfg(feature = "glam-0-33")]
pub use glam_0_33;

/// One algebra module, with the batch modules when the `batch` feature is on and the
/// WGSL constant when `wgsl` is (the macro's `lanes` and `shaders` keys cannot carry a
/// `cfg` that stops the work itself: a `cfg` on the emitted item would still have the
/// macro write the shader source on every build), the integrations the crate features
/// ask for, and the items after the braces (G3's glam free functions `quat`, `vec3`).
/// The macro writes a closed module, so it is written as a private `generated` module
/// whose items the public one re-exports next to those extra items.
// Unused when no precision is on.
#[allow(unused_macros)]
macro_rules! algebra {
    (
        #[doc = $doc:tt]
        $name:tt {
            metric: $metric:tt, scalar: $scalar:tt, lanes: $lanes:tt, shaders: $shaders:tt
            $(, $mint:tt)?
        }
        $($extra:item)*
    ) => {
        #[doc = $doc]
        pub mod $name {
            #[cfg(all(feature = "batch", feature = "wgsl"))]
            algebra!(@one $metric $scalar [lanes: $lanes, shaders: $shaders,] $($mint)?);
            #[cfg(all(feature = "batch", not(feature = "wgsl")))]
            algebra!(@one $metric $scalar [lanes: $lanes,] $($mint)?);
            #[cfg(all(not(feature = "batch"), feature = "wgsl"))]
            algebra!(@one $metric $scalar [shaders: $shaders,] $($mint)?);
            #[cfg(all(not(feature = "batch"), not(feature = "wgsl")))]
            algebra!(@one $metric $scalar [] $($mint)?);
            pub use generated::*;
            $($extra)*
        }
    };
    (@one $metric:tt $scalar:tt [$($keys:tt)*] $($mint:tt)?) => {
        ga_macros::algebra! {
            mod generated {
                metric: $metric,
                scalar: $scalar,
                $($keys)*
                math: auto(crate::libm),
                derive: [
                    #[cfg(feature = "serde")] serde,
                    #[cfg(feature = "bytemuck")] bytemuck,
                    #[cfg(feature = "approx")] approx,
                    $(#[cfg(feature = "mint")] $mint,)?
                ],
            }
        }
    };
}

/// Double-precision algebras.
#[cfg(feature = "f64")]
pub mod f64 {
    #[cfg(feature = "g2")]
    algebra! {
        #[doc = "The Euclidean plane, G(2, 0, 0), in `f64`."]
        g2 { metric: [1, 1], scalar: f64, lanes: [], shaders: [] }
    }
    #[cfg(feature = "g3")]
    algebra! {
        #[doc = "Euclidean space, G(3, 0, 0), in `f64`."]
        g3 { metric: [1, 1, 1], scalar: f64, lanes: [4], shaders: [], mint }
        /// glam's `dquat(x, y, z, w)`: [`Rotor::from_xyzw`].
        pub use crate::glam_vocabulary::g3_f64::dquat;
        /// glam's `dvec3(x, y, z)`: [`Vector::new`].
        pub use crate::glam_vocabulary::g3_f64::dvec3;
    }
    #[cfg(feature = "g4")]
    algebra! {
        #[doc = "Euclidean four-space, G(4, 0, 0), in `f64`."]
        g4 { metric: [1, 1, 1, 1], scalar: f64, lanes: [], shaders: [] }
    }
}

/// Single-precision algebras.
#[cfg(feature = "f32")]
pub mod f32 {
    #[cfg(feature = "g2")]
    algebra! {
        #[doc = "The Euclidean plane, G(2, 0, 0), in `f32`."]
        g2 {
            metric: [1, 1], scalar: f32, lanes: [],
            shaders: [wgsl]
        }
    }
    #[cfg(feature = "g3")]
    algebra! {
        #[doc = "Euclidean space, G(3, 0, 0), in `f32`."]
        g3 {
            metric: [1, 1, 1], scalar: f32, lanes: [4, 8],
            shaders: [wgsl], mint
        }
        /// glam's `quat(x, y, z, w)`: [`Rotor::from_xyzw`].
        pub use crate::glam_vocabulary::g3_f32::quat;
        /// glam's `vec3(x, y, z)`: [`Vector::new`].
        pub use crate::glam_vocabulary::g3_f32::vec3;
    }
    #[cfg(feature = "g4")]
    algebra! {
        #[doc = "Euclidean four-space, G(4, 0, 0), in `f32`."]
        g4 {
            metric: [1, 1, 1, 1], scalar: f32, lanes: [4],
            shaders: [wgsl]
        }
    }
}

/// The README's examples, compiled and run as doctests.
#[cfg(all(
    doctest,
    feature = "std",
    feature = "glam",
    feature = "g3",
    feature = "f32",
    feature = "f64"
))]
#[doc = include_str!("../../README.md")]
struct ReadmeDoctests;

/// docs/glam.md's examples, compiled and run as doctests.
#[cfg(all(
    doctest,
    feature = "std",
    feature = "glam",
    feature = "g3",
    feature = "f32",
    feature = "f64"
))]
#[doc = include_str!("../../docs/glam.md")]
struct GlamDoctests;

/// docs/dual-numbers.md's examples, compiled and run as doctests.
#[cfg(all(doctest, feature = "std", feature = "dual", feature = "g3"))]
#[doc = include_str!("../../docs/dual-numbers.md")]
struct DualNumberDoctests;
