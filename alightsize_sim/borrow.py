"""Views of the caller's arrays without reference counts, for the step loop.

Numba counts the references to every array a compiled function receives or slices, with an atomic add on the
array's memory record. In the step loop a right-hand side passes the scene's ~30 arrays through several calls per
leg, and these counts took a sixth of a footpad landing's time (sampled with perf). `borrowed` gives views whose
memory record is NULL, which numba's counting skips. A view is valid while the array it views is alive: the step
loop borrows only arrays its caller holds for the whole call, and never returns or stores a view.
"""

from __future__ import annotations

from numba import config, types
from numba.extending import intrinsic
from numba.np.arrayobj import make_array, populate_array


def _strip(context, builder, ty, val):
    """val of type ty with every array in it (through nested plain tuples) a view without a memory record."""
    if isinstance(ty, types.Array):
        src = make_array(ty)(context, builder, value=val)
        out = make_array(ty)(context, builder)
        populate_array(out, data=src.data, shape=src.shape, strides=src.strides, itemsize=src.itemsize,
                       meminfo=None)
        return out._getvalue()
    if isinstance(ty, types.BaseTuple) and not isinstance(ty, types.BaseNamedTuple):
        items = [_strip(context, builder, t, builder.extract_value(val, k)) for k, t in enumerate(ty)]
        return context.make_tuple(builder, ty, items)
    context.nrt.incref(builder, ty, val)            # passed on as a new reference, like the views
    return val


@intrinsic
def _borrowed(typingctx, x):
    """x with every array in it (through nested tuples) a view without reference counts; anything else as it is.
    One intrinsic, lowered in place: no function is compiled per element. Compiled code only."""
    def codegen(context, builder, sig, args):
        return _strip(context, builder, sig.args[0], args[0])

    return x(x), codegen


def _as_is(x):
    return x


# `borrowed(x)`; run as Python (NUMBA_DISABLE_JIT) there is nothing to borrow: x itself.
borrowed = _as_is if config.DISABLE_JIT else _borrowed
