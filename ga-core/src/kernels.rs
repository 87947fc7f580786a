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
    #[cfg(target_arch = "x86_64")]
    {
        if std::arch::is_x86_feature_detected!("avx512f") {
            return "avx512f";
        }
        if std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma")
        {
            return "avx2+fma";
        }
    }
    "baseline"
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
            use super::{same_length, LengthMismatch};
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

            /// `out[i] = a[i] b[i]` for every `i`.
            ///
            /// # Errors
            /// [`LengthMismatch`] when the three slices differ in length (nothing is
            /// written).
            pub fn mul_pairs(
                a: &[Rotor],
                b: &[Rotor],
                out: &mut [Rotor],
            ) -> Result<(), LengthMismatch> {
                same_length(a.len(), b.len())?;
                same_length(a.len(), out.len())?;
                mul_checked(a, b, out);
                Ok(())
            }

            dispatched! {
                /// `out[i] = a[i] b[i]`, the lengths already checked.
                fn mul_checked(a: &[Rotor], b: &[Rotor], out: &mut [Rotor]) {
                    for ((slot, &p), &q) in out.iter_mut().zip(a).zip(b) {
                        *slot = p * q;
                    }
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

/// A matrix on many vectors with AVX2 and FMA: the matrix's columns in one register each,
/// each vector's components broadcast from memory (a load, no shuffle), two fused
/// multiply-adds, and one store of a whole register. The store is one component wider than
/// a vector; it runs ahead into the next output slot, which the next iteration overwrites,
/// and the last vector is written by the scalar code.
#[cfg(target_arch = "x86_64")]
mod x86 {
    #[cfg(feature = "f32")]
    pub mod f32 {
        use crate::f32::g3::Vector;
        use core::arch::x86_64::{
            _mm_broadcast_ss, _mm_fmadd_ps, _mm_mul_ps, _mm_set_ps, _mm_storeu_ps,
        };

        /// `out[i] = m x[i]`.
        ///
        /// # Safety
        /// The CPU has AVX2 and FMA, and `x` and `out` have the same length.
        #[target_feature(enable = "avx2,fma")]
        pub unsafe fn apply_matrix(m: [[f32; 3]; 3], x: &[Vector], out: &mut [Vector]) {
            let Some(last) = x.len().checked_sub(1) else {
                return;
            };
            let column = |c: usize| _mm_set_ps(0.0, m[2][c], m[1][c], m[0][c]);
            let (c0, c1, c2) = (column(0), column(1), column(2));
            let output = out.as_mut_ptr().cast::<f32>();
            for (i, v) in x[..last].iter().enumerate() {
                let y = _mm_fmadd_ps(
                    c2,
                    _mm_broadcast_ss(&v.e3),
                    _mm_fmadd_ps(
                        c1,
                        _mm_broadcast_ss(&v.e2),
                        _mm_mul_ps(c0, _mm_broadcast_ss(&v.e1)),
                    ),
                );
                // SAFETY: `Vector` is `#[repr(C)]` of three `f32`, so slot `i` starts at
                // float `3 i`; the four floats written are slot `i` and the first
                // component of slot `i + 1`, which exists because `i < last`.
                unsafe { _mm_storeu_ps(output.add(3 * i), y) };
            }
            out[last] = super::super::f32::apply(&m, &x[last]);
        }
    }

    #[cfg(feature = "f64")]
    pub mod f64 {
        use crate::f64::g3::Vector;
        use core::arch::x86_64::{
            _mm256_broadcast_sd, _mm256_fmadd_pd, _mm256_mul_pd, _mm256_set_pd, _mm256_storeu_pd,
        };

        /// `out[i] = m x[i]`.
        ///
        /// # Safety
        /// The CPU has AVX2 and FMA, and `x` and `out` have the same length.
        #[target_feature(enable = "avx2,fma")]
        pub unsafe fn apply_matrix(m: [[f64; 3]; 3], x: &[Vector], out: &mut [Vector]) {
            let Some(last) = x.len().checked_sub(1) else {
                return;
            };
            let column = |c: usize| _mm256_set_pd(0.0, m[2][c], m[1][c], m[0][c]);
            let (c0, c1, c2) = (column(0), column(1), column(2));
            let output = out.as_mut_ptr().cast::<f64>();
            for (i, v) in x[..last].iter().enumerate() {
                let y = _mm256_fmadd_pd(
                    c2,
                    _mm256_broadcast_sd(&v.e3),
                    _mm256_fmadd_pd(
                        c1,
                        _mm256_broadcast_sd(&v.e2),
                        _mm256_mul_pd(c0, _mm256_broadcast_sd(&v.e1)),
                    ),
                );
                // SAFETY: as for f32: slot `i` starts at double `3 i`, and the fourth
                // double written is the first component of slot `i + 1 <= last`.
                unsafe { _mm256_storeu_pd(output.add(3 * i), y) };
            }
            out[last] = super::super::f64::apply(&m, &x[last]);
        }
    }
}
