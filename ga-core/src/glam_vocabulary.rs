//! glam's `Vec3` and `Quat` vocabulary on G3's `Vector` and `Rotor`, with glam's meanings
//! (for the same inputs, glam's result, up to the sign of a rotor), so that code ported
//! from glam keeps working by name. The mapping is `w = s, x = -e23, y = e13, z = -e12`
//! (docs/derivations/rotor-quaternion.md). What differs on purpose is listed in
//! docs/glam.md with the reason.

/// glam's view of a G3 vector: its components under glam's names, `x = e1`, `y = e2`,
/// `z = e3`. `Vector` dereferences to it, as glam's `Vec3A` does to its `XYZ`, so that
/// `v.x` reads and `v.x = 1.0` writes the `e1` component. Not made by itself: it is
/// reached through a `Vector`.
///
/// ```
/// use ga_core::f64::g3::*;
/// let mut v = Vector::new(1.0, 2.0, 3.0);
/// v.z += 1.0;
/// assert_eq!((v.x, v.y, v.z), (1.0, 2.0, 4.0));
/// assert_eq!(v.e3, 4.0);
/// ```
#[cfg(any(feature = "f32", feature = "f64"))]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C)]
pub struct Xyz<S> {
    /// The `e1` component.
    pub x: S,
    /// The `e2` component.
    pub y: S,
    /// The `e3` component.
    pub z: S,
}

// Unused when no precision is on.
#[allow(unused_macros)]
macro_rules! glam_vocabulary {
    (
        $s:ident, $quat_fn:ident, $vec3_fn:ident, $vec4:ident, $mat3:ident, $mat4:ident,
        $affine3:ident
    ) => {
        #[cfg(not(feature = "std"))]
        #[allow(unused_imports)]
        use crate::rotor::no_std_math::Real as _;
        use super::Xyz;
        use crate::$s::g3::{Rotor, Sandwich, Vector};

        // The pointer casts of `Deref` and `DerefMut` below rely on this: both types are
        // `#[repr(C)]` with three fields of type `$s` in the order e1/x, e2/y, e3/z.
        const _: () = {
            use ::core::mem::{align_of, offset_of, size_of};
            assert!(size_of::<Vector>() == size_of::<Xyz<$s>>());
            assert!(align_of::<Vector>() == align_of::<Xyz<$s>>());
            assert!(offset_of!(Vector, e1) == offset_of!(Xyz<$s>, x));
            assert!(offset_of!(Vector, e2) == offset_of!(Xyz<$s>, y));
            assert!(offset_of!(Vector, e3) == offset_of!(Xyz<$s>, z));
        };

        /// The rotor of glam's quaternion `(x, y, z, w)` (glam's free function of this
        /// name): [`Rotor::from_xyzw`], re-exported in the `g3` module.
        ///
        /// ```
        #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
        #[doc = concat!("assert_eq!(", stringify!($quat_fn), "(0.0, 0.0, 0.0, 1.0), Rotor::IDENTITY);")]
        /// ```
        #[inline]
        #[must_use]
        pub const fn $quat_fn(x: $s, y: $s, z: $s, w: $s) -> Rotor {
            Rotor::from_xyzw(x, y, z, w)
        }

        /// The vector `x e1 + y e2 + z e3` (glam's free function of this name):
        /// [`Vector::new`], re-exported in the `g3` module.
        ///
        /// ```
        #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
        #[doc = concat!("assert_eq!(", stringify!($vec3_fn), "(1.0, 2.0, 3.0).y, 2.0);")]
        /// ```
        #[inline]
        #[must_use]
        pub const fn $vec3_fn(x: $s, y: $s, z: $s) -> Vector {
            Vector::new(x, y, z)
        }

        /// glam's field names: `v.x`, `v.y`, `v.z` are `e1`, `e2`, `e3` (read through
        /// `Xyz`, as glam's `Vec3A` reads through its `XYZ`).
        impl ::core::ops::Deref for Vector {
            type Target = Xyz<$s>;

            #[inline]
            fn deref(&self) -> &Xyz<$s> {
                // SAFETY: `Vector` and `Xyz<$s>` are both `#[repr(C)]` structs of three
                // `$s` fields with the same size, alignment and offsets (asserted at
                // compile time above), so a valid `Vector` is a valid `Xyz<$s>`, and the
                // reference borrows `self` for its lifetime.
                unsafe { &*(self as *const Vector).cast::<Xyz<$s>>() }
            }
        }

        /// glam's field names for writing: `v.x = 1.0` sets `e1`.
        impl ::core::ops::DerefMut for Vector {
            #[inline]
            fn deref_mut(&mut self) -> &mut Xyz<$s> {
                // SAFETY: as in `deref`; every bit pattern of the three `$s` is valid for
                // both types, and the unique borrow of `self` is handed on.
                unsafe { &mut *(self as *mut Vector).cast::<Xyz<$s>>() }
            }
        }

        impl Vector {
            /// The unit vector along x (glam's `Vec3::X`), `e1`.
            pub const X: Vector = Vector::E1;
            /// The unit vector along y (glam's `Vec3::Y`), `e2`.
            pub const Y: Vector = Vector::E2;
            /// The unit vector along z (glam's `Vec3::Z`), `e3`.
            pub const Z: Vector = Vector::E3;

            /// The dot product (glam's `dot`); the same as `self | rhs`.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// assert_eq!(Vector::new(1.0, 2.0, 3.0).dot(Vector::new(4.0, 5.0, 6.0)), 32.0);
            /// ```
            #[inline]
            #[must_use]
            pub fn dot(self, rhs: Vector) -> $s {
                self.e1 * rhs.e1 + self.e2 * rhs.e2 + self.e3 * rhs.e3
            }

            /// The cross product (glam's `cross`), right-handed: `X.cross(Y) = Z`. In the
            /// algebra it is `-I (a ^ b)`, the vector dual to the plane `a ^ b`.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// assert_eq!(Vector::X.cross(Vector::Y), Vector::Z);
            /// ```
            #[inline]
            #[must_use]
            pub fn cross(self, rhs: Vector) -> Vector {
                Vector::new(
                    self.e2 * rhs.e3 - self.e3 * rhs.e2,
                    self.e3 * rhs.e1 - self.e1 * rhs.e3,
                    self.e1 * rhs.e2 - self.e2 * rhs.e1,
                )
            }

            /// The length (glam's `length`): `sqrt(x^2 + y^2 + z^2)` as written, which
            /// overflows where `norm` (scaled) does not.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// assert_eq!(Vector::new(3.0, 0.0, 4.0).length(), 5.0);
            /// ```
            #[inline]
            #[must_use]
            pub fn length(self) -> $s {
                self.dot(self).sqrt()
            }

            /// The squared length (glam's `length_squared`).
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// assert_eq!(Vector::new(3.0, 0.0, 4.0).length_squared(), 25.0);
            /// ```
            #[inline]
            #[must_use]
            pub fn length_squared(self) -> $s {
                self.dot(self)
            }

            /// `self / |self|` (glam's `normalize`): non-finite for the zero vector, as
            /// glam's (which asserts only with its `glam_assert` feature). `normalized()`
            /// and `try_normalized()` are the careful forms.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// assert_eq!(Vector::new(0.0, 0.0, 2.0).normalize(), Vector::Z);
            /// assert!(!Vector::ZERO.normalize().is_finite());
            /// ```
            #[inline]
            #[must_use]
            pub fn normalize(self) -> Vector {
                self * (1.0 / self.length())
            }

            /// Whether the length is 1 to glam's tolerance, `|length^2 - 1| <= 2e-4`
            /// (glam's `is_normalized`, the same in f32 and f64).
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// assert!(Vector::X.is_normalized() && !(Vector::X * 1.001).is_normalized());
            /// ```
            #[inline]
            #[must_use]
            pub fn is_normalized(self) -> bool {
                (self.length_squared() - 1.0).abs() <= 2e-4
            }

            /// The vector from the first three entries `[x, y, z]` of `slice` (glam's
            /// `from_slice`).
            ///
            /// # Panics
            /// When `slice` has fewer than three entries, as glam's.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// assert_eq!(Vector::from_slice(&[1.0, 2.0, 3.0, 4.0]), Vector::new(1.0, 2.0, 3.0));
            /// ```
            #[inline]
            #[must_use]
            pub fn from_slice(slice: &[$s]) -> Vector {
                Vector::new(slice[0], slice[1], slice[2])
            }

            /// Writes `[x, y, z]` to the first three entries of `slice` (glam's
            /// `write_to_slice`).
            ///
            /// # Panics
            /// When `slice` has fewer than three entries, as glam's.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let mut out = [0.0; 3];
            /// Vector::new(1.0, 2.0, 3.0).write_to_slice(&mut out);
            /// assert_eq!(out, [1.0, 2.0, 3.0]);
            /// ```
            #[inline]
            pub fn write_to_slice(self, slice: &mut [$s]) {
                slice[..3].copy_from_slice(&self.to_array());
            }
        }

        /// glam's `Vec3` constants and component-wise methods, with glam's meanings.
        impl Vector {
            /// All components 1 (glam's `Vec3::ONE`); not the scalar 1 of the algebra.
            pub const ONE: Vector = Vector::splat(1.0);
            /// All components -1 (glam's `Vec3::NEG_ONE`).
            pub const NEG_ONE: Vector = Vector::splat(-1.0);
            /// `-e1` (glam's `Vec3::NEG_X`).
            pub const NEG_X: Vector = Vector::new(-1.0, 0.0, 0.0);
            /// `-e2` (glam's `Vec3::NEG_Y`).
            pub const NEG_Y: Vector = Vector::new(0.0, -1.0, 0.0);
            /// `-e3` (glam's `Vec3::NEG_Z`).
            pub const NEG_Z: Vector = Vector::new(0.0, 0.0, -1.0);
            /// `[X, Y, Z]` (glam's `Vec3::AXES`).
            pub const AXES: [Vector; 3] = [Vector::X, Vector::Y, Vector::Z];
            /// All components the smallest finite value (glam's `Vec3::MIN`).
            pub const MIN: Vector = Vector::splat($s::MIN);
            /// All components the largest finite value (glam's `Vec3::MAX`).
            pub const MAX: Vector = Vector::splat($s::MAX);
            /// All components NaN (glam's `Vec3::NAN`).
            pub const NAN: Vector = Vector::splat($s::NAN);
            /// All components `+inf` (glam's `Vec3::INFINITY`).
            pub const INFINITY: Vector = Vector::splat($s::INFINITY);
            /// All components `-inf` (glam's `Vec3::NEG_INFINITY`).
            pub const NEG_INFINITY: Vector = Vector::splat($s::NEG_INFINITY);

            /// Every component `v` (glam's `Vec3::splat`).
            #[inline]
            #[must_use]
            pub const fn splat(v: $s) -> Vector {
                Vector::new(v, v, v)
            }

            /// `self` at `s = 0`, `rhs` at `s = 1`, as `self (1 - s) + rhs s` (glam's
            /// `lerp`, also called `mix`).
            #[doc(alias = "mix")]
            #[inline]
            #[must_use]
            pub fn lerp(self, rhs: Vector, s: $s) -> Vector {
                self * (1.0 - s) + rhs * s
            }

            /// `|self - rhs|` (glam's `distance`).
            #[inline]
            #[must_use]
            pub fn distance(self, rhs: Vector) -> $s {
                (self - rhs).length()
            }

            /// `|self - rhs|^2` (glam's `distance_squared`).
            #[inline]
            #[must_use]
            pub fn distance_squared(self, rhs: Vector) -> $s {
                (self - rhs).length_squared()
            }

            /// `1 / |self|` (glam's `length_recip`): infinite for the zero vector.
            #[inline]
            #[must_use]
            pub fn length_recip(self) -> $s {
                1.0 / self.length()
            }

            /// `self / |self|`, or `fallback` when `1 / |self|` is zero or not finite
            /// (zero, non-finite or overflowing length), as glam's `normalize_or`.
            #[inline]
            #[must_use]
            pub fn normalize_or(self, fallback: Vector) -> Vector {
                let recip = self.length_recip();
                if recip.is_finite() && recip > 0.0 {
                    self * recip
                } else {
                    fallback
                }
            }

            /// `self / |self|`, or zero where glam's `normalize_or_zero` gives zero (zero,
            /// non-finite or overflowing length).
            #[inline]
            #[must_use]
            pub fn normalize_or_zero(self) -> Vector {
                self.normalize_or(Vector::ZERO)
            }

            /// The angle in `[0, pi]` between two vectors (glam's `angle_between`), as
            /// `atan2(|a x b|, a . b)`: no `acos`, so it keeps its digits near 0 and pi
            /// where glam's (a polynomial `acos` of the clamped cosine in f32, `acos` in
            /// f64) loses half of them. NaN when either vector is zero, as glam's.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            #[doc = concat!("use core::", stringify!($s), "::consts::PI;")]
            /// assert!((Vector::X.angle_between(-Vector::X) - PI).abs() < 1e-6);
            /// assert!(Vector::X.angle_between(Vector::ZERO).is_nan());
            /// ```
            #[inline]
            #[must_use]
            pub fn angle_between(self, rhs: Vector) -> $s {
                let sin = self.cross(rhs).norm();
                let cos = self.dot(rhs);
                if sin == 0.0 && cos == 0.0 {
                    return $s::NAN;
                }
                sin.atan2(cos)
            }

            /// Component-wise absolute value (glam's `abs`).
            #[inline]
            #[must_use]
            pub fn abs(self) -> Vector {
                Vector::new(self.e1.abs(), self.e2.abs(), self.e3.abs())
            }

            /// Component-wise minimum (glam's `min`: `rhs`'s component where the
            /// comparison fails, so a NaN in `self` gives `rhs`'s).
            #[inline]
            #[must_use]
            pub fn min(self, rhs: Vector) -> Vector {
                let min = |a: $s, b: $s| if a < b { a } else { b };
                Vector::new(min(self.e1, rhs.e1), min(self.e2, rhs.e2), min(self.e3, rhs.e3))
            }

            /// Component-wise maximum (glam's `max`, NaN as in [`min`](Self::min)).
            #[inline]
            #[must_use]
            pub fn max(self, rhs: Vector) -> Vector {
                let max = |a: $s, b: $s| if a > b { a } else { b };
                Vector::new(max(self.e1, rhs.e1), max(self.e2, rhs.e2), max(self.e3, rhs.e3))
            }

            /// The smallest component (glam's `min_element`).
            #[inline]
            #[must_use]
            pub fn min_element(self) -> $s {
                let min = |a: $s, b: $s| if a < b { a } else { b };
                min(self.e1, min(self.e2, self.e3))
            }

            /// The largest component (glam's `max_element`).
            #[inline]
            #[must_use]
            pub fn max_element(self) -> $s {
                let max = |a: $s, b: $s| if a > b { a } else { b };
                max(self.e1, max(self.e2, self.e3))
            }

            /// The part of `self` along `rhs`, `rhs (self . rhs) / |rhs|^2` (glam's
            /// `project_onto`): non-finite when `rhs` is zero.
            #[inline]
            #[must_use]
            pub fn project_onto(self, rhs: Vector) -> Vector {
                rhs * self.dot(rhs) * (1.0 / rhs.dot(rhs))
            }

            /// The part of `self` along the unit `rhs`, `rhs (self . rhs)` (glam's
            /// `project_onto_normalized`).
            #[inline]
            #[must_use]
            pub fn project_onto_normalized(self, rhs: Vector) -> Vector {
                rhs * self.dot(rhs)
            }

            /// The part of `self` perpendicular to `rhs` (glam's `reject_from`):
            /// non-finite when `rhs` is zero.
            #[inline]
            #[must_use]
            pub fn reject_from(self, rhs: Vector) -> Vector {
                self - self.project_onto(rhs)
            }

            /// A vector perpendicular to `self`, not unit (glam's
            /// `any_orthogonal_vector`: `self x Y` when `|x| > |y|`, else `self x X`).
            #[inline]
            #[must_use]
            pub fn any_orthogonal_vector(self) -> Vector {
                if self.e1.abs() > self.e2.abs() {
                    Vector::new(-self.e3, 0.0, self.e1)
                } else {
                    Vector::new(0.0, self.e3, -self.e2)
                }
            }

            /// A unit vector perpendicular to the unit `self` (glam's
            /// `any_orthonormal_vector`, the same vector): Duff et al., "Building an
            /// orthonormal basis, revisited", JCGT 6(1), 2017, whose second basis vector
            /// it is.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let n = Vector::new(0.0, 0.6, -0.8);
            /// let t = n.any_orthonormal_vector();
            /// assert!(t.dot(n).abs() < 1e-6 && t.is_normalized());
            /// ```
            #[inline]
            #[must_use]
            pub fn any_orthonormal_vector(self) -> Vector {
                let sign = (1.0 as $s).copysign(self.e3);
                let a = -1.0 / (sign + self.e3);
                let b = self.e1 * self.e2 * a;
                Vector::new(b, sign + self.e2 * self.e2 * a, -self.e2)
            }

            /// Whether every component is within `max_abs_diff` of `rhs`'s (glam's
            /// `abs_diff_eq`).
            #[inline]
            #[must_use]
            pub fn abs_diff_eq(self, rhs: Vector, max_abs_diff: $s) -> bool {
                (self - rhs).iter().all(|d| d.abs() <= max_abs_diff)
            }
        }

        impl Rotor {
            /// The identity rotation (glam's `Quat::IDENTITY`), the same as `Rotor::ONE`.
            /// `Rotor::default()` is the zero rotor, not this: see docs/glam.md.
            #[doc(alias = "default")]
            pub const IDENTITY: Rotor = Rotor::ONE;

            /// The rotor of glam's quaternion `(x, y, z, w)` (glam's `from_xyzw`):
            /// `w - z e12 + y e13 - x e23`.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// assert_eq!(Rotor::from_xyzw(0.0, 0.0, 0.0, 1.0), Rotor::IDENTITY);
            /// ```
            #[doc(alias = "from_array")]
            #[inline]
            #[must_use]
            pub const fn from_xyzw(x: $s, y: $s, z: $s, w: $s) -> Rotor {
                Rotor::new(w, -z, y, -x)
            }

            /// glam's quaternion components `[x, y, z, w]` of this rotor (glam's
            /// `Quat::to_array` order; `to_array` itself is the canonical
            /// `[s, e12, e13, e23]`).
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// assert_eq!(Rotor::from_xyzw(1.0, 2.0, 3.0, 4.0).to_xyzw(), [1.0, 2.0, 3.0, 4.0]);
            /// ```
            #[doc(alias = "to_array")]
            #[inline]
            #[must_use]
            pub const fn to_xyzw(self) -> [$s; 4] {
                [-self.e23, self.e13, -self.e12, self.s]
            }

            /// The rotor of glam's quaternion layout `[x, y, z, w]` in the first four
            /// entries of `slice` (glam's `Quat::from_slice`, same order; not the
            /// canonical order of `from_array`).
            ///
            /// # Panics
            /// When `slice` has fewer than four entries, as glam's.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// assert_eq!(Rotor::from_slice(&[0.0, 0.0, 0.0, 1.0]), Rotor::IDENTITY);
            /// ```
            #[inline]
            #[must_use]
            pub fn from_slice(slice: &[$s]) -> Rotor {
                Rotor::from_xyzw(slice[0], slice[1], slice[2], slice[3])
            }

            /// Writes glam's layout `[x, y, z, w]` to the first four entries of `slice`
            /// (glam's `Quat::write_to_slice`).
            ///
            /// # Panics
            /// When `slice` has fewer than four entries, as glam's.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let mut out = [0.0; 4];
            /// Rotor::IDENTITY.write_to_slice(&mut out);
            /// assert_eq!(out, [0.0, 0.0, 0.0, 1.0]);
            /// ```
            #[inline]
            pub fn write_to_slice(self, slice: &mut [$s]) {
                slice[..4].copy_from_slice(&self.to_xyzw());
            }

            /// The rotation by `angle` about x (glam's `from_rotation_x`): `exp(-e23 angle / 2)`.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            #[doc = concat!("let r = Rotor::from_rotation_x(core::", stringify!($s), "::consts::FRAC_PI_2);")]
            /// assert!((r.mul_vec3(Vector::Y) - Vector::Z).norm() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn from_rotation_x(angle: $s) -> Rotor {
                let (sin, cos) = (angle * 0.5).sin_cos();
                Rotor::new(cos, 0.0, 0.0, -sin)
            }

            /// The rotation by `angle` about y (glam's `from_rotation_y`): `exp(e13 angle / 2)`.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            #[doc = concat!("let r = Rotor::from_rotation_y(core::", stringify!($s), "::consts::FRAC_PI_2);")]
            /// assert!((r.mul_vec3(Vector::Z) - Vector::X).norm() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn from_rotation_y(angle: $s) -> Rotor {
                let (sin, cos) = (angle * 0.5).sin_cos();
                Rotor::new(cos, 0.0, sin, 0.0)
            }

            /// The rotation by `angle` about z (glam's `from_rotation_z`): `exp(-e12 angle / 2)`.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            #[doc = concat!("let r = Rotor::from_rotation_z(core::", stringify!($s), "::consts::FRAC_PI_2);")]
            /// assert!((r.mul_vec3(Vector::X) - Vector::Y).norm() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn from_rotation_z(angle: $s) -> Rotor {
                let (sin, cos) = (angle * 0.5).sin_cos();
                Rotor::new(cos, -sin, 0.0, 0.0)
            }

            /// `R v ~R` (glam's `Quat::mul_vec3` and `Quat * Vec3`): the sandwich, which
            /// is what glam's formula computes for any quaternion (scaled by `|R|^2` when
            /// `R` is not unit). `Rotor * Vector` is the geometric product: see docs/glam.md.
            /// `v` is a `Vector` or any type that converts to and from one (glam's
            /// `Vec3`, `[x, y, z]`, mint's), and the result is of `v`'s type, so that a
            /// ported `q * v` becomes `q.mul_vec3(v)` whichever vector `v` is.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let r = Rotor::from_rotation_z(1.0);
            /// assert_eq!(r.mul_vec3(Vector::X), r.sandwich(Vector::X));
            /// assert_eq!(r.mul_vec3([1.0, 0.0, 0.0]), r.sandwich(Vector::X).to_array());
            /// ```
            #[doc(alias = "mul")]
            #[inline]
            #[must_use]
            pub fn mul_vec3<V: Into<Vector> + From<Vector>>(self, v: V) -> V {
                V::from(self.sandwich(v.into()))
            }

            /// The four-component dot product (glam's `Quat::dot`): `<self ~rhs>_0`.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// assert_eq!(Rotor::IDENTITY.dot(Rotor::IDENTITY), 1.0);
            /// ```
            #[inline]
            #[must_use]
            pub fn dot(self, rhs: Rotor) -> $s {
                self.s * rhs.s + self.e12 * rhs.e12 + self.e13 * rhs.e13 + self.e23 * rhs.e23
            }

            /// The length `sqrt(<R ~R>)` as written (glam's `Quat::length`).
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// assert_eq!((Rotor::IDENTITY * 2.0).length(), 2.0);
            /// ```
            #[inline]
            #[must_use]
            pub fn length(self) -> $s {
                self.dot(self).sqrt()
            }

            /// `<R ~R>` (glam's `Quat::length_squared`).
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// assert_eq!((Rotor::IDENTITY * 2.0).length_squared(), 4.0);
            /// ```
            #[inline]
            #[must_use]
            pub fn length_squared(self) -> $s {
                self.dot(self)
            }

            /// `R / |R|` (glam's `Quat::normalize`): non-finite for the zero rotor, as
            /// glam's; `normalized()` and `try_normalized()` are the careful forms.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// assert_eq!((Rotor::IDENTITY * 3.0).normalize(), Rotor::IDENTITY);
            /// ```
            #[inline]
            #[must_use]
            pub fn normalize(self) -> Rotor {
                self * (1.0 / self.length())
            }

            /// Whether `|<R ~R> - 1| <= 2e-4` (glam's `Quat::is_normalized`, the same
            /// tolerance in f32 and f64).
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// assert!(Rotor::IDENTITY.is_normalized() && !Rotor::ZERO.is_normalized());
            /// ```
            #[inline]
            #[must_use]
            pub fn is_normalized(self) -> bool {
                (self.length_squared() - 1.0).abs() <= 2e-4
            }

            /// Whether the rotation angle `2 acos(|s|)` is below glam's threshold
            /// (glam's `Quat::is_near_identity`: `0.0028474` rad in f32, from
            /// `acos(1 - 1e-6)`, and `2.8273e-7` rad in f64, from `acos(1 - 1e-14)`).
            /// `R` and `-R` agree.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// assert!(Rotor::from_rotation_x(1e-8).is_near_identity());
            /// assert!(!Rotor::from_rotation_x(0.01).is_near_identity());
            /// ```
            #[inline]
            #[must_use]
            pub fn is_near_identity(self) -> bool {
                // Each precision's constant written in its own type.
                let threshold: $s = if ::core::mem::size_of::<$s>() == 4 {
                    0.002_847_144_6_f32 as $s
                } else {
                    2.827_296_549_232_347_4e-7_f64 as $s
                };
                2.0 * self.s.abs().min(1.0).acos() < threshold
            }

            /// Turns `self` toward `rhs` by at most `max_angle` (glam's
            /// `Quat::rotate_towards`): `rhs` itself within `1e-4` rad of it, otherwise
            /// `slerp` by `max_angle / angle` clamped to `[-1, 1]`, so a negative
            /// `max_angle` turns away. Both rotors unit.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let r = Rotor::IDENTITY.rotate_towards(Rotor::from_rotation_z(1.0), 0.25);
            /// assert!((r - Rotor::from_rotation_z(0.25)).norm() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn rotate_towards(self, rhs: Rotor, max_angle: $s) -> Rotor {
                let angle = self.angle_between(rhs);
                if angle <= 1e-4 {
                    return rhs;
                }
                self.slerp(rhs, (max_angle / angle).clamp(-1.0, 1.0))
            }

            /// The shortest rotation taking the unit `from` onto the line of the unit
            /// `to`, to `to` or `-to` whichever is nearer, at most a quarter turn (glam's
            /// `from_rotation_arc_colinear`).
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let r = Rotor::from_rotation_arc_colinear(Vector::X, -Vector::X);
            /// assert_eq!(r, Rotor::IDENTITY);
            /// ```
            #[inline]
            #[must_use]
            pub fn from_rotation_arc_colinear(from: Vector, to: Vector) -> Rotor {
                if from.dot(to) < 0.0 {
                    Rotor::from_rotation_arc(from, -to)
                } else {
                    Rotor::from_rotation_arc(from, to)
                }
            }

            /// glam's `Quat::look_to_lh(dir, up)`: the rotation taking world directions
            /// to a left-handed view frame (`+x` right, `+y` up, `+z` forward), so that
            /// it sends `dir` to `+z` and the part of `up` perpendicular to `dir` to
            /// `+y`. `dir` and `up` need not be unit (glam asks for unit input and
            /// gives a non-rotation otherwise); `None` when `dir` is zero, `up` is
            /// parallel to it, or either is not finite (glam returns NaN).
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let view = Rotor::look_to_lh(Vector::X, Vector::Z).unwrap();
            /// assert!((view.mul_vec3(Vector::X) - Vector::Z).norm() < 1e-6);
            /// assert!((view.mul_vec3(Vector::Z) - Vector::Y).norm() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn look_to_lh(dir: Vector, up: Vector) -> Option<Rotor> {
                Rotor::from_forward_up(dir, up).map(Rotor::reverse)
            }

            /// glam's `Quat::look_to_rh(dir, up)`: the rotation taking world directions
            /// to a right-handed view frame (`+x` right, `+y` up, `+z` back), so that it
            /// sends `dir` to `-z` and the part of `up` perpendicular to `dir` to `+y`.
            /// `None` as for [`look_to_lh`](Self::look_to_lh).
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let view = Rotor::look_to_rh(Vector::X, Vector::Z).unwrap();
            /// assert!((view.mul_vec3(Vector::X) + Vector::Z).norm() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn look_to_rh(dir: Vector, up: Vector) -> Option<Rotor> {
                Rotor::look_to_lh(-dir, up)
            }

            /// glam's `Quat::look_at_lh(eye, center, up)`: `look_to_lh(center - eye, up)`.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let view = Rotor::look_at_lh(Vector::ZERO, Vector::X * 5.0, Vector::Z).unwrap();
            /// assert!((view.mul_vec3(Vector::X) - Vector::Z).norm() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn look_at_lh(eye: Vector, center: Vector, up: Vector) -> Option<Rotor> {
                Rotor::look_to_lh(center - eye, up)
            }

            /// glam's `Quat::look_at_rh(eye, center, up)`: `look_to_rh(center - eye, up)`.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let view = Rotor::look_at_rh(Vector::ZERO, Vector::X * 5.0, Vector::Z).unwrap();
            /// assert!((view.mul_vec3(Vector::X) + Vector::Z).norm() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn look_at_rh(eye: Vector, center: Vector, up: Vector) -> Option<Rotor> {
                Rotor::look_to_rh(center - eye, up)
            }
        }

        /// glam's `Vec3` names for rotating and splitting vectors, with glam's meanings.
        impl Vector {
            /// `self` turned by `angle` about x, right-handed (glam's `Vec3::rotate_x`):
            /// `Rotor::from_rotation_x(angle).mul_vec3(self)`.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            #[doc = concat!("let v = Vector::Y.rotate_x(core::", stringify!($s), "::consts::FRAC_PI_2);")]
            /// assert!((v - Vector::Z).norm() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn rotate_x(self, angle: $s) -> Vector {
                Rotor::from_rotation_x(angle).mul_vec3(self)
            }

            /// `self` turned by `angle` about y, right-handed (glam's `Vec3::rotate_y`).
            #[inline]
            #[must_use]
            pub fn rotate_y(self, angle: $s) -> Vector {
                Rotor::from_rotation_y(angle).mul_vec3(self)
            }

            /// `self` turned by `angle` about z, right-handed (glam's `Vec3::rotate_z`).
            #[inline]
            #[must_use]
            pub fn rotate_z(self, angle: $s) -> Vector {
                Rotor::from_rotation_z(angle).mul_vec3(self)
            }

            /// `self` turned by `angle` about the unit `axis` (glam's
            /// `Vec3::rotate_axis`): `Rotor::from_axis_angle(axis, angle).mul_vec3(self)`.
            #[inline]
            #[must_use]
            pub fn rotate_axis(self, axis: Vector, angle: $s) -> Vector {
                Rotor::from_axis_angle(axis, angle).mul_vec3(self)
            }

            /// `self` turned toward `rhs` by at most `max_angle` about their common
            /// normal (glam's `Vec3::rotate_towards`): parallel to `rhs` once
            /// `max_angle` reaches the angle between them, and a negative `max_angle`
            /// turns away, at most to the opposite of `rhs`. Parallel or opposite
            /// vectors turn about [`any_orthogonal_vector`](Self::any_orthogonal_vector).
            /// A zero input is returned unchanged (glam panics there: its clamp gets NaN).
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let v = Vector::X.rotate_towards(Vector::Y, 0.5);
            /// assert!((v - Vector::X.rotate_z(0.5)).norm() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn rotate_towards(self, rhs: Vector, max_angle: $s) -> Vector {
                let between = self.angle_between(rhs);
                if between.is_nan() {
                    return self;
                }
                // `max` and `min`, not `clamp`: no panic on a NaN `max_angle`.
                let angle = max_angle
                    .max(between - ::core::$s::consts::PI)
                    .min(between);
                let axis = match self.cross(rhs).try_normalized() {
                    Some(axis) => axis,
                    None => self.any_orthogonal_vector().normalize(),
                };
                self.rotate_axis(axis, angle)
            }

            /// Two unit vectors that make a right-handed orthonormal basis with the unit
            /// `self` (glam's `Vec3::any_orthonormal_pair`, the same pair): Duff et al.,
            /// "Building an orthonormal basis, revisited", JCGT 6(1), 2017.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let n = Vector::new(0.0, 0.6, -0.8);
            /// let (a, b) = n.any_orthonormal_pair();
            /// assert!((a.cross(b) - n).norm() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn any_orthonormal_pair(self) -> (Vector, Vector) {
                let sign = (1.0 as $s).copysign(self.e3);
                let a = -1.0 / (sign + self.e3);
                let b = self.e1 * self.e2 * a;
                (
                    Vector::new(1.0 + sign * self.e1 * self.e1 * a, sign * b, -sign * self.e1),
                    self.any_orthonormal_vector(),
                )
            }

            /// The part of `self` perpendicular to the unit `rhs` (glam's
            /// `Vec3::reject_from_normalized`): `self - rhs (self . rhs)`.
            #[inline]
            #[must_use]
            pub fn reject_from_normalized(self, rhs: Vector) -> Vector {
                self - self.project_onto_normalized(rhs)
            }
        }

        /// glam's `Quat` names beyond the rotor toolkit, with glam's meanings.
        impl Rotor {
            /// All components NaN (glam's `Quat::NAN`).
            pub const NAN: Rotor = Rotor::new($s::NAN, $s::NAN, $s::NAN, $s::NAN);

            /// glam's vector part `(x, y, z) = (-e23, e13, -e12)` as a `Vector` (glam's
            /// `Quat::xyz`): `sin(angle / 2)` times the axis for a unit rotor.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let r = Rotor::from_xyzw(1.0, 2.0, 3.0, 4.0);
            /// assert_eq!((r.xyz(), r.w()), (Vector::new(1.0, 2.0, 3.0), 4.0));
            /// ```
            #[inline]
            #[must_use]
            pub const fn xyz(self) -> Vector {
                Vector::new(-self.e23, self.e13, -self.e12)
            }

            /// glam's `w`, the scalar part `s`: a method, since glam's `x, y, z` are not
            /// this type's fields (see docs/glam.md).
            #[inline]
            #[must_use]
            pub const fn w(self) -> $s {
                self.s
            }

            /// `1 / |R|` (glam's `Quat::length_recip`): infinite for the zero rotor.
            #[inline]
            #[must_use]
            pub fn length_recip(self) -> $s {
                1.0 / self.length()
            }

            /// The rotor product `self rhs`, glam's `Quat::mul_quat` (and glam's
            /// `Quat * Quat`, which `*` is here too): `rhs` acts first, then `self`.
            #[inline]
            #[must_use]
            pub fn mul_quat(self, rhs: Rotor) -> Rotor {
                self * rhs
            }

            /// Normalised linear interpolation along the shorter arc (glam's
            /// `Quat::lerp`, also called `mix`): the same as [`nlerp`](Self::nlerp).
            #[doc(alias = "mix")]
            #[inline]
            #[must_use]
            pub fn lerp(self, end: Rotor, s: $s) -> Rotor {
                self.nlerp(end, s)
            }

            /// Spherical interpolation that keeps the sign of `end`, so it takes the
            /// longer arc when `self . end < 0` (glam 0.33's `Quat::slerp_long`): `self`
            /// at `s = 0`, exactly `end`'s quaternion at `s = 1`, a turn of more than a
            /// half turn in between. Both rotors unit. When `end = -self` the plane is
            /// undefined and the full turn is taken about z (glam interpolates linearly
            /// there through zero).
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            #[doc = concat!("use core::", stringify!($s), "::consts::PI;")]
            /// let end = Rotor::from_rotation_z(1.5 * PI); // the long way to a quarter turn back
            /// let half = Rotor::IDENTITY.slerp_long(end, 0.5);
            /// assert!((half - Rotor::from_rotation_z(0.75 * PI)).norm() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn slerp_long(self, end: Rotor, s: $s) -> Rotor {
                let d = self.reverse() * end;
                let length = (d.e12 * d.e12 + d.e13 * d.e13 + d.e23 * d.e23).sqrt();
                if length == 0.0 && d.s < 0.0 {
                    // `end = -self`: a full turn, about z.
                    return self * Rotor::from_rotation_z(s * 2.0 * ::core::$s::consts::PI);
                }
                let (sin, cos) = (s * length.atan2(d.s)).sin_cos();
                let k = if length > 0.0 { sin / length } else { s };
                self * Rotor::new(cos, k * d.e12, k * d.e13, k * d.e23)
            }

            /// The rotor of the orthonormal frame whose columns are `x_axis`, `y_axis`,
            /// `z_axis`, the images of `X`, `Y`, `Z` (glam's `Quat::from_rotation_axes`):
            /// [`from_mat3`](Self::from_mat3) of those columns, unchecked as glam's.
            #[inline]
            #[must_use]
            pub fn from_rotation_axes(
                x_axis: impl Into<Vector>,
                y_axis: impl Into<Vector>,
                z_axis: impl Into<Vector>,
            ) -> Rotor {
                let (x, y, z) = (x_axis.into(), y_axis.into(), z_axis.into());
                Rotor::from_mat3([x.to_array(), y.to_array(), z.to_array()])
            }

            /// The rotation about z taking the direction of the 2D vector `from` to that
            /// of `to`, the shorter way (glam's `Quat::from_rotation_arc_2d`; `from` and
            /// `to` are glam's `Vec2`/`DVec2` or `[x, y]`). As
            /// [`from_rotation_arc`](Self::from_rotation_arc): accurate near opposite
            /// vectors, non-unit input counts by its direction, and a zero input gives
            /// the zero rotor (glam: the identity). Exactly opposite vectors give the half
            /// turn about z, as glam's.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let r = Rotor::from_rotation_arc_2d([1.0, 0.0], [0.0, 1.0]);
            /// assert!((r.mul_vec3(Vector::X) - Vector::Y).norm() < 1e-6);
            /// assert_eq!(Rotor::from_rotation_arc_2d([1.0, 0.0], [-1.0, 0.0]), Rotor::from_xyzw(0.0, 0.0, 1.0, 0.0));
            /// ```
            #[inline]
            #[must_use]
            pub fn from_rotation_arc_2d(from: impl Into<[$s; 2]>, to: impl Into<[$s; 2]>) -> Rotor {
                let ([fx, fy], [tx, ty]) = (from.into(), to.into());
                let from = Vector::new(fx, fy, 0.0);
                let to = Vector::new(tx, ty, 0.0);
                if from == Vector::ZERO || to == Vector::ZERO {
                    return Rotor::ZERO;
                }
                // glam's quaternion (0, 0, z, w): z = |f||t| sin(angle), w = |f||t| + f.t.
                let (f, t) = (from.normalize(), to.normalize());
                let z = f.e1 * t.e2 - f.e2 * t.e1;
                let dot = f.dot(t);
                let w = if dot >= 0.0 {
                    1.0 + dot
                } else if z == 0.0 {
                    return Rotor::from_xyzw(0.0, 0.0, 1.0, 0.0);
                } else {
                    // (1 + dot)(1 - dot) = z^2, without the cancellation of 1 + dot.
                    z * z / (1.0 - dot)
                };
                let k = 1.0 / (z * z + w * w).sqrt();
                Rotor::from_xyzw(0.0, 0.0, z * k, w * k)
            }

            /// Whether every component is within `max_abs_diff` of `rhs`'s (glam's
            /// `Quat::abs_diff_eq`; `R` and `-R` differ here, as in glam).
            #[inline]
            #[must_use]
            pub fn abs_diff_eq(self, rhs: Rotor, max_abs_diff: $s) -> bool {
                (self - rhs).iter().all(|d| d.abs() <= max_abs_diff)
            }
        }

        /// glam's names whose inputs or outputs are glam's types (feature `glam`).
        #[cfg(feature = "glam")]
        impl Vector {
            /// glam's 4-vector `(x, y, z, w)` (glam's `Vec3::extend`): there is no
            /// 4-vector type in G3, so this exists only with the `glam` feature.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let v = Vector::new(1.0, 2.0, 3.0).extend(4.0);
            /// assert_eq!(v.to_array(), [1.0, 2.0, 3.0, 4.0]);
            /// ```
            #[inline]
            #[must_use]
            pub fn extend(self, w: $s) -> crate::glam::$vec4 {
                crate::glam::$vec4::new(self.e1, self.e2, self.e3, w)
            }
        }

        /// glam's names whose inputs are glam's types (feature `glam`).
        #[cfg(feature = "glam")]
        impl Rotor {
            /// The rotor of glam's 4-vector `(x, y, z, w)` (glam's `Quat::from_vec4`),
            /// not normalised.
            #[inline]
            #[must_use]
            pub fn from_vec4(v: crate::glam::$vec4) -> Rotor {
                Rotor::from_xyzw(v.x, v.y, v.z, v.w)
            }

            /// The rotor of the upper-left 3x3 block of a 4x4 matrix (glam's
            /// `Quat::from_mat4`; translation and projection are ignored), unchecked as
            /// glam's; [`from_matrix`](Self::from_matrix) is the checked form.
            #[inline]
            #[must_use]
            pub fn from_mat4(mat: &crate::glam::$mat4) -> Rotor {
                Rotor::from_mat3(mat)
            }

            /// The rotor of the 3x3 part of an affine transform (glam's
            /// `Quat::from_affine3`), unchecked as glam's.
            #[inline]
            #[must_use]
            pub fn from_affine3(a: &crate::glam::$affine3) -> Rotor {
                Rotor::from_mat3(a.matrix3)
            }
        }

        /// glam's 4-vector `(x, y, z, w)` of a rotor (glam's `From<Quat> for Vec4`), the
        /// inverse of [`Rotor::from_vec4`].
        #[cfg(feature = "glam")]
        impl From<Rotor> for crate::glam::$vec4 {
            #[inline]
            fn from(r: Rotor) -> crate::glam::$vec4 {
                let [x, y, z, w] = r.to_xyzw();
                crate::glam::$vec4::new(x, y, z, w)
            }
        }

        /// glam's `Mat3 * Vec3` with a `Vector`: the matrix (column-major) times the
        /// vector, so that a ported program that keeps glam's matrices can apply them to
        /// `Vector`s.
        #[cfg(feature = "glam")]
        impl ::core::ops::Mul<Vector> for crate::glam::$mat3 {
            type Output = Vector;
            #[inline]
            fn mul(self, v: Vector) -> Vector {
                Vector::from(self.mul_vec3(v.into()))
            }
        }

        /// glam's `Mat3 * &Vec3` with a `Vector`: as `Mat3 * Vector`.
        #[cfg(feature = "glam")]
        impl ::core::ops::Mul<&Vector> for crate::glam::$mat3 {
            type Output = Vector;
            #[inline]
            fn mul(self, v: &Vector) -> Vector {
                self * *v
            }
        }

        /// glam's `&Mat3 * Vec3` with a `Vector`: as `Mat3 * Vector`.
        #[cfg(feature = "glam")]
        impl ::core::ops::Mul<Vector> for &crate::glam::$mat3 {
            type Output = Vector;
            #[inline]
            fn mul(self, v: Vector) -> Vector {
                *self * v
            }
        }

        /// glam's `&Mat3 * &Vec3` with a `Vector`: as `Mat3 * Vector`.
        #[cfg(feature = "glam")]
        impl ::core::ops::Mul<&Vector> for &crate::glam::$mat3 {
            type Output = Vector;
            #[inline]
            fn mul(self, v: &Vector) -> Vector {
                *self * *v
            }
        }
    };
}

#[cfg(all(feature = "g3", feature = "f64"))]
pub(crate) mod g3_f64 {
    glam_vocabulary!(f64, dquat, dvec3, DVec4, DMat3, DMat4, DAffine3);
}

#[cfg(all(feature = "g3", feature = "f32"))]
pub(crate) mod g3_f32 {
    glam_vocabulary!(f32, quat, vec3, Vec4, Mat3, Mat4, Affine3);
}

/// glam's SIMD-aligned f32 types as inputs (feature `glam`): `Vec3A`, `Mat3A`, `Affine3A`.
#[cfg(all(feature = "g3", feature = "f32", feature = "glam"))]
mod g3_f32_aligned {
    use crate::f32::g3::{Rotor, Vector};
    use crate::glam::{Affine3A, Mat3A, Vec3A};
    use crate::RotationMatrix;

    impl From<Vec3A> for Vector {
        #[inline]
        fn from(v: Vec3A) -> Vector {
            Vector::new(v.x, v.y, v.z)
        }
    }

    impl From<Vector> for Vec3A {
        #[inline]
        fn from(v: Vector) -> Vec3A {
            Vec3A::new(v.e1, v.e2, v.e3)
        }
    }

    /// glam's `Mat3A::from_quat`: the matrix of `x -> R x ~R` (for a unit rotor), as
    /// `Mat3::from(r)`.
    impl From<Rotor> for Mat3A {
        #[inline]
        fn from(r: Rotor) -> Mat3A {
            Mat3A::from(crate::glam::Mat3::from(r))
        }
    }

    /// So that `from_mat3`, `from_matrix` take glam's `Mat3A` as they take its `Mat3`.
    impl RotationMatrix<f32> for Mat3A {
        #[inline]
        fn to_cols_array_2d(&self) -> [[f32; 3]; 3] {
            Mat3A::to_cols_array_2d(self)
        }
    }

    impl Rotor {
        /// `R v ~R` for glam's `Vec3A` (glam's `Quat::mul_vec3a`).
        ///
        /// ```
        /// use ga_core::f32::g3::*;
        /// use ga_core::glam::Vec3A;
        /// let r = Rotor::from_rotation_z(core::f32::consts::FRAC_PI_2);
        /// assert!(r.mul_vec3a(Vec3A::X).abs_diff_eq(Vec3A::Y, 1e-6));
        /// ```
        #[inline]
        #[must_use]
        pub fn mul_vec3a(self, rhs: Vec3A) -> Vec3A {
            self.mul_vec3(rhs)
        }

        /// The rotor of glam's `Mat3A` (glam's `Quat::from_mat3a`), unchecked as glam's.
        #[inline]
        #[must_use]
        pub fn from_mat3a(mat: &Mat3A) -> Rotor {
            Rotor::from_mat3(mat)
        }

        /// The rotor of the 3x3 part of glam's `Affine3A` (glam's
        /// `Quat::from_affine3a`), unchecked as glam's.
        #[inline]
        #[must_use]
        pub fn from_affine3a(a: &Affine3A) -> Rotor {
            Rotor::from_mat3(a.matrix3)
        }
    }
}

/// glam's precision casts `as_dquat`, `as_quat`, `as_dvec3`, `as_vec3`, the same as
/// `as_f64` and `as_f32`.
#[cfg(all(feature = "g3", feature = "f32", feature = "f64"))]
mod g3_casts {
    use crate::{f32, f64};

    impl f32::g3::Rotor {
        /// This rotor in f64 (glam's `Quat::as_dquat`, the same as `as_f64`).
        #[inline]
        #[must_use]
        pub fn as_dquat(self) -> f64::g3::Rotor {
            self.as_f64()
        }
    }

    impl f64::g3::Rotor {
        /// This rotor in f32 (glam's `DQuat::as_quat`, the same as `as_f32`).
        #[inline]
        #[must_use]
        pub fn as_quat(self) -> f32::g3::Rotor {
            self.as_f32()
        }
    }

    impl f32::g3::Vector {
        /// This vector in f64 (glam's `Vec3::as_dvec3`, the same as `as_f64`).
        #[inline]
        #[must_use]
        pub fn as_dvec3(self) -> f64::g3::Vector {
            self.as_f64()
        }
    }

    impl f64::g3::Vector {
        /// This vector in f32 (glam's `DVec3::as_vec3`, the same as `as_f32`).
        #[inline]
        #[must_use]
        pub fn as_vec3(self) -> f32::g3::Vector {
            self.as_f32()
        }
    }
}
