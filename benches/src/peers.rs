//! Conversions from canonical G3 arrays to the peer libraries' types.
//!
//! A rotor `[s, e12, e13, e23]` is the quaternion `w = s, (x, y, z) = (-e23, e13, -e12)`
//! for glam and nalgebra, and `Rotor3 { s, bv: Bivec3 { xy: e12, xz: e13, yz: e23 } }`
//! for ultraviolet; all three then rotate a vector as `R v ~R` (checked by the tests
//! below against the table-driven algebra). A bivector `B` is handed to glam and
//! nalgebra as the scaled axis `2 (-e23, e13, -e12)`, so that their `from_scaled_axis`
//! returns the same rotor as `exp(B)`.

use glam::{DQuat, DVec3, Quat, Vec3};
use nalgebra::{Quaternion, RealField, UnitQuaternion, Vector3};
use ultraviolet::{
    f32x4, f32x8, f64x2, f64x4, Bivec3, Bivec3x4, Bivec3x8, DBivec3, DBivec3x2, DBivec3x4, DRotor3,
    DRotor3x2, DRotor3x4, DVec3 as UvDVec3, DVec3x2, DVec3x4, Rotor3, Rotor3x4, Rotor3x8,
    Vec3 as UvVec3, Vec3x4, Vec3x8,
};

/// A type built from a G3 rotor `[s, e12, e13, e23]` (per lane for wide types).
pub trait FromRotor3<S> {
    /// The peer's rotor or quaternion for `r`.
    fn from_rotor3(r: [S; 4]) -> Self;
}

/// A type built from a G3 vector `[e1, e2, e3]` (per lane for wide types).
pub trait FromVector3<S> {
    /// The peer's vector for `v`.
    fn from_vector3(v: [S; 3]) -> Self;
}

/// A type built from a G3 bivector `[e12, e13, e23]`: a bivector, or the scaled axis
/// whose `from_scaled_axis` equals `exp(B)`.
pub trait FromBivector3<S> {
    /// The peer's bivector (or scaled axis) for `b`.
    fn from_bivector3(b: [S; 3]) -> Self;
}

/// A SIMD vector of `L` lanes of `S`.
pub trait Lanes<S, const L: usize>: Copy {
    /// The vector holding `x`, lane `i` from `x[i]`.
    fn from_lanes(x: [S; L]) -> Self;
}

macro_rules! impl_lanes {
    ($($wide:ty => ($s:ty, $l:literal)),+) => {$(
        impl Lanes<$s, $l> for $wide {
            #[inline]
            fn from_lanes(x: [$s; $l]) -> Self {
                <$wide>::new(x)
            }
        }
    )+};
}

impl_lanes!(f32x4 => (f32, 4), f32x8 => (f32, 8), f64x2 => (f64, 2), f64x4 => (f64, 4));

/// Packs `items` into wide values, `L` items at a time (a tail shorter than `L` is
/// dropped): component `k` of lane `l` comes from `items[l][k]`.
#[must_use]
pub fn pack<S: Copy, V: Lanes<S, L>, T, const L: usize, const K: usize>(
    items: &[[S; K]],
    build: impl Fn([V; K]) -> T,
) -> Vec<T> {
    items
        .chunks_exact(L)
        .map(|chunk| {
            build(std::array::from_fn(|k| {
                V::from_lanes(std::array::from_fn(|l| chunk[l][k]))
            }))
        })
        .collect()
}

macro_rules! impl_glam {
    ($s:ty, $quat:ty, $vec:ty) => {
        impl FromRotor3<$s> for $quat {
            #[inline]
            fn from_rotor3(r: [$s; 4]) -> Self {
                <$quat>::from_xyzw(-r[3], r[2], -r[1], r[0])
            }
        }
        impl FromVector3<$s> for $vec {
            #[inline]
            fn from_vector3(v: [$s; 3]) -> Self {
                <$vec>::from_array(v)
            }
        }
        impl FromBivector3<$s> for $vec {
            #[inline]
            fn from_bivector3(b: [$s; 3]) -> Self {
                <$vec>::new(-2.0 * b[2], 2.0 * b[1], -2.0 * b[0])
            }
        }
    };
}

impl_glam!(f32, Quat, Vec3);
impl_glam!(f64, DQuat, DVec3);

impl<S: RealField + Copy> FromRotor3<S> for UnitQuaternion<S> {
    #[inline]
    fn from_rotor3(r: [S; 4]) -> Self {
        UnitQuaternion::new_unchecked(Quaternion::new(r[0], -r[3], r[2], -r[1]))
    }
}

impl<S: RealField + Copy> FromVector3<S> for Vector3<S> {
    #[inline]
    fn from_vector3(v: [S; 3]) -> Self {
        Vector3::new(v[0], v[1], v[2])
    }
}

impl<S: RealField + Copy> FromBivector3<S> for Vector3<S> {
    #[inline]
    fn from_bivector3(b: [S; 3]) -> Self {
        let two = S::one() + S::one();
        Vector3::new(-two * b[2], two * b[1], -two * b[0])
    }
}

macro_rules! impl_ultraviolet {
    ($($s:ty => ($rotor:ty, $vec:ty, $bivec:ty)),+) => {$(
        impl FromRotor3<$s> for $rotor {
            #[inline]
            fn from_rotor3(r: [$s; 4]) -> Self {
                <$rotor>::new(r[0], <$bivec>::new(r[1], r[2], r[3]))
            }
        }
        impl FromVector3<$s> for $vec {
            #[inline]
            fn from_vector3(v: [$s; 3]) -> Self {
                <$vec>::new(v[0], v[1], v[2])
            }
        }
        impl FromBivector3<$s> for $bivec {
            #[inline]
            fn from_bivector3(b: [$s; 3]) -> Self {
                <$bivec>::new(b[0], b[1], b[2])
            }
        }
    )+};
}

impl_ultraviolet!(
    f32 => (Rotor3, UvVec3, Bivec3),
    f32x4 => (Rotor3x4, Vec3x4, Bivec3x4),
    f32x8 => (Rotor3x8, Vec3x8, Bivec3x8),
    f64 => (DRotor3, UvDVec3, DBivec3),
    f64x2 => (DRotor3x2, DVec3x2, DBivec3x2),
    f64x4 => (DRotor3x4, DVec3x4, DBivec3x4)
);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::inputs::{g3_bivectors, g3_rotors, g3_vectors};
    use crate::table::G3;

    const TOLERANCE: f64 = 1e-12;

    fn close(a: &[f64], b: &[f64]) -> bool {
        a.iter().zip(b).all(|(x, y)| (x - y).abs() < TOLERANCE)
    }

    struct Blades {
        algebra: G3,
        vector: Vec<usize>,
        bivector: Vec<usize>,
        even: Vec<usize>,
    }

    fn blades() -> Blades {
        let algebra = G3::euclidean();
        Blades {
            vector: algebra.blades_of_grades(&[1]),
            bivector: algebra.blades_of_grades(&[2]),
            even: algebra.blades_of_grades(&[0, 2]),
            algebra,
        }
    }

    #[test]
    fn every_peer_rotates_a_vector_like_the_table_sandwich() {
        let b = blades();
        for (r, v) in g3_rotors(200, 1).into_iter().zip(g3_vectors(200, 2)) {
            let rotor = b.algebra.embed(&b.even, &r);
            let vector = b.algebra.embed(&b.vector, &v);
            let expected = b
                .algebra
                .extract(&b.vector, &b.algebra.sandwich(&rotor, &vector));

            let glam = DQuat::from_rotor3(r).mul_vec3(DVec3::from_vector3(v));
            let na = UnitQuaternion::from_rotor3(r) * Vector3::from_vector3(v);
            let uv = DRotor3::from_rotor3(r) * UvDVec3::from_vector3(v);
            assert!(
                close(&expected, &glam.to_array()),
                "glam {expected:?} {glam:?}"
            );
            assert!(
                close(&expected, na.as_slice()),
                "nalgebra {expected:?} {na:?}"
            );
            assert!(
                close(&expected, &[uv.x, uv.y, uv.z]),
                "ultraviolet {expected:?} {uv:?}"
            );
        }
    }

    #[test]
    fn every_peer_composes_rotors_like_the_table_product() {
        let b = blades();
        let rotors = g3_rotors(200, 3);
        for pair in rotors.windows(2) {
            let (p, q) = (pair[0], pair[1]);
            let product = b
                .algebra
                .geometric(&b.algebra.embed(&b.even, &p), &b.algebra.embed(&b.even, &q));
            let e = b.algebra.extract(&b.even, &product);
            let as_glam = DQuat::from_rotor3([e[0], e[1], e[2], e[3]]);
            let glam = DQuat::from_rotor3(p) * DQuat::from_rotor3(q);
            assert!(close(&as_glam.to_array(), &glam.to_array()));
            let uv = DRotor3::from_rotor3(p) * DRotor3::from_rotor3(q);
            assert!(close(&e, &[uv.s, uv.bv.xy, uv.bv.xz, uv.bv.yz]));
        }
    }

    #[test]
    fn scaled_axis_exponentials_match_the_table_exp() {
        let b = blades();
        for biv in g3_bivectors(200, 4) {
            let exp = b.algebra.exp(&b.algebra.embed(&b.bivector, &biv));
            let e = b.algebra.extract(&b.even, &exp);
            let expected = DQuat::from_rotor3([e[0], e[1], e[2], e[3]]);
            let glam = DQuat::from_scaled_axis(DVec3::from_bivector3(biv));
            assert!(close(&expected.to_array(), &glam.to_array()));
            let na = UnitQuaternion::from_scaled_axis(Vector3::from_bivector3(biv));
            assert!(close(&expected.to_array(), na.coords.as_slice()));
        }
    }

    #[test]
    fn wide_lanes_match_scalar_rotation() {
        let rotors = g3_rotors(8, 5);
        let vectors = g3_vectors(8, 6);
        let wide_r = pack::<f64, f64x4, _, 4, 4>(&rotors, DRotor3x4::from_rotor3);
        let wide_v = pack::<f64, f64x4, _, 4, 3>(&vectors, DVec3x4::from_vector3);
        for chunk in 0..2 {
            let rotated = wide_r[chunk] * wide_v[chunk];
            for lane in 0..4 {
                let i = 4 * chunk + lane;
                let scalar = DRotor3::from_rotor3(rotors[i]) * UvDVec3::from_vector3(vectors[i]);
                let got = [
                    rotated.x.to_array()[lane],
                    rotated.y.to_array()[lane],
                    rotated.z.to_array()[lane],
                ];
                assert!(close(&got, &[scalar.x, scalar.y, scalar.z]));
            }
        }
    }
}
