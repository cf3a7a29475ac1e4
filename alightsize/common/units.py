"""Quantities with units: parsed once at the input boundary into SI floats, formatted for display."""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from functools import lru_cache

import pint


@lru_cache(maxsize=1)
def registry() -> pint.UnitRegistry:
    """The shared pint registry (lb is pound mass, lbf pound force, g_0 standard gravity)."""
    return pint.UnitRegistry()


@dataclass(frozen=True)
class Dim:
    """A physical dimension as exponents of mass, length and time."""

    name: str
    mass: int
    length: int
    time: int


DIMS = {d.name: d for d in (
    Dim("dimensionless", 0, 0, 0),
    Dim("length", 0, 1, 0),
    Dim("area", 0, 2, 0),
    Dim("second_moment", 0, 4, 0),
    Dim("mass", 1, 0, 0),
    Dim("force", 1, 1, -2),
    Dim("moment", 1, 2, -2),
    Dim("stress", 1, -1, -2),
    Dim("density", 1, -3, 0),
    Dim("velocity", 0, 1, -1),
    Dim("acceleration", 0, 1, -2),
    Dim("time", 0, 0, 1),
    Dim("inertia", 1, 2, 0),
    Dim("energy", 1, 2, -2),
    Dim("spring_rate", 1, 0, -2),
    Dim("angular_velocity", 0, 0, -1),
    Dim("damping", 1, 0, -1),
)}

# The magnitudes an input quantity may have, SI (zero is always allowed; sign rules are the key's own): wide
# enough for any landing gear from a model to a crewed lander, narrow enough that no formula under- or
# overflows a double (a 1e-311 m diameter, a 1e300 m leg). docs/reference/units.md lists them.
RANGES = {"length": (1e-6, 1e5, "m"), "area": (1e-12, 1e4, "m^2"), "second_moment": (1e-24, 1e2, "m^4"),
          "mass": (1e-6, 1e9, "kg"), "force": (1e-9, 1e12, "N"), "moment": (1e-9, 1e12, "N*m"),
          "stress": (1e-6, 1e13, "Pa"), "density": (1e-3, 1e5, "kg/m^3"), "velocity": (1e-12, 1e4, "m/s"),
          "acceleration": (1e-12, 1e5, "m/s^2"), "time": (1e-12, 1e6, "s"), "inertia": (1e-12, 1e12, "kg*m^2"),
          "energy": (1e-9, 1e12, "J"), "spring_rate": (1e-9, 1e13, "N/m"), "angular_velocity": (1e-12, 1e4, "rad/s"),
          "damping": (1e-12, 1e12, "N*s/m"), "dimensionless": (1e-300, 1e12, ""), "angle": (1e-300, 100.0, "rad")}

# What a user most likely meant when the dimension is wrong: (wanted, found) -> hint.
_HINTS = {("force", (1, 0, 0)): " (write lbf for pound-force; lb is pound-mass)",
          ("moment", (1, 1, 0)): " (write lbf*in for a moment; lb is pound-mass)"}


def dimension_of(q: pint.Quantity) -> tuple[int, int, int]:
    d = q.dimensionality
    return (int(d.get("[mass]", 0)), int(d.get("[length]", 0)), int(d.get("[time]", 0)))


def parse(text: str | float | int, dim: str) -> float:
    """Parse "3750 lbf" into SI for dimension `dim`; raise ValueError with a readable reason.

    Angles are given as "15 deg" or "0.26 rad" and returned in radians (dimension "angle").
    """
    if isinstance(text, bool):
        raise ValueError(f"a quantity in {example(dim)}")
    if isinstance(text, (int, float)):
        if dim == "dimensionless":
            return float(_in_range(text, dim))         # an integer too large for a float is out of range too
        raise ValueError(f"a number with a unit of {dim}, e.g. \"{example(dim)}\"")
    return _parse_text(str(text).strip(), dim)


# A quantity is a number and a unit; nothing is evaluated ("2**2000 in" and "9**9**9 in" are refused, not
# computed). A unit is names joined by *, / and small integer powers (^2, **-1, in^4).
_QUANTITY = re.compile(r"([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*)")
_UNIT = re.compile(r"(?=[A-Za-z_°µ(]|$)(?:[A-Za-z_°µ][A-Za-z_0-9°µ]*|[*/·() ]|\^ ?-?\d(?!\d)|\*\* ?-?\d(?!\d))*")


def _split(text: str) -> tuple[float, str]:
    """(number, unit text) of "3750 lbf"; ValueError when the text is not a number followed by a unit."""
    m = _QUANTITY.fullmatch(text)
    if m is None or not _UNIT.fullmatch(m.group(2)):
        raise ValueError("a number followed by a unit")
    value = float(m.group(1))
    if not math.isfinite(value):
        raise ValueError("a finite number")
    return value, m.group(2).replace("·", "*")


@lru_cache(maxsize=4096)
def _parse_text(text: str, dim: str) -> float:
    """`parse` of a text, memoized: a study reads the same quantities for every landing (pint is slow)."""
    ureg = registry()
    try:
        number, unit = _split(text)
        q = ureg.Quantity(number, unit)
    except Exception as exc:  # pint raises many kinds on garbage
        raise ValueError(f"a quantity like \"{example(dim)}\" (could not read it: {exc})") from None
    if dim == "angle":
        if not q.dimensionless:
            raise ValueError(f"an angle like \"{example(dim)}\"")
        return _in_range(float(q.to("rad").magnitude), dim)
    want = DIMS[dim]
    if dimension_of(q) != (want.mass, want.length, want.time):
        hint = _HINTS.get((dim, dimension_of(q)), "")
        article = "an" if dim[0] in "aeiou" else "a"
        raise ValueError(f"{article} {dim} like \"{example(dim)}\"{hint}")
    return _in_range(float(q.to_base_units().magnitude), dim)


def _in_range(value: float | int, dim: str) -> float | int:
    """`value` (SI) when zero or of a magnitude within RANGES[dim]; else ValueError saying the range."""
    low, high, unit = RANGES[dim]
    if value != 0 and not low <= abs(value) <= high:          # NaN fails the comparison too
        raise ValueError(f"a magnitude from {low:g} to {high:g} {unit} (or 0)".rstrip())
    return value


def in_unit_of(value_si: float, text: str, digits: int = 4) -> str:
    """An SI value written in the unit of the quantity `text` (same dimension), to `digits` significant
    figures: (2.0982e-7, "0.478 in^4") -> "0.5041 in^4"."""
    text = str(text).strip()
    q = registry().Quantity(text)
    unit = text.partition(" ")[2].strip() or f"{q.units:~}"
    return f"{value_si * q.magnitude / q.to_base_units().magnitude:.{digits}g} {unit}"


def example(dim: str) -> str:
    return {"length": "0.050 in", "area": "0.463 in^2", "second_moment": "0.478 in^4",
            "mass": "3000 lb", "force": "3750 lbf", "moment": "16150 lbf*in",
            "stress": "69000 psi", "density": "0.100 lb/in^3", "velocity": "35 ft/s",
            "acceleration": "20 g_0", "time": "0.5 s", "inertia": "3.326 slug*ft^2",
            "energy": "68000 ft*lbf", "spring_rate": "500 lbf/in", "angle": "15 deg",
            "angular_velocity": "3 rad/s", "damping": "300 lbf*s/ft", "dimensionless": "1.2"}[dim]


# Display units per dimension for the two unit systems a report may ask for.
DISPLAY = {
    "US": {"length": "in", "area": "in^2", "second_moment": "in^4", "mass": "lb", "force": "lbf",
           "moment": "lbf*in", "stress": "psi", "density": "lb/in^3", "velocity": "ft/s",
           "acceleration": "g_0", "time": "s", "inertia": "slug*ft^2", "energy": "ft*lbf",
           "spring_rate": "lbf/in", "angular_velocity": "rad/s", "damping": "lbf*s/ft", "dimensionless": ""},
    "SI": {"length": "mm", "area": "mm^2", "second_moment": "mm^4", "mass": "kg", "force": "N",
           "moment": "N*m", "stress": "MPa", "density": "kg/m^3", "velocity": "m/s",
           "acceleration": "m/s^2", "time": "s", "inertia": "kg*m^2", "energy": "J",
           "spring_rate": "N/mm", "angular_velocity": "rad/s", "damping": "N*s/m", "dimensionless": ""},
}

_LABEL = {"in^2": "in²", "in^4": "in⁴", "mm^2": "mm²", "mm^4": "mm⁴", "lbf*in": "lbf·in",
          "N*m": "N·m", "lb/in^3": "lb/in³", "kg/m^3": "kg/m³", "slug*ft^2": "slug·ft²",
          "kg*m^2": "kg·m²", "ft*lbf": "ft·lbf", "g_0": "g", "m/s^2": "m/s²"}


@lru_cache(maxsize=None)
def _si_per_display(system: str, dim: str) -> float:
    unit = DISPLAY[system][dim]
    if not unit:
        return 1.0
    return float(registry().Quantity(1.0, unit).to_base_units().magnitude)


def to_display(value_si: float, dim: str, system: str) -> float:
    """Convert an SI float to the display unit of `dim` in `system` ("US" or "SI")."""
    return value_si / _si_per_display(system, dim)


def unit_label(dim: str, system: str) -> str:
    unit = DISPLAY[system][dim]
    return _LABEL.get(unit, unit)


def fmt(value_si: float, dim: str, system: str, digits: int = 4) -> str:
    """Format an SI value in display units with `digits` significant figures and thousands separators."""
    v = to_display(value_si, dim, system)
    if v == 0 or not (abs(v) < float("inf")):
        text = "0" if v == 0 else "∞"
    else:
        from math import floor, log10
        decimals = max(0, digits - 1 - int(floor(log10(abs(v)))))
        text = f"{v:,.{decimals}f}"
    label = unit_label(dim, system)
    return f"{text} {label}".strip()
