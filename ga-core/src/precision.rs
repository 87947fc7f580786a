//! `as_f32()` and `as_f64()` between the two precisions of each algebra, component by
//! component (glam's `as_vec3`/`as_dvec3`): `f64 -> f32` rounds to nearest, `f32 -> f64`
//! is exact.

macro_rules! impl_precision_casts {
    ($algebra:ident: $($ty:ident),+) => {
        $(
            impl crate::f64::$algebra::$ty {
                /// The same value in single precision, each component rounded to nearest.
                ///
                /// ```
                #[doc = concat!("let x = ga_core::f64::", stringify!($algebra), "::", stringify!($ty), "::ZERO;")]
                /// assert!(x.as_f32().to_array().iter().all(|&c| c == 0.0));
                /// ```
                #[inline]
                #[must_use]
                pub fn as_f32(self) -> crate::f32::$algebra::$ty {
                    crate::f32::$algebra::$ty::from_array(self.to_array().map(|c| c as f32))
                }
            }

            impl crate::f32::$algebra::$ty {
                /// The same value in double precision (exact).
                ///
                /// ```
                #[doc = concat!("let x = ga_core::f32::", stringify!($algebra), "::", stringify!($ty), "::ZERO;")]
                /// assert_eq!(x.as_f64().as_f32(), x);
                /// ```
                #[inline]
                #[must_use]
                pub fn as_f64(self) -> crate::f64::$algebra::$ty {
                    crate::f64::$algebra::$ty::from_array(self.to_array().map(f64::from))
                }
            }
        )+
    };
}

#[cfg(feature = "g2")]
impl_precision_casts!(g2: Vector, Bivector, Even, Odd, Multivector);
#[cfg(feature = "g3")]
impl_precision_casts!(g3: Vector, Bivector, Trivector, Even, Odd, Multivector);
#[cfg(feature = "g4")]
impl_precision_casts!(g4: Vector, Bivector, Trivector, Quadvector, Even, Odd, Multivector);
