"""The outrigger: the structure from the capsule's body to a leg's attachments when they lie outside the body
(AFFDL-TR-66-33 Sec. II.D: the report's leg weights leave out this "outrigger" leg support structure,
representative only of a body whose radius reaches the attachment radius).

Idealisation, either leg kind: a straight tube cantilevered from the body wall at `[structure] body_radius`,
radial, out to the leg's attachment fitting, its length L. The leg (massless) brings the ground force to the
fitting; at the root the moment vector is bounded by force x arm terms, each |r x F| <= |r| |F| (moments as
vectors r x F, Young & Budynas 2002 Table 8.1 case 1a, end load on a cantilever), so the sum of the terms
bounds bending and torsion together:

- telescoping (the tube at the pivot's height, L = attachment radius - body radius): the axial force AF1 along
  the leg, its line through the pivot, |L e_r x AF1 e_leg| <= AF1 L at any swing; the side force P1 at the
  footpad, rho below the pivot along the leg (App. III), |(L e_r - rho e_leg) x P1 e_p| <= P1 (L + rho) in any
  direction. M = AF1 L + P1 (L + rho); the axial term is P1 (the side force when radial; AF1's radial component
  at a swing theta, AF1 sin theta, is left out: the bound's P1 (L + rho) exceeds the exact P1 sqrt(L^2 + rho^2)
  there).
- articulated (App. III configuration): the lower and upper parallelogram hinges and the upper cell's inboard
  pivot share one fitting; the tube runs at the lower hinge's height (the leg's origin, `[legs] radius`) out to
  the outermost attachment, L = its radius - body radius. The leg being massless, the forces on the fitting are
  equivalent to the ground force F at the footpad, so the root moment is exactly (L0 e1 + S') x F, L0 = radius -
  body radius <= L, S' the footpad from the lower hinge (eq. 38-40): S' = AU e_psi + (AO, 0, -AE) + t, the peg
  leg's part t = (c cos beta, c sin beta, -(AS sin a + AL cos a)), c = AS - AS cos a + AL sin a, of length
  |(AS, 0) + (-AS cos a + AL sin a, AS sin a + AL cos a)| <= |AS| + hypot(AS, AL) (the second vector a rotation of
  (-AS, AL)). So |S'| <= reach = AU + hypot(AO, AE) + |AS| + hypot(AS, AL) at any (alpha, beta, psi), and
  M = |F| (L0 + reach); the axial term is |F|. The ground force, not App. III's attachment forces: those (Q1,
  Q2, RA, RB along and across the links at the hinges, AF1 at the cell's pivot) sum to F but leave the moment
  about the leg's S3 axis unbalanced (the report's pinned trusses split Q equally), so their moments would miss
  the couple the hinges carry.

The thin tube under bending M_b and torsion T has the Tresca stress sqrt(sigma^2 + 4 tau^2) = M / (pi r^2 t)
(sigma = M_b / (pi r^2 t), tau = T / (2 pi r^2 t)), at most M c / I, so the `combined` check of the axial term
with M bounds it; local buckling takes the same. The axial term also loads the tube as a fixed-free column
(effective length 2 L, Timoshenko & Gere 1961 sec. 2.1). Valid for L at least the tube's outside diameter: the
beam's transverse shear (at most 2 V / A in a thin tube) is then below its bending stress.
"""

from __future__ import annotations

from dataclasses import dataclass
from math import hypot, sin
from typing import Annotated, Any

from pydantic import BaseModel, ConfigDict, model_validator

from alightsize_sim.articulated_kinematics import ArticulatedGeometry

from alightsize.checks.rules import RULES, RuleSet
from alightsize.common.config import Node
from alightsize.common.errors import InputError
from alightsize.common.typed import Quantity, Table, refuse, validate
from alightsize.loads.quasi_static import TELESCOPING
from alightsize.loads.telescoping import TelescopingLeg
from alightsize.pipeline.items import Size
from alightsize.pipeline.members import ITEM_KEYS, _ref

OUTRIGGER = "outrigger"


@dataclass(frozen=True)
class Outrigger:
    """The tube's length (m), the load reference bounding its axial force and the (force reference, arm m) terms
    whose sum bounds its root moment (module docstring)."""

    span: float
    axial: dict
    moment: tuple[tuple[dict, float], ...]


def outrigger_span(attachment_radius: float, body_radius: float | None) -> float | None:
    """The length L = attachment radius - body radius (m); None without a body radius or when the attachment lies
    on the body."""
    if body_radius is None or attachment_radius <= body_radius:
        return None
    return attachment_radius - body_radius


def telescoping_outrigger(span: float, leg: TelescopingLeg) -> Outrigger:
    """A telescoping leg's outrigger: AF1 at arm L, P1 at arm L + rho, axial P1 (App. III free body)."""
    af1, p1 = _ref(TELESCOPING, "AF1"), _ref(TELESCOPING, "P1")
    return Outrigger(span, p1, ((af1, span), (p1, span + leg.length)))


def articulated_reach(g: ArticulatedGeometry) -> float:
    """A bound on |S'|, the footpad's distance from the lower hinge (eq. 38-40), at any (alpha, beta, psi), m."""
    return g.AU + hypot(g.AO, g.AE) + abs(g.AS) + hypot(g.AS, g.AL)


def articulated_outrigger(node: Node, g: ArticulatedGeometry, radius: float, body_radius: float | None,
                          envelope: str) -> Outrigger | None:
    """An articulated leg's outrigger to the fitting of its hinges (lower at `radius`, upper -AD sin PHI further
    out) and the upper cell's pivot (AA further out), loaded by the ground force F of `envelope`; None without a
    body radius or with every attachment on the body. `node`: [structure], to refuse a body wall between them."""
    if body_radius is None:
        return None
    radii = {"lower hinge": radius, "upper hinge": radius - g.AD * sin(g.PHI), "upper cell pivot": radius + g.AA}
    outer = max(radii.values())
    if outer <= body_radius:
        return None
    if radius <= body_radius:
        raise node.error("body_radius", "a body radius below the lower hinge ([legs] radius, the outrigger's tip) "
                         "or beyond every attachment (" + ", ".join(f"{k} at {v:.4g} m" for k, v in radii.items())
                         + ")", f"{body_radius:.4g} m")
    f = {"envelope": envelope, "member": "F", "sense": "magnitude"}
    return Outrigger(outer - body_radius, f, ((f, radius - body_radius + articulated_reach(g)),))


class _Tube(BaseModel):
    """The outrigger's view of its section, a tube by its outside diameter (the item's reader reads every key)."""

    model_config = ConfigDict(extra="ignore", strict=True, frozen=True)

    shape: Any = None
    outside_diameter: Annotated[float, Quantity("length")]

    @model_validator(mode="after")
    def _tube(self):
        if self.shape != "tube":
            raise refuse("\"tube\" (the outrigger is a tube cantilevered from the body)", repr(self.shape), "shape")
        return self


class OutriggerMember(Table):
    """`[members.outrigger]`: its rules, its section and size typed; the item's keys (ITEM_KEYS but length and
    count, which the outrigger gives) passed on as written to the item's reader."""

    rules: RuleSet | None = None
    material: Any = None
    section: _Tube
    weight: Any = None
    size: Size | None = None
    note: Any = None
    required_design_factor: Any = None
    allow_below_one: Any = None

    def largest_diameter(self) -> float:
        """The tube's outside diameter, m: the section's, or the largest its sizing reaches."""
        s = self.size
        if s is None or s.dimension != "outside_diameter":
            return self.section.outside_diameter
        return max(self.section.outside_diameter, *s.gauges, *(() if s.max is None else (s.max,)))


def outrigger_item(node: Node, rig: Outrigger | None, default_rules: str) -> dict:
    """`[members.outrigger]` as an item with its derived checks, length and tube weight; refused when the lander
    has no outrigger (no `[structure] body_radius`, or the attachments on the body)."""
    if rig is None:
        raise InputError(node.file, node.path, "an outrigger only on legs attached outside the body (a [structure] "
                         "body_radius below the legs' attachment radius)", "no such attachment")
    m = validate(OutriggerMember, node.data, node.file, node.path)
    rules = RULES[m.rules or default_rules]
    od = m.largest_diameter()
    if rig.span < od:
        raise node.error("section", f"an outside diameter up to the outrigger's length {rig.span:.4g} m (attachment "
                         "radius - body radius): a shorter stub is a shear lug, not the beam this check is",
                         f"{od:.4g} m")
    bend = {"moment_force": [f for f, _ in rig.moment], "moment_arm": [f"{arm!r} m" for _, arm in rig.moment]}
    checks = [{"kind": "combined", "load": rig.axial, **bend},
              {"kind": "column_buckling", "load": rig.axial, "length": f"{2 * rig.span!r} m", "formula": rules.column},
              {"kind": "local_buckling", "load": rig.axial, **bend, "formula": rules.local}]
    item = {k: node.data[k] for k in ITEM_KEYS if k in node.data}
    return {"name": OUTRIGGER, **item, "length": f"{rig.span!r} m", "weight": item.get("weight", {"method": "tube"}),
            "check": checks}
