"""Footpad-soil model: a rigid flat pad sinking into soil, and the soil it plows when it slides while sunk.

Normal resistance is Bekker's pressure-sinkage relation p = (k_c/b + k_phi) z^n (Bekker 1969; Wong, Theory of
Ground Vehicles, Ch. 2), b the least width of the pad. A soil of constant bearing pressure p0 ("rigid-plastic")
is the case n = 0, k_c = 0, k_phi = p0 (`Soil.rigid_plastic`). Plowing is the Rankine passive earth pressure
on a vertical blade of width b sunk to z, which is Bekker's bulldozing resistance.

The numeric kernels are numba-compiled and take the soil packed as floats (`Soil.packed`, an array or a tuple;
indices N, KC, KPHI, C, PHI, GAMMA below) so compiled code can call them. Soil files and the shipped presets
(materials/soils/) are read by alightsize.model.soils.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numba import njit

N, KC, KPHI, C, PHI, GAMMA = range(6)   # positions in Soil.packed



@dataclass(frozen=True)
class Soil:
    """Bekker and Mohr-Coulomb parameters, SI: n (-), k_c (N/m^(n+1)), k_phi (N/m^(n+2)), cohesion c (Pa),
    friction angle phi (rad), unit weight gamma (N/m^3, for the gravity where the soil lies)."""

    n: float
    k_c: float
    k_phi: float
    c: float = 0.0
    phi: float = 0.0
    gamma: float = 0.0
    name: str = ""
    source: dict = field(default_factory=dict, compare=False)

    def __post_init__(self):
        if not (self.n >= 0 and self.k_c >= 0 and self.k_phi >= 0 and self.k_c + self.k_phi > 0):
            raise ValueError("a soil needs n >= 0, k_c >= 0, k_phi >= 0 and k_c + k_phi > 0")
        if not (self.c >= 0 and 0 <= self.phi < math.pi / 2 and self.gamma >= 0):
            raise ValueError("a soil needs c >= 0, 0 <= phi < pi/2 rad and gamma >= 0")

    @classmethod
    def rigid_plastic(cls, p0: float, c: float = 0.0, phi: float = 0.0, gamma: float = 0.0, name: str = "") -> Soil:
        """A soil whose bearing pressure is p0 at every sinkage, whatever the pad's size (n = 0, k_c = 0)."""
        return cls(0.0, 0.0, p0, c, phi, gamma, name)

    @property
    def packed(self) -> np.ndarray:
        """The parameters as the kernels take them: [n, k_c, k_phi, c, phi, gamma]."""
        return np.array([self.n, self.k_c, self.k_phi, self.c, self.phi, self.gamma], dtype=np.float64)


@njit(cache=True)
def sinkage_modulus(soil: np.ndarray, b: float) -> float:
    """k_c/b + k_phi: the pressure at unit sinkage under a pad of least width b (N/m^(n+2))."""
    return soil[KC] / b + soil[KPHI]


@njit(cache=True)
def pressure(soil: np.ndarray, b: float, z: float) -> float:
    """Pressure under a flat pad of least width b at sinkage z (Pa); none above the surface, and at it the limit
    from within (p0 for a constant bearing pressure, n = 0; zero for n > 0)."""
    if z < 0.0:
        return 0.0
    return sinkage_modulus(soil, b) * z ** soil[N]   # Bekker 1969; Wong, Theory of Ground Vehicles, Ch. 2


@njit(cache=True)
def normal_force(soil: np.ndarray, area: float, b: float, z: float) -> float:
    """Normal resistance of a flat pad of the given area and least width b at sinkage z (N)."""
    return area * pressure(soil, b, z)


@njit(cache=True)
def sinkage_work(soil: np.ndarray, area: float, b: float, z: float) -> float:
    """Work to push the pad from the surface to sinkage z (J): A (k_c/b + k_phi) z^(n+1) / (n+1)."""
    if z <= 0.0:
        return 0.0
    n = soil[N]
    return area * sinkage_modulus(soil, b) * z ** (n + 1.0) / (n + 1.0)   # integral of normal_force over z


@njit(cache=True)
def sinkage_depth(soil: np.ndarray, area: float, b: float, energy: float) -> float:
    """Sinkage at which the work equals `energy` (m): the inverse of sinkage_work."""
    if energy <= 0.0:
        return 0.0
    n = soil[N]
    return ((n + 1.0) * energy / (area * sinkage_modulus(soil, b))) ** (1.0 / (n + 1.0))


@njit(cache=True)
def flow_value(phi: float) -> float:
    """N_phi = tan^2(45 deg + phi/2), the Rankine passive coefficient."""
    return math.tan(0.25 * math.pi + 0.5 * phi) ** 2   # Rankine 1857; Bekker 1956 bulldozing (flow value)


@njit(cache=True)
def plowing_force(soil: np.ndarray, b: float, z: float) -> float:
    """Resistance to a vertical blade of width b sunk to z pushed sideways (N): b (gamma z^2 N_phi / 2 +
    2 c z sqrt(N_phi)), the resultant of the Rankine passive pressure over the blade's depth."""
    if z <= 0.0:
        return 0.0
    n_phi = flow_value(soil[PHI])
    return b * (0.5 * soil[GAMMA] * z * z * n_phi + 2.0 * soil[C] * z * math.sqrt(n_phi))   # Bekker 1956
