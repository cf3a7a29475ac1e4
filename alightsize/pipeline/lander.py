"""A lander file: one TOML from which every analysis derives (the landing scene, the App. III envelopes, the
members' checks, the landing cases of the requirements). Reading it only reads and validates.

```
[lander]        name, title, gravity ("earth" | "moon" | "mars" | an acceleration), rules, materials
[capsule] [cells.NAME] [legs] [terrain] [controls] [initial]     as in a scene (docs/reference/scene.md)
[structure]     telescoping: bearing_length, friction, body_radius (outrigger); articulated: truss, psi_final, grid,
                configuration, combined, body_radius (outrigger); tripod: none
[members.NAME]  material, section, role, size, weight, ... (alightsize.pipeline.members, .outrigger; tripod legs:
                .tripod_members, loaded by the landings' strut-load extremes)
[[item]]        App. IV items with their checks written out (overrides; the 1966 examples)
[requirements]  required_design_factor (allow_below_one), decimals, weight_goal, criteria, envelope, monte_carlo
[report]        units = "US" | "SI"
```
"""

from __future__ import annotations

import copy
import itertools
from dataclasses import dataclass
from functools import partial
from math import degrees, radians
from pathlib import Path
from typing import Annotated, Any, Literal

import numpy as np
from pydantic import ValidationInfo, model_validator

from alightsize_sim.articulated_kinematics import footpad as articulated_footpad
from alightsize_sim.articulated_leg import ArticulatedLeg
from alightsize_sim.landing import G0
from alightsize_sim.rigid_body import quat_matrix
from alightsize_sim.telescoping_leg import TelescopingLeg as SimTelescopingLeg
from alightsize_sim.tripod_leg import TripodLeg
from alightsize_sim.crush_curve import CrushCurve

from alightsize.common.config import SEED_MAX, Node, load_toml
from alightsize.common.errors import InputError
from alightsize.common.typed import Integer, Number, Quantity, Table, refuse, validate
from alightsize.landings.criteria import CriteriaTable
from alightsize.landings.dispersions import Dispersion, SpeedRegion
from alightsize.landings.study import Run, Study, _sampled
from alightsize.loads.config import Combined, Configuration, GridTable, LoadsConfig, Name, check_combined
from alightsize.loads.envelopes import LegCase, default_grid
from alightsize.loads.interface import landing_loads
from alightsize.loads.quasi_static import TELESCOPING, LoadReference, check_references
from alightsize.loads.telescoping import TelescopingLeg
from alightsize.model.envelope import Envelope
from alightsize.model.materials import library, material_paths
from alightsize.model.gravity import Gravity
from alightsize.model.legs import TrussTable
from alightsize.model.scene_config import (ArticulatedLegs, Cell, SceneConfig, SceneDocument, SceneFile,
                                           TelescopingLegs, TripodLegs, build_scene, lander_scene, read_scene)
from alightsize.model.soils import find_soil
from alightsize.pipeline.cores import CoreWeight, core_weight, crush_stroke
from alightsize.pipeline.config import DesignSpec, UnitSystem, read_design, read_items
from alightsize.pipeline.landings import LandingSpec
from alightsize.checks.rules import DEFAULT_RULES, RuleSet
from alightsize.pipeline.items import Item, RequiredFactor, references
from alightsize.pipeline.members import member_item
from alightsize.pipeline.outrigger import (OUTRIGGER, Outrigger, articulated_outrigger, outrigger_item,
                                           outrigger_span, telescoping_outrigger)
from alightsize.pipeline.tripod_members import (FOOTPAD, TripodLoads, landing_tripod_items, tripod_items,
                                                tripod_references)

SCENE_TABLES = ("capsule", "cells", "legs", "terrain", "initial", "controls", "output")
ALL_CONFIGURATIONS = "all"           # the combined envelope of App. III cell variants when none is named
DEFAULT_SAMPLES = 100                # Monte Carlo landings: about a minute on 2 cores (docs/notes)
MAX_SCATTER = 0.15                   # cell_scatter: a normal force factor 1 +- 0.15 is 0 only 6.7 sd out (1e-11 of
                                     # draws: 3e-5 in 100,000 samples of 20 cells), so every drawn cell can crush


class MonteCarlo(Table):
    samples: Annotated[int, Integer(0, 100_000)] = DEFAULT_SAMPLES
    seed: Annotated[int, Integer(0, SEED_MAX)] = 1
    cell_scatter: Annotated[float, Number("nonnegative", MAX_SCATTER)] = 0.0
    note: str = ""


class TerrainRequirement(Table):
    """`[requirements.terrain]`: ground beyond the envelope's plane the lander must land on. Each key given adds
    the envelope's corners on its largest descent speed again on that ground (`terrain_cases`)."""

    rock_height: Annotated[float, Quantity("length")] | None = None     # a hemispherical rock under a footpad
    hole_depth: Annotated[float, Quantity("length")] | None = None      # a footpad into a hole
    soil: str | None = None                                             # a soil preset or file
    note: str = ""


class Requirements(RequiredFactor):
    """`[requirements]`: the design factor members must reach, the landing criteria, the impact envelope and the
    terrain."""

    decimals: Annotated[int, Integer(0, 12)] | None = None
    weight_goal: Annotated[float, Number()] | None = None
    criteria: CriteriaTable = CriteriaTable()
    envelope: Envelope
    monte_carlo: MonteCarlo = MonteCarlo()
    terrain: TerrainRequirement = TerrainRequirement()
    note: str = ""

    @model_validator(mode="after")
    def _goal(self):
        if self.weight_goal is not None and not 0 < self.weight_goal < 1:
            raise refuse("the leg system's weight as a fraction of the capsule, in (0, 1)", repr(self.weight_goal),
                         "weight_goal")
        return self

    @property
    def required(self) -> float:
        return 1.25 if self.required_design_factor is None else self.required_design_factor


class LanderHead(Table):
    name: Name | None = None
    title: str | None = None
    gravity: Gravity = G0
    rules: RuleSet = DEFAULT_RULES
    materials: list[str] = []
    note: str = ""


class ReportTable(Table):
    units: UnitSystem = "SI"


class LanderFile(Table):
    """A lander file's own tables, typed; the scene tables are the scene model's (SceneFile), [structure],
    [members] and [[item]] are read with the design config's readers, [synthesis] by alightsize.synthesis."""

    lander: LanderHead
    requirements: Requirements
    report: ReportTable = ReportTable()
    structure: dict = {}
    members: dict = {}
    item: list = []
    synthesis: dict = {}
    capsule: Any = None
    cells: Any = None
    legs: Any = None
    terrain: Any = None
    initial: Any = None
    controls: Any = None
    output: Any = None


@dataclass(frozen=True)
class Lander:
    """A lander as read: its design (`spec`, what `alightsize.design` runs), its nominal landing scene (and the
    scene document its landing cases vary) and its requirements."""

    spec: DesignSpec
    scene: SceneConfig
    requirements: Requirements
    document: SceneDocument
    cells: dict[str, Cell]            # the [cells.NAME] tables as read (a curve as written, before any factor)

    @property
    def study(self) -> Study:
        landings = self.spec.landings
        assert landings is not None                 # `read_lander` gives a lander's design its landing cases
        return landings.study


def _q(x: float, unit: str) -> str:
    return f"{x:.12g} {unit}"


def _place(x: float) -> str:
    """A computed position, m, as a quantity: below a micrometre (round-off of a footpad on an axis) it reads 0 m,
    as the parser refuses a smaller magnitude; a micrometre is far below any rock or step."""
    return _q(x if abs(x) >= 1e-6 else 0.0, "m")


def landing_cases(scene: SceneDocument, name: str, req: Requirements, legs: int, base: dict | None = None) -> Study:
    """The envelope's corners (every vertex of its speed region, `Envelope.corners`: a box's four; each other
    range at both ends, a slope or inclination magnitude and the roll rate at either sign, a leg leading or two legs
    straddling the velocity), `[requirements.terrain]`'s cases at the corners on the largest descent speed, and
    `samples` seeded Monte Carlo landings drawn uniformly over the envelope (the speed region jointly, heading,
    roll and, with cell_scatter, every cell's crushing force as well); every
    run lands the lander file's scene with the overrides `base` (a design variant) under its own."""
    base = dict(base or {})
    e, mc = req.envelope, req.monte_carlo
    speeds = e.corners()
    axes: dict[str, list] = {"initial.roll": ["0.0 deg", _q(180.0 / legs, "deg")]}
    signed = (("terrain.slope", tuple(map(degrees, e.slope)), "deg"),
              ("initial.inclination", tuple(map(degrees, e.inclination)), "deg"),
              ("initial.rates[2]", (-e.roll_rate, e.roll_rate), "rad/s"))
    fixed = dict(base)
    for key, (lo, hi), unit in signed:
        if lo != hi:
            axes[key] = [_q(lo, unit), _q(hi, unit)]
        elif lo != 0:
            fixed[key] = _q(lo, unit)
    if e.friction is not None:
        fixed["terrain.mu_static"] = e.friction[1]
        if e.friction[0] < e.friction[1]:
            axes["terrain.mu_dynamic"] = list(e.friction)
        else:                                       # one friction: the Monte Carlo lands at it too
            fixed["terrain.mu_dynamic"] = e.friction[0]
    combos = [({"initial.velocity[2]": _q(-v, "m/s"), "initial.velocity[1]": _q(h, "m/s"), **dict(zip(axes, c))},
               top) for ((h, v), top), *c in itertools.product(speeds, *axes.values())]
    width = len(str(len(combos)))
    points = [(f"corner-{n + 1:0{width}d}", "lander", {**fixed, **c}, c, None) for n, (c, _) in enumerate(combos)]
    points += terrain_cases(scene, req.terrain, [p for p, (_, top) in zip(points, combos) if top])
    disp: list[Dispersion | SpeedRegion] = [
        SpeedRegion("initial.velocity[2]", "initial.velocity[1]", e.upper(), e.vertical_speed[0]),
        Dispersion("initial.heading", "uniform", tuple(map(degrees, e.heading)), "deg", False),
            Dispersion("initial.roll", "uniform", (0.0, 360.0 / legs), "deg", False)]
    disp += [Dispersion(key, "uniform", (lo, hi), unit, False) for key, (lo, hi), unit in signed if lo != hi]
    if e.friction is not None and e.friction[0] < e.friction[1]:
        disp.append(Dispersion("terrain.mu_dynamic", "uniform", e.friction, "", False))
    if mc.cell_scatter > 0:
        disp.append(Dispersion("legs.cell_factors", "normal", (1.0, mc.cell_scatter), "", True))
    runs = [Run(rid, skey, scene, over, params, ref) for rid, skey, over, params, ref in points]
    if mc.samples:
        nominal: list[tuple] = [("mc", "lander", dict(fixed), {}, None)]
        runs += [Run(rid, skey, scene, over, params, ref)
                 for rid, skey, over, params, ref in _sampled(nominal, disp, mc.samples, mc.seed, {"lander": scene})]
    plot = ("initial.velocity[1]", "initial.velocity[2]")
    title = f"Landing cases of {name}: {len(combos)} envelope corners, {mc.samples} Monte Carlo"
    return Study(scene.path, name, title, tuple(runs), req.criteria.criteria(), ("initial.velocity[1]", *axes),
                 "initial.velocity[2]", False, mc.seed, plot)


def rest_footpad(leg: SimTelescopingLeg | ArticulatedLeg | TripodLeg) -> np.ndarray:
    """A leg's footpad at rest (hanging straight; the parallelogram at its initial psi, the peg leg straight down;
    a tripod's as given), m in principal axes from the centre of gravity."""
    if isinstance(leg, TripodLeg):
        return np.asarray(leg.footpad, float)
    if isinstance(leg, ArticulatedLeg):
        s = np.array(articulated_footpad(leg.geometry, 0.0, 0.0, leg.psi0), float)
    elif isinstance(leg, SimTelescopingLeg):
        s = np.array([0.0, 0.0, -leg.rho])
    else:
        raise ValueError(f"no rest footpad for a leg of kind {type(leg).__name__}")
    return leg.attach + leg.to_body @ s


def terrain_cases(scene: SceneDocument, terrain: TerrainRequirement, corners: list[tuple]) -> list[tuple]:
    """The landing cases of `[requirements.terrain]`: each of `corners` (run id, scene key, overrides, parameters,
    reference) again with, for each key given, a hemispherical rock of radius `rock_height` centred under leg 1's
    footpad ("corner-rock-NN"); leg 1's footpad over a hole `hole_depth` deep, a down-step whose edge runs across
    leg 1's azimuth midway between its footpad and the nearest other footpad's reach along it ("corner-hole-NN");
    the terrain's soil set to `soil` ("corner-soil-NN"). Footpads are placed as the simulator starts a landing:
    the centre of gravity over the terrain origin, the scene's initial attitude (roll, inclination, slope), legs
    at rest. Rocks and steps the scene already has are kept."""
    ter = scene.data.get("terrain", {})
    out = []
    for rid, skey, over, params, ref in corners:
        n = rid.removeprefix("corner-")
        cfg = read_scene(scene, over)
        R = quat_matrix(cfg.scene.q0)
        feet = np.array([(R @ rest_footpad(leg))[:2] for leg in cfg.scene.legs])
        extra: list[tuple[str, str, object]] = []
        if terrain.rock_height is not None:
            x, y = feet[0]
            rock = {"shape": "hemisphere", "x": _place(x), "y": _place(y), "radius": _q(terrain.rock_height, "m"),
                    "note": "under leg 1 ([requirements.terrain] rock_height)"}
            extra.append(("rock", "terrain.rocks", [*ter.get("rocks", []), rock]))
        if terrain.hole_depth is not None:
            e = feet[0] / np.linalg.norm(feet[0])
            edge = 0.5 * (feet[0] @ e + np.max(feet[1:] @ e)) * e                 # a file has 2 legs or more
            step = {"x": _place(edge[0]), "y": _place(edge[1]),
                    "direction": _q(degrees(np.arctan2(-e[0], e[1])), "deg"),     # leg 1 on its left
                    "height": _q(-terrain.hole_depth, "m"),
                    "note": "leg 1 into a hole ([requirements.terrain] hole_depth)"}
            extra.append(("hole", "terrain.steps", [*ter.get("steps", []), step]))
        if terrain.soil is not None:
            extra.append(("soil", "terrain.soil", terrain.soil))
        out += [(f"corner-{kind}-{n}", skey, {**over, key: value}, {**params, key: value}, ref)
                for kind, key, value in extra]
    return out


def _crush(curve) -> float:
    return crush_stroke(curve.deflection, curve.force)[0]


class TelescopingStructure(Table):
    """[structure] of telescoping legs: what the App. III free body needs beyond the legs and cells."""

    bearing_length: Annotated[float, Quantity("length")]
    friction: Annotated[float, Number("any")] = 0.05
    body_radius: Annotated[float, Quantity("length")] | None = None     # outrigger out to [legs] radius
    note: str = ""

    @model_validator(mode="after")
    def _friction(self):
        if not 0 <= self.friction < 1:
            raise refuse("a friction coefficient in [0, 1)", f"{self.friction}", "friction")
        return self


class ArticulatedStructure(Table):
    """[structure] of articulated legs: the truss and the psi swept for the App. III envelopes of the lander's
    own cells (configuration `name`), other cell variants and their combinations."""

    truss: TrussTable
    psi_final: Annotated[float, Quantity("angle", "any")]
    grid: GridTable = GridTable()
    configuration: list[Configuration] = []
    combined: list[Combined] = []
    name: Name | None = None
    body_radius: Annotated[float, Quantity("length")] | None = None     # outrigger out to the hinges
    note: str = ""

    @model_validator(mode="after")
    def _cases(self, info: ValidationInfo):
        assert info.context is not None             # `_loads_config` passes psi_initial and name
        p0, p1 = info.context["psi_initial"], self.psi_final
        if not (radians(-90) < p0 < p1 < radians(90)):
            raise refuse("-90 deg < [legs] psi_initial < psi_final < 90 deg",
                          f"{degrees(p0):g} and {degrees(p1):g} deg", "psi_final")
        names = [c.name for c in self.configuration] + [self.name or info.context["name"]]
        dup = next((n for n in names if names.count(n) > 1), None)
        if dup:
            raise refuse("configuration names unique (with the lander's own, `name`)", f"{dup!r} twice",
                         "configuration")
        check_combined(names, self.combined)
        return self


def _loads_config(path: Path, name: str, structure: dict, scene: SceneFile, legs: tuple,
                  units: str) -> tuple[LoadsConfig | None, tuple[str, ...]]:
    """The App. III loads config of the lander's own legs and cells (and the envelopes its members use); none for
    tripod legs, whose members take their loads from the landings alone."""
    file = str(path)
    if isinstance(scene.legs, TripodLegs):
        if structure:
            raise InputError(file, f"structure.{next(iter(structure))}", "no [structure] for tripod legs (their "
                             "geometry gives every length; the members' loads come from the landings)",
                             repr(structure[next(iter(structure))]))
        return None, ()
    if isinstance(scene.legs, TelescopingLegs):
        s = validate(TelescopingStructure, structure, file, "structure")
        leg = legs[0]
        if not leg.pads:
            raise InputError(file, "legs.pad_angles", "rotational pads on the telescoping leg (App. III free body)",
                             "none")
        if not leg.pad_lever > 0:
            raise InputError(file, "legs.pad_lever", "a pad lever above 0 (the pads react the leg's moment about "
                             "its pivot: App. III free body)", "0 m")
        tele = TelescopingLeg(_crush(leg.axial.curve), _crush(leg.pads[0].curve), leg.pad_lever, leg.rho,
                              s.bearing_length, s.friction)
        return LoadsConfig(path, f"{name} telescoping leg (App. III free body)", units, default_grid(), (), (), tele), \
            (TELESCOPING,)
    own = scene.legs
    s = validate(ArticulatedStructure, structure, file, "structure", psi_initial=own.psi_initial, name=name)
    upper, lower = scene.cells[own.upper], scene.cells[own.lower]
    cases = [c.case(own.geometry, s.truss) for c in s.configuration]
    cases.append(LegCase(s.name or name, own.geometry.geometry(own.length_scale), s.truss.truss(),
                         CrushCurve(upper.deflection, upper.force), CrushCurve(lower.deflection, lower.force),
                         own.psi_initial, s.psi_final))
    combined = [(c.name, tuple(c.configurations)) for c in s.combined]
    if len(cases) > 1 and not combined:
        combined.append((ALL_CONFIGURATIONS, tuple(c.name for c in cases)))
    cfg = LoadsConfig(path, f"{name} articulated leg (App. III envelopes)", units, s.grid.grid(), tuple(cases),
                      tuple(combined), None)
    return cfg, (cases[-1].name, *(c[0] for c in combined))


def _outrigger(path: Path, name: str, structure: dict, scene: SceneFile, loads: LoadsConfig,
               envelope: str) -> Outrigger | None:
    """The outrigger of a lander with `[structure] body_radius` (None: no body radius or the attachments on it);
    an articulated leg's is loaded by the ground force of `envelope`."""
    file = str(path)
    if isinstance(scene.legs, TelescopingLegs):
        body = validate(TelescopingStructure, structure, file, "structure").body_radius
        span = outrigger_span(scene.legs.radius, body)
        assert loads.telescoping is not None          # a telescoping lander's loads are its App. III free body
        return None if span is None else telescoping_outrigger(span, loads.telescoping)
    own = scene.legs
    assert isinstance(own, ArticulatedLegs)           # tripod legs have no outrigger (read_lander)
    s = validate(ArticulatedStructure, structure, file, "structure", psi_initial=own.psi_initial, name=name)
    return articulated_outrigger(Node(file, "structure", structure), own.geometry.geometry(own.length_scale),
                                 own.radius, s.body_radius, envelope)


class CrushableWeight(CoreWeight):
    """`[[item]] weight = {method = "crushable", cell = NAME}`: the item weighed as the crushable core of the cell
    `[cells.NAME]` (the prism `core_weight` gives)."""

    method: Literal["crushable"]
    cell: str

    @model_validator(mode="after")
    def _cell(self, info: ValidationInfo):
        assert info.context is not None             # `_crushable` passes the file's cells
        if self.cell not in info.context["cells"]:
            raise refuse("the name of a [cells.NAME] table", repr(self.cell), "cell")
        return self


def _crushable(node: Node, scene: SceneFile, mats: dict) -> Node:
    """An item weighed as a cell's crushable core (`CrushableWeight`) as the prism it is: area = crushing force /
    crush strength, length = stroke / usable stroke fraction (App. V); any other item as it is."""
    w = node.data.get("weight")
    if not (isinstance(w, dict) and w.get("method") == "crushable"):
        return node
    core = validate(CrushableWeight, w, node.file, f"{node.path}.weight", cells=scene.cells)
    mat = mats.get(str(node.data.get("material")))
    if mat is None or mat.crush_strength is None or mat.stroke_fraction is None:
        raise node.error("material", "a crushable material (with crush_strength and stroke_fraction)",
                         repr(node.data.get("material")))
    cell = scene.cells[core.cell]
    prism = core_weight(core, cell.deflection, cell.force, mat, f"{node.path}.weight")
    return Node(node.file, node.path, {**node.data, "weight": prism})


def _tripod_landing_items(leg: TripodLeg, members: Node, rules: str, mats: dict, required: float,
                          others: tuple[Item, ...], rows: tuple[dict, ...]
                          ) -> tuple[tuple[Item, ...], tuple[LoadReference, ...]]:
    """A tripod lander's items under the strut-load extremes of its landing `rows`: its members
    (`landing_tripod_items`), then its [[item]]s `others` as read; and those extremes with their landings."""
    nodes = landing_tripod_items(leg, members, rules, mats, rows)
    return (*read_items(tuple(nodes), mats, required, members, rules), *others), tripod_references(rows)


def read_lander(path: str | Path, overrides: dict | None = None, root: Node | None = None) -> Lander:
    """Read and validate a lander file (or its TOML `root`, already loaded), with `overrides` (dotted key path ->
    TOML value, e.g. {"legs.radius": "2 m"}) applied first; any problem is an InputError naming file, key path,
    what was expected and what was found. Nothing is computed (`alightsize.design` runs the analyses)."""
    path = Path(path)
    root = load_toml(path) if root is None else root
    for key, value in (overrides or {}).items():
        root.set_path(key, value)
    scene_over = {k: v for k, v in (overrides or {}).items() if k.split(".")[0] in SCENE_TABLES}
    lander = validate(LanderFile, root.data, str(path))
    head, req, units = lander.lander, lander.requirements, lander.report.units
    name = head.name if head.name is not None else path.stem
    title = head.title if head.title is not None else name
    rules = head.rules
    extra = material_paths(head.materials, path.parent, str(path), "lander.materials")
    document = lander_scene(path, root.data, req.envelope.nominal_velocity())
    scene_file = validate(SceneFile, document.data, str(path), cells_used=document.cells_used)
    scene = build_scene(path, scene_file)
    for t in ("lander", "requirements", "report", "structure", "synthesis", *SCENE_TABLES):
        root.raw(t, None)                         # read above (alightsize.synthesis reads [synthesis])
    loads, envelopes = _loads_config(path, name, lander.structure, scene_file, scene.scene.legs, units)
    mats = library(extra)
    members = root.table("members", optional=True)
    rig = _outrigger(path, name, lander.structure, scene_file, loads, envelopes[-1]) if loads is not None else None
    if rig is not None and OUTRIGGER not in (members.data if members else {}):
        raise root.error(f"members.{OUTRIGGER}", f"the outrigger from the body ([structure] body_radius) to the "
                         f"legs' attachment, {rig.span:.4g} m out: a member to check and weigh", "none")
    nodes: list[Node] = []
    tripod: tuple[TripodLeg, Node] | None = None
    leg = scene.scene.legs[0]
    if isinstance(leg, TripodLeg) and members:     # a tripod lander's legs are alike but for their azimuth
        tripod = (leg, Node(members.file, members.path, copy.deepcopy(members.data)))
        nodes += tripod_items(leg, TripodLoads.stand_in(), members, rules, mats)
    elif members:
        assert loads is not None                    # telescoping and articulated legs have their App. III config
        for key in members.data:
            m = members.table(key)
            data = (outrigger_item(m, rig, rules) if key == OUTRIGGER
                    else member_item(m, key, loads.telescoping, envelopes[-1], rules))
            nodes.append(Node(root.file, m.path, data))
        members.finish()
    n_members = len(nodes)
    nodes += [_crushable(n, scene_file, mats) for n in root.tables("item", optional=True, label="name")]
    if not nodes:
        raise root.error("members", "at least one [members.NAME] table or [[item]]", "neither")
    items = read_items(tuple(nodes), mats, req.required, root, rules)
    root.finish()
    check_references(references(items), loads, str(path))
    if req.terrain.soil is not None:
        find_soil(req.terrain.soil, path.parent, str(path), "requirements.terrain.soil")
        if not (scene_file.legs.footpad_mass > 0 and scene_file.legs.footpad_diameter > 0):
            raise InputError(str(path), "requirements.terrain.soil", "footpads that sink into it ([legs] "
                             "footpad_mass and footpad_diameter)", "massless footpads or no footpad_diameter")
    study = landing_cases(document, name, req, len(scene.scene.legs), scene_over)
    if loads is None:
        member_loads = landing_loads(tripod=True)
    else:
        member_loads = landing_loads(truss=None if loads.telescoping else loads.cases[0].truss,
                                     telescoping=loads.telescoping)
    landings = LandingSpec(study, envelopes, "criteria", member_loads)
    derived = (partial(_tripod_landing_items, *tripod, rules, mats, req.required, items[n_members:]) if tripod
               else None)
    # the footpad mass the sized footpad must match; none with massless footpads, which a tripod has only where
    # the landings hold its footpads (a footpad that never moves plays no part through its mass)
    m = scene_file.legs.footpad_mass
    pad = m if tripod and FOOTPAD in tripod[1].data and m > 0 else None
    spec = DesignSpec(path, name, title, scene.scene.mass, len(scene.scene.legs), units, req.required, req.decimals,
                      mats, items, loads, landings, req.weight_goal, rules, derived, pad)
    return Lander(spec, scene, req, document, scene_file.cells)


def read_input(path: str | Path) -> DesignSpec:
    """A lander file or a design config, as read (`alightsize design` and `audit` take either)."""
    root = load_toml(path)
    return read_lander(path, root=root).spec if "lander" in root.data else read_design(path, root)
