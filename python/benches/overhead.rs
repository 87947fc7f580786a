//! The slice kernels `ga_rs.g3.sandwich` calls, timed from Rust on the sizes of
//! `python/bench/bench.py`'s large rows (1e6 float64 vectors: one rotor on all of them,
//! and a rotor per vector), so that the Python layer's overhead is the ratio of the two.
//!
//! `cargo bench --manifest-path python/Cargo.toml --bench overhead` (built with the
//! package's release profile, as maturin builds the extension).

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use ga_core::f64::g3::{Rotor, Vector};
use ga_core::kernels::f64 as kernels;

/// The item count of the Python benchmark's large rows.
const N: usize = 1_000_000;

/// A deterministic stream of numbers in [-1, 1) (splitmix64): the kernels' speed does not
/// depend on the values, only on their being ordinary floats.
fn uniform(seed: u64, count: usize) -> Vec<f64> {
    let mut state = seed;
    (0..count)
        .map(|_| {
            state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            z ^= z >> 31;
            (z >> 11) as f64 / (1u64 << 52) as f64 - 1.0
        })
        .collect()
}

fn vectors(seed: u64) -> Vec<Vector> {
    uniform(seed, 3 * N)
        .chunks_exact(3)
        .map(|c| Vector::new(c[0], c[1], c[2]))
        .collect()
}

fn rotors(seed: u64) -> Vec<Rotor> {
    uniform(seed, 4 * N)
        .chunks_exact(4)
        .map(|c| Rotor::new(c[0], c[1], c[2], c[3]).normalized())
        .collect()
}

fn sandwich(c: &mut Criterion) {
    let v = vectors(1);
    let r = rotors(2);
    let mut out = vec![Vector::ZERO; N];
    let mut g = c.benchmark_group("python_overhead/f64");
    g.sample_size(20);
    g.bench_function("sandwich_all 1e6 vectors", |b| {
        b.iter(|| kernels::sandwich_all(black_box(r[0]), black_box(&v), &mut out))
    });
    g.bench_function("sandwich_pairs 1e6 rotors and vectors", |b| {
        b.iter(|| kernels::sandwich_pairs(black_box(&r), black_box(&v), &mut out))
    });
    g.finish();
}

criterion_group!(benches, sandwich);
criterion_main!(benches);
