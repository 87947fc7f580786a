//! G3 rotors against glam, nalgebra, ultraviolet and the table-driven algebra:
//! rotor * rotor, the sandwich of one vector, one rotor on a batch of vectors,
//! bivector exp and rotor log, in f32 and f64; per item over a batch (throughput) and
//! per step of a dependent chain (latency).

mod common;

use common::{batch1, batch2, chain, config, conv, group, in_place, kernel2, BATCH};
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use ga_benches::inputs::{cast_all, g3_bivectors, g3_rotors, g3_vectors};
use ga_benches::peers::{pack, ExpLog, FromBivector3, FromRotor3, FromVector3};
use ga_benches::table::{add, scale, G3};
use nalgebra::{Quaternion, UnitQuaternion, Vector3};

/// Weight of the previous log fed back into the next rotor of the log chain: small
/// enough that the input stays a unit rotor within ga-core's `log` tolerance (the square
/// root of epsilon) in both precisions, so the chain measures the log, not its `None`.
const LOG_FEEDBACK: f64 = 1e-9;

macro_rules! g3_rotor_benches {
    (
        $module:ident, $s:ident,
        glam: ($quat:ty, $vec3:ty, $mat3:ty),
        ultraviolet: ($rotor:ty, $uvec:ty, $bivec:ty),
        wide: [$(($lanes:literal, $w:ty, $wrotor:ty, $wvec:ty, $wbivec:ty)),+],
        batch: [$(($ga_lanes:literal, $ga_batch:ident)),+]
    ) => {
        mod $module {
            use super::*;
            use ga::{Sandwich as _, SandwichUnit as _};
            use ga_core::$s::g3 as ga;
            use ga_core::kernels::$s as kernels;

            type S = $s;
            const PRECISION: &str = stringify!($s);

            /// Items grouped into lanes of a ga-core batch type.
            fn lanes<T: Copy, W, const L: usize>(items: &[T], build: impl Fn([T; L]) -> W) -> Vec<W> {
                items.chunks_exact(L).map(|c| build(std::array::from_fn(|i| c[i]))).collect()
            }

            fn rotors(seed: u64) -> Vec<[S; 4]> {
                cast_all(&g3_rotors(BATCH, seed))
            }

            fn dense<const K: usize>(table: &G3, grades: &[u32], xs: &[[S; K]]) -> Vec<[S; 8]> {
                let blades = table.blades_of_grades(grades);
                xs.iter().map(|x| table.embed(&blades, x)).collect()
            }

            /// Rotor * rotor (the quaternion product).
            pub fn rotor_mul(c: &mut Criterion) {
                let (p, q) = (rotors(1), rotors(2));
                let table = black_box(G3::euclidean());
                let (tp, tq) = (dense(&table, &[0, 2], &p), dense(&table, &[0, 2], &q));

                let mut g = group(c, &format!("g3/rotor_mul/{PRECISION}/batch"));
                batch2(&mut g, "ga-core", &conv(&p, ga::Even::from_array), &conv(&q, ga::Even::from_array), |a, b| a * b);
                kernel2(&mut g, "ga-core mul_pairs", &conv(&p, ga::Even::from_array), &conv(&q, ga::Even::from_array), ga::Even::ZERO,
                    |a, b, out| kernels::mul_pairs(a, b, out).expect("equal lengths"));
                // Each copy by name, where this CPU has it: the AVX2 one on an AVX-512 CPU,
                // and the SSE2 baseline every x86-64 CPU runs without AVX2.
                for set in [ga_core::kernels::InstructionSet::Avx2Fma, ga_core::kernels::InstructionSet::Baseline] {
                    if set.is_available() && set != ga_core::kernels::InstructionSet::detect() {
                        kernel2(&mut g, &format!("ga-core mul_pairs {}", set.name()), &conv(&p, ga::Even::from_array),
                            &conv(&q, ga::Even::from_array), ga::Even::ZERO,
                            |a, b, out| { kernels::mul_pairs_on(set, a, b, out).expect("equal lengths"); });
                    }
                }
                batch2(&mut g, "glam", &conv(&p, <$quat>::from_rotor3), &conv(&q, <$quat>::from_rotor3), |a, b| a * b);
                batch2(&mut g, "nalgebra", &conv(&p, UnitQuaternion::<S>::from_rotor3), &conv(&q, UnitQuaternion::<S>::from_rotor3), |a, b| a * b);
                batch2(&mut g, "ultraviolet", &conv(&p, <$rotor>::from_rotor3), &conv(&q, <$rotor>::from_rotor3), |a, b| a * b);
                $(
                    batch2(&mut g, concat!("ultraviolet x", $lanes),
                        &pack::<S, $w, _, $lanes, 4>(&p, <$wrotor>::from_rotor3),
                        &pack::<S, $w, _, $lanes, 4>(&q, <$wrotor>::from_rotor3), |a, b| a * b);
                )+
                $(
                    batch2(&mut g, concat!("ga-core x", $ga_lanes),
                        &lanes(&conv(&p, ga::Even::from_array), ga::$ga_batch::Even::from_items),
                        &lanes(&conv(&q, ga::Even::from_array), ga::$ga_batch::Even::from_items), |a, b| a * b);
                )+
                batch2(&mut g, "table", &tp, &tq, |a, b| table.geometric(&a, &b));
                g.finish();

                let mut g = group(c, &format!("g3/rotor_mul/{PRECISION}/chain"));
                let start = p[0];
                chain(&mut g, "ga-core", ga::Even::from_array(start), &conv(&q, ga::Even::from_array), |x, a| x * a);
                chain(&mut g, "glam", <$quat>::from_rotor3(start), &conv(&q, <$quat>::from_rotor3), |x, a| x * a);
                chain(&mut g, "nalgebra", UnitQuaternion::<S>::from_rotor3(start), &conv(&q, UnitQuaternion::<S>::from_rotor3), |x, a| x * a);
                chain(&mut g, "ultraviolet", <$rotor>::from_rotor3(start), &conv(&q, <$rotor>::from_rotor3), |x, a| x * a);
                chain(&mut g, "table", tp[0], &tq, |x, a| table.geometric(&x, &a));
                g.finish();
            }

            /// The sandwich `R v ~R` of one vector by its own rotor.
            pub fn sandwich(c: &mut Criterion) {
                let r = rotors(3);
                let v: Vec<[S; 3]> = cast_all(&g3_vectors(BATCH, 4));
                let table = black_box(G3::euclidean());
                let (tr, tv) = (dense(&table, &[0, 2], &r), dense(&table, &[1], &v));

                let mut g = group(c, &format!("g3/sandwich/{PRECISION}/batch"));
                batch2(&mut g, "ga-core", &conv(&r, ga::Even::from_array), &conv(&v, ga::Vector::from_array), |r, v| r.sandwich(v));
                batch2(&mut g, "ga-core sandwich_unit", &conv(&r, ga::Even::from_array), &conv(&v, ga::Vector::from_array), |r, v| r.sandwich_unit(v));
                kernel2(&mut g, "ga-core sandwich_pairs", &conv(&r, ga::Even::from_array), &conv(&v, ga::Vector::from_array), ga::Vector::ZERO,
                    |r, v, out| kernels::sandwich_pairs(r, v, out).expect("equal lengths"));
                batch2(&mut g, "glam", &conv(&r, <$quat>::from_rotor3), &conv(&v, <$vec3 as FromVector3<S>>::from_vector3), |r, v| r.mul_vec3(v));
                batch2(&mut g, "nalgebra", &conv(&r, UnitQuaternion::<S>::from_rotor3), &conv(&v, <Vector3<S> as FromVector3<S>>::from_vector3), |r, v| r * v);
                batch2(&mut g, "ultraviolet", &conv(&r, <$rotor>::from_rotor3), &conv(&v, <$uvec>::from_vector3), |r, v| r * v);
                $(
                    batch2(&mut g, concat!("ultraviolet x", $lanes),
                        &pack::<S, $w, _, $lanes, 4>(&r, <$wrotor>::from_rotor3),
                        &pack::<S, $w, _, $lanes, 3>(&v, <$wvec>::from_vector3), |r, v| r * v);
                )+
                $(
                    batch2(&mut g, concat!("ga-core x", $ga_lanes),
                        &lanes(&conv(&r, ga::Even::from_array), ga::$ga_batch::Even::from_items),
                        &lanes(&conv(&v, ga::Vector::from_array), ga::$ga_batch::Vector::from_items),
                        |r, v| ga::$ga_batch::Sandwich::sandwich(r, v));
                )+
                batch2(&mut g, "table", &tr, &tv, |r, v| table.sandwich(&r, &v));
                g.finish();

                let mut g = group(c, &format!("g3/sandwich/{PRECISION}/chain"));
                let start = v[0];
                chain(&mut g, "ga-core", ga::Vector::from_array(start), &conv(&r, ga::Even::from_array), |v, r| r.sandwich(v));
                chain(&mut g, "ga-core sandwich_unit", ga::Vector::from_array(start), &conv(&r, ga::Even::from_array), |v, r| r.sandwich_unit(v));
                chain(&mut g, "glam", <$vec3 as FromVector3<S>>::from_vector3(start), &conv(&r, <$quat>::from_rotor3), |v, r| r.mul_vec3(v));
                chain(&mut g, "nalgebra", <Vector3<S> as FromVector3<S>>::from_vector3(start), &conv(&r, UnitQuaternion::<S>::from_rotor3), |v, r| r * v);
                chain(&mut g, "ultraviolet", <$uvec>::from_vector3(start), &conv(&r, <$rotor>::from_rotor3), |v, r| r * v);
                chain(&mut g, "table", tv[0], &tr, |v, r| table.sandwich(&r, &v));
                g.finish();
            }

            /// One rotor applied to a batch of vectors (peers may precompute a matrix).
            pub fn rotate_batch(c: &mut Criterion) {
                let r = black_box(rotors(5)[0]);
                let v: Vec<[S; 3]> = cast_all(&g3_vectors(BATCH, 6));
                let table = black_box(G3::euclidean());
                let tr = dense(&table, &[0, 2], &[r])[0];
                let tv = dense(&table, &[1], &v);
                let ga_r = ga::Even::from_array(r);
                let quat = <$quat>::from_rotor3(r);
                let mat3 = <$mat3>::from_quat(quat);
                let na_quat = UnitQuaternion::<S>::from_rotor3(r);
                let na_matrix = na_quat.to_rotation_matrix();
                let uv_rotor = <$rotor>::from_rotor3(r);

                let mut g = group(c, &format!("g3/rotate_batch/{PRECISION}/batch"));
                batch1(&mut g, "ga-core", &conv(&v, ga::Vector::from_array), |v| ga_r.sandwich(v));
                batch1(&mut g, "ga-core sandwich_unit", &conv(&v, ga::Vector::from_array), |v| ga_r.sandwich_unit(v));
                in_place(&mut g, "ga-core sandwich_vectors", &mut conv(&v, ga::Vector::from_array), |vs| ga_r.sandwich_vectors(vs));
                kernel2(&mut g, "ga-core sandwich_all", &conv(&v, ga::Vector::from_array), &[()], ga::Vector::ZERO,
                    |v, _, out| kernels::sandwich_all(ga_r, v, out).expect("equal lengths"));
                $(
                    let ga_wide_r = ga::$ga_batch::Even::splat(ga_r);
                    batch1(&mut g, concat!("ga-core x", $ga_lanes),
                        &lanes(&conv(&v, ga::Vector::from_array), ga::$ga_batch::Vector::from_items),
                        |v| ga::$ga_batch::Sandwich::sandwich(ga_wide_r, v));
                )+
                let glam_v = conv(&v, <$vec3 as FromVector3<S>>::from_vector3);
                batch1(&mut g, "glam", &glam_v, |v| quat.mul_vec3(v));
                batch1(&mut g, "glam mat3", &glam_v, |v| mat3 * v);
                let na_v = conv(&v, <Vector3<S> as FromVector3<S>>::from_vector3);
                batch1(&mut g, "nalgebra", &na_v, |v| na_quat * v);
                batch1(&mut g, "nalgebra matrix", &na_v, |v| na_matrix * v);
                batch1(&mut g, "ultraviolet", &conv(&v, <$uvec>::from_vector3), |v| uv_rotor * v);
                in_place(&mut g, "ultraviolet rotate_vecs", &mut conv(&v, <$uvec>::from_vector3), |vs| uv_rotor.rotate_vecs(vs));
                $(
                    let wide_r = pack::<S, $w, _, $lanes, 4>(&[r; $lanes], <$wrotor>::from_rotor3)[0];
                    batch1(&mut g, concat!("ultraviolet x", $lanes),
                        &pack::<S, $w, _, $lanes, 3>(&v, <$wvec>::from_vector3), |v| wide_r * v);
                )+
                batch1(&mut g, "table", &tv, |v| table.sandwich(&tr, &v));
                g.finish();

                let mut g = group(c, &format!("g3/rotate_batch/{PRECISION}/chain"));
                let steps = [(); BATCH];
                let start = v[0];
                chain(&mut g, "ga-core", ga::Vector::from_array(start), &steps, |v, ()| ga_r.sandwich(v));
                chain(&mut g, "glam", glam_v[0], &steps, |v, ()| quat.mul_vec3(v));
                chain(&mut g, "glam mat3", glam_v[0], &steps, |v, ()| mat3 * v);
                chain(&mut g, "nalgebra", na_v[0], &steps, |v, ()| na_quat * v);
                chain(&mut g, "nalgebra matrix", na_v[0], &steps, |v, ()| na_matrix * v);
                chain(&mut g, "ultraviolet", <$uvec>::from_vector3(start), &steps, |v, ()| uv_rotor * v);
                chain(&mut g, "table", tv[0], &steps, |v, ()| table.sandwich(&tr, &v));
                g.finish();
            }

            /// Bivector exp (glam and nalgebra: `from_scaled_axis`).
            pub fn exp(c: &mut Criterion) {
                let b: Vec<[S; 3]> = cast_all(&g3_bivectors(BATCH, 7));
                let feed: Vec<[S; 3]> = cast_all(&g3_bivectors(BATCH, 8));
                let table = black_box(G3::euclidean());
                let (tb, tfeed) = (dense(&table, &[2], &b), dense(&table, &[2], &feed));

                let mut g = group(c, &format!("g3/exp/{PRECISION}/batch"));
                batch1(&mut g, "ga-core", &conv(&b, ga::Bivector::from_array), |b| b.exp());
                batch1(&mut g, "glam", &conv(&b, <$vec3 as FromBivector3<S>>::from_bivector3), <$quat>::from_scaled_axis);
                batch1(&mut g, "nalgebra", &conv(&b, <Vector3<S> as FromBivector3<S>>::from_bivector3), UnitQuaternion::<S>::from_scaled_axis);
                batch1(&mut g, "ultraviolet", &conv(&b, <$bivec>::from_bivector3), <$rotor>::exp_of);
                $(
                    batch1(&mut g, concat!("ultraviolet x", $lanes),
                        &pack::<S, $w, _, $lanes, 3>(&b, <$wbivec>::from_bivector3), <$wrotor>::exp_of);
                )+
                batch1(&mut g, "table", &tb, |b| table.exp(&b));
                g.finish();

                // B <- <exp B>_2 + <exp B>_0 C: the next input depends on the whole result.
                let mut g = group(c, &format!("g3/exp/{PRECISION}/chain"));
                chain(&mut g, "ga-core", ga::Bivector::from_array(b[0]), &conv(&feed, ga::Bivector::from_array), |b, c| {
                    let r = b.exp();
                    ga::Bivector::new(r.e12, r.e13, r.e23) + c * r.s
                });
                let glam_axis = <$vec3 as FromBivector3<S>>::from_bivector3;
                chain(&mut g, "glam", glam_axis(b[0]), &conv(&feed, glam_axis), |v, c| {
                    let q = <$quat>::from_scaled_axis(v);
                    q.xyz() + c * q.w
                });
                let na_axis = <Vector3<S> as FromBivector3<S>>::from_bivector3;
                chain(&mut g, "nalgebra", na_axis(b[0]), &conv(&feed, na_axis), |v, c| {
                    let q = UnitQuaternion::<S>::from_scaled_axis(v);
                    q.imag() + c * q.scalar()
                });
                chain(&mut g, "ultraviolet", <$bivec>::from_bivector3(b[0]), &conv(&feed, <$bivec>::from_bivector3), |b, c| {
                    let r = <$rotor>::exp_of(b);
                    r.bv + c * r.s
                });
                chain(&mut g, "table", tb[0], &tfeed, |b, c| {
                    let r = table.exp(&b);
                    add(&table.grade_part(&r, 2), &scale(&c, r[0]))
                });
                g.finish();
            }

            /// Rotor log (glam: `to_scaled_axis`, nalgebra: `scaled_axis`).
            pub fn log(c: &mut Criterion) {
                let r = rotors(9);
                let table = black_box(G3::euclidean());
                let tr = dense(&table, &[0, 2], &r);

                let mut g = group(c, &format!("g3/log/{PRECISION}/batch"));
                batch1(&mut g, "ga-core", &conv(&r, ga::Even::from_array), |r| r.log());
                batch1(&mut g, "glam", &conv(&r, <$quat>::from_rotor3), |q| q.to_scaled_axis());
                batch1(&mut g, "nalgebra", &conv(&r, UnitQuaternion::<S>::from_rotor3), |q| q.scaled_axis());
                batch1(&mut g, "ultraviolet", &conv(&r, <$rotor>::from_rotor3), <$rotor>::log_of);
                $(
                    batch1(&mut g, concat!("ultraviolet x", $lanes),
                        &pack::<S, $w, _, $lanes, 4>(&r, <$wrotor>::from_rotor3), <$wrotor>::log_of);
                )+
                batch1(&mut g, "table", &tr, |r| table.log(&r));
                g.finish();

                // The same rotors with the scalar part made non-negative (`-R` is the same
                // rotation): the path most inputs take, apart from log's branch past a
                // right angle.
                let positive: Vec<[S; 4]> = r
                    .iter()
                    .map(|x| if x[0] < 0.0 { x.map(|c| -c) } else { *x })
                    .collect();
                let mut g = group(c, &format!("g3/log/{PRECISION}/batch-nonnegative-scalar"));
                batch1(&mut g, "ga-core", &conv(&positive, ga::Even::from_array), |r| r.log());
                g.finish();

                // The next rotor is the input plus a small multiple of the last log.
                let eps = LOG_FEEDBACK as S;
                let mut g = group(c, &format!("g3/log/{PRECISION}/chain"));
                chain(&mut g, "ga-core", ga::Bivector::ZERO, &conv(&r, ga::Even::from_array), |b, r| (r + b * eps).log().unwrap_or(b));
                chain(&mut g, "glam", <$vec3>::ZERO, &conv(&r, <$quat>::from_rotor3), |v, q| {
                    (q + <$quat>::from_xyzw(v.x, v.y, v.z, 0.0) * eps).to_scaled_axis()
                });
                chain(&mut g, "nalgebra", Vector3::<S>::zeros(), &conv(&r, UnitQuaternion::<S>::from_rotor3), |v, q| {
                    UnitQuaternion::new_unchecked(q.into_inner() + Quaternion::from_imag(v * eps)).scaled_axis()
                });
                chain(&mut g, "ultraviolet", <$bivec>::zero(), &conv(&r, <$rotor>::from_rotor3), |b, r| {
                    (r + <$rotor>::new(0.0, b * eps)).log_of()
                });
                chain(&mut g, "table", [0.0; 8], &tr, |b, r| table.log(&add(&r, &scale(&b, eps))));
                g.finish();
            }
        }
    };
}

g3_rotor_benches!(
    single, f32,
    glam: (glam::Quat, glam::Vec3, glam::Mat3),
    ultraviolet: (ultraviolet::Rotor3, ultraviolet::Vec3, ultraviolet::Bivec3),
    wide: [
        (4, ultraviolet::f32x4, ultraviolet::Rotor3x4, ultraviolet::Vec3x4, ultraviolet::Bivec3x4),
        (8, ultraviolet::f32x8, ultraviolet::Rotor3x8, ultraviolet::Vec3x8, ultraviolet::Bivec3x8)
    ],
    batch: [(4, x4), (8, x8)]
);

g3_rotor_benches!(
    double, f64,
    glam: (glam::DQuat, glam::DVec3, glam::DMat3),
    ultraviolet: (ultraviolet::DRotor3, ultraviolet::DVec3, ultraviolet::DBivec3),
    wide: [
        (2, ultraviolet::f64x2, ultraviolet::DRotor3x2, ultraviolet::DVec3x2, ultraviolet::DBivec3x2),
        (4, ultraviolet::f64x4, ultraviolet::DRotor3x4, ultraviolet::DVec3x4, ultraviolet::DBivec3x4)
    ],
    batch: [(4, x4)]
);

criterion_group! {
    name = benches;
    config = config();
    targets =
        single::rotor_mul, double::rotor_mul,
        single::sandwich, double::sandwich,
        single::rotate_batch, double::rotate_batch,
        single::exp, double::exp,
        single::log, double::log
}
criterion_main!(benches);
