"""Member cross-sections and plates: the dimensions an item is made of and the properties checks use."""

from __future__ import annotations

from dataclasses import dataclass, field, replace

from . import stress
from .config import Node

# shape -> (dimensions it is given by, derived properties a config may override with printed values)
SHAPES = {
    "tube": (("outside_diameter", "inside_diameter", "wall"), ("area", "inertia", "c")),
    "rod": (("diameter",), ("area",)),
    "rectangle": (("width", "height"), ("area", "inertia", "c")),
    "plate": (("diameter", "thickness", "inner_diameter"), ()),
    "given": ((), ("area", "inertia", "c")),
}
_OVERRIDE_DIMS = {"area": "area", "inertia": "second_moment", "c": "length"}


@dataclass(frozen=True)
class Section:
    """A shape with its dimensions (SI) and any printed properties that replace the derived ones."""

    shape: str
    dims: dict[str, float]
    overrides: dict[str, float] = field(default_factory=dict)

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

    def area(self) -> float:
        if "area" in self.overrides:
            return self.overrides["area"]
        d = self.dims
        if self.shape == "tube":
            return stress.tube_area(self.mean_diameter, self.wall)
        if self.shape == "rod":
            return stress.rod_area(d["diameter"])
        if self.shape == "rectangle":
            return stress.rect_area(d["width"], d["height"])
        raise KeyError("area")

    def inertia(self) -> float:
        if "inertia" in self.overrides:
            return self.overrides["inertia"]
        if self.shape == "tube":
            return stress.tube_inertia(self.mean_diameter, self.wall)
        if self.shape == "rectangle":
            return stress.rect_inertia(self.dims["width"], self.dims["height"])
        raise KeyError("inertia")

    def c(self) -> float:
        """Distance to the extreme fibre: OD/2 for a tube, h/2 for a rectangle, unless printed."""
        if "c" in self.overrides:
            return self.overrides["c"]
        if self.shape == "tube":
            return self.outside_diameter / 2
        if self.shape == "rectangle":
            return self.dims["height"] / 2
        raise KeyError("c")


def read_section(node: Node) -> Section:
    shape = node.string("shape", choices=tuple(SHAPES))
    names, overridable = SHAPES[shape]
    node.allow(("shape", *names, *overridable))
    dims = {n: node.quantity(n, "length") for n in names if node.has(n)}
    if shape == "tube":
        if ("outside_diameter" in dims) == ("inside_diameter" in dims):
            raise node.error("outside_diameter", "exactly one of outside_diameter, inside_diameter",
                             "both" if "outside_diameter" in dims else "neither")
        required = ("wall",)
    else:
        required = tuple(n for n in names if n != "inner_diameter")
    for n in required:
        if n not in dims:
            node.raw(n)  # raises "expected this key to be present"
    overrides = {n: node.quantity(n, _OVERRIDE_DIMS[n]) for n in overridable if node.has(n)}
    node.finish()
    return Section(shape, dims, overrides)
