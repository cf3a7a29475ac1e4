"""Monte Carlo dispersions of scene values: normal, uniform and truncated normal, in the unit the user wrote.

A dispersion is read from a study's `[dispersions]` table, e.g.
`"terrain.slope" = { dist = "normal", mean = "10 deg", sd = "1 deg" }`; `per_cell = true` on
`legs.cell_factors` draws one factor per cell of every leg (the per-cell scatter of Sec. VI.C). Sample k of a
study draws from `numpy.random.default_rng([seed, k])` in the declared order, so a run depends only on
(seed, k), never on the order or place it executes.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Literal

import numpy as np
from pydantic import RootModel
from scipy.special import ndtr, ndtri

from alightsize.common.config import Node, key_name
from alightsize.common.typed import Table, Tagged
from alightsize.common.units import registry

DISTRIBUTIONS = {"normal": ("mean", "sd"), "uniform": ("low", "high"),
                 "truncated_normal": ("mean", "sd", "low", "high")}


@dataclass(frozen=True)
class Dispersion:
    key: str                    # scene key path
    dist: str
    params: tuple[float, ...]   # in `unit`
    unit: str                   # "" for plain numbers
    per_cell: bool

    def draw(self, rng: np.random.Generator, shape: tuple[int, ...] = ()) -> np.ndarray:
        """Draws in `unit`; a truncated normal by inverting its CDF (exact, one uniform per draw)."""
        if self.dist == "normal":
            return rng.normal(self.params[0], self.params[1], shape)
        if self.dist == "uniform":
            return rng.uniform(self.params[0], self.params[1], shape)
        mean, sd, low, high = self.params
        a, b = ndtr((low - mean) / sd), ndtr((high - mean) / sd)
        return np.clip(mean + sd * ndtri(a + (b - a) * rng.uniform(0.0, 1.0, shape)), low, high)

    def value(self, rng: np.random.Generator, cells: tuple[int, int] | None = None):
        """One sample as a scene value: "x unit" (x a float), a number, or per-cell nested lists."""
        return self._scene_value(self.draw(rng, cells if self.per_cell else ()))

    def centre(self, cells: tuple[int, int] | None = None):
        """The distribution's centre (the mean, or the middle of a uniform range) as a scene value."""
        mid = (self.params[0] + self.params[1]) / 2 if self.dist == "uniform" else self.params[0]
        return self._scene_value(np.full(cells if self.per_cell else (), mid))

    def _scene_value(self, x: np.ndarray):
        if self.per_cell:
            return [[float(v) for v in row] for row in x]
        return f"{float(x)!r} {self.unit}" if self.unit else float(x)


class _Spread(Table):
    per_cell: bool = False
    note: str = ""


class Normal(_Spread):
    dist: Literal["normal"]
    mean: Any                   # a number or a quantity, each parameter in the first's unit (`_magnitudes`)
    sd: Any


class Uniform(_Spread):
    dist: Literal["uniform"]
    low: Any
    high: Any


class TruncatedNormal(_Spread):
    dist: Literal["truncated_normal"]
    mean: Any
    sd: Any
    low: Any
    high: Any


class DispersionTable(RootModel):
    """A `[dispersions]` entry: the table of its `dist`."""

    root: Tagged("dist", None, Normal, Uniform, TruncatedNormal)  # type: ignore[valid-type]


def _magnitude(spec: Node, key: str, value, unit: str | None) -> tuple[float, str]:
    """A distribution parameter as (magnitude, unit); later parameters are converted to the first's unit."""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        if unit:
            raise spec.error(key, f"a quantity in {unit} like the first parameter", repr(value))
        try:
            mag = float(value)
        except OverflowError:                          # an integer beyond any float
            mag = float("inf")
        if not np.isfinite(mag):
            raise spec.error(key, "a finite value", repr(value))
        return mag, ""
    try:
        q = registry().Quantity(str(value))
        q = q.to(unit) if unit else q
    except Exception:                                  # noqa: BLE001 - pint raises many kinds
        raise spec.error(key, "a number or a quantity with a unit" + (f" convertible to {unit}" if unit else ""),
                         repr(value)) from None
    mag = float(q.magnitude)
    if not np.isfinite(mag):
        raise spec.error(key, "a finite value", repr(value))
    return mag, unit if unit is not None else ("" if str(q.units) == "dimensionless" else str(q.units))


def dispersion(file: str, key: str, table: DispersionTable) -> Dispersion:
    """The `[dispersions]` entry `key` (read as a DispersionTable), its parameters in the first one's unit; errors
    name the key path."""
    d = table.root
    spec = Node(file, "dispersions." + key_name(key), {})
    unit, values = None, []
    for name in DISTRIBUTIONS[d.dist]:
        mag, unit = _magnitude(spec, name, getattr(d, name), unit)
        values.append(mag)
    if d.dist != "uniform" and values[1] <= 0:
        raise spec.error("sd", "a positive standard deviation", repr(d.sd))
    lo_hi = values[-2:] if d.dist != "normal" else None
    if lo_hi and not lo_hi[0] < lo_hi[1]:
        raise spec.error("high", f"a bound above low ({lo_hi[0]:g})", f"{lo_hi[1]:g}")
    if d.per_cell and (key != "legs.cell_factors" or unit):
        raise spec.error("per_cell", "per_cell only on legs.cell_factors with plain-number factors", "true")
    return Dispersion(key, d.dist, tuple(values), unit or "", d.per_cell)
