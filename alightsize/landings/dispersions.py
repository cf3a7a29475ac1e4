"""Monte Carlo dispersions of scene values: normal, uniform and truncated normal, in the unit the user wrote.

A dispersion is read from a study's `[dispersions]` table, e.g.
`"terrain.slope" = { dist = "normal", mean = "10 deg", sd = "1 deg" }`; `per_cell = true` on
`legs.cell_factors` draws one factor per cell of every leg (the per-cell scatter of Sec. VI.C). Sample k of a
study draws from `numpy.random.default_rng([seed, k])` in the declared order, so a run depends only on
(seed, k), never on the order or place it executes.
"""

from __future__ import annotations

from dataclasses import dataclass
from math import sqrt
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

    def draws(self, rng: np.random.Generator, cells: tuple[int, int] | None = None) -> dict:
        """One sample as {key: scene value}."""
        return {self.key: self.value(rng, cells)}

    def centre(self, cells: tuple[int, int] | None = None):
        """The distribution's centre (the mean, or the middle of a uniform range) as a scene value."""
        mid = (self.params[0] + self.params[1]) / 2 if self.dist == "uniform" else self.params[0]
        return self._scene_value(np.full(cells if self.per_cell else (), mid))

    def _scene_value(self, x: np.ndarray):
        if self.per_cell:
            return [[float(v) for v in row] for row in x]
        return f"{float(x)!r} {self.unit}" if self.unit else float(x)


@dataclass(frozen=True)
class SpeedRegion:
    """Descent and horizontal speeds drawn jointly and uniformly over the region between the descent speed `low`
    and the piecewise-linear largest descent speed `upper` ((horizontal, descent) points, m/s, horizontal
    ascending, each descent >= low), by inverting the horizontal speed's marginal CDF (density proportional to
    upper - low; exact for a piecewise-linear edge) and drawing the descent uniformly below the edge there. It
    takes two uniforms, descent's first: over a box (a flat `upper`) it draws exactly what uniform dispersions of
    the descent (negative, `descent_key`) and horizontal speeds in that order draw."""

    descent_key: str
    horizontal_key: str
    upper: tuple[tuple[float, float], ...]
    low: float
    per_cell: bool = False

    def draws(self, rng: np.random.Generator, cells: tuple[int, int] | None = None) -> dict:
        u_descent, u_horizontal = rng.random(), rng.random()
        h, top = self._horizontal(u_horizontal)
        v = -top + (-self.low - -top) * u_descent          # as rng.uniform(-top, -low) draws
        return {self.descent_key: f"{float(v)!r} m/s", self.horizontal_key: f"{float(h)!r} m/s"}

    def _horizontal(self, u: float) -> tuple[float, float]:
        """(horizontal speed, largest descent speed there) at marginal CDF value u."""
        (h_lo, top), (h_hi, _) = self.upper[0], self.upper[-1]
        heights = [v - self.low for _, v in self.upper]
        if len(set(heights)) == 1:                         # a flat edge (a box; also a line): uniform
            return h_lo + (h_hi - h_lo) * u, top           # as rng.uniform(h_lo, h_hi) draws
        areas = [(h1 - h0) * (y0 + y1) / 2 for (h0, _), (h1, _), y0, y1
                 in zip(self.upper, self.upper[1:], heights, heights[1:])]
        s = u * sum(areas)
        for ((h0, v0), (h1, v1)), y0, y1, a in zip(zip(self.upper, self.upper[1:]), heights, heights[1:], areas):
            if s <= a or (h1, v1) == self.upper[-1]:
                w = h1 - h0                                # area below the edge from h0 to h0 + x:
                k = (y1 - y0) / (2 * w)                    # y0 x + k x^2 = s, its root in [0, w] written stably
                root = sqrt(max(y0 * y0 + 4 * k * s, 0.0))
                x = min(max(2 * s / (y0 + root), 0.0), w) if y0 + root > 0 else 0.0
                return h0 + x, v0 + (v1 - v0) * x / w
            s -= a
        raise AssertionError("unreachable: the last segment takes the rest")


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
