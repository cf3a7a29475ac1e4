"""Where the footpads went: the terrain features each leg met (the plan view is common.figures.footprints_figure)."""

from __future__ import annotations

import numpy as np

from alightsize_sim.landing import Result, Scene
from alightsize_sim.terrain import BOX, HEIGHT_FIELD, HEMISPHERE, STEP, features_along
from alightsize_sim.terrain import pack as pack_terrain

KIND_NAMES = {STEP: "step", HEMISPHERE: "hemisphere rock", BOX: "box rock", HEIGHT_FIELD: "height field"}


def features_met(scene: Scene, res: Result) -> list[list[str]]:
    """Per leg, the features under its footpad while on the ground, in the order first met ("step 1",
    "hemisphere rock 2", "height field"; "plane" for the bare ground; numbered from 1 in the scene's order)."""
    packed = pack_terrain(scene.terrain)
    out = []
    for i in range(len(scene.legs)):
        on = res.contact[:, i] > 0
        kinds, indices = features_along(packed, np.ascontiguousarray(res.footpad[on, i, :2]))
        pairs = np.stack([kinds, indices], axis=1)
        _, first = np.unique(pairs, axis=0, return_index=True)
        met = []
        for kind, index in pairs[np.sort(first)]:
            if kind < 0:
                name = "plane"
            else:
                name = KIND_NAMES[kind] if kind == HEIGHT_FIELD else f"{KIND_NAMES[kind]} {index + 1}"
            if name not in met:
                met.append(name)
        out.append(met)
    return out
