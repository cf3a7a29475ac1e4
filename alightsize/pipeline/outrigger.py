"""The outrigger: the structure from the capsule's body to a telescoping leg's attachment when the attachment lies
outside the body (AFFDL-TR-66-33 Sec. II.D: the report's leg weights leave out this "outrigger" leg support
structure, representative only of a body whose radius reaches the attachment radius).

Idealisation: a straight tube cantilevered from the body wall at `[structure] body_radius` out to the leg's
pivot, radial and at the pivot's height, its length L = attachment radius - body radius. The leg (massless)
brings the ground force to the pivot and, through its rotational pads, to the outrigger's tip fitting: the axial
force AF1 along the leg, whose line passes through the pivot, and the side force P1 at the footpad, rho below the
pivot along the leg (App. III). At the root (Young & Budynas 2002 Table 8.1 case 1a, end load on a cantilever;
moments as vectors r x F):

- AF1's moment: |L e_r x AF1 e_leg| <= AF1 L, at any swing of the leg;
- P1's moment: |(L e_r - rho e_leg) x P1 e_p| <= P1 (L + rho), in any direction, bending and torsion together;
- the bending and torsion of a thin tube under a moment vector of magnitude M give a Tresca stress
  sqrt(sigma^2 + 4 tau^2) = M / (pi r^2 t) (sigma = M_b / (pi r^2 t), tau = T / (2 pi r^2 t)), at most M c / I,
  so the `combined` check of P1 (axial, the side force when radial) and M = AF1 L + P1 (L + rho) bounds it.

The compression P1 also loads the outrigger as a fixed-free column (effective length 2 L, Timoshenko & Gere 1961
sec. 2.1). Valid for L at least the tube's outside diameter: the beam's transverse shear (at most 2 V / A in a
thin tube) is then below its bending stress. AF1's radial component at a swing theta, AF1 sin theta, is not in
the axial term (the moment bound's P1 (L + rho) exceeds the exact P1 sqrt(L^2 + rho^2) there).
"""

from __future__ import annotations

from alightsize.checks.rules import RULES
from alightsize.common.config import Node
from alightsize.common.errors import InputError
from alightsize.loads.quasi_static import TELESCOPING
from alightsize.loads.telescoping import TelescopingLeg
from alightsize.pipeline.members import ITEM_KEYS, _ref

OUTRIGGER = "outrigger"


def outrigger_span(attachment_radius: float, body_radius: float | None) -> float | None:
    """The outrigger's length L = attachment radius - body radius (m); None without a body radius or when the
    attachment lies on the body."""
    if body_radius is None or attachment_radius <= body_radius:
        return None
    return attachment_radius - body_radius


def outrigger_arms(span: float, leg: TelescopingLeg) -> tuple[float, float]:
    """(AF1's arm L, P1's arm L + rho) of the moment bound at the outrigger's root (module docstring)."""
    return span, span + leg.length


def outrigger_item(node: Node, leg: TelescopingLeg | None, span: float | None, default_rules: str) -> dict:
    """`[members.outrigger]` as an item with its derived checks, length and tube weight; refused when the lander
    has no outrigger (no `[structure] body_radius`, or the attachment on the body)."""
    if leg is None or span is None:
        raise InputError(node.file, node.path, "an outrigger only on telescoping legs attached outside the body "
                         "(a [structure] body_radius below [legs] radius)", "no such attachment")
    node.allow((*(k for k in ITEM_KEYS if k not in ("length", "count")), "rules"))
    rules = RULES[node.string("rules", default_rules, choices=tuple(RULES))]
    section = node.table("section")
    if section.data.get("shape") != "tube":
        raise section.error("shape", "\"tube\" (the outrigger is a tube cantilevered from the body)",
                            repr(section.data.get("shape")))
    size = node.data.get("size")
    sized = isinstance(size, dict) and size.get("dimension") == "outside_diameter" and "max" in size
    od = max([section.quantity("outside_diameter", "length")]
             + ([node.table("size").quantity("max", "length")] if sized else []))
    if span < od:
        raise node.error("section", f"an outside diameter up to the outrigger's length {span:.4g} m (attachment "
                         "radius - body radius): a shorter stub is a shear lug, not the beam this check is",
                         f"{od:.4g} m")
    af1, p1 = _ref(TELESCOPING, "AF1"), _ref(TELESCOPING, "P1")
    arms = [f"{arm!r} m" for arm in outrigger_arms(span, leg)]
    bend = {"moment_force": [af1, p1], "moment_arm": arms}
    checks = [{"kind": "combined", "load": p1, **bend},
              {"kind": "column_buckling", "load": p1, "length": f"{2 * span!r} m", "formula": rules.column},
              {"kind": "local_buckling", "load": p1, **bend, "formula": rules.local}]
    item = {k: node.data[k] for k in ITEM_KEYS if k in node.data}
    return {"name": OUTRIGGER, **item, "length": f"{span!r} m", "weight": item.get("weight", {"method": "tube"}),
            "check": checks}
