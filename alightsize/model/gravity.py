"""Surface gravity of the body a lander lands on: "earth", "moon", "mars" or an acceleration with units.

Only the acceleration the capsule feels changes: a weight given in a file is an Earth weight (mass =
W / g0), and accelerations are still reported and judged in g0 = 9.80665 m/s^2, as the criteria of Sec. II
are written."""

from __future__ import annotations

from alightsize_sim.landing import G0

from typing import Annotated

from pydantic import PlainValidator

from alightsize.common import units
from alightsize.common.typed import refuse

BODIES = {
    "earth": G0,        # standard gravity (CGPM 1901)
    "moon": 1.62,       # NASA Moon Fact Sheet, surface gravity 1.62 m/s^2
    "mars": 3.71,       # NASA Mars Fact Sheet, surface gravity 3.71 m/s^2
}


G_MIN, G_MAX = 1e-6, 100.0      # m/s^2: below a comet's (67P, about 2e-4) to ten Earth g (Jupiter's is 24.8)


def _gravity(value) -> float:
    """The surface gravity in m/s^2 of a body's name or an acceleration ("1.62 m/s^2"), from G_MIN to G_MAX:
    zero is refused (the tip-over and rest criteria need a "down"; a landing in near free fall takes a small
    value and runs to its time limit)."""
    if isinstance(value, str) and value.strip().lower() in BODIES:
        return BODIES[value.strip().lower()]
    if isinstance(value, str) and value.strip().isalpha():
        raise refuse(f"one of {', '.join(BODIES)} or an acceleration with units", repr(value))
    try:
        g = units.parse(value, "acceleration")
    except ValueError as exc:
        raise refuse(str(exc)) from None
    if not G_MIN <= g <= G_MAX:
        raise refuse(f"a surface gravity from {G_MIN:g} to {G_MAX:g} m/s^2 (it points down the terrain "
                     "normal; zero leaves no down for the tip-over and rest criteria: give a small value such "
                     "as \"1e-6 m/s^2\" for near free fall)", repr(value))
    return g


Gravity = Annotated[float, PlainValidator(_gravity)]
