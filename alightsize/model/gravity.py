"""Surface gravity of the body a lander lands on: "earth", "moon", "mars" or an acceleration with units.

Only the acceleration the capsule feels changes: a weight given in a file is an Earth weight (mass =
W / g0), and accelerations are still reported and judged in g0 = 9.80665 m/s^2, as the criteria of Sec. II
are written."""

from __future__ import annotations

from alightsize_sim.landing import G0

from alightsize.common.config import Node

BODIES = {
    "earth": G0,        # standard gravity (CGPM 1901)
    "moon": 1.62,       # NASA Moon Fact Sheet, surface gravity 1.62 m/s^2
    "mars": 3.71,       # NASA Mars Fact Sheet, surface gravity 3.71 m/s^2
}


G_MIN, G_MAX = 1e-6, 100.0      # m/s^2: below a comet's (67P, about 2e-4) to ten Earth g (Jupiter's is 24.8)


def read_gravity(node: Node, key: str) -> float:
    """The surface gravity at `key` in m/s^2: a body's name or an acceleration ("1.62 m/s^2"); Earth if
    absent. From G_MIN to G_MAX: zero is refused (the tip-over and rest criteria need a "down"; a landing in
    near free fall takes a small value and runs to its time limit)."""
    value = node.raw(key, "earth")
    if isinstance(value, str) and value.strip().lower() in BODIES:
        return BODIES[value.strip().lower()]
    if isinstance(value, str) and value.strip().isalpha():
        raise node.error(key, f"one of {', '.join(BODIES)} or an acceleration with units", repr(value))
    g = node.parse_quantity(key, value, "acceleration", positive=False)
    if not G_MIN <= g <= G_MAX:
        raise node.error(key, f"a surface gravity from {G_MIN:g} to {G_MAX:g} m/s^2 (it points down the terrain "
                         "normal; zero leaves no down for the tip-over and rest criteria: give a small value such "
                         "as \"1e-6 m/s^2\" for near free fall)", repr(value))
    return g
