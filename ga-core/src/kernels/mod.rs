//! Slice kernels for G3: one call over many items, on the widest instruction set the CPU
//! has, chosen at run time.
//!
//! A single product is too small to pay for a feature check, so the per-item operations
//! are compiled for the target's baseline (SSE2 on x86-64). A slice is not: these kernels
//! check once per call and run a copy of the loop compiled with AVX2 and FMA, or with
//! AVX-512, where the CPU has them. Each copy is the same per-item code (the generated
//! products and sandwiches), so the copies agree with the one-item operations up to the
//! rounding of fused multiply-adds.
//!
//! ```
//! use ga_core::f64::g3::*;
//! use ga_core::kernels;
//!
//! let r = (Bivector::E12 * (-std::f64::consts::FRAC_PI_4)).exp();
//! let xs = [Vector::E1, Vector::E2];
//! let mut out = [Vector::ZERO; 2];
//! kernels::f64::sandwich_all(r, &xs, &mut out)?;
//! assert!((out[0] - Vector::E2).norm() < 1e-15);
//! # Ok::<(), kernels::LengthMismatch>(())
//! ```

/// The output slice's length differs from an input's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LengthMismatch {
    /// The input's length.
    pub input: usize,
    /// The output's (or the second input's) length.
    pub other: usize,
}

impl core::fmt::Display for LengthMismatch {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "slice lengths differ: {} input items against {}; every slice of a kernel call must have the same length",
            self.input, self.other
        )
    }
}

impl std::error::Error for LengthMismatch {}

fn same_length(input: usize, other: usize) -> Result<(), LengthMismatch> {
    if input == other {
        Ok(())
    } else {
        Err(LengthMismatch { input, other })
    }
}

/// The instruction set the kernels run on here: `"avx512f"`, `"avx2+fma"` or
/// `"baseline"` (SSE2 on x86-64, the target's default elsewhere).
pub fn instruction_set() -> &'static str {
    InstructionSet::detect().name()
}

/// An instruction set a kernel has a copy for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum InstructionSet {
    /// AVX-512F (with AVX2 and FMA, which every AVX-512F CPU has).
    Avx512f,
    /// AVX2 and FMA.
    Avx2Fma,
    /// The target's baseline: SSE2 on x86-64.
    Baseline,
}

impl InstructionSet {
    /// The widest set this CPU has.
    pub fn detect() -> Self {
        [Self::Avx512f, Self::Avx2Fma]
            .into_iter()
            .find(|set| set.is_available())
            .unwrap_or(Self::Baseline)
    }

    /// Whether this CPU can run the set.
    pub fn is_available(self) -> bool {
        match self {
            #[cfg(target_arch = "x86_64")]
            Self::Avx512f => std::arch::is_x86_feature_detected!("avx512f"),
            #[cfg(target_arch = "x86_64")]
            Self::Avx2Fma => {
                std::arch::is_x86_feature_detected!("avx2")
                    && std::arch::is_x86_feature_detected!("fma")
            }
            #[cfg(not(target_arch = "x86_64"))]
            Self::Avx512f | Self::Avx2Fma => false,
            Self::Baseline => true,
        }
    }

    /// `"avx512f"`, `"avx2+fma"` or `"baseline"`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Avx512f => "avx512f",
            Self::Avx2Fma => "avx2+fma",
            Self::Baseline => "baseline",
        }
    }
}

/// Writes one kernel in three copies (AVX-512, AVX2 + FMA, baseline) and the function that
/// picks one at run time.
macro_rules! dispatched {
    (
        $(#[$doc:meta])*
        fn $name:ident($($arg:ident: $ty:ty),*) $body:block
    ) => {
        $(#[$doc])*
        #[inline]
        fn $name($($arg: $ty),*) {
            #[inline(always)]
            fn body($($arg: $ty),*) $body

            #[cfg(target_arch = "x86_64")]
            {
                #[target_feature(enable = "avx512f,avx2,fma")]
                unsafe fn avx512($($arg: $ty),*) {
                    body($($arg),*)
                }
                #[target_feature(enable = "avx2,fma")]
                unsafe fn avx2($($arg: $ty),*) {
                    body($($arg),*)
                }
                if std::arch::is_x86_feature_detected!("avx512f") {
                    // SAFETY: the CPU has AVX-512F (checked just above), and AVX2 and FMA,
                    // which every AVX-512F CPU has.
                    return unsafe { avx512($($arg),*) };
                }
                if std::arch::is_x86_feature_detected!("avx2")
                    && std::arch::is_x86_feature_detected!("fma")
                {
                    // SAFETY: the CPU has AVX2 and FMA (checked just above).
                    return unsafe { avx2($($arg),*) };
                }
            }
            body($($arg),*)
        }
    };
}

macro_rules! g3_kernels {
    ($scalar:ident) => {
        #[doc = concat!("The kernels on `ga_core::", stringify!($scalar), "::g3`.")]
        pub mod $scalar {
            use super::{same_length, InstructionSet, LengthMismatch};
            use crate::$scalar::g3::{Rotor, Sandwich, Vector};

            /// `out[i] = r x[i] ~r` for every `i`: one rotor on many vectors, its matrix
            /// built once. With AVX2 and FMA each vector is three broadcast loads and
            /// three fused multiply-adds against the matrix's columns, so the results may
            /// differ from [`Sandwich::sandwich`] in the last bit.
            ///
            /// # Errors
            /// [`LengthMismatch`] when `out` and `x` differ in length (nothing is written).
            pub fn sandwich_all(
                r: Rotor,
                x: &[Vector],
                out: &mut [Vector],
            ) -> Result<(), LengthMismatch> {
                same_length(x.len(), out.len())?;
                let m = r.sandwich_matrix();
                #[cfg(target_arch = "x86_64")]
                {
                    if std::arch::is_x86_feature_detected!("avx2")
                        && std::arch::is_x86_feature_detected!("fma")
                    {
                        // SAFETY: the CPU has AVX2 and FMA (checked just above), and the
                        // lengths are equal (checked above).
                        unsafe { super::x86::$scalar::apply_matrix(m, x, out) };
                        return Ok(());
                    }
                }
                for (slot, v) in out.iter_mut().zip(x) {
                    *slot = apply(&m, v);
                }
                Ok(())
            }

            /// `m v`.
            #[inline(always)]
            pub(super) fn apply(m: &[[$scalar; 3]; 3], v: &Vector) -> Vector {
                Vector::new(
                    m[0][0] * v.e1 + m[0][1] * v.e2 + m[0][2] * v.e3,
                    m[1][0] * v.e1 + m[1][1] * v.e2 + m[1][2] * v.e3,
                    m[2][0] * v.e1 + m[2][1] * v.e2 + m[2][2] * v.e3,
                )
            }

            /// `out[i] = a[i] b[i]` for every `i`, bit for bit what `a[i] * b[i]` gives
            /// (signed zeros included; where an input holds a NaN, the same components
            /// are NaN, with sign and payload not promised).
            /// With AVX2 (AVX-512) the rotors are taken 8 (16) at a time for `f32`, 4
            /// (8) for `f64`, transposed into one register per component, multiplied
            /// with the one-item product's operations in its order, and transposed back.
            ///
            /// # Errors
            /// [`LengthMismatch`] when the three slices differ in length (nothing is
            /// written).
            pub fn mul_pairs(
                a: &[Rotor],
                b: &[Rotor],
                out: &mut [Rotor],
            ) -> Result<(), LengthMismatch> {
                mul_pairs_on(InstructionSet::detect(), a, b, out).map(|_| ())
            }

            /// [`mul_pairs`] on the instruction set `set`, or on the baseline where this
            /// CPU lacks it; returns the set that ran. For comparing the copies (they
            /// agree bit for bit) and for timing each.
            ///
            /// # Errors
            /// [`LengthMismatch`] when the three slices differ in length (nothing is
            /// written).
            pub fn mul_pairs_on(
                set: InstructionSet,
                a: &[Rotor],
                b: &[Rotor],
                out: &mut [Rotor],
            ) -> Result<InstructionSet, LengthMismatch> {
                same_length(a.len(), b.len())?;
                same_length(a.len(), out.len())?;
                #[cfg(target_arch = "x86_64")]
                {
                    if set == InstructionSet::Avx512f && set.is_available() {
                        // SAFETY: the CPU has AVX-512F (checked just above); the
                        // lengths are equal (checked above).
                        return Ok(unsafe { super::x86::$scalar::mul_pairs_avx512(a, b, out) });
                    }
                    if set == InstructionSet::Avx2Fma && set.is_available() {
                        // SAFETY: the CPU has AVX2 (checked just above); the lengths
                        // are equal (checked above).
                        return Ok(unsafe { super::x86::$scalar::mul_pairs_avx2(a, b, out) });
                    }
                }
                let _ = set;
                mul_items(a, b, out);
                Ok(InstructionSet::Baseline)
            }

            /// `out[i] = a[i] b[i]` one item at a time (the kernels' tails, and the
            /// baseline).
            #[inline(always)]
            pub(super) fn mul_items(a: &[Rotor], b: &[Rotor], out: &mut [Rotor]) {
                for ((slot, &p), &q) in out.iter_mut().zip(a).zip(b) {
                    *slot = p * q;
                }
            }

            /// `out[i] = r[i] x[i] ~r[i]` for every `i` (exact for any rotor, as
            /// [`Sandwich::sandwich`]).
            ///
            /// # Errors
            /// [`LengthMismatch`] when the three slices differ in length (nothing is
            /// written).
            pub fn sandwich_pairs(
                r: &[Rotor],
                x: &[Vector],
                out: &mut [Vector],
            ) -> Result<(), LengthMismatch> {
                same_length(r.len(), x.len())?;
                same_length(r.len(), out.len())?;
                sandwich_checked(r, x, out);
                Ok(())
            }

            dispatched! {
                /// `out[i] = r[i] x[i] ~r[i]`, the lengths already checked.
                fn sandwich_checked(r: &[Rotor], x: &[Vector], out: &mut [Vector]) {
                    for ((slot, &q), &v) in out.iter_mut().zip(r).zip(x) {
                        *slot = q.sandwich(v);
                    }
                }
            }
        }
    };
}

#[cfg(feature = "f32")]
g3_kernels!(f32);
#[cfg(feature = "f64")]
g3_kernels!(f64);

#[cfg(target_arch = "x86_64")]
mod x86;
