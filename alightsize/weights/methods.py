"""Item weights of AFFDL-TR-66-33 App. V: computed (rho x volume) or scaled from the test model (eq. 107)."""

from __future__ import annotations

from dataclasses import dataclass
from math import pi

from alightsize.common.trace import Step
from alightsize.common.config import Node
from alightsize.model.materials import Material, lookup
from alightsize.model.sections import Section, given


def tube_weight(rho: float, d_mean: float, t: float, length: float) -> float:
    """W = rho pi d t l (App. V, telescoping leg tubes)."""
    return rho * pi * d_mean * t * length


def disc_weight(rho: float, d: float, t: float, holes: int = 0, hole_d: float = 0.0, inner_d: float = 0.0) -> float:
    """W = rho pi/4 (d^2 - n d_h^2 - d_i^2) t (App. V, plates and caps)."""
    return rho * pi / 4 * (d * d - holes * hole_d * hole_d - inner_d * inner_d) * t


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


METHODS = ("tube", "disc", "prism", "scaled", "fixed")


def _area(node: Node) -> float | None:
    if node.has("area"):
        return node.quantity("area", "area")
    if node.has("diameter"):
        return pi / 4 * node.quantity("diameter", "length") ** 2
    if node.has("width"):
        return node.quantity("width", "length") * node.quantity("height", "length")
    return None


def read_weight(node: Node, materials: dict[str, Material]) -> WeightSpec:
    method = node.string("method", choices=METHODS)
    q = lambda name, dim: node.quantity(name, dim, default=None)  # noqa: E731 - optional quantity
    p: dict = {"rho": q("density", "density")}
    if node.has("material"):
        p["rho"] = lookup(materials, node).density
    if method == "fixed":
        p["weight"] = node.quantity("weight", "mass")
    elif method == "scaled":
        p["k"] = node.number("k", 1.0)
        p["model_weight"] = node.quantity("model_weight", "mass")
        p["length_ratio"] = node.number("length_ratio")
        p["area_ratio"] = node.number("area_ratio", None)
        p["model_area"] = q("model_area", "area")
        if (p["area_ratio"] is None) == (p["model_area"] is None):
            raise node.error("area_ratio", "exactly one of area_ratio, model_area", "both or neither")
        p["density_ratio"] = node.number("density_ratio", None)
        p["model_density"] = None
        if node.has("model_material"):
                p["model_density"] = lookup(materials, node, "model_material").density
        if (p["density_ratio"] is None) == (p["model_density"] is None):
            raise node.error("density_ratio", "exactly one of density_ratio, model_material", "both or neither")
    else:
        p.update(length=q("length", "length"), allowance=node.number("allowance", 0.0, positive=False),
                 extra=node.quantity("extra", "mass", default=0.0))
        if method == "tube":
            p.update(diameter=q("diameter", "length"), wall=q("wall", "length"))
        elif method == "disc":
            p.update(diameter=q("diameter", "length"), thickness=q("thickness", "length"),
                     inner_diameter=node.quantity("inner_diameter", "length", default=None),
                     holes=node.integer("holes", 0, minimum=0), hole_diameter=q("hole_diameter", "length"))
        else:
            p["area"] = _area(node)
    node.string("note", "")
    label = node.string("label", "")
    node.finish()
    return WeightSpec(method, p, node.path, label)
