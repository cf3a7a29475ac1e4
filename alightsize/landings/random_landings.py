"""Seeded random landings for robustness sweeps of the simulator: terrain slope (+-35 deg), horizontal and
vertical velocity, inclination toward any azimuth, roll rate (0 or 3 rad/s) and friction (mu_D 0.3-1.2,
mu_S = 1.5 mu_D) dispersed about a base scene. Landing k of a sweep depends only on (seed, k), never on the
order or place it runs."""

from __future__ import annotations

import dataclasses

import numpy as np

from alightsize_sim.landing import Scene
from alightsize_sim.rigid_body import axis_rotation, matrix_quat, quat_matrix
from alightsize_sim.terrain import random_feature

FT = 0.3048


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
    span = max(float(np.hypot(*leg.attach[:2])) for leg in base.legs) * 1.5
    return dataclasses.replace(scene, terrain=random_feature(rng, span, step_height=(-2.0 * FT, 2.0 * FT),
                                                             radius=(0.2 * FT, 2.0 * FT), box_size=(0.5 * FT, 4.0 * FT),
                                                             box_height=(0.2 * FT, 2.0 * FT)))
