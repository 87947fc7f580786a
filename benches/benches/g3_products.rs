//! G3 products against glam, nalgebra, ultraviolet and the table-driven algebra:
//! vector * vector (peers: dot and cross or wedge) and the full multivector product
//! (only the table-driven algebra has it), in f32 and f64; per item over a batch
//! (throughput) and per step of a dependent chain (latency).

mod common;

use common::{batch2, chain, config, conv, group, BATCH};
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use ga_benches::inputs::{cast_all, g3_multivectors, g3_vectors};
use ga_benches::peers::{pack, FromVector3};
use ga_benches::table::{add, scale, G3};
use nalgebra::Vector3;

/// Coefficient bound of the right factors in the multivector chain: the coefficient
/// 1-norm of a factor is at most 8 * 0.1 < 1, so `m <- m q + c` stays bounded.
const CHAIN_FACTOR_AMPLITUDE: f64 = 0.1;

macro_rules! g3_product_benches {
    (
        $module:ident, $s:ident,
        glam: $vec3:ty,
        ultraviolet: ($rotor:ty, $uvec:ty),
        wide: [$(($lanes:literal, $w:ty, $wrotor:ty, $wvec:ty)),+]
    ) => {
        mod $module {
            use super::*;
            use ga_core::$s::g3 as ga;

            type S = $s;
            const PRECISION: &str = stringify!($s);

            fn dense<const K: usize>(table: &G3, grades: &[u32], xs: &[[S; K]]) -> Vec<[S; 8]> {
                let blades = table.blades_of_grades(grades);
                xs.iter().map(|x| table.embed(&blades, x)).collect()
            }

            /// Vector * vector (peers: dot and cross, or dot and wedge).
            pub fn vector_mul(c: &mut Criterion) {
                let a: Vec<[S; 3]> = cast_all(&g3_vectors(BATCH, 21));
                let b: Vec<[S; 3]> = cast_all(&g3_vectors(BATCH, 22));
                let table = black_box(G3::euclidean());
                let (ta, tb) = (dense(&table, &[1], &a), dense(&table, &[1], &b));
                let glam_vec = <$vec3 as FromVector3<S>>::from_vector3;
                let na_vec = <Vector3<S> as FromVector3<S>>::from_vector3;

                let mut g = group(c, &format!("g3/vector_mul/{PRECISION}/batch"));
                batch2(&mut g, "ga-core", &conv(&a, ga::Vector::from_array), &conv(&b, ga::Vector::from_array), |a, b| a * b);
                batch2(&mut g, "glam", &conv(&a, glam_vec), &conv(&b, glam_vec), |a, b| (a.dot(b), a.cross(b)));
                batch2(&mut g, "nalgebra", &conv(&a, na_vec), &conv(&b, na_vec), |a, b| (a.dot(&b), a.cross(&b)));
                batch2(&mut g, "ultraviolet", &conv(&a, <$uvec>::from_vector3), &conv(&b, <$uvec>::from_vector3), |a, b| {
                    <$rotor>::new(a.dot(b), a.wedge(b))
                });
                $(
                    batch2(&mut g, concat!("ultraviolet x", $lanes),
                        &pack::<S, $w, _, $lanes, 3>(&a, <$wvec>::from_vector3),
                        &pack::<S, $w, _, $lanes, 3>(&b, <$wvec>::from_vector3),
                        |a, b| <$wrotor>::new(a.dot(b), a.wedge(b)));
                )+
                batch2(&mut g, "table", &ta, &tb, |a, b| table.geometric(&a, &b));
                g.finish();

                // a <- a x b + (a . b) b = (e23, -e13, e12) of ab plus <ab>_0 b: the next
                // vector uses every component of the product and keeps |a| for unit b.
                let mut g = group(c, &format!("g3/vector_mul/{PRECISION}/chain"));
                chain(&mut g, "ga-core", ga::Vector::from_array(a[0]), &conv(&b, ga::Vector::from_array), |a, b| {
                    let p = a * b;
                    ga::Vector::new(p.e23, -p.e13, p.e12) + b * p.s
                });
                chain(&mut g, "glam", glam_vec(a[0]), &conv(&b, glam_vec), |a, b| a.cross(b) + b * a.dot(b));
                chain(&mut g, "nalgebra", na_vec(a[0]), &conv(&b, na_vec), |a, b| a.cross(&b) + b * a.dot(&b));
                chain(&mut g, "ultraviolet", <$uvec>::from_vector3(a[0]), &conv(&b, <$uvec>::from_vector3), |a, b| {
                    let w = a.wedge(b);
                    <$uvec>::new(w.yz, -w.xz, w.xy) + b * a.dot(b)
                });
                let [e1, e2, e3, e12, e13, e23] = [0b001, 0b010, 0b100, 0b011, 0b101, 0b110];
                chain(&mut g, "table", ta[0], &tb, |a, b| {
                    let p = table.geometric(&a, &b);
                    let mut dual = [0.0; 8];
                    dual[e1] = p[e23];
                    dual[e2] = -p[e13];
                    dual[e3] = p[e12];
                    add(&dual, &scale(&b, p[0]))
                });
                g.finish();
            }

            /// The full multivector product.
            pub fn multivector_mul(c: &mut Criterion) {
                let a: Vec<[S; 8]> = cast_all(&g3_multivectors(BATCH, 1.0, 23));
                let b: Vec<[S; 8]> = cast_all(&g3_multivectors(BATCH, 1.0, 24));
                let q: Vec<[S; 8]> = cast_all(&g3_multivectors(BATCH, CHAIN_FACTOR_AMPLITUDE, 25));
                let table = black_box(G3::euclidean());
                let (ta, tb, tq) = (dense(&table, &[0, 1, 2, 3], &a), dense(&table, &[0, 1, 2, 3], &b), dense(&table, &[0, 1, 2, 3], &q));

                let mut g = group(c, &format!("g3/multivector_mul/{PRECISION}/batch"));
                batch2(&mut g, "ga-core", &conv(&a, ga::Multivector::from_array), &conv(&b, ga::Multivector::from_array), |a, b| a * b);
                batch2(&mut g, "table", &ta, &tb, |a, b| table.geometric(&a, &b));
                g.finish();

                // m <- m q + c: the factor q is small, so the chain neither grows nor dies out.
                let mut g = group(c, &format!("g3/multivector_mul/{PRECISION}/chain"));
                {
                    let pairs: Vec<_> = q.iter().zip(&b).map(|(&q, &c)| (ga::Multivector::from_array(q), ga::Multivector::from_array(c))).collect();
                    chain(&mut g, "ga-core", ga::Multivector::from_array(a[0]), &pairs, |m, (q, c)| m * q + c);
                }
                let pairs: Vec<_> = tq.iter().copied().zip(tb.iter().copied()).collect();
                chain(&mut g, "table", ta[0], &pairs, |m, (q, c)| add(&table.geometric(&m, &q), &c));
                g.finish();
            }
        }
    };
}

g3_product_benches!(
    single, f32,
    glam: glam::Vec3,
    ultraviolet: (ultraviolet::Rotor3, ultraviolet::Vec3),
    wide: [
        (4, ultraviolet::f32x4, ultraviolet::Rotor3x4, ultraviolet::Vec3x4),
        (8, ultraviolet::f32x8, ultraviolet::Rotor3x8, ultraviolet::Vec3x8)
    ]
);

g3_product_benches!(
    double, f64,
    glam: glam::DVec3,
    ultraviolet: (ultraviolet::DRotor3, ultraviolet::DVec3),
    wide: [
        (2, ultraviolet::f64x2, ultraviolet::DRotor3x2, ultraviolet::DVec3x2),
        (4, ultraviolet::f64x4, ultraviolet::DRotor3x4, ultraviolet::DVec3x4)
    ]
);

criterion_group! {
    name = benches;
    config = config();
    targets =
        single::vector_mul, double::vector_mul,
        single::multivector_mul, double::multivector_mul
}
criterion_main!(benches);
