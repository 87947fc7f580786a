//! The rest of glam's `Vec3` vocabulary on G3's `Vector`: the component-wise functions
//! (rounding, `exp`, `powf`, `sin`, `signum`, `clamp`, ...), length clamps, interpolation
//! and the masks, with glam's formulas, so that a ported program that uses them keeps
//! compiling and gets glam's numbers (`glam_vocabulary.rs` has the geometric names; the
//! table in docs/glam.md lists both). A component-wise function is not a geometric-algebra
//! operation (`v.exp()` is not the exponential of the vector), which is why these live
//! apart, under glam's names only.

/// Methods of `Vector` that apply one function of the scalar to each component, each
/// with its doc line: `name => function;`.
// Unused when no precision is on.
#[allow(unused_macros)]
macro_rules! each_component {
    ($($(#[$doc:meta])* $name:ident => $f:expr;)*) => {
        $(
            $(#[$doc])*
            #[inline]
            #[must_use]
            pub fn $name(self) -> Vector {
                each(self, $f)
            }
        )*
    };
}

// Unused when no precision is on.
#[allow(unused_macros)]
macro_rules! glam_componentwise {
    ($s:ident, $vec2:ident, $vec4:ident) => {
        #[cfg(not(feature = "std"))]
        #[allow(unused_imports)]
        use crate::rotor::no_std_math::Real as _;
        use crate::$s::g3::{Rotor, Vector};

        /// `f` on each component.
        #[inline(always)]
        fn each(v: Vector, f: impl Fn($s) -> $s) -> Vector {
            Vector::new(f(v.e1), f(v.e2), f(v.e3))
        }

        /// `f` on each pair of components.
        #[inline(always)]
        fn pairs(a: Vector, b: Vector, f: impl Fn($s, $s) -> $s) -> Vector {
            Vector::new(f(a.e1, b.e1), f(a.e2, b.e2), f(a.e3, b.e3))
        }

        /// `v` scaled to the length `target`, as glam writes it: `target (v / |v|)`, with
        /// `|v|^2` given.
        #[inline(always)]
        fn rescaled(v: Vector, length_squared: $s, target: $s) -> Vector {
            let length = length_squared.sqrt();
            each(v, |c| target * (c / length))
        }

        impl Vector {
            each_component! {
                /// Each component rounded down (glam's `floor`).
                floor => $s::floor;
                /// Each component rounded up (glam's `ceil`).
                ceil => $s::ceil;
                /// Each component rounded to the nearest integer, halves away from zero
                /// (glam's `round`).
                round => $s::round;
                /// Each component's integer part, towards zero (glam's `trunc`).
                trunc => $s::trunc;
                /// Each component's sign: `1`, `-1` (for `-0.0` too) or NaN (glam's `signum`).
                signum => $s::signum;
                /// `1 / c` for each component (glam's `recip`).
                recip => |c| 1.0 / c;
                /// Each component's square root (glam's `sqrt`).
                sqrt => $s::sqrt;
                /// `e^c` for each component (glam's `exp`; not a geometric exponential,
                /// such as `Bivector::exp`, the rotor of a plane and angle).
                exp => $s::exp;
                /// `2^c` for each component (glam's `exp2`).
                exp2 => $s::exp2;
                /// The natural logarithm of each component (glam's `ln`).
                ln => $s::ln;
                /// The base-2 logarithm of each component (glam's `log2`).
                log2 => $s::log2;
                /// The sine of each component (glam's `sin`).
                sin => $s::sin;
                /// The cosine of each component (glam's `cos`).
                cos => $s::cos;
            }

            /// `self - self.trunc()` (glam's `fract`, Rust's convention: negative for
            /// negative components).
            #[inline]
            #[must_use]
            pub fn fract(self) -> Vector {
                self - self.trunc()
            }

            /// `self - self.floor()` (glam's `fract_gl`, GLSL's `fract`: in `[0, 1)`).
            #[inline]
            #[must_use]
            pub fn fract_gl(self) -> Vector {
                self - self.floor()
            }

            /// Each component's magnitude with the sign of `rhs`'s (glam's `copysign`).
            #[inline]
            #[must_use]
            pub fn copysign(self, rhs: Vector) -> Vector {
                pairs(self, rhs, $s::copysign)
            }

            /// `c^n` for each component (glam's `powf`).
            #[inline]
            #[must_use]
            pub fn powf(self, n: $s) -> Vector {
                each(self, |c| c.powf(n))
            }

            /// The sines and the cosines of the components (glam's `sin_cos`).
            #[inline]
            #[must_use]
            pub fn sin_cos(self) -> (Vector, Vector) {
                let [(s1, c1), (s2, c2), (s3, c3)] = [self.e1, self.e2, self.e3].map($s::sin_cos);
                (Vector::new(s1, s2, s3), Vector::new(c1, c2, c3))
            }

            /// `self * a + b` per component with one rounding (glam's `mul_add`, a fused
            /// multiply-add; slow where the CPU has no FMA instruction).
            #[inline]
            #[must_use]
            pub fn mul_add(self, a: Vector, b: Vector) -> Vector {
                Vector::new(
                    self.e1.mul_add(a.e1, b.e1),
                    self.e2.mul_add(a.e2, b.e2),
                    self.e3.mul_add(a.e3, b.e3),
                )
            }

            /// The Euclidean remainder of each component by `rhs`'s, in `[0, |rhs|)`
            /// (glam's `rem_euclid`).
            #[inline]
            #[must_use]
            pub fn rem_euclid(self, rhs: Vector) -> Vector {
                pairs(self, rhs, $s::rem_euclid)
            }

            /// The Euclidean quotient of each component by `rhs`'s (glam's `div_euclid`).
            #[inline]
            #[must_use]
            pub fn div_euclid(self, rhs: Vector) -> Vector {
                pairs(self, rhs, $s::div_euclid)
            }

            /// `f` applied to each component (glam's `map`).
            #[inline]
            #[must_use]
            pub fn map(self, f: impl Fn($s) -> $s) -> Vector {
                each(self, f)
            }

            /// `x + y + z` (glam's `element_sum`).
            #[inline]
            #[must_use]
            pub fn element_sum(self) -> $s {
                self.e1 + self.e2 + self.e3
            }

            /// `x y z` (glam's `element_product`).
            #[inline]
            #[must_use]
            pub fn element_product(self) -> $s {
                self.e1 * self.e2 * self.e3
            }

            /// The index of the largest component, the first of equals (glam's
            /// `max_position`; a NaN is never the largest).
            #[inline]
            #[must_use]
            pub fn max_position(self) -> usize {
                let (mut max, mut index) = (self.e1, 0);
                if self.e2 > max {
                    (max, index) = (self.e2, 1);
                }
                if self.e3 > max {
                    index = 2;
                }
                index
            }

            /// The index of the smallest component, the first of equals (glam's
            /// `min_position`).
            #[inline]
            #[must_use]
            pub fn min_position(self) -> usize {
                let (mut min, mut index) = (self.e1, 0);
                if self.e2 < min {
                    (min, index) = (self.e2, 1);
                }
                if self.e3 < min {
                    index = 2;
                }
                index
            }

            /// `(self + rhs) / 2` (glam's `midpoint`).
            #[inline]
            #[must_use]
            pub fn midpoint(self, rhs: Vector) -> Vector {
                (self + rhs) * 0.5
            }

            /// `self` moved by `d` towards `rhs`, or `rhs` when it is at most `d` away
            /// (or closer than `1e-4`) (glam's `move_towards`).
            #[inline]
            #[must_use]
            pub fn move_towards(self, rhs: Vector, d: $s) -> Vector {
                let a = rhs - self;
                let length = a.length();
                if length <= d || length <= 1e-4 {
                    return rhs;
                }
                self + each(a, |c| c / length * d)
            }

            /// `self` with `x` replaced (glam's `with_x`).
            #[inline]
            #[must_use]
            pub fn with_x(self, x: $s) -> Vector {
                Vector::new(x, self.e2, self.e3)
            }

            /// `self` with `y` replaced (glam's `with_y`).
            #[inline]
            #[must_use]
            pub fn with_y(self, y: $s) -> Vector {
                Vector::new(self.e1, y, self.e3)
            }

            /// `self` with `z` replaced (glam's `with_z`).
            #[inline]
            #[must_use]
            pub fn with_z(self, z: $s) -> Vector {
                Vector::new(self.e1, self.e2, z)
            }

            /// Each component limited to `[min, max]`'s (glam's `clamp`: `self.max(min)
            /// .min(max)`, so a NaN component becomes `max`'s).
            #[inline]
            #[must_use]
            pub fn clamp(self, min: Vector, max: Vector) -> Vector {
                self.max(min).min(max)
            }

            /// Each component limited to `[0, 1]` (glam's `saturate`).
            #[inline]
            #[must_use]
            pub fn saturate(self) -> Vector {
                self.clamp(Vector::ZERO, Vector::ONE)
            }

            /// `self` with its length limited to `[min, max]` (glam's `clamp_length`;
            /// the zero vector below a positive `min` gives NaN, as glam's).
            #[inline]
            #[must_use]
            pub fn clamp_length(self, min: $s, max: $s) -> Vector {
                let length_squared = self.length_squared();
                if length_squared < min * min {
                    rescaled(self, length_squared, min)
                } else if length_squared > max * max {
                    rescaled(self, length_squared, max)
                } else {
                    self
                }
            }

            /// `self` with its length at most `max` (glam's `clamp_length_max`).
            #[inline]
            #[must_use]
            pub fn clamp_length_max(self, max: $s) -> Vector {
                let length_squared = self.length_squared();
                if length_squared > max * max {
                    rescaled(self, length_squared, max)
                } else {
                    self
                }
            }

            /// `self` with its length at least `min` (glam's `clamp_length_min`).
            #[inline]
            #[must_use]
            pub fn clamp_length_min(self, min: $s) -> Vector {
                let length_squared = self.length_squared();
                if length_squared < min * min {
                    rescaled(self, length_squared, min)
                } else {
                    self
                }
            }

            /// `self / |self|`, or `None` for a zero, non-finite or overflowing length
            /// (glam's `try_normalize`; [`try_normalized`](Self::try_normalized) is the
            /// algebra's form, which scales first and so normalises vectors whose squared
            /// length overflows or underflows).
            #[inline]
            #[must_use]
            pub fn try_normalize(self) -> Option<Vector> {
                let recip = self.length_recip();
                if recip.is_finite() && recip > 0.0 {
                    Some(self * recip)
                } else {
                    None
                }
            }

            /// `(self / |self|, |self|)`, or `(X, 0)` where glam's `try_normalize` gives
            /// `None` (glam's `normalize_and_length`).
            #[inline]
            #[must_use]
            pub fn normalize_and_length(self) -> (Vector, $s) {
                let length = self.length();
                let recip = 1.0 / length;
                if recip.is_finite() && recip > 0.0 {
                    (self * recip, length)
                } else {
                    (Vector::X, 0.0)
                }
            }

            /// The dot product in every component (glam's `dot_into_vec`).
            #[inline]
            #[must_use]
            pub fn dot_into_vec(self, rhs: Vector) -> Vector {
                Vector::splat(self.dot(rhs))
            }

            /// The unit `self` refracted at a surface of unit `normal` with the ratio of
            /// indices `eta`, or zero at total internal reflection (glam's `refract`,
            /// GLSL's formula).
            #[inline]
            #[must_use]
            pub fn refract(self, normal: Vector, eta: $s) -> Vector {
                let n_dot_i = normal.dot(self);
                let k = 1.0 - eta * eta * (1.0 - n_dot_i * n_dot_i);
                if k >= 0.0 {
                    self * eta - normal * (eta * n_dot_i + k.sqrt())
                } else {
                    Vector::ZERO
                }
            }

            /// `0` where `rhs`'s component is below `self`'s, else `1` (glam's `step`;
            /// GLSL's `step(edge, x)` is `edge.step(x)`).
            #[inline]
            #[must_use]
            pub fn step(self, rhs: Vector) -> Vector {
                pairs(self, rhs, |edge, x| if x < edge { 0.0 } else { 1.0 })
            }

            /// Hermite interpolation `t^2 (3 - 2t)` of `t`, `self` placed in `[edge0,
            /// edge1]` and clamped to `[0, 1]`, per component (glam 0.33's `smoothstep`).
            #[inline]
            #[must_use]
            pub fn smoothstep(self, edge0: Vector, edge1: Vector) -> Vector {
                let t = pairs(self - edge0, edge1 - edge0, |a, b| a / b).saturate();
                each(t, |t| t * t * (3.0 - 2.0 * t))
            }

            /// `self + (rhs - self) s` (glam 0.33's `lerp_monotonic`): equal inputs
            /// stay exact and the result is monotonic in `s`; [`lerp`](Self::lerp) is
            /// the more accurate for inputs far apart.
            #[inline]
            #[must_use]
            pub fn lerp_monotonic(self, rhs: Vector, s: $s) -> Vector {
                self + (rhs - self) * s
            }

            /// The signed angle in `[-pi, pi]` from `self` to `rhs` about the unit
            /// `axis`, right-handed (glam 0.33's `angle_to`): `atan2((self x rhs) . axis,
            /// self . rhs)`, so that `self.rotate_axis(axis, angle)` points along `rhs`
            /// when both are perpendicular to `axis`.
            #[doc(alias = "signed_angle")]
            #[inline]
            #[must_use]
            pub fn angle_to(self, rhs: Vector, axis: Vector) -> $s {
                self.cross(rhs).dot(axis).atan2(self.dot(rhs))
            }

            /// The sign bits of `x`, `y`, `z` as bits 0, 1, 2, so that `-0.0` and a
            /// negative NaN count as negative (glam's `is_negative_bitmask`).
            #[inline]
            #[must_use]
            pub fn is_negative_bitmask(self) -> u32 {
                u32::from(self.e1.is_sign_negative())
                    | (u32::from(self.e2.is_sign_negative()) << 1)
                    | (u32::from(self.e3.is_sign_negative()) << 2)
            }

            /// Spherical interpolation from `self` (`s = 0`) to `rhs` (`s = 1`): the
            /// direction turns at a constant rate in their plane, the length goes
            /// linearly (glam's `slerp`, with its cases: nearly opposite vectors turn
            /// about `any_orthogonal_vector`, nearly parallel ones, or a zero one,
            /// interpolate linearly). The angle comes from `atan2`, not glam's polynomial
            /// `acos`, so results agree with glam's to about `1e-6` of their length in
            /// f32.
            #[inline]
            #[must_use]
            pub fn slerp(self, rhs: Vector, s: $s) -> Vector {
                let (self_length, rhs_length) = (self.length(), rhs.length());
                let cos = self.dot(rhs) / (self_length * rhs_length);
                let result_length = self_length + (rhs_length - self_length) * s;
                if cos.abs() < 1.0 - 3e-7 {
                    let theta = self.cross(rhs).length().atan2(self.dot(rhs));
                    let (t1, t2) = ((theta * (1.0 - s)).sin(), (theta * s).sin());
                    let recip = 1.0 / theta.sin();
                    return (self * (result_length / self_length) * t1
                        + rhs * (result_length / rhs_length) * t2)
                        * recip;
                }
                if cos < 0.0 {
                    let axis = self.any_orthogonal_vector().normalize();
                    let turn = Rotor::from_axis_angle(axis, core::$s::consts::PI * s);
                    turn.mul_vec3(self) * (result_length / self_length)
                } else {
                    self.lerp(rhs, s)
                }
            }
        }

        /// glam's names whose results are glam's types (feature `glam`).
        #[cfg(feature = "glam")]
        impl Vector {
            /// `(x, y)` (glam's `truncate`), glam's 2-vector.
            #[inline]
            #[must_use]
            pub fn truncate(self) -> crate::glam::$vec2 {
                crate::glam::$vec2::new(self.e1, self.e2)
            }

            /// `(x, y, z, 1)` (glam's `to_homogeneous`), glam's 4-vector.
            #[inline]
            #[must_use]
            pub fn to_homogeneous(self) -> crate::glam::$vec4 {
                self.extend(1.0)
            }

            /// `(x, y, z) / w` (glam's `from_homogeneous`).
            #[inline]
            #[must_use]
            pub fn from_homogeneous(v: crate::glam::$vec4) -> Vector {
                Vector::new(v.x / v.w, v.y / v.w, v.z / v.w)
            }

            /// `self == rhs` per component, as glam's mask (glam's `cmpeq`).
            #[inline]
            #[must_use]
            pub fn cmpeq(self, rhs: Vector) -> crate::glam::BVec3 {
                mask(self, rhs, |a, b| a == b)
            }

            /// `self != rhs` per component (glam's `cmpne`).
            #[inline]
            #[must_use]
            pub fn cmpne(self, rhs: Vector) -> crate::glam::BVec3 {
                mask(self, rhs, |a, b| a != b)
            }

            /// `self >= rhs` per component (glam's `cmpge`).
            #[inline]
            #[must_use]
            pub fn cmpge(self, rhs: Vector) -> crate::glam::BVec3 {
                mask(self, rhs, |a, b| a >= b)
            }

            /// `self > rhs` per component (glam's `cmpgt`).
            #[inline]
            #[must_use]
            pub fn cmpgt(self, rhs: Vector) -> crate::glam::BVec3 {
                mask(self, rhs, |a, b| a > b)
            }

            /// `self <= rhs` per component (glam's `cmple`).
            #[inline]
            #[must_use]
            pub fn cmple(self, rhs: Vector) -> crate::glam::BVec3 {
                mask(self, rhs, |a, b| a <= b)
            }

            /// `self < rhs` per component (glam's `cmplt`).
            #[inline]
            #[must_use]
            pub fn cmplt(self, rhs: Vector) -> crate::glam::BVec3 {
                mask(self, rhs, |a, b| a < b)
            }

            /// `if_true`'s component where `mask` is set, else `if_false`'s (glam's
            /// `select`).
            #[inline]
            #[must_use]
            pub fn select(mask: crate::glam::BVec3, if_true: Vector, if_false: Vector) -> Vector {
                let pick = |i: usize, a: $s, b: $s| if mask.test(i) { a } else { b };
                Vector::new(
                    pick(0, if_true.e1, if_false.e1),
                    pick(1, if_true.e2, if_false.e2),
                    pick(2, if_true.e3, if_false.e3),
                )
            }

            /// Which components are NaN (glam's `is_nan_mask`).
            #[inline]
            #[must_use]
            pub fn is_nan_mask(self) -> crate::glam::BVec3 {
                mask(self, self, |a, _| a.is_nan())
            }

            /// Which components are finite (glam's `is_finite_mask`).
            #[inline]
            #[must_use]
            pub fn is_finite_mask(self) -> crate::glam::BVec3 {
                mask(self, self, |a, _| a.is_finite())
            }

            /// Which components have the sign bit set, `-0.0` included (glam 0.33's
            /// `is_negative_mask`).
            #[inline]
            #[must_use]
            pub fn is_negative_mask(self) -> crate::glam::BVec3 {
                mask(self, self, |a, _| a.is_sign_negative())
            }
        }

        /// `test` on each pair of components, as glam's mask.
        #[cfg(feature = "glam")]
        #[inline(always)]
        fn mask(a: Vector, b: Vector, test: impl Fn($s, $s) -> bool) -> crate::glam::BVec3 {
            crate::glam::BVec3::new(test(a.e1, b.e1), test(a.e2, b.e2), test(a.e3, b.e3))
        }
    };
}

#[cfg(all(feature = "g3", feature = "f64"))]
mod g3_f64 {
    glam_componentwise!(f64, DVec2, DVec4);
}

#[cfg(all(feature = "g3", feature = "f32"))]
mod g3_f32 {
    glam_componentwise!(f32, Vec2, Vec4);
}
