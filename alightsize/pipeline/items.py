"""Leg items (the report's members): material, section, the checks that apply, weight and sizing."""

from __future__ import annotations

from dataclasses import dataclass, replace
from math import inf
from typing import Annotated

from alightsize.common import units
from alightsize.checks.kinds import SANDWICH_CORE, Check, Outcome, out_of_range, read_check
from alightsize.checks.rules import Rules
from pydantic import model_validator

from alightsize.common.config import Node
from alightsize.common.typed import Integer, Number, Quantities, Quantity, Table, refuse, validate
from alightsize.common.errors import InputError
from alightsize.common.trace import Step
from alightsize.loads.quasi_static import ForceRef, LoadReference, LoadsResult, Unloaded, resolve
from alightsize.model.materials import Material, lookup, require
from alightsize.model.sections import SHAPES, Section, geometry_error, read_section
from alightsize.weights.methods import WeightSpec, read_weight


@dataclass(frozen=True)
class SizeSpec:
    """Size an item instead of checking it: the dimension varied and its range or standard gauges (m)."""

    dimension: str
    low: float
    high: float
    gauges: tuple[float, ...] = ()


@dataclass(frozen=True)
class Item:
    name: str
    count: int
    material: Material
    section: Section | None
    length: float | None
    checks: tuple[Check, ...]
    required: float
    weight: WeightSpec | None
    size: SizeSpec | None = None
    note: str = ""
    where: str = ""                   # its key path as written, `item["Upper Truss"]` or `members.lower_tube`

    def evaluate(self, section: Section | None = None) -> list[Outcome]:
        return [c.evaluate(section or self.section, self.material) for c in self.checks]

    def governing_factor(self, section: Section | None = None) -> float:
        return min((o.factor for o in self.evaluate(section)), default=inf)

    def weight_each(self, section: Section | None = None) -> tuple[float, list[Step]] | None:
        """(kg, steps) or None when the item has no weight entry."""
        if self.weight is None:
            return None
        return self.weight.evaluate(section or self.section, self.material, self.length)

    def with_section(self, section: Section) -> "Item":
        return replace(self, section=section)


class RequiredFactor(Table):
    """A table's `required_design_factor`: finite, positive and at least 1, or below 1 only with
    `allow_below_one = true` beside it (below 1 a member passes at stresses above its allowable, so the override
    is explicit and the report names it)."""

    required_design_factor: Annotated[float, Number()] | None = None
    allow_below_one: bool = False

    @model_validator(mode="after")
    def _below_one(self):
        required, allow = self.required_design_factor, self.allow_below_one
        if required is not None and required < 1 and not allow:
            raise refuse("a required design factor of at least 1 (below 1 a member passes above its allowable; to "
                         "mean it, write allow_below_one = true beside it)", f"{required:g}", "required_design_factor")
        if allow and not (required is not None and required < 1):
            found = "no required_design_factor here" if required is None else f"required_design_factor {required:g}"
            raise refuse("allow_below_one = true only beside a required_design_factor below 1", found,
                         "allow_below_one")
        return self


class Size(Table):
    """An item's `size` table: the dimension varied, over [min, max] or standard `gauges` (m)."""

    dimension: str
    min: Annotated[float, Quantity("length")] | None = None
    max: Annotated[float, Quantity("length")] | None = None
    gauges: Annotated[tuple[float, ...], Quantities("length", "positive", minimum=1)] = ()

    @model_validator(mode="after")
    def _range(self):
        if self.gauges:
            both = next((k for k in ("min", "max") if getattr(self, k) is not None), None)
            if both:
                raise refuse("either gauges or min and max", f"gauges and {both}", both)
            return self
        for k in ("min", "max"):
            if getattr(self, k) is None:
                raise refuse("this key to be present", "nothing", k)
        if self.min >= self.max:
            raise refuse("max greater than min", f"min {self.min:g} m, max {self.max:g} m", "max")
        return self


class ItemTable(RequiredFactor):
    """An `[[item]]` table (docs/reference/design.md); its section, checks and weight are read by their kinds'
    readers (model.sections, checks.kinds, weights.methods)."""

    name: str
    count: Annotated[int, Integer(1)] = 1
    material: str
    length: Annotated[float, Quantity("length")] | None = None
    section: dict | None = None
    check: list[dict] = []
    weight: dict | WeightSpec | None = None    # WeightSpec: a crushable core's prism (pipeline.cores)
    size: Size | None = None
    note: str = ""


def _size_spec(t: Size, node: Node, section: Section | None, checks: tuple[Check, ...]) -> SizeSpec:
    """The size of an item; refused when a printed property or a check's own value would not follow the size, or
    an end of the range leaves no real section."""
    if section is None:
        raise node.error("dimension", "an item with a [section] to size", "no section")
    if section.overrides:
        raise node.error("dimension", "a section without printed area/inertia/c overrides (they would not follow the "
                         "size)", ", ".join(section.overrides))
    dim = t.dimension
    if dim not in section.dims:
        raise node.error("dimension", "one of " + ", ".join(repr(c) for c in section.dims), repr(dim))
    for check in checks:
        key = next((k for k, d in check.replaces.items() if d == dim), None)
        if key is not None:
            raise node.error("dimension", f"a dimension no check gives its own value for ({check.where}.{key} would "
                             f"keep its value while the {dim} is sized: remove it, or size another dimension)",
                             repr(dim))
    gauges = tuple(sorted(t.gauges))
    low, high = (gauges[0], gauges[-1]) if gauges else (t.min, t.max)
    assert low is not None and high is not None          # Size requires min and max without gauges
    for key, value in (("gauges" if gauges else "min", low), ("gauges" if gauges else "max", high)):
        problem = geometry_error(section.with_dim(dim, value))
        if problem:
            written = node.data[key][0] if gauges else node.data[key]     # lengths shown in the unit written here
            others = ", ".join(f"{n} {units.in_unit_of(v, written)}" for n, v in section.dims.items() if n != dim)
            raise node.error(key, f"sizes that keep a real section: {problem[1]}",
                             f"{dim} {units.in_unit_of(value, written)} with {others}")
    return SizeSpec(dim, low, high, gauges)


def read_item(node: Node, materials: dict[str, Material], required_default: float, rules: Rules) -> Item:
    """An `[[item]]` table (or a member's, as an item): ItemTable, then its section, checks, weight and size."""
    t = validate(ItemTable, node.data, node.file, node.path)
    if t.material not in materials:
        raise node.error("material", "one of the materials " + ", ".join(sorted(materials)), repr(t.material))
    section = read_section(node.table("section"), materials) if t.section is not None else None
    read: list[Check] = []
    for c in node.tables("check", optional=True, label="kind"):
        check = read_check(c, rules)
        if check.params.get("material") is not None:      # a bearing check's lug: a material of the library
            lug = lookup(materials, c)
            require(lug, "yield_strength", InputError(c.file, c.key("material"), "", ""))
            check = replace(check, params={**check.params, "material": lug})
        read.append(check)
    checks = tuple(read)
    required = required_default if t.required_design_factor is None else t.required_design_factor
    weight = (t.weight if isinstance(t.weight, WeightSpec)
              else read_weight(node.table("weight"), materials) if t.weight is not None else None)
    size = _size_spec(t.size, node.table("size"), section, checks) if t.size is not None else None
    item = Item(t.name, t.count, materials[t.material], section, t.length, checks, required, weight, size, t.note,
                node.path)
    _validate(item, node.file)
    return item


def references(items: tuple[Item, ...]) -> list[ForceRef]:
    """The envelope references of the items' checks as read, in order."""
    return [v for item in items for check in item.checks for p in check.params.values()
            for v in (p if isinstance(p, tuple) else (p,)) if isinstance(v, ForceRef)]


def _resolved(value, res: LoadsResult, file: str, refs: list[LoadReference]):
    """A check parameter with its envelope references (`ForceRef`, read as 1 N) given their values."""
    if isinstance(value, ForceRef):
        refs.append(resolve(res, value, file))
        return refs[-1].value
    if isinstance(value, tuple):
        return tuple(_resolved(v, res, file, refs) for v in value)
    return value


def with_loads(item: Item, res: LoadsResult | None, file: str) -> tuple[Item, list[LoadReference]]:
    """The item with its checks' envelope references resolved from `res`, and the references; a check of a member
    never loaded in an optional reference's sense is dropped (`Unloaded`). Validated again at the loads found."""
    if res is None:                     # without loads there is no reference (check_references refuses it)
        return item, []
    checks, refs = [], []
    for check in item.checks:
        found: list[LoadReference] = []
        try:
            params = {k: _resolved(v, res, file, found) for k, v in check.params.items()}
        except Unloaded:
            continue
        checks.append(replace(check, params=params))
        refs += found
    item = replace(item, checks=tuple(checks))
    _validate(item, file)
    return item, refs


def _validate(item: Item, file: str) -> None:
    """Evaluate once so a missing section property or material property is reported as bad input."""
    if not item.checks and item.weight is None:
        raise InputError(file, f"{item.where}.check", "at least one [[item.check]] or an [item.weight]", "neither")
    for check in item.checks:
        where = InputError(file, check.where, "", "")
        for prop in check.needs():
            require(item.material, prop, where)
        core = item.section.core if item.section is not None else None
        if core is not None:
            for prop in SANDWICH_CORE.get(check.kind, ()):
                require(core, prop, InputError(file, f"{item.where}.section.core_material", "", ""))
        try:
            bad = out_of_range(check, item.section, item.material)
            if bad:
                key, expected, found = bad
                raise InputError(file, f"{item.where}.{key}" if key.startswith("section.") else
                                 f"{check.where}.{key}", expected, found)
            check.evaluate(item.section, item.material)
        except (KeyError, AttributeError, TypeError) as exc:
            raise InputError(file, check.where, f"the item's [section] to give what check {check.kind!r} needs "
                             f"(shapes: {', '.join(SHAPES)})", f"missing {exc}") from None
        except (ValueError, ZeroDivisionError) as exc:
            raise InputError(file, check.where, "geometry for which the formula is defined", str(exc)) from None

    size, section = item.size, item.section
    if size is not None:
        assert section is not None                  # `_size_spec` refuses a size without a section
        for value in (size.low, size.high):         # sizes stay in every formula's range
            for check in item.checks:
                bad = out_of_range(check, section.with_dim(size.dimension, value), item.material)
                if bad:
                    raise InputError(file, f"{item.where}.size", f"a size range keeping {check.where} in its "
                                     f"formula's range: {bad[1]}",
                                     f"{size.dimension} {units.fmt(value, 'length', 'US')}: {bad[2]}")

    if item.weight is not None:
        try:
            w, _ = item.weight.evaluate(item.section, item.material, item.length)
        except (KeyError, AttributeError, TypeError) as exc:
            raise InputError(file, item.weight.where, "the sizes this weight method needs (given here or in the "
                             "item's [section] and length)", f"missing {exc}") from None
        if not w > 0:
            raise InputError(file, item.weight.where, "a positive weight", f"{w!r} kg")
