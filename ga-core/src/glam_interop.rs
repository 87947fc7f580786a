//! Conversions to and from glam: vectors, quaternions and rotation matrices (3x3 and 4x4).
//!
//! A G3 rotor `s + b12 e12 + b13 e13 + b23 e23` and a glam quaternion rotate alike when
//! `w = s, x = -b23, y = b13, z = -b12` (a rotation in the e12 plane turning e1 toward e2
//! is a positive rotation about z). See docs/derivations/rotor-quaternion.md.

// Unused when no glam version or no precision is on.
#[allow(unused_macros)]
macro_rules! impl_glam_interop {
    ($g3:path, $vec3:ty, $quat:ty, $mat3:ty, $mat4:ty) => {
        use $g3 as g3;

        impl From<$vec3> for g3::Vector {
            #[inline]
            fn from(v: $vec3) -> Self {
                g3::Vector::new(v.x, v.y, v.z)
            }
        }

        impl From<g3::Vector> for $vec3 {
            #[inline]
            fn from(v: g3::Vector) -> Self {
                <$vec3>::new(v.e1, v.e2, v.e3)
            }
        }

        impl From<$quat> for g3::Rotor {
            #[inline]
            fn from(q: $quat) -> Self {
                g3::Rotor::new(q.w, -q.z, q.y, -q.x)
            }
        }

        impl From<g3::Rotor> for $quat {
            #[inline]
            fn from(r: g3::Rotor) -> Self {
                <$quat>::from_xyzw(-r.e23, r.e13, -r.e12, r.s)
            }
        }

        impl From<g3::Rotor> for $mat3 {
            /// The matrix of `x -> R x ~R` (for a unit rotor), columns the images of e1, e2, e3.
            #[inline]
            fn from(r: g3::Rotor) -> Self {
                use g3::Sandwich;
                let columns = [g3::Vector::E1, g3::Vector::E2, g3::Vector::E3]
                    .map(|e| <$vec3>::from(r.sandwich(e)));
                <$mat3>::from_cols(columns[0], columns[1], columns[2])
            }
        }

        impl From<g3::Rotor> for $mat4 {
            /// The rotation as a 4x4 affine matrix (glam's `Mat4::from_quat`): the 3x3
            /// block of `x -> R x ~R` (for a unit rotor), no translation.
            #[inline]
            fn from(r: g3::Rotor) -> Self {
                <$mat4>::from_mat3(<$mat3>::from(r))
            }
        }
    };
}

/// The conversions for one glam major version, in each precision that is on.
macro_rules! glam_version {
    ($feature:literal, $glam:ident) => {
        #[cfg(all(feature = $feature, feature = "f32"))]
        const _: () = {
            impl_glam_interop!(
                crate::f32::g3,
                $glam::Vec3,
                $glam::Quat,
                $glam::Mat3,
                $glam::Mat4
            );
        };
        #[cfg(all(feature = $feature, feature = "f64"))]
        const _: () = {
            impl_glam_interop!(
                crate::f64::g3,
                $glam::DVec3,
                $glam::DQuat,
                $glam::DMat3,
                $glam::DMat4
            );
        };
    };
}

glam_version!("glam-0-29", glam_0_29);
glam_version!("glam-0-30", glam_0_30);
glam_version!("glam-0-31", glam_0_31);
glam_version!("glam-0-32", glam_0_32);
glam_version!("glam-0-33", glam_0_33);
