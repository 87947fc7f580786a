//! The trait a scalar type other than `f32`/`f64` implements to be used in `algebra!`
//! (`scalar: num_dual::Dual64`), with its implementations for `f64`, `f32` and, behind the
//! feature `dual`, num-dual's `Dual64` and `HyperDual64`.

use core::fmt::{Debug, Display};
use core::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// A scalar type for `algebra!`: arithmetic, the few functions the products, norms,
/// inverses, exp and log call, and constants.
///
/// The generated code is the `f64` code with every `f64` replaced by `Self` and every float
/// literal by [`Scalar::from_f64`] (`ZERO` and `ONE` where constants need them). Where that
/// code branches on a value, it compares with `PartialOrd`/`PartialEq`, which **must compare
/// the real part only** (as num-dual's types do): the branch is then the one the `f64` code
/// takes, and the derivative parts follow it exactly.
///
/// The constants are the `f64` values lifted (`EPSILON` is `f64::EPSILON` with zero
/// derivative parts, and so on).
#[diagnostic::on_unimplemented(
    message = "`{Self}` is not a scalar type for `algebra!`: it does not implement `ga_core::Scalar`",
    label = "`scalar:` takes f32, f64 or a type implementing `ga_core::Scalar`",
    note = "ga-core implements it for num-dual's `Dual64` and `HyperDual64` (feature `dual`); see the documentation of `ga_core::Scalar`"
)]
pub trait Scalar:
    Copy
    + Debug
    + Display
    + PartialEq
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + AddAssign
    + SubAssign
    + MulAssign
    + DivAssign
{
    /// Zero.
    const ZERO: Self;
    /// One.
    const ONE: Self;
    /// `f64::EPSILON`.
    const EPSILON: Self;
    /// `f64::MIN_POSITIVE`.
    const MIN_POSITIVE: Self;
    /// `f64::MAX`.
    const MAX: Self;
    /// `f64::INFINITY`.
    const INFINITY: Self;
    /// `f64::NAN`.
    const NAN: Self;

    /// Whether every part (the real one and the derivatives) is zero: the generated code
    /// skips a multiplication by an exact zero only then.
    fn is_exact_zero(self) -> bool;
    /// A constant: `x` with zero derivative parts.
    fn from_f64(x: f64) -> Self;
    /// The real part.
    fn re(self) -> f64;
    /// Square root.
    fn sqrt(self) -> Self;
    /// Sine.
    fn sin(self) -> Self;
    /// Cosine.
    fn cos(self) -> Self;
    /// `(sin, cos)`.
    fn sin_cos(self) -> (Self, Self) {
        (self.sin(), self.cos())
    }
    /// Hyperbolic sine.
    fn sinh(self) -> Self;
    /// Hyperbolic cosine.
    fn cosh(self) -> Self;
    /// Inverse hyperbolic sine.
    fn asinh(self) -> Self;
    /// `ln(1 + x)`.
    fn ln_1p(self) -> Self;
    /// Four-quadrant arctangent of `self / x`.
    fn atan2(self, x: Self) -> Self;

    /// Absolute value: `-self` where the real part is negative.
    fn abs(self) -> Self {
        if self.re() < 0.0 {
            -self
        } else {
            self
        }
    }
    /// The larger by real part (the other where one real part is NaN, like `f64::max`).
    fn max(self, other: Self) -> Self {
        if self.re().is_nan() || other.re() > self.re() {
            other
        } else {
            self
        }
    }
    /// The smaller by real part (the other where one real part is NaN, like `f64::min`).
    fn min(self, other: Self) -> Self {
        if self.re().is_nan() || other.re() < self.re() {
            other
        } else {
            self
        }
    }
    /// `f64::signum` of the real part, as a constant (its derivative is zero).
    fn signum(self) -> Self {
        Self::from_f64(self.re().signum())
    }
    /// Whether the real part is finite.
    fn is_finite(self) -> bool {
        self.re().is_finite()
    }
    /// Whether the real part is NaN.
    fn is_nan(self) -> bool {
        self.re().is_nan()
    }
    /// Whether the real part's sign bit is set.
    fn is_sign_negative(self) -> bool {
        self.re().is_sign_negative()
    }
    /// `|self|` with the sign of `sign`'s real part.
    fn copysign(self, sign: Self) -> Self {
        let magnitude = self.abs();
        if sign.re().is_sign_negative() {
            -magnitude
        } else {
            magnitude
        }
    }
    /// `sqrt(self^2 + y^2)` without overflow: scaled by the larger magnitude.
    fn hypot(self, y: Self) -> Self {
        let (a, b) = (self.abs(), y.abs());
        let (big, small) = if a >= b { (a, b) } else { (b, a) };
        if big.re() == 0.0 || !big.is_finite() {
            return big;
        }
        let ratio = small / big;
        big * (Self::ONE + ratio * ratio).sqrt()
    }
}

macro_rules! float_scalar {
    ($t:ident) => {
        impl Scalar for $t {
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const EPSILON: Self = $t::EPSILON;
            const MIN_POSITIVE: Self = $t::MIN_POSITIVE;
            const MAX: Self = $t::MAX;
            const INFINITY: Self = $t::INFINITY;
            const NAN: Self = $t::NAN;

            #[inline]
            fn is_exact_zero(self) -> bool {
                self == 0.0
            }
            #[inline]
            fn from_f64(x: f64) -> Self {
                x as $t
            }
            #[inline]
            fn re(self) -> f64 {
                self.into()
            }
            #[inline]
            fn sqrt(self) -> Self {
                libm_or_std!($t, sqrt, self)
            }
            #[inline]
            fn sin(self) -> Self {
                libm_or_std!($t, sin, self)
            }
            #[inline]
            fn cos(self) -> Self {
                libm_or_std!($t, cos, self)
            }
            #[inline]
            fn sinh(self) -> Self {
                libm_or_std!($t, sinh, self)
            }
            #[inline]
            fn cosh(self) -> Self {
                libm_or_std!($t, cosh, self)
            }
            #[inline]
            fn asinh(self) -> Self {
                libm_or_std!($t, asinh, self)
            }
            #[inline]
            fn ln_1p(self) -> Self {
                libm_or_std!($t, ln_1p, self)
            }
            #[inline]
            fn atan2(self, x: Self) -> Self {
                libm_or_std!($t, atan2, self, x)
            }
        }
    };
}

/// `std`'s method where the standard library is linked, `libm`'s function otherwise.
macro_rules! libm_or_std {
    (f64, ln_1p, $x:expr) => {
        libm_or_std!(@ f64, ln_1p, log1p, $x)
    };
    (f32, ln_1p, $x:expr) => {
        libm_or_std!(@ f32, ln_1p, log1pf, $x)
    };
    (f64, $m:ident, $x:expr $(, $y:expr)?) => {
        libm_or_std!(@ f64, $m, $m, $x $(, $y)?)
    };
    (f32, $m:ident, $x:expr $(, $y:expr)?) => {
        paste_f32!($m, $x $(, $y)?)
    };
    (@ $t:ident, $m:ident, $l:ident, $x:expr $(, $y:expr)?) => {{
        #[cfg(feature = "std")]
        {
            $t::$m($x $(, $y)?)
        }
        #[cfg(not(feature = "std"))]
        {
            crate::libm::$l($x $(, $y)?)
        }
    }};
}

/// The `f32` functions of `libm` carry an `f` suffix.
macro_rules! paste_f32 {
    (sqrt, $x:expr) => { libm_or_std!(@ f32, sqrt, sqrtf, $x) };
    (sin, $x:expr) => { libm_or_std!(@ f32, sin, sinf, $x) };
    (cos, $x:expr) => { libm_or_std!(@ f32, cos, cosf, $x) };
    (sinh, $x:expr) => { libm_or_std!(@ f32, sinh, sinhf, $x) };
    (cosh, $x:expr) => { libm_or_std!(@ f32, cosh, coshf, $x) };
    (asinh, $x:expr) => { libm_or_std!(@ f32, asinh, asinhf, $x) };
    (atan2, $x:expr, $y:expr) => { libm_or_std!(@ f32, atan2, atan2f, $x, $y) };
}

float_scalar!(f64);
float_scalar!(f32);

/// num-dual's scalar types: every function is num-dual's own (`DualNum`), and comparisons
/// are num-dual's, on the real part.
#[cfg(feature = "dual")]
mod num_dual_impls {
    use super::Scalar;
    use num_dual::{Dual64, DualNum, HyperDual64};

    macro_rules! dual_scalar {
        ($t:ty, $lift:expr, [$($part:ident),*]) => {
            impl Scalar for $t {
                const ZERO: Self = $lift(0.0);
                const ONE: Self = $lift(1.0);
                const EPSILON: Self = $lift(f64::EPSILON);
                const MIN_POSITIVE: Self = $lift(f64::MIN_POSITIVE);
                const MAX: Self = $lift(f64::MAX);
                const INFINITY: Self = $lift(f64::INFINITY);
                const NAN: Self = $lift(f64::NAN);

                #[inline]
                fn is_exact_zero(self) -> bool {
                    self.re == 0.0 $(&& self.$part == 0.0)*
                }
                #[inline]
                fn from_f64(x: f64) -> Self {
                    $lift(x)
                }
                #[inline]
                fn re(self) -> f64 {
                    self.re
                }
                /// num-dual's square root, except at an exact zero (every part zero), whose
                /// root is zero: num-dual's `0 * (1 / sqrt 0)` would make the derivative NaN
                /// where a constant zero is passed (Carlson's `R_J(0, y, z, p)`, the norm of
                /// zero).
                #[inline]
                fn sqrt(self) -> Self {
                    if self.is_exact_zero() {
                        return Self::ZERO;
                    }
                    DualNum::sqrt(&self)
                }
                #[inline]
                fn sin(self) -> Self {
                    DualNum::sin(&self)
                }
                #[inline]
                fn cos(self) -> Self {
                    DualNum::cos(&self)
                }
                #[inline]
                fn sin_cos(self) -> (Self, Self) {
                    DualNum::sin_cos(&self)
                }
                #[inline]
                fn sinh(self) -> Self {
                    DualNum::sinh(&self)
                }
                #[inline]
                fn cosh(self) -> Self {
                    DualNum::cosh(&self)
                }
                #[inline]
                fn asinh(self) -> Self {
                    DualNum::asinh(&self)
                }
                #[inline]
                fn ln_1p(self) -> Self {
                    DualNum::ln_1p(&self)
                }
                #[inline]
                fn atan2(self, x: Self) -> Self {
                    DualNum::atan2(&self, x)
                }
            }
        };
    }

    const fn dual(x: f64) -> Dual64 {
        Dual64 { re: x, eps: 0.0 }
    }
    const fn hyper(x: f64) -> HyperDual64 {
        HyperDual64 {
            re: x,
            eps1: 0.0,
            eps2: 0.0,
            eps1eps2: 0.0,
        }
    }

    dual_scalar!(Dual64, dual, [eps]);
    dual_scalar!(HyperDual64, hyper, [eps1, eps2, eps1eps2]);
}

/// How `algebra!` names a generic scalar `S` (not API): its modules write
/// `<[S; checked::<S>()] as Element>::Type`, which is `S` when `S: Scalar`. When it is not,
/// the one error is the bound of [`checked`] at the user's `scalar:` token, and the array
/// length, and with it the type, is an error that the compiler does not report again, where
/// naming `S` itself gave one error per use (over a thousand for G3).
#[doc(hidden)]
pub mod checked {
    use super::Scalar;

    /// Zero, for a scalar type only: the length of the array that [`Element`] unwraps.
    #[must_use]
    pub const fn checked<S: Scalar>() -> usize {
        0
    }

    /// The element type of an array.
    pub trait Element {
        /// The element type.
        type Type;
    }

    impl<T, const N: usize> Element for [T; N] {
        type Type = T;
    }
}
