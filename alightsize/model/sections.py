"""Member cross-sections and plates: the dimensions an item is made of and the properties checks use."""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Annotated, Literal

from pydantic import RootModel, model_validator

from alightsize.model import section_properties as props

from alightsize.common import units
from alightsize.common.config import Node
from alightsize.common.typed import Quantity, Table, Tagged, refuse, validate
from alightsize.model.materials import Material

# shape -> (dimensions it is given by, derived properties a config may override with printed values)
SHAPES = {
    "tube": (("outside_diameter", "inside_diameter", "wall"), ("area", "inertia", "c")),
    "rod": (("diameter",), ("area", "inertia", "c")),
    "rectangle": (("width", "height"), ("area", "inertia", "c")),
    "plate": (("diameter", "thickness", "inner_diameter"), ()),
    "sandwich": (("diameter", "face", "core_depth"), ()),
    "given": ((), ("area", "inertia", "c")),
}


@dataclass(frozen=True)
class Section:
    """A shape with its dimensions (SI) and any printed properties that replace the derived ones; a sandwich's
    core material (`core`)."""

    shape: str
    dims: dict[str, float]
    overrides: dict[str, float] = field(default_factory=dict)
    core: Material | None = None

    def with_dim(self, name: str, value: float) -> "Section":
        return replace(self, dims={**self.dims, name: value})

    @property
    def wall(self) -> float:
        return self.dims["wall"]

    @property
    def outside_diameter(self) -> float:
        d = self.dims
        return d["outside_diameter"] if "outside_diameter" in d else d["inside_diameter"] + 2 * d["wall"]

    @property
    def mean_diameter(self) -> float:
        """Tube mean diameter d = OD - t (App. IV uses it in A = pi d t and I = pi r^3 t)."""
        return self.outside_diameter - self.wall

    def derived(self, name: str) -> float:
        """Property `name` ("area", "inertia", "c") from the dimensions alone; KeyError when the shape has none."""
        try:
            formula = _DERIVED[self.shape, name]
        except KeyError:
            raise KeyError(name) from None
        return formula(self)

    def _property(self, name: str) -> float:
        return self.overrides[name] if name in self.overrides else self.derived(name)

    def area(self) -> float:
        return self._property("area")

    def inertia(self) -> float:
        return self._property("inertia")

    def c(self) -> float:
        """Distance to the extreme fibre: OD/2 for a tube, d/2 for a rod, h/2 for a rectangle, unless printed."""
        return self._property("c")


# (shape, property) -> the property from the dimensions (AFFDL-TR-66-33 App. IV; formulas in section_properties.py)
_DERIVED = {
    ("tube", "area"): lambda s: props.tube_area(s.mean_diameter, s.wall),
    ("tube", "inertia"): lambda s: props.tube_inertia(s.mean_diameter, s.wall),
    ("tube", "c"): lambda s: s.outside_diameter / 2,
    ("rod", "area"): lambda s: props.rod_area(s.dims["diameter"]),
    ("rod", "inertia"): lambda s: props.rod_inertia(s.dims["diameter"]),
    ("rod", "c"): lambda s: s.dims["diameter"] / 2,
    ("rectangle", "area"): lambda s: props.rect_area(s.dims["width"], s.dims["height"]),
    ("rectangle", "inertia"): lambda s: props.rect_inertia(s.dims["width"], s.dims["height"]),
    ("rectangle", "c"): lambda s: s.dims["height"] / 2,
}

# A printed property further than this from the one its section's dimensions give is taken to belong to
# other dimensions (an edited wall, say). The shipped App. IV transcriptions are within 5.2 %: the report
# computes I = pi r^3 t on the inner radius (telescoping leg, 0.478 against 0.504 in^4) or a smaller
# diameter than its size line (config. 9 parallelogram post, 2.07 against 2.17 in^4). 10 % keeps them
# quiet with a margin of two, and a wall edited by a fifth or more moves a thin tube's inertia (about
# proportional to t) beyond it even from the -5 % the telescoping leg's printed I starts at.
OVERRIDE_TOLERANCE = 0.10


def given(section: Section | None) -> Section:
    """An item's section where a formula takes a size from it: KeyError "section" when the item has none (as a
    missing dimension raises KeyError naming it)."""
    if section is None:
        raise KeyError("section")
    return section


def geometry_error(section: Section) -> tuple[str, str] | None:
    """(dimension, expected) when the dimensions describe no real section: a tube wall of half its outside
    diameter or more (no bore: A = pi d t and I = pi r^3 t would be taken on a mean diameter below the wall),
    a plate's inner diameter as large as its diameter. Rods and rectangles only need positive sizes."""
    d = section.dims
    if section.shape == "tube" and "outside_diameter" in d and d["wall"] >= d["outside_diameter"] / 2:
        return "wall", "a wall less than half the outside diameter (an inside diameter above 0)"
    if section.shape == "plate" and d.get("inner_diameter", 0.0) >= d["diameter"]:
        return "inner_diameter", "an inner diameter less than the diameter"
    return None


def _check_overrides(node: Node, section: Section) -> None:
    """Warn where a printed property does not match the section's own dimensions (OVERRIDE_TOLERANCE)."""
    for name, printed in section.overrides.items():
        try:
            derived = section.derived(name)
        except KeyError:        # a shape that does not give it (`given`)
            continue
        if abs(printed / derived - 1) > OVERRIDE_TOLERANCE:
            written = node.raw(name)
            node.warn(name, f"printed {written} but the section's dimensions give {units.in_unit_of(derived, written)} "
                            f"({100 * (printed / derived - 1):+.1f} %, beyond the {OVERRIDE_TOLERANCE:.0%} tolerance); "
                            "the printed value is used: is it left over from other dimensions?")


Length = Annotated[float, Quantity("length")]


class _Printed(Table):
    """Printed properties that replace the derived ones."""

    area: Annotated[float, Quantity("area")] | None = None
    inertia: Annotated[float, Quantity("second_moment")] | None = None
    c: Length | None = None


class TubeTable(_Printed):
    shape: Literal["tube"]
    outside_diameter: Length | None = None
    inside_diameter: Length | None = None
    wall: Length

    @model_validator(mode="after")
    def _one_diameter(self):
        if (self.outside_diameter is None) == (self.inside_diameter is None):
            raise refuse("exactly one of outside_diameter, inside_diameter",
                         "neither" if self.outside_diameter is None else "both", "outside_diameter")
        return self


class RodTable(_Printed):
    shape: Literal["rod"]
    diameter: Length


class RectangleTable(_Printed):
    shape: Literal["rectangle"]
    width: Length
    height: Length


class PlateTable(Table):
    shape: Literal["plate"]
    diameter: Length
    thickness: Length
    inner_diameter: Length | None = None


class SandwichTable(Table):
    """A circular sandwich plate: two faces of thickness `face` on a core of depth `core_depth`, the core a
    material of the library."""

    shape: Literal["sandwich"]
    diameter: Length
    face: Length
    core_depth: Length
    core_material: str


class GivenTable(_Printed):
    shape: Literal["given"]


class SectionTable(RootModel):
    """An item's `section`: the table of its `shape` (dimensions and printed properties in SI)."""

    root: Tagged("shape", None, TubeTable, RodTable, RectangleTable, PlateTable,  # type: ignore[valid-type]
                 SandwichTable, GivenTable)


def read_section(node: Node, materials: dict[str, Material] | None = None) -> Section:
    """An item's `section` table (SectionTable), refused where its dimensions describe no real section; a printed
    property far from the derived one warns. A sandwich's `core_material` is one of `materials`."""
    t = validate(SectionTable, node.data, node.file, node.path).root
    names, overridable = SHAPES[t.shape]
    dims = {n: getattr(t, n) for n in names if getattr(t, n) is not None}
    core = None
    if isinstance(t, SandwichTable):
        materials = materials or {}
        if t.core_material not in materials:
            raise node.error("core_material", "one of the materials " + ", ".join(sorted(materials)),
                             repr(t.core_material))
        core = materials[t.core_material]
    section = Section(t.shape, dims, {n: getattr(t, n) for n in overridable if getattr(t, n) is not None}, core)
    problem = geometry_error(section)
    if problem:
        raise node.error(problem[0], problem[1], ", ".join(f"{n} {node.raw(n)}" for n in dims))
    _check_overrides(node, section)
    return section
