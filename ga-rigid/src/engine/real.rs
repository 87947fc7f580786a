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
    /// Round to the nearest integer, ties to even, for |x| below 2^(p-2) (p the
    /// significand's bits): adding and removing 1.5 * 2^(p-1) leaves no fraction bits.
    fn round_small(self) -> Self;
    /// pi split as `PI_HI + PI_LO` (Cody and Waite), `PI_HI` short enough that `n * PI_HI`
    /// is exact for every `n` the reduction meets in practice.
    const PI_HI: f64;
    /// The rest of pi.
    const PI_LO: f64;
    /// Taylor coefficients of `sin x / x` in powers of `x^2`, enough for a correctly
    /// rounded-ish result (under an ulp) for |x| <= pi/2 in this precision.
    const SIN: &'static [f64];
    /// Taylor coefficients of `cos x` in powers of `x^2`, likewise.
    const COS: &'static [f64];
}

/// Taylor coefficients of sin x / x: (-1)^k / (2k+1)!, k = 0..10.
const SIN_TAYLOR: [f64; 11] = [
    1.0,
    -1.0 / 6.0,
    1.0 / 120.0,
    -1.0 / 5040.0,
    1.0 / 362_880.0,
    -1.0 / 39_916_800.0,
    1.0 / 6_227_020_800.0,
    -1.0 / 1_307_674_368_000.0,
    1.0 / 355_687_428_096_000.0,
    -1.0 / 121_645_100_408_832_000.0,
    1.0 / 51_090_942_171_709_440_000.0,
];

/// Taylor coefficients of cos x: (-1)^k / (2k)!, k = 0..11.
const COS_TAYLOR: [f64; 12] = [
    1.0,
    -1.0 / 2.0,
    1.0 / 24.0,
    -1.0 / 720.0,
    1.0 / 40_320.0,
    -1.0 / 3_628_800.0,
    1.0 / 479_001_600.0,
    -1.0 / 87_178_291_200.0,
    1.0 / 20_922_789_888_000.0,
    -1.0 / 6_402_373_705_728_000.0,
    1.0 / 2_432_902_008_176_640_000.0,
    -1.0 / 1_124_000_727_777_607_680_000.0,
];

macro_rules! scalar_real {
    ($t:ty, $sqrt:path, $magic:expr, $pi_hi:expr, $pi_lo:expr, $sin_terms:expr, $cos_terms:expr) => {
        impl Real for $t {
            type Mask = bool;
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
            fn round_small(self) -> Self {
                // The compiler may not fold (x + m) - m to x: in IEEE arithmetic it is not.
                (self + $magic) - $magic
            }
            const PI_HI: f64 = $pi_hi;
            const PI_LO: f64 = $pi_lo;
            const SIN: &'static [f64] = SIN_TAYLOR.split_at($sin_terms).0;
            const COS: &'static [f64] = COS_TAYLOR.split_at($cos_terms).0;
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

// Terms: the first Taylor term left out is, at pi/2, far below half an ulp of 1
// (f32: x^15/15! = 6.7e-10 and x^16/16! = 6.5e-11 against 6e-8; f64: x^23/23! = 1.2e-18
// and x^24/24! = 8e-20 against 1.1e-16). The magic numbers are 1.5 * 2^23 and 1.5 * 2^52;
// pi's high parts have 8 and 30 significant bits (n * PI_HI exact for |n| < 2^16, 2^23).
scalar_real!(
    f32,
    sqrt32,
    12_582_912.0_f32,
    3.140_625,
    0.000_967_653_589_793_238_5,
    7,
    8
);
scalar_real!(
    f64,
    sqrt64,
    6_755_399_441_055_744.0_f64,
    3.141_592_651_605_606,
    1.984_187_159_361_081e-9,
    11,
    12
);

/// `N` floats stepped side by side, each exactly as the scalar would be.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(transparent)]
pub(crate) struct Lanes<T, const N: usize>(pub(crate) [T; N]);

macro_rules! lane_op {
    ($trait:ident, $method:ident, $op:tt) => {
        impl<T: Real, const N: usize> $trait for Lanes<T, N> {
            type Output = Self;
            #[inline(always)]
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
    #[inline(always)]
    fn neg(self) -> Self {
        Lanes(self.0.map(|x| -x))
    }
}

impl<T: Real<Mask = bool>, const N: usize> Real for Lanes<T, N> {
    type Mask = [bool; N];
    #[inline(always)]
    fn splat(x: f64) -> Self {
        Lanes([T::splat(x); N])
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        Lanes(self.0.map(T::sqrt))
    }
    #[inline(always)]
    fn lt(self, other: Self) -> [bool; N] {
        let mut m = [false; N];
        for ((m, a), b) in m.iter_mut().zip(self.0).zip(other.0) {
            *m = a.lt(b);
        }
        m
    }
    #[inline(always)]
    fn select(mask: [bool; N], yes: Self, no: Self) -> Self {
        let mut out = no.0;
        for ((o, m), y) in out.iter_mut().zip(mask).zip(yes.0) {
            *o = T::select(m, y, *o);
        }
        Lanes(out)
    }
    #[inline(always)]
    fn any(mask: [bool; N]) -> bool {
        mask.iter().any(|&m| m)
    }
    #[inline(always)]
    fn round_small(self) -> Self {
        Lanes(self.0.map(T::round_small))
    }
    const PI_HI: f64 = T::PI_HI;
    const PI_LO: f64 = T::PI_LO;
    const SIN: &'static [f64] = T::SIN;
    const COS: &'static [f64] = T::COS;
}
