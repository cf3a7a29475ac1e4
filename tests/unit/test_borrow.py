"""The step loop's views without reference counts (alightsize_sim.borrow)."""

import numpy as np
from numba import njit

from alightsize_sim.borrow import borrowed


@njit
def _write_through(packed):
    a, rest = borrowed(packed)
    flag, (b, scale) = rest
    a[0, 1] = 7.0                      # writes reach the caller's arrays: the views share their data
    b[2] = scale * a[1, 0]
    return a.shape[0] * 10 + b.shape[0], flag is None


def test_borrowed_views_share_the_arrays_of_a_nested_tuple():
    """Every array in a nested tuple (None and floats among them) becomes a view of the same data, shape and
    dtype: what is written through the views is in the caller's arrays, exactly."""
    a, b = np.arange(6.0).reshape(3, 2), np.zeros(4)
    shapes, none_kept = _write_through((a, (None, (b, 2.5))))
    assert shapes == 34 and none_kept
    assert a[0, 1] == 7.0 and b[2] == 2.5 * a[1, 0] == 5.0
