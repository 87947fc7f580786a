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

/// `exp` and `log` for ultraviolet's rotors (it has neither), written with its own API
/// the way a user would: `from_angle_plane` and `into_angle_plane`, whose angle is
/// minus twice the rotor's.
///
/// The plane is scaled by the reciprocal of the magnitude because ultraviolet 0.9's
/// `Bivec3 / scalar` divides only the `xy` component.
pub trait ExpLog: Sized {
    /// The bivector type of the rotor.
    type Bivector;
    /// `exp(b) = cos|b| + b sin|b| / |b|`; `b` must not be zero.
    fn exp_of(b: Self::Bivector) -> Self;
    /// `log(r) = atan2(|B|, s) B / |B|` for a unit rotor `r = s + B` with `B` not zero.
    fn log_of(self) -> Self::Bivector;
}

macro_rules! impl_exp_log {
    ($($rotor:ty => ($bivec:ty, $scalar:ty, $splat:expr)),+) => {$(
        impl ExpLog for $rotor {
            type Bivector = $bivec;
            #[inline]
            fn exp_of(b: $bivec) -> Self {
                let splat: fn(f64) -> $scalar = $splat;
                let size = b.mag();
                <$rotor>::from_angle_plane(size * splat(-2.0), b * (splat(1.0) / size))
            }
            #[inline]
            fn log_of(self) -> $bivec {
                let splat: fn(f64) -> $scalar = $splat;
                let (angle, plane) = self.into_angle_plane();
                plane * (angle * splat(-0.5))
            }
        }
    )+};
}

impl_exp_log!(
    Rotor3 => (Bivec3, f32, |x| x as f32),
    Rotor3x4 => (Bivec3x4, f32x4, |x| f32x4::splat(x as f32)),
    Rotor3x8 => (Bivec3x8, f32x8, |x| f32x8::splat(x as f32)),
    DRotor3 => (DBivec3, f64, |x| x),
    DRotor3x2 => (DBivec3x2, f64x2, f64x2::splat),
    DRotor3x4 => (DBivec3x4, f64x4, f64x4::splat)
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

    #[test]
    fn ga_core_g3_agrees_with_the_table_on_every_benched_operation() {
        use ga::Sandwich as _;
        use ga_core::f64::g3 as ga;
        let b = blades();
        let t = &b.algebra;
        let rotors = g3_rotors(100, 7);
        for ((pair, v), biv) in rotors
            .windows(2)
            .zip(g3_vectors(100, 8))
            .zip(g3_bivectors(100, 9))
        {
            let (p, q) = (pair[0], pair[1]);
            let (tp, tq) = (t.embed(&b.even, &p), t.embed(&b.even, &q));
            let (gp, gq) = (ga::Even::from_array(p), ga::Even::from_array(q));
            assert!(close(
                &(gp * gq).to_array(),
                &t.extract(&b.even, &t.geometric(&tp, &tq))
            ));
            let tv = t.embed(&b.vector, &v);
            let rotated = gp.sandwich(ga::Vector::from_array(v));
            assert!(close(
                &rotated.to_array(),
                &t.extract(&b.vector, &t.sandwich(&tp, &tv))
            ));
            let tb = t.embed(&b.bivector, &biv);
            let exp = ga::Bivector::from_array(biv).exp();
            assert!(close(&exp.to_array(), &t.extract(&b.even, &t.exp(&tb))));
            assert!(close(
                &gp.log().expect("a unit rotor has a log").to_array(),
                &t.extract(&b.bivector, &t.log(&tp))
            ));
            let wv = ga::Vector::from_array(v) * ga::Vector::from_array(g3_vectors(1, 10)[0]);
            let tw = t.geometric(&tv, &t.embed(&b.vector, &g3_vectors(1, 10)[0]));
            assert!(close(&wv.to_array(), &t.extract(&b.even, &tw)));
        }
    }

    #[test]
    fn ga_core_g4_agrees_with_the_table_on_every_benched_operation() {
        use crate::inputs::{g4_bivectors, g4_multivectors, g4_rotors, g4_vectors};
        use crate::table::G4;
        use ga::Sandwich as _;
        use ga_core::f64::g4 as ga;
        let t = G4::euclidean();
        let (vector, bivector, even) = (
            t.blades_of_grades(&[1]),
            t.blades_of_grades(&[2]),
            t.blades_of_grades(&[0, 2, 4]),
        );
        let all = t.blades_of_grades(&[0, 1, 2, 3, 4]);
        let rotors = g4_rotors(50, 11);
        let multivectors = g4_multivectors(50, 1.0, 12);
        let vectors = g4_vectors(50, 13);
        let bivectors = g4_bivectors(50, 14);
        for i in 1..50 {
            let (p, q) = (rotors[i - 1], rotors[i]);
            let (tp, tq) = (t.embed(&even, &p), t.embed(&even, &q));
            let product = ga::Even::from_array(p) * ga::Even::from_array(q);
            assert!(close(
                &product.to_array(),
                &t.extract(&even, &t.geometric(&tp, &tq))
            ));
            let (a, c) = (multivectors[i - 1], multivectors[i]);
            let full = ga::Multivector::from_array(a) * ga::Multivector::from_array(c);
            let expected = t.geometric(&t.embed(&all, &a), &t.embed(&all, &c));
            assert!(close(&full.to_array(), &t.extract(&all, &expected)));
            let rotated = ga::Even::from_array(p).sandwich(ga::Vector::from_array(vectors[i]));
            let expected = t.sandwich(&tp, &t.embed(&vector, &vectors[i]));
            assert!(close(&rotated.to_array(), &t.extract(&vector, &expected)));
            let exp = ga::Bivector::from_array(bivectors[i]).exp();
            let expected = t.exp(&t.embed(&bivector, &bivectors[i]));
            assert!(
                close(&exp.to_array(), &t.extract(&even, &expected)),
                "{exp:?}"
            );
        }
    }

    #[test]
    fn ultraviolet_exp_and_log_match_the_table() {
        let b = blades();
        for (biv, r) in g3_bivectors(100, 15).into_iter().zip(g3_rotors(100, 16)) {
            let exp = DRotor3::exp_of(DBivec3::from_bivector3(biv));
            let expected = b.algebra.exp(&b.algebra.embed(&b.bivector, &biv));
            let got = [exp.s, exp.bv.xy, exp.bv.xz, exp.bv.yz];
            assert!(
                close(&got, &b.algebra.extract(&b.even, &expected)),
                "{got:?}"
            );
            let log = DRotor3::from_rotor3(r).log_of();
            let expected = b.algebra.log(&b.algebra.embed(&b.even, &r));
            let got = [log.xy, log.xz, log.yz];
            assert!(
                close(&got, &b.algebra.extract(&b.bivector, &expected)),
                "{got:?}"
            );
        }
        let wide = pack::<f64, f64x4, _, 4, 3>(&g3_bivectors(4, 17), DBivec3x4::from_bivector3)[0];
        let scalar = DRotor3::exp_of(DBivec3::from_bivector3(g3_bivectors(4, 17)[3]));
        assert!((DRotor3x4::exp_of(wide).s.to_array()[3] - scalar.s).abs() < TOLERANCE);
    }
}
