//! Euler angles with glam's `EulerRot` orders and meanings: for an intrinsic order `ABC`,
//! `from_euler(ABC, a, b, c) = R_A(a) R_B(b) R_C(c)` (each rotation about the axis of the
//! frame the previous ones turned); for an extrinsic order `ABCEx` the same rotations about
//! the fixed axes, `R_C(c) R_B(b) R_A(a)`. `to_euler` inverts it, reading the angles off
//! the rotation matrix (the closed forms are in docs/derivations/euler-angles.md).

/// An Euler rotation sequence, the same 24 orders and names as glam's `EulerRot` (with
/// `From` both ways under the `glam` features): Tait-Bryan (`XYZ`, three distinct axes),
/// proper Euler (`ZXZ`, first axis repeated), each intrinsic or extrinsic (`Ex`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum EulerRot {
    /// Intrinsic Z, then Y, then X.
    ZYX,
    /// Intrinsic Z, then X, then Y.
    ZXY,
    /// Intrinsic Y, then X, then Z: yaw, pitch, roll, glam's default.
    #[default]
    YXZ,
    /// Intrinsic Y, then Z, then X.
    YZX,
    /// Intrinsic X, then Y, then Z.
    XYZ,
    /// Intrinsic X, then Z, then Y.
    XZY,
    /// Intrinsic proper Euler Z, Y, Z.
    ZYZ,
    /// Intrinsic proper Euler Z, X, Z.
    ZXZ,
    /// Intrinsic proper Euler Y, X, Y.
    YXY,
    /// Intrinsic proper Euler Y, Z, Y.
    YZY,
    /// Intrinsic proper Euler X, Y, X.
    XYX,
    /// Intrinsic proper Euler X, Z, X.
    XZX,
    /// Extrinsic Z, then Y, then X (about the fixed axes).
    ZYXEx,
    /// Extrinsic Z, then X, then Y.
    ZXYEx,
    /// Extrinsic Y, then X, then Z.
    YXZEx,
    /// Extrinsic Y, then Z, then X.
    YZXEx,
    /// Extrinsic X, then Y, then Z.
    XYZEx,
    /// Extrinsic X, then Z, then Y.
    XZYEx,
    /// Extrinsic proper Euler Z, Y, Z.
    ZYZEx,
    /// Extrinsic proper Euler Z, X, Z.
    ZXZEx,
    /// Extrinsic proper Euler Y, X, Y.
    YXYEx,
    /// Extrinsic proper Euler Y, Z, Y.
    YZYEx,
    /// Extrinsic proper Euler X, Y, X.
    XYXEx,
    /// Extrinsic proper Euler X, Z, X.
    XZXEx,
}

impl EulerRot {
    /// The axes (0 = x, 1 = y, 2 = z) in the order the angles are given, and whether
    /// they are the fixed (extrinsic) axes.
    // Unused when no precision is on (the enum exists for G3 alone).
    #[cfg_attr(not(any(feature = "f32", feature = "f64")), allow(dead_code))]
    const fn axes(self) -> ([usize; 3], bool) {
        use EulerRot::*;
        const X: usize = 0;
        const Y: usize = 1;
        const Z: usize = 2;
        match self {
            ZYX => ([Z, Y, X], false),
            ZXY => ([Z, X, Y], false),
            YXZ => ([Y, X, Z], false),
            YZX => ([Y, Z, X], false),
            XYZ => ([X, Y, Z], false),
            XZY => ([X, Z, Y], false),
            ZYZ => ([Z, Y, Z], false),
            ZXZ => ([Z, X, Z], false),
            YXY => ([Y, X, Y], false),
            YZY => ([Y, Z, Y], false),
            XYX => ([X, Y, X], false),
            XZX => ([X, Z, X], false),
            ZYXEx => ([Z, Y, X], true),
            ZXYEx => ([Z, X, Y], true),
            YXZEx => ([Y, X, Z], true),
            YZXEx => ([Y, Z, X], true),
            XYZEx => ([X, Y, Z], true),
            XZYEx => ([X, Z, Y], true),
            ZYZEx => ([Z, Y, Z], true),
            ZXZEx => ([Z, X, Z], true),
            YXYEx => ([Y, X, Y], true),
            YZYEx => ([Y, Z, Y], true),
            XYXEx => ([X, Y, X], true),
            XZXEx => ([X, Z, X], true),
        }
    }
}

/// `From` both ways between [`EulerRot`] and one glam version's `EulerRot`.
macro_rules! glam_euler_version {
    ($feature:literal, $glam:ident, $($v:ident),*) => {
        #[cfg(feature = $feature)]
        impl From<crate::$glam::EulerRot> for EulerRot {
            #[inline]
            fn from(order: crate::$glam::EulerRot) -> EulerRot {
                match order {
                    $(crate::$glam::EulerRot::$v => EulerRot::$v,)*
                }
            }
        }

        #[cfg(feature = $feature)]
        impl From<EulerRot> for crate::$glam::EulerRot {
            #[inline]
            fn from(order: EulerRot) -> crate::$glam::EulerRot {
                match order {
                    $(EulerRot::$v => crate::$glam::EulerRot::$v,)*
                }
            }
        }
    };
}

/// The conversions for every glam version, over all 24 orders.
macro_rules! glam_euler_conversions {
    ($($feature:literal => $glam:ident),*) => {
        $(
            glam_euler_version!(
                $feature, $glam, ZYX, ZXY, YXZ, YZX, XYZ, XZY, ZYZ, ZXZ, YXY, YZY, XYX, XZX,
                ZYXEx, ZXYEx, YXZEx, YZXEx, XYZEx, XZYEx, ZYZEx, ZXZEx, YXYEx, YZYEx, XYXEx, XZXEx
            );
        )*
    };
}

glam_euler_conversions!(
    "glam-0-29" => glam_0_29,
    "glam-0-30" => glam_0_30,
    "glam-0-31" => glam_0_31,
    "glam-0-32" => glam_0_32,
    "glam-0-33" => glam_0_33
);

// Unused when no precision is on.
#[allow(unused_macros)]
macro_rules! euler_angles {
    ($s:ident) => {
        use super::EulerRot;
        #[cfg(not(feature = "std"))]
        #[allow(unused_imports)]
        use crate::rotor::no_std_math::Real as _;
        use crate::$s::g3::Rotor;

        /// The rotation by `angle` about axis 0, 1 or 2.
        fn about(axis: usize, angle: $s) -> Rotor {
            match axis {
                0 => Rotor::from_rotation_x(angle),
                1 => Rotor::from_rotation_y(angle),
                _ => Rotor::from_rotation_z(angle),
            }
        }

        /// The angles `(a, b, c)` with `R_i(a) R_j(b) R_k(c) = M` (Tait-Bryan, `k` the
        /// third axis) or `R_i(a) R_j(b) R_i(c) = M` (proper), `M[row][column]`. At
        /// gimbal lock (the middle angle's cosine, or sine, below `16 EPSILON`, glam's
        /// threshold) `c = 0` and `a` takes the whole turn about the merged axis.
        fn intrinsic_angles(m: [[$s; 3]; 3], [i, j, third]: [usize; 3]) -> ($s, $s, $s) {
            let k = 3 - i - j;
            // +1 when (i, j, k) is a cyclic permutation of (x, y, z).
            let e: $s = if j == (i + 1) % 3 { 1.0 } else { -1.0 };
            let limit = 16.0 * $s::EPSILON;
            if third == i {
                let sin_b = (m[i][j] * m[i][j] + m[i][k] * m[i][k]).sqrt();
                let b = sin_b.atan2(m[i][i]);
                let (a, b, c) = if sin_b > limit {
                    (m[j][i].atan2(-e * m[k][i]), b, m[i][j].atan2(e * m[i][k]))
                } else {
                    ((e * m[k][j]).atan2(m[j][j]), b, 0.0)
                };
                // glam's range for the cyclic proper orders (XYX, YZY, ZXZ) puts the middle
                // angle in [-pi, 0]: (a + pi, -b, c + pi) is the same rotation, since a
                // half turn about i conjugates R_j(-b) into R_j(b).
                if e > 0.0 {
                    let turn = |x: $s| {
                        if x > 0.0 {
                            x - core::$s::consts::PI
                        } else {
                            x + core::$s::consts::PI
                        }
                    };
                    (turn(a), -b, turn(c))
                } else {
                    (a, b, c)
                }
            } else {
                let cos_b = (m[i][i] * m[i][i] + m[i][j] * m[i][j]).sqrt();
                let b = (e * m[i][k]).atan2(cos_b);
                if cos_b > limit {
                    (
                        (-e * m[j][k]).atan2(m[k][k]),
                        b,
                        (-e * m[i][j]).atan2(m[i][i]),
                    )
                } else {
                    ((e * m[k][j]).atan2(m[j][j]), b, 0.0)
                }
            }
        }

        impl Rotor {
            /// The rotation of the Euler angles `(a, b, c)` in `order` (glam's
            /// `Quat::from_euler`): intrinsic `ABC` is `R_A(a) R_B(b) R_C(c)`, extrinsic
            /// `ABCEx` is `R_C(c) R_B(b) R_A(a)`, with `R_X = from_rotation_x` and so on.
            ///
            /// ```
            #[doc = concat!("use ga_core::{EulerRot, ", stringify!($s), "::g3::*};")]
            /// let r = Rotor::from_euler(EulerRot::XYZ, 0.1, 0.2, 0.3);
            /// let q = Rotor::from_rotation_x(0.1) * Rotor::from_rotation_y(0.2) * Rotor::from_rotation_z(0.3);
            /// assert!((r - q).norm() < 1e-6);
            /// ```
            #[must_use]
            pub fn from_euler(order: EulerRot, a: $s, b: $s, c: $s) -> Rotor {
                let ([p, q, r], extrinsic) = order.axes();
                let (ra, rb, rc) = (about(p, a), about(q, b), about(r, c));
                if extrinsic {
                    rc * rb * ra
                } else {
                    ra * rb * rc
                }
            }

            /// The Euler angles of a unit rotor in `order` (glam's `Quat::to_euler`), the
            /// inverse of [`from_euler`](Self::from_euler): angles in `[-pi, pi]`, the
            /// middle one in `[-pi/2, pi/2]` (Tait-Bryan) or, as glam's, `[-pi, 0]` for
            /// the proper orders XYX, YZY, ZXZ (and their `Ex`) and `[0, pi]` for the
            /// other three. At gimbal
            /// lock the split between the first and last angle is a choice; the rotation
            /// they give back is the same.
            ///
            /// ```
            #[doc = concat!("use ga_core::{EulerRot, ", stringify!($s), "::g3::*};")]
            /// let (a, b, c) = Rotor::from_euler(EulerRot::ZYX, 0.1, 0.2, 0.3).to_euler(EulerRot::ZYX);
            /// assert!((a - 0.1).abs() < 1e-6 && (b - 0.2).abs() < 1e-6 && (c - 0.3).abs() < 1e-6);
            /// ```
            #[must_use]
            pub fn to_euler(self, order: EulerRot) -> ($s, $s, $s) {
                let columns = self.to_matrix();
                let m: [[$s; 3]; 3] =
                    core::array::from_fn(|r| core::array::from_fn(|c| columns[c][r]));
                let ([p, q, r], extrinsic) = order.axes();
                if extrinsic {
                    // R_C(c) R_B(b) R_A(a) is the intrinsic order CBA with angles (c, b, a).
                    let (c, b, a) = intrinsic_angles(m, [r, q, p]);
                    (a, b, c)
                } else {
                    intrinsic_angles(m, [p, q, r])
                }
            }
        }
    };
}

#[cfg(all(feature = "g3", feature = "f64"))]
mod g3_f64 {
    euler_angles!(f64);
}

#[cfg(all(feature = "g3", feature = "f32"))]
mod g3_f32 {
    euler_angles!(f32);
}
