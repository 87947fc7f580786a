import numpy as np
import pytest


@pytest.fixture
def rng():
    return np.random.default_rng(20261127)


def bits(a):
    """The bit patterns of a float array, so that equality means bit-for-bit."""
    a = np.ascontiguousarray(a)
    return a.view(np.uint64 if a.dtype == np.float64 else np.uint32)
