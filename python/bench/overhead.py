"""The Python layer's overhead: ga_rs.g3.sandwich on 1e6 float64 items against the same
ga-core kernels called from Rust (the criterion bench python/benches/overhead.rs).

    cargo bench --manifest-path python/Cargo.toml --bench overhead -- --noplot
    python python/bench/overhead.py    # reads criterion's medians from python/target/criterion

Each figure is a median over many single calls with ``out=`` given (the Rust bench writes
into one preallocated output too), in wall time and in the calling thread's CPU time (the
kernel runs on the calling thread with the GIL released); the CPU time leaves out the time
other processes held the core, which on a shared machine inflates wall times.
"""

import json
import pathlib
import statistics
import time

import numpy as np

from ga_rs import g3

N = 1_000_000
CRITERION = pathlib.Path(__file__).resolve().parents[1] / "target" / "criterion"

rng = np.random.default_rng(1)
R = rng.normal(size=(N, 4))
R /= np.linalg.norm(R, axis=-1, keepdims=True)
V = rng.normal(size=(N, 3))
out = np.empty_like(V)
r = R[0].copy()


def medians(call, repeat=101):
    """Median wall and thread-CPU milliseconds of single calls."""
    call()
    wall, cpu = [], []
    for _ in range(repeat):
        w, c = time.perf_counter_ns(), time.thread_time_ns()
        call()
        cpu.append(time.thread_time_ns() - c)
        wall.append(time.perf_counter_ns() - w)
    return statistics.median(wall) / 1e6, statistics.median(cpu) / 1e6


def rust(group, bench):
    """Criterion's median in milliseconds, or None before the bench has run."""
    path = CRITERION / group / bench / "new" / "estimates.json"
    if not path.exists():
        return None
    return json.loads(path.read_text())["median"]["point_estimate"] / 1e6


cases = [
    ("one rotor on 1e6 vectors", "sandwich_all 1e6 vectors", lambda: g3.sandwich(r, V, out=out)),
    ("1e6 rotors, each on its own vector", "sandwich_pairs 1e6 rotors and vectors",
     lambda: g3.sandwich(R, V, out=out)),
]
print("| case | wall: Python / Rust (ms) | ratio | CPU: Python / Rust (ms) | ratio |")
print("|---|---:|---:|---:|---:|")
for case, bench, call in cases:
    py_wall, py_cpu = medians(call)
    rs_wall, rs_cpu = rust("python_overhead_f64", bench), rust("python_overhead_cpu_f64", bench)
    cells = []
    for p, q in ((py_wall, rs_wall), (py_cpu, rs_cpu)):
        cells += [f"{p:.3f} / {q:.3f}", f"{p / q:.3f}"] if q else [f"{p:.3f} / (run the bench)", ""]
    print(f"| {case} | " + " | ".join(cells) + " |")
