//! The slice kernels `ga_rs.g3.sandwich` calls, timed from Rust on the sizes of
//! `python/bench/bench.py`'s large rows (1e6 float64 vectors: one rotor on all of them,
//! and a rotor per vector), so that the Python layer's overhead is the ratio of the two.
//!
//! `cargo bench --manifest-path python/Cargo.toml --bench overhead` (built with the
//! package's release profile, as maturin builds the extension). Each kernel is timed twice:
//! in wall time (`python_overhead/f64`) and in the thread's CPU time
//! (`python_overhead_cpu/f64`), which a shared machine's preemptions do not inflate;
//! `python/bench/overhead.py` times the Python calls both ways and prints the ratios.

use criterion::measurement::{Measurement, ValueFormatter};
use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};
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

/// `items` collected into memory advised for transparent huge pages before it is first
/// written, as numpy advises its arrays of 4 MiB and more on Linux: without it the Rust
/// side runs its kernels with 4 KiB pages (more TLB misses) while the Python side has
/// huge pages, and the comparison would not be of the same kernels on the same arrays.
fn advised<T>(items: impl ExactSizeIterator<Item = T>) -> Vec<T> {
    let mut v = Vec::with_capacity(items.len());
    let bytes = v.capacity() * std::mem::size_of::<T>();
    let start = v.as_mut_ptr() as usize;
    let page = 4096;
    let (first, last) = (start.div_ceil(page) * page, (start + bytes) / page * page);
    if last > first {
        // SAFETY: the range lies inside the vector's own allocation (rounded inwards to
        // whole pages); the advice changes only how the kernel backs it.
        unsafe {
            libc::madvise(
                first as *mut libc::c_void,
                last - first,
                libc::MADV_HUGEPAGE,
            )
        };
    }
    v.extend(items);
    v
}

fn vectors(seed: u64) -> Vec<Vector> {
    let u = uniform(seed, 3 * N);
    advised(u.chunks_exact(3).map(|c| Vector::new(c[0], c[1], c[2])))
}

fn rotors(seed: u64) -> Vec<Rotor> {
    let u = uniform(seed, 4 * N);
    advised(
        u.chunks_exact(4)
            .map(|c| Rotor::new(c[0], c[1], c[2], c[3]).normalized()),
    )
}

/// The calling thread's CPU time (`CLOCK_THREAD_CPUTIME_ID`), in nanoseconds: the time
/// the kernel ran, without the time other processes held the core.
struct ThreadCpuTime;

fn thread_cpu_ns() -> u64 {
    let mut t = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `t` is a valid timespec to write; the clock id is a constant Linux knows.
    let rc = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut t) };
    assert_eq!(rc, 0, "clock_gettime(CLOCK_THREAD_CPUTIME_ID) failed");
    t.tv_sec as u64 * 1_000_000_000 + t.tv_nsec as u64
}

impl Measurement for ThreadCpuTime {
    type Intermediate = u64;
    type Value = u64;
    fn start(&self) -> u64 {
        thread_cpu_ns()
    }
    fn end(&self, start: u64) -> u64 {
        thread_cpu_ns() - start
    }
    fn add(&self, a: &u64, b: &u64) -> u64 {
        a + b
    }
    fn zero(&self) -> u64 {
        0
    }
    fn to_f64(&self, v: &u64) -> f64 {
        *v as f64
    }
    fn formatter(&self) -> &dyn ValueFormatter {
        &Nanoseconds
    }
}

/// Values in nanoseconds, shown in ms (criterion's files keep nanoseconds).
struct Nanoseconds;

impl ValueFormatter for Nanoseconds {
    fn scale_values(&self, _typical: f64, values: &mut [f64]) -> &'static str {
        values.iter_mut().for_each(|v| *v /= 1e6);
        "ms (CPU)"
    }
    fn scale_throughputs(
        &self,
        _typical: f64,
        _t: &Throughput,
        values: &mut [f64],
    ) -> &'static str {
        values.iter_mut().for_each(|v| *v /= 1e6);
        "ms (CPU)"
    }
    fn scale_for_machines(&self, _values: &mut [f64]) -> &'static str {
        "ns"
    }
}

fn sandwich(c: &mut Criterion) {
    run(c, "python_overhead/f64");
}

fn sandwich_cpu(c: &mut Criterion<ThreadCpuTime>) {
    run(c, "python_overhead_cpu/f64");
}

fn run<M: Measurement>(c: &mut Criterion<M>, group: &str) {
    let v = vectors(1);
    let r = rotors(2);
    let mut out = advised(std::iter::repeat_n(Vector::ZERO, N));
    let mut g = c.benchmark_group(group);
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
criterion_group! {
    name = cpu;
    config = Criterion::default().with_measurement(ThreadCpuTime);
    targets = sandwich_cpu
}
criterion_main!(benches, cpu);
