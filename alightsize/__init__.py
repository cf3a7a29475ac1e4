"""alightsize: landing-leg design toolkit after AFFDL-TR-66-33 (1966).

The Python API (the CLI is a thin layer over it)::

    import alightsize
    lander = alightsize.read_lander("examples/lunar_lander.toml")
    res = alightsize.design(lander)              # or alightsize.design(path), or a design config
    res.ok, res.verdict()                        # the verdict on every check and landing
    tables = res.to_pandas()                     # {"checks", "weights"[, "landings"]} DataFrames, SI
    res.plot("factors")                          # a matplotlib Figure
    alightsize.write_design(res, "out/tel")      # summary.json, report.html/.md, design.xlsx, charts
"""

from __future__ import annotations

from importlib.metadata import PackageNotFoundError, version
from pathlib import Path

__all__ = ["__version__", "design", "read_design", "read_lander", "write_design"]

try:
    __version__ = version("alightsize")
except PackageNotFoundError:                           # run from a source tree without installing
    __version__ = "0+unknown"


def read_lander(path: str | Path):
    """Read and validate a lander file (TOML): capsule, gravity, legs, cells, members and requirements. Bad
    input raises alightsize.common.errors.InputError naming the file, key path, what was expected and what was
    found. Nothing runs until `design`."""
    from alightsize.pipeline.lander import read_lander as _read
    return _read(path)


def read_design(path: str | Path):
    """Read and validate a design config (the App. IV item schema) or, given a lander file, its design. Nothing
    runs until `design`."""
    from alightsize.pipeline.lander import read_input
    return read_input(path)


def design(config, out: str | Path | None = None, progress: bool = False):
    """Run the design pipeline on a lander (from `read_lander`), a design config or a path to either: App. III
    envelopes, landing cases (stored in `out`/landings, resumable), member loads, checks and sizing, weights,
    verdict; with `out` also write the reports there. Returns a DesignResult (`.ok`, `.verdict()`,
    `.summary_lines()`, `.to_pandas()`, `.plot()`)."""
    from alightsize.pipeline.design import run_design
    spec = read_design(config) if isinstance(config, (str, Path)) else getattr(config, "spec", config)
    res = run_design(spec, Path(out) / "landings" if out is not None else None, progress)
    if out is not None:
        write_design(res, out)
    return res


def write_design(result, out: str | Path) -> list[Path]:
    """Write a DesignResult's reports into folder `out` (each file atomically); returns the paths."""
    from alightsize.reports.design_report import write_design as _write
    return _write(result, Path(out))
