//! G4 against the table-driven algebra (no peer library has G4): the full product,
//! rotor * rotor (`Even * Even`), the rotor sandwich of a vector, bivector exp and the
//! general inverse, in
//! f32 and f64; per item over a batch (throughput) and per step of a dependent chain
//! (latency).

mod common;

use common::{batch1, batch2, chain, config, conv, group, BATCH};
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use ga_benches::inputs::{cast_all, g4_bivectors, g4_multivectors, g4_rotors, g4_vectors};
use ga_benches::table::{add, scale, G4};

/// Coefficient bound of the right factors in the multivector chain: the coefficient
/// 1-norm of a factor is at most 16 * 0.05 < 1, so `m <- m q + c` stays bounded.
const CHAIN_FACTOR_AMPLITUDE: f64 = 0.05;

macro_rules! g4_benches {
    ($module:ident, $s:ident, batch: [$(($ga_lanes:literal, $ga_batch:ident)),*]) => {
        mod $module {
            use super::*;
            use ga::Sandwich as _;
            use ga_core::$s::g4 as ga;

            type S = $s;
            const PRECISION: &str = stringify!($s);

            fn dense<const K: usize>(table: &G4, grades: &[u32], xs: &[[S; K]]) -> Vec<[S; 16]> {
                let blades = table.blades_of_grades(grades);
                xs.iter().map(|x| table.embed(&blades, x)).collect()
            }

            /// The full multivector product.
            pub fn multivector_mul(c: &mut Criterion) {
                let a: Vec<[S; 16]> = cast_all(&g4_multivectors(BATCH, 1.0, 41));
                let b: Vec<[S; 16]> = cast_all(&g4_multivectors(BATCH, 1.0, 42));
                let q: Vec<[S; 16]> = cast_all(&g4_multivectors(BATCH, CHAIN_FACTOR_AMPLITUDE, 43));
                let table = black_box(G4::euclidean());
                let all = [0, 1, 2, 3, 4];
                let (ta, tb, tq) = (
                    dense(&table, &all, &a),
                    dense(&table, &all, &b),
                    dense(&table, &all, &q),
                );

                let mut g = group(c, &format!("g4/multivector_mul/{PRECISION}/batch"));
                batch2(
                    &mut g,
                    "ga-core",
                    &conv(&a, ga::Multivector::from_array),
                    &conv(&b, ga::Multivector::from_array),
                    |a, b| a * b,
                );
                $(
                    let lanes = |xs: &[[S; 16]]| -> Vec<ga::$ga_batch::Multivector> {
                        xs.chunks_exact($ga_lanes)
                            .map(|c| ga::$ga_batch::Multivector::from_items(std::array::from_fn(|i| ga::Multivector::from_array(c[i]))))
                            .collect()
                    };
                    batch2(&mut g, concat!("ga-core x", $ga_lanes), &lanes(&a), &lanes(&b), |a, b| a * b);
                )*
                batch2(&mut g, "table", &ta, &tb, |a, b| table.geometric(&a, &b));
                g.finish();

                // m <- m q + c: the factor q is small, so the chain neither grows nor dies out.
                let mut g = group(c, &format!("g4/multivector_mul/{PRECISION}/chain"));
                {
                    let pairs: Vec<_> = q
                        .iter()
                        .zip(&b)
                        .map(|(&q, &c)| {
                            (
                                ga::Multivector::from_array(q),
                                ga::Multivector::from_array(c),
                            )
                        })
                        .collect();
                    chain(
                        &mut g,
                        "ga-core",
                        ga::Multivector::from_array(a[0]),
                        &pairs,
                        |m, (q, c)| m * q + c,
                    );
                }
                let pairs: Vec<_> = tq.iter().copied().zip(tb.iter().copied()).collect();
                chain(&mut g, "table", ta[0], &pairs, |m, (q, c)| {
                    add(&table.geometric(&m, &q), &c)
                });
                g.finish();
            }

            /// Even * even (rotor composition).
            pub fn rotor_mul(c: &mut Criterion) {
                let p: Vec<[S; 8]> = cast_all(&g4_rotors(BATCH, 44));
                let q: Vec<[S; 8]> = cast_all(&g4_rotors(BATCH, 45));
                let table = black_box(G4::euclidean());
                let (tp, tq) = (dense(&table, &[0, 2, 4], &p), dense(&table, &[0, 2, 4], &q));

                let mut g = group(c, &format!("g4/rotor_mul/{PRECISION}/batch"));
                batch2(
                    &mut g,
                    "ga-core",
                    &conv(&p, ga::Even::from_array),
                    &conv(&q, ga::Even::from_array),
                    |a, b| a * b,
                );
                batch2(&mut g, "table", &tp, &tq, |a, b| table.geometric(&a, &b));
                g.finish();

                let mut g = group(c, &format!("g4/rotor_mul/{PRECISION}/chain"));
                chain(
                    &mut g,
                    "ga-core",
                    ga::Even::from_array(p[0]),
                    &conv(&q, ga::Even::from_array),
                    |x, a| x * a,
                );
                chain(&mut g, "table", tp[0], &tq, |x, a| table.geometric(&x, &a));
                g.finish();
            }

            /// The sandwich `R v ~R` of one vector by its own rotor.
            pub fn sandwich(c: &mut Criterion) {
                let r: Vec<[S; 8]> = cast_all(&g4_rotors(BATCH, 46));
                let v: Vec<[S; 4]> = cast_all(&g4_vectors(BATCH, 47));
                let table = black_box(G4::euclidean());
                let (tr, tv) = (dense(&table, &[0, 2, 4], &r), dense(&table, &[1], &v));

                let mut g = group(c, &format!("g4/sandwich/{PRECISION}/batch"));
                batch2(
                    &mut g,
                    "ga-core",
                    &conv(&r, ga::Even::from_array),
                    &conv(&v, ga::Vector::from_array),
                    |r, v| r.sandwich(v),
                );
                batch2(&mut g, "table", &tr, &tv, |r, v| table.sandwich(&r, &v));
                g.finish();

                let mut g = group(c, &format!("g4/sandwich/{PRECISION}/chain"));
                chain(
                    &mut g,
                    "ga-core",
                    ga::Vector::from_array(v[0]),
                    &conv(&r, ga::Even::from_array),
                    |v, r| r.sandwich(v),
                );
                chain(&mut g, "table", tv[0], &tr, |v, r| table.sandwich(&r, &v));
                g.finish();
            }

            /// The general inverse (a 16 x 16 solve, refined once and certified), with the
            /// full product beside it as the unit of cost.
            pub fn inverse(c: &mut Criterion) {
                let a: Vec<[S; 16]> = cast_all(&g4_multivectors(BATCH, 1.0, 50));
                let b: Vec<[S; 16]> = cast_all(&g4_multivectors(BATCH, 1.0, 51));
                let mut g = group(c, &format!("g4/multivector_inverse/{PRECISION}/batch"));
                batch1(
                    &mut g,
                    "ga-core inverse",
                    &conv(&a, ga::Multivector::from_array),
                    |a| a.inverse(),
                );
                batch2(
                    &mut g,
                    "ga-core product",
                    &conv(&a, ga::Multivector::from_array),
                    &conv(&b, ga::Multivector::from_array),
                    |a, b| a * b,
                );
                g.finish();
            }

            /// Bivector exp (non-simple bivectors: two invariant planes).
            pub fn exp(c: &mut Criterion) {
                let b: Vec<[S; 6]> = cast_all(&g4_bivectors(BATCH, 48));
                let feed: Vec<[S; 6]> = cast_all(&g4_bivectors(BATCH, 49));
                let table = black_box(G4::euclidean());
                let (tb, tfeed) = (dense(&table, &[2], &b), dense(&table, &[2], &feed));

                let mut g = group(c, &format!("g4/exp/{PRECISION}/batch"));
                batch1(
                    &mut g,
                    "ga-core",
                    &conv(&b, ga::Bivector::from_array),
                    |b| b.exp(),
                );
                batch1(&mut g, "table", &tb, |b| table.exp(&b));
                g.finish();

                // B <- <exp B>_2 + (<exp B>_0 + <exp B>_4) C: every component feeds the next.
                let mut g = group(c, &format!("g4/exp/{PRECISION}/chain"));
                chain(
                    &mut g,
                    "ga-core",
                    ga::Bivector::from_array(b[0]),
                    &conv(&feed, ga::Bivector::from_array),
                    |b, c| {
                        let r = b.exp();
                        ga::Bivector::new(r.e12, r.e13, r.e14, r.e23, r.e24, r.e34)
                            + c * (r.s + r.e1234)
                    },
                );
                chain(&mut g, "table", tb[0], &tfeed, |b, c| {
                    let r = table.exp(&b);
                    add(&table.grade_part(&r, 2), &scale(&c, r[0] + r[0b1111]))
                });
                g.finish();
            }
        }
    };
}

g4_benches!(single, f32, batch: [(4, x4)]);
g4_benches!(double, f64, batch: []);

criterion_group! {
    name = benches;
    config = config();
    targets =
        single::multivector_mul, double::multivector_mul,
        single::rotor_mul, double::rotor_mul,
        single::sandwich, double::sandwich,
        single::exp, double::exp,
        single::inverse, double::inverse
}
criterion_main!(benches);
