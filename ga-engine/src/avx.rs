//! Eight `f32` lanes in one AVX register, for the slice form on x86-64 CPUs with AVX.
//!
//! The slice form is bound by the chain of its three dependent turns, not by its
//! instruction count: a group of four in SSE takes about as long as one body's chain
//! (BENCHMARKS.md, issue 19). A group of eight in one 256-bit register runs the same
//! chain for twice the bodies. Every lane operation is one AVX instruction and the IEEE
//! operation the scalar does (`vaddps` rounds each lane as `addss` does; no FMA), so
//! each body gets the bits it gets alone, with or without AVX.
//!
//! The code is generic (`splitting.rs` over [`Real`]) and inlined into
//! `dispatch.rs`'s `step_all_avx`, the one function compiled for AVX; the CPU is checked
//! before it is called.

use core::arch::x86_64::{
    __m128, __m256, _mm256_add_ps, _mm256_and_ps, _mm256_andnot_ps, _mm256_castps256_ps128,
    _mm256_cmp_ps, _mm256_div_ps, _mm256_extractf128_ps, _mm256_max_ps, _mm256_min_ps,
    _mm256_movemask_ps, _mm256_mul_ps, _mm256_or_ps, _mm256_set1_ps, _mm256_set_m128,
    _mm256_shuffle_ps, _mm256_sqrt_ps, _mm256_sub_ps, _mm256_unpackhi_ps, _mm256_unpacklo_ps,
    _mm256_xor_ps, _mm_setr_ps, _CMP_LT_OQ,
};
use core::ops::{Add, Div, Mul, Neg, Sub};

use super::real::{Group, Real};

/// Eight `f32` stepped side by side.
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub(crate) struct F32x8(__m256);

/// A lane mask: all ones where true.
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub(crate) struct Mask8(__m256);

macro_rules! avx_op {
    ($trait:ident, $method:ident, $intrinsic:ident) => {
        impl $trait for F32x8 {
            type Output = Self;
            #[inline(always)]
            fn $method(self, other: Self) -> Self {
                // SAFETY: only reached from `dispatch.rs`'s `step_all_avx`, compiled for
                // AVX and called on a CPU that has it.
                F32x8(unsafe { $intrinsic(self.0, other.0) })
            }
        }
    };
}
avx_op!(Add, add, _mm256_add_ps);
avx_op!(Sub, sub, _mm256_sub_ps);
avx_op!(Mul, mul, _mm256_mul_ps);
avx_op!(Div, div, _mm256_div_ps);

impl Neg for F32x8 {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        // SAFETY: as for the arithmetic above. Flips the sign bit, as the scalar's `-`.
        F32x8(unsafe { _mm256_xor_ps(self.0, _mm256_set1_ps(-0.0)) })
    }
}

impl Real for F32x8 {
    type Mask = Mask8;
    const EPSILON: f64 = f32::EPSILON as f64;
    #[inline(always)]
    fn splat(x: f64) -> Self {
        // SAFETY: as for the arithmetic above.
        F32x8(unsafe { _mm256_set1_ps(x as f32) })
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        // SAFETY: as for the arithmetic above.
        F32x8(unsafe { _mm256_sqrt_ps(self.0) })
    }
    #[inline(always)]
    fn lt(self, other: Self) -> Mask8 {
        // SAFETY: as for the arithmetic above. Ordered, quiet: false where either is
        // NaN, as the scalar `<`.
        Mask8(unsafe { _mm256_cmp_ps::<_CMP_LT_OQ>(self.0, other.0) })
    }
    #[inline(always)]
    fn select(mask: Mask8, yes: Self, no: Self) -> Self {
        // SAFETY: as for the arithmetic above.
        F32x8(unsafe { _mm256_or_ps(_mm256_and_ps(mask.0, yes.0), _mm256_andnot_ps(mask.0, no.0)) })
    }
    #[inline(always)]
    fn any(mask: Mask8) -> bool {
        // SAFETY: as for the arithmetic above.
        unsafe { _mm256_movemask_ps(mask.0) != 0 }
    }
    #[inline(always)]
    fn and(a: Mask8, b: Mask8) -> Mask8 {
        // SAFETY: as for the arithmetic above.
        Mask8(unsafe { _mm256_and_ps(a.0, b.0) })
    }
    #[inline(always)]
    fn all(mask: Mask8) -> bool {
        // SAFETY: as for the arithmetic above.
        unsafe { _mm256_movemask_ps(mask.0) == 0xff }
    }
    #[inline(always)]
    fn min_or(self, other: Self) -> Self {
        // SAFETY: as for the arithmetic above. `vminps a, b` is `a < b ? a : b` in each
        // lane, NaN included: the default's select in one instruction, which LLVM does
        // not fold the and/andnot/or form back into.
        F32x8(unsafe { _mm256_min_ps(self.0, other.0) })
    }
    #[inline(always)]
    fn max_or(self, other: Self) -> Self {
        // SAFETY: as in `min_or`; `vmaxps a, b` is `a > b ? a : b`.
        F32x8(unsafe { _mm256_max_ps(self.0, other.0) })
    }
}

impl Group<f32, 8> for F32x8 {
    #[inline(always)]
    fn pack(x: [f32; 8]) -> Self {
        // SAFETY: `[f32; 8]` and `__m256` are both 32 bytes, and every bit pattern is a
        // valid value of either.
        F32x8(unsafe { core::mem::transmute::<[f32; 8], __m256>(x) })
    }
    #[inline(always)]
    fn pack_mask(m: [bool; 8]) -> Mask8 {
        let bits = m.map(|b| if b { u32::MAX } else { 0 });
        // SAFETY: as in `pack`, for `[u32; 8]`.
        Mask8(unsafe { core::mem::transmute::<[u32; 8], __m256>(bits) })
    }
    #[inline(always)]
    fn unpack(self) -> [f32; 8] {
        // SAFETY: as in `pack`.
        unsafe { core::mem::transmute::<__m256, [f32; 8]>(self.0) }
    }

    // Inlined only when optimised (see "Unoptimised builds" in `splitting.rs`).
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn columns(rows: [[f32; 4]; 8]) -> [Self; 4] {
        // Rows `i` and `i + 4` in the two halves of one register (each row one load
        // where its values lie side by side), then a 4 x 4 transpose within each half:
        // twelve shuffles for four columns, where filling lane by lane takes seven each.
        // SAFETY: the caller has AVX (`F32x8` is stepped only inside `step_all_avx` and
        // `step_blocks_avx`, which enable it).
        unsafe {
            let row = |i: usize| _mm_setr_ps(rows[i][0], rows[i][1], rows[i][2], rows[i][3]);
            let pair = |i: usize| _mm256_set_m128(row(i + 4), row(i));
            let (r0, r1, r2, r3) = (pair(0), pair(1), pair(2), pair(3));
            // Per half: (r0_0, r1_0, r0_1, r1_1) and (r2_0, r3_0, r2_1, r3_1), then the
            // same of values 2 and 3; each column takes two values from each.
            let (t0, t1) = (_mm256_unpacklo_ps(r0, r1), _mm256_unpacklo_ps(r2, r3));
            let (t2, t3) = (_mm256_unpackhi_ps(r0, r1), _mm256_unpackhi_ps(r2, r3));
            [
                F32x8(_mm256_shuffle_ps::<0b01_00_01_00>(t0, t1)),
                F32x8(_mm256_shuffle_ps::<0b11_10_11_10>(t0, t1)),
                F32x8(_mm256_shuffle_ps::<0b01_00_01_00>(t2, t3)),
                F32x8(_mm256_shuffle_ps::<0b11_10_11_10>(t2, t3)),
            ]
        }
    }

    // Inlined only when optimised (see "Unoptimised builds" in `splitting.rs`).
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn rows(columns: [Self; 4]) -> [[f32; 4]; 8] {
        // The same transpose within each half (it is its own inverse) gives rows `i` and
        // `i + 4` in the halves of register `i`.
        // SAFETY: as for `columns`.
        unsafe {
            let [c0, c1, c2, c3] = columns.map(|c| c.0);
            let (t0, t1) = (_mm256_unpacklo_ps(c0, c1), _mm256_unpacklo_ps(c2, c3));
            let (t2, t3) = (_mm256_unpackhi_ps(c0, c1), _mm256_unpackhi_ps(c2, c3));
            let pairs = [
                _mm256_shuffle_ps::<0b01_00_01_00>(t0, t1),
                _mm256_shuffle_ps::<0b11_10_11_10>(t0, t1),
                _mm256_shuffle_ps::<0b01_00_01_00>(t2, t3),
                _mm256_shuffle_ps::<0b11_10_11_10>(t2, t3),
            ];
            let row = |r: __m128| core::mem::transmute::<__m128, [f32; 4]>(r);
            core::array::from_fn(|i| {
                let pair = pairs[i % 4];
                if i < 4 {
                    row(_mm256_castps256_ps128(pair))
                } else {
                    row(_mm256_extractf128_ps::<1>(pair))
                }
            })
        }
    }
}
