"""ga-rs: geometric algebra G3, rigid-body simulation and an engine rotation step on numpy arrays.

Modules:

- ``ga_rs.g3``: rotors ``[s, e12, e13, e23]``, vectors ``[e1, e2, e3]`` and bivectors
  ``[e12, e13, e23]`` on the last axis of numpy arrays, broadcast like numpy, in float32 or
  float64; and ``Rotor``/``Vector``/``Bivector`` objects for one value at a time.
- ``ga_rs.rigid``: ``simulate`` a scene by any registry method (the checks and messages of
  ``ga-rigid simulate``), ``exact_free_body``, ``inertia``, ``report``.
- ``ga_rs.engine``: ``ga_engine``'s step on many bodies in place (glam ``[x, y, z, w]``
  quaternions).
"""

from . import engine, g3, rigid
from ._native import __version__

__all__ = ["g3", "rigid", "engine", "__version__"]
