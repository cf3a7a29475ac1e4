"""Members of a lander file and the checks derived from their role: a `[members.NAME]` table becomes an item
(the App. IV schema of alightsize.pipeline.items) whose checks, loads and lengths come from the leg.

Articulated legs: NAME is an App. III member (PU1, PL1, R123, ...), a truss tube by default (`role`):
axial stress, column buckling, local buckling under its envelope load; `role = "rod"`: tension only;
`role = "pin"`: double shear of the pin through it and bearing on its lug (`pin.lug_material`). Telescoping legs
(App. III free body): `lower_tube` and `upper_tube` (axial crush AF1 with the bending moment P1 (rho - a) at the
pads, the lower tube also as a column of the leg's length rho, or `column_length`; each tube weighs its span from
the pads, rho - a and a, unless `length` is given), `axial_cap` (fixed-edge plate under AF1), `pad_plate`
(supported plate under P3) and `swivel_pin` (the pin carrying the resultant of AF1 and P2, in shear and in
bearing on its lug).

`rules = "current"` (default) applies Johnson's parabola below the Euler transition, the SP-8007 thin-wall
knockdown, Roark's equivalent load radius and the Tresca criterion on plates; `rules = "app_iv"` the 1966
formulas (Euler only, 0.4 E t / D, (sigma_r + sigma_t)/2 against Fcy/2).
"""

from __future__ import annotations

from alightsize.checks.rules import RULES, Rules
from alightsize.common.config import Node
from alightsize.common.errors import InputError
from alightsize.loads.quasi_static import TELESCOPING
from alightsize.loads.telescoping import TelescopingLeg
from alightsize_sim.articulated_statics import MEMBERS

TELESCOPING_MEMBERS = ("lower_tube", "upper_tube", "axial_cap", "pad_plate", "swivel_pin")
ARTICULATED_ROLES = ("truss", "rod", "pin")
# what a member table may say besides its derived checks (passed on to the item)
ITEM_KEYS = ("material", "section", "length", "weight", "size", "count", "note", "required_design_factor",
             "allow_below_one")


def _si(x: float, unit: str) -> str:
    return f"{x!r} {unit}"


def _ref(env: str, member: str, sense: str = "magnitude") -> dict:
    """An envelope load; a member never loaded in that sense has no check of that sense."""
    return {"envelope": env, "member": member, "sense": sense, "optional": True}


def _tube(load: dict, rules: Rules, moment: tuple[dict, str] | None, column: str | None) -> list[dict]:
    """Axial (or combined) stress, local buckling and, with a column length, column buckling of a tube."""
    bend = {"moment_force": moment[0], "moment_arm": moment[1]} if moment else {}
    out = [{"kind": "combined", "load": load, **bend} if moment else {"kind": "compression", "load": load}]
    if column:
        out.append({"kind": "column_buckling", "load": load, "length": column, "formula": rules.column})
    out.append({"kind": "local_buckling", "load": load, **bend, "formula": rules.local})
    return out


def _plate(kind: str, load: dict | str, node: Node, rules: Rules) -> list[dict]:
    return [{"kind": kind, "load": load, "load_radius": node.raw("load_radius"), "theory": rules.plate,
             "equivalent_radius": rules.equivalent_radius}]


def _pin(loads: list[dict] | list[str], node: Node) -> list[dict]:
    """A pin of the member's rod section: double (or n-plane) shear, and bearing on its lug judged on the weaker
    of the pin's and the lug's material (Bruhn 1973 D1). `lug_material` is required: the lug is often the softer
    part (an aluminium lug on a steel pin), and the pin's own material would overstate the bearing allowable."""
    pin = node.table("pin")
    pin.allow(("lug_thickness", "lug_material", "planes"))
    t = pin.raw("lug_thickness")
    lug = pin.string("lug_material")
    planes = pin.integer("planes", 2, minimum=1)
    pin.finish()
    return [{"kind": "pin_double_shear", "loads": loads, "planes": planes},
            {"kind": "bearing", "loads": loads, "bearing_length": t, "material": lug}]


def telescoping_checks(name: str, node: Node, leg: TelescopingLeg, rules: Rules) -> list[dict]:
    """The checks of a telescoping-leg member from the App. III free body (AFFDL-TR-66-33 App. III-IV)."""
    f = {k: _ref(TELESCOPING, k) for k in ("AF1", "P1", "P2", "P3")}
    arm = _si(leg.length - leg.pad_lever, "m")          # P1 (rho - a) = w2 chi^2 / 6 at the pads (App. III)
    column = node.raw("column_length", None) or _si(leg.length, "m")
    if name == "lower_tube":
        return _tube(f["AF1"], rules, (f["P1"], arm), column)
    if name == "upper_tube":
        return _tube(f["AF1"], rules, (f["P1"], arm), None)
    if name == "axial_cap":
        return _plate("plate_fixed_center_load", f["AF1"], node, rules)
    if name == "pad_plate":
        return _plate("plate_supported_center_load", f["P3"], node, rules)
    return _pin([f["AF1"], f["P2"]], node)


def articulated_checks(name: str, node: Node, envelope: str, rules: Rules) -> list[dict]:
    """The checks of an App. III truss member under its envelope extremes (AFFDL-TR-66-33 App. III-IV)."""
    role = node.string("role", "truss", choices=ARTICULATED_ROLES)
    tension = {"kind": "tension", "load": _ref(envelope, name, "tension")}
    if role == "rod":
        return [tension]
    if role == "pin":
        return _pin([_ref(envelope, name)], node)
    length = node.raw("length", None)
    if length is None:
        raise node.error("length", "the member's column length (articulated truss lengths are not derived from "
                         "the leg geometry)", "nothing")
    return _tube(_ref(envelope, name, "compression"), rules, None, length) + [tension]


def member_item(node: Node, name: str, leg: TelescopingLeg | None, envelope: str, default_rules: str) -> dict:
    """A `[members.NAME]` table as an item table with its derived checks (`rules` and role read here); `leg`: the
    telescoping leg's free body, None for an articulated leg."""
    kind = "telescoping" if leg is not None else "articulated"
    allowed = TELESCOPING_MEMBERS if kind == "telescoping" else MEMBERS
    if name not in allowed:
        raise InputError(node.file, node.path, f"a member of the {kind} leg: " + ", ".join(allowed), repr(name))
    node.allow((*ITEM_KEYS, "rules", "role", "load_radius", "pin", "column_length"))
    rules = RULES[node.string("rules", default_rules, choices=tuple(RULES))]
    checks = (telescoping_checks(name, node, leg, rules) if leg is not None
              else articulated_checks(name, node, envelope, rules))
    item = {k: node.data[k] for k in ITEM_KEYS if k in node.data}
    if leg is not None and name.endswith("_tube") and "length" not in item:   # each tube's span from the pads
        item["length"] = _si(leg.length - leg.pad_lever if name == "lower_tube" else leg.pad_lever, "m")
    if "weight" not in item and "section" in node.data:
        shape = node.data["section"].get("shape") if isinstance(node.data["section"], dict) else None
        default = {"tube": {"method": "tube"}, "plate": {"method": "disc"}}.get(shape) if isinstance(shape, str) \
            else None        # any other shape: the section reader names it
        if default and (shape != "tube" or "length" in item):
            item["weight"] = default
    return {"name": name, **item, "check": checks}
