"""Failure-mode checks of AFFDL-TR-66-33 App. IV: each reads its loads from a config table and
evaluates, for a given section and material, the stress, the allowable and the design factor,
keeping every formula with its substituted numbers for the stress sheets."""

from __future__ import annotations

from dataclasses import dataclass, field
from math import pi, sqrt
from typing import Annotated, Any, Callable, Literal

from pydantic import PlainValidator, RootModel, ValidationInfo, model_validator
from pydantic_core import PydanticCustomError

from alightsize.checks import plates, sandwich

from alightsize.checks import stress
from alightsize.checks.rules import RULES, DEFAULT_RULES, Rules
from alightsize.common.config import Node, _describe
from alightsize.common.typed import Integer, Quantity, Sign, Table, Tagged, nested, quantity, refuse, validate
from alightsize.common.trace import Step
from alightsize.loads.quasi_static import ForceRef, Reference
from alightsize.model.materials import Material
from alightsize.model.sections import Section, given
from alightsize.common.units import fmt


@dataclass(frozen=True)
class Outcome:
    """What one check found: `stress`/`allowable` in Pa (None where the check is on loads only)."""

    mode: str
    load: float
    stress: float | None
    allowable: float | None
    factor: float
    steps: tuple[Step, ...]


@dataclass(frozen=True)
class Check:
    """A parsed check: its kind, its SI parameters, the config key path it came from and the config keys
    given in it that stand in for a section dimension (key -> dimension)."""

    kind: str
    params: dict
    where: str
    note: str = ""
    replaces: dict[str, str] = field(default_factory=dict)

    def evaluate(self, section: Section | None, material: Material) -> Outcome:
        """The check at `section` (None: an item without one; a formula that takes a size from it then raises)."""
        return KINDS[self.kind][1](self.params, section, material)

    def needs(self) -> tuple[str, ...]:
        """The material properties this check's formulas use."""
        return KINDS[self.kind][2]


# ---------------------------------------------------------------- check tables (typed, chosen by `kind`)

def _force(value: Any, info: ValidationInfo, sign: Sign, index: str = "") -> float:
    """A force with units, or an envelope reference table read as a `ForceRef` (its names are checked once the
    design is read: `check_references`)."""
    if isinstance(value, dict):
        assert info.context is not None and info.field_name is not None     # `read_check` gives the check's path
        return ForceRef(f"{info.context['where']}.{info.field_name}{index}", nested(Reference, value))
    return quantity(value, "force", sign)


def _forces(value: Any, info: ValidationInfo) -> tuple[float, ...]:
    if not isinstance(value, list) or not value:
        raise refuse("a non-empty array of quantities", repr(value))
    out = []
    for i, v in enumerate(value):
        try:
            out.append(_force(v, info, "any", f"[{i}]"))
        except PydanticCustomError as exc:
            ctx = exc.context or {}
            below = f"[{i}]" + (f".{ctx['key']}" if ctx["key"] else "")        # an element, or a key of its table
            raise refuse(ctx["expected"], ctx["found"] or _describe(v), below) from None
    return tuple(out)


def _force_or_forces(value: Any, info: ValidationInfo) -> float | tuple[float, ...]:
    return _forces(value, info) if isinstance(value, list) else _force(value, info, "any")


def _lengths_or_length(value: Any) -> float | tuple[float, ...]:
    if not isinstance(value, list):
        return quantity(value, "length", "positive")
    out = []
    for i, v in enumerate(value):
        try:
            out.append(quantity(v, "length", "positive"))
        except PydanticCustomError as exc:
            raise refuse((exc.context or {})["expected"], _describe(v), f"[{i}]") from None
    return tuple(out)


Force = Annotated[float, PlainValidator(lambda v, info: _force(v, info, "any"))]
PositiveForce = Annotated[float, PlainValidator(lambda v, info: _force(v, info, "positive"))]
Forces = Annotated[tuple[float, ...], PlainValidator(_forces)]
Length = Annotated[float, Quantity("length")]
Plate = Literal["app_iv", "tresca", "von_mises"]


class _Check(Table):
    note: str = ""


class _Loaded(_Check):
    load: Force


class _Moment(_Check):
    """A moment given directly, or as force x arm; arrays of forces and arms (same length) for a bound."""

    moment: Annotated[float, Quantity("moment", "any")] | None = None
    moment_force: Annotated[float | tuple[float, ...], PlainValidator(_force_or_forces)] | None = None
    moment_arm: Annotated[float | tuple[float, ...], PlainValidator(_lengths_or_length)] | None = None

    def _moment_required(self) -> bool:
        return True

    @model_validator(mode="after")
    def _one_moment(self):
        force, arm = self.moment_force, self.moment_arm
        if self.moment is not None and (force is not None or arm is not None):
            raise refuse("a moment or moment_force and moment_arm, not both", "moment and "
                         + ("moment_force" if force is not None else "moment_arm"),
                         "moment_force" if force is not None else "moment_arm")
        if self.moment is None and force is None:
            if arm is not None:
                raise refuse("moment_arm only with moment_force", "no moment_force", "moment_arm")
            if self._moment_required():
                raise refuse("a moment (\"16150 lbf*in\") or moment_force and moment_arm", "neither", "moment")
        if force is not None:
            if arm is None:
                raise refuse("this key to be present", "nothing", "moment_arm")
            if isinstance(force, tuple) and not (isinstance(arm, tuple) and len(arm) == len(force)):
                raise refuse(f"an array of {len(force)} lengths, one per moment_force",
                             f"{len(arm)} lengths" if isinstance(arm, tuple) else "one length", "moment_arm")
            if not isinstance(force, tuple) and isinstance(arm, tuple):
                raise refuse("a length", "an array", "moment_arm")
        return self

    def moment_params(self) -> dict:
        if self.moment is not None:
            return {"M": self.moment}
        return {"Mf": self.moment_force, "arm": self.moment_arm}


class Compression(_Loaded):
    kind: Literal["compression"]


class Tension(_Loaded):
    kind: Literal["tension"]


class Bending(_Moment):
    kind: Literal["bending"]


class Combined(_Moment):
    kind: Literal["combined"]
    load: Force


class ColumnBuckling(_Loaded):
    kind: Literal["column_buckling"]
    length: Length
    formula: Literal["euler", "johnson_euler"] | None = None


class LocalBuckling(_Moment):
    kind: Literal["local_buckling"]
    load: Force
    wall: Length | None = None
    formula: Literal["app_iv", "sp8007"] | None = None

    def _moment_required(self) -> bool:
        return False


class Bearing(_Check):
    kind: Literal["bearing"]
    loads: Forces
    combine: Literal["resultant", "sum"] = "resultant"
    diameter: Length | None = None
    bearing_length: Length
    material: str | None = None


class PinDoubleShear(_Check):
    kind: Literal["pin_double_shear"]
    loads: Forces
    diameter: Length | None = None
    planes: Annotated[int, Integer(1)] = 2


class PinShear(_Check):
    kind: Literal["pin_shear"]
    loads: Forces
    allowable_load: PositiveForce


class RingBending(_Loaded):
    kind: Literal["ring_bending"]
    span: Length


class ConeTension(_Loaded):
    kind: Literal["cone_tension"]
    thickness: Length


class _Thick(_Check):
    accept_thick_plate: bool = False


class _PlateLoad(_Thick):
    """A load W over a circle of radius r0 on a plate; the plate's radius and thickness default to the section's."""

    load: PositiveForce
    load_radius: Length
    radius: Length | None = None
    thickness: Length | None = None
    theory: Plate | None = None
    equivalent_radius: bool | None = None


class PlateFixedCenterLoad(_PlateLoad):
    kind: Literal["plate_fixed_center_load"]


class PlateSupportedCenterLoad(_PlateLoad):
    kind: Literal["plate_supported_center_load"]


class PlateFixedMoment(_PlateLoad, _Moment):
    kind: Literal["plate_fixed_center_moment_and_load"]
    formula: Literal["thin_plate", "app_iv"] | None = None
    pi_squared: bool = False


class PlateSupportedMoment(_PlateLoad, _Moment):
    kind: Literal["plate_supported_center_moment_and_load"]
    formula: Literal["thin_plate"] | None = None


class _Annular(_Thick):
    pressure: Annotated[float, Quantity("stress")]
    radius: Length | None = None
    inner_radius: Length | None = None
    thickness: Length | None = None


class AnnularOuterSupported(_Annular):
    kind: Literal["plate_annular_outer_supported_uniform_pressure"]


class AnnularOuterFixed(_Annular):
    kind: Literal["plate_annular_outer_fixed_uniform_pressure"]


class AnnularInnerSupported(_Annular):
    kind: Literal["plate_annular_inner_supported_uniform_pressure"]


class AnnularInnerFixed(_Annular):
    kind: Literal["plate_annular_inner_fixed_uniform_pressure"]


class PlateEccentric(_PlateLoad):
    kind: Literal["plate_supported_eccentric_and_distributed"]
    formula: Literal["thin_plate", "app_iv"] | None = None
    radius_tangential: Length | None = None
    distributed_load: PositiveForce
    load_offset: Length


class _Sandwich(_Check):
    """A load W over a central circle of radius r0 on a circular sandwich plate, edge simply supported; the plate's
    radius defaults to the section's."""

    load: PositiveForce
    load_radius: Length
    radius: Length | None = None


class SandwichFaceStress(_Sandwich):
    kind: Literal["sandwich_face_stress"]
    theory: Plate | None = None


class SandwichFaceBuckling(_Sandwich):
    kind: Literal["sandwich_face_buckling"]


class SandwichCoreShear(_Sandwich):
    kind: Literal["sandwich_core_shear"]


class SandwichCoreCrushing(_Sandwich):
    kind: Literal["sandwich_core_crushing"]


class CheckTable(RootModel):
    """An `[[item.check]]` table: the table of its `kind`."""

    root: Tagged("kind", None, Compression, Tension, Bending, Combined,  # type: ignore[valid-type]
                 ColumnBuckling, LocalBuckling, Bearing, PinShear, PinDoubleShear, RingBending, ConeTension,
                 PlateFixedCenterLoad, PlateSupportedCenterLoad, PlateFixedMoment, PlateSupportedMoment,
                 AnnularOuterSupported, AnnularOuterFixed, AnnularInnerSupported, AnnularInnerFixed, PlateEccentric,
                 SandwichFaceStress, SandwichFaceBuckling, SandwichCoreShear, SandwichCoreCrushing)


# ---------------------------------------------------------------- the checks' parameters (SI) from their tables

def _load(t, rules: Rules, node: Node) -> dict:
    """An axial load of either sign (tension or compression): the checks use its magnitude."""
    return {"P": t.load}


def _moment_of(t, rules: Rules, node: Node) -> dict:
    """M, or force x arm (M = P l, App. IV; either sign, the worst fibre is taken); arrays give the bound
    M = sum |P_i| l_i of moments whose vectors may add."""
    return t.moment_params()


def _axial_and_moment(t, rules: Rules, node: Node) -> dict:
    return {"P": t.load, **t.moment_params()}


def _buckling(t, rules: Rules, node: Node) -> dict:
    """`formula`: "euler" (App. IV's lines) or "johnson_euler" (Bruhn's); either way Johnson's parabola below the
    transition slenderness, where Euler's formula does not hold."""
    return {"P": t.load, "L": t.length, "formula": t.formula or rules.column}


def _local_params(t, rules: Rules, node: Node) -> dict:
    out = {"P": t.load}
    if t.moment is not None or t.moment_force is not None:
        out.update(t.moment_params())
    out["t"] = t.wall
    out["formula"] = t.formula or rules.local            # 0.4 E t / D, or SP-8007
    return out


def _bearing_params(t, rules: Rules, node: Node) -> dict:
    """`combine`: "resultant" of orthogonal components (default) or "sum" of loads pressing the same surface
    (App. IV's w1 + w2); `material`: the part the pin bears on (a lug), resolved by the item reader."""
    return {"components": t.loads, "combine": t.combine, "d": t.diameter, "t": t.bearing_length,
            "material": t.material}


def _double_shear_params(t, rules: Rules, node: Node) -> dict:
    return {"components": t.loads, "d": t.diameter, "planes": t.planes}


def _pin_params(t, rules: Rules, node: Node) -> dict:
    return {"components": t.loads, "allowable_load": t.allowable_load}


def _ring_params(t, rules: Rules, node: Node) -> dict:
    return {"P": t.load, "span": t.span}


def _cone_params(t, rules: Rules, node: Node) -> dict:
    return {"P": t.load, "t": t.thickness}


def _theory(t, rules: Rules) -> dict:
    """`theory`: "app_iv" (|sigma_r + sigma_t|/2 against Fcy/2), "tresca" or "von_mises" (principal stresses,
    sigma_z = 0, against Fcy); `equivalent_radius`: Roark's r0' for a load circle r0 < 0.5 t; with
    `accept_thick_plate` the thin-plate range is not enforced."""
    return {"theory": t.theory or rules.plate,
            "r0_equivalent": rules.equivalent_radius if t.equivalent_radius is None else t.equivalent_radius,
            "thick": t.accept_thick_plate}


def _plate_params(t, rules: Rules, node: Node) -> dict:
    return {"W": t.load, "r0": t.load_radius, "a": t.radius, "t": t.thickness, **_theory(t, rules)}


def _plate_moment_params(edge: str) -> Callable[[Any, Rules, Node], dict]:
    """A couple through a rigid hub of radius `load_radius` plus the load over it; outer edge `edge`. `formula`:
    "thin_plate", or "app_iv" (Roark 1954 p. 197, fixed edge only; `pi_squared` with it)."""
    def params(t, rules: Rules, node: Node) -> dict:
        choices = ("thin_plate", "app_iv") if edge == "fixed" else ("thin_plate",)
        formula = t.formula or (rules.plate_formula if rules.plate_formula in choices else "thin_plate")
        squared = t.pi_squared if edge == "fixed" else False
        if squared and formula != "app_iv":
            raise node.error("pi_squared", 'pi_squared only with formula = "app_iv" (the 1954 hub formula)',
                             f"formula = {formula!r}")
        return {**_plate_params(t, rules, node), **t.moment_params(), "edge": edge, "formula": formula,
                "pi_squared": squared}
    return params


def _annular_params(outer: str, inner: str) -> Callable[[Any, Rules, Node], dict]:
    """An annular plate under uniform pressure, its outer and inner edge `outer` and `inner`."""
    def params(t, rules: Rules, node: Node) -> dict:
        return {"q": t.pressure, "a": t.radius, "b": t.inner_radius, "t": t.thickness, "outer": outer,
                "inner": inner, "thick": t.accept_thick_plate}
    return params


def _eccentric_params(t, rules: Rules, node: Node) -> dict:
    """`formula`: "thin_plate" or "app_iv" (App. IV's load on a plate of radius a - p); `radius_tangential` only
    with "app_iv" (it reproduces a printed radius)."""
    formula = t.formula or rules.plate_formula
    if t.radius_tangential is not None and formula != "app_iv":
        raise node.error("radius_tangential", 'radius_tangential only with formula = "app_iv" (it reproduces the '
                         "radius App. IV printed)", f"formula = {formula!r}")
    return {"W": t.load, "W_total": t.distributed_load, "p": t.load_offset, "r0": t.load_radius, "a": t.radius,
            "a_t": t.radius_tangential, "formula": formula, "t": t.thickness, **_theory(t, rules)}


def _sandwich_params(t, rules: Rules, node: Node) -> dict:
    """`theory` (face stress only): the plate criterion of the faces' equal biaxial stress at the centre."""
    out = {"W": t.load, "r0": t.load_radius, "a": t.radius}
    if t.kind == "sandwich_face_stress":
        out["theory"] = t.theory or rules.plate
    return out


# ---------------------------------------------------------------- evaluators

def _moment(p: dict) -> tuple[float, Step | None]:
    """The moment's magnitude |M| (or |P| l): the checks take the worst fibre, whichever side it is on."""
    if "M" in p:
        return abs(p["M"]), None
    if not isinstance(p["Mf"], tuple):
        m = abs(p["Mf"]) * p["arm"]
        return m, Step("Moment", "M", "|{P}| {l}", (("P", p["Mf"], "force"), ("l", p["arm"], "length")), m, "moment")
    n = range(1, len(p["Mf"]) + 1)
    m = sum(abs(f) * a for f, a in zip(p["Mf"], p["arm"]))
    return m, Step("Moment (bound: the terms' magnitudes added)", "M", " + ".join(f"|{{P{i}}}| {{l{i}}}" for i in n),
                   tuple(x for i, f, a in zip(n, p["Mf"], p["arm"]) for x in ((f"P{i}", f, "force"),
                                                                             (f"l{i}", a, "length"))), m, "moment")


def _direct_step(load: float, area: float, label: str = "Compressive stress", symbol: str = "σc") -> Step:
    """sigma = P / A as a stress-sheet line."""
    return Step(label, symbol, "{P} / {A}", (("P", load, "force"), ("A", area, "area")),
                stress.direct_stress(load, area), "stress")


def _compression(p, s: Section | None, mat: Material, mode="compression", label="Compressive stress") -> Outcome:
    step = _direct_step(p["P"], given(s).area(), label, "σ")
    fy = mat.value("yield_strength")
    return Outcome(mode, p["P"], step.value, fy, stress.design_factor(fy, step.value), (step,))


def _tension(p, s, mat) -> Outcome:
    return _compression(p, s, mat, "tension", "Tensile stress")


def _bending_steps(p, s) -> tuple[float, float, list[Step]]:
    m, mstep = _moment(p)
    i, c = s.inertia(), s.c()
    sig = stress.bending_stress(m, c, i)
    steps = [mstep] if mstep else []
    steps.append(Step("Bending stress", "σB", "{M} {c} / {I}",
                      (("M", m, "moment"), ("c", c, "length"), ("I", i, "second_moment")), sig, "stress"))
    return m, sig, steps


def _bending(p, s, mat) -> Outcome:
    m, sig, steps = _bending_steps(p, s)
    fy = mat.yield_strength
    return Outcome("bending", m / s.c(), sig, fy, stress.design_factor(fy, sig), tuple(steps))


def _combined_parts(p, s) -> tuple[float, list[Step]]:
    direct = _direct_step(p["P"], s.area(), symbol="σC")
    sc = direct.value
    _, sb, steps = _bending_steps(p, s)
    total = stress.combined_stress(sc, sb)
    steps = [direct, *steps, Step("Combined stress at the worst fibre", "σmax", "|{σB}| + |{σC}|",
                                  (("σB", sb, "stress"), ("σC", sc, "stress")), total, "stress")]
    return total, steps


def _combined(p, s, mat) -> Outcome:
    total, steps = _combined_parts(p, s)
    fy = mat.yield_strength
    return Outcome("combined", p["P"], total, fy, stress.design_factor(fy, total), tuple(steps))


def _column(p, s, mat) -> Outcome:
    """App. IV's Euler lines (`euler`) or Bruhn's slenderness lines (`johnson_euler`); below the transition
    slenderness both judge on Johnson's parabola, Euler's formula holding only at or above it."""
    a, i, e, fy = s.area(), s.inertia(), mat.elastic_modulus, mat.yield_strength
    k = sqrt(i / a)
    lk, lt = p["L"] / k, stress.transition_slenderness(e, fy)
    direct = _direct_step(p["P"], a)
    sig = direct.value
    steps = [direct, Step("Radius of gyration", "k", "√({I} / {A})", (("I", i, "second_moment"), ("A", a, "area")),
                          k, "length")]
    if p["formula"] == "euler":
        steps += [Step("Critical column stress (Euler)", "σcB", "π² {E} / ({L} / {k})²",
                       (("E", e, "stress"), ("L", p["L"], "length"), ("k", k, "length")),
                       stress.euler_stress(e, p["L"], k), "stress"),
                  Step("Critical column load (Euler)", "Pcr", "π² {E} {I} / {L}²",
                       (("E", e, "stress"), ("I", i, "second_moment"), ("L", p["L"], "length")),
                       stress.euler_load(e, i, p["L"]), "force")]
        if lk >= lt:
            return Outcome("column_buckling", p["P"], sig, steps[2].value, stress.design_factor(steps[2].value, sig),
                           tuple(steps))
    crit, which = stress.column_stress(e, fy, lk)
    ek = (("E", e, "stress"), ("Fcy", fy, "stress"))
    steps += [Step("Slenderness", "L/k", "{L} / {k}", (("L", p["L"], "length"), ("k", k, "length")), lk,
                   "dimensionless"),
              Step("Transition slenderness (Bruhn 1973 C2.4)", "(L/k)T", "π √(2 {E} / {Fcy})", ek, lt, "dimensionless"),
              Step("Critical column stress, Johnson parabola (L/k below the transition, where Euler's does not hold)",
                   "σcr", "{Fcy} - ({Fcy} / 2π)² ({L/k})² / {E}", ek + (("L/k", lk, "dimensionless"),), crit, "stress")
              if which == "johnson" else
              Step("Critical column stress, Euler (L/k at or above the transition)", "σcr", "π² {E} / ({L/k})²",
                   (("E", e, "stress"), ("L/k", lk, "dimensionless")), crit, "stress")]
    return Outcome("column_buckling", p["P"], sig, crit, stress.design_factor(crit, sig), tuple(steps))


def _own_wall(p, s: Section) -> Section:
    """The section a local-buckling check works on: with the check's own `wall` when it gives one."""
    return s if p["t"] is None else s.with_dim("wall", p["t"])


def _local_range(p, s: Section, nu: float) -> str | None:
    """Why the check's thin-shell formula does not hold for this wall, or None (r/t >= 10 and < 1500, and App.
    IV's 0.4 E t / D at most SP-8007's curve); r/t < 10 is not refused: the wall yields first."""
    t = s.wall
    r = (s.outside_diameter - t) / 2
    if r / t >= stress.SP8007_MAX_R_OVER_T:
        return f"r/t = {r / t:.0f}: NASA SP-8007 states its knockdown for r/t below {stress.SP8007_MAX_R_OVER_T:.0f}"
    if (p["formula"] == "app_iv" and r / t >= stress.THIN_WALL_MIN_R_OVER_T
            and not stress.app_iv_local_in_range(1.0, t, r, nu)):         # E cancels from both sides
        return (f"r/t = {r / t:.0f}: App. IV's 0.4 E t / D exceeds NASA SP-8007's design curve there (above r/t "
                f"474 for nu = 0.3); use formula = \"sp8007\"")
    return None


def _local(p, s, mat) -> Outcome:
    s = _own_wall(p, s)
    t, d, e, fy, nu = s.wall, s.outside_diameter, mat.elastic_modulus, mat.yield_strength, 1 / mat.poisson_m
    problem = _local_range(p, s, nu)
    if problem:
        raise ValueError(problem)
    r = (d - t) / 2
    if "M" in p or "Mf" in p:
        applied, steps = _combined_parts(p, s)
    else:
        steps = [_direct_step(p["P"], s.area())]
        applied = steps[0].value
    steps.append(Step("Radius to wall", "r/t", "({D} - {t}) / (2 {t})", (("D", d, "length"), ("t", t, "length")),
                      r / t, "dimensionless"))
    if r / t < stress.THIN_WALL_MIN_R_OVER_T:
        crit = fy
        steps.append(Step("Thick wall (r/t below 10): it yields before it buckles locally", "σcr", "{Fcy}",
                          (("Fcy", fy, "stress"),), crit, "stress"))
        return Outcome("local_buckling", p["P"], applied, crit, stress.design_factor(crit, applied), tuple(steps))
    if p["formula"] == "sp8007":
        gamma = stress.thin_wall_knockdown(r / t)
        elastic = gamma * stress.classical_cylinder_stress(e, t, r, nu)
        steps.append(Step("Thin-wall knockdown (NASA SP-8007 eq. 4)", "γ", "1 - 0.901 (1 - exp(-√({r} / {t}) / 16))",
                          (("r", r, "length"), ("t", t, "length")), gamma, "dimensionless"))
        steps.append(Step("Local buckling stress (Timoshenko & Gere eq. 11-13 with γ)", "σLB",
                          "{γ} {E} {t} / ({r} √(3 (1 - {ν}²)))", (("γ", gamma, "dimensionless"), ("E", e, "stress"),
                          ("t", t, "length"), ("r", r, "length"), ("ν", nu, "dimensionless")), elastic, "stress"))
    else:
        elastic = stress.local_buckling_stress(e, t, d)
        steps.append(Step("Local buckling stress", "σLB", "0.4 {E} {t} / {D}",
                          (("E", e, "stress"), ("t", t, "length"), ("D", d, "length")), elastic, "stress"))
    crit = stress.local_critical(elastic, fy)
    if crit < elastic:
        steps.append(Step("Capped at the compressive yield (the elastic formula holds below it)", "σcr",
                          "min({σLB}, {Fcy})", (("σLB", elastic, "stress"), ("Fcy", fy, "stress")), crit, "stress"))
    return Outcome("local_buckling", p["P"], applied, crit, stress.design_factor(crit, applied), tuple(steps))


def _component_load(comps: tuple[float, ...], combine: str) -> tuple[float, Step]:
    """The resultant of orthogonal components, or the sum of loads pressing one surface, as a sheet line."""
    names = tuple((f"P{j + 1}", v, "force") for j, v in enumerate(comps))
    if combine == "sum":
        return stress.collinear_sum(*comps), Step("Collinear loads", "P", " + ".join(f"|{{{n}}}|" for n, _, _ in names),
                                                  names, stress.collinear_sum(*comps), "force")
    load = stress.resultant(*comps)
    return load, Step("Resultant pin load", "P", "√(" + " + ".join(f"{{{n}}}²" for n, _, _ in names) + ")",
                      names, load, "force")


def _bearing(p, s, mat) -> Outcome:
    """P / (d t) against the yield of the weaker of the pin and the part it bears on (Bruhn 1973 D1: the same
    bearing pressure acts on the pin and on the lug's hole)."""
    load, lstep = _component_load(p["components"], p["combine"])
    d = p["d"] or s.dims["diameter"]                 # the pin's diameter, else the rod section's
    sig = stress.bearing_stress(load, d, p["t"])
    steps = [lstep, Step("Bearing stress", "σBR", "{P} / ({d} {t})",
                         (("P", load, "force"), ("d", d, "length"), ("t", p["t"], "length")), sig, "stress")]
    fy, lug = mat.yield_strength, p["material"]
    if lug is not None:
        fy = min(fy, lug.yield_strength)
        steps.append(Step(f"Bearing allowable: the weaker of {mat.name} and {lug.name}", "Fbr", "min({Fcy1}, {Fcy2})",
                          (("Fcy1", mat.yield_strength, "stress"), ("Fcy2", lug.yield_strength, "stress")), fy,
                          "stress"))
    return Outcome("bearing", load, sig, fy, stress.design_factor(fy, sig), tuple(steps))


def _pin(p, s, mat) -> Outcome:
    load, lstep = _component_load(p["components"], "resultant")
    steps = (lstep, Step("Double-shear allowable load", "Pallow", "{Pallow}",
                         (("Pallow", p["allowable_load"], "force"),), p["allowable_load"], "force"))
    return Outcome("shear", load, None, None, stress.design_factor(p["allowable_load"], load), steps)


def _double_shear(p, s, mat) -> Outcome:
    load, lstep = _component_load(p["components"], "resultant")
    d = p["d"] or s.dims["diameter"]                 # the pin's own diameter, else the rod section's
    tau = stress.pin_shear_stress(load, d, p["planes"])
    allow = stress.shear_allowable(mat.yield_strength)
    steps = (lstep,
             Step("Pin shear stress (Bruhn 1973 D1.4)", "τ", "{P} / ({n} π {d}² / 4)",
                  (("P", load, "force"), ("n", p["planes"], "dimensionless"), ("d", d, "length")), tau, "stress"),
             Step("Shear allowable (maximum shear)", "τallow", "{Fcy} / 2", (("Fcy", mat.yield_strength, "stress"),),
                  allow, "stress"))
    return Outcome("shear", load, tau, allow, stress.design_factor(allow, tau), steps)


def _ring(p, s, mat) -> Outcome:
    m = stress.ring_moment(abs(p["P"]), p["span"])
    i, c = s.inertia(), s.c()
    if p["span"] / 2 / c < stress.RING_MIN_R_OVER_C:
        raise ValueError(f"R/c = {p['span'] / 2 / c:.2f}: a ring as a straight beam needs R/c >= "
                         f"{stress.RING_MIN_R_OVER_C:g} (R = span / 2)")
    sig = stress.bending_stress(m, c, i)
    fy = mat.yield_strength
    steps = (Step("Ring moment", "M", "|{P}| {L} / 4", (("P", p["P"], "force"), ("L", p["span"], "length")), m,
                  "moment"),
             Step("Bending stress", "σB", "{M} {c} / {I}",
                  (("M", m, "moment"), ("c", c, "length"), ("I", i, "second_moment")), sig, "stress"))
    return Outcome("bending", p["P"], sig, fy, stress.design_factor(fy, sig), steps)


def _cone(p, s, mat) -> Outcome:
    a = stress.cone_strip_area(p["t"])
    sig = stress.direct_stress(p["P"], a)
    fy = mat.yield_strength
    steps = (Step("Tensile stress on a 10t strip", "σT", "{P} / (10 {t}²)",
                  (("P", p["P"], "force"), ("t", p["t"], "length")), sig, "stress"),)
    return Outcome("tension", p["P"], sig, fy, stress.design_factor(fy, sig), steps)


def _plate_geometry(p, s: Section) -> tuple[float, float]:
    a = p.get("a") or s.dims["diameter"] / 2
    t = p.get("t") or s.dims["thickness"]
    return a, t


def _equivalent(sr: float, st: float, theory: str) -> float:
    """App. IV's |sigma_r + sigma_t|/2, or the Tresca or von Mises stress of (sigma_r, sigma_t, 0)."""
    if theory == "app_iv":
        return abs(stress.report_max_shear(sr, st))
    return (stress.tresca_stress if theory == "tresca" else stress.von_mises_stress)(sr, st, 0.0)


_THEORY = {"app_iv": ("Maximum shear stress", "τmax", "|{σr} + {σt}| / 2"),
           "tresca": ("Equivalent stress (Tresca, principal stresses, σz = 0)", "σeq",
                      "max(|{σr} - {σt}|, |{σt}|, |{σr}|)"),
           "von_mises": ("Equivalent stress (von Mises, principal stresses, σz = 0)", "σeq",
                         "√(({σr} - {σt})² + {σt}² + {σr}²) / √2")}


def _equivalent_step(sr: float, st: float, theory: str, where: str) -> Step:
    label, symbol, formula = _THEORY[theory]
    return Step(f"{label}, {where}", symbol, formula, (("σr", sr, "stress"), ("σt", st, "stress")),
                _equivalent(sr, st, theory), "stress")


def _verdict(eq: float, load: float, mat: Material, steps: list[Step], theory: str) -> Outcome:
    """App. IV's shear stress against Fcy/2, or an equivalent stress against Fcy; f from magnitudes."""
    fy = mat.value("yield_strength")
    allow = stress.shear_allowable(fy) if theory == "app_iv" else fy
    if theory == "app_iv":
        steps.append(Step("Shear allowable", "τallow", "{Fcy} / 2", (("Fcy", fy, "stress"),), allow, "stress"))
    return Outcome("plate_bending", load, eq, allow, stress.design_factor(allow, eq), tuple(steps))


def _shear_outcome(points: list[tuple[str, float, float]], load: float, mat: Material, steps: list[Step],
                   theory: str) -> Outcome:
    """Judge the governing one of `points` (where, sigma_r, sigma_t) by `theory`."""
    where, sr, st = max(points, key=lambda pt: _equivalent(pt[1], pt[2], theory))
    step = _equivalent_step(sr, st, theory, f"{where} (governs)" if len(points) > 1 else where)
    return _verdict(step.value, load, mat, [*steps, step], theory)


def _outside(bad: tuple[str, str, str], load: float) -> Outcome:
    """A plate evaluated outside its formula's range (a sizing scan past it): no factor, f = 0, never a pass."""
    key, expected, found = bad
    return Outcome("plate_bending", load, None, None, 0.0,
                   (Step(f"Outside the formula's range: {key} {found}, expected {expected}", "f", "{f}",
                         (("f", 0.0, "dimensionless"),), 0.0, "dimensionless"),))


def _thin_limit(p, t: float, span: float) -> tuple[str, str, str] | None:
    """Thin plate: t <= span/2, a quarter of the least transverse dimension (Young & Budynas 2002 §11.1)."""
    if t > span / 2 and not p["thick"]:
        expected = (f"a thin plate, thickness (this check's or the section's) at most {_length(span / 2)}, a quarter "
                    "of the plate's least transverse dimension (accept_thick_plate = true applies the thin-plate "
                    "formula beyond it, as App. IV does)")
        return "thickness", expected, _length(t)
    return None


def _plate_range(p, s: Section) -> tuple[str, str, str] | None:
    """(key, expected, found) when a plate check leaves its formula's range (ranges: alightsize.checks.plates)."""
    a, t = _plate_geometry(p, s)
    if "b" in p:                                                   # annular plate
        b = p["b"] or s.dims["inner_diameter"] / 2
        if b >= a:
            return "inner_radius", f"an inner radius below the plate radius {_length(a)}", _length(b)
        return _thin_limit(p, t, a - b)
    r0 = p["r0"]
    if "edge" in p:                                                # couple through a rigid hub of radius r0
        if p["formula"] == "app_iv" and r0 > plates.APP_IV_HUB_MAX * a:
            expected = (f"a hub radius at most {plates.APP_IV_HUB_MAX:g} times the plate radius, "
                        f"{_length(plates.APP_IV_HUB_MAX * a)}, for the 1954 formula (formula = \"thin_plate\" "
                        "holds up to the plate radius)")
            return "load_radius", expected, _length(r0)
        if r0 >= a:
            return "load_radius", f"a hub radius below the plate radius {_length(a)}", _length(r0)
        return _thin_limit(p, t, a - r0)
    if "p" in p:                                                   # eccentric load circle
        r = plates.equivalent_radius(r0, t) if p["r0_equivalent"] else r0
        if p["p"] + r > a:
            expected = ("a load circle inside the plate, load_offset + load_radius at most the plate radius "
                        f"{_length(a)}")
            return "load_offset", expected, f"{_length(p['p'])} + {_length(r)}" + (" (r0')" if r != r0 else "")
        return _thin_limit(p, t, a)
    if r0 > a:
        return "load_radius", f"a load radius at most the plate radius {_length(a)}", _length(r0)
    return _thin_limit(p, t, a)


_FIXED = "3 {W} ({m}+1) / (2π {m} {t}²) [ln({a}/{r0}) + {r0}²/(4 {a}²)]"
_FIXED_EDGE = "-3 {W} / (2π {t}²) [1 - {r0}²/(2 {a}²)], σt = σr / {m}"
_SUPPORTED = "3 {W} / (2π {m} {t}²) [{m} + ({m}+1) ln({a}/{r0}) - ({m}-1) {r0}²/(4 {a}²)]"
_CENTER = {"fixed": (("centre", plates.fixed_center_load, _FIXED, "edge fixed, at the centre (Roark 1954 p. 196)"),
                     ("edge", plates.fixed_edge_load, _FIXED_EDGE,
                      "edge fixed, at the edge (thin plate, Timoshenko & Woinowsky-Krieger 1959 ch. 3)")),
           "supported": (("centre", plates.supported_center_load, _SUPPORTED,
                          "edge supported, at the centre (Roark 1954 p. 194-195)"),)}


def _load_radius(p, t: float) -> tuple[float, list[Step]]:
    """r0, or Roark's equivalent r0' when asked for and r0 < 0.5 t (with the step that says so)."""
    r0 = p["r0"]
    if not p.get("r0_equivalent") or r0 >= 0.5 * t:
        return r0, []
    r = plates.equivalent_radius(r0, t)
    return r, [Step("Equivalent load radius (Roark 1954 p. 194: r0 < 0.5 t)", "r0'", "√(1.6 {r0}² + {t}²) - 0.675 {t}",
                    (("r0", r0, "length"), ("t", t, "length")), r, "length")]


def _center_points(p, edge: str, a: float, t: float, m: float) -> tuple[list[tuple[str, float, float]], list[Step]]:
    """The stresses of the load W over r0 (or r0') at each point that may govern, with their steps."""
    r0, steps = _load_radius(p, t)
    points = []
    for where, fn, formula, label in _CENTER[edge]:
        sr, st = fn(p["W"], t, a, r0, m)
        steps.append(Step(f"Stress due to load, {label}", "σr", formula,
                          (("W", p["W"], "force"), ("t", t, "length"), ("a", a, "length"), ("r0", r0, "length"),
                           ("m", m, "dimensionless")), sr, "stress"))
        points.append((f"load at the {where}", sr, st))
    return points, steps


def _plate_center(edge: str) -> Evaluator:
    def evaluate(p, s, mat) -> Outcome:
        bad = _plate_range(p, s)
        if bad:
            return _outside(bad, p["W"])
        a, t = _plate_geometry(p, s)
        points, steps = _center_points(p, edge, a, t, mat.poisson_m)
        return _shear_outcome(points, p["W"], mat, steps, p["theory"])
    return evaluate


def _plate_moment(p, s, mat) -> Outcome:
    """Couple through a rigid hub plus the load over it: each part at its own governing point, their equivalent
    stresses added (an upper bound where the two do not coincide; App. IV adds them the same way)."""
    bad = _plate_range(p, s)
    if bad:
        return _outside(bad, p["W"])
    a, t = _plate_geometry(p, s)
    m, r0 = mat.poisson_m, p["r0"]
    moment, mstep = _moment(p)
    steps = [mstep] if mstep else []
    ins = (("M", moment, "moment"), ("t", t, "length"), ("r0", r0, "length"), ("a", a, "length"),
           ("m", m, "dimensionless"))
    if p["formula"] == "app_iv":
        sm = plates.fixed_center_moment(moment, t, a, r0, m, p["pi_squared"])
        steps.append(Step("Stress due to moment (Roark 1954 p. 197)", "σM",
                          "3 {M} / (4 π" + ("²" if p["pi_squared"] else "") + " {t}² {r0}) [1 + ({m}+1)/{m} "
                          "ln(2(0.45 {a} - {r0}) / (0.45 k {a}))], k = 0.1 {a}² / ({r0} + 0.28 {a})²", ins, sm[0],
                          "stress"))
    else:
        sm = plates.hub_couple(moment, t, a, r0, m, p["edge"])
        fixed = p["edge"] == "fixed"
        steps.append(Step(f"Stress due to moment at the hub edge, rigid hub, edge {p['edge']} (thin plate)", "σM",
                          "3 {M} F / (π {r0} {t}²), F = " + ("({a}² - {r0}²)/({a}² + {r0}²)" if fixed else
                          "[(3+{ν}){a}⁴ - 2(1+{ν}){a}²{r0}² - (1-{ν}){r0}⁴] / [(3+{ν}){a}⁴ + (1-{ν}){r0}⁴]"),
                          ins + (("ν", 1 / m, "dimensionless"),), sm[0], "stress"))
    points, load_steps = _center_points(p, p["edge"], a, t, m)
    steps += load_steps
    where, wr, wt = max(points, key=lambda pt: _equivalent(pt[1], pt[2], p["theory"]))
    parts = (_equivalent_step(*sm, p["theory"], "couple at the hub edge"),
             _equivalent_step(wr, wt, p["theory"], where))
    total = parts[0].value + parts[1].value
    steps += [*parts, Step("Couple and load added", parts[0].symbol, "{couple} + {load}",
                           (("couple", parts[0].value, "stress"), ("load", parts[1].value, "stress")), total, "stress")]
    return _verdict(total, p["W"], mat, steps, p["theory"])


_CASE_2 = {("supported", "free"): "2a", ("fixed", "free"): "2e", ("free", "supported"): "2i", ("free", "fixed"): "2j"}


def _plate_annular(p, s, mat) -> Outcome:
    """Both edges of the annular plate, judged by Tresca (there sigma_r = 0 or sigma_t = nu sigma_r, so Tresca is
    the larger principal stress App. IV judged, against Fcy)."""
    bad = _plate_range(p, s)
    a, t = _plate_geometry(p, s)
    b = p["b"] or s.dims["inner_diameter"] / 2
    load = p["q"] * pi * (a * a - b * b)
    if bad:
        return _outside(bad, load)
    case = _CASE_2[(p["outer"], p["inner"])]
    ins = (("q", p["q"], "stress"), ("a", a, "length"), ("b", b, "length"), ("t", t, "length"))
    edges = plates.annular_uniform_pressure(p["q"], t, a, b, mat.poisson_m, p["outer"], p["inner"])
    steps, points = [], []
    for where, (sr, st) in zip(("inner edge", "outer edge"), edges):
        for symbol, value in (("σr", sr), ("σt", st)):
            steps.append(Step(f"{'Radial' if symbol == 'σr' else 'Tangential'} stress at the {where} (thin plate, "
                              f"Young & Budynas 2002 Table 11.2 case {case})", symbol,
                              f"6 M/t² of {{q}} on {{a}} x {{b}} x {{t}}, outer edge {p['outer']}, inner {p['inner']}",
                              ins, value, "stress"))
        points.append((where, sr, st))
    return _shear_outcome(points, load, mat, steps, "tresca")


def _plate_eccentric(p, s, mat) -> Outcome:
    """App. IV's sign: the load W (a rod) acts against W' (spread over the plate); at the centre of W's circle."""
    bad = _plate_range(p, s)
    if bad:
        return _outside(bad, p["W"])
    a, t = _plate_geometry(p, s)
    m = mat.poisson_m
    r0, steps = _load_radius(p, t)
    ins = (("W", p["W"], "force"), ("W'", p["W_total"], "force"), ("t", t, "length"), ("a", a, "length"),
           ("p", p["p"], "length"), ("r0", r0, "length"), ("m", m, "dimensionless"))
    if p["formula"] == "app_iv":
        e = plates.app_iv_eccentric_load(p["W"], t, a, p["p"], r0, m)
        er, et = e, e
        steps.append(Step("Stress due to the eccentric load, as a central load on a plate of radius a - p "
                          "(App. IV; Roark 1954 p. 194-195)", "σW",
                          "3 {W} / (2π {m} {t}²) [{m} + ({m}+1) ln(({a}-{p})/{r0}) - ({m}-1) {r0}²/(4({a}-{p})²)]",
                          ins, e, "stress"))
    else:
        er, et = plates.supported_eccentric_load(p["W"], t, a, p["p"], r0, m)
        for symbol, value in (("σW,r", er), ("σW,t", et)):
            steps.append(Step(f"{'Radial' if symbol == 'σW,r' else 'Tangential'} stress due to the eccentric load "
                              "(thin plate, supported edge: Green's function over the load circle)", symbol,
                              "6 M/t² of {W} over {r0} at {p} on a plate {a} x {t}", ins, value, "stress"))
    a_t = p["a_t"] or a
    dr, dt = plates.supported_uniform_load(p["W_total"], t, a, p["p"], m, a_t)
    steps.append(Step("Radial stress due to the distributed load (Roark 1954 p. 194)", "σW',r",
                      "3 {W'} / (8π {m} {t}²) (3 {m}+1)(1 - {p}²/{a}²)", ins, dr, "stress"))
    steps.append(Step("Tangential stress due to the distributed load (Roark 1954 p. 194)", "σW',t",
                      "3 {W'} / (8π {m} {t}²) [(3 {m}+1) - ({m}+3) {p}²/{at}²]", ins + (("at", a_t, "length"),), dt,
                      "stress"))
    sr, st = dr - er, dt - et
    steps.append(Step("Radial stress at the load", "σr", "{σW',r} - {σW,r}",
                      (("σW',r", dr, "stress"), ("σW,r", er, "stress")), sr, "stress"))
    steps.append(Step("Tangential stress at the load", "σt", "{σW',t} - {σW,t}",
                      (("σW',t", dt, "stress"), ("σW,t", et, "stress")), st, "stress"))
    return _shear_outcome([("at the load", sr, st)], p["W"], mat, steps, p["theory"])


def _sandwich_geometry(p, s: Section) -> tuple[float, float, float, Material]:
    """(a, tf, c, core) of a sandwich check: the plate radius (the check's or the section's), the face thickness,
    the core depth and the core material."""
    if s.core is None:
        raise KeyError("core_material")
    return p["a"] or s.dims["diameter"] / 2, s.dims["face"], s.dims["core_depth"], s.core


def _sandwich_range(p, s: Section) -> tuple[str, str, str] | None:
    """The load circle inside the plate, and a thin plate: the sandwich's depth c + 2 tf at most half its radius
    (Young & Budynas 2002 §11.1, as the solid plates)."""
    a, tf, c, _ = _sandwich_geometry(p, s)
    if p["r0"] > a:
        return "load_radius", f"a load radius at most the plate radius {_length(a)}", _length(p["r0"])
    if c + 2 * tf > a / 2:
        return ("section.core_depth", f"a thin plate, depth (core_depth + 2 face) at most {_length(a / 2)}, half the "
                "plate's radius", _length(c + 2 * tf))
    return None


def _sandwich_face(p, s, mat) -> tuple[float, list[Step]]:
    """The faces' stress at the centre (equal radial and tangential, tension on the lower face, compression on
    the loaded one) with its steps."""
    a, tf, c, _ = _sandwich_geometry(p, s)
    m = mat.value("poisson_m")
    moment = sandwich.centre_moment(p["W"], a, p["r0"], m)
    sig = sandwich.face_stress(moment, tf, c)
    return sig, [Step("Bending moment per unit width at the centre, edge supported (Roark 1954 p. 194-195; the "
                      "sandwich's moments are the solid plate's)", "M",
                      "{W} / (4π) [1 + (1 + 1/{m}) ln({a}/{r0}) - (1 - 1/{m}) {r0}²/(4 {a}²)]",
                      (("W", p["W"], "force"), ("m", m, "dimensionless"), ("a", a, "length"),
                       ("r0", p["r0"], "length")), moment, "force"),
                 Step("Face stress at the centre, outer fibre (Allen 1969 ch. 2)", "σf",
                      "6 {M} ({c} + 2 {tf}) / (({c} + 2 {tf})³ - {c}³)",
                      (("M", moment, "force"), ("c", c, "length"), ("tf", tf, "length")), sig, "stress")]


def _sandwich_outside(p, s) -> Outcome | None:
    bad = _sandwich_range(p, s)
    return _outside(bad, p["W"]) if bad else None


def _sandwich_stress(p, s, mat) -> Outcome:
    out = _sandwich_outside(p, s)
    if out:
        return out
    sig, steps = _sandwich_face(p, s, mat)
    return _shear_outcome([("faces at the centre", sig, sig)], p["W"], mat, steps, p["theory"])


def _sandwich_buckling(p, s, mat) -> Outcome:
    """The loaded face in equal biaxial compression at the centre: intracell buckling judged on the sum of the two
    compressive stresses (the linear interaction, exact for a square cell's first mode, Timoshenko & Gere 1961
    §9.5), wrinkling on either stress (one-way wrinkles); each elastic critical stress capped at the face's yield
    (2 Fcy for the sum), where the face stress check governs. The lower factor of the two is the check's."""
    out = _sandwich_outside(p, s)
    if out:
        return out
    _, tf, _, core = _sandwich_geometry(p, s)
    e, fy, nu = mat.value("elastic_modulus"), mat.value("yield_strength"), 1 / mat.value("poisson_m")
    sig, steps = _sandwich_face(p, s, mat)
    ic = sandwich.intracell_buckling(e, nu, tf, core.value("cell_size"))
    wr = sandwich.wrinkling(e, core.value("elastic_modulus"), core.value("shear_modulus"))
    ic_crit, wr_crit = min(ic, 2 * fy), stress.local_critical(wr, fy)
    steps += [Step("Intracell buckling stress (Hexcel 2000 TSB 124 p. 5)", "σic", "2 {Ef} / (1 - {ν}²) ({tf} / {s})²",
                   (("Ef", e, "stress"), ("ν", nu, "dimensionless"), ("tf", tf, "length"),
                    ("s", core.value("cell_size"), "length")), ic, "stress"),
              Step("Intracell allowable of σr + σt, capped at the equal-biaxial yield", "σic,allow",
                   "min({σic}, 2 {Fcy})", (("σic", ic, "stress"), ("Fcy", fy, "stress")), ic_crit, "stress"),
              Step("Intracell factor: σr + σt against it", "fic", "{σic,allow} / (2 {σf})",
                   (("σic,allow", ic_crit, "stress"), ("σf", sig, "stress")), ic_crit / (2 * sig), "dimensionless"),
              Step("Wrinkling stress (Hexcel 2000 TSB 124 p. 5)", "σwr", "0.5 ({Ef} {Ec} {Gc})^(1/3)",
                   (("Ef", e, "stress"), ("Ec", core.value("elastic_modulus"), "stress"),
                    ("Gc", core.value("shear_modulus"), "stress")), wr, "stress"),
              Step("Wrinkling allowable, capped at the face's yield", "σwr,allow", "min({σwr}, {Fcy})",
                   (("σwr", wr, "stress"), ("Fcy", fy, "stress")), wr_crit, "stress")]
    if ic_crit / 2 <= wr_crit:
        return Outcome("face_buckling", p["W"], 2 * sig, ic_crit, stress.design_factor(ic_crit, 2 * sig), tuple(steps))
    return Outcome("face_buckling", p["W"], sig, wr_crit, stress.design_factor(wr_crit, sig), tuple(steps))


def _sandwich_shear(p, s, mat) -> Outcome:
    out = _sandwich_outside(p, s)
    if out:
        return out
    _, tf, c, core = _sandwich_geometry(p, s)
    tau = sandwich.core_shear(p["W"], p["r0"], tf, c)
    allow = core.value("shear_strength")
    steps = (Step("Core shear stress at the load circle (Allen 1969 ch. 2)", "τc", "{W} / (2π {r0} ({c} + {tf}))",
                  (("W", p["W"], "force"), ("r0", p["r0"], "length"), ("c", c, "length"), ("tf", tf, "length")),
                  tau, "stress"),
             Step(f"Core shear strength ({core.name})", "τallow", "{τallow}", (("τallow", allow, "stress"),), allow,
                  "stress"))
    return Outcome("core_shear", p["W"], tau, allow, stress.design_factor(allow, tau), steps)


def _sandwich_crushing(p, s, mat) -> Outcome:
    out = _sandwich_outside(p, s)
    if out:
        return out
    core = _sandwich_geometry(p, s)[3]
    sig = sandwich.core_bearing(p["W"], p["r0"])
    allow = core.value("compressive_strength")
    steps = (Step("Core bearing stress under the load circle", "σc", "{W} / (π {r0}²)",
                  (("W", p["W"], "force"), ("r0", p["r0"], "length")), sig, "stress"),
             Step(f"Core compressive strength ({core.name})", "Fc", "{Fc}", (("Fc", allow, "stress"),), allow,
                  "stress"))
    return Outcome("core_crushing", p["W"], sig, allow, stress.design_factor(allow, sig), steps)


# kind -> (parameters from its table, evaluator, material properties it needs)
Reader = Callable[[Any, Rules, Node], dict]
Evaluator = Callable[[dict, Section | None, Material], Outcome]      # section None: an item without one
KINDS: dict[str, tuple[Reader, Evaluator, tuple[str, ...]]] = {
    "compression": (_load, _compression, ("yield_strength",)),
    "tension": (_load, _tension, ("yield_strength",)),
    "bending": (_moment_of, _bending, ("yield_strength",)),
    "combined": (_axial_and_moment, _combined, ("yield_strength",)),
    "column_buckling": (_buckling, _column, ("elastic_modulus", "yield_strength")),
    "local_buckling": (_local_params, _local, ("elastic_modulus", "yield_strength", "poisson_m")),
    "bearing": (_bearing_params, _bearing, ("yield_strength",)),
    "pin_shear": (_pin_params, _pin, ()),
    "pin_double_shear": (_double_shear_params, _double_shear, ("yield_strength",)),
    "ring_bending": (_ring_params, _ring, ("yield_strength",)),
    "cone_tension": (_cone_params, _cone, ("yield_strength",)),
    "plate_fixed_center_load": (_plate_params, _plate_center("fixed"), ("yield_strength", "poisson_m")),
    "plate_supported_center_load": (_plate_params, _plate_center("supported"), ("yield_strength", "poisson_m")),
    "plate_fixed_center_moment_and_load": (_plate_moment_params("fixed"), _plate_moment,
                                           ("yield_strength", "poisson_m")),
    "plate_supported_center_moment_and_load": (_plate_moment_params("supported"), _plate_moment,
                                               ("yield_strength", "poisson_m")),
    "plate_annular_outer_supported_uniform_pressure": (_annular_params("supported", "free"), _plate_annular,
                                                       ("yield_strength", "poisson_m")),
    "plate_annular_outer_fixed_uniform_pressure": (_annular_params("fixed", "free"), _plate_annular,
                                                   ("yield_strength", "poisson_m")),
    "plate_annular_inner_supported_uniform_pressure": (_annular_params("free", "supported"), _plate_annular,
                                                       ("yield_strength", "poisson_m")),
    "plate_annular_inner_fixed_uniform_pressure": (_annular_params("free", "fixed"), _plate_annular,
                                                   ("yield_strength", "poisson_m")),
    "plate_supported_eccentric_and_distributed": (_eccentric_params, _plate_eccentric, ("yield_strength", "poisson_m")),
    "sandwich_face_stress": (_sandwich_params, _sandwich_stress, ("yield_strength", "poisson_m")),
    "sandwich_face_buckling": (_sandwich_params, _sandwich_buckling,
                               ("elastic_modulus", "yield_strength", "poisson_m")),
    "sandwich_core_shear": (_sandwich_params, _sandwich_shear, ()),
    "sandwich_core_crushing": (_sandwich_params, _sandwich_crushing, ()),
}
# sandwich kind -> the core material properties it uses
SANDWICH_CORE = {"sandwich_face_stress": (),
                 "sandwich_face_buckling": ("elastic_modulus", "shear_modulus", "cell_size"),
                 "sandwich_core_shear": ("shear_strength",), "sandwich_core_crushing": ("compressive_strength",)}
# retired kind -> what to write instead
RETIRED = {"plate_annular_uniform_pressure": (
    ("plate_annular_inner_supported_uniform_pressure (what this name computed: inner edge supported, outer edge "
     "free; App. IV's peg-leg absorber cap), plate_annular_outer_supported_uniform_pressure, "
     "plate_annular_outer_fixed_uniform_pressure or plate_annular_inner_fixed_uniform_pressure"),
    ("plate_annular_uniform_pressure, retired: documented as outer edge supported, it computed the inner-supported "
     "plate"))}


_PLATE = {"radius": "diameter", "thickness": "thickness"}
# kind -> {config key: the section dimension its value replaces when given}
STANDS_IN: dict[str, dict[str, str]] = {
    "pin_double_shear": {"diameter": "diameter"},
    "bearing": {"diameter": "diameter"},
    "local_buckling": {"wall": "wall"},
    "plate_fixed_center_load": _PLATE,
    "plate_supported_center_load": _PLATE,
    "plate_fixed_center_moment_and_load": _PLATE,
    "plate_supported_center_moment_and_load": _PLATE,
    **{f"plate_annular_{edge}_uniform_pressure": {**_PLATE, "inner_radius": "inner_diameter"}
       for edge in ("outer_supported", "outer_fixed", "inner_supported", "inner_fixed")},
    "plate_supported_eccentric_and_distributed": {**_PLATE, "radius_tangential": "diameter"},
    **{kind: {"radius": "diameter"} for kind in SANDWICH_CORE},
}


def _length(x: float) -> str:
    return f"{fmt(x, 'length', 'US')} ({fmt(x, 'length', 'SI')})"


def out_of_range(check: Check, section: Section | None, material: Material) -> tuple[str, str, str] | None:
    """(key, expected, found) when a check's geometry leaves its formula's domain: a local-buckling wall of the
    tube's outside radius or more, or outside its formula's r/t range; a ring of R/c below 2; a plate outside
    its formula's range (_plate_range). A key "section.NAME" is the item section's own."""
    p = check.params
    if section is None:                            # no geometry to range: the evaluation names what is missing
        return None
    if check.kind == "local_buckling":
        r = section.outside_diameter / 2           # the section's own wall is checked where it is read
        if p["t"] is not None and p["t"] >= r:
            return "wall", f"a wall below the tube's outside radius {_length(r)}", _length(p["t"])
        own = _own_wall(p, section)
        problem = _local_range(p, own, 1 / material.value("poisson_m"))
        if problem:
            return ("wall" if p["t"] is not None else "section.wall",
                    "a wall in the range of the local-buckling formula", f"{_length(own.wall)} ({problem})")
    elif check.kind == "ring_bending":
        c = section.c()
        if p["span"] / 2 / c < stress.RING_MIN_R_OVER_C:
            expected = (f"a span of at least {2 * stress.RING_MIN_R_OVER_C:g} times the section's c {_length(c)} "
                        "(the straight-beam ring holds for R/c >= 2, R = span / 2)")
            return "span", expected, _length(p["span"])
    elif check.kind.startswith(("plate_", "sandwich_")):
        try:
            return (_sandwich_range if check.kind.startswith("sandwich_") else _plate_range)(p, section)
        except (KeyError, AttributeError, TypeError):     # a dimension missing: the evaluation names it
            return None
    return None


def read_check(node: Node, rules: Rules = RULES[DEFAULT_RULES]) -> Check:
    """A check table (CheckTable, chosen by `kind`); keys it does not give take their formula from `rules`."""
    retired = node.raw("kind", None)
    if isinstance(retired, str) and retired in RETIRED:
        raise node.error("kind", *RETIRED[retired])
    t = validate(CheckTable, node.data, node.file, node.path, where=node.path).root
    params = KINDS[t.kind][0](t, rules, node)
    replaces = {key: dim for key, dim in STANDS_IN.get(t.kind, {}).items() if node.has(key)}
    return Check(t.kind, params, node.path, t.note, replaces)

