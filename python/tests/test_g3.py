"""ga_rs.g3 against independent numpy formulas (quaternions with i = -e23, j = e13,
k = -e12, so that R v ~R is q v q*), bit for bit against the per-item objects, and its
broadcasting, dtype and error rules."""

import tracemalloc

import numpy as np
import pytest

from conftest import bits
from ga_rs import g3


def unit_rotors(rng, n, dtype=np.float64):
    r = rng.normal(size=(n, 4))
    return (r / np.linalg.norm(r, axis=-1, keepdims=True)).astype(dtype)


def quat(r):
    """Rotor [s, e12, e13, e23] -> quaternion (w, x, y, z)."""
    return np.stack([r[..., 0], -r[..., 3], r[..., 2], -r[..., 1]], axis=-1)


def rotor(q):
    return np.stack([q[..., 0], -q[..., 3], q[..., 2], -q[..., 1]], axis=-1)


def qmul(a, b):
    w1, x1, y1, z1 = np.moveaxis(a, -1, 0)
    w2, x2, y2, z2 = np.moveaxis(b, -1, 0)
    return np.stack([
        w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
        w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
        w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
        w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
    ], axis=-1)


def rotate(r, v):
    """v + 2w (u x v) + 2 u x (u x v), the quaternion formula."""
    q = quat(r)
    w, u = q[..., :1], q[..., 1:]
    uv = np.cross(u, v)
    return v + 2 * w * uv + 2 * np.cross(u, uv)


# --- against independent formulas ---------------------------------------------------

def test_rotor_product_is_the_quaternion_product(rng):
    a, b = unit_rotors(rng, 1000), unit_rotors(rng, 1000)
    np.testing.assert_allclose(g3.geometric(a, b), rotor(qmul(quat(a), quat(b))), atol=1e-15)


def test_sandwich_is_the_quaternion_rotation(rng):
    r, v = unit_rotors(rng, 1000), rng.normal(size=(1000, 3))
    np.testing.assert_allclose(g3.sandwich(r, v), rotate(r, v), atol=1e-14)
    np.testing.assert_allclose(g3.sandwich(r[0], v), rotate(r[0], v), atol=1e-14)


def test_vector_product_is_dot_plus_wedge(rng):
    a, b = rng.normal(size=(100, 3)), rng.normal(size=(100, 3))
    ab = g3.geometric(a, b)
    np.testing.assert_allclose(ab[:, 0], np.sum(a * b, axis=-1), atol=1e-14)
    w = g3.outer(a, b)
    np.testing.assert_allclose(ab[:, 1:], w, atol=0)
    # e12, e13, e23 of a ^ b
    expect = np.stack([a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0],
                       a[:, 0] * b[:, 2] - a[:, 2] * b[:, 0],
                       a[:, 1] * b[:, 2] - a[:, 2] * b[:, 1]], axis=-1)
    np.testing.assert_allclose(w, expect, atol=1e-14)
    np.testing.assert_allclose(g3.inner(a, b), np.sum(a * b, axis=-1), atol=1e-14)


def test_exp_log_axis_angle_and_matrix_round_trip(rng):
    axis = rng.normal(size=(200, 3))
    axis /= np.linalg.norm(axis, axis=-1, keepdims=True)
    angle = rng.uniform(-3, 3, size=200)
    r = g3.from_axis_angle(axis, angle)
    half = angle / 2
    q = np.concatenate([np.cos(half)[:, None], np.sin(half)[:, None] * axis], axis=-1)
    np.testing.assert_allclose(r, rotor(q), atol=1e-15)
    np.testing.assert_allclose(g3.exp(g3.log(r)), r, atol=1e-14)
    m = g3.to_matrix(r)
    v = rng.normal(size=(200, 3))
    np.testing.assert_allclose(np.einsum("nij,nj->ni", m, v), rotate(r, v), atol=1e-14)
    back = g3.from_matrix(m)
    np.testing.assert_allclose(back * np.sign(back[:, :1] * r[:, :1]), r, atol=1e-14)
    np.testing.assert_allclose(g3.reverse(r), r * [1, -1, -1, -1], atol=0)
    np.testing.assert_allclose(g3.normalize(3 * r), r, atol=1e-15)


def test_slerp_halfway_is_the_half_angle(rng):
    axis = np.array([0.0, 0.6, 0.8])
    a = g3.from_axis_angle(axis, 0.0)
    b = g3.from_axis_angle(axis, 1.0)
    np.testing.assert_allclose(g3.slerp(a, b, [0.0, 0.5, 1.0]),
                               g3.from_axis_angle(axis, [0.0, 0.5, 1.0]), atol=1e-15)


def test_log_of_a_non_unit_rotor_is_nan():
    assert np.isnan(g3.log([2.0, 0, 0, 0])).all()
    assert np.isnan(g3.from_matrix(np.ones((3, 3)))).all()


# --- bit for bit against the objects -------------------------------------------------

def test_batched_calls_equal_the_object_api_bit_for_bit(rng):
    a, b = unit_rotors(rng, 300), unit_rotors(rng, 300)
    v = rng.normal(size=(300, 3))
    biv = rng.normal(size=(300, 3))
    t = rng.uniform(size=300)
    R = lambda x: g3.Rotor(*x)
    cases = [
        (g3.geometric(a, b), [(R(x) * R(y)).to_array() for x, y in zip(a, b)]),
        (g3.sandwich(a, v), [R(x).sandwich(g3.Vector(*y)).to_array() for x, y in zip(a, v)]),
        (g3.reverse(a), [R(x).reverse().to_array() for x in a]),
        (g3.normalize(2 * a), [R(x).normalize().to_array() for x in 2 * a]),
        (g3.exp(biv), [g3.Bivector(*x).exp().to_array() for x in biv]),
        (g3.log(a), [R(x).log().to_array() for x in a]),
        (g3.slerp(a, b, t), [R(x).slerp(R(y), s).to_array() for x, y, s in zip(a, b, t)]),
        (g3.to_matrix(a), [R(x).to_matrix() for x in a]),
        (g3.geometric(v, biv), [(g3.Vector(*x) * g3.Vector(*y)).to_array() for x, y in zip(v, biv)]),
        (g3.outer(v, biv), [g3.Vector(*x).outer(g3.Vector(*y)).to_array() for x, y in zip(v, biv)]),
    ]
    for batched, items in cases:
        assert (bits(batched) == bits(np.array(items))).all()


def test_one_rotor_on_many_vectors_is_the_matrix_kernel_within_an_ulp(rng):
    r, v = unit_rotors(rng, 1)[0], rng.normal(size=(10_000, 3))
    one = g3.sandwich(r, v)
    pairs = g3.sandwich(np.broadcast_to(r, (10_000, 4)).copy(), v)
    np.testing.assert_allclose(one, pairs, rtol=0, atol=4 * np.finfo(float).eps * np.abs(v).max())


def test_float32_is_computed_in_float32(rng):
    a, b = unit_rotors(rng, 100, np.float32), unit_rotors(rng, 100, np.float32)
    v = rng.normal(size=(100, 3)).astype(np.float32)
    for out in [g3.geometric(a, b), g3.sandwich(a, v), g3.exp(v), g3.log(a), g3.slerp(a, b, 0.5),
                g3.to_matrix(a), g3.from_axis_angle(v, np.float32(1.0))]:
        assert out.dtype == np.float32
    f64 = g3.geometric(a.astype(np.float64), b.astype(np.float64))
    np.testing.assert_allclose(g3.geometric(a, b), f64, atol=1e-6)
    assert not np.array_equal(g3.geometric(a, b).astype(np.float64), f64)


# --- broadcasting and dtypes -----------------------------------------------------

def test_broadcasting_follows_numpy(rng):
    r = unit_rotors(rng, 6).reshape(2, 1, 3, 4)
    v = rng.normal(size=(5, 1, 3))
    out = g3.sandwich(r, v)
    assert out.shape == (2, 5, 3, 3)
    np.testing.assert_allclose(out, rotate(r, v), atol=1e-14)
    assert g3.sandwich(r[0, 0, 0], v[0, 0]).shape == (3,)
    assert g3.from_axis_angle([0, 0, 1.0], np.zeros((4, 2))).shape == (4, 2, 4)
    assert g3.geometric(np.zeros((0, 4)), np.zeros((1, 4))).shape == (0, 4)


def test_dtype_rules():
    r32 = np.array([1, 0, 0, 0], np.float32)
    assert g3.slerp(r32, r32, 0.5).dtype == np.float32  # a Python float is weak
    assert g3.geometric(r32, r32.astype(np.float64)).dtype == np.float64
    assert g3.geometric([1, 0, 0, 0], [1, 0, 0, 0]).dtype == np.float64  # ints -> float64
    assert g3.exp(np.zeros(3, np.float16)).dtype == np.float32


@pytest.mark.parametrize("call", [
    lambda: g3.sandwich(np.zeros((2, 3)), np.zeros((2, 3))),
    lambda: g3.sandwich(np.zeros((2, 4)), np.zeros((3, 3))),
    lambda: g3.geometric(np.zeros(4), np.zeros(3)),
    lambda: g3.exp(np.zeros((2, 4))),
    lambda: g3.from_matrix(np.zeros((2, 3))),
    lambda: g3.reverse(np.zeros(4), out=np.zeros((2, 4))),
    lambda: g3.reverse(np.zeros((2, 4)), out=np.zeros((4, 2)).T),
    lambda: g3.log(5.0),
])
def test_bad_shapes_are_value_errors(call):
    with pytest.raises(ValueError, match="ga_rs.g3"):
        call()


@pytest.mark.parametrize("call", [
    lambda: g3.reverse(np.zeros(4, np.complex128)),
    lambda: g3.reverse(np.array(["a", "b", "c", "d"])),
    lambda: g3.reverse(np.zeros(4, object)),
    lambda: g3.reverse(np.zeros(4), out=np.zeros(4, np.float32)),
    lambda: g3.reverse(np.zeros(4), out=[0.0] * 4),
    lambda: g3.exp(np.zeros(3, np.longdouble)) if np.longdouble != np.float64 else g3.exp(None),
])
def test_bad_dtypes_are_type_errors(call):
    with pytest.raises(TypeError):
        call()


def test_the_native_layer_validates_too():
    from ga_rs._native import g3 as native
    with pytest.raises(ValueError, match="broadcast"):
        native.sandwich_f64(np.zeros((2, 4)), np.zeros((3, 3)), np.zeros((3, 3)))
    with pytest.raises(ValueError, match="components"):
        native.sandwich_f64(np.zeros((1, 3)), np.zeros((3, 3)), np.zeros((3, 3)))
    with pytest.raises(ValueError, match="contiguous"):
        native.reverse_f64(np.zeros((4, 2)).T, np.zeros((2, 4)))
    with pytest.raises(TypeError):
        native.reverse_f64(np.zeros((1, 4), np.float32), np.zeros((1, 4)))


# --- the native fast path ---------------------------------------------------------

def _quick_cases(rng, dtype):
    """(name, arguments) of every function, in ndarrays of `dtype` that take the fast path."""
    r, q = unit_rotors(rng, 50, dtype), unit_rotors(rng, 50, dtype)
    v, w = rng.normal(size=(2, 50, 3)).astype(dtype)
    t = rng.uniform(size=50).astype(dtype)
    m = g3.to_matrix(r)
    return [
        ("geometric", (r, q)), ("geometric", (v, w)), ("geometric", (r[0], q)),
        ("sandwich", (r, v)), ("sandwich", (r[0], v)), ("sandwich", (r, v[0])),
        ("outer", (v, w)), ("inner", (v, w)), ("reverse", (r,)), ("normalize", (2 * r,)),
        ("exp", (v,)), ("log", (r,)), ("to_matrix", (r,)), ("from_matrix", (m,)),
        ("from_axis_angle", (v, t)), ("from_axis_angle", (v[0], t)), ("slerp", (r, q, t)),
        ("slerp", (r, q, 0.25)), ("sandwich", (r.reshape(5, 10, 4), v.reshape(5, 10, 3))),
        ("reverse", (r[0],)),
    ]


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_the_fast_path_equals_the_general_path_bit_for_bit(rng, dtype):
    from ga_rs._native import g3 as native
    for name, args in _quick_cases(rng, dtype):
        quick = getattr(native, name + "_quick")(*args, None)
        assert quick is not None, name  # the case does take the fast path
        # Strided views of the same values take the general path (it copies them).
        views = [np.repeat(a, 2, axis=-1)[..., ::2] if isinstance(a, np.ndarray) else a
                 for a in args]
        assert getattr(native, name + "_quick")(*views, None) is None, name
        general = getattr(g3, name)(*views)
        assert quick.dtype == general.dtype == dtype and quick.shape == general.shape, name
        assert (bits(quick) == bits(general)).all(), name
        out = np.full_like(quick, np.nan)
        assert getattr(g3, name)(*args, out=out) is out
        assert (bits(out) == bits(quick)).all(), name
    empty = native.geometric_quick(np.zeros((0, 4), dtype), np.zeros(4, dtype), None)
    assert empty.shape == (0, 4) and empty.dtype == dtype


def test_the_fast_path_leaves_every_other_case_to_the_general_path(rng):
    from ga_rs._native import g3 as native
    r, v = unit_rotors(rng, 6), rng.normal(size=(6, 3))
    out = np.empty((6, 3))
    read_only = np.empty((6, 3))
    read_only.flags.writeable = False
    others = [
        (r, [list(x) for x in v], None),                 # not an array
        (r.astype(np.float32), v, None),                 # mixed dtypes
        (r, v.astype(np.float32), out),                  # mixed dtypes
        (r, v.astype(">f8"), None),                      # byte-swapped
        (r.reshape(2, 1, 3, 4), v.reshape(2, 3, 3), None),  # broadcast needs numpy
        (r[:1], v, None),                                # (1,) against (6,): numpy's rule
        (np.asfortranarray(r), v, None),                  # not C-contiguous
        (r[::2], v[::2], None),                          # a strided view
        (r, v, v),                                       # out is an input
        (r, v, out.astype(np.float32)),                  # out of another dtype
        (r, v, np.empty((3, 6)).T),                      # out not C-contiguous
        (r, v, read_only),                               # out not writable
        (r, v, np.empty((6, 4))),                        # out of another shape
        (np.zeros((6, 3)), v, None),                     # rotors of 3 components
        (r, v.astype(np.int64), None),                   # integers
    ]
    for a, b, o in others:
        assert native.sandwich_quick(a, b, o) is None
    assert native.slerp_quick(r, r, np.float64(0.5), None) is None  # a numpy scalar
    assert native.slerp_quick(r, r, 1, None) is None                 # a Python int
    with pytest.raises(ValueError, match="writable"):
        g3.sandwich(r, v, out=read_only)
    np.testing.assert_allclose(g3.sandwich(r[::2], v[::2]), rotate(r[::2], v[::2]), atol=1e-14)
    np.testing.assert_allclose(g3.sandwich(r[:1], v), rotate(r[:1], v), atol=1e-14)


# --- copies -------------------------------------------------------------------------

def test_out_is_written_in_place_and_aliasing_is_safe(rng):
    r = unit_rotors(rng, 1000)
    v = rng.normal(size=(1000, 3))
    out = np.empty_like(v)
    assert g3.sandwich(r, v, out=out) is out
    expect = g3.sandwich(r, v)
    assert g3.sandwich(r, v, out=v) is v  # in place: the input is copied first
    assert (bits(v) == bits(expect)).all()


def test_a_million_item_call_allocates_about_one_output(rng):
    n = 1_000_000
    r = unit_rotors(rng, 1)[0]
    v = rng.normal(size=(n, 3))
    rs = unit_rotors(rng, n)
    out = np.empty_like(v)
    for call in [lambda: g3.sandwich(r, v), lambda: g3.sandwich(rs, v)]:
        tracemalloc.start()
        res = call()
        _, peak = tracemalloc.get_traced_memory()
        tracemalloc.stop()
        assert peak < 1.1 * res.nbytes, peak
    tracemalloc.start()
    g3.sandwich(rs, v, out=out)
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    assert peak < 0.01 * out.nbytes, peak


def test_objects_repr_and_equality():
    r = g3.Rotor(1.0, 0.0, 0.5, 0.0)
    assert repr(r) == "Rotor(1.0, 0.0, 0.5, 0.0)"
    assert r == g3.Rotor(1.0, 0.0, 0.5, 0.0)
    assert repr(g3.Vector(1, 2, 3)) == "Vector(1.0, 2.0, 3.0)"
    assert g3.Vector(1, 0, 0).inner(g3.Vector(2, 0, 0)) == 2.0
    with pytest.raises(TypeError):
        r * 2.0
    assert g3.Rotor.from_matrix(np.ones((3, 3)).tolist()) is None
