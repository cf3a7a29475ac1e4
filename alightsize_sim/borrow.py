"""Views of the caller's arrays without reference counts, for the step loop.

Numba counts the references to every array a compiled function receives or slices, with an atomic add on the
array's memory record. In the step loop a right-hand side passes the scene's ~30 arrays through several calls per
leg, and these counts took most of a landing's time (sampled with perf). `borrowed` gives views whose memory
record is NULL, which numba's counting skips. A view is valid while the array it views is alive: the step loop
borrows only arrays its caller holds for the whole call, and never returns or stores a view.
"""

from __future__ import annotations

from numba import types
from numba.extending import intrinsic, overload
from numba.np.arrayobj import make_array, populate_array


@intrinsic
def _view(typingctx, arr):
    """The array arr without its memory record (same data, shape and strides)."""
    if not isinstance(arr, types.Array):
        return None

    def codegen(context, builder, sig, args):
        src = make_array(arr)(context, builder, value=args[0])
        out = make_array(arr)(context, builder)
        populate_array(out, data=src.data, shape=src.shape, strides=src.strides, itemsize=src.itemsize,
                       meminfo=None)
        return out._getvalue()

    return arr(arr), codegen


def borrowed(x):
    """x with every array in it (through nested tuples) replaced by a view without reference counts; anything
    else as it is. Compiled code only."""
    return x


@overload(borrowed)
def _borrowed(x):
    if isinstance(x, types.Array):
        return lambda x: _view(x)
    if isinstance(x, types.BaseTuple) and not isinstance(x, types.BaseNamedTuple) and len(x) > 0:
        items = ", ".join(f"borrowed(x[{k}])" for k in range(len(x)))
        scope = {"borrowed": borrowed}
        exec(f"def impl(x):\n    return ({items},)\n", scope)
        return scope["impl"]
    return lambda x: x
