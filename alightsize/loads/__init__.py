"""Member loads: the quasi-static envelopes of App. III, the telescoping free body, landing load histories.

`alightsize.loads` is also the API function `alightsize.loads(config, ...)`. Importing this package binds the
package over that name on `alightsize`, so the package is callable and a call runs the function."""

import sys
import types


class _CallablePackage(types.ModuleType):
    def __call__(self, *args, **kwargs):
        from alightsize import run_loads_envelopes
        return run_loads_envelopes(*args, **kwargs)


sys.modules[__name__].__class__ = _CallablePackage
