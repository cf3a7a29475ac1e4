"""Robustness sweep of the landing simulator: N seeded random landings about configuration 1
(alightsize.landings.random_landings), each run to its outcome or t_final, on a process pool.

Reports the outcome counts, failures (must be none), the worst energy closure, and the wall time per landing
and per simulated second. With --terrain each landing has one random step or rock within the leg span; with
--soil NAME (a shipped soil; needs --footpad-mass) the ground is that soil, under nominal 0.5 m footpads.
Usage: python benchmarks/random_scenes.py [-n 1000] [--t-final 1.0] [--workers 2] [--terrain] [--footpad-mass KG]
[--soil NAME] [--json FILE]
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import os
import platform
import time
from collections import Counter
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

from alightsize.landings.random_landings import random_landing
from alightsize.model.scene_config import read_scene
from alightsize.model.soils import soil_presets
from alightsize_sim.landing import simulate

BASE = Path(__file__).resolve().parent.parent / "examples" / "affdl-tr-66-33" / "scenes" / "telescoping_config1.toml"
SEED = 20261121
PAD_DIAMETER = 0.5                  # m: a nominal footpad (the report gives none for configuration 1)


def one(k: int, t_final: float, features: bool = False, footpad_mass: float = 0.0, soil: str | None = None) -> dict:
    base = read_scene(BASE)
    scene = dataclasses.replace(random_landing(base.scene, SEED, k, features), footpad_mass=footpad_mass,
                                soil=soil_presets()[soil] if soil else None, footpad_diameter=PAD_DIAMETER)
    res = simulate(scene, dataclasses.replace(base.controls, t_final=t_final))
    return {"k": k, "status": res.status, "t_end": float(res.t[-1]), "wall_s": res.wall_s, "steps": res.steps,
            "rejected": res.rejected, "events": res.events, "closure_rel": res.energy["closure_rel"],
            "finite": bool(np.isfinite(res.y).all())}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-n", type=int, default=1000)
    ap.add_argument("--t-final", type=float, default=1.0)
    ap.add_argument("--workers", type=int, default=os.cpu_count())
    ap.add_argument("--json", type=Path)
    ap.add_argument("--terrain", action="store_true", help="a random step or rock within the leg span in each")
    ap.add_argument("--footpad-mass", type=float, default=0.0, help="footpad mass, kg (0: massless, the default)")
    ap.add_argument("--soil", help="a shipped soil under the footpads (needs --footpad-mass)")
    a = ap.parse_args()
    one(0, 0.01, a.terrain, a.footpad_mass, a.soil)        # compile (cached) before timing
    t0 = time.perf_counter()
    with ProcessPoolExecutor(a.workers) as pool:
        runs = list(pool.map(one, range(a.n), [a.t_final] * a.n, [a.terrain] * a.n, [a.footpad_mass] * a.n,
                             [a.soil] * a.n, chunksize=8))
    wall = time.perf_counter() - t0
    walls = np.array([r["wall_s"] for r in runs])
    sim_t = np.array([r["t_end"] for r in runs])
    out = {"n": a.n, "t_final_s": a.t_final, "workers": a.workers, "terrain": a.terrain,
           "footpad_mass_kg": a.footpad_mass, "soil": a.soil,
           "machine": platform.processor() or platform.machine(),
           "outcomes": dict(Counter(r["status"] for r in runs)),
           "failed": [r["k"] for r in runs if r["status"] == "failed" or not r["finite"]],
           "closure_rel_max": max(r["closure_rel"] for r in runs),
           "closure_worst_k": max(runs, key=lambda r: r["closure_rel"])["k"],
           "wall_total_s": wall, "wall_per_landing_ms": {"median": 1e3 * float(np.median(walls)),
                                                         "p95": 1e3 * float(np.percentile(walls, 95)),
                                                         "max": 1e3 * float(walls.max())},
           "ms_per_simulated_s": 1e3 * float(walls.sum() / sim_t.sum()),
           "slowest": sorted(runs, key=lambda r: -r["wall_s"])[:5]}
    print(json.dumps(out, indent=1))
    if a.json:
        a.json.write_text(json.dumps({**out, "runs": runs}, indent=1))


if __name__ == "__main__":
    main()
