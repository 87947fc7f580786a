//! glam's `Vec3` and `Quat` vocabulary on G3's `Vector` and `Rotor`, with glam's meanings
//! (for the same inputs, glam's result, up to the sign of a rotor), so that code ported
//! from glam keeps working by name. The mapping is `w = s, x = -e23, y = e13, z = -e12`
//! (docs/derivations/rotor-quaternion.md). What differs on purpose is listed in
//! docs/glam.md with the reason.

// Unused when no precision is on.
#[allow(unused_macros)]
macro_rules! glam_vocabulary {
    ($s:ident) => {
        #[cfg(not(feature = "std"))]
        #[allow(unused_imports)]
        use crate::rotor::no_std_math::Real as _;
        use crate::$s::g3::{Rotor, Sandwich, Vector};

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

        impl Rotor {
            /// The identity rotation (glam's `Quat::IDENTITY`), the same as `Rotor::ONE`.
            /// `Rotor::default()` is the zero rotor, not this: see docs/glam.md.
            pub const IDENTITY: Rotor = Rotor::ONE;

            /// The rotor of glam's quaternion `(x, y, z, w)` (glam's `from_xyzw`):
            /// `w - z e12 + y e13 - x e23`.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// assert_eq!(Rotor::from_xyzw(0.0, 0.0, 0.0, 1.0), Rotor::IDENTITY);
            /// ```
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
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let r = Rotor::from_rotation_z(1.0);
            /// assert_eq!(r.mul_vec3(Vector::X), r.sandwich(Vector::X));
            /// ```
            #[inline]
            #[must_use]
            pub fn mul_vec3(self, v: Vector) -> Vector {
                self.sandwich(v)
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
    };
}

#[cfg(all(feature = "g3", feature = "f64"))]
mod g3_f64 {
    glam_vocabulary!(f64);
}

#[cfg(all(feature = "g3", feature = "f32"))]
mod g3_f32 {
    glam_vocabulary!(f32);
}
