"""Monte Carlo landings of the lunar tripod example, a telescoping baseline timed in the same run.

Each example's `[requirements.monte_carlo]` draws (`alightsize.pipeline.lander.landing_cases`: speeds, heading,
roll, slope, friction and every cell's crushing force scattered over the lander file's envelope), N of them
(`requirements.monte_carlo.samples` set to N), landed as `alightsize sweep` lands a study's runs: its process pool
(`alightsize.landings.sweep.run_tasks`, the simulator compiled before the workers fork), no history files, into
a fresh run store in a temporary folder, two landings run first in this process (untimed) so that the
workers inherit the compiled simulator. examples/lunar_lander.toml (telescoping) is the baseline: same capsule,
stance and envelope. Prints, per example, the wall time of the N landings, their outcome counts and the per-landing
wall time, then the tripod / telescoping ratio and `uptime` (the machine's load, which the figures depend on).
Usage: python benchmarks/tripod_monte_carlo.py [-n 1000] [--workers 2] [--json FILE]
"""

from __future__ import annotations

import argparse
import json
import subprocess
import tempfile
import time
from collections import Counter
from pathlib import Path

import numpy as np

from alightsize.landings.run_store import RunStore
from alightsize.landings.sweep import run_tasks, task_of
from alightsize.pipeline.lander import read_lander

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = {"telescoping": ROOT / "examples" / "lunar_lander.toml", "tripod": ROOT / "examples" / "lunar_tripod.toml"}


def monte_carlo(path: Path, n: int, workers: int) -> dict:
    """Land the first n Monte Carlo draws of the lander file at `path` on `workers` processes."""
    study = read_lander(path, {"requirements.monte_carlo.samples": n}).study
    runs = [r for r in study.runs if not r.run_id.startswith("corner")]
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp)
        tasks = [{**task_of(study, r, out), "history": None} for r in runs]
        run_tasks(tasks[:2], out / "warm", "serial", quiet=True)     # compiled here, untimed: the workers fork it
        t0 = time.perf_counter()
        stats = run_tasks(tasks, out, "pool", workers, quiet=True)
        wall = time.perf_counter() - t0
        store = RunStore(out / "runs.sqlite")
        rows = store.rows([r.run_id for r in runs])
        store.close()
    walls = np.array([r["wall_s"] for r in rows])
    t_end = np.array([r.get("t_end_s") or 0.0 for r in rows])
    return {"landings": len(runs), "failed": stats.failed, "wall_s": wall,
            "outcomes": dict(Counter(str(r.get("outcome")) for r in rows)),
            "criteria_ok": sum(bool(r.get("criteria_ok")) for r in rows),
            "landing_wall_ms": {"median": 1e3 * float(np.median(walls)), "p95": 1e3 * float(np.percentile(walls, 95)),
                                "max": 1e3 * float(walls.max())},
            "simulated_s_mean": float(t_end.mean())}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-n", type=int, default=1000)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--json", type=Path)
    a = ap.parse_args()
    out: dict = {"n": a.n, "workers": a.workers, "uptime_before": subprocess.run(["uptime"], capture_output=True,
                                                                                 text=True).stdout.strip()}
    for name, path in EXAMPLES.items():
        out[name] = monte_carlo(path, a.n, a.workers)
        print(name, json.dumps(out[name]), flush=True)
    out["ratio_tripod_over_telescoping"] = out["tripod"]["wall_s"] / out["telescoping"]["wall_s"]
    out["uptime_after"] = subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()
    print(json.dumps({k: v for k, v in out.items() if k not in EXAMPLES}, indent=1))
    if a.json:
        a.json.write_text(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
