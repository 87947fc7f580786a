//! The rotor toolkit of G3 (and G2's share of it) with glam's names and argument order,
//! so that a user of `Quat` finds `from_axis_angle`, `from_rotation_arc`, `slerp`, ...
//!
//! Conventions (README): a rotor acts as `y = R x ~R`. An axis `a` stands for the plane
//! `I a` (`I = e1e2e3`; `I e3 = e12`) and a positive angle turns by the right-hand rule:
//! `from_axis_angle(e3, theta)` is `exp(-e12 theta / 2)`, which turns e1 toward e2, and
//! equals glam's `Quat::from_axis_angle(Vec3::Z, theta)` under `w = s, x = -e23,
//! y = e13, z = -e12`. Inputs documented as unit must be unit (glam asserts the same).
//! Non-finite input gives non-finite output (NaN propagates); zero input is stated on
//! each method; `from_matrix` and the `look_*` constructors, whose input can fail in
//! ordinary use, return `Option`. glam's Quat and Vec3 vocabulary beyond this file is in
//! `glam_vocabulary.rs`; what differs from glam on purpose is in docs/glam.md.

/// A 3x3 rotation matrix that [`Rotor::from_matrix`](crate::f64::g3::Rotor::from_matrix)
/// accepts: a column-major `[[S; 3]; 3]` (glam's `to_cols_array_2d` layout) and, under the
/// `glam` feature, glam's `Mat3`/`DMat3`.
///
/// ```
/// use ga_core::RotationMatrix;
/// let m = [[1.0f64, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// assert_eq!(m.to_cols_array_2d()[1][1], 1.0);
/// ```
#[cfg(feature = "g3")]
pub trait RotationMatrix<S> {
    /// The columns, each the image of e1, e2 and e3 in turn.
    fn to_cols_array_2d(&self) -> [[S; 3]; 3];
}

#[cfg(feature = "g3")]
impl<S: Copy> RotationMatrix<S> for [[S; 3]; 3] {
    #[inline]
    fn to_cols_array_2d(&self) -> [[S; 3]; 3] {
        *self
    }
}

/// A reference to a matrix, so that `Rotor::from_mat3(&m)` reads as glam's `Quat::from_mat3(&m)`.
#[cfg(feature = "g3")]
impl<S, M: RotationMatrix<S> + ?Sized> RotationMatrix<S> for &M {
    #[inline]
    fn to_cols_array_2d(&self) -> [[S; 3]; 3] {
        (**self).to_cols_array_2d()
    }
}

/// glam's matrices as [`RotationMatrix`], for every glam version a feature turns on.
macro_rules! glam_rotation_matrices {
    ($($feature:literal => $glam:ident),*) => {
        $(
            #[cfg(all(feature = $feature, feature = "g3"))]
            impl RotationMatrix<f32> for crate::$glam::Mat3 {
                #[inline]
                fn to_cols_array_2d(&self) -> [[f32; 3]; 3] {
                    crate::$glam::Mat3::to_cols_array_2d(self)
                }
            }

            #[cfg(all(feature = $feature, feature = "g3"))]
            impl RotationMatrix<f64> for crate::$glam::DMat3 {
                #[inline]
                fn to_cols_array_2d(&self) -> [[f64; 3]; 3] {
                    crate::$glam::DMat3::to_cols_array_2d(self)
                }
            }

            /// The upper-left 3x3 block (the translation and projection row are ignored).
            #[cfg(all(feature = $feature, feature = "g3"))]
            impl RotationMatrix<f32> for crate::$glam::Mat4 {
                #[inline]
                fn to_cols_array_2d(&self) -> [[f32; 3]; 3] {
                    crate::$glam::Mat3::from_mat4(*self).to_cols_array_2d()
                }
            }

            /// The upper-left 3x3 block (the translation and projection row are ignored).
            #[cfg(all(feature = $feature, feature = "g3"))]
            impl RotationMatrix<f64> for crate::$glam::DMat4 {
                #[inline]
                fn to_cols_array_2d(&self) -> [[f64; 3]; 3] {
                    crate::$glam::DMat3::from_mat4(*self).to_cols_array_2d()
                }
            }
        )*
    };
}

glam_rotation_matrices!(
    "glam-0-29" => glam_0_29,
    "glam-0-30" => glam_0_30,
    "glam-0-31" => glam_0_31,
    "glam-0-32" => glam_0_32,
    "glam-0-33" => glam_0_33
);

/// Without the standard library, the float functions the toolkit calls come from libm
/// (with it, the inherent methods of the same names take precedence).
#[cfg(not(feature = "std"))]
pub(crate) mod no_std_math {
    /// The float functions of the toolkit, for `f32` and `f64`.
    // Which of them a build calls depends on the algebras its features turn on.
    #[allow(dead_code)]
    pub(crate) trait Real: Sized {
        fn sqrt(self) -> Self;
        fn sin_cos(self) -> (Self, Self);
        fn atan2(self, other: Self) -> Self;
        fn acos(self) -> Self;
        fn floor(self) -> Self;
        fn ceil(self) -> Self;
        fn round(self) -> Self;
        fn trunc(self) -> Self;
        fn exp(self) -> Self;
        fn exp2(self) -> Self;
        fn ln(self) -> Self;
        fn log2(self) -> Self;
        fn powf(self, n: Self) -> Self;
        fn sin(self) -> Self;
        fn cos(self) -> Self;
        fn mul_add(self, a: Self, b: Self) -> Self;
        /// As std's: `self % rhs`, moved into `[0, |rhs|)`.
        fn rem_euclid(self, rhs: Self) -> Self;
        /// As std's: the quotient that goes with `rem_euclid`.
        fn div_euclid(self, rhs: Self) -> Self;
    }

    /// `Real` for one float type from libm's functions of that type, named in the trait's
    /// order.
    macro_rules! libm_real {
        (
            $t:ident: $sqrt:ident, $sincos:ident, $atan2:ident, $acos:ident, $floor:ident,
            $ceil:ident, $round:ident, $trunc:ident, $exp:ident, $exp2:ident, $ln:ident,
            $log2:ident, $pow:ident, $sin:ident, $cos:ident, $fma:ident
        ) => {
            impl Real for $t {
                fn sqrt(self) -> $t {
                    crate::libm::$sqrt(self)
                }
                fn sin_cos(self) -> ($t, $t) {
                    crate::libm::$sincos(self)
                }
                fn atan2(self, other: $t) -> $t {
                    crate::libm::$atan2(self, other)
                }
                fn acos(self) -> $t {
                    crate::libm::$acos(self)
                }
                fn floor(self) -> $t {
                    crate::libm::$floor(self)
                }
                fn ceil(self) -> $t {
                    crate::libm::$ceil(self)
                }
                fn round(self) -> $t {
                    crate::libm::$round(self)
                }
                fn trunc(self) -> $t {
                    crate::libm::$trunc(self)
                }
                fn exp(self) -> $t {
                    crate::libm::$exp(self)
                }
                fn exp2(self) -> $t {
                    crate::libm::$exp2(self)
                }
                fn ln(self) -> $t {
                    crate::libm::$ln(self)
                }
                fn log2(self) -> $t {
                    crate::libm::$log2(self)
                }
                fn powf(self, n: $t) -> $t {
                    crate::libm::$pow(self, n)
                }
                fn sin(self) -> $t {
                    crate::libm::$sin(self)
                }
                fn cos(self) -> $t {
                    crate::libm::$cos(self)
                }
                fn mul_add(self, a: $t, b: $t) -> $t {
                    crate::libm::$fma(self, a, b)
                }
                fn rem_euclid(self, rhs: $t) -> $t {
                    let r = self % rhs;
                    if r < 0.0 {
                        r + rhs.abs()
                    } else {
                        r
                    }
                }
                fn div_euclid(self, rhs: $t) -> $t {
                    let q = Real::trunc(self / rhs);
                    if self % rhs < 0.0 {
                        return if rhs > 0.0 { q - 1.0 } else { q + 1.0 };
                    }
                    q
                }
            }
        };
    }

    libm_real!(
        f64: sqrt, sincos, atan2, acos, floor, ceil, round, trunc, exp, exp2, log, log2, pow, sin,
        cos, fma
    );
    libm_real!(
        f32: sqrtf, sincosf, atan2f, acosf, floorf, ceilf, roundf, truncf, expf, exp2f, logf,
        log2f, powf, sinf, cosf, fmaf
    );
}

#[cfg(feature = "g3")]
// Unused when no precision is on.
#[allow(unused_macros)]
macro_rules! rotor3_toolkit {
    ($s:ident) => {
        #[cfg(not(feature = "std"))]
        #[allow(unused_imports)]
        use super::no_std_math::Real as _;
        use super::RotationMatrix;
        use crate::$s::g3::{Rotor, Vector};

        /// A unit vector perpendicular to the unit `v`, by Duff et al., "Building an
        /// orthonormal basis, revisited", JCGT 6(1), 2017 (no branch on a near-zero
        /// component).
        fn any_orthonormal(v: Vector) -> Vector {
            let sign = (1.0 as $s).copysign(v.e3);
            let a = -1.0 / (sign + v.e3);
            let b = v.e1 * v.e2 * a;
            Vector::new(1.0 + sign * v.e1 * v.e1 * a, sign * b, -sign * v.e1)
        }

        /// The relative rotor `~a b` taken with a non-negative scalar (the shorter way
        /// round), and the length of its bivector part.
        fn relative(a: Rotor, b: Rotor) -> (Rotor, $s) {
            let d = a.reverse() * b;
            let d = if d.s < 0.0 { -d } else { d };
            (d, (d.e12 * d.e12 + d.e13 * d.e13 + d.e23 * d.e23).sqrt())
        }

        impl Rotor {
            /// The rotation by `angle` radians about the unit `axis`, right-handed (glam's
            /// `Quat::from_axis_angle`): `exp(-I axis angle / 2)`, a turn in the plane
            /// `I axis`.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            #[doc = concat!("let r = Rotor::from_axis_angle(Vector::E3, core::", stringify!($s), "::consts::FRAC_PI_2);")]
            /// assert!((r.sandwich(Vector::E1) - Vector::E2).norm() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn from_axis_angle(axis: Vector, angle: $s) -> Self {
                let (sin, cos) = (angle * 0.5).sin_cos();
                Rotor::new(cos, -sin * axis.e3, sin * axis.e2, -sin * axis.e1)
            }

            /// The unit axis and the angle in `[0, pi]` of a unit rotor (the shorter way
            /// round, so `R` and `-R` agree); `(e1, 0)` for the identity (and the zero
            /// rotor), NaN when a component is.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let (axis, angle) = Rotor::from_axis_angle(Vector::E2, 0.5).to_axis_angle();
            /// assert!((axis - Vector::E2).norm() < 1e-6 && (angle - 0.5).abs() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn to_axis_angle(self) -> (Vector, $s) {
                let r = if self.s < 0.0 { -self } else { self };
                let axis = Vector::new(-r.e23, r.e13, -r.e12);
                let length = axis.norm();
                if length > 0.0 {
                    (axis * (1.0 / length), 2.0 * length.atan2(r.s))
                } else if r.is_nan() {
                    (Vector::new($s::NAN, $s::NAN, $s::NAN), $s::NAN)
                } else {
                    (Vector::E1, 0.0)
                }
            }

            /// The rotation by `|v|` radians about `v / |v|` (glam's
            /// `Quat::from_scaled_axis`); the identity for the zero vector.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let v = Vector::new(0.1, -0.2, 0.3);
            /// assert!((Rotor::from_scaled_axis(v).to_scaled_axis() - v).norm() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn from_scaled_axis(v: Vector) -> Self {
                let angle = v.norm();
                let half = 0.5 * angle;
                let (sin, cos) = half.sin_cos();
                // sin(angle / 2) / angle, by its series where the division would lose digits.
                let k = if angle < 1e-4 {
                    0.5 - angle * angle / 48.0
                } else {
                    sin / angle
                };
                Rotor::new(cos, -k * v.e3, k * v.e2, -k * v.e1)
            }

            /// The axis times the angle, the angle in `[0, pi]` (the shorter way round,
            /// so `R` and `-R` agree, unlike glam's `to_scaled_axis`, whose angle reaches
            /// 2 pi); the inverse of `from_scaled_axis`. Zero for the identity and for
            /// the zero rotor, NaN when a component is.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let r = Rotor::from_axis_angle(Vector::E1, 1.0);
            /// assert!(((-r).to_scaled_axis() - Vector::E1).norm() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn to_scaled_axis(self) -> Vector {
                let r = if self.s < 0.0 { -self } else { self };
                let axis = Vector::new(-r.e23, r.e13, -r.e12);
                let length = axis.norm();
                if length > 0.0 {
                    axis * (2.0 * length.atan2(r.s) / length)
                } else if r.is_nan() {
                    Vector::new($s::NAN, $s::NAN, $s::NAN)
                } else {
                    Vector::ZERO
                }
            }

            /// The rotor turning the unit vector `from` into the unit vector `to` in the
            /// plane they span, the shorter way (glam's `Quat::from_rotation_arc`).
            ///
            /// `R = (1 + t f) / |1 + t f|` for the unit directions `f`, `t` of `from` and
            /// `to` (`R = h f` with `h` their unit bisector): scalar `1 + f.t`, bivector
            /// `t ^ f`. Near opposite vectors `1 + f.t` is a difference of nearly equal
            /// numbers (glam's form, which misses `to` by about `2 EPSILON / |f + t|`), so
            /// for `f.t < 0` it is taken as `|t ^ f|^2 / (1 - f.t)`, the same number (their
            /// product is `1 - (f.t)^2`) without the cancellation, and the bivector is
            /// computed as `(f + t) ^ f`, whose plane contains `f` whatever the rounding
            /// (`f + t` is exact to a relative `EPSILON` even when small). For
            /// `f.t >= 0` the plain form is accurate and the inputs are not normalised
            /// (`|from||to|` stands for 1). So `R from ~R`
            /// lands within a few `EPSILON` of the direction of `to` at every angle. The
            /// result is unit, and non-unit input counts by its direction. Exactly
            /// opposite vectors give a half turn in a plane containing `from` (any such
            /// plane is a shortest arc). Either input zero gives the zero rotor (glam
            /// gives the identity for `(X, ZERO)`; see docs/glam.md); NaN propagates.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let r = Rotor::from_rotation_arc(Vector::E1, -Vector::E1);
            /// assert!((r.sandwich(Vector::E1) + Vector::E1).norm() < 1e-6);
            /// assert_eq!(Rotor::from_rotation_arc(Vector::E1, Vector::ZERO), Rotor::ZERO);
            /// ```
            #[inline]
            #[must_use]
            pub fn from_rotation_arc(from: Vector, to: Vector) -> Self {
                if from == Vector::ZERO || to == Vector::ZERO {
                    return Rotor::ZERO;
                }
                let dot = from | to;
                let (scalar, plane) = if dot >= 0.0 {
                    // `|f||t| + f.t` has no cancellation here, and `t ^ f` is accurate
                    // relative to its size (an angle error of about EPSILON).
                    let m = (from.norm_squared() * to.norm_squared()).sqrt();
                    (m + dot, to ^ from)
                } else {
                    // Near opposite: unit directions, so that `f + t` is small exactly when
                    // the vectors are opposite, and `(f + t) ^ f` keeps `f` in its plane.
                    let f = from * (1.0 / from.norm_squared().sqrt());
                    let t = to * (1.0 / to.norm_squared().sqrt());
                    let plane = (f + t) ^ f;
                    let plane_squared = plane.e12 * plane.e12 + plane.e13 * plane.e13 + plane.e23 * plane.e23;
                    if plane_squared == 0.0 {
                        // Exactly opposite: a half turn in a plane containing `f`.
                        return any_orthonormal(f) * f;
                    }
                    (plane_squared / (1.0 - (f | t)), plane)
                };
                let length_squared =
                    scalar * scalar + plane.e12 * plane.e12 + plane.e13 * plane.e13 + plane.e23 * plane.e23;
                // NaN propagates.
                let k = 1.0 / length_squared.sqrt();
                Rotor::new(scalar * k, plane.e12 * k, plane.e13 * k, plane.e23 * k)
            }

            /// The rotor of a rotation matrix (column-major `[[S; 3]; 3]`, or glam's
            /// `Mat3`/`DMat3`/`Mat4`/`DMat4` under the `glam` feature), with a non-negative
            /// scalar; `None` when the matrix is not a rotation: a column product
            /// `c_i . c_j` differs from `delta_ij` by more than `sqrt(EPSILON)` (the
            /// tolerance `log` uses for `<R ~R> = 1`), the determinant is not positive,
            /// or an entry is not finite. Such a matrix has no rotor, and the formula
            /// would still return one (for the all-ones matrix, exactly 1), so it says so.
            /// [`from_mat3`](Self::from_mat3) is the unchecked conversion, as glam's.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let r = Rotor::from_axis_angle(Vector::new(0.0, 0.6, 0.8), 3.1);
            /// let back = Rotor::from_matrix(r.to_matrix()).unwrap();
            /// assert!((back - r).norm() < 1e-5 || (back + r).norm() < 1e-5);
            /// assert!(Rotor::from_matrix([[1.0; 3]; 3]).is_none());
            /// ```
            #[must_use]
            pub fn from_matrix(m: impl RotationMatrix<$s>) -> Option<Self> {
                let c = m.to_cols_array_2d();
                let dot = |a: [$s; 3], b: [$s; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
                let tolerance = $s::EPSILON.sqrt();
                for i in 0..3 {
                    for j in i..3 {
                        let expected = if i == j { 1.0 } else { 0.0 };
                        // Asked as "within", so that NaN fails.
                        let within = (dot(c[i], c[j]) - expected).abs() <= tolerance;
                        if !within {
                            return None;
                        }
                    }
                }
                let cross = Vector::from_array(c[1]).cross(Vector::from_array(c[2]));
                let right_handed = dot(c[0], cross.to_array()) > 0.0;
                if !right_handed {
                    return None;
                }
                // `from_mat3` keeps glam's sign; this form promises a non-negative scalar.
                let r = Self::from_mat3(c);
                Some(if r.s < 0.0 { -r } else { r })
            }

            /// The rotor of a rotation matrix without checking that it is one (glam's
            /// `Quat::from_mat3`): for a matrix with scale, shear or reflection the result
            /// is ill-defined, as glam's is. The sign is glam's too: the quaternion
            /// component whose square the branch computes is positive, so that the result
            /// equals glam's componentwise, not only up to `R = -R` (a half turn about x
            /// gives `x = 1`, whatever the sign of the rounding in `w`);
            /// [`from_matrix`](Self::from_matrix) returns a non-negative scalar.
            ///
            /// Shepperd's method (S. W. Shepperd, "Quaternion from rotation matrix",
            /// J. Guidance and Control 1(3), 1978) with the branch chosen by signs
            /// (M. Day, "Converting a rotation matrix to a quaternion", Insomniac Games,
            /// 2015): the square root is taken of a diagonal combination of at least 1,
            /// so it is accurate near a half turn too. Ties between branches go the way
            /// glam's do (`<=`), so that the sign matches there as well.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let r = Rotor::from_axis_angle(Vector::new(0.0, 0.6, 0.8), 3.1);
            /// let back = Rotor::from_mat3(r.to_matrix());
            /// assert!((back - r).norm() < 1e-5 || (back + r).norm() < 1e-5);
            /// ```
            #[must_use]
            pub fn from_mat3(m: impl RotationMatrix<$s>) -> Self {
                // m_rc: row r, column c.
                let [[m00, m10, m20], [m01, m11, m21], [m02, m12, m22]] = m.to_cols_array_2d();
                // Day's selection: signs of the diagonal pick a component whose squared
                // magnitude times 4 is `t >= 1`, so `1 / sqrt(t)` never loses digits.
                // `t` is summed in glam's order, so that the two agree to the last bit.
                let (t, w, x, y, z);
                if m22 <= 0.0 {
                    if m00 >= m11 {
                        t = (1.0 - m22) - (m11 - m00);
                        (w, x, y, z) = (m21 - m12, t, m01 + m10, m02 + m20);
                    } else {
                        t = (1.0 - m22) + (m11 - m00);
                        (w, x, y, z) = (m02 - m20, m01 + m10, t, m12 + m21);
                    }
                } else if m00 <= -m11 {
                    t = (1.0 + m22) - (m11 + m00);
                    (w, x, y, z) = (m10 - m01, m02 + m20, m12 + m21, t);
                } else {
                    t = (1.0 + m22) + (m11 + m00);
                    (w, x, y, z) = (t, m21 - m12, m02 - m20, m10 - m01);
                }
                let k = 0.5 / t.sqrt();
                Rotor::new(w * k, -z * k, y * k, -x * k)
            }

            /// The rotation matrix of a unit rotor, column-major (`[c][r]`: column `c` is
            /// the image of `e_(c+1)`), glam's `from_cols_array_2d` layout. For glam,
            /// `Mat3::from(r)` does the same.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            #[doc = concat!("let r = Rotor::from_axis_angle(Vector::E3, core::", stringify!($s), "::consts::FRAC_PI_2);")]
            /// let m = r.to_matrix();
            /// assert!((m[0][1] - 1.0).abs() < 1e-6); // e1 goes to e2
            /// ```
            #[inline]
            #[must_use]
            pub fn to_matrix(self) -> [[$s; 3]; 3] {
                let rows = self.sandwich_matrix();
                core::array::from_fn(|c| core::array::from_fn(|r| rows[r][c]))
            }

            /// Spherical interpolation from `self` (t = 0) to `end` (t = 1) along the
            /// shorter arc (glam's `Quat::slerp`): `self (~self end)^t`, the power taken
            /// through the half-angle `atan2(|<d>_2|, <d>_0)` of `d = ~self end`, which
            /// stays accurate for nearly equal rotors where `acos` of the dot product
            /// does not. Both rotors unit; at t = 1 it returns `end` or `-end`.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let a = Rotor::ONE;
            /// let b = Rotor::from_axis_angle(Vector::E3, 1.0);
            /// let half = a.slerp(b, 0.5);
            /// assert!((half - Rotor::from_axis_angle(Vector::E3, 0.5)).norm() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn slerp(self, end: Self, t: $s) -> Self {
                let (d, length) = relative(self, end);
                let (sin, cos) = (t * length.atan2(d.s)).sin_cos();
                // sin(t phi) / |<d>_2| -> t as the angle vanishes.
                let k = if length > 0.0 { sin / length } else { t };
                self * Rotor::new(cos, k * d.e12, k * d.e13, k * d.e23)
            }

            /// Normalised linear interpolation along the shorter arc (glam's `Quat::lerp`):
            /// cheaper than `slerp`, not constant speed. Both rotors unit.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let b = Rotor::from_axis_angle(Vector::E1, 0.2);
            /// assert!((Rotor::ONE.nlerp(-b, 1.0) - b).norm() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn nlerp(self, end: Self, t: $s) -> Self {
                let dot = self.s * end.s + self.e12 * end.e12 + self.e13 * end.e13 + self.e23 * end.e23;
                let end = if dot < 0.0 { -end } else { end };
                (self * (1.0 - t) + end * t).normalized()
            }

            /// The angle in `[0, pi]` of the rotation taking `self` to `other` (glam's
            /// `Quat::angle_between`), as `2 atan2(|<d>_2|, |<d>_0|)` with `d = ~self other`:
            /// accurate for nearly equal rotors, where `acos` is not.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let b = Rotor::from_axis_angle(Vector::E2, 0.3);
            /// assert!((Rotor::ONE.angle_between(b) - 0.3).abs() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn angle_between(self, other: Self) -> $s {
                let (d, length) = relative(self, other);
                2.0 * length.atan2(d.s)
            }

            /// The rotor turning e3 into `forward` and e2 into the part of `up`
            /// perpendicular to it (so e1 goes to `up x forward`): the orientation of an
            /// object whose local e3 looks along `forward`. This was `look_to` before it
            /// took glam's meaning: it is glam's `Quat::look_to_lh(forward, up).inverse()`,
            /// and [`look_to_lh`](Self::look_to_lh) is its reverse. `None` when `forward` is
            /// zero, `up` is parallel to it, or either is not finite.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g3::*;")]
            /// let r = Rotor::from_forward_up(Vector::E1, Vector::E3).unwrap();
            /// assert!((r.sandwich(Vector::E3) - Vector::E1).norm() < 1e-6);
            /// assert!(Rotor::from_forward_up(Vector::E1, Vector::E1).is_none());
            /// ```
            #[must_use]
            pub fn from_forward_up(forward: Vector, up: Vector) -> Option<Self> {
                let dir = forward;
                let forward = dir.try_normalized()?;
                let up = (up - forward * (up | forward)).try_normalized()?;
                let right = Vector::new(
                    up.e2 * forward.e3 - up.e3 * forward.e2,
                    up.e3 * forward.e1 - up.e1 * forward.e3,
                    up.e1 * forward.e2 - up.e2 * forward.e1,
                );
                // Orthonormal by construction: no check needed.
                Some(Rotor::from_mat3([right.to_array(), up.to_array(), forward.to_array()]))
            }
        }
    };
}

// Defined only where instantiated: a G3-only build has no G2 toolkit.
#[cfg(feature = "g2")]
// Unused when no precision is on.
#[allow(unused_macros)]
macro_rules! rotor2_toolkit {
    ($s:ident) => {
        #[cfg(not(feature = "std"))]
        #[allow(unused_imports)]
        use super::no_std_math::Real as _;
        use crate::$s::g2::Rotor;

        impl Rotor {
            /// The rotation by `angle` radians turning e1 toward e2 (glam's
            /// `Mat2::from_angle`): `exp(-e12 angle / 2)`.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g2::*;")]
            #[doc = concat!("let r = Rotor::from_angle(core::", stringify!($s), "::consts::FRAC_PI_2);")]
            /// assert!((r.sandwich(Vector::E1) - Vector::E2).norm() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn from_angle(angle: $s) -> Self {
                let (sin, cos) = (angle * 0.5).sin_cos();
                Rotor::new(cos, -sin)
            }

            /// The angle in `(-pi, pi]` of a rotor (e1 toward e2 positive), the same for
            /// `R` and `-R`; the inverse of `from_angle` on that range.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g2::*;")]
            /// assert!((Rotor::from_angle(-2.0).angle() + 2.0).abs() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn angle(self) -> $s {
                let r = if self.s < 0.0 { -self } else { self };
                2.0 * (-r.e12).atan2(r.s)
            }

            /// Spherical interpolation along the shorter arc, as G3's `slerp`: `self`
            /// at t = 0, `end` or `-end` at t = 1. Both rotors unit.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g2::*;")]
            /// let r = Rotor::ONE.slerp(Rotor::from_angle(1.0), 0.25);
            /// assert!((r.angle() - 0.25).abs() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn slerp(self, end: Self, t: $s) -> Self {
                let d = self.reverse() * end;
                let d = if d.s < 0.0 { -d } else { d };
                self * Rotor::from_angle(t * 2.0 * (-d.e12).atan2(d.s))
            }

            /// The angle in `[0, pi]` of the rotation taking `self` to `other`.
            ///
            /// ```
            #[doc = concat!("use ga_core::", stringify!($s), "::g2::*;")]
            /// let (a, b) = (Rotor::from_angle(0.5), Rotor::from_angle(-0.25));
            /// assert!((a.angle_between(b) - 0.75).abs() < 1e-6);
            /// ```
            #[inline]
            #[must_use]
            pub fn angle_between(self, other: Self) -> $s {
                (self.reverse() * other).angle().abs()
            }
        }
    };
}

#[cfg(all(feature = "g3", feature = "f64"))]
mod g3_f64 {
    rotor3_toolkit!(f64);
}

#[cfg(all(feature = "g3", feature = "f32"))]
mod g3_f32 {
    rotor3_toolkit!(f32);
}

#[cfg(all(feature = "g2", feature = "f64"))]
mod g2_f64 {
    rotor2_toolkit!(f64);
}

#[cfg(all(feature = "g2", feature = "f32"))]
mod g2_f32 {
    rotor2_toolkit!(f32);
}
