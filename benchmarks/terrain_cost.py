"""What terrain features cost the landing simulator: configuration 2 and the slipping articulated bench landing
(5 lb footpads) on the bare plane against the same landings with a step, two rocks and a height field placed
where no footpad meets them (the same landing, so the difference is the cost of looking the surface up), and
with a rock under a footpad (a different landing, for scale). Median of 7 timed runs after a warm-up, one core.
Usage: python benchmarks/terrain_cost.py [--json FILE]
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import time
from pathlib import Path

import numpy as np

from alightsize.model.scene_config import read_scene
from alightsize_sim.landing import simulate
from alightsize_sim.terrain import Box, HeightField, Hemisphere, Step, Terrain

SCENES = Path(__file__).resolve().parent.parent / "examples" / "affdl-tr-66-33" / "scenes"
FAR = Terrain(steps=(Step(40.0, 0.0, -90.0, 0.3),), hemispheres=(Hemisphere(30.0, 30.0, 0.5),),
              boxes=(Box(-30.0, 30.0, 1.0, 1.0, 0.3),),
              height_field=HeightField(50.0, 50.0, 1.0, 1.0, np.zeros((20, 20))))


def _timed(scene, ctl) -> tuple[float, object]:
    simulate(scene, ctl)
    walls = []
    for _ in range(7):
        t0 = time.perf_counter()
        res = simulate(scene, ctl)
        walls.append(time.perf_counter() - t0)
    return float(np.median(walls)), res


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--json", type=Path)
    a = ap.parse_args()
    rows = []
    for name in ("telescoping_config2", "articulated_config5_slope35_footpads"):
        cfg = read_scene(SCENES / f"{name}.toml")
        ctl = dataclasses.replace(cfg.controls, rtol=1e-4)
        plane, res = _timed(cfg.scene, ctl)
        foot = res.footpad[np.argmax(res.contact[:, 0] > 0), 0]
        rock = Terrain(hemispheres=(Hemisphere(float(foot[0]), float(foot[1]), 0.15),))
        far, res_far = _timed(dataclasses.replace(cfg.scene, terrain=FAR), ctl)
        met, _ = _timed(dataclasses.replace(cfg.scene, terrain=rock), ctl)
        same = bool(len(res.t) == len(res_far.t) and np.array_equal(res.y, res_far.y))
        rows.append({"scene": name, "plane_ms": 1e3 * plane, "features_not_met_ms": 1e3 * far,
                     "overhead": far / plane - 1.0, "same_landing": same, "rock_under_leg_1_ms": 1e3 * met})
        print(f"{name}: plane {1e3 * plane:.2f} ms, features not met {1e3 * far:.2f} ms "
              f"({100 * (far / plane - 1):+.1f} %, same landing: {same}), a rock under leg 1 {1e3 * met:.2f} ms")
    if a.json:
        a.json.write_text(json.dumps(rows, indent=1))


if __name__ == "__main__":
    main()
