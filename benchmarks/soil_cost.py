"""What soil costs the landing simulator: the lunar lander's nominal landing (examples/terrain/lunar_regolith.toml,
8 kg footpads) on rigid ground, on each shipped soil, and its error against the same landing at rtol 1e-10.
Median of 7 timed runs after a warm-up (terrain_cost._timed), one core; ms per simulated second (landings end
at their outcome).
Usage: python benchmarks/soil_cost.py [--json FILE]
"""

from __future__ import annotations

import argparse
import dataclasses
import json
from pathlib import Path

import numpy as np

from alightsize.model.scene_config import read_scene
from alightsize.model.soils import soil_presets
from alightsize_sim.landing import accel_g, simulate
from terrain_cost import _timed

SCENE = Path(__file__).resolve().parent.parent / "examples" / "terrain" / "lunar_regolith.toml"


def _peak(res) -> float:
    return float(np.max(np.abs(accel_g(res.y, res.dy, res.gravity)[:, 2])))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--json", type=Path)
    a = ap.parse_args()
    cfg = read_scene(SCENE)
    rows = []
    for name, soil in [("rigid", None), *soil_presets().items()]:
        scene = dataclasses.replace(cfg.scene, soil=soil)
        ref = simulate(scene, dataclasses.replace(cfg.controls, rtol=1e-10, atol=1e-12))
        wall, res = _timed(scene, cfg.controls)
        rows.append({"ground": name, "outcome": res.status, "t_end_s": float(res.t[-1]),
                     "ms_per_simulated_s": 1e3 * wall / float(res.t[-1]), "steps": res.steps,
                     "peak_xdd3_g": _peak(res), "peak_error_rel": abs(_peak(res) / _peak(ref) - 1),
                     "closure_rel": res.energy["closure_rel"], "soil_J": res.energy["soil_J"],
                     "max_sinkage_m": float(-np.min(res.footpad[:, :, 2])) if soil else 0.0})
    for r in rows:
        print(json.dumps(r))
    if a.json:
        a.json.write_text(json.dumps(rows, indent=1))


if __name__ == "__main__":
    main()
