"""alightsize simulator: leg kinematics, crush cells, footpad slip and landing dynamics. Never imports
alightsize.

Numba's on-disk cache keys a compiled function on its own file only, so editing a function in one module
would leave stale machine code in the cache of every caller in another. The cache therefore lives in a
directory named by a digest of all the simulator's sources (unless NUMBA_CACHE_DIR is set).

The leg dispatch is inlined at numba's IR level (legs.py); numba's SSA pass then flags variables assigned in
branches of the inlined bodies as "not in scope", an internal pedantic check (numba's own wording) that this
package silences so a first run does not print it.
"""

import hashlib
import os
import shutil
import warnings
from pathlib import Path

from numba.core import config as _numba_config
from numba.core.errors import NumbaIRAssumptionWarning

warnings.filterwarnings("ignore", message=r"variable '.*' is not in scope", category=NumbaIRAssumptionWarning)

_HERE = Path(__file__).resolve().parent
if not os.environ.get("NUMBA_CACHE_DIR"):
    _digest = hashlib.sha256(b"".join(p.read_bytes() for p in sorted(_HERE.glob("*.py")))).hexdigest()[:16]
    _root = _HERE / "__pycache__" / "numba"
    try:
        (_root / _digest).mkdir(parents=True, exist_ok=True)
    except OSError:                                    # read-only install: numba's default locations
        pass
    else:
        _numba_config.CACHE_DIR = str(_root / _digest)
        for _old in _root.iterdir():                   # caches of earlier sources
            if _old.name != _digest:
                shutil.rmtree(_old, ignore_errors=True)
