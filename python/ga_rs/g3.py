"""G3 on numpy arrays: components on the last axis, any leading shape, numpy broadcasting.

Canonical component order: rotor ``[s, e12, e13, e23]``, vector ``[e1, e2, e3]``, bivector
``[e12, e13, e23]``. The dtype is numpy's ``result_type`` of the inputs (Python scalars
weak): float32 stays float32 and is computed in float32, float64 in float64, integers
become float64; anything else is a ``TypeError``. Each function takes ``out=``, a
C-contiguous writable array of the result's shape and dtype, written in place and
returned. Calls of 4096 items or more release the GIL.

Each function first tries the native fast path (``*_quick``): C-contiguous float64 or
float32 arrays of one dtype (a Python float where a scalar goes), leading shapes equal or
a single item, ``out`` absent or fitting without overlap. It returns ``None`` for anything
else, and the general path below converts, broadcasts, copies or raises.

A rotor per vector (``sandwich(R, V)`` with ``R.shape[:-1] == V.shape[:-1]``) and the
rotor product give exactly what the per-item objects (``Rotor(...).sandwich(Vector(...))``,
``Rotor * Rotor``) give. One rotor on many vectors runs ga-core's matrix kernel
(``kernels::sandwich_all``), which on CPUs with FMA may differ in the last bit.
"""

import math

import numpy as np

from ._native import g3 as _native
Rotor, Vector, Bivector = _native.Rotor, _native.Vector, _native.Bivector

__all__ = [
    "geometric", "sandwich", "reverse", "exp", "log", "normalize", "from_axis_angle",
    "to_matrix", "from_matrix", "slerp", "outer", "inner", "Rotor", "Vector", "Bivector",
    "instruction_set",
]

instruction_set = _native.instruction_set

_ROTOR, _VECTOR, _BIVECTOR, _MATRIX = 4, 3, 3, (3, 3)


def _dtype(name, values):
    """The computing dtype of a call: float32 or float64."""
    try:
        dt = np.result_type(*values)
    except TypeError as e:
        raise TypeError(f"ga_rs.g3.{name}: {e}") from None
    if dt.kind in "iub":
        return np.dtype(np.float64)
    if dt.kind == "f" and dt.itemsize <= 4:
        return np.dtype(np.float32)
    if dt == np.float64:
        return dt
    raise TypeError(
        f"ga_rs.g3.{name}: dtype {dt} is not supported; give float32 or float64 arrays"
    )


def _array(name, arg, x, comps, what):
    """`x` as an array whose trailing axes are `comps` (a tuple, () for scalars)."""
    if isinstance(x, (Rotor, Vector, Bivector)):
        x = x.to_array()
    try:
        a = np.asarray(x)
    except (ValueError, TypeError) as e:
        raise ValueError(f"ga_rs.g3.{name}: {arg} is not an array: {e}") from None
    if a.dtype.kind not in "fiub":
        raise TypeError(
            f"ga_rs.g3.{name}: {arg} has dtype {a.dtype}; give float32 or float64 arrays"
        )
    if comps and a.shape[a.ndim - len(comps):] != comps:
        want = ", ".join(map(str, comps))
        raise ValueError(
            f"ga_rs.g3.{name}: {arg} must be {what} with ({want}) on its last "
            f"axis{'es' if len(comps) > 1 else ''}, got shape {a.shape}"
        )
    return a


def _call(name, kernel, inputs, out_comps, out):
    """Broadcast `inputs` ((arg, value, comps, what) tuples), run `kernel` on flat views."""
    arrays = [_array(name, arg, x, comps, what) for arg, x, comps, what in inputs]
    weak = [x if type(x) in (float, int) else a for (_, x, _, _), a in zip(inputs, arrays)]
    dtype = _dtype(name, weak)
    leads = [a.shape[: a.ndim - len(c)] for a, (_, _, c, _) in zip(arrays, inputs)]
    try:
        lead = np.broadcast_shapes(*leads)
    except ValueError:
        shapes = " and ".join(str(a.shape) for a in arrays)
        raise ValueError(
            f"ga_rs.g3.{name}: shapes {shapes} do not broadcast (leading axes "
            f"{' and '.join(map(str, leads))})"
        ) from None
    n = math.prod(lead)
    shape = lead + out_comps
    if out is None:
        out = np.empty(shape, dtype)
    else:
        if not isinstance(out, np.ndarray):
            raise TypeError(f"ga_rs.g3.{name}: out must be a numpy array, got {type(out).__name__}")
        if out.dtype != dtype:
            raise TypeError(f"ga_rs.g3.{name}: out has dtype {out.dtype}, the result is {dtype}")
        if out.shape != shape:
            raise ValueError(f"ga_rs.g3.{name}: out has shape {out.shape}, the result is {shape}")
        if not (out.flags.c_contiguous and out.flags.writeable):
            raise ValueError(f"ga_rs.g3.{name}: out must be C-contiguous and writable")
    flats = []
    for a, lead_a, (_, _, comps, _) in zip(arrays, leads, inputs):
        size = math.prod(comps)
        if lead_a != lead and math.prod(lead_a) != 1:
            a = np.broadcast_to(a, lead + comps)  # the one copy: below
        flat = np.ascontiguousarray(a, dtype).reshape(-1, size) if comps else \
            np.ascontiguousarray(a, dtype).reshape(-1)
        if np.may_share_memory(flat, out):
            flat = flat.copy()
        flats.append(flat)
    out_size = math.prod(out_comps)
    out_flat = out.reshape(n, out_size) if out_comps else out.reshape(n)
    suffix = "_f32" if dtype == np.float32 else "_f64"
    getattr(_native, kernel + suffix)(*flats, out_flat)
    return out


def geometric(a, b, out=None):
    """The geometric product: rotor * rotor -> rotor, or vector * vector -> rotor (a.b + a^b)."""
    result = _native.geometric_quick(a, b, out)
    if result is not None:
        return result
    ka = np.shape(a.to_array() if hasattr(a, "to_array") else a)[-1:]
    kb = np.shape(b.to_array() if hasattr(b, "to_array") else b)[-1:]
    if ka == (4,) and kb == (4,):
        return _call("geometric", "mul_rotors",
                     [("a", a, (4,), "rotors"), ("b", b, (4,), "rotors")], (4,), out)
    if ka == (3,) and kb == (3,):
        return _call("geometric", "mul_vectors",
                     [("a", a, (3,), "vectors"), ("b", b, (3,), "vectors")], (4,), out)
    raise ValueError(
        "ga_rs.g3.geometric: give rotors (4 components) times rotors or vectors (3) times "
        f"vectors, got last axes {ka or '()'} and {kb or '()'}"
    )


def sandwich(rotor, vector, out=None):
    """``R v ~R``: each rotor applied to its vector (broadcast: one rotor on many vectors)."""
    result = _native.sandwich_quick(rotor, vector, out)
    if result is not None:
        return result
    return _call("sandwich", "sandwich",
                 [("rotor", rotor, (4,), "rotors"), ("vector", vector, (3,), "vectors")],
                 (3,), out)


def reverse(rotor, out=None):
    """``~R``: the rotor with its bivector part negated."""
    result = _native.reverse_quick(rotor, out)
    if result is not None:
        return result
    return _call("reverse", "reverse", [("rotor", rotor, (4,), "rotors")], (4,), out)


def normalize(rotor, out=None):
    """``R / |R|``."""
    result = _native.normalize_quick(rotor, out)
    if result is not None:
        return result
    return _call("normalize", "normalize", [("rotor", rotor, (4,), "rotors")], (4,), out)


def exp(bivector, out=None):
    """``exp(B)``: a bivector's rotor (``exp(-I axis angle / 2)`` turns by ``angle``)."""
    result = _native.exp_quick(bivector, out)
    if result is not None:
        return result
    return _call("exp", "exp", [("bivector", bivector, (3,), "bivectors")], (4,), out)


def log(rotor, out=None):
    """The bivector ``B`` with ``exp(B) = R``; NaN where ``R`` is not unit (within 1.5e-8)."""
    result = _native.log_quick(rotor, out)
    if result is not None:
        return result
    return _call("log", "log", [("rotor", rotor, (4,), "rotors")], (3,), out)


def from_axis_angle(axis, angle, out=None):
    """The rotor turning by ``angle`` (radians) about the unit ``axis``."""
    result = _native.from_axis_angle_quick(axis, angle, out)
    if result is not None:
        return result
    return _call("from_axis_angle", "from_axis_angle",
                 [("axis", axis, (3,), "vectors"), ("angle", angle, (), "angles")], (4,), out)


def to_matrix(rotor, out=None):
    """The rotation matrices ``(..., 3, 3)``: ``M @ v`` is ``R v ~R`` (R unit)."""
    result = _native.to_matrix_quick(rotor, out)
    if result is not None:
        return result
    return _call("to_matrix", "to_matrix", [("rotor", rotor, (4,), "rotors")], (3, 3), out)


def from_matrix(matrix, out=None):
    """The unit rotors (scalar part >= 0) of rotation matrices; NaN where one is not a rotation."""
    result = _native.from_matrix_quick(matrix, out)
    if result is not None:
        return result
    return _call("from_matrix", "from_matrix",
                 [("matrix", matrix, (3, 3), "matrices")], (4,), out)


def slerp(a, b, t, out=None):
    """Spherical interpolation from ``a`` (t = 0) to ``b`` (t = 1) along the shorter arc."""
    result = _native.slerp_quick(a, b, t, out)
    if result is not None:
        return result
    return _call("slerp", "slerp",
                 [("a", a, (4,), "rotors"), ("b", b, (4,), "rotors"), ("t", t, (), "times")],
                 (4,), out)


def outer(a, b, out=None):
    """``a ^ b`` for vectors: a bivector ``[e12, e13, e23]``."""
    result = _native.outer_quick(a, b, out)
    if result is not None:
        return result
    return _call("outer", "outer", [("a", a, (3,), "vectors"), ("b", b, (3,), "vectors")],
                 (3,), out)


def inner(a, b, out=None):
    """``a . b`` for vectors: the scalar product, leading shape only."""
    result = _native.inner_quick(a, b, out)
    if result is not None:
        return result
    return _call("inner", "inner", [("a", a, (3,), "vectors"), ("b", b, (3,), "vectors")],
                 (), out)
