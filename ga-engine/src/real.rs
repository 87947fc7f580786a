//! The arithmetic the steps are written in, once for a scalar and once for lanes.
//!
//! Every step is generic over [`Real`], implemented for `f32`, `f64` and [`Lanes`] of
//! either. A lane does exactly the operations the scalar does, in the same order (IEEE
//! `+ - * /` and `sqrt`, each correctly rounded; no fused multiply-add: Rust never
//! contracts `a * b + c`), so a body stepped in a slice of lanes gets the bits it gets
//! alone, whatever the vector width the compiler picks.

use core::ops::{Add, Div, Mul, Neg, Sub};

/// A float or a fixed group of floats stepped together.
pub(crate) trait Real:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// One truth value per lane.
    type Mask: Copy + core::fmt::Debug;
    /// The precision's machine epsilon (the gap between 1 and the next float), in f64.
    const EPSILON: f64;
    /// `x` rounded to this precision (constants are written in f64).
    fn splat(x: f64) -> Self;
    /// The correctly rounded square root.
    fn sqrt(self) -> Self;
    /// `self < other`, per lane.
    fn lt(self, other: Self) -> Self::Mask;
    /// `yes` where `mask` holds, `no` elsewhere.
    fn select(mask: Self::Mask, yes: Self, no: Self) -> Self;
    /// Whether `mask` holds in some lane.
    fn any(mask: Self::Mask) -> bool;
    /// Whether `mask` holds in every lane.
    fn all(mask: Self::Mask) -> bool;
    /// Both masks, per lane.
    fn and(a: Self::Mask, b: Self::Mask) -> Self::Mask;
    /// `self`, unchanged, where the optimiser cannot look into it (a scalar's chain
    /// kept scalar, see `hidden`; lanes are already vectors).
    #[inline(always)]
    fn opaque(self) -> Self {
        self
    }
    /// `self` where `self < other`, else `other` (so `other` where `self` is NaN).
    #[inline(always)]
    fn min_or(self, other: Self) -> Self {
        Self::select(self.lt(other), self, other)
    }
    /// `self` where `other < self`, else `other` (so `other` where `self` is NaN).
    #[inline(always)]
    fn max_or(self, other: Self) -> Self {
        Self::select(other.lt(self), self, other)
    }
}

macro_rules! scalar_real {
    ($t:ty, $sqrt:path, $hidden:path) => {
        impl Real for $t {
            type Mask = bool;
            const EPSILON: f64 = <$t>::EPSILON as f64;
            #[inline(always)]
            fn splat(x: f64) -> Self {
                x as $t
            }
            #[inline(always)]
            fn sqrt(self) -> Self {
                $sqrt(self)
            }
            #[inline(always)]
            fn lt(self, other: Self) -> bool {
                self < other
            }
            #[inline(always)]
            fn select(mask: bool, yes: Self, no: Self) -> Self {
                if mask {
                    yes
                } else {
                    no
                }
            }
            #[inline(always)]
            fn any(mask: bool) -> bool {
                mask
            }
            #[inline(always)]
            fn all(mask: bool) -> bool {
                mask
            }
            #[inline(always)]
            fn and(a: bool, b: bool) -> bool {
                a & b
            }
            #[inline(always)]
            fn opaque(self) -> Self {
                $hidden(self)
            }
        }
    };
}

/// f32's square root: the instruction with `std`, libm's (also correctly rounded) without.
#[inline(always)]
fn sqrt32(x: f32) -> f32 {
    #[cfg(feature = "std")]
    {
        x.sqrt()
    }
    #[cfg(not(feature = "std"))]
    {
        libm::sqrtf(x)
    }
}

/// f64's square root, likewise.
#[inline(always)]
fn sqrt64(x: f64) -> f64 {
    #[cfg(feature = "std")]
    {
        x.sqrt()
    }
    #[cfg(not(feature = "std"))]
    {
        libm::sqrt(x)
    }
}

/// `x`, unchanged, hidden from the optimiser by an empty `asm!` on x86-64: no instruction
/// is emitted, but LLVM's SLP vectoriser can no longer pack the one-body step's scalar
/// chain (a turn's `t`, norm, numerators) into vectors with shuffles, which lengthened
/// that chain (BENCHMARKS.md, issue 19). Elsewhere, `x` as it is.
macro_rules! hidden {
    ($name:ident, $t:ty) => {
        #[inline(always)]
        fn $name(x: $t) -> $t {
            #[cfg(target_arch = "x86_64")]
            {
                let mut x = x;
                // SAFETY: an empty template (a comment naming the register): it reads
                // and writes nothing but `x`'s register, and leaves it as it was.
                unsafe {
                    core::arch::asm!(
                        "/* {0} */",
                        inout(xmm_reg) x,
                        options(pure, nomem, nostack, preserves_flags)
                    );
                }
                x
            }
            #[cfg(not(target_arch = "x86_64"))]
            {
                x
            }
        }
    };
}
hidden!(hidden32, f32);
hidden!(hidden64, f64);

scalar_real!(f32, sqrt32, hidden32);
scalar_real!(f64, sqrt64, hidden64);

/// `N` floats stepped side by side, each exactly as the scalar would be. Its operations
/// are inlined only when optimised: unoptimised, each inlined operation's loop keeps its
/// iterators in the caller's frame, and the slice form's free flow needed over 100 KiB
/// (see "Unoptimised builds" in `splitting.rs`).
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(transparent)]
pub(crate) struct Lanes<T, const N: usize>(pub(crate) [T; N]);

macro_rules! lane_op {
    ($trait:ident, $method:ident, $op:tt) => {
        impl<T: Real, const N: usize> $trait for Lanes<T, N> {
            type Output = Self;
            #[cfg_attr(not(debug_assertions), inline(always))]
            #[cfg_attr(debug_assertions, inline)]
            fn $method(self, other: Self) -> Self {
                let mut out = self.0;
                for (o, b) in out.iter_mut().zip(other.0) {
                    *o = *o $op b;
                }
                Lanes(out)
            }
        }
    };
}
lane_op!(Add, add, +);
lane_op!(Sub, sub, -);
lane_op!(Mul, mul, *);
lane_op!(Div, div, /);

impl<T: Real, const N: usize> Neg for Lanes<T, N> {
    type Output = Self;
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn neg(self) -> Self {
        // A loop, as the other lane operations: `array::map` was left out of line in the
        // f64 slice step (a call a lane vector, its lanes through memory).
        let mut out = self.0;
        for o in &mut out {
            *o = -*o;
        }
        Lanes(out)
    }
}

impl<T: Real<Mask = bool>, const N: usize> Real for Lanes<T, N> {
    type Mask = [bool; N];
    const EPSILON: f64 = T::EPSILON;
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn splat(x: f64) -> Self {
        Lanes([T::splat(x); N])
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn sqrt(self) -> Self {
        // A loop, not `array::map` (see `neg`).
        let mut out = self.0;
        for o in &mut out {
            *o = o.sqrt();
        }
        Lanes(out)
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn lt(self, other: Self) -> [bool; N] {
        let mut m = [false; N];
        for ((m, a), b) in m.iter_mut().zip(self.0).zip(other.0) {
            *m = a.lt(b);
        }
        m
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn select(mask: [bool; N], yes: Self, no: Self) -> Self {
        let mut out = no.0;
        for ((o, m), y) in out.iter_mut().zip(mask).zip(yes.0) {
            *o = T::select(m, y, *o);
        }
        Lanes(out)
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn any(mask: [bool; N]) -> bool {
        mask.iter().any(|&m| m)
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn all(mask: [bool; N]) -> bool {
        mask.iter().all(|&m| m)
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn and(a: [bool; N], b: [bool; N]) -> [bool; N] {
        let mut out = a;
        for (o, m) in out.iter_mut().zip(b) {
            *o &= m;
        }
        out
    }
}

/// `N` values of `T` stepped side by side as one [`Real`]: how the slice form packs a
/// group's components and unpacks the results.
pub(crate) trait Group<T, const N: usize>: Real {
    /// The lanes of an array, lane 0 first.
    fn pack(x: [T; N]) -> Self;
    /// A mask of `N` truth values.
    fn pack_mask(m: [bool; N]) -> Self::Mask;
    /// The lanes as an array, lane 0 first.
    fn unpack(self) -> [T; N];
    /// Four lane vectors from `N` rows of four values (row `i` lane `i`'s): column `k` is
    /// every row's value `k`. Lane by lane here; by transposing registers where a form
    /// has them (AVX: a row is one load where its values lie side by side in memory).
    // Inlined only when optimised (see "Unoptimised builds" in `splitting.rs`).
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn columns(rows: [[T; 4]; N]) -> [Self; 4]
    where
        T: Copy,
    {
        // Indexed, not `array::map`: that was left out of line in the f64 slice step.
        let column = |k: usize| Self::pack(core::array::from_fn(|i| rows[i][k]));
        [column(0), column(1), column(2), column(3)]
    }
    /// The inverse of [`Group::columns`]: `N` rows of four values from four lane vectors.
    // Inlined only when optimised (see "Unoptimised builds" in `splitting.rs`).
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[cfg_attr(debug_assertions, inline)]
    fn rows(columns: [Self; 4]) -> [[T; 4]; N]
    where
        T: Copy,
    {
        // Indexed, not `array::map` (see `columns`).
        let [a, b, c, d] = columns;
        let columns = [a.unpack(), b.unpack(), c.unpack(), d.unpack()];
        core::array::from_fn(|i| [columns[0][i], columns[1][i], columns[2][i], columns[3][i]])
    }
}

impl<T: Real<Mask = bool>, const N: usize> Group<T, N> for Lanes<T, N> {
    #[inline(always)]
    fn pack(x: [T; N]) -> Self {
        Lanes(x)
    }
    #[inline(always)]
    fn pack_mask(m: [bool; N]) -> [bool; N] {
        m
    }
    #[inline(always)]
    fn unpack(self) -> [T; N] {
        self.0
    }
}
