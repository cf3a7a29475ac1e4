"""alightsize simulator: leg kinematics, crush cells, footpad slip and landing dynamics. Never imports
alightsize.

numba caches the compiled kernels in a user cache folder, never in the package (alightsize_sim.cache); a
NUMBA_CACHE_DIR set by the user wins. Importing the package writes nothing.

The leg dispatch is inlined at numba's IR level (legs.py); numba's SSA pass then flags variables assigned in
branches of the inlined bodies as "not in scope", an internal pedantic check (numba's own wording) that this
package silences so a first run does not print it.
"""

import warnings
from importlib.metadata import PackageNotFoundError, version

from numba.core.errors import NumbaIRAssumptionWarning

from alightsize_sim.cache import register

__all__ = ["__version__"]

try:
    __version__ = version("alightsize")
except PackageNotFoundError:                           # run from a source tree without installing
    __version__ = "0+unknown"

warnings.filterwarnings("ignore", message=r"variable '.*' is not in scope", category=NumbaIRAssumptionWarning)
register(__file__)
