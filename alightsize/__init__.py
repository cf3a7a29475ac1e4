"""alightsize: landing-leg design toolkit after AFFDL-TR-66-33 (1966).

The Python API (the CLI is a thin layer over it)::

    import alightsize
    lander = alightsize.read_lander("examples/lunar_lander.toml")
    res = alightsize.design(lander)              # or alightsize.design(path), or a design config
    res.ok, res.verdict()                        # the verdict on every check and landing
    tables = res.to_pandas()                     # {"checks", "weights"[, "landings"]} DataFrames, SI
    res.plot("factors")                          # a matplotlib Figure
    alightsize.write_design(res, "out/tel")      # summary.json, report.html/.md, design.xlsx, charts

Every command has its function, each returning a result object with `.to_pandas()` (its tables: SI, the unit in
each column name, as docs/contracts.md names the JSON fields) and `.plot(kind)` (a matplotlib Figure):
`design`, `audit`, `loads`, `simulate`, `sweep` and `synthesize`. Nothing runs or is imported at import time.
"""

from __future__ import annotations

from pathlib import Path

from alightsize.common.version import __version__

__all__ = ["__version__", "audit", "design", "loads", "read_design", "read_lander", "simulate", "sweep", "synthesize",
           "write_design"]


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
    `.summary_lines()`, `.to_pandas()`: "checks", "weights", "landings", "sizing", "load_references";
    `.plot()`: "factors", "weights").

        res = alightsize.design("examples/affdl-tr-66-33/telescoping.toml")
        res.verdict(), res.to_pandas()["checks"][["item", "design_factor", "ok"]]
    """
    from alightsize.pipeline.design import run_design
    spec = _design_spec(config)
    res = run_design(spec, Path(out) / "landings" if out is not None else None, progress)
    if out is not None:
        write_design(res, out)
    return res


def write_design(result, out: str | Path) -> list[Path]:
    """Write a DesignResult's reports into folder `out` (each file atomically); returns the paths."""
    from alightsize.reports.design_report import write_design as _write
    return _write(result, Path(out))


def _design_spec(config):
    """A design as read: a path read with `read_design`, a lander's design, or a design config as given."""
    return read_design(config) if isinstance(config, (str, Path)) else getattr(config, "spec", config)


def audit(config):
    """The design-factor audit (`alightsize audit`): every member of a lander file or design config (a path, or
    as read) judged at the section written in the file, never sized. Returns a DesignResult; its
    `to_pandas()["checks"]` is the audit JSON's `checks`.

        res = alightsize.audit("examples/affdl-tr-66-33/telescoping.toml")
        res.checks_ok, res.to_pandas()["checks"][["item", "check", "design_factor"]]
    """
    from alightsize.pipeline.design import audit as _audit
    return _audit(_design_spec(config))


def run_loads_envelopes(config, out: str | Path | None = None, units: str | None = None):
    """The quasi-static member-load envelopes (`alightsize loads`, App. III) of a loads config or a design
    config's [loads] (a path, or a LoadsConfig as read); with `out` also write max_member_loads.json/.xlsx, the
    heat maps and the report there (display `units` "US" or "SI", default the config's). Returns a LoadsResult:
    `to_pandas()` gives "envelopes" (and "telescoping"), `.plot(configuration)` a heat map.

        res = alightsize.loads("examples/affdl-tr-66-33/loads/articulated.toml")
        env = res.to_pandas()["envelopes"]; fig = res.plot("9")

    (`alightsize.loads` is this function until the package alightsize.loads is imported, then that package,
    which calls this function when called.)
    """
    from alightsize.loads.config import read_loads
    from alightsize.loads.quasi_static import run_loads
    res = run_loads(read_loads(config) if isinstance(config, (str, Path)) else config)
    if out is not None:
        from alightsize.reports.loads_report import write_loads
        write_loads(res, Path(out), units)
    return res


loads = run_loads_envelopes


def simulate(scene, out: str | Path | None = None):
    """One landing (`alightsize simulate`) of a scene file, a lander file (its nominal landing) or a scene as
    read (`read_scene`); with `out` also write summary.json, history.parquet and the charts there. Returns a
    LandingResult: `.summary` (the summary.json document), `to_pandas()` ("history", "cells", "legs", "peak",
    "energy", "solver", "srs") and `.plot(kind)` ("xdd", "omd", "strokes", "energy", "footprints", "srs_xdd3").

        res = alightsize.simulate("examples/affdl-tr-66-33/scenes/telescoping_config2.toml")
        res.summary["outcome"], res.to_pandas()["history"]["xdd3_g"].abs().max()
    """
    from alightsize.landings.output import land
    from alightsize.model.scene_config import read_scene
    res = land(read_scene(scene) if isinstance(scene, (str, Path)) else scene)
    if out is not None:
        from alightsize.reports.landing_report import write_landing
        write_landing(res, Path(out))
    return res


def sweep(study, out: str | Path, backend: str = "pool", workers: int | None = None, scheduler: str | None = None,
          quiet: bool = True):
    """A parametric or Monte Carlo study (`alightsize sweep`) of a study file (or a Study as read): every run not
    yet stored in `out`/runs.sqlite is landed (backend "serial", "pool" or "dask"), then outcomes.json,
    outcomes.xlsx and report.html are written to `out`. Returns a SweepResult: `.document` (outcomes.json),
    `to_pandas()` ("runs", "outcomes") and `.plot(kind)` ("boundary", "distributions").

        res = alightsize.sweep("examples/affdl-tr-66-33/studies/table2.toml", "out/t2", backend="serial")
        res.to_pandas()["outcomes"]
    """
    from alightsize.landings.outcomes import SweepResult
    from alightsize.landings.study import read_study
    from alightsize.landings.sweep import run_sweep
    from alightsize.reports.sweep_report import write_results
    study = read_study(study) if isinstance(study, (str, Path)) else study
    run_sweep(study, Path(out), backend, workers, scheduler, quiet=quiet)
    write_results(study, Path(out))
    return SweepResult.load(study, Path(out))


def synthesize(lander: str | Path, out: str | Path, start: dict[str, float] | None = None, trade: bool = True,
               backend: str = "pool", workers: int | None = None, scheduler: str | None = None):
    """The lightest landing system (`alightsize synthesize`) meeting a lander file's requirements over its
    [synthesis.free] parameters (`start`: SI starting values by key); resumable in `out`, where the reports are
    written (synthesis.json, report.html/.md, synthesis.xlsx, charts, chosen/). Returns a SynthesisResult:
    `.ok`, `to_pandas()` ("candidates", "convergence", "trade", "check") and `.plot(kind)` ("convergence",
    "pareto", or a trade axis).

        res = alightsize.synthesize("examples/lunar_lander.toml", "out/syn", trade=False)
        res.to_pandas()["convergence"]
    """
    from alightsize.reports.synthesis_report import write_synthesis
    from alightsize.synthesis.search import synthesize as _synthesize
    res = _synthesize(lander, Path(out), start, trade=trade, backend=backend, workers=workers, scheduler=scheduler)
    write_synthesis(res, Path(out))
    return res
