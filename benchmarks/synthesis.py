"""Synthesis speed: one synthesis of the lunar example (its [synthesis] table with a reduced budget, no trade
curves, a 200-landing re-check) into a fresh folder on the local process pool with 2 workers and on a Dask
LocalCluster with 1 and 2 workers; wall time, landings computed, landings per second, the Dask speed-up of 2
workers over 1, and whether every backend chose the same design (it must: the search is seeded).

Usage: python benchmarks/synthesis.py [--generations 3] [--json FILE]
"""

from __future__ import annotations

import argparse
import json
import platform
import re
import tempfile
import time
from pathlib import Path

from alightsize.synthesis.search import synthesize

LANDER = Path(__file__).resolve().parent.parent / "examples" / "lunar_lander.toml"


def _budgeted(folder: Path, generations: int) -> Path:
    text = LANDER.read_text()
    text = re.sub(r"(?m)^generations = \d+$", f"generations = {generations}", text, count=1)
    text = re.sub(r"(?m)^check_samples = \d+$", "check_samples = 200", text, count=1)
    path = folder / "lunar_lander.toml"
    path.write_text(text)
    return path


def one(backend: str, workers: int, generations: int) -> dict:
    with tempfile.TemporaryDirectory() as tmp:
        lander = _budgeted(Path(tmp), generations)
        t0 = time.perf_counter()
        res = synthesize(lander, Path(tmp) / "out", trade=False, backend=backend, workers=workers)
        wall = time.perf_counter() - t0
    n = res.stats["landings_computed"]
    return {"backend": backend, "workers": workers, "wall_s": wall, "landings": n, "landings_per_s": n / wall,
            "candidates": res.stats["candidates"], "chosen_x": list(res.best.x), "weight_fraction": res.best.fraction,
            "ok": res.ok}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--generations", type=int, default=3)
    ap.add_argument("--json")
    args = ap.parse_args()
    # compile first
    synthesize(_budgeted(Path(tempfile.mkdtemp()), 0), Path(tempfile.mkdtemp()), trade=False, backend="serial")
    rows = [one("pool", 2, args.generations), one("dask", 1, args.generations), one("dask", 2, args.generations)]
    for r in rows:
        print(f"{r['backend']:5s} {r['workers']} workers: {r['wall_s']:7.1f} s, {r['landings']:6d} landings, "
              f"{r['landings_per_s']:6.1f} landings/s, {r['candidates']} candidates, "
              f"weight {100 * r['weight_fraction']:.4f} %")
    same = all(r["chosen_x"] == rows[0]["chosen_x"] for r in rows)
    print(f"Dask speed-up, 2 workers over 1: {rows[1]['wall_s'] / rows[2]['wall_s']:.2f}; same design on every "
          f"backend: {same}")
    if args.json:
        Path(args.json).write_text(json.dumps({"schema": "alightsize.bench-synthesis/1", "machine": platform.node(),
                                               "runs": rows, "same_design": same}, indent=2) + "\n")


if __name__ == "__main__":
    main()
