"""alightsize: landing-leg design toolkit after AFFDL-TR-66-33 (1966).

The Python API (the CLI is a thin layer over it)::

    import alightsize
    cfg = alightsize.read_design("examples/affdl-tr-66-33/telescoping.toml")
    res = alightsize.design(cfg)                 # or alightsize.design(path)
    res.ok, res.verdict()                        # the verdict on every check and landing
    tables = res.to_pandas()                     # {"checks", "weights"[, "landings"]} DataFrames, SI
    res.plot("factors")                          # a matplotlib Figure
    alightsize.write_design(res, "out/tel")      # summary.json, report.html/.md, design.xlsx, charts
"""

from __future__ import annotations

from pathlib import Path

__version__ = "0.1.0"


def read_design(path: str | Path):
    """Read and validate a design config (TOML); bad input raises alightsize.common.errors.InputError naming
    the file, key path, what was expected and what was found. Its landing cases, if any, run here."""
    from alightsize.pipeline.config import read_design as _read
    return _read(path)


def design(config, out: str | Path | None = None):
    """Run the design pipeline (sizing, checks, weights, verdict) on a config or a path to one; with `out`
    also write the reports there. Returns a DesignResult (`.ok`, `.verdict()`, `.to_pandas()`, `.plot()`)."""
    from alightsize.pipeline.design import run_design
    res = run_design(read_design(config) if isinstance(config, (str, Path)) else config)
    if out is not None:
        write_design(res, out)
    return res


def write_design(result, out: str | Path) -> list[Path]:
    """Write a DesignResult's reports into folder `out` (each file atomically); returns the paths."""
    from alightsize.reports.design_report import write_design as _write
    return _write(result, Path(out))
