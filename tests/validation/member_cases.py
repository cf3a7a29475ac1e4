"""Shared by the member-check validation cases: a check read and evaluated as a design file's item is
(alightsize.pipeline.items.read_item: materials resolved, formula ranges enforced), in the units the
textbooks print (lbf, in, psi)."""

from __future__ import annotations

from alightsize.checks.kinds import Outcome
from alightsize.checks.rules import RULES
from alightsize.common.config import Node
from alightsize.model.materials import Material, library
from alightsize.pipeline.items import Item, read_item

IN = 0.0254                          # m, exact
LBF = 4.4482216152605                # N, exact (0.45359237 kg x 9.80665 m/s^2)
PSI = LBF / IN ** 2                  # Pa

# 6061-T6 (MIL-HDBK-5J): Fcy 35 ksi, E 9.9e6 psi, nu 0.33; not a shipped material.
AL_6061_T6 = Material("6061-t6", "6061-T6 aluminum", density=0.098 * 0.45359237 / IN ** 3,
                      yield_strength=35_000 * PSI, elastic_modulus=9.9e6 * PSI, poisson_m=1 / 0.33)
MATERIALS = {**library(), "6061-t6": AL_6061_T6}


def item(check: dict, section: dict | None, material: str = "7178-t6", rules: str = "current") -> Item:
    """One item of one check, read as `[[item]]` of a design file (bad input raises InputError)."""
    data = {"name": "case", "material": material, "check": [check]}
    if section is not None:
        data["section"] = section
    return read_item(Node("case.toml", "item[0]", data), MATERIALS, 1.2, RULES[rules])


def outcome(check: dict, section: dict | None, material: str = "7178-t6", rules: str = "current") -> Outcome:
    return item(check, section, material, rules).evaluate()[0]


def step(o: Outcome, symbol: str) -> float:
    """The value of the stress-sheet line with `symbol`."""
    return next(s.value for s in o.steps if s.symbol == symbol)


def tube(od: float, wall: float) -> dict:
    return {"shape": "tube", "outside_diameter": f"{od!r} in", "wall": f"{wall!r} in"}


def rod(d: float) -> dict:
    return {"shape": "rod", "diameter": f"{d!r} in"}
