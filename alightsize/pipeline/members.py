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

from typing import Annotated, Any, Literal

from alightsize.checks.rules import RULES, RuleSet, Rules
from alightsize.common.config import Node
from alightsize.common.errors import InputError
from alightsize.common.typed import Integer, Quantity, Table, validate
from alightsize.loads.quasi_static import TELESCOPING
from alightsize.loads.telescoping import TelescopingLeg
from alightsize_sim.articulated_statics import MEMBERS

TELESCOPING_MEMBERS = ("lower_tube", "upper_tube", "axial_cap", "pad_plate", "swivel_pin")
# what a member table may say besides its derived checks (passed on to the item)
ITEM_KEYS = ("material", "section", "length", "weight", "size", "count", "note", "required_design_factor",
             "allow_below_one")
# the member's own keys, by member: each is used there (a key that would be ignored is refused)
OWN_KEYS = {"lower_tube": ("rules", "column_length"), "upper_tube": ("rules",), "axial_cap": ("rules", "load_radius"),
            "pad_plate": ("rules", "load_radius"), "swivel_pin": ("rules", "pin")}
ARTICULATED_KEYS = {"truss": ("rules", "role"), "rod": ("rules", "role"), "pin": ("rules", "role", "pin")}


class Pin(Table):
    lug_thickness: Annotated[float, Quantity("length")]
    lug_material: str
    planes: Annotated[int, Integer(1)] = 2


class Member(Table):
    """A `[members.NAME]` table: its own keys typed; the item's keys (ITEM_KEYS) are read by read_item."""

    rules: RuleSet | None = None
    role: Literal["truss", "rod", "pin"] = "truss"
    load_radius: Annotated[float, Quantity("length")] | None = None
    pin: Pin | None = None
    column_length: Annotated[float, Quantity("length")] | None = None
    material: Any = None                # the item's keys, as written
    section: Any = None
    length: Any = None
    weight: Any = None
    size: Any = None
    count: Any = None
    note: Any = None
    required_design_factor: Any = None
    allow_below_one: Any = None


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


def _plate(kind: str, load: dict | str, member: Member, node: Node, rules: Rules) -> list[dict]:
    if member.load_radius is None:
        raise node.error("load_radius", "this key to be present (the radius the load bears on)", "nothing")
    return [{"kind": kind, "load": load, "load_radius": _si(member.load_radius, "m"), "theory": rules.plate,
             "equivalent_radius": rules.equivalent_radius}]


def _pin(loads: list[dict] | list[str], member: Member, node: Node) -> list[dict]:
    """A pin of the member's rod section: double (or n-plane) shear, and bearing on its lug judged on the weaker
    of the pin's and the lug's material (Bruhn 1973 D1). `lug_material` is required: the lug is often the softer
    part (an aluminium lug on a steel pin), and the pin's own material would overstate the bearing allowable."""
    pin = member.pin
    if pin is None:
        raise node.error("pin", "this key to be present (lug_thickness, lug_material)", "nothing")
    return [{"kind": "pin_double_shear", "loads": loads, "planes": pin.planes},
            {"kind": "bearing", "loads": loads, "bearing_length": _si(pin.lug_thickness, "m"),
             "material": pin.lug_material}]


def telescoping_checks(name: str, member: Member, node: Node, leg: TelescopingLeg, rules: Rules) -> list[dict]:
    """The checks of a telescoping-leg member from the App. III free body (AFFDL-TR-66-33 App. III-IV)."""
    f = {k: _ref(TELESCOPING, k) for k in ("AF1", "P1", "P2", "P3")}
    arm = _si(leg.length - leg.pad_lever, "m")          # P1 (rho - a) = w2 chi^2 / 6 at the pads (App. III)
    column = _si(member.column_length or leg.length, "m")
    if name == "lower_tube":
        return _tube(f["AF1"], rules, (f["P1"], arm), column)
    if name == "upper_tube":
        return _tube(f["AF1"], rules, (f["P1"], arm), None)
    if name == "axial_cap":
        return _plate("plate_fixed_center_load", f["AF1"], member, node, rules)
    if name == "pad_plate":
        return _plate("plate_supported_center_load", f["P3"], member, node, rules)
    return _pin([f["AF1"], f["P2"]], member, node)


def articulated_checks(name: str, member: Member, node: Node, envelope: str, rules: Rules) -> list[dict]:
    """The checks of an App. III truss member under its envelope extremes (AFFDL-TR-66-33 App. III-IV)."""
    tension = {"kind": "tension", "load": _ref(envelope, name, "tension")}
    if member.role == "rod":
        return [tension]
    if member.role == "pin":
        return _pin([_ref(envelope, name)], member, node)
    length = node.data.get("length")
    if length is None:
        raise node.error("length", "the member's column length (articulated truss lengths are not derived from "
                         "the leg geometry)", "nothing")
    return _tube(_ref(envelope, name, "compression"), rules, None, length) + [tension]


def member_item(node: Node, name: str, leg: TelescopingLeg | None, envelope: str, default_rules: str) -> dict:
    """A `[members.NAME]` table (read as `Member`) as an item table with the checks derived from its role and the
    leg; `leg`: the telescoping leg's free body, None for an articulated leg."""
    kind = "telescoping" if leg is not None else "articulated"
    allowed = TELESCOPING_MEMBERS if kind == "telescoping" else MEMBERS
    if name not in allowed:
        raise InputError(node.file, node.path, f"a member of the {kind} leg: " + ", ".join(allowed), repr(name))
    member = validate(Member, node.data, node.file, node.path)
    own = OWN_KEYS[name] if leg is not None else ARTICULATED_KEYS[member.role]
    unused = next((k for k in node.data if k not in ITEM_KEYS and k not in own), None)
    if unused is not None:            # a key of another member (a typo is refused by Member, naming the keys)
        raise node.error(unused, f"the keys of a {name} member (" + ", ".join((*ITEM_KEYS, *own)) + ")",
                         f"{unused!r}, which it does not use" + ("" if leg is not None else f" as a {member.role}"))
    rules = RULES[member.rules or default_rules]
    checks = (telescoping_checks(name, member, node, leg, rules) if leg is not None
              else articulated_checks(name, member, node, envelope, rules))
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
