"""A lander's impact envelope (`[requirements.envelope]`, docs/reference/lander.md): the ranges of the landing
conditions its landing cases cover, SI. Read here, below the scene, because a lander file's nominal landing
takes its largest speeds from it."""

from __future__ import annotations

from math import degrees, pi
from typing import Annotated, Any

from pydantic import PlainValidator, model_validator
from pydantic_core import PydanticCustomError

from alightsize.common.config import _describe
from alightsize.common.typed import Quantity, Table, quantity, refuse

Pair = tuple[float, float]


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


def Range(dim: str) -> PlainValidator:  # noqa: N802 - a type's validator: Annotated[Pair, Range("velocity")]
    return PlainValidator(lambda v: _range(v, dim))


def Signed(limit: float) -> PlainValidator:  # noqa: N802 - a type's validator: Annotated[Pair, Signed(pi)]
    return PlainValidator(lambda v: _signed(v, limit))


class Envelope(Table):
    """Impact envelope, SI: (low, high) descent and horizontal speeds; signed (low, high) slope (negative: the
    velocity heads into the slope) and inclination (positive: leaning toward the velocity); the Monte Carlo's
    heading range; largest roll rate (either sign); footpad friction range (None: the scene's terrain)."""

    vertical_speed: Annotated[Pair, Range("velocity")]
    horizontal_speed: Annotated[Pair, Range("velocity")] = (0.0, 0.0)
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
        return self

    def nominal_velocity(self) -> tuple[float, float, float]:
        """The nominal landing's initial velocity in kappa (m/s): the largest horizontal and descent speeds."""
        return 0.0, self.horizontal_speed[1], -self.vertical_speed[1]
