"""Benchmark: sizing alone, per sized item of a design: governing-factor evaluations and wall time.

The design is prepared first (envelopes, landing cases into --landings, resumable), then each item with a
`size` table is sized `--repeat` times; the count of Item.governing_factor calls and the median wall time
are per item.
Usage: python benchmarks/sizing.py CONFIG.toml [--landings DIR] [--repeat N] [--json FILE]
"""

from __future__ import annotations

import argparse
import json
import platform
import statistics
import time
from pathlib import Path

from alightsize.pipeline.sizing import size_item
from alightsize.pipeline.config import prepare
from alightsize.pipeline.items import Item
from alightsize.pipeline.lander import read_input


def _count_calls(item: Item) -> int:
    """Governing-factor evaluations made by one size_item(item)."""
    calls = 0
    original = Item.governing_factor

    def counted(self, section=None):
        nonlocal calls
        calls += 1
        return original(self, section)

    Item.governing_factor = counted
    try:
        size_item(item)
    finally:
        Item.governing_factor = original
    return calls


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("config")
    ap.add_argument("--landings", help="folder of the landing cases (resumable)")
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--json")
    args = ap.parse_args()
    cfg = prepare(read_input(args.config), Path(args.landings) if args.landings else None)
    rows = []
    for item in cfg.items:
        if item.size is None:
            continue
        times = []
        for _ in range(args.repeat):
            t0 = time.perf_counter()
            s = size_item(item)
            times.append(time.perf_counter() - t0)
        rows.append({"item": item.name, "dimension": s.dimension, "sized_m": s.sized, "design_factor": s.factor_sized,
                     "weight_kg": s.weight_sized, "feasible": s.feasible, "evaluations": _count_calls(item),
                     "wall_s": statistics.median(times)})
        print(f"{item.name:32s} {s.dimension:16s} {s.sized:.9g} m  f {s.factor_sized:.6g}  "
              f"W {s.weight_sized if s.weight_sized is None else round(s.weight_sized, 6)} kg  "
              f"{rows[-1]['evaluations']:4d} evaluations  {1e3 * rows[-1]['wall_s']:.2f} ms")
    total = sum(r["wall_s"] for r in rows)
    print(f"sizing alone: {1e3 * total:.2f} ms for {len(rows)} items")
    if args.json:
        out = {"schema": "alightsize.bench-sizing/1", "machine": {"python": platform.python_version()},
               "config": args.config, "items": rows, "total_wall_s": total}
        Path(args.json).write_text(json.dumps(out, indent=2) + "\n")


if __name__ == "__main__":
    main()
