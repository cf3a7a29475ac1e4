"""Members of a tripod leg derived from its geometry: each member's length (and so its weight) comes from the
hardpoints and the footpad, its loads from the strut-load extremes; the items are in the schema of
alightsize.pipeline.items, so sizing and weights treat them as any other.

`[members.NAME]` of a tripod leg (material, section, size, weight, rules, note, required_design_factor; never a
length or a count: the geometry gives them):

- `primary_strut` (inverted tripod): a tube over the pin-to-pin length Lp (hardpoint to footpad) in compression,
  as a pinned column over Lp (Johnson-Euler) and in local buckling (SP-8007).
- `primary_upper` (cantilever): the primary between its hardpoint and the knee, length a = (1 - s) L0: its axial
  force (either sense) with the knee moment (combined), a pinned column over a, local buckling under both.
- `primary_lower` (cantilever): the primary's overhang below the knee, length b = s L0: the cartridge's
  compression with the knee moment (combined), local buckling under both, and a column of effective length
  `overhang_effective_length(a, b)` under the larger compression of the primary's two parts.
- `secondary_strut`: one item per secondary (`secondary_strut_1`, `_2`), a tube over its pin-to-pin length
  l_i: compression, a pinned column over l_i, local buckling, tension.
- `end_pin`: the pins at both ends of each strut (`end_pin_primary`, `end_pin_secondary_1`, `_2`, two each): a
  rod section in double shear and in bearing on its lug (`pin`, as members.py's pins) under the strut's largest
  end force (for the cantilever's primary the resultant on its hardpoint pin or the ground force at its footpad).
- `footpad`: a plate of the leg's footpad diameter (the section gives its thickness), supported at its edge under
  the largest ground force over `load_radius` (as the telescoping `pad_plate`); or, with a `shape = "sandwich"`
  section (faces, core depth and core material), a sandwich plate under the same load: its faces' stress and
  local buckling, its core's shear at the load circle and crushing under it (alightsize.checks.sandwich).
- `primary_core`, `secondary_core`: crushable cores weighed from the leg's cells (`core_primary`,
  `core_secondary_1_compression`, ...), as `weight = { method = "crushable" }` items are.
"""

from __future__ import annotations

import copy
import json
from dataclasses import dataclass
from math import cos, isfinite, pi, sin

import numpy as np

from alightsize.checks.rules import RULES, Rules
from alightsize.common.config import Node
from alightsize.common.errors import InputError
from alightsize.common.typed import validate
from alightsize.loads.envelopes import Extreme
from alightsize.loads.quasi_static import LoadReference
from alightsize.model.materials import Material
from alightsize.pipeline.cores import CoreWeight, core_weight
from alightsize.pipeline.landings import LANDING
from alightsize.pipeline.members import Member, _pin, _plate
from alightsize_sim.tripod_leg import TripodLeg, strut_forces

INVERTED = ("primary_strut", "secondary_strut", "end_pin", "footpad", "primary_core", "secondary_core")
CANTILEVER = ("primary_upper", "primary_lower", *INVERTED[1:])
# what a tripod member table may say (the geometry gives every length and count)
TRIPOD_ITEM_KEYS = ("material", "section", "weight", "size", "note", "required_design_factor", "allow_below_one")
CORE_KEYS = ("material", "weight", "note")            # a core is weighed, not checked
FOOTPAD = "footpad"                                   # the member (and item) the landings' footpad_mass must match
TRIPOD_ENVELOPE = "landings"                          # the envelope of every landing, a tripod's member loads
ROUNDOFF = 1e-9                                       # relative: a strut force below it is round-off (landing_extremes)
# a sandwich footpad's checks (alightsize.checks.sandwich)
SANDWICH_CHECKS = ("sandwich_face_stress", "sandwich_face_buckling", "sandwich_core_shear", "sandwich_core_crushing")


@dataclass(frozen=True)
class TripodLoads:
    """Extremes of one leg's loads (magnitudes, N and N m; 0 where never loaded in that sense): the primary
    cartridge's compression, each secondary's compression and tension, the primary above the knee in compression
    and in tension (the cartridge's force for an inverted tripod), the bending moment at the knee (0 for an
    inverted tripod), the resultant on the primary's hardpoint pin, and the ground force on the footpad."""

    primary: float
    secondary_compression: tuple[float, float]
    secondary_tension: tuple[float, float]
    primary_upper_compression: float
    primary_upper_tension: float
    knee_moment: float
    primary_pin: float
    footpad: float

    @classmethod
    def stand_in(cls) -> "TripodLoads":
        """1 N (and 1 N m) everywhere: every check present, to validate member tables before any landing."""
        return cls(1.0, (1.0, 1.0), (1.0, 1.0), 1.0, 1.0, 1.0, 1.0, 1.0)

    @classmethod
    def from_landings(cls, rows) -> "TripodLoads":
        """The extremes over every landing of the stored rows' `member_loads_json`
        (alightsize.loads.histories.tripod_envelope): each strut's largest compression and tension, the largest
        knee moment, primary pin force and footpad force; 0 where never loaded so."""
        best = landing_extremes(rows)
        c, t, g = ((lambda m, sense=sense: best.get((m, sense), (0.0, ""))[0])
                   for sense in ("compression", "tension", "largest"))
        return cls(c("primary"), (c("secondary1"), c("secondary2")), (t("secondary1"), t("secondary2")),
                   c("primary_upper"), t("primary_upper"), g("knee_moment"), g("primary_pin"), g("footpad"))

    def __post_init__(self):
        values = (self.primary, *self.secondary_compression, *self.secondary_tension, self.primary_upper_compression,
                  self.primary_upper_tension, self.knee_moment, self.primary_pin, self.footpad)
        if len(self.secondary_compression) != 2 or len(self.secondary_tension) != 2:
            raise ValueError("secondary_compression, secondary_tension: expected one value per secondary (two)")
        if not all(isfinite(v) and v >= 0 for v in values):
            raise ValueError(f"tripod loads: expected finite magnitudes >= 0, got {values!r}")

    @classmethod
    def from_forces(cls, leg: TripodLeg, forces, positions=None) -> "TripodLoads":
        """The extremes over footpad forces F (N, rows) on the footpad at `positions` (rows; rest if None), by
        the leg's statics (`strut_forces`; tension positive)."""
        forces = np.atleast_2d(np.asarray(forces, float))
        where = [None] * len(forces) if positions is None else list(np.atleast_2d(positions))
        s = [strut_forces(leg, F, P) for F, P in zip(forces, where)]
        t = np.array([x.secondaries for x in s])
        c, e = np.maximum(0.0, -t.min(0)), np.maximum(0.0, t.max(0))
        return cls(max(0.0, -min(float(x.primary) for x in s)), (float(c[0]), float(c[1])),
                   (float(e[0]), float(e[1])), max(0.0, -min(float(x.primary_upper) for x in s)),
                   max(0.0, max(float(x.primary_upper) for x in s)), max(float(x.knee_moment) for x in s),
                   max(float(np.linalg.norm(x.hardpoint_forces[0])) for x in s),
                   float(np.linalg.norm(forces, axis=1).max()))


def landing_extremes(rows) -> dict[tuple[str, str], tuple[float, str]]:
    """(member, sense) -> (largest magnitude, run id of the landing that set it; the first in the rows on a tie)
    over the stored rows' `member_loads_json` (alightsize.loads.histories.tripod_envelope), sense "tension",
    "compression" or "largest". A strut force below ROUNDOFF times the largest strut force of the landings is the
    statics solve's round-off (about 1e-16 relative), not a load in that sense, and is left out."""
    best: dict[tuple[str, str], tuple[float, str]] = {}
    for r in rows:
        for d in json.loads(r.get("member_loads_json") or "[]"):
            if "largest" in d:
                senses = [("largest", d["largest"])]
            else:
                c = d["compression_N"]
                senses = [("tension", d["tension_N"]), ("compression", None if c is None else -c)]
            for sense, v in senses:
                if v is not None and v > best.get((d["member"], sense), (0.0, ""))[0]:
                    best[(d["member"], sense)] = (v, r["run_id"])
    floor = ROUNDOFF * max((v for (_, sense), (v, _) in best.items() if sense != "largest"), default=0.0)
    return {k: x for k, x in best.items() if k[1] == "largest" or x[0] > floor}


def tripod_references(rows) -> tuple[LoadReference, ...]:
    """The loads of `TripodLoads.from_landings(rows)`, each with the landing that set it (`landing_extremes`):
    one reference per stored member and sense ever loaded, envelope TRIPOD_ENVELOPE (every landing)."""
    best = landing_extremes(rows)
    return tuple(LoadReference(f"{m} {sense}", TRIPOD_ENVELOPE, m, sense, 1.0, v, Extreme(v, (), LANDING + run))
                 for (m, sense), (v, run) in best.items())


def overhang_effective_length(a: float, b: float) -> float:
    """Effective (pinned) length of a uniform column pinned at its top, held laterally at a = the hardpoint-knee
    distance below it and free at its foot b further down, under one axial compression throughout: pi / k with
    k the least root of k a (cot k a + cot k b) = 1. The overhang's base turns against the span's rotational
    stiffness E I k^2 a / (1 - k a cot k a) (far end pinned, Timoshenko & Gere 1961 sec. 1.11 and 2.1), which
    its tip's load P = E I k^2 needs as the moment P delta at the knee. Limits: a -> 0 gives 2 b (the clamped
    cantilever, K = 2), b -> 0 gives a (the pinned span). Valid for b > 0, a > 0; the upper part taken as stiff
    as the overhang (E I), conservative when it is stiffer, as an outer tube around the overhang is."""
    if not (a > 0 and b > 0):
        raise ValueError(f"overhang_effective_length: expected a, b > 0 m, got {a!r}, {b!r}")
    r = a / b
    hi = min(pi / 2, pi / r)          # f(z) = r z (cot r z + cot z) - 1 falls from r to below 0 on (0, hi)

    def f(z: float) -> float:
        return r * z * (cos(r * z) / sin(r * z) + cos(z) / sin(z)) - 1.0

    lo = 0.0
    for _ in range(200):              # bisection to the float resolution
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        lo, hi = (mid, hi) if f(mid) > 0 else (lo, mid)
    return pi * b / (0.5 * (lo + hi))


def _n(x: float) -> str:
    return f"{float(x)!r} N"


def _m(x: float) -> str:
    return f"{float(x)!r} m"


def _tube(compression: float, tension: float, rules: Rules, column: float, moment: float = 0.0,
          column_load: float | None = None) -> list[dict]:
    """A strut tube: axial stress in each sense it is loaded (combined with the moment when there is one), a pinned
    column of length `column` under `column_load` (its compression if None) and local buckling (with the moment)
    under its compression."""
    bend = {"moment": f"{float(moment)!r} N*m"} if moment > 0 else {}
    out: list[dict] = []
    if bend:
        out.append({"kind": "combined", "load": _n(max(compression, tension)), **bend})
    else:
        out += [{"kind": kind, "load": _n(p)} for kind, p in (("compression", compression), ("tension", tension))
                if p > 0]
    column_load = compression if column_load is None else column_load
    if column_load > 0:
        out.append({"kind": "column_buckling", "load": _n(column_load), "length": _m(column),
                    "formula": rules.column})
    if compression > 0 or bend:
        out.append({"kind": "local_buckling", "load": _n(compression), **bend, "formula": rules.local})
    return out


def _sandwich(load: str, member: Member, node: Node, rules: Rules) -> list[dict]:
    """A sandwich footpad's checks (SANDWICH_CHECKS) under `load` over the member's `load_radius`."""
    r0 = _plate(SANDWICH_CHECKS[0], load, member, node, rules)[0]["load_radius"]     # required as for a plate
    return [{"kind": kind, "load": load, "load_radius": r0, **({"theory": rules.plate} if kind == SANDWICH_CHECKS[0]
                                                               else {})} for kind in SANDWICH_CHECKS]


def _cores(node: Node, name: str, leg: TripodLeg, materials: dict[str, Material]) -> list[dict]:
    mat = materials.get(str(node.data.get("material")))
    if mat is None or mat.crush_strength is None or mat.stroke_fraction is None:
        raise node.error("material", "a crushable material (with crush_strength and stroke_fraction)",
                         repr(node.data.get("material")))
    weight = validate(CoreWeight, node.data.get("weight", {}), node.file, node.key("weight"))
    if name == "primary_core":
        cells = [("core_primary", leg.primary)]
    else:
        cells = [(f"core_secondary_{i + 1}_{sense}", cells[i]) for i in range(2)
                 for sense, cells in (("compression", leg.secondary_compression), ("tension", leg.secondary_tension))]
    return [{"name": n, "material": node.data["material"], **({"note": node.data["note"]} if "note" in node.data
                                                                   else {}),
             "weight": core_weight(weight, c.curve.deflection, c.curve.force, mat, node.key("weight"))}
            for n, c in cells]


def tripod_member_items(node: Node, name: str, leg: TripodLeg, loads: TripodLoads, default_rules: str,
                        materials: dict[str, Material]) -> list[dict]:
    """The items of the `[members.NAME]` table `node` of a tripod leg (module docstring), with their derived
    checks, lengths and weights."""
    allowed = CANTILEVER if leg.is_cantilever else INVERTED
    if name not in allowed:
        variant = "cantilever" if leg.is_cantilever else "inverted tripod"
        raise InputError(node.file, node.path, f"a member of the {variant} leg: " + ", ".join(allowed), repr(name))
    if name.endswith("_core"):
        node.allow(CORE_KEYS)
        return _cores(node, name, leg, materials)
    extra = {"end_pin": ("pin",), "footpad": ("load_radius",)}.get(name, ())
    node.allow((*TRIPOD_ITEM_KEYS, "rules", *extra))
    member = validate(Member, node.data, node.file, node.path)
    rules = RULES[member.rules or default_rules]
    base = {k: node.data[k] for k in TRIPOD_ITEM_KEYS if k in node.data}
    lp, l1, l2 = leg.rest_lengths
    a, b = leg.knee_offset, lp - leg.knee_offset
    tube = {"method": "tube"}
    if name == "primary_strut":
        items = [("primary_strut", lp, tube, _tube(loads.primary, 0.0, rules, lp))]
    elif name == "primary_upper":
        items = [("primary_upper", a, tube, _tube(loads.primary_upper_compression, loads.primary_upper_tension,
                                                   rules, a, loads.knee_moment))]
    elif name == "primary_lower":
        items = [("primary_lower", b, tube, _tube(loads.primary, 0.0, rules, overhang_effective_length(a, b),
                                                   loads.knee_moment,      # the whole primary buckles as one
                                                   max(loads.primary, loads.primary_upper_compression)))]
    elif name == "secondary_strut":
        items = [(f"secondary_strut_{i + 1}", li, tube, _tube(loads.secondary_compression[i],
                                                              loads.secondary_tension[i], rules, li))
                 for i, li in enumerate((l1, l2))]
    elif name == "end_pin":
        primary_end = max(loads.primary_pin, loads.footpad if leg.is_cantilever else loads.primary)
        ends = [("end_pin_primary", primary_end)] + [
            (f"end_pin_secondary_{i + 1}", max(loads.secondary_compression[i], loads.secondary_tension[i]))
            for i in range(2)]
        checks = {n: _pin([_n(p)], member, node) if p > 0 else [] for n, p in ends}
        return [{"name": n, **base, "count": 2, "check": checks[n]} for n, _ in ends]
    else:                                               # footpad
        section = node.table("section")
        if section.has("diameter"):
            raise section.error("diameter", "no diameter: the footpad's is the leg's footpad diameter",
                                repr(section.raw("diameter")))
        base["section"] = {**section.data, "diameter": _m(leg.footpad_diameter)}
        if section.raw("shape", None) == "sandwich":
            return [{"name": "footpad", **base, "weight": base.get("weight", {"method": "sandwich"}),
                     "check": _sandwich(_n(loads.footpad), member, node, rules)}]
        return [{"name": "footpad", **base, "weight": base.get("weight", {"method": "disc"}),
                 "check": _plate("plate_supported_center_load", _n(loads.footpad), member, node, rules)}]
    return [{"name": n, **base, "length": _m(length), "weight": base.get("weight", w), "check": checks}
            for n, length, w, checks in items]


def landing_tripod_items(leg: TripodLeg, members: Node, rules: str, materials: dict[str, Material],
                         rows: tuple[dict, ...]) -> list[Node]:
    """The item tables of a tripod lander's `[members.NAME]` tables (`members`, as read: a copy is consumed) under
    the load extremes of the stored landing `rows` (`TripodLoads.from_landings`)."""
    fresh = Node(members.file, members.path, copy.deepcopy(members.data))
    return tripod_items(leg, TripodLoads.from_landings(rows), fresh, rules, materials)


def tripod_items(leg: TripodLeg, loads: TripodLoads, members: Node, rules: str,
                 materials: dict[str, Material]) -> list[Node]:
    """Every `[members.NAME]` table of a tripod leg's lander file as item tables (Nodes under the member's key
    path, ready for `read_items`); `rules` is the file's rule set."""
    out = []
    for key in members.data:
        m = members.table(key)
        out += [Node(m.file, m.path, data)
                for data in tripod_member_items(m, key, leg, loads, rules, materials)]
    members.finish()
    return out
