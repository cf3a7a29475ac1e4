"""Tripod landings: speed at 0.1 % peak-acceleration accuracy, first compile, massless footpads against footpads
with mass; a telescoping baseline timed in the same run (examples/lunar_lander.toml beside
examples/lunar_tripod.toml: same capsule, stance and envelope).

1. Accuracy and speed: each scene's nominal landing, and the same landing across a 12 deg slope at mu 0.4 (the
   footpads slide), run for 1 s (the energy criterion off, so that every run simulates the same second) at rtol
   1e-3 ... 1e-8 against rtol 1e-11 (atol 1e-3 rtol): the loosest rtol from which every tighter one puts the peak
   |acceleration| within 0.1 % of the reference, and its wall time per simulated second (median of --repeat
   runs, one core: the process is pinned to CPU 0).
2. First compile: `alightsize simulate` of each example in a fresh process with an empty numba cache
   (NUMBA_CACHE_DIR), the second run's wall time taken off.
3. Footpad model: the sliding tripod landing with the example's footpads of 5 kg (footpad_mass, their in-plane
   inertia integrated) and with 0.5 kg: speed at 0.1 % against each model's own reference, and how far the
   references lie apart (the massless slide, measured against them in docs/notes/tripod-design.md, is refused
   for tripods on ground they can slip on).
Prints a table and `uptime`; --json writes the figures. Usage: python benchmarks/tripod_landing.py [--repeat 5]
[--no-compile] [--json FILE]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
SCENES = {"telescoping": ROOT / "examples" / "lunar_lander.toml", "tripod": ROOT / "examples" / "lunar_tripod.toml"}
SLIDING = {"terrain.slope": "12 deg", "terrain.mu_static": 0.4, "terrain.mu_dynamic": 0.4,
           "initial.velocity": ["1 m/s", "0 m/s", "-3 m/s"]}
LADDER = (1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8)
ACCURACY = 1e-3


def _landing(scene: Path, overrides: dict, rtol: float, pad_mass: float | None = None):
    """The scene's landing for 1 s at rtol (footpad mass changed to pad_mass kg unless None)."""
    from dataclasses import replace
    from alightsize.model.scene_config import read_scene
    from alightsize_sim.landing import simulate
    cfg = read_scene(scene, overrides)
    sc = cfg.scene if pad_mass is None else replace(cfg.scene, footpad_mass=pad_mass)
    return simulate(sc, replace(cfg.controls, rtol=rtol, atol=1e-3 * rtol, t_final=1.0, energy_check_from=None))


def _peak(res) -> float:
    return float(np.abs(res.accel_g).max())


def accuracy_speed(scene: Path, overrides: dict, repeat: int, pad_mass: float | None = None) -> dict:
    """The loosest rtol of LADDER from which every tighter one is within ACCURACY of the reference's peak, its wall
    time per simulated second."""
    ref = _landing(scene, overrides, 1e-11, pad_mass)
    out = {"reference_peak_g": _peak(ref), "t_end_s": float(ref.t[-1]), "status": ref.status, "ladder": []}
    for rtol in LADDER:
        walls, res = [], None
        for _ in range(repeat):
            res = _landing(scene, overrides, rtol, pad_mass)
            walls.append(res.wall_s)
        err = abs(_peak(res) / out["reference_peak_g"] - 1.0)
        row = {"rtol": rtol, "peak_error": err, "wall_s": float(np.median(walls)), "t_end_s": float(res.t[-1]),
               "steps": res.steps, "closure": res.energy["closure_rel"]}
        row["ms_per_simulated_s"] = 1e3 * row["wall_s"] / row["t_end_s"]
        out["ladder"].append(row)
    within = [row["peak_error"] <= ACCURACY for row in out["ladder"]]
    first = next((k for k in range(len(within)) if all(within[k:])), None)
    out["at_accuracy"] = None if first is None else out["ladder"][first]
    return out


def first_compile(scene: Path) -> float:
    """Seconds of the first `alightsize simulate` in a fresh numba cache less the second run's."""
    with tempfile.TemporaryDirectory() as cache, tempfile.TemporaryDirectory() as out:
        env = {**os.environ, "NUMBA_CACHE_DIR": cache, "PYTHONPATH": str(ROOT)}
        walls = []
        for _ in range(2):
            t = time.perf_counter()
            subprocess.run([sys.executable, "-m", "alightsize", "simulate", str(scene), "--out", out], env=env,
                           check=True, capture_output=True)
            walls.append(time.perf_counter() - t)
    return walls[0] - walls[1]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--no-compile", action="store_true")
    ap.add_argument("--json", type=Path)
    args = ap.parse_args()
    if hasattr(os, "sched_setaffinity"):
        os.sched_setaffinity(0, {0})
    doc: dict = {"uptime_before": subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()}
    if not args.no_compile:
        doc["first_compile_s"] = {k: first_compile(p) for k, p in SCENES.items()}
    _landing(SCENES["tripod"], {}, 1e-6)                 # compile in this process before timing
    _landing(SCENES["telescoping"], {}, 1e-6)
    doc["speed"] = {f"{k} {case}": accuracy_speed(p, over, args.repeat) for k, p in SCENES.items()
                    for case, over in (("nominal", {}), ("sliding", SLIDING))}
    for mass in (0.5,):
        doc["speed"][f"tripod sliding, {mass:g} kg footpads"] = accuracy_speed(SCENES["tripod"], SLIDING,
                                                                              args.repeat, mass)
    m0 = doc["speed"]["tripod sliding"]["reference_peak_g"]
    doc["footpad_model_peak_difference"] = {k: abs(s["reference_peak_g"] / m0 - 1.0) for k, s in doc["speed"].items()
                                            if k.startswith("tripod sliding, ")}
    doc["uptime_after"] = subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()
    for name, s in doc["speed"].items():
        a = s["at_accuracy"]
        line = (f"rtol {a['rtol']:g}: peak error {a['peak_error']:.2e}, {a['ms_per_simulated_s']:.2f} ms per "
                f"simulated s ({a['wall_s'] * 1e3:.2f} ms for {a['t_end_s']:.3f} s, {a['steps']} steps, closure "
                f"{a['closure']:.1e})") if a else \
            "no rung within 0.1 %"
        print(f"{name:40s} {s['status']:8s} {line}")
    base, tri = doc["speed"]["telescoping nominal"]["at_accuracy"], doc["speed"]["tripod nominal"]["at_accuracy"]
    if base and tri:
        print(f"tripod / telescoping, nominal: {tri['ms_per_simulated_s'] / base['ms_per_simulated_s']:.2f}")
    if "first_compile_s" in doc:
        c = doc["first_compile_s"]
        print(f"first compile: telescoping {c['telescoping']:.1f} s, tripod {c['tripod']:.1f} s "
              f"(ratio {c['tripod'] / c['telescoping']:.2f})")
    for k, d in doc["footpad_model_peak_difference"].items():
        print(f"{k}: reference peak {d:.2e} from the 5 kg footpads'")
    print(doc["uptime_before"], "/", doc["uptime_after"])
    if args.json:
        args.json.write_text(json.dumps(doc, indent=1))


if __name__ == "__main__":
    main()
