"""``ga_engine``'s rotation step on many bodies, in place, in float32 or float64.

Orientations are glam quaternions ``[x, y, z, w]`` (body to world), ``(n, 4)``; world
angular momenta ``(n, 3)``; world torques ``(n, 3)`` or ``(3,)``, held over the step.
``Bodies(tensors)`` diagonalises the inertia tensors ``(n, 3, 3)`` once (or one ``(3, 3)``
shared by all); its dtype is the precision of the steps. The result is, bit for bit,
``ga_engine::{f32, f64}::step`` (or ``step_order4``) on each body.
"""

import numpy as np

from ._native import engine as _native
Bodies = _native.Bodies

__all__ = ["Bodies", "step"]


def _state(name, x, k, dtype):
    if not isinstance(x, np.ndarray):
        raise TypeError(f"ga_rs.engine.step: {name} must be a numpy array (it is updated in place)")
    if x.dtype != dtype:
        raise TypeError(
            f"ga_rs.engine.step: {name} has dtype {x.dtype}, the bodies are {dtype}"
        )
    if x.ndim != 2 or x.shape[1] != k:
        raise ValueError(f"ga_rs.engine.step: {name} must have shape (n, {k}), got {x.shape}")
    if not (x.flags.c_contiguous and x.flags.writeable):
        raise ValueError(f"ga_rs.engine.step: {name} must be C-contiguous and writable")
    return x


def step(bodies, q, l, torque, dt, order=2):
    """Step every body once by ``dt``, updating ``q`` and ``l`` in place; ``order`` 2
    (``step``) or 4 (``step_order4``). Returns ``(q, l)``."""
    if not isinstance(bodies, Bodies):
        raise TypeError(f"ga_rs.engine.step: bodies must be a Bodies, got {type(bodies).__name__}")
    dtype = np.dtype(bodies.dtype)
    q = _state("q", q, 4, dtype)
    l = _state("l", l, 3, dtype)
    if q.shape[0] != l.shape[0]:
        raise ValueError(f"ga_rs.engine.step: q has {q.shape[0]} rows, l {l.shape[0]}")
    t = np.asarray(torque)
    if t.dtype.kind not in "fiu":
        raise TypeError(f"ga_rs.engine.step: torque has dtype {t.dtype}")
    if t.shape == (3,):
        t = t.reshape(1, 3)
    if t.ndim != 2 or t.shape[1] != 3 or t.shape[0] not in (1, q.shape[0]):
        raise ValueError(
            f"ga_rs.engine.step: torque must have shape ({q.shape[0]}, 3) or (3,), got {np.shape(torque)}"
        )
    t = np.ascontiguousarray(t, dtype)
    if np.may_share_memory(t, q) or np.may_share_memory(t, l):
        t = t.copy()
    if len(bodies) not in (1, q.shape[0]):
        raise ValueError(f"ga_rs.engine.step: {len(bodies)} bodies for {q.shape[0]} states")
    if order not in (2, 4):
        raise ValueError(f"ga_rs.engine.step: order must be 2 or 4, got {order!r}")
    _native.step(bodies, q, l, t, float(dt), int(order))
    return q, l
