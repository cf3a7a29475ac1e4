"""Benchmark: member-load envelope of one configuration on the default grid, one core.

Times `envelope()` (closed form eq. 59-61 + back substitution, vectorized) and, for the same positions,
the 6x6 route of eq. 96-97 (batched LAPACK solves), with the largest difference between the two.
Usage: python benchmarks/loads_envelope.py [--repeat N] [--json FILE]
"""

from __future__ import annotations

import os

for _v in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_v] = "1"                       # one core, as the issue asks

import argparse  # noqa: E402
import json  # noqa: E402
import platform  # noqa: E402
import statistics  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

from alightsize.loads.envelopes import cell_forces, envelope  # noqa: E402
from alightsize.loads.config import read_loads  # noqa: E402
from alightsize_sim.articulated_statics import reactions  # noqa: E402

CONFIG = Path(__file__).resolve().parent.parent / "examples" / "affdl-tr-66-33" / "loads" / "articulated.toml"


def _median_time(fn, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=7)
    ap.add_argument("--json")
    args = ap.parse_args()
    cfg = read_loads(CONFIG)
    case = cfg.cases[0]
    n = cfg.grid.size(case.psi_initial, case.psi_final)
    envelope(case, cfg.grid)                                   # warm-up
    t_env = _median_time(lambda: envelope(case, cfg.grid), args.repeat)
    psi = cfg.grid.psi(case.psi_initial, case.psi_final)
    P, A, B = np.meshgrid(psi, np.asarray(cfg.grid.alpha), np.asarray(cfg.grid.beta), indexing="ij")
    af1, af2 = cell_forces(case, A, P)
    t_closed = _median_time(lambda: reactions(case.geometry, A, B, P, af1, af2), args.repeat)
    t_matrix = _median_time(lambda: reactions(case.geometry, A, B, P, af1, af2, method="matrix"),
                            max(1, args.repeat // 3))
    rc = reactions(case.geometry, A, B, P, af1, af2)
    rm = reactions(case.geometry, A, B, P, af1, af2, method="matrix")
    scale = np.maximum(np.maximum(af1, af2), 1.0)
    diff = max(float(np.max(np.abs(getattr(rc, k) - getattr(rm, k)) / scale))
               for k in ("F1", "F3", "Q1", "Q2", "R11", "R12"))
    out = {"schema": "alightsize.landings.bench-loads/1",
           "machine": {"python": platform.python_version(), "numpy": np.__version__, "cores_used": 1},
           "configuration": case.name, "positions": n, "envelope_wall_s": t_env,
           "positions_per_s": n / t_env, "reactions_closed_wall_s": t_closed, "reactions_matrix_wall_s": t_matrix,
           "closed_vs_matrix_max_rel": diff}
    for k, v in out.items():
        print(f"{k:28s} {v}")
    if args.json:
        Path(args.json).write_text(json.dumps(out, indent=2) + "\n")


if __name__ == "__main__":
    main()
