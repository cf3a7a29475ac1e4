"""Crushable cores weighed from their cells: the prism a cell's curve needs of a crushable material
(AFFDL-TR-66-33 App. V: area = crushing force / crush strength, length = stroke / usable stroke fraction)."""

from __future__ import annotations

from alightsize.model.materials import Material


def crush_stroke(deflection, force) -> tuple[float, float]:
    """(crushing force, stroke to bottoming) of a cell curve: the largest force before the bottoming segment
    and the deflection where that segment starts."""
    return max(force[:-1]), deflection[-2]


def core_prism(weight: dict, deflection, force, material: Material, cell: str) -> dict:
    """The `weight` table (without its `method` and `cell`) as the prism weighing the core of a cell whose curve is
    (deflection m, force N), in `material` (one with crush_strength and stroke_fraction)."""
    crush, stroke = crush_stroke(deflection, force)
    assert material.crush_strength is not None and material.stroke_fraction is not None   # callers check it
    prism = {k: v for k, v in weight.items() if k not in ("method", "cell")}
    prism.update(method="prism", area=f"{crush / material.crush_strength!r} m^2",
                 length=f"{stroke / material.stroke_fraction!r} m")
    prism.setdefault("note", f"cell {cell}: area = crushing force / crush strength, "
                             f"length = stroke / {material.stroke_fraction:g}")
    return prism
