"""3-vector helpers on scalar tuples for the compiled loop (no small-array allocation, no BLAS call)."""

from numba import njit


@njit(cache=True)
def mv(M, x0, x1, x2):
    """M x."""
    return (M[0, 0] * x0 + M[0, 1] * x1 + M[0, 2] * x2, M[1, 0] * x0 + M[1, 1] * x1 + M[1, 2] * x2,
            M[2, 0] * x0 + M[2, 1] * x1 + M[2, 2] * x2)


@njit(cache=True)
def mtv(M, x0, x1, x2):
    """M^T x."""
    return (M[0, 0] * x0 + M[1, 0] * x1 + M[2, 0] * x2, M[0, 1] * x0 + M[1, 1] * x1 + M[2, 1] * x2,
            M[0, 2] * x0 + M[1, 2] * x1 + M[2, 2] * x2)


@njit(cache=True)
def cross(a0, a1, a2, b0, b1, b2):
    """a x b."""
    return a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0
