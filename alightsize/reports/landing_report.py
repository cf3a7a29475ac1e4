"""Writing one landing (`alightsize simulate`): summary.json (alightsize.simulate/1), history.parquet and the
charts of its LandingResult."""

from __future__ import annotations

import json
from pathlib import Path

from alightsize.common.atomic import write_atomic
from alightsize.common.figures import save_png
from alightsize.landings.output import LandingResult

PNGS = {"xdd": "xdd.png", "omd": "omd.png", "strokes": "strokes.png", "energy": "energy.png",
        "footprints": "footprints.png", "srs_xdd3": "srs_xdd3.png"}


def plots(res: LandingResult, out: Path) -> list[Path]:
    """Every chart of the landing as a PNG in `out` (no shock spectrum for a landing that ended at its start)."""
    kinds = [k for k in PNGS if k != "srs_xdd3" or res.result.t[-1] > 0]
    return [write_atomic(out / PNGS[k], lambda p, k=k: save_png(res.plot(k), p, 110)) for k in kinds]


def write_landing(res: LandingResult, out: Path) -> list[Path]:
    """summary.json, history.parquet and the charts in `out`, each written atomically."""
    out.mkdir(parents=True, exist_ok=True)
    files = [write_atomic(out / "summary.json", json.dumps(res.summary, indent=2) + "\n"),
             write_atomic(out / "history.parquet", lambda tmp: res.history.to_parquet(tmp, index=False))]
    return files + plots(res, out)
