"""Item weights of AFFDL-TR-66-33 App. V: computed (rho x volume) or scaled from the test model (eq. 107)."""

from __future__ import annotations

from dataclasses import dataclass
from math import pi
from typing import Annotated, Literal

from pydantic import BaseModel, RootModel, model_validator

from alightsize.common.trace import Step
from alightsize.common.config import Node
from alightsize.common.typed import Integer, Number, Quantity, Table, Tagged, refuse, validate
from alightsize.model.materials import Material, lookup
from alightsize.model.sections import Section, given


def tube_weight(rho: float, d_mean: float, t: float, length: float) -> float:
    """W = rho pi d t l (App. V, telescoping leg tubes)."""
    return rho * pi * d_mean * t * length


def disc_weight(rho: float, d: float, t: float, holes: int = 0, hole_d: float = 0.0, inner_d: float = 0.0) -> float:
    """W = rho pi/4 (d^2 - n d_h^2 - d_i^2) t (App. V, plates and caps)."""
    return rho * pi / 4 * (d * d - holes * hole_d * hole_d - inner_d * inner_d) * t


def sandwich_weight(rho_face: float, rho_core: float, d: float, tf: float, c: float) -> float:
    """W = pi/4 d² (2 rho_f tf + rho_c c): a circular sandwich plate's two faces and core (volumes, as App. V
    weighs plates; the bond lines and closeouts are not included: `allowance` or `extra`)."""
    return pi / 4 * d * d * (2 * rho_face * tf + rho_core * c)


def prism_weight(rho: float, area: float, length: float) -> float:
    """W = rho A l (App. V, rods, honeycomb, swivel)."""
    return rho * area * length


def scaled_weight(k: float, density_ratio: float, length_ratio: float, area_ratio: float, w_model: float) -> float:
    """W = K (rho/rho_TM) (l/l_TM) (A/A_TM) W_TM (AFFDL-TR-66-33 eq. 107)."""
    return k * density_ratio * length_ratio * area_ratio * w_model


def _given(value: float | None, key: str) -> float:
    """A size the weight method needs (KeyError naming it when neither the method nor the item gives it)."""
    if value is None:
        raise KeyError(key)
    return value


def _disc_area(holes: int, hole_d: float, inner_d: float) -> str:
    """The disc's area term of disc_weight with only the cut-outs it has: "{d}²", "({d}² - 6 {dh}²)", ..."""
    cuts = (f" - {holes} {{dh}}²" if holes and hole_d else "") + (" - {di}²" if inner_d else "")
    return f"({{d}}²{cuts})" if cuts else "{d}²"


@dataclass(frozen=True)
class WeightSpec:
    """How an item's weight is obtained; lengths in m, masses in kg. Missing sizes come from the section."""

    method: str
    params: dict
    where: str
    label: str = ""

    def evaluate(self, section: Section | None, material: Material, length: float | None) -> tuple[float, list[Step]]:
        p, rho = self.params, self.params.get("rho") or material.density
        if self.method == "fixed":
            return p["weight"], [Step("Weight (given)", "W", "{W}", (("W", p["weight"], "mass"),), p["weight"], "mass")]
        if self.method == "scaled":
            ar = p["area_ratio"] if p["area_ratio"] is not None else given(section).area() / p["model_area"]
            dr = p["density_ratio"] if p["density_ratio"] is not None else material.density / p["model_density"]
            w = scaled_weight(p["k"], dr, p["length_ratio"], ar, p["model_weight"])
            return w, [Step("Scaled weight (eq. 107)", "W", "{K} ({ρ/ρTM}) ({l/lTM}) ({A/ATM}) {WTM}",
                            (("K", p["k"], "dimensionless"), ("ρ/ρTM", dr, "dimensionless"),
                             ("l/lTM", p["length_ratio"], "dimensionless"), ("A/ATM", ar, "dimensionless"),
                             ("WTM", p["model_weight"], "mass")), w, "mass")]
        span = p.get("length") or length
        if self.method == "tube":
            d = p["diameter"] or given(section).mean_diameter
            t = p["wall"] or given(section).wall
            span = _given(span, "length")
            w = tube_weight(rho, d, t, span)
            steps = [Step("Weight", "W", "{ρ} π {d} {t} {l}", (("ρ", rho, "density"), ("d", d, "length"),
                                                              ("t", t, "length"), ("l", span, "length")), w, "mass")]
        elif self.method == "disc":
            d = p["diameter"] or given(section).dims["diameter"]
            t = p["thickness"] or given(section).dims["thickness"]
            di = p["inner_diameter"]
            if di is None:
                di = section.dims.get("inner_diameter", 0.0) if section else 0.0
            dh = p["hole_diameter"] or 0.0
            w = disc_weight(rho, d, t, p["holes"], dh, di)
            steps = [Step("Weight", "W", f"{{ρ}} π/4 {_disc_area(p['holes'], dh, di)} {{t}}",
                          (("ρ", rho, "density"), ("d", d, "length"), ("dh", dh, "length"), ("di", di, "length"),
                           ("t", t, "length")), w, "mass")]
        elif self.method == "sandwich":
            sec = given(section)
            if sec.core is None:
                raise KeyError("core_material")
            d, tf, c, rho_c = sec.dims["diameter"], sec.dims["face"], sec.dims["core_depth"], sec.core.density
            w = sandwich_weight(rho, rho_c, d, tf, c)
            steps = [Step("Weight: two faces and the core", "W", "π/4 {d}² (2 {ρf} {tf} + {ρc} {c})",
                          (("d", d, "length"), ("ρf", rho, "density"), ("tf", tf, "length"), ("ρc", rho_c, "density"),
                           ("c", c, "length")), w, "mass")]
        else:  # prism
            a = p["area"] if p["area"] is not None else given(section).area()
            span = _given(span, "length")
            w = prism_weight(rho, a, span)
            steps = [Step("Weight", "W", "{ρ} {A} {l}",
                          (("ρ", rho, "density"), ("A", a, "area"), ("l", span, "length")), w, "mass")]
        if p["allowance"]:
            w_allow = w * p["allowance"]
            steps.append(Step("Allowance", "ΔW", "{f} {W}", (("f", p["allowance"], "dimensionless"), ("W", w, "mass")),
                              w_allow, "mass"))
            w += w_allow
        if p["extra"]:
            steps.append(Step("Extra (bolts, fittings)", "ΔW", "{ΔW}", (("ΔW", p["extra"], "mass"),), p["extra"],
                              "mass"))
            w += p["extra"]
        return w, steps


Length = Annotated[float, Quantity("length")]
Area = Annotated[float, Quantity("area")]
Mass = Annotated[float, Quantity("mass")]
Ratio = Annotated[float, Number()]


class _Weight(Table):
    note: str = ""
    label: str = ""                   # the row name in the weight table (default: the item's name)


class _Formula(_Weight):
    """The keys of the methods that weigh a volume: a span, an allowance, extra mass and the density."""

    length: Length | None = None
    allowance: Annotated[float, Number("any")] = 0.0
    extra: Mass = 0.0
    density: Annotated[float, Quantity("density")] | None = None
    material: str | None = None       # a material of the library, for its density


class TubeWeight(_Formula):
    method: Literal["tube"]
    diameter: Length | None = None    # the mean diameter
    wall: Length | None = None


class DiscWeight(_Formula):
    method: Literal["disc"]
    diameter: Length | None = None
    thickness: Length | None = None
    inner_diameter: Length | None = None
    holes: Annotated[int, Integer(0)] = 0
    hole_diameter: Length | None = None


class SandwichWeight(_Formula):
    """A sandwich section's faces (the item's material, or `density`/`material`) and core (its core material)."""

    method: Literal["sandwich"]

    @model_validator(mode="after")
    def _no_length(self):
        if self.length is not None:
            raise refuse("no length (the section's diameter, faces and core give the volume)", "a length", "length")
        return self


class PrismWeight(_Formula):
    method: Literal["prism"]
    area: Area | None = None
    diameter: Length | None = None
    width: Length | None = None
    height: Length | None = None

    @model_validator(mode="after")
    def _one_area(self):
        given = [k for k in ("area", "diameter", "width") if getattr(self, k) is not None]
        if len(given) > 1:
            raise refuse("one of area, diameter, or width and height", " and ".join(given), given[1])
        if (self.width is None) != (self.height is None):
            raise refuse("width and height together", "only " + ("height" if self.width is None else "width"),
                         "width" if self.width is None else "height")
        return self


def _exactly_one(model: BaseModel, first: str, second: str) -> None:
    if (getattr(model, first) is None) == (getattr(model, second) is None):
        raise refuse(f"exactly one of {first}, {second}", "neither" if getattr(model, first) is None else "both",
                     first)


class ScaledWeight(_Weight):
    method: Literal["scaled"]
    k: Ratio = 1.0
    model_weight: Mass
    length_ratio: Ratio
    area_ratio: Ratio | None = None
    model_area: Area | None = None
    density_ratio: Ratio | None = None
    model_material: str | None = None

    @model_validator(mode="after")
    def _ratios(self):
        _exactly_one(self, "area_ratio", "model_area")
        _exactly_one(self, "density_ratio", "model_material")
        return self


class FixedWeight(_Weight):
    method: Literal["fixed"]
    weight: Mass


METHODS = ("tube", "disc", "prism", "sandwich", "scaled", "fixed")


class WeightTable(RootModel):
    """An item's `weight`: the table of its `method`."""

    root: Tagged("method", None, TubeWeight, DiscWeight, PrismWeight,  # type: ignore[valid-type]
                 SandwichWeight, ScaledWeight, FixedWeight)


def _area(t: PrismWeight) -> float | None:
    """A prism's cross-section area from what the table gives (None: the section's)."""
    if t.diameter is not None:
        return pi / 4 * t.diameter ** 2
    if t.width is not None and t.height is not None:
        return t.width * t.height
    return t.area


def read_weight(node: Node, materials: dict[str, Material]) -> WeightSpec:
    """An item's `weight` table (WeightTable) with its materials' densities: the method's parameters (SI)."""
    t = validate(WeightTable, node.data, node.file, node.path).root
    p: dict = {"rho": getattr(t, "density", None)}
    if getattr(t, "material", None) is not None:
        p["rho"] = lookup(materials, node).density
    if isinstance(t, FixedWeight):
        p["weight"] = t.weight
    elif isinstance(t, ScaledWeight):
        p.update(k=t.k, model_weight=t.model_weight, length_ratio=t.length_ratio, area_ratio=t.area_ratio,
                 model_area=t.model_area, density_ratio=t.density_ratio,
                 model_density=None if t.model_material is None else
                 lookup(materials, node, "model_material").density)
    else:
        p.update(length=t.length, allowance=t.allowance, extra=t.extra)
        if isinstance(t, TubeWeight):
            p.update(diameter=t.diameter, wall=t.wall)
        elif isinstance(t, DiscWeight):
            p.update(diameter=t.diameter, thickness=t.thickness, inner_diameter=t.inner_diameter, holes=t.holes,
                     hole_diameter=t.hole_diameter)
        elif isinstance(t, PrismWeight):
            p["area"] = _area(t)
    return WeightSpec(t.method, p, node.path, t.label)
