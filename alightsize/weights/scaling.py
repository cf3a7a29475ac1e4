"""Drop-test model scaling with acceleration scale 1 (AFFDL-TR-66-33 App. VI, Table 27).

Every quantity of dimension M^a L^b T^c scales by mass^a length^b time^c with time = sqrt(length),
so that accelerations are equal in model and full scale. Factors are full scale / model.
"""

from __future__ import annotations

from math import sqrt
from typing import Any

from alightsize.common import units

# Table 27 rows: name -> (mass, length, time) exponents
TABLE27 = {
    "acceleration": (0, 1, -2), "length": (0, 1, 0), "mass": (1, 0, 0), "angular_velocity": (0, 0, -1),
    "energy": (1, 2, -2), "force": (1, 1, -2), "mass_density": (1, -3, 0), "moment_of_inertia": (1, 2, 0),
    "pressure_stress": (1, -1, -2), "spring_rate": (1, 0, -2), "time": (0, 0, 1), "velocity": (0, 1, -1),
}


# Model-to-full-scale length and mass factors accepted: any drop test's model, with every Table 27 factor
# (exponents up to |4| in mass and length) finite in double precision.
SCHEMA = "alightsize.scale/1"             # the JSON `alightsize scale --json` writes (docs/contracts.md)
SCALE_RANGE = (1e-4, 1e4)


def factor(length: float, mass: float, exponents: tuple[int, int, int]) -> float:
    """Scale factor of a quantity with (mass, length, time) exponents; time scale sqrt(length) (Table 27)."""
    a, b, c = exponents
    return mass ** a * length ** b * sqrt(length) ** c


def table27(length: float, mass: float) -> dict[str, float]:
    """The twelve scaling factors of Table 27 for a length scale and a mass scale."""
    return {k: factor(length, mass, e) for k, e in TABLE27.items()}


def impact_energy_per_weight(v_vertical: float, v_horizontal: float, g: float = 9.80665) -> float:
    """E / W = (v_v^2 + v_h^2) / (2 g) (AFFDL-TR-66-33 Sec. II.C: 22.54 ft for 35 and 15 ft/s)."""
    return (v_vertical ** 2 + v_horizontal ** 2) / (2 * g)


def cushioning_weight_fraction(energy_per_weight: float, efficiency: float) -> float:
    """Absorber weight / capsule weight = (E/W) / (energy absorbed per unit weight of absorber) (Sec. II.C).

    `efficiency` is in J per newton of absorber weight (10,000 ft-lbf/lbf = 3048 m)."""
    return energy_per_weight / efficiency


def scale_tree(tree: Any, length: float, mass: float) -> Any:
    """Scale every quantity string in a config tree (geometry, masses, inertias, curves, velocities).

    Strings that parse as quantities are scaled by their dimension and written back in their own unit;
    angles, plain numbers and other strings are unchanged.
    """
    if isinstance(tree, dict):
        return {k: scale_tree(v, length, mass) for k, v in tree.items()}
    if isinstance(tree, list):
        return [scale_tree(v, length, mass) for v in tree]
    if isinstance(tree, str):
        return _scale_string(tree, length, mass)
    return tree


def _scale_string(text: str, length: float, mass: float) -> str:
    try:
        q: Any = units.registry().Quantity(text)     # pint's Quantity is untyped
    except Exception:
        return text
    if not hasattr(q, "units") or q.dimensionless or not str(q.units):
        return text
    dims = q.dimensionality
    if set(dims) - {"[mass]", "[length]", "[time]"}:
        return text
    f = factor(length, mass, units.dimension_of(q))
    return f"{q.magnitude * f:.6g} {q.units:~}".replace(" ** ", "^").replace("**", "^")
