"""Named values passed between compiled functions as one pointer (a numba StructRef), for the step loop.

Numba passes every array of a call's arguments as its ~8 fields (data, shape, strides, ...); the step loop's
functions took ~35 arrays each. As one bundle a call passes one pointer: configuration 2's impact ran 23 %
faster and the 5 lb footpad scene 25 % (docs/notes/simulator-log.md); the first compile did not change
measurably (its time is in the functions' bodies). Bundles are built in compiled code: an entry point called
from Python receives plain arrays and bundles them (run as Python, with numba's JIT disabled, a bundle is a
SimpleNamespace).
"""

from __future__ import annotations

from types import SimpleNamespace

from numba import types
from numba.experimental import structref
from numba.extending import overload


@structref.register
class BundleType(types.StructRef):
    def preprocess_fields(self, fields):
        return tuple((name, types.unliteral(t)) for name, t in fields)


def bundler(fields: str):
    """A function for compiled code taking values in the order of `fields` (names separated by spaces) and
    returning one bundle with those names as attributes. Attributes are set in place, never rebound by the
    step loop; the bundle holds what it was given (views without reference counts stay so: borrow.py)."""
    names = fields.split()

    def bundle(*values):
        return SimpleNamespace(**dict(zip(names, values)))     # run as Python (NUMBA_DISABLE_JIT)

    bundle.fields = tuple(names)                               # for callers that pack the values by name

    @overload(bundle)
    def _bundle(*values):
        if len(values) != len(names):
            raise TypeError(f"bundle of {names} given {len(values)} values")
        ty = BundleType(list(zip(names, values)))
        sets = "".join(f"    b.{m} = values[{k}]\n" for k, m in enumerate(names))
        src = "def impl(*values):\n    b = new(ty)\n" + sets + "    return b\n"
        scope = {"new": structref.new, "ty": ty}
        exec(src, scope)
        return scope["impl"]

    return bundle
