"""ga_rs.engine: ga_engine's step on many bodies in place; the T-handle of the README
(|L| kept to the bit without torque), many bodies at once equal to each alone, the
dtype and shape rules."""

import numpy as np
import pytest

from conftest import bits
from ga_rs import engine


def test_t_handle_keeps_its_momentum_to_the_bit():
    # README's example: f32, 60 Hz, 600 steps, no torque.
    body = engine.Bodies(np.diag([1.0, 2.0, 3.0]).astype(np.float32))
    q = np.array([[0, 0, 0, 1]], np.float32)
    l = np.array([[0.01, 2.0, 0.0]], np.float32)
    for _ in range(600):
        engine.step(body, q, l, np.zeros(3), 1.0 / 60.0)
    assert (bits(l) == bits(np.array([[0.01, 2.0, 0.0]], np.float32))).all()
    assert abs(np.linalg.norm(q.astype(np.float64)) - 1) < 1e-6
    # the intermediate axis flips: the orientation has left the identity
    assert abs(q[0, 3]) < 0.99


def random_bodies(rng, n, dtype):
    a = rng.normal(size=(n, 3, 3))
    tensors = (a @ np.swapaxes(a, 1, 2) + np.eye(3)).astype(dtype)
    q = rng.normal(size=(n, 4))
    q /= np.linalg.norm(q, axis=-1, keepdims=True)
    return tensors, q.astype(dtype), rng.normal(size=(n, 3)).astype(dtype), \
        rng.normal(size=(n, 3)).astype(dtype)


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize("order", [2, 4])
def test_many_bodies_at_once_equal_each_alone(rng, dtype, order):
    tensors, q, l, torque = random_bodies(rng, 1000, dtype)
    bodies = engine.Bodies(tensors)
    assert bodies.dtype == np.dtype(dtype).name and len(bodies) == 1000
    qa, la = q.copy(), l.copy()
    for _ in range(5):
        engine.step(bodies, qa, la, torque, 0.01, order=order)
    for i in range(0, 1000, 37):
        one = engine.Bodies(tensors[i])
        qi, li = q[i:i + 1].copy(), l[i:i + 1].copy()
        for _ in range(5):
            engine.step(one, qi, li, torque[i], 0.01, order=order)
        assert (bits(qi) == bits(qa[i:i + 1])).all() and (bits(li) == bits(la[i:i + 1])).all()


def test_without_torque_every_momentum_is_kept_exactly(rng):
    tensors, q, l, _ = random_bodies(rng, 500, np.float64)
    l0 = l.copy()
    engine.step(engine.Bodies(tensors), q, l, np.zeros(3), 0.05)
    assert (bits(l) == bits(l0)).all()


def test_one_body_shape_for_many_states(rng):
    _, q, l, torque = random_bodies(rng, 100, np.float64)
    shared = engine.Bodies(np.diag([1.0, 2.0, 3.0]))
    many = engine.Bodies(np.broadcast_to(np.diag([1.0, 2.0, 3.0]), (100, 3, 3)).copy())
    q1, l1 = q.copy(), l.copy()
    engine.step(shared, q, l, torque, 0.1)
    engine.step(many, q1, l1, torque, 0.1)
    assert (bits(q) == bits(q1)).all() and (bits(l) == bits(l1)).all()


def test_bad_inputs(rng):
    tensors, q, l, torque = random_bodies(rng, 4, np.float64)
    bodies = engine.Bodies(tensors)
    with pytest.raises(TypeError, match="float64"):
        engine.step(bodies, q.astype(np.float32), l, torque, 0.1)
    with pytest.raises(TypeError, match="numpy array"):
        engine.step(bodies, q.tolist(), l, torque, 0.1)
    with pytest.raises(ValueError, match=r"\(n, 4\)"):
        engine.step(bodies, q[:, :3].copy(), l, torque, 0.1)
    with pytest.raises(ValueError, match="torque"):
        engine.step(bodies, q, l, np.zeros((2, 3)), 0.1)
    with pytest.raises(ValueError, match="bodies"):
        engine.step(bodies, q[:3].copy(), l[:3].copy(), torque[:3], 0.1)
    with pytest.raises(ValueError, match="order"):
        engine.step(bodies, q, l, torque, 0.1, order=3)
    with pytest.raises(ValueError, match="C-contiguous"):
        engine.step(bodies, np.asfortranarray(q), l, torque, 0.1)
    with pytest.raises(ValueError, match=r"tensors\[1\]: inertia"):
        engine.Bodies(np.array([np.eye(3), -np.eye(3)]))
    with pytest.raises(ValueError, match="shape"):
        engine.Bodies(np.zeros((2, 3)))
    with pytest.raises(TypeError, match="float32 or float64"):
        engine.Bodies(np.eye(3, dtype=np.int64))
