//! Two `f64` lanes in one SSE2 register, for the f64 slice form on x86-64 CPUs without
//! AVX (`avx64.rs` takes four where the CPU has it).
//!
//! In arrays of four (`Lanes<f64, 4>`), the slice step, where each lane is read from its
//! own body, had LLVM step part of the lanes with scalar instructions: the slice took
//! longer than one body at a time (BENCHMARKS.md). Here every lane operation is one SSE2
//! instruction and the IEEE operation the scalar does (`addpd` rounds each lane as `addsd`
//! does), so each body gets the bits it gets alone. SSE2 is part of x86-64: no check.

use core::arch::x86_64::{
    __m128d, _mm_add_pd, _mm_and_pd, _mm_andnot_pd, _mm_cmplt_pd, _mm_div_pd, _mm_loadu_pd,
    _mm_max_pd, _mm_min_pd, _mm_movemask_pd, _mm_mul_pd, _mm_or_pd, _mm_set1_pd, _mm_sqrt_pd,
    _mm_storeu_pd, _mm_sub_pd, _mm_unpackhi_pd, _mm_unpacklo_pd, _mm_xor_pd,
};
use core::ops::{Add, Div, Mul, Neg, Sub};

use super::real::{Group, Real};

/// Two `f64` stepped side by side.
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub(crate) struct F64x2(__m128d);

/// A lane mask: all ones where true.
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub(crate) struct MaskD2(__m128d);

macro_rules! sse_op {
    ($trait:ident, $method:ident, $intrinsic:ident) => {
        impl $trait for F64x2 {
            type Output = Self;
            #[inline(always)]
            fn $method(self, other: Self) -> Self {
                // SAFETY: SSE2 is part of x86-64.
                F64x2(unsafe { $intrinsic(self.0, other.0) })
            }
        }
    };
}
sse_op!(Add, add, _mm_add_pd);
sse_op!(Sub, sub, _mm_sub_pd);
sse_op!(Mul, mul, _mm_mul_pd);
sse_op!(Div, div, _mm_div_pd);

impl Neg for F64x2 {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        // SAFETY: SSE2 is part of x86-64. Flips the sign bit, as the scalar's `-`.
        F64x2(unsafe { _mm_xor_pd(self.0, _mm_set1_pd(-0.0)) })
    }
}

impl Real for F64x2 {
    type Mask = MaskD2;
    const EPSILON: f64 = f64::EPSILON;
    #[inline(always)]
    fn splat(x: f64) -> Self {
        // SAFETY: SSE2 is part of x86-64.
        F64x2(unsafe { _mm_set1_pd(x) })
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        // SAFETY: SSE2 is part of x86-64. Correctly rounded, as `sqrtsd`.
        F64x2(unsafe { _mm_sqrt_pd(self.0) })
    }
    #[inline(always)]
    fn lt(self, other: Self) -> MaskD2 {
        // SAFETY: SSE2 is part of x86-64. `cmpltpd` is ordered: false where either is
        // NaN, as the scalar `<`.
        MaskD2(unsafe { _mm_cmplt_pd(self.0, other.0) })
    }
    #[inline(always)]
    fn select(mask: MaskD2, yes: Self, no: Self) -> Self {
        // SAFETY: SSE2 is part of x86-64.
        F64x2(unsafe { _mm_or_pd(_mm_and_pd(mask.0, yes.0), _mm_andnot_pd(mask.0, no.0)) })
    }
    #[inline(always)]
    fn any(mask: MaskD2) -> bool {
        // SAFETY: SSE2 is part of x86-64.
        unsafe { _mm_movemask_pd(mask.0) != 0 }
    }
    #[inline(always)]
    fn and(a: MaskD2, b: MaskD2) -> MaskD2 {
        // SAFETY: SSE2 is part of x86-64.
        MaskD2(unsafe { _mm_and_pd(a.0, b.0) })
    }
    #[inline(always)]
    fn all(mask: MaskD2) -> bool {
        // SAFETY: SSE2 is part of x86-64.
        unsafe { _mm_movemask_pd(mask.0) == 0b11 }
    }
    #[inline(always)]
    fn min_or(self, other: Self) -> Self {
        // SAFETY: SSE2 is part of x86-64. `minpd a, b` is `a < b ? a : b` in each lane,
        // NaN included (the default's select in one instruction).
        F64x2(unsafe { _mm_min_pd(self.0, other.0) })
    }
    #[inline(always)]
    fn max_or(self, other: Self) -> Self {
        // SAFETY: as in `min_or`; `maxpd a, b` is `a > b ? a : b`.
        F64x2(unsafe { _mm_max_pd(self.0, other.0) })
    }
}

impl Group<f64, 2> for F64x2 {
    #[inline(always)]
    fn pack(x: [f64; 2]) -> Self {
        // SAFETY: SSE2 is part of x86-64; `x` holds two f64.
        F64x2(unsafe { _mm_loadu_pd(x.as_ptr()) })
    }
    #[inline(always)]
    fn pack_mask(m: [bool; 2]) -> MaskD2 {
        let bit = |i: usize| if m[i] { u64::MAX } else { 0 };
        // SAFETY: `[u64; 2]` and `__m128d` are both 16 bytes, and every bit pattern is a
        // valid value of either.
        MaskD2(unsafe { core::mem::transmute::<[u64; 2], __m128d>([bit(0), bit(1)]) })
    }
    #[inline(always)]
    fn unpack(self) -> [f64; 2] {
        let mut out = [0.0; 2];
        // SAFETY: SSE2 is part of x86-64; `out` holds two f64.
        unsafe { _mm_storeu_pd(out.as_mut_ptr(), self.0) };
        out
    }

    // Inlined only when optimised (see "Unoptimised builds" in `splitting.rs`).
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn columns(rows: [[f64; 4]; 2]) -> [Self; 4] {
        // Each row two registers (values 0-1 and 2-3), then column `k` from the two rows'
        // halves: four shuffles for four columns.
        // SAFETY: SSE2 is part of x86-64; each row holds four f64.
        unsafe {
            let (a, b) = (rows[0].as_ptr(), rows[1].as_ptr());
            let (a01, a23) = (_mm_loadu_pd(a), _mm_loadu_pd(a.add(2)));
            let (b01, b23) = (_mm_loadu_pd(b), _mm_loadu_pd(b.add(2)));
            [
                F64x2(_mm_unpacklo_pd(a01, b01)),
                F64x2(_mm_unpackhi_pd(a01, b01)),
                F64x2(_mm_unpacklo_pd(a23, b23)),
                F64x2(_mm_unpackhi_pd(a23, b23)),
            ]
        }
    }

    // Inlined only when optimised (see "Unoptimised builds" in `splitting.rs`).
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn rows(columns: [Self; 4]) -> [[f64; 4]; 2] {
        // SAFETY: SSE2 is part of x86-64; each row holds four f64.
        unsafe {
            let [c0, c1, c2, c3] = columns;
            let mut rows = [[0.0; 4]; 2];
            let (a, b) = rows.split_at_mut(1);
            let (a, b) = (a[0].as_mut_ptr(), b[0].as_mut_ptr());
            _mm_storeu_pd(a, _mm_unpacklo_pd(c0.0, c1.0));
            _mm_storeu_pd(a.add(2), _mm_unpacklo_pd(c2.0, c3.0));
            _mm_storeu_pd(b, _mm_unpackhi_pd(c0.0, c1.0));
            _mm_storeu_pd(b.add(2), _mm_unpackhi_pd(c2.0, c3.0));
            rows
        }
    }
}
