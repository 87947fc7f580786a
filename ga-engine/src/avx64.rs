//! Four `f64` lanes in one AVX register, for the f64 slice form on x86-64 CPUs with AVX.
//!
//! Without it, the f64 slice form keeps its lanes in arrays (`Lanes<f64, 4>`, two SSE
//! registers a value), and in the slice step, where each lane is read from its own body,
//! LLVM stepped part of the lanes with scalar instructions and joined them with shuffles:
//! 1559 instructions a group of four against 849 for the same step on bodies kept column
//! by column (BENCHMARKS.md). Here every lane operation is one AVX instruction and the IEEE
//! operation the scalar does (`vaddpd` rounds each lane as `addsd` does; no FMA), so each
//! body gets the bits it gets alone, with or without AVX.
//!
//! As for `avx.rs`, the code is generic and inlined into the functions of `dispatch.rs`
//! compiled for AVX; the CPU is checked before they are called.

use core::arch::x86_64::{
    __m256d, _mm256_add_pd, _mm256_and_pd, _mm256_andnot_pd, _mm256_cmp_pd, _mm256_div_pd,
    _mm256_max_pd, _mm256_min_pd, _mm256_movemask_pd, _mm256_mul_pd, _mm256_or_pd,
    _mm256_permute2f128_pd, _mm256_set1_pd, _mm256_setr_pd, _mm256_sqrt_pd, _mm256_sub_pd,
    _mm256_unpackhi_pd, _mm256_unpacklo_pd, _mm256_xor_pd, _CMP_LT_OQ,
};
use core::ops::{Add, Div, Mul, Neg, Sub};

use super::real::{Group, Real};

/// Four `f64` stepped side by side.
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub(crate) struct F64x4(__m256d);

/// A lane mask: all ones where true.
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub(crate) struct MaskD4(__m256d);

macro_rules! avx_op {
    ($trait:ident, $method:ident, $intrinsic:ident) => {
        impl $trait for F64x4 {
            type Output = Self;
            #[inline(always)]
            fn $method(self, other: Self) -> Self {
                // SAFETY: only reached from `dispatch.rs`'s functions compiled for AVX,
                // called on a CPU that has it.
                F64x4(unsafe { $intrinsic(self.0, other.0) })
            }
        }
    };
}
avx_op!(Add, add, _mm256_add_pd);
avx_op!(Sub, sub, _mm256_sub_pd);
avx_op!(Mul, mul, _mm256_mul_pd);
avx_op!(Div, div, _mm256_div_pd);

impl Neg for F64x4 {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        // SAFETY: as for the arithmetic above. Flips the sign bit, as the scalar's `-`.
        F64x4(unsafe { _mm256_xor_pd(self.0, _mm256_set1_pd(-0.0)) })
    }
}

impl Real for F64x4 {
    type Mask = MaskD4;
    const EPSILON: f64 = f64::EPSILON;
    #[inline(always)]
    fn splat(x: f64) -> Self {
        // SAFETY: as for the arithmetic above.
        F64x4(unsafe { _mm256_set1_pd(x) })
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        // SAFETY: as for the arithmetic above. Correctly rounded, as `sqrtsd`.
        F64x4(unsafe { _mm256_sqrt_pd(self.0) })
    }
    #[inline(always)]
    fn lt(self, other: Self) -> MaskD4 {
        // SAFETY: as for the arithmetic above. Ordered, quiet: false where either is
        // NaN, as the scalar `<`.
        MaskD4(unsafe { _mm256_cmp_pd::<_CMP_LT_OQ>(self.0, other.0) })
    }
    #[inline(always)]
    fn select(mask: MaskD4, yes: Self, no: Self) -> Self {
        // SAFETY: as for the arithmetic above.
        F64x4(unsafe { _mm256_or_pd(_mm256_and_pd(mask.0, yes.0), _mm256_andnot_pd(mask.0, no.0)) })
    }
    #[inline(always)]
    fn any(mask: MaskD4) -> bool {
        // SAFETY: as for the arithmetic above.
        unsafe { _mm256_movemask_pd(mask.0) != 0 }
    }
    #[inline(always)]
    fn and(a: MaskD4, b: MaskD4) -> MaskD4 {
        // SAFETY: as for the arithmetic above.
        MaskD4(unsafe { _mm256_and_pd(a.0, b.0) })
    }
    #[inline(always)]
    fn all(mask: MaskD4) -> bool {
        // SAFETY: as for the arithmetic above.
        unsafe { _mm256_movemask_pd(mask.0) == 0xf }
    }
    #[inline(always)]
    fn min_or(self, other: Self) -> Self {
        // SAFETY: as for the arithmetic above. `vminpd a, b` is `a < b ? a : b` in each
        // lane, NaN included (the default's select in one instruction).
        F64x4(unsafe { _mm256_min_pd(self.0, other.0) })
    }
    #[inline(always)]
    fn max_or(self, other: Self) -> Self {
        // SAFETY: as in `min_or`; `vmaxpd a, b` is `a > b ? a : b`.
        F64x4(unsafe { _mm256_max_pd(self.0, other.0) })
    }
}

/// The 4 x 4 transpose of four registers (its own inverse): pairs of values by
/// unpacking, then the 128-bit halves crossed.
///
/// # Safety
/// The CPU must have AVX.
#[inline(always)]
unsafe fn transpose(r: [__m256d; 4]) -> [__m256d; 4] {
    // (r0_0, r1_0, r0_2, r1_2), (r0_1, r1_1, r0_3, r1_3), and the same of rows 2 and 3.
    let (t0, t1) = (
        _mm256_unpacklo_pd(r[0], r[1]),
        _mm256_unpackhi_pd(r[0], r[1]),
    );
    let (t2, t3) = (
        _mm256_unpacklo_pd(r[2], r[3]),
        _mm256_unpackhi_pd(r[2], r[3]),
    );
    [
        _mm256_permute2f128_pd::<0x20>(t0, t2),
        _mm256_permute2f128_pd::<0x20>(t1, t3),
        _mm256_permute2f128_pd::<0x31>(t0, t2),
        _mm256_permute2f128_pd::<0x31>(t1, t3),
    ]
}

impl Group<f64, 4> for F64x4 {
    #[inline(always)]
    fn pack(x: [f64; 4]) -> Self {
        // SAFETY: `[f64; 4]` and `__m256d` are both 32 bytes, and every bit pattern is a
        // valid value of either.
        F64x4(unsafe { core::mem::transmute::<[f64; 4], __m256d>(x) })
    }
    #[inline(always)]
    fn pack_mask(m: [bool; 4]) -> MaskD4 {
        // Indexed, not `array::map` (which LLVM may leave out of line in the slice step).
        let bit = |i: usize| if m[i] { u64::MAX } else { 0 };
        let bits = [bit(0), bit(1), bit(2), bit(3)];
        // SAFETY: as in `pack`, for `[u64; 4]`.
        MaskD4(unsafe { core::mem::transmute::<[u64; 4], __m256d>(bits) })
    }
    #[inline(always)]
    fn unpack(self) -> [f64; 4] {
        // SAFETY: as in `pack`.
        unsafe { core::mem::transmute::<__m256d, [f64; 4]>(self.0) }
    }

    // Inlined only when optimised (see "Unoptimised builds" in `splitting.rs`).
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn columns(rows: [[f64; 4]; 4]) -> [Self; 4] {
        // Each row one register (one load where its values lie side by side), then a
        // transpose: eight shuffles for four columns.
        // SAFETY: the caller has AVX (`F64x4` is stepped only inside the functions of
        // `dispatch.rs` that enable it).
        unsafe {
            let row = |i: usize| _mm256_setr_pd(rows[i][0], rows[i][1], rows[i][2], rows[i][3]);
            let [c0, c1, c2, c3] = transpose([row(0), row(1), row(2), row(3)]);
            [F64x4(c0), F64x4(c1), F64x4(c2), F64x4(c3)]
        }
    }

    // Inlined only when optimised (see "Unoptimised builds" in `splitting.rs`).
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn rows(columns: [Self; 4]) -> [[f64; 4]; 4] {
        // SAFETY: as for `columns`; the transpose is its own inverse.
        unsafe {
            let [c0, c1, c2, c3] = columns;
            let [r0, r1, r2, r3] = transpose([c0.0, c1.0, c2.0, c3.0]);
            let row = |r: __m256d| core::mem::transmute::<__m256d, [f64; 4]>(r);
            [row(r0), row(r1), row(r2), row(r3)]
        }
    }
}
