//! Shared by the bench files: criterion settings, the batch runners (throughput) and the
//! chain runner (latency). Each bench file uses a different subset.
#![allow(dead_code)] // Each bench target compiles this module and uses only part of it.

use std::time::Duration;

use criterion::measurement::WallTime;
use criterion::{black_box, BenchmarkGroup, Criterion, Throughput};
pub use ga_benches::inputs::BATCH;

/// Short runs (the machine is small and shared): 0.5 s warm-up, 2 s of 30 samples, and
/// a tenth of criterion's default bootstrap resamples, which only refine the intervals.
pub fn config() -> Criterion {
    Criterion::default()
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(500))
        .sample_size(30)
        .nresamples(10_000)
}

/// A group whose times are reported per item of a batch (or per step of a chain).
pub fn group<'a>(c: &'a mut Criterion, name: &str) -> BenchmarkGroup<'a, WallTime> {
    let mut g = c.benchmark_group(name);
    g.throughput(Throughput::Elements(BATCH as u64));
    g
}

/// Converts every item with `f` (outside the timed loop).
pub fn conv<A: Copy, T>(xs: &[A], f: impl Fn(A) -> T) -> Vec<T> {
    xs.iter().map(|&x| f(x)).collect()
}

/// Throughput of a unary operation: `f` on every item, results written to a buffer.
pub fn batch1<A: Copy, O>(g: &mut BenchmarkGroup<WallTime>, id: &str, a: &[A], f: impl Fn(A) -> O) {
    let mut out = Vec::with_capacity(a.len());
    g.bench_function(id, |bencher| {
        bencher.iter(|| {
            out.clear();
            out.extend(black_box(a).iter().map(|&x| f(x)));
            black_box(&mut out);
        })
    });
}

/// Throughput of a binary operation on pairs `(a[i], b[i])`.
pub fn batch2<A: Copy, B: Copy, O>(
    g: &mut BenchmarkGroup<WallTime>,
    id: &str,
    a: &[A],
    b: &[B],
    f: impl Fn(A, B) -> O,
) {
    let mut out = Vec::with_capacity(a.len());
    g.bench_function(id, |bencher| {
        bencher.iter(|| {
            out.clear();
            out.extend(
                black_box(a)
                    .iter()
                    .zip(black_box(b))
                    .map(|(&x, &y)| f(x, y)),
            );
            black_box(&mut out);
        })
    });
}

/// Throughput of an in-place batch kernel (ultraviolet's `rotate_vecs`). The items are
/// transformed again on every iteration, so `f` must keep them bounded (a rotation).
pub fn in_place<T>(
    g: &mut BenchmarkGroup<WallTime>,
    id: &str,
    items: &mut [T],
    f: impl Fn(&mut [T]),
) {
    g.bench_function(id, |bencher| bencher.iter(|| f(black_box(&mut *items))));
}

/// Latency: `x = f(x, input)` over all inputs, each step waiting for the last.
pub fn chain<A: Copy, X: Copy>(
    g: &mut BenchmarkGroup<WallTime>,
    id: &str,
    start: X,
    inputs: &[A],
    f: impl Fn(X, A) -> X,
) {
    g.bench_function(id, |bencher| {
        bencher.iter(|| {
            let mut x = black_box(start);
            for &a in black_box(inputs) {
                x = f(x, a);
            }
            x
        })
    });
}

/// Throughput of a slice kernel `f(a, b, out)` (one call per batch).
pub fn kernel2<A, B, O: Clone>(
    g: &mut BenchmarkGroup<WallTime>,
    id: &str,
    a: &[A],
    b: &[B],
    zero: O,
    f: impl Fn(&[A], &[B], &mut [O]),
) {
    let mut out = vec![zero; a.len()];
    g.bench_function(id, |bencher| {
        bencher.iter(|| {
            f(black_box(a), black_box(b), &mut out);
            black_box(&mut out);
        })
    });
}
