"""A lander's impact envelope (`[requirements.envelope]`, docs/reference/lander.md): the ranges of the landing
conditions its landing cases cover, SI. Read here, below the scene, because a lander file's nominal landing
takes its largest speeds from it."""

from __future__ import annotations

import itertools
from math import degrees, pi
from typing import Annotated, Any

from pydantic import PlainValidator, model_validator
from pydantic_core import PydanticCustomError

from alightsize.common.config import _describe
from alightsize.common.typed import Quantity, Table, quantity, refuse

Pair = tuple[float, float]
Polyline = tuple[Pair, ...]


def _range(value: Any, dim: str) -> Pair:
    """A value or a [low, high] range, 0 <= low <= high; a single value v is the range (v, v)."""
    if isinstance(value, list):
        if len(value) != 2:
            raise refuse("a value or a [low, high] range", repr(value))
        lo, hi = (_element(v, dim, f"[{i}]") for i, v in enumerate(value))
    else:
        lo = hi = quantity(value, dim, "any")
    if lo < 0 or hi < lo:
        raise refuse("0 <= low <= high", repr(value))
    return lo + 0.0, hi + 0.0          # "-0 m/s" as 0 (numpy's uniform refuses a high of -0.0 over a low of 0.0)


def _element(value: Any, dim: str, key: str) -> float:
    try:
        return quantity(value, dim, "any")
    except PydanticCustomError as exc:
        assert exc.context is not None              # `refuse` sets it
        raise refuse(exc.context["expected"], _describe(value), key) from None


def _signed(value: Any, limit: float) -> Pair:
    """An angle range: a largest magnitude v (either sign: (-v, v)) or a signed [low, high] range, each end within
    +-limit (exclusive)."""
    if isinstance(value, list):
        if len(value) != 2:
            raise refuse("a largest magnitude or a signed [low, high] range", repr(value))
        lo, hi = (_element(v, "angle", f"[{i}]") for i, v in enumerate(value))
    else:
        hi = quantity(value, "angle", "any")
        if hi < 0:
            raise refuse("a largest magnitude (either sign is landed) or a signed [low, high] range",
                          "a negative value")
        lo = -hi
    if not (lo <= hi and max(abs(lo), abs(hi)) < limit):
        raise refuse(f"low <= high, each within +-{degrees(limit):.0f} deg (exclusive)", repr(value))
    return lo, hi


def _polyline(value: Any) -> Polyline:
    """(horizontal, largest descent) speed points, m/s: at least two, each speed >= 0, horizontal strictly
    ascending."""
    if not (isinstance(value, list) and len(value) >= 2):
        raise refuse("at least two [horizontal speed, largest descent speed] points", _describe(value))
    points: list[Pair] = []
    for i, point in enumerate(value):
        if not (isinstance(point, list) and len(point) == 2):
            raise refuse("a [horizontal speed, largest descent speed] pair", _describe(point), f"[{i}]")
        h, v = (_element(x, "velocity", f"[{i}][{j}]") for j, x in enumerate(point))
        if h < 0 or v < 0:
            raise refuse("speeds >= 0 (a descent speed is positive downward)", repr(point), f"[{i}]")
        if points and h <= points[-1][0]:
            raise refuse("horizontal speeds strictly ascending", repr(point), f"[{i}]")
        points.append((h + 0.0, v + 0.0))
    return tuple(points)


def _interpolate(points: Polyline, h: float) -> float:
    """The polyline's descent speed at horizontal speed h (within its span)."""
    for (h0, v0), (h1, v1) in itertools.pairwise(points):
        if h0 <= h <= h1:
            return v0 + (v1 - v0) * (h - h0) / (h1 - h0)
    raise ValueError(f"{h} m/s outside the polyline's span")


def Range(dim: str) -> PlainValidator:  # noqa: N802 - a type's validator: Annotated[Pair, Range("velocity")]
    return PlainValidator(lambda v: _range(v, dim))


def Signed(limit: float) -> PlainValidator:  # noqa: N802 - a type's validator: Annotated[Pair, Signed(pi)]
    return PlainValidator(lambda v: _signed(v, limit))


class Envelope(Table):
    """Impact envelope, SI: (low, high) descent and horizontal speeds, the descent speed optionally limited further
    by a polyline of (horizontal speed, largest descent speed) points (the sloped envelope); signed (low, high)
    slope (negative: the velocity heads into the slope) and inclination (positive: leaning toward the velocity);
    the Monte Carlo's heading range; largest roll rate (either sign); footpad friction range (None: the scene's
    terrain)."""

    vertical_speed: Annotated[Pair, Range("velocity")]
    horizontal_speed: Annotated[Pair, Range("velocity")] = (0.0, 0.0)
    vertical_speed_limit: Annotated[Polyline, PlainValidator(_polyline)] | None = None
    slope: Annotated[Pair, Signed(pi / 2)] = (0.0, 0.0)
    inclination: Annotated[Pair, Signed(pi)] = (0.0, 0.0)
    heading: Annotated[Pair, Signed(2 * pi)] = (-pi, pi)
    roll_rate: Annotated[float, Quantity("angular_velocity", "any")] = 0.0
    friction: Annotated[Pair, Range("dimensionless")] | None = None
    note: str = ""

    @model_validator(mode="after")
    def _descent(self):
        if self.vertical_speed[1] <= 0:
            raise refuse("a descent speed above 0, or a [low, high] range", repr(self.vertical_speed),
                         "vertical_speed")
        if self.roll_rate < 0:
            raise refuse("a largest magnitude (either sign is landed)", "a negative value", "roll_rate")
        if self.vertical_speed_limit is not None:
            (h_lo, h_hi), limit = self.horizontal_speed, self.vertical_speed_limit
            if not limit[0][0] <= h_lo <= h_hi <= limit[-1][0]:
                raise refuse(f"points spanning horizontal_speed's range ({h_lo:.6g} to {h_hi:.6g} m/s)",
                             f"a span of {limit[0][0]:.6g} to {limit[-1][0]:.6g} m/s", "vertical_speed_limit")
            inside = [v for h, v in limit if h_lo < h < h_hi] + [_interpolate(limit, h_lo), _interpolate(limit, h_hi)]
            if min(inside) < self.vertical_speed[0]:
                raise refuse(f"a largest descent speed of at least vertical_speed's low ({self.vertical_speed[0]:.6g} "
                             "m/s) over horizontal_speed's range", f"{min(inside):.6g} m/s", "vertical_speed_limit")
            if max(inside) <= 0:
                raise refuse("a largest descent speed above 0 somewhere in horizontal_speed's range", "0 m/s",
                             "vertical_speed_limit")
        return self

    def upper(self) -> Polyline:
        """The region's largest descent speed along the horizontal range, as (horizontal, descent) points m/s,
        horizontal ascending: vertical_speed's high, lowered by vertical_speed_limit where given (its points inside
        the range, its value at each end and where it crosses the high). One point if the range is one speed."""
        (h_lo, h_hi), top = self.horizontal_speed, self.vertical_speed[1]
        if self.vertical_speed_limit is None:
            return ((h_lo, top),) if h_lo == h_hi else ((h_lo, top), (h_hi, top))
        limit = self.vertical_speed_limit
        knots = [(h_lo, _interpolate(limit, h_lo))] + [p for p in limit if h_lo < p[0] < h_hi]
        knots += [(h_hi, _interpolate(limit, h_hi))] if h_hi > h_lo else []
        out: list[Pair] = []
        for n, (h0, v0) in enumerate(knots):
            if n > 0 and (knots[n - 1][1] - top) * (v0 - top) < 0:     # crosses the high since the last point
                hp, vp = knots[n - 1]
                out.append((hp + (h0 - hp) * (top - vp) / (v0 - vp), top))
            if v0 <= top or n in (0, len(knots) - 1):                     # a point above the high is cut off
                out.append((h0, min(v0, top)))
        return tuple(out)

    def corners(self) -> tuple[tuple[Pair, bool], ...]:
        """The vertices of the (horizontal, descent) speed region, m/s, each with whether it lies on the largest
        descent speed (`upper`): the upper points and the low descent speed at both ends of the horizontal range,
        once each, ordered by descent then horizontal speed (a box: its four corners)."""
        upper = self.upper()
        lower = [(h, self.vertical_speed[0]) for h in sorted({upper[0][0], upper[-1][0]})]
        points = dict.fromkeys(upper, True) | {p: False for p in lower if p not in upper}
        return tuple(sorted(points.items(), key=lambda item: (item[0][1], item[0][0])))

    def nominal_velocity(self) -> tuple[float, float, float]:
        """The nominal landing's initial velocity in kappa (m/s): the largest descent speed of the region, at its
        largest horizontal speed (a box: the largest horizontal and descent speeds)."""
        h, v = max(self.upper(), key=lambda p: (p[1], p[0]))
        return 0.0, h, -v
