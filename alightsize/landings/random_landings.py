"""Seeded random landings for robustness sweeps of the simulator: terrain slope (+-35 deg), horizontal and
vertical velocity, inclination toward any azimuth, roll rate (0 or 3 rad/s) and friction (mu_D 0.3-1.2,
mu_S = 1.5 mu_D) dispersed about a base scene (`random_landing`); and, for a mixed sweep, the scene itself
drawn about a base (`mixed_overrides`): footpad mass and diameter, the ground (rigid or a shipped soil), gravity
and every cell's loading curve, with rocks and steps within the leg span (`random_terrain`). Landing k of a
sweep depends only on (seed, k), never on the order or place it runs."""

from __future__ import annotations

import dataclasses

import numpy as np

from alightsize_sim.crush_cell import CellModel
from alightsize_sim.landing import Scene
from alightsize_sim.rigid_body import axis_rotation, matrix_quat, quat_matrix
from alightsize_sim.terrain import Terrain, random_feature

FT = 0.3048
G0 = 9.80665
G_LEAST = 1e-6          # m/s^2: the least gravity a scene takes (docs/reference/scene.md [scene] gravity)
NEAR_DEGENERATE = 0.15  # the share of drawn curves whose first point carries next to nothing: 1e-9 to 1e-6 N
LEAST_FORCE = 1e-9      # N: the least non-zero force an input takes (alightsize.common.units)


def random_landing(base: Scene, seed: int, k: int, features: bool = False) -> Scene:
    """Landing k of the sweep seeded `seed`: the base scene on a random slope with random initial motion; with
    `features`, one step (up or down to 2 ft, the report's Sec. VII.B discontinuity) or rock (a hemisphere or a
    box up to 2 ft high) anywhere within the leg span."""
    rng = np.random.default_rng([seed, k])
    slope = np.radians(rng.uniform(-35.0, 35.0))
    c, s = np.cos(slope), np.sin(slope)
    lepk = np.array([[1.0, 0.0, 0.0], [0.0, c, s], [0.0, -s, c]])        # vertical -> terrain axes
    v = np.array([rng.uniform(-2.0, 2.0), rng.uniform(0.0, 15.0), -rng.uniform(5.0, 35.0)]) * FT
    tilt = np.radians(rng.uniform(0.0, 12.0))
    az = rng.uniform(0.0, 2.0 * np.pi)
    axis = np.array([np.cos(az), np.sin(az), 0.0])
    q0 = matrix_quat(lepk @ axis_rotation(axis, tilt) @ quat_matrix(base.q0))
    mu_d = rng.uniform(0.3, 1.2)
    g = float(np.linalg.norm(base.gravity))
    scene = dataclasses.replace(base, gravity=lepk @ np.array([0.0, 0.0, -g]), v0=lepk @ v, q0=q0,
                                omega0=np.array([0.0, 0.0, rng.choice([0.0, 3.0])]), mu_dynamic=mu_d,
                                mu_static=1.5 * mu_d)
    if not features:
        return scene
    return dataclasses.replace(scene, terrain=random_terrain(rng, base, 1))


def random_terrain(rng: np.random.Generator, base: Scene, count: int) -> Terrain:
    """`count` steps or rocks (each as random_landing's feature) within the leg span of `base`, on one plane."""
    span = max(float(np.hypot(*leg.attach[:2])) for leg in base.legs) * 1.5
    parts = [random_feature(rng, span, step_height=(-2.0 * FT, 2.0 * FT), radius=(0.2 * FT, 2.0 * FT),
                            box_size=(0.5 * FT, 4.0 * FT), box_height=(0.2 * FT, 2.0 * FT)) for _ in range(count)]
    return Terrain(steps=sum((p.steps for p in parts), ()), hemispheres=sum((p.hemispheres for p in parts), ()),
                   boxes=sum((p.boxes for p in parts), ()))


def _q(x: float, unit: str) -> str:
    """A TOML quantity, exact (the shortest repr of the float)."""
    return f"{float(x)!r} {unit}"


def random_curve(rng: np.random.Generator, cell: CellModel, max_stroke: float = np.inf) -> dict:
    """A cell table (TOML values, SI) about `cell`: 3 to 6 points over 0.5-1.5 x its stroke (short of
    `max_stroke`, m: a cantilever's primary strokes below its knee), a first point at
    0.5-10 % of the stroke carrying 0.3-1 x the force level (or, in NEAR_DEGENERATE of the draws, 1e-9 to 1e-6 N:
    a leg with free play), stages at 0.8-1.3 x the level (mostly rising, dips allowed), a last point at 1.5-3 x (the
    bottoming ramp); level 0.5-1.5 x the cell's largest force short of its ramp; unloading rate 1-2 x the
    steepest segment (or the cell's own rate if that is larger), the cell's damping."""
    d, f = cell.curve.deflection, cell.curve.force
    stroke = d[-1] * rng.uniform(0.5, min(1.5, max_stroke / d[-1]))
    level = max(f[:-1] if len(f) > 2 else f) * rng.uniform(0.5, 1.5)
    m = int(rng.integers(3, 7))
    first = stroke * rng.uniform(0.005, 0.1)
    defl = [0.0, first, *np.sort(rng.uniform(first, stroke, m - 3)), stroke]
    near = rng.uniform() < NEAR_DEGENERATE
    onset = LEAST_FORCE * 10.0 ** rng.uniform(0.0, 3.0) if near else level * rng.uniform(0.3, 1.0)
    force = [0.0, onset, *(level * rng.uniform(0.8, 1.3, m - 3)), level * rng.uniform(1.5, 3.0)]
    slopes = [(b - a) / (y - x) for x, y, a, b in zip(defl, defl[1:], force, force[1:]) if y > x]
    rate = max(max(slopes) * rng.uniform(1.0, 2.0), cell.k)
    return {"deflection": [_q(x, "m") for x in defl], "force": [_q(x, "N") for x in force],
            "unloading_rate": _q(rate, "N/m"), "damping": _q(cell.c, "N*s/m")}


def mixed_overrides(rng: np.random.Generator, cells: dict[str, CellModel], soils: tuple[str, ...],
                    massless: bool = True, max_strokes: dict[str, float] | None = None) -> dict:
    """Overrides of a base scene (dotted key -> TOML value) for a mixed sweep: footpads massless (a third of the
    draws; never with `massless` False, for legs whose footpads need mass) or of 1-50 kg, 0.2-0.8 m across; with
    mass, rigid ground or one of `soils` (equally likely); gravity log-uniform from G_LEAST to 1.5 g0; every cell of
    `cells` (its name in the file's [cells] -> its model) redrawn (random_curve), short of its stroke limit in
    `max_strokes` (name -> m) if it has one."""
    over: dict = {}
    mass = 0.0 if massless and rng.uniform() < 1.0 / 3.0 else rng.uniform(1.0, 50.0)
    diameter = rng.uniform(0.2, 0.8)
    ground = int(rng.integers(len(soils) + 1)) if mass > 0.0 else 0
    over["legs.footpad_mass"] = _q(mass, "kg")
    if ground:
        over["legs.footpad_diameter"] = _q(diameter, "m")
        over["terrain.soil"] = soils[ground - 1]
    over["scene.gravity"] = _q(np.exp(rng.uniform(np.log(G_LEAST), np.log(1.5 * G0))), "m/s^2")
    for name, cell in sorted(cells.items()):
        for key, value in random_curve(rng, cell, (max_strokes or {}).get(name, np.inf)).items():
            over[f"cells.{name}.{key}"] = value
    return over
