"""Crushable cores weighed from their cells: the prism a cell's curve needs of a crushable material
(AFFDL-TR-66-33 App. V: area = crushing force / crush strength, length = stroke / usable stroke fraction)."""

from __future__ import annotations

from typing import Annotated

from alightsize.common.typed import Number, Quantity, Table
from alightsize.model.materials import Material
from alightsize.weights.methods import WeightSpec


def crush_stroke(deflection, force) -> tuple[float, float]:
    """(crushing force, stroke to bottoming) of a cell curve: the largest force before the bottoming segment
    and the deflection where that segment starts."""
    return max(force[:-1]), deflection[-2]


class CoreWeight(Table):
    """The `weight` keys of an item weighed as a cell's crushable core: the cell's curve gives its prism."""

    allowance: Annotated[float, Number("any")] = 0.0
    extra: Annotated[float, Quantity("mass")] = 0.0
    label: str = ""
    note: str = ""


def core_weight(t: CoreWeight, deflection, force, material: Material, where: str) -> WeightSpec:
    """The prism weighing the core of a cell whose curve is (deflection m, force N) in `material` (one with
    crush_strength and stroke_fraction), with the allowance, extra mass and label of `t`."""
    crush, stroke = crush_stroke(deflection, force)
    assert material.crush_strength is not None and material.stroke_fraction is not None   # callers check it
    return WeightSpec("prism", {"rho": None, "area": crush / material.crush_strength,
                                "length": stroke / material.stroke_fraction, "allowance": t.allowance,
                                "extra": t.extra}, where, t.label)
