"""Scene configs for one landing (`alightsize simulate`): TOML with units, parsed to SI at the boundary.

Frames follow AFFDL-TR-66-33 Sec. V.B: chi, geometric body axes (3 = roll axis, up); kappa, vertical
(3 up); epsilon, terrain (3 normal, eq. 1: a rotation by the slope gamma about the 1 axis). The capsule's
attitude is roll, yaw, pitch (3-2-1 about chi-3, chi-2, chi-1, eq. 2) from kappa, or an inclination from
the vertical toward an azimuth; the initial velocity (V1-V3) is in kappa and the body rates in chi, as in
Appendix VIII. Principal axes come from the eigen-decomposition of the inertia tensor (eq. 1 ff.).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from alightsize_sim.crush_cell import CellModel
from alightsize_sim.landing import G0, Controls, Scene
from alightsize_sim.landing_kernel import GRAZE_SPEED
from alightsize_sim.rigid_body import matrix_quat
from alightsize_sim.articulated_leg import ArticulatedLeg
from alightsize_sim.telescoping_leg import TelescopingLeg
from alightsize_sim.terrain import Box, HeightField, Hemisphere, Step, Terrain

from alightsize.common.config import Node, is_file, load_toml
from alightsize.model.gravity import read_gravity
from alightsize.model.legs import LENGTHS, read_curve, read_geometry
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


def _vector(node: Node, name: str, dim: str, count: int = 3, positive: bool = False) -> np.ndarray:
    values = node.raw(name)
    if not isinstance(values, list) or len(values) != count:
        raise node.error(name, f"an array of {('two', 'three')[count - 2]} {dim} quantities", repr(values))
    return np.array([node.parse_quantity(f"{name}[{i}]", v, dim, positive=positive) for i, v in enumerate(values)])


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


def _cell(node: Node, factor: float = 1.0) -> CellModel:
    curve = read_curve(node, extra=("unloading_rate", "damping", "yield_force"))
    k = node.quantity("unloading_rate", "spring_rate")
    c = node.quantity("damping", "damping", positive=False) if node.has("damping") else 0.0
    y = node.quantity("yield_force", "force") if node.has("yield_force") else None
    node.finish()
    if c < 0:
        raise node.error("damping", "a damping coefficient >= 0", f"{c}")
    return CellModel(curve, k, c, factor, y)


def _cell_name(node: Node, key: str, cells: dict[str, Node]) -> str:
    name = node.string(key)
    if name not in cells:
        raise node.error(key, "the name of a [cells.NAME] table (" + ", ".join(sorted(cells)) + ")", repr(name))
    return name


def _factors(node: Node, n: int, n_cell: int, what: str) -> list[list[float]]:
    factors = node.raw("cell_factors", None)
    if factors is None:
        return [[1.0] * n_cell for _ in range(n)]
    ok = (isinstance(factors, list) and len(factors) == n and all(
        isinstance(r, list) and len(r) == n_cell and all(isinstance(x, (int, float)) and not isinstance(x, bool)
                                                            and x > 0 for x in r) for r in factors))
    if not ok:
        raise node.error("cell_factors", f"{n} arrays (one per leg) of {n_cell} positive force factors ({what})",
                         repr(factors))
    return [[float(x) for x in r] for r in factors]


def _legs(node: Node, cells: dict[str, Node]) -> list[dict]:
    """A pattern of identical legs around the roll axis: count, radius, height, first azimuth."""
    kind = node.string("kind", "telescoping", choices=("telescoping", "articulated"))
    if kind == "articulated":
        return _articulated_legs(node, cells)
    node.allow(("kind", "count", "radius", "height", "first_azimuth", "length", "pad_lever", "pad_angles", "axial",
                "pads", "cell_factors", "small_angle", "footpad_mass", "footpad_band", "footpad_diameter", "note"))
    n, radius, height, az0 = _pattern(node)
    pad_mass, pad_band, pad_diameter = _footpad_mass(node), _footpad_band(node), _footpad_diameter(node)
    rho = node.quantity("length", "length")
    lever = node.quantity("pad_lever", "length", 0.0, positive=False) if node.has("pad_lever") else 0.0
    angles_raw = node.raw("pad_angles", [])
    if not isinstance(angles_raw, list):
        raise node.error("pad_angles", "an array of angles", repr(angles_raw))
    angles = tuple(node.parse_quantity(f"pad_angles[{i}]", a, "angle", positive=False)
                   for i, a in enumerate(angles_raw))
    axial = _cell_name(node, "axial", cells)
    pads = _cell_name(node, "pads", cells) if angles else ""
    factors = _factors(node, n, 1 + len(angles), "axial, then each pad")
    small = node.boolean("small_angle", False)
    node.string("note", "")
    node.finish()
    if not 0 <= lever < rho:
        raise node.error("pad_lever", f"a pad lever from 0 to less than the leg ({rho:.4g} m)", f"{lever:.4g} m")
    legs = []
    for i in range(n):
        az = az0 + 2 * np.pi * i / n
        legs.append(dict(kind=kind, attach=np.array([radius * np.cos(az), radius * np.sin(az), height]), rho=rho,
                         lever=lever, angles=angles, axial=axial, pads=pads, small=small, factors=factors[i],
                         footpad_mass=pad_mass, footpad_band=pad_band, footpad_diameter=pad_diameter))
    return legs


def _features(ter: Node, path: Path) -> Terrain:
    """Steps, rocks and a height field on the terrain plane (terrain axes: x, y in the plane, from the point
    under the capsule's CG at first contact; docs/terrain.md)."""
    steps = []
    for n in ter.tables("steps", optional=True):
        n.allow(("x", "y", "direction", "height", "note"))
        steps.append(Step(n.quantity("x", "length", positive=False), n.quantity("y", "length", positive=False),
                          float(np.degrees(n.quantity("direction", "angle", positive=False))),
                          n.quantity("height", "length", positive=False)))
        n.string("note", "")
        n.finish()
    hemispheres, boxes = [], []
    for n in ter.tables("rocks", optional=True):
        shape = n.string("shape", choices=("hemisphere", "box"))
        x, y = n.quantity("x", "length", positive=False), n.quantity("y", "length", positive=False)
        if shape == "hemisphere":
            n.allow(("shape", "x", "y", "radius", "note"))
            hemispheres.append(Hemisphere(x, y, n.quantity("radius", "length")))
        else:
            n.allow(("shape", "x", "y", "length", "width", "height", "yaw", "note"))
            yaw = n.quantity("yaw", "angle", positive=False) if n.has("yaw") else 0.0
            boxes.append(Box(x, y, n.quantity("length", "length"), n.quantity("width", "length"),
                             n.quantity("height", "length"), float(np.degrees(yaw))))
        n.string("note", "")
        n.finish()
    field = None
    f = ter.table("height_field", optional=True)
    if f:
        f.allow(("file", "spacing", "origin", "note"))
        name = f.string("file")
        spacing = _vector(f, "spacing", "length", 2, positive=True)
        origin = _vector(f, "origin", "length", 2) if f.has("origin") else np.zeros(2)
        f.string("note", "")
        f.finish()
        try:
            field = HeightField.from_file(path.parent / name, *map(float, spacing), *map(float, origin))
        except (OSError, ValueError) as exc:
            raise f.error("file", "a .npy or .csv grid of finite heights (m), at least 2 x 2", str(exc)) from None
    return Terrain(tuple(steps), tuple(hemispheres), tuple(boxes), field)


FOOTPAD_MASS_MIN = 0.01     # kg: measured on configuration 5's footpad scene, 0.01 kg lands in 90k steps, 1 g does not


def _footpad_mass(node: Node) -> float:
    """Each footpad's mass (0, the default: massless footpads, the report's model; alightsize_sim.footpad_mass)."""
    mass = node.quantity("footpad_mass", "mass", positive=False) if node.has("footpad_mass") else 0.0
    if not (mass == 0.0 or FOOTPAD_MASS_MIN <= mass):
        raise node.error("footpad_mass", f"0 (massless footpads) or a mass of {FOOTPAD_MASS_MIN:g} kg or more (a "
                         "lighter footpad rings on its leg faster than any step can follow)",
                         repr(node.raw("footpad_mass")))
    return mass


def _footpad_band(node: Node) -> float:
    """The Karnopp velocity band of footpads with mass (alightsize_sim.footpad_mass; Scene's default)."""
    return node.quantity("footpad_band", "velocity") if node.has("footpad_band") else Scene.footpad_band


def _footpad_diameter(node: Node) -> float:
    """Each footpad's diameter: round footpads bearing on soil (0, the default: not given)."""
    return node.quantity("footpad_diameter", "length") if node.has("footpad_diameter") else 0.0


def _pattern(node: Node) -> tuple[int, float, float, float]:
    n = node.integer("count", minimum=2)
    radius = node.quantity("radius", "length")
    height = node.quantity("height", "length", positive=False)
    az0 = node.quantity("first_azimuth", "angle", 0.0, positive=False) if node.has("first_azimuth") else 0.0
    return n, radius, height, az0


def _articulated_legs(node: Node, cells: dict[str, Node]) -> list[dict]:
    """Articulated legs (Sec. V.F): the leg origin (lower inboard parallelogram pivot) at radius and height, S1
    outward along the azimuth, S3 along the roll axis; the geometry of Fig. 22-25 and the initial psi."""
    node.allow(("kind", "count", "radius", "height", "first_azimuth", "geometry", "length_scale", "psi_initial",
                "upper", "lower", "cell_factors", "footpad_mass", "footpad_band", "footpad_diameter", "note"))
    n, radius, height, az0 = _pattern(node)
    pad_mass, pad_band, pad_diameter = _footpad_mass(node), _footpad_band(node), _footpad_diameter(node)
    geometry = read_geometry(node.table("geometry"))
    scale = node.number("length_scale", 1.0)
    geometry = geometry._replace(**{k: scale * getattr(geometry, k) for k in LENGTHS})   # test-model scaling (Table 27)
    psi0 = node.quantity("psi_initial", "angle", positive=False)
    if not -np.pi / 2 < psi0 < np.pi / 2:
        raise node.error("psi_initial", "an angle between -90 and 90 deg", f"{np.degrees(psi0):.4g} deg")
    upper, lower = _cell_name(node, "upper", cells), _cell_name(node, "lower", cells)
    factors = _factors(node, n, 2, "upper, lower")
    node.string("note", "")
    node.finish()
    legs = []
    for i in range(n):
        az = az0 + 2 * np.pi * i / n
        legs.append(dict(kind="articulated", attach=np.array([radius * np.cos(az), radius * np.sin(az), height]),
                         azimuth=az, geometry=geometry, psi0=psi0, upper=upper, lower=lower, factors=factors[i],
                         footpad_mass=pad_mass, footpad_band=pad_band, footpad_diameter=pad_diameter))
    return legs


def _inclination_attitude(roll: float, theta: float, azimuth: float) -> tuple[float, float]:
    """(yaw, pitch) that tilt the roll axis by theta toward kappa azimuth `azimuth` at a given roll: chi-3 in
    kappa = (sR sP + cR sY cP, -cR sP + sR sY cP, cY cP) (eq. 2) set to (s cos az, s sin az, cos theta)."""
    s = np.sin(theta)
    sp = s * np.sin(roll - azimuth)
    pitch = np.arcsin(np.clip(sp, -1, 1))
    yaw = np.arctan2(s * np.cos(roll - azimuth), np.cos(theta))
    return float(yaw), float(pitch)


MAX_BASES = 8


def _merge(base: dict, over: dict) -> dict:
    """Tables of `over` merged key by key into those of `base`; any other value replaces."""
    out = dict(base)
    for k, v in over.items():
        out[k] = _merge(out[k], v) if isinstance(v, dict) and isinstance(out.get(k), dict) else v
    return out


# tables of a lander file (alightsize.pipeline.lander) that do not describe the landing itself
LANDER_ONLY = ("lander", "structure", "members", "item", "requirements", "report", "synthesis")


def _upper(value):
    """The larger end of a requirement written as a value or a [low, high] range (as written)."""
    return value[-1] if isinstance(value, list) and value else value


def lander_scene(root: Node) -> Node:
    """A lander file read as its nominal landing: the scene tables, [lander] name, title and gravity as its
    [scene], and, without an [initial] table, the envelope's largest vertical and horizontal speeds."""
    head = root.data["lander"] if isinstance(root.data["lander"], dict) else {}
    data = {k: v for k, v in root.data.items() if k not in LANDER_ONLY}
    data["scene"] = {k: head[k] for k in ("name", "title", "gravity") if k in head}
    req = root.data.get("requirements")
    env = req.get("envelope") if isinstance(req, dict) else None
    if "initial" not in data and isinstance(env, dict) and isinstance(_upper(env.get("vertical_speed")), str):
        h = _upper(env.get("horizontal_speed", "0 m/s"))
        data["initial"] = {"velocity": ["0 m/s", h, "-" + _upper(env["vertical_speed"]).strip()]}
    return Node(root.file, "", data)


def load_scene_toml(path: Path, depth: int = 0) -> Node:
    """The scene TOML with its `scene.base` chain (a scene it varies, path relative to it) merged under it;
    a lander file gives its nominal landing (`lander_scene`)."""
    root = load_toml(path)
    if "lander" in root.data:
        return lander_scene(root)
    head = root.data.get("scene")
    if not (isinstance(head, dict) and "base" in head):
        return root
    base = head["base"]
    base_path = path.parent / base if isinstance(base, str) else None
    if base_path is None or not is_file(base_path):
        raise root.error("scene.base", "the path of a scene TOML (relative to this one)", repr(base))
    if depth >= MAX_BASES:
        raise root.error("scene.base", f"at most {MAX_BASES} nested bases", "a longer chain (a cycle?)")
    base_data = load_scene_toml(base_path, depth + 1).data
    data = _merge(base_data, root.data)
    inherited = {k: v for k, v in (base_data.get("scene") or {}).items() if k == "gravity"}
    data["scene"] = inherited | {k: v for k, v in head.items() if k != "base"}   # name and title are not inherited
    return Node(path, "", data)


def read_scene(path: str | Path, overrides: dict[str, object] | None = None) -> SceneConfig:
    """Read and validate a scene config, with `overrides` (dotted key path -> TOML value, e.g.
    {"terrain.slope": "-20 deg"}) applied first; problems are InputErrors naming file and key path. A scene
    may vary another (`[scene] base = "other.toml"`): its tables are merged key by key over the base's."""
    path = Path(path)
    root = load_scene_toml(path)
    for key, value in (overrides or {}).items():
        root.set_path(key, value)
    root.allow(("scene", "capsule", "cells", "legs", "terrain", "initial", "controls", "output"))
    head = root.table("scene", optional=True)
    name = head.string("name", path.stem) if head else path.stem
    title = head.string("title", name) if head else name
    g = read_gravity(head, "gravity") if head else G0
    if head:
        head.finish()

    cap = root.table("capsule")
    cap.allow(("weight", "mass", "inertia", "cg", "bottom", "note"))
    if cap.has("weight") == cap.has("mass"):
        raise cap.error("weight", "exactly one of weight (force) or mass", "both" if cap.has("mass") else "neither")
    mass = cap.quantity("weight", "force") / G0 if cap.has("weight") else cap.quantity("mass", "mass")
    inertia_raw = cap.raw("inertia")
    if isinstance(inertia_raw, list) and len(inertia_raw) == 3 and not any(isinstance(r, list) for r in inertia_raw):
        tensor = np.diag([cap.parse_quantity(f"inertia[{i}]", v, "inertia") for i, v in enumerate(inertia_raw)])
    elif isinstance(inertia_raw, list) and len(inertia_raw) == 3 and all(isinstance(r, list) and len(r) == 3
                                                                          for r in inertia_raw):
        tensor = np.array([[cap.parse_quantity(f"inertia[{i}][{j}]", v, "inertia", positive=(i == j))
                            for j, v in enumerate(row)] for i, row in enumerate(inertia_raw)])
        if not np.allclose(tensor, tensor.T, rtol=1e-9, atol=0):
            raise cap.error("inertia", "a symmetric tensor", "I_ij != I_ji")
    else:
        raise cap.error("inertia", "three principal moments or a 3x3 tensor about the CG (geometric axes)",
                        repr(inertia_raw))
    moments, to_geo = principal_axes(tensor)
    if not np.all(moments > 0):
        raise cap.error("inertia", "a positive definite tensor", f"principal moments {moments}")
    cg = _vector(cap, "cg", "length") if cap.has("cg") else np.zeros(3)
    bottom = cap.quantity("bottom", "length") if cap.has("bottom") else None
    cap.string("note", "")
    cap.finish()

    cells_node = root.table("cells")
    cell_nodes = {k: cells_node.table(k) for k in cells_node.data}
    cells_node.finish()
    leg_specs = _legs(root.table("legs"), cell_nodes)
    models = {k: _cell(n) for k, n in cell_nodes.items()}
    legs: list[TelescopingLeg | ArticulatedLeg] = []
    names: list[tuple[str, ...]] = []
    for spec in leg_specs:
        f = spec["factors"]
        if spec["kind"] == "articulated":
            up, lo = models[spec["upper"]], models[spec["lower"]]
            legs.append(ArticulatedLeg(to_geo.T @ (spec["attach"] - cg), to_geo.T @ rot(2, spec["azimuth"]),
                                       spec["geometry"], spec["psi0"],
                                       CellModel(up.curve, up.k, up.c, f[0], up.yield_force),
                                       CellModel(lo.curve, lo.k, lo.c, f[1], lo.yield_force)))
            names.append(("upper", "lower"))
            continue
        ax = models[spec["axial"]]
        axial = CellModel(ax.curve, ax.k, ax.c, f[0], ax.yield_force)
        pads = []
        for j in range(len(spec["angles"])):
            pm = models[spec["pads"]]
            pads.append(CellModel(pm.curve, pm.k, pm.c, f[1 + j], pm.yield_force))
        legs.append(TelescopingLeg(to_geo.T @ (spec["attach"] - cg), to_geo.T.copy(), spec["rho"], spec["lever"],
                                   spec["angles"], axial, tuple(pads), spec["small"]))
        names.append(("axial", *[f"rot{j + 1}" for j in range(len(spec["angles"]))]))

    ter = root.table("terrain", optional=True)
    slope = mu_s = mu_d = soil = None
    features = Terrain()
    if ter:
        ter.allow(("slope", "mu_static", "mu_dynamic", "steps", "rocks", "height_field", "soil", "note"))
        features = _features(ter, path)
        if ter.has("soil"):
            soil = find_soil(ter, "soil", path.parent)
            if not leg_specs[0]["footpad_mass"] > 0:
                raise ter.error("soil", "footpads with mass to sink into it ([legs] footpad_mass > 0)",
                                "massless footpads")
            if not leg_specs[0]["footpad_diameter"] > 0:
                raise ter.error("soil", "the footpads' bearing size ([legs] footpad_diameter)", "none given")
        slope = ter.quantity("slope", "angle", 0.0, positive=False) if ter.has("slope") else 0.0
        mu_s = ter.number("mu_static", 1.5e6, positive=False)
        mu_d = ter.number("mu_dynamic", 1.0e6, positive=False)
        if mu_d < 0:
            raise ter.error("mu_dynamic", "a friction coefficient >= 0 (0: frictionless)", f"{mu_d}")
        ter.string("note", "")
        ter.finish()
        if mu_d > mu_s:
            raise ter.error("mu_dynamic", f"a dynamic coefficient <= the static one ({mu_s})", f"{mu_d}")
        if not -np.pi / 2 < slope < np.pi / 2:
            raise ter.error("slope", "a slope between -90 and 90 deg", f"{np.degrees(slope):.4g} deg")
    slope = slope or 0.0
    lepk = rot(0, slope)            # kappa -> epsilon (eq. 1, LEPK): gravity (0, g sin, -g cos) (eq. 4-5)

    ini = root.table("initial")
    ini.allow(("velocity", "heading", "roll", "yaw", "pitch", "inclination", "inclination_azimuth", "rates", "note"))
    vel = _vector(ini, "velocity", "velocity")
    if ini.has("heading"):                              # the horizontal velocity turned from kappa-2 toward kappa-1
        h, v_h = ini.quantity("heading", "angle", positive=False), float(np.hypot(vel[0], vel[1]))
        vel = np.array([v_h * np.sin(h), v_h * np.cos(h), vel[2]])
    if vel[2] > 0:                                      # legal (a rebound, a hop), but more likely a sign slip
        ini.warn("velocity[2]", f"an upward initial velocity, V3 = {ini.raw('velocity')[2]} (kappa-3 is up, a "
                                "descent is negative): the capsule rises before it lands; simulated as given")
    roll = ini.quantity("roll", "angle", 0.0, positive=False) if ini.has("roll") else 0.0
    if ini.has("inclination"):
        if ini.has("yaw") or ini.has("pitch"):
            raise ini.error("inclination", "either inclination or yaw/pitch", "both")
        theta = ini.quantity("inclination", "angle", positive=False)
        default_az = float(np.arctan2(vel[1], vel[0])) if np.hypot(vel[0], vel[1]) > 0 else 0.0
        az = (ini.quantity("inclination_azimuth", "angle", positive=False) if ini.has("inclination_azimuth")
              else default_az)
        yaw, pitch = _inclination_attitude(roll, theta, az)
    else:
        yaw = ini.quantity("yaw", "angle", 0.0, positive=False) if ini.has("yaw") else 0.0
        pitch = ini.quantity("pitch", "angle", 0.0, positive=False) if ini.has("pitch") else 0.0
    rates = _vector(ini, "rates", "angular_velocity") if ini.has("rates") else np.zeros(3)
    ini.string("note", "")
    ini.finish()
    lkx = rot(2, roll) @ rot(1, yaw) @ rot(0, pitch)    # chi -> kappa (eq. 2, FUNEV LKX)
    q0 = matrix_quat(lepk @ lkx @ to_geo)

    ctl_node = root.table("controls", optional=True)
    c = _controls(ctl_node, mass, legs)
    out = root.table("output", optional=True)
    interval, srs_damping = None, 0.05
    if out:
        out.allow(("interval", "srs_damping"))
        interval = out.quantity("interval", "time") if out.has("interval") else None
        srs_damping = out.number("srs_damping", 0.05)
        out.finish()
        if not 0 < srs_damping < 1:
            raise out.error("srs_damping", "a damping ratio in (0, 1)", f"{srs_damping}")
    root.finish()

    body = np.zeros((0, 3)) if bottom is None else (to_geo.T @ (np.array([0.0, 0.0, -bottom]) - cg))[None, :]
    scene = Scene(mass, moments, tuple(legs), lepk @ np.array([0.0, 0.0, -g]), lepk @ vel, q0, to_geo.T @ rates,
                  mu_s if mu_s is not None else 1.5e6, mu_d if mu_d is not None else 1.0e6,
                  to_geo.T @ np.array([0.0, 0, 1]),
                  body, leg_specs[0]["footpad_mass"], terrain=features, soil=soil,
                  footpad_band=leg_specs[0]["footpad_band"], footpad_diameter=leg_specs[0]["footpad_diameter"])
    return SceneConfig(path, name, title, scene, c, to_geo, lepk, interval, srs_damping, tuple(names))


def _controls(node: Node | None, mass: float, legs: list[TelescopingLeg | ArticulatedLeg]) -> Controls:
    if node is None:
        return Controls()
    node.allow(("t_final", "rtol", "atol", "fixed_step", "max_step", "event_tol", "tip_angle", "taus",
                "stop_on_bottoming", "energy_criterion_from", "closed_form_flight", "note"))
    d = Controls()
    t_final = node.quantity("t_final", "time", d.t_final)
    rtol = node.number("rtol", d.rtol)
    atol = node.number("atol", d.atol)
    fixed = node.quantity("fixed_step", "time") if node.has("fixed_step") else None
    max_step = node.quantity("max_step", "time", d.max_step)
    event_tol = node.quantity("event_tol", "time", d.event_tol)
    tip = node.quantity("tip_angle", "angle", d.tip_angle)
    taus = node.number("taus", 0.0, positive=False)
    stop = node.boolean("stop_on_bottoming", True)
    energy_from = node.raw("energy_criterion_from", "0.05 s")
    energy_t = None if energy_from is False else node.parse_quantity("energy_criterion_from", energy_from, "time",
                                                                       positive=False)
    flight = node.boolean("closed_form_flight", True)
    node.string("note", "")
    node.finish()
    if not 0 < tip <= np.pi:
        raise node.error("tip_angle", "an angle in (0, 180] deg", f"{np.degrees(tip):.4g} deg")
    if taus < 0:
        raise node.error("taus", "a number of periods >= 0", f"{taus}")
    if rtol >= 1:
        raise node.error("rtol", "a relative tolerance below 1", f"{rtol}")
    if event_tol > d.contact_band / GRAZE_SPEED:
        raise node.error("event_tol", f"a time of at most {d.contact_band / GRAZE_SPEED:g} s (the grazing band "
                         f"{d.contact_band:g} m at {GRAZE_SPEED:g} m/s)", f"{event_tol:g} s")
    period = float(np.pi * np.sqrt(mass / legs[0].cells[0].k))    # TAU = pi sqrt(M / SLOPE(1)) (App. VII,
                                                                  # telescoping subroutine FORCE)
    return Controls(t_final=t_final, rtol=rtol, atol=atol, fixed_step=fixed, max_step=max_step, event_tol=event_tol,
                    tip_angle=tip, taus=taus, period=period, stop_on_bottoming=stop, energy_check_from=energy_t,
                    closed_form_flight=flight)


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
