"""Scene configs for one landing (`alightsize simulate`): TOML with units, parsed to SI at the boundary.

Frames follow AFFDL-TR-66-33 Sec. V.B: chi, geometric body axes (3 = roll axis, up); kappa, vertical
(3 up); epsilon, terrain (3 normal, eq. 1: a rotation by the slope gamma about the 1 axis). The capsule's
attitude is roll, yaw, pitch (3-2-1 about chi-3, chi-2, chi-1, eq. 2) from kappa, or an inclination from
the vertical toward an azimuth; the initial velocity (V1-V3) is in kappa and the body rates in chi, as in
Appendix VIII. Principal axes come from the eigen-decomposition of the inertia tensor (eq. 1 ff.).
"""

from __future__ import annotations

import copy
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any, Literal

import numpy as np
from pydantic import PlainValidator, ValidationInfo, field_validator, model_validator
from pydantic_core import PydanticCustomError

from alightsize_sim.crush_cell import CellModel
from alightsize_sim.landing import G0, HELD_FRICTION, Controls, Scene
from alightsize_sim.landing_kernel import GRAZE_SPEED
from alightsize_sim.rigid_body import matrix_quat
from alightsize_sim.articulated_leg import ArticulatedLeg
from alightsize_sim.telescoping_leg import TelescopingLeg
from alightsize_sim.tripod_leg import TripodLeg, tripod_from_params
from alightsize_sim.terrain import Box, HeightField, Hemisphere, Step, Terrain

from alightsize.common.config import Node, _describe, is_file, load_toml
from alightsize.common.errors import InputError, warn_input
from alightsize.common.typed import Integer, Tagged, Number, Quantities, Quantity, Table, quantity, refuse, validate
from alightsize.model.envelope import Envelope
from alightsize.model.gravity import Gravity
from alightsize.model.legs import CurveTable, GeometryTable
from alightsize.model.soils import find_soil


@dataclass(frozen=True)
class SceneConfig:
    path: Path
    name: str
    title: str
    scene: Scene
    controls: Controls
    to_geometric: np.ndarray          # principal -> geometric body axes
    terrain_from_vertical: np.ndarray  # kappa -> epsilon (eq. 1)
    output_interval: float | None
    srs_damping: float
    cell_names: tuple[tuple[str, ...], ...]


def rot(axis: int, angle: float) -> np.ndarray:
    """Rotation matrix about a coordinate axis (0, 1, 2) by angle (rad), active."""
    c, s = np.cos(angle), np.sin(angle)
    m = np.eye(3)
    i, j = [(1, 2), (2, 0), (0, 1)][axis]
    m[i, i], m[i, j], m[j, i], m[j, j] = c, -s, s, c
    return m


def principal_axes(inertia: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(principal moments, principal -> geometric matrix): eigenvectors assigned to the geometric axis each
    lies closest to, signed to point along it, so a diagonal tensor gives the identity."""
    moments, vecs = np.linalg.eigh(inertia)
    cols = np.zeros((3, 3))
    out = np.zeros(3)
    taken = set()
    for k in np.argsort(-np.abs(vecs).max(axis=0)):                  # most clear-cut eigenvector first
        axis = max((a for a in range(3) if a not in taken), key=lambda a: abs(vecs[a, k]))
        taken.add(axis)
        cols[:, axis] = vecs[:, k] * np.sign(vecs[axis, k] or 1.0)
        out[axis] = moments[k]
    if np.linalg.det(cols) < 0:
        cols[:, 0] = -cols[:, 0]
    return out, cols


def _inclination_attitude(roll: float, theta: float, azimuth: float) -> tuple[float, float]:
    """(yaw, pitch) that tilt the roll axis by theta toward kappa azimuth `azimuth` at a given roll: chi-3 in
    kappa = (sR sP + cR sY cP, -cR sP + sR sY cP, cY cP) (eq. 2) set to (s cos az, s sin az, cos theta)."""
    s = np.sin(theta)
    sp = s * np.sin(roll - azimuth)
    pitch = np.arcsin(np.clip(sp, -1, 1))
    yaw = np.arctan2(s * np.cos(roll - azimuth), np.cos(theta))
    return float(yaw), float(pitch)




Length = Annotated[float, Quantity("length")]
LengthSigned = Annotated[float, Quantity("length", "any")]
Angle = Annotated[float, Quantity("angle", "any")]
Time = Annotated[float, Quantity("time")]


@dataclass(frozen=True)
class SceneDocument:
    """A scene as read from its file(s): the TOML of its `scene.base` chain merged, or a lander file's nominal
    landing; picklable, so a landing task validates it with its own overrides without reading a file."""

    path: Path
    data: dict
    cells_used: tuple[str, ...] = ()     # cells a lander file's own tables name (its crushable items, its synthesis)


class SceneHead(Table):
    name: str | None = None
    title: str | None = None
    gravity: Gravity = G0
    base: str | None = None          # merged away by `scene_document`


def _inertia(value: Any) -> np.ndarray:
    """Three principal moments or a symmetric 3x3 tensor about the CG (geometric axes), kg m^2."""
    def one(v, key, positive):
        try:
            return quantity(v, "inertia", "positive" if positive else "any")
        except PydanticCustomError as exc:
            raise refuse(exc.context["expected"], _describe(v), key) from None
    if isinstance(value, list) and len(value) == 3 and not any(isinstance(r, list) for r in value):
        return np.diag([one(v, f"[{i}]", True) for i, v in enumerate(value)])
    if isinstance(value, list) and len(value) == 3 and all(isinstance(r, list) and len(r) == 3 for r in value):
        tensor = np.array([[one(v, f"[{i}][{j}]", i == j) for j, v in enumerate(row)] for i, row in enumerate(value)])
        if not np.allclose(tensor, tensor.T, rtol=1e-9, atol=0):
            raise refuse("a symmetric tensor", "I_ij != I_ji")
        return tensor
    raise refuse("three principal moments or a 3x3 tensor about the CG (geometric axes)", repr(value))


class Capsule(Table):
    weight: Annotated[float, Quantity("force")] | None = None
    mass: Annotated[float, Quantity("mass")] | None = None
    inertia: Annotated[np.ndarray, PlainValidator(_inertia)]
    cg: Annotated[tuple[float, ...], Quantities("length", count=3)] = (0.0, 0.0, 0.0)
    bottom: Length | None = None
    note: str = ""

    @model_validator(mode="after")
    def _mass(self):
        if (self.weight is None) == (self.mass is None):
            raise refuse("exactly one of weight (force) or mass", "neither" if self.mass is None else "both", "weight")
        return self


class Cell(CurveTable):
    unloading_rate: Annotated[float, Quantity("spring_rate")]
    damping: Annotated[float, Quantity("damping", "any")] = 0.0
    yield_force: Annotated[float, Quantity("force")] | None = None

    @model_validator(mode="after")
    def _damping(self):
        if self.damping < 0:
            raise refuse("a damping coefficient >= 0", f"{self.damping}", "damping")
        return self

    def model(self, factor: float = 1.0) -> CellModel:
        return CellModel(self.curve(), self.unloading_rate, self.damping, factor, self.yield_force)


FOOTPAD_MASS_MIN = 0.01     # kg: measured on configuration 5's footpad scene, 0.01 kg lands in 90k steps, 1 g does not


def _factors(value: Any) -> tuple[tuple[float, ...], ...]:
    ok = isinstance(value, list) and all(isinstance(r, list) and all(
        isinstance(x, (int, float)) and not isinstance(x, bool) and x > 0 for x in r) for r in value)
    if not ok:
        raise refuse("arrays (one per leg) of positive force factors", repr(value))
    return tuple(tuple(float(x) for x in r) for r in value)


class Legs(Table):
    """A pattern of identical legs around the roll axis: count, radius, height, first azimuth."""

    count: Annotated[int, Integer(2)]
    radius: Length
    height: LengthSigned
    first_azimuth: Angle = 0.0
    cell_factors: Annotated[tuple, PlainValidator(_factors)] | None = None
    footpad_mass: Annotated[float, Quantity("mass", "any")] = 0.0
    footpad_band: Annotated[float, Quantity("velocity")] = Scene.footpad_band
    footpad_diameter: Length = 0.0
    note: str = ""

    def _check(self, n_cell: int, what: str):
        if not (self.footpad_mass == 0.0 or FOOTPAD_MASS_MIN <= self.footpad_mass):
            raise refuse(f"0 (massless footpads) or a mass of {FOOTPAD_MASS_MIN:g} kg or more (a lighter footpad "
                         "rings on its leg faster than any step can follow)", f"{self.footpad_mass:g} kg",
                         "footpad_mass")
        f = self.cell_factors
        if f is not None and (len(f) != self.count or any(len(r) != n_cell for r in f)):
            raise refuse(f"{self.count} arrays (one per leg) of {n_cell} positive force factors ({what})", repr(f),
                         "cell_factors")
        return self

    def factors(self, n_cell: int) -> tuple[tuple[float, ...], ...]:
        return self.cell_factors or tuple((1.0,) * n_cell for _ in range(self.count))

    def attachments(self) -> list[tuple[float, np.ndarray]]:
        """(azimuth, attachment point in chi) of each leg."""
        out = []
        for i in range(self.count):
            az = self.first_azimuth + 2 * np.pi * i / self.count
            out.append((az, np.array([self.radius * np.cos(az), self.radius * np.sin(az), self.height])))
        return out


class TelescopingLegs(Legs):
    kind: Literal["telescoping"] = "telescoping"
    length: Length
    pad_lever: LengthSigned = 0.0
    pad_angles: Annotated[tuple[float, ...], Quantities("angle")] = ()
    axial: str
    pads: str = ""
    small_angle: bool = False

    @model_validator(mode="after")
    def _lever(self):
        if not 0 <= self.pad_lever < self.length:
            raise refuse(f"a pad lever from 0 to less than the leg ({self.length:.4g} m)", f"{self.pad_lever:.4g} m",
                         "pad_lever")
        return self._check(1 + len(self.pad_angles), "axial, then each pad")


class ArticulatedLegs(Legs):
    """Articulated legs (Sec. V.F): the leg origin (lower inboard parallelogram pivot) at radius and height, S1
    outward along the azimuth, S3 along the roll axis; the geometry of Fig. 22-25 and the initial psi."""

    kind: Literal["articulated"]
    geometry: GeometryTable
    length_scale: Annotated[float, Number()] = 1.0
    psi_initial: Angle
    upper: str
    lower: str

    @model_validator(mode="after")
    def _psi(self):
        if not -np.pi / 2 < self.psi_initial < np.pi / 2:
            raise refuse("an angle between -90 and 90 deg", f"{np.degrees(self.psi_initial):.4g} deg", "psi_initial")
        return self._check(2, "upper, lower")


class TerrainStep(Table):
    x: LengthSigned
    y: LengthSigned
    direction: Angle
    height: LengthSigned
    note: str = ""


class HemisphereRock(Table):
    shape: Literal["hemisphere"]
    x: LengthSigned
    y: LengthSigned
    radius: Length
    note: str = ""


class BoxRock(Table):
    shape: Literal["box"]
    x: LengthSigned
    y: LengthSigned
    length: Length
    width: Length
    height: Length
    yaw: Angle = 0.0
    note: str = ""


class HeightFieldTable(Table):
    file: str
    spacing: Annotated[tuple[float, ...], Quantities("length", "positive", count=2)]
    origin: Annotated[tuple[float, ...], Quantities("length", count=2)] = (0.0, 0.0)
    note: str = ""


if TYPE_CHECKING:        # a discriminated union pydantic builds at run time; mypy sees the plain union
    Rock = HemisphereRock | BoxRock
else:
    Rock = Tagged("shape", None, HemisphereRock, BoxRock)


class TerrainTable(Table):
    slope: Angle = 0.0
    mu_static: Annotated[float, Number("any")] = 1.5e6
    mu_dynamic: Annotated[float, Number("any")] = 1.0e6
    steps: list[TerrainStep] = []
    rocks: list[Rock] = []
    height_field: HeightFieldTable | None = None
    soil: str | None = None
    note: str = ""

    @model_validator(mode="after")
    def _friction(self):
        if self.mu_dynamic < 0:
            raise refuse("a friction coefficient >= 0 (0: frictionless)", f"{self.mu_dynamic}", "mu_dynamic")
        if self.mu_dynamic > self.mu_static:
            raise refuse(f"a dynamic coefficient <= the static one ({self.mu_static})", f"{self.mu_dynamic}",
                         "mu_dynamic")
        if not -np.pi / 2 < self.slope < np.pi / 2:
            raise refuse("a slope between -90 and 90 deg", f"{np.degrees(self.slope):.4g} deg", "slope")
        return self


class Initial(Table):
    velocity: Annotated[tuple[float, ...], Quantities("velocity", count=3)]
    heading: Angle | None = None
    roll: Angle = 0.0
    yaw: Angle | None = None
    pitch: Angle | None = None
    inclination: Angle | None = None
    inclination_azimuth: Angle | None = None
    rates: Annotated[tuple[float, ...], Quantities("angular_velocity", count=3)] = (0.0, 0.0, 0.0)
    note: str = ""

    @field_validator("velocity", mode="wrap")
    @classmethod
    def _upward(cls, value: Any, handler, info: ValidationInfo):
        si = handler(value)
        assert info.context is not None             # `validate` passes the file
        if si[2] > 0:                                   # legal (a rebound, a hop), but more likely a sign slip
            warn_input(info.context["file"], "initial.velocity[2]", f"an upward initial velocity, V3 = {value[2]} "
                       "(kappa-3 is up, a descent is negative): the capsule rises before it lands; simulated as given")
        return si

    @model_validator(mode="after")
    def _attitude(self):
        if self.inclination is not None and (self.yaw is not None or self.pitch is not None):
            raise refuse("either inclination or yaw/pitch", "both", "inclination")
        return self


def _energy_from(value: Any) -> float | None:
    if value is False:
        return None
    return quantity(value, "time", "any")


_D = Controls()


class ControlsTable(Table):
    t_final: Time = _D.t_final
    rtol: Annotated[float, Number()] = _D.rtol
    atol: Annotated[float, Number()] = _D.atol
    fixed_step: Time | None = None
    max_step: Time = _D.max_step
    event_tol: Time = _D.event_tol
    tip_angle: Annotated[float, Quantity("angle")] = _D.tip_angle
    taus: Annotated[float, Number("any")] = 0.0
    stop_on_bottoming: bool = True
    energy_criterion_from: Annotated[float | None, PlainValidator(_energy_from)] = 0.05
    closed_form_flight: bool = True
    note: str = ""

    @model_validator(mode="after")
    def _ranges(self):
        if not 0 < self.tip_angle <= np.pi:
            raise refuse("an angle in (0, 180] deg", f"{np.degrees(self.tip_angle):.4g} deg", "tip_angle")
        if self.taus < 0:
            raise refuse("a number of periods >= 0", f"{self.taus}", "taus")
        if self.rtol >= 1:
            raise refuse("a relative tolerance below 1", f"{self.rtol}", "rtol")
        if self.event_tol > _D.contact_band / GRAZE_SPEED:
            raise refuse(f"a time of at most {_D.contact_band / GRAZE_SPEED:g} s (the grazing band "
                         f"{_D.contact_band:g} m at {GRAZE_SPEED:g} m/s)", f"{self.event_tol:g} s", "event_tol")
        return self


class OutputTable(Table):
    interval: Time | None = None
    srs_damping: Annotated[float, Number()] = 0.05

    @model_validator(mode="after")
    def _damping(self):
        if not 0 < self.srs_damping < 1:
            raise refuse("a damping ratio in (0, 1)", f"{self.srs_damping}", "srs_damping")
        return self


TRIPOD_COUNT = (3, 8)       # legs of a tripod gear


class TripodLegs(Legs):
    """Tripod legs (inverted tripod or cantilever): the primary hardpoint at radius and height, the footpad at rest
    at footpad_radius and footpad_height, the secondary hardpoints at secondary_radius and secondary_height,
    +-secondary_half_angle about the leg's azimuth (geometric axes); the secondaries meet the primary at the
    footpad (secondary_attach 0) or secondary_attach up it from the footpad (a cantilever)."""

    kind: Literal["tripod"]
    count: Annotated[int, Integer(*TRIPOD_COUNT)] = 4
    azimuths: Annotated[tuple[float, ...], Quantities("angle", minimum=TRIPOD_COUNT[0])] | None = None
    footpad_radius: Length
    footpad_height: LengthSigned
    secondary_radius: Length
    secondary_height: LengthSigned
    secondary_half_angle: Angle
    secondary_attach: Annotated[float, Quantity("length", "nonnegative")] = 0.0
    primary: str
    secondary_compression: str
    secondary_tension: str

    @model_validator(mode="before")
    @classmethod
    def _count(cls, data: Any) -> Any:
        """Without a count, the legs are as many as their azimuths."""
        if isinstance(data, dict) and isinstance(data.get("azimuths"), list) and "count" not in data:
            return {**data, "count": len(data["azimuths"])}
        return data

    @model_validator(mode="after")
    def _shape(self):
        if self.azimuths is not None and self.count != len(self.azimuths):
            raise refuse(f"as many legs as azimuths ({len(self.azimuths)}; give one of count and azimuths)",
                         f"count = {self.count}", "count")
        if self.azimuths is not None and len(self.azimuths) > TRIPOD_COUNT[1]:
            raise refuse(f"{TRIPOD_COUNT[0]} to {TRIPOD_COUNT[1]} angles", f"{len(self.azimuths)}", "azimuths")
        if not 0 < self.secondary_half_angle < np.pi:
            raise refuse("an angle between 0 and 180 deg", f"{np.degrees(self.secondary_half_angle):.4g} deg",
                         "secondary_half_angle")
        if not self.footpad_height < self.height:
            raise refuse(f"a height below the primary hardpoint's ({self.height:.4g} m)",
                         f"{self.footpad_height:.4g} m", "footpad_height")
        if not self.footpad_diameter > 0:
            raise refuse("the footpads' diameter (> 0)", "none given", "footpad_diameter")
        return self._check(5, "primary, then each secondary's compression and tension")

    def attachments(self) -> list[tuple[float, np.ndarray]]:
        if self.azimuths is None:
            return super().attachments()
        return [(az, np.array([self.radius * np.cos(az), self.radius * np.sin(az), self.height]))
                for az in self.azimuths]


if TYPE_CHECKING:        # as Rock
    AnyLegs = TelescopingLegs | ArticulatedLegs | TripodLegs
else:
    AnyLegs = Tagged("kind", "telescoping", TelescopingLegs, ArticulatedLegs, TripodLegs)


class SceneFile(Table):
    """A scene file (docs/reference/scene.md): one landing."""

    scene: SceneHead = SceneHead()
    capsule: Capsule
    cells: dict[str, Cell]
    legs: AnyLegs
    terrain: TerrainTable = TerrainTable()
    initial: Initial
    controls: ControlsTable = ControlsTable()
    output: OutputTable = OutputTable()

    @model_validator(mode="after")
    def _references(self, info: ValidationInfo):
        legs = self.legs
        names = ("upper", "lower") if isinstance(legs, ArticulatedLegs) else \
            ("primary", "secondary_compression", "secondary_tension") if isinstance(legs, TripodLegs) else \
            ("axial", "pads") if legs.pad_angles else ("axial",)
        for key in names:
            name = getattr(legs, key)
            if key == "pads" and not name:
                raise refuse("this key to be present", "nothing", "legs.pads")
            if name not in self.cells:
                raise refuse("the name of a [cells.NAME] table (" + ", ".join(sorted(self.cells)) + ")",
                             repr(name), "legs." + key)
        named = {getattr(legs, key) for key in names}
        for name in sorted(self.cells):      # a table no leg names would be read and ignored (a misspelt override)
            if name not in named and name not in (info.context or {}).get("cells_used", ()):
                raise refuse("a cell a leg names (" + ", ".join(sorted(named)) + ")", "a cell nothing uses",
                             "cells." + name)
        slips = min(self.terrain.mu_static, self.terrain.mu_dynamic) < HELD_FRICTION or self.terrain.soil is not None
        if isinstance(legs, TripodLegs) and slips and not legs.footpad_mass > 0:
            raise refuse("footpads with mass for tripod legs on ground they can slip on (their massless slide does "
                         "not converge with the tolerance: docs/simulator.md#tripod-legs)", "0 (massless footpads)",
                         "legs.footpad_mass")
        if self.terrain.soil is not None:
            if not legs.footpad_mass > 0:
                raise refuse("footpads with mass to sink into it ([legs] footpad_mass > 0)", "massless footpads",
                             "terrain.soil")
            if not legs.footpad_diameter > 0:
                raise refuse("the footpads' bearing size ([legs] footpad_diameter)", "none given", "terrain.soil")
        return self


MAX_BASES = 8


def _merge(base: dict, over: dict) -> dict:
    """Tables of `over` merged key by key into those of `base`; any other value replaces."""
    out = dict(base)
    for k, v in over.items():
        out[k] = _merge(out[k], v) if isinstance(v, dict) and isinstance(out.get(k), dict) else v
    return out


# tables of a lander file (alightsize.pipeline.lander) that do not describe the landing itself
LANDER_ONLY = ("lander", "structure", "members", "item", "requirements", "report", "synthesis")



def lander_scene(path: Path, data: dict, velocity: tuple[float, float, float] | None) -> SceneDocument:
    """A lander file's nominal landing: its scene tables, [lander] name, title and gravity as its [scene], and,
    without an [initial] table, `velocity` (m/s, kappa: the envelope's largest speeds)."""
    head = data["lander"] if isinstance(data.get("lander"), dict) else {}
    scene = {k: v for k, v in data.items() if k not in LANDER_ONLY}
    scene["scene"] = {k: head[k] for k in ("name", "title", "gravity") if k in head}
    if "initial" not in scene and velocity is not None:
        scene["initial"] = {"velocity": [f"{v!r} m/s" for v in velocity]}
    return SceneDocument(path, scene, _lander_cells(data))


def _lander_cells(data: dict) -> tuple[str, ...]:
    """The cells a lander file's own tables name: `[[item]] weight = {method = "crushable", cell = NAME}` and the
    [synthesis.free] keys `cells.NAME.KEY` (their readers check them)."""
    items = data.get("item")
    weights = [i.get("weight") for i in items if isinstance(i, dict)] if isinstance(items, list) else []
    named = [w.get("cell") for w in weights if isinstance(w, dict) and w.get("method") == "crushable"]
    synthesis = data.get("synthesis")
    free = synthesis.get("free") if isinstance(synthesis, dict) else None
    if isinstance(free, dict):
        named += [k.split(".")[1] for k in free if k.startswith("cells.") and k.count(".") >= 2]
    return tuple(sorted({n for n in named if isinstance(n, str)}))


def scene_document(path: Path, depth: int = 0) -> SceneDocument:
    """The scene TOML with its `scene.base` chain (a scene it varies, path relative to it) merged under it; a
    lander file gives its nominal landing (alightsize.pipeline.lander.read_lander)."""
    root = load_toml(path)
    if "lander" in root.data:
        env = root.table("requirements").table("envelope")
        return lander_scene(path, root.data, validate(Envelope, env.data, env.file, env.path).nominal_velocity())
    head = root.data.get("scene")
    if not (isinstance(head, dict) and "base" in head):
        return SceneDocument(path, root.data)
    base = head["base"]
    base_path = path.parent / base if isinstance(base, str) else None
    if base_path is None or not is_file(base_path):
        raise root.error("scene.base", "the path of a scene TOML (relative to this one)", repr(base))
    if depth >= MAX_BASES:
        raise root.error("scene.base", f"at most {MAX_BASES} nested bases", "a longer chain (a cycle?)")
    base_data = scene_document(base_path, depth + 1).data
    data = _merge(base_data, root.data)
    inherited = {k: v for k, v in (base_data.get("scene") or {}).items() if k == "gravity"}
    data["scene"] = inherited | {k: v for k, v in head.items() if k != "base"}   # name and title are not inherited
    return SceneDocument(path, data)


def read_scene(source: str | Path | SceneDocument, overrides: dict[str, object] | None = None) -> SceneConfig:
    """Read and validate a scene config (a file, or a scene already read), with `overrides` (dotted key path ->
    TOML value, e.g. {"terrain.slope": "-20 deg"}) applied first; problems are InputErrors naming file and key
    path. A scene may vary another (`[scene] base = "other.toml"`): its tables are merged key by key over the
    base's."""
    doc = source if isinstance(source, SceneDocument) else scene_document(Path(source))
    data = doc.data
    if overrides:
        data = copy.deepcopy(data)
        root = Node(doc.path, "", data)
        for key, value in overrides.items():
            root.set_path(key, value)
    return build_scene(doc.path, validate(SceneFile, data, str(doc.path), cells_used=doc.cells_used))


def build_scene(path: Path, f: SceneFile) -> SceneConfig:
    """The landing a validated scene file describes, in SI: principal axes, the legs placed and turned into
    them, the terrain and the initial state in the frames of Sec. V.B."""
    file = str(path)
    cap = f.capsule
    mass = cap.weight / G0 if cap.weight is not None else cap.mass
    assert mass is not None                     # Capsule._mass: exactly one of weight and mass
    moments, to_geo = principal_axes(cap.inertia)
    if not np.all(moments > 0):
        raise InputError(file, "capsule.inertia", "a positive definite tensor", f"principal moments {moments}")
    cg = np.array(cap.cg)
    legs, names = _legs(f.legs, f.cells, to_geo, cg, file)
    ter = f.terrain
    features = Terrain(
        tuple(Step(s.x, s.y, float(np.degrees(s.direction)), s.height) for s in ter.steps),
        tuple(Hemisphere(r.x, r.y, r.radius) for r in ter.rocks if isinstance(r, HemisphereRock)),
        tuple(Box(r.x, r.y, r.length, r.width, r.height, float(np.degrees(r.yaw))) for r in ter.rocks
              if isinstance(r, BoxRock)),
        _height_field(ter.height_field, path))
    soil = None if ter.soil is None else find_soil(ter.soil, path.parent, file, "terrain.soil")
    lepk = rot(0, ter.slope)            # kappa -> epsilon (eq. 1, LEPK): gravity (0, g sin, -g cos) (eq. 4-5)

    ini = f.initial
    vel = np.array(ini.velocity)
    if ini.heading is not None:                         # the horizontal velocity turned from kappa-2 toward kappa-1
        v_h = float(np.hypot(vel[0], vel[1]))
        vel = np.array([v_h * np.sin(ini.heading), v_h * np.cos(ini.heading), vel[2]])
    if ini.inclination is not None:
        default_az = float(np.arctan2(vel[1], vel[0])) if np.hypot(vel[0], vel[1]) > 0 else 0.0
        az = ini.inclination_azimuth if ini.inclination_azimuth is not None else default_az
        yaw, pitch = _inclination_attitude(ini.roll, ini.inclination, az)
    else:
        yaw, pitch = ini.yaw or 0.0, ini.pitch or 0.0
    lkx = rot(2, ini.roll) @ rot(1, yaw) @ rot(0, pitch)    # chi -> kappa (eq. 2, FUNEV LKX)
    q0 = matrix_quat(lepk @ lkx @ to_geo)

    c = f.controls
    period = float(np.pi * np.sqrt(mass / legs[0].cells[0].k))    # TAU = pi sqrt(M / SLOPE(1)) (App. VII,
                                                                  # telescoping subroutine FORCE)
    controls = Controls(t_final=c.t_final, rtol=c.rtol, atol=c.atol, fixed_step=c.fixed_step, max_step=c.max_step,
                        event_tol=c.event_tol, tip_angle=c.tip_angle, taus=c.taus, period=period,
                        stop_on_bottoming=c.stop_on_bottoming, energy_check_from=c.energy_criterion_from,
                        closed_form_flight=c.closed_form_flight)
    g = f.scene.gravity
    body = np.zeros((0, 3)) if cap.bottom is None else (to_geo.T @ (np.array([0.0, 0.0, -cap.bottom]) - cg))[None, :]
    lg = f.legs
    scene = Scene(mass, moments, tuple(legs), lepk @ np.array([0.0, 0.0, -g]), lepk @ vel, q0,
                  to_geo.T @ np.array(ini.rates), ter.mu_static, ter.mu_dynamic, to_geo.T @ np.array([0.0, 0, 1]),
                  body, lg.footpad_mass, terrain=features, soil=soil, footpad_band=lg.footpad_band,
                  footpad_diameter=lg.footpad_diameter)
    name = f.scene.name if f.scene.name is not None else path.stem
    title = f.scene.title if f.scene.title is not None else name
    return SceneConfig(path, name, title, scene, controls, to_geo, lepk, f.output.interval, f.output.srs_damping,
                       tuple(names))


TRIPOD_CELLS = ("primary", "secondary1_compression", "secondary1_tension", "secondary2_compression",
                "secondary2_tension")


def _tripods(legs: TripodLegs, cells: dict[str, Cell], to_geo: np.ndarray, cg: np.ndarray,
             file: str) -> list[TripodLeg]:
    """Tripod legs from their parametric form (geometric axes), turned into principal axes from the CG."""
    out = []
    for (az, _), f in zip(legs.attachments(), legs.factors(5)):
        try:
            root = tripod_from_params(legs.footpad_radius, legs.radius, legs.height,
                                      secondary_spread=legs.secondary_half_angle,
                                      primary=cells[legs.primary].model(f[0]),
                                      secondary_compression=cells[legs.secondary_compression].model(),
                                      secondary_tension=cells[legs.secondary_tension].model(),
                                      footpad_diameter=legs.footpad_diameter, footpad_height=legs.footpad_height,
                                      secondary_radius=legs.secondary_radius,
                                      secondary_height=legs.secondary_height, azimuth=az)
            fraction = legs.secondary_attach / root.rest_primary_length
            if not fraction < 1.0:
                raise ValueError(f"secondary_attach: expected a length up the primary shorter than it "
                                 f"({root.rest_primary_length:.4g} m), got {legs.secondary_attach:.4g} m")
            comp, tens = cells[legs.secondary_compression], cells[legs.secondary_tension]
            leg = TripodLeg(to_geo.T @ (root.primary_hardpoint - cg), (root.secondary_hardpoints - cg) @ to_geo,
                            to_geo.T @ (root.footpad - cg), fraction, root.primary,
                            (comp.model(f[1]), comp.model(f[3])), (tens.model(f[2]), tens.model(f[4])),
                            legs.footpad_diameter, legs.footpad_mass)
        except ValueError as exc:
            key, _, why = str(exc).partition(": ")
            raise InputError(file, f"legs.{_TRIPOD_KEYS.get(key, key)}", "a tripod leg that can stand", why) from None
        out.append(leg)
    return out


# tripod_leg's names for what the scene file calls otherwise
_TRIPOD_KEYS = {"primary_hardpoint": "radius", "hardpoint_radius": "radius", "footpad": "footpad_height",
                "secondary_hardpoints": "secondary_half_angle", "secondary_spread": "secondary_half_angle",
                "primary": "secondary_attach"}


def _legs(legs: TelescopingLegs | ArticulatedLegs | TripodLegs, cells: dict[str, Cell], to_geo: np.ndarray,
          cg: np.ndarray, file: str) -> tuple[list[TelescopingLeg | ArticulatedLeg | TripodLeg], list[tuple[str, ...]]]:
    """The simulator's legs (in principal axes, from the CG) and the names of each leg's cells."""
    out: list[TelescopingLeg | ArticulatedLeg | TripodLeg] = []
    names: list[tuple[str, ...]] = []
    if isinstance(legs, TripodLegs):
        tripods = _tripods(legs, cells, to_geo, cg, file)
        return list(tripods), [TRIPOD_CELLS] * len(tripods)
    if isinstance(legs, ArticulatedLegs):
        geometry = legs.geometry.geometry(legs.length_scale)       # test-model scaling (Table 27)
        for (az, attach), f in zip(legs.attachments(), legs.factors(2)):
            out.append(ArticulatedLeg(to_geo.T @ (attach - cg), to_geo.T @ rot(2, az), geometry, legs.psi_initial,
                                      cells[legs.upper].model(f[0]), cells[legs.lower].model(f[1])))
            names.append(("upper", "lower"))
        return out, names
    n_pads = len(legs.pad_angles)
    for (_, attach), f in zip(legs.attachments(), legs.factors(1 + n_pads)):
        pads = tuple(cells[legs.pads].model(f[1 + j]) for j in range(n_pads))
        out.append(TelescopingLeg(to_geo.T @ (attach - cg), to_geo.T.copy(), legs.length, legs.pad_lever,
                                  legs.pad_angles, cells[legs.axial].model(f[0]), pads, legs.small_angle))
        names.append(("axial", *[f"rot{j + 1}" for j in range(n_pads)]))
    return out, names


def _height_field(table: HeightFieldTable | None, path: Path) -> HeightField | None:
    if table is None:
        return None
    try:
        return HeightField.from_file(path.parent / table.file, *table.spacing, *table.origin)
    except (OSError, ValueError) as exc:
        raise InputError(str(path), "terrain.height_field.file",
                         "a .npy or .csv grid of finite heights (m), at least 2 x 2", str(exc)) from None


def impact_conditions(cfg: SceneConfig) -> dict:
    """What a reader asks of a landing case, in SI: the sink speed along gravity, the speed across it, the
    terrain slope (angle between the terrain normal and the vertical), the angle of the horizontal velocity
    from the downhill direction (0 downhill, 180 uphill; None on level ground or with no horizontal speed) and
    the friction coefficients."""
    g = cfg.scene.gravity / np.linalg.norm(cfg.scene.gravity)
    v = cfg.scene.v0
    down = float(v @ g)
    v_h = v - down * g
    downhill = np.array([0.0, 0.0, 1.0]) - g * g[2]     # the terrain normal, less its vertical part, points downhill
    heading = None
    if np.linalg.norm(downhill) > 1e-9 and np.linalg.norm(v_h) > 1e-9:
        cos = v_h @ downhill / (np.linalg.norm(v_h) * np.linalg.norm(downhill))
        heading = float(np.degrees(np.arccos(np.clip(cos, -1.0, 1.0))))
    return {"vertical_m_s": down, "horizontal_m_s": float(np.linalg.norm(v_h)),
            "slope_deg": float(np.degrees(np.arccos(np.clip(-g[2], -1.0, 1.0)))), "from_downhill_deg": heading,
            "mu_static": float(cfg.scene.mu_static), "mu_dynamic": float(cfg.scene.mu_dynamic)}
