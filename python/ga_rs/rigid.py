"""Rigid bodies: a scene run by any registry method, as ``ga-rigid simulate`` runs it.

A scene is a dict (the scene file's tables: ``{"body": {...}, "initial": {...},
"run": {...}}``, converted to TOML and parsed by ``Scene::parse``) or a path to a scene
file (``Scene::load``). Every error of the library is a ``ValueError`` whose message is
the line ``ga-rigid simulate`` prints (with its flag names, ``--dt``, ``--tol``...).
"""

import os

import numpy as np

from ._native import rigid as _native

__all__ = ["simulate", "exact_free_body", "inertia", "report", "methods"]

methods = _native.methods


def _scene(scene):
    if isinstance(scene, dict):
        return scene
    if isinstance(scene, (str, bytes, os.PathLike)):
        return os.fsdecode(os.fspath(scene))
    raise TypeError(
        f"ga_rs.rigid: scene must be a dict or a path (str or os.PathLike), "
        f"got {type(scene).__name__}"
    )


def _number(name, x, kind):
    if x is None:
        return None
    if isinstance(x, bool) or not isinstance(x, (int, float, np.integer, np.floating)):
        raise TypeError(f"ga_rs.rigid: {name} must be a number, got {type(x).__name__}")
    if kind is int:
        if isinstance(x, (float, np.floating)) and not float(x).is_integer():
            raise ValueError(f"ga_rs.rigid: {name} must be an integer, got {x!r}")
        return int(x)
    return float(x)


def simulate(scene, method, dt=None, tol=None, t_end=None, samples=None):
    """Run ``scene`` by ``method`` (a registry name, see ``methods()``) and return a dict of
    arrays: ``time (n,)``, ``rotor (n, 4)``, ``omega (n, 3)``, ``energy (n,)``,
    ``momentum (n, 3)``. ``dt`` (fixed-step methods) or ``tol`` (adaptive ones) as the
    command's ``--dt``/``--tol``, by default the scene's; ``t_end`` and ``samples`` replace
    the scene's ``[run]`` values. The checks are the command's: ``Method::given_step``,
    ``limits::plan`` with the default limits, then the run (GIL released)."""
    if not isinstance(method, str):
        raise TypeError(f"ga_rs.rigid.simulate: method must be a str, got {type(method).__name__}")
    return _native.simulate(
        _scene(scene), method, _number("dt", dt, float), _number("tol", tol, float),
        _number("t_end", t_end, float), _number("samples", samples, int),
    )


def _components(name, x, k):
    a = np.asarray(x, dtype=np.float64)
    if a.shape != (k,):
        raise ValueError(f"ga_rs.rigid.exact_free_body: {name} must have shape ({k},), got {a.shape}")
    return a.tolist()


def exact_free_body(moments, m0, r0, t):
    """The exact free-rigid-body flow at the times ``t`` (any shape): ``(rotor, m)`` with
    ``rotor`` of shape ``t.shape + (4,)`` and the body angular momentum ``m``
    ``t.shape + (3,)``. ``moments`` the principal moments, ``m0`` the body angular momentum
    at t = 0, ``r0`` the rotor at t = 0. NaN for invalid inputs."""
    t = np.asarray(t, dtype=np.float64)
    flat = np.ascontiguousarray(t).reshape(-1)
    rotor = np.empty((flat.size, 4))
    m = np.empty((flat.size, 3))
    _native.exact_free_body(
        _components("moments", moments, 3), _components("m0", m0, 3),
        _components("r0", r0, 4), flat, rotor, m,
    )
    return rotor.reshape(t.shape + (4,)), m.reshape(t.shape + (3,))


def inertia(scene):
    """The body's mass properties as ``ga-rigid inertia`` prints them: ``mass`` (None for a
    body given by its moments), ``centre``, ``moments`` and the principal ``rotor``."""
    return _native.inertia(_scene(scene))


def report(out_dir, quick=False):
    """Write the report (``ga-rigid report --out out_dir [--quick]``): runs every method on
    the suite's scenes; minutes for the full report. Where the command would exit with
    status 2 (``--out`` a file, its parent missing, a report file in it that cannot be
    replaced) this raises ``ValueError`` with the line the command prints, where it would
    exit with 1 (a failed write) ``OSError``; nothing is written then."""
    return _native.report(os.fsdecode(os.fspath(out_dir)), bool(quick))
