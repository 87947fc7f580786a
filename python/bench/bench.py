"""Time ga_rs against kingdon, clifford and plain numpy on G3 rotations; print a Markdown table.

Set-up (once; kingdon and clifford pull numba):

    python3 -m venv /tmp/ga-bench && /tmp/ga-bench/bin/pip install ./python kingdon clifford
    /tmp/ga-bench/bin/python python/bench/bench.py

A library that is not installed is left out of the table (and named under it). Each figure
is the best of 15 repeats, in microseconds per call; the checks at the start make sure
every contestant computes the same rotation.
"""

import platform
import sys
import timeit

import numpy as np

from ga_rs import g3

rng = np.random.default_rng(1)
missing = []
try:
    from kingdon import Algebra
    alg = Algebra(3, 0, 0)
except ImportError:
    alg = None
    missing.append("kingdon")
try:
    from clifford.g3 import blades
except ImportError:
    blades = None
    missing.append("clifford")


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


REPEATS = 15


def best_us(fn, budget=0.3):
    """Best time per call in microseconds over `REPEATS` repeats, each sized to about
    `budget` / 5 seconds: on a shared CPU a long call (1e6 items, milliseconds) is often
    preempted, and the more repeats the likelier one runs uninterrupted."""
    fn()
    timer = timeit.Timer(fn)
    number, took = timer.autorange()
    number = max(1, int(number * budget / max(took, 1e-9) / 5))
    return min(timer.repeat(repeat=REPEATS, number=number)) / number * 1e6


def unit(n):
    r = rng.normal(size=(n, 4))
    return r / np.linalg.norm(r, axis=-1, keepdims=True)


def quat_rotate(r, v):
    """v + 2w (u x v) + 2 u x (u x v) on rotors [s, e12, e13, e23] (u = (-e23, e13, -e12))."""
    w = r[..., :1]
    u = np.stack([-r[..., 3], r[..., 2], -r[..., 1]], axis=-1)
    uv = np.cross(u, v)
    return v + 2 * w * uv + 2 * np.cross(u, uv)


def quat_mul(a, b):
    """The rotor product written as numpy arithmetic on [s, e12, e13, e23]."""
    s1, a12, a13, a23 = a
    s2, b12, b13, b23 = b
    return np.array([
        s1 * s2 - a12 * b12 - a13 * b13 - a23 * b23,
        s1 * b12 + a12 * s2 - a13 * b23 + a23 * b13,
        s1 * b13 + a13 * s2 + a12 * b23 - a23 * b12,
        s1 * b23 + a23 * s2 - a12 * b13 + a13 * b12,
    ])


rows = {}


def add(case, who, fn):
    rows.setdefault(case, {})[who] = best_us(fn)


# One product and one sandwich.
a, b = unit(2)
v = rng.normal(size=3)
assert np.allclose(quat_mul(a, b), g3.geometric(a, b))
assert np.allclose(quat_rotate(a, v), g3.sandwich(a, v))
A, B, Vo = g3.Rotor(*a), g3.Rotor(*b), g3.Vector(*v)
add("one geometric product", "ga_rs object", lambda: A * B)
add("one geometric product", "ga_rs array", lambda: g3.geometric(a, b))
add("one geometric product", "numpy formula", lambda: quat_mul(a, b))
add("one sandwich", "ga_rs object", lambda: A.sandwich(Vo))
add("one sandwich", "ga_rs array", lambda: g3.sandwich(a, v))
add("one sandwich", "numpy formula", lambda: quat_rotate(a, v))
add("one sandwich", "numpy V @ M.T", lambda: v @ g3.to_matrix(a).T)
if alg is not None:
    ka = alg.evenmv(e=a[0], e12=a[1], e13=a[2], e23=a[3])
    kb = alg.evenmv(e=b[0], e12=b[1], e13=b[2], e23=b[3])
    kv = alg.vector(list(v))
    assert np.allclose(np.array((ka >> kv).values()), g3.sandwich(a, v))
    add("one geometric product", "kingdon", lambda: ka * kb)
    add("one sandwich", "kingdon", lambda: ka >> kv)
if blades is not None:
    ca = a[0] + a[1] * blades["e12"] + a[2] * blades["e13"] + a[3] * blades["e23"]
    cb = b[0] + b[1] * blades["e12"] + b[2] * blades["e13"] + b[3] * blades["e23"]
    cv = v[0] * blades["e1"] + v[1] * blades["e2"] + v[2] * blades["e3"]
    cr = ca * cv * ~ca
    assert np.allclose([cr[blades["e1"]], cr[blades["e2"]], cr[blades["e3"]]], g3.sandwich(a, v))
    add("one geometric product", "clifford", lambda: ca * cb)
    add("one sandwich", "clifford", lambda: ca * cv * ~ca)

# One rotor on many vectors, and a rotor per vector.
for n in (10_000, 1_000_000):
    case = f"one rotor on {n:.0e} vectors"
    r = unit(1)[0]
    V = rng.normal(size=(n, 3))
    out = np.empty_like(V)
    assert np.allclose(g3.sandwich(r, V), quat_rotate(r, V))
    add(case, "ga_rs array", lambda: g3.sandwich(r, V, out=out))
    add(case, "numpy formula", lambda: quat_rotate(r, V))
    add(case, "numpy V @ M.T", lambda: V @ g3.to_matrix(r).T)
    if alg is not None:
        kr = alg.evenmv(e=r[0], e12=r[1], e13=r[2], e23=r[3])
        kV = alg.vector(V.T.copy())
        assert np.allclose(np.array((kr >> kV).values()).T, out)
        add(case, "kingdon", lambda: kr >> kV)
    if blades is not None and n <= 10_000:
        cr_ = r[0] + r[1] * blades["e12"] + r[2] * blades["e13"] + r[3] * blades["e23"]
        cvs = [x[0] * blades["e1"] + x[1] * blades["e2"] + x[2] * blades["e3"] for x in V]
        rev = ~cr_
        add(case, "clifford", lambda: [cr_ * x * rev for x in cvs])

n = 1_000_000
case = "1e6 rotors, each on its own vector"
R = unit(n)
V = rng.normal(size=(n, 3))
out = np.empty_like(V)
assert np.allclose(g3.sandwich(R, V), quat_rotate(R, V))
add(case, "ga_rs array", lambda: g3.sandwich(R, V, out=out))
add(case, "numpy formula", lambda: quat_rotate(R, V))
M = g3.to_matrix(R)
add(case, "numpy V @ M.T", lambda: np.einsum("nij,nj->ni", M, V))
if alg is not None:
    kR = alg.evenmv(R.T.copy())
    kV = alg.vector(V.T.copy())
    assert np.allclose(np.array((kR >> kV).values()).T, out)
    add(case, "kingdon", lambda: kR >> kV)

columns = ["ga_rs object", "ga_rs array", "kingdon", "clifford", "numpy formula", "numpy V @ M.T"]
print(f"CPU: {cpu_model()}; Python {platform.python_version()}, numpy {np.__version__}; "
      f"ga_rs kernels: {g3.instruction_set}; float64; microseconds per call (best of {REPEATS})\n")
print("| case | " + " | ".join(columns) + " |")
print("|---|" + "---:|" * len(columns))
for case, times in rows.items():
    cells = [f"{times[c]:.3g}" if c in times else "—" for c in columns]
    print(f"| {case} | " + " | ".join(cells) + " |")
print("\nnumpy V @ M.T: the matrix built by ga_rs.g3.to_matrix (per rotor: np.einsum with the "
      "matrices precomputed, their build not timed); clifford on 1e6 vectors: a Python loop, "
      "not run.")
if missing:
    print(f"\nNot installed, left out: {', '.join(missing)} (pip install kingdon clifford).")
sys.stdout.flush()
