"""Sweep backends against each other (issue 6): one Monte Carlo study of N runs (default 200 landings of
configuration 5 on a 10 deg slope) on the local pool with 1 and 2 workers and on a 2-worker Dask
LocalCluster; speed-up of 2 workers over 1; overhead per run (worker time not spent landing); Dask's
dispatch overhead per task measured on a running cluster with no-op tasks; cluster start-up separately.

Usage: python benchmarks/sweep_backends.py [-n 200] [--study PATH] [--json FILE]
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import platform
import sqlite3
import tempfile
import time
from pathlib import Path

from alightsize.landings.study import read_study
from alightsize.landings.sweep import run_sweep

STUDY = Path(__file__).resolve().parent.parent / "examples" / "affdl-tr-66-33" / "studies" / "config5_monte_carlo.toml"


def _noop(x: int) -> int:
    return x


def one(study, backend: str, workers: int) -> dict:
    """Wall time of the whole sweep into a fresh folder, and the overhead per run beyond the landings."""
    with tempfile.TemporaryDirectory() as tmp:
        t0 = time.perf_counter()
        stats = run_sweep(study, Path(tmp), backend, workers, quiet=True)
        wall = time.perf_counter() - t0
        busy = sqlite3.connect(Path(tmp) / "runs.sqlite").execute("SELECT sum(wall_s) FROM runs").fetchone()[0]
    n = stats.computed
    return {"backend": backend, "workers": workers, "runs": n, "failed": stats.failed, "wall_s": wall,
            "landing_s": busy, "overhead_per_run_ms": 1e3 * (wall * workers - busy) / n}


def dask_dispatch(tasks: int = 2000) -> dict:
    """Start-up of a 2-worker LocalCluster and the round trip per no-op task once it runs."""
    from distributed import Client, LocalCluster
    t0 = time.perf_counter()
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    client = Client(cluster)
    startup = time.perf_counter() - t0
    client.gather(client.map(_noop, range(100), pure=False))        # warm
    t0 = time.perf_counter()
    client.gather(client.map(_noop, range(tasks), pure=False))
    per = (time.perf_counter() - t0) / tasks
    client.close()
    cluster.close()
    return {"startup_s": startup, "per_task_ms": 1e3 * per, "tasks": tasks}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-n", type=int, default=200, help="runs (Monte Carlo samples)")
    ap.add_argument("--study", type=Path, default=STUDY)
    ap.add_argument("--json", type=Path)
    a = ap.parse_args()
    study = read_study(a.study)
    study = dataclasses.replace(study, runs=study.runs[:a.n])
    one(dataclasses.replace(study, runs=study.runs[:2]), "serial", 1)   # load the compiled simulator first
    cases = [one(study, "pool", 1), one(study, "pool", 2), one(study, "dask", 2)]
    out = {"machine": platform.processor() or platform.machine(), "study": str(a.study), "cases": cases,
           "speedup_2_over_1": cases[0]["wall_s"] / cases[1]["wall_s"], "dask": dask_dispatch()}
    print(json.dumps(out, indent=1))
    if a.json:
        a.json.write_text(json.dumps(out, indent=1) + "\n")


if __name__ == "__main__":
    main()
