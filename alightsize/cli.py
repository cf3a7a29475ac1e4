"""Command line: `alightsize design | audit | loads | simulate | sweep | synthesize | bench | scale | reports`
(see docs/contracts.md). Exit 0 ok, 1 check failed, 2 bad input, 3 internal error."""

from __future__ import annotations

import argparse
import json
import os
import sys
import traceback
import warnings
from pathlib import Path

from alightsize.common.version import __version__
from alightsize.common.errors import InputError, InputWarning
from alightsize.common.compile_notice import compile_notice
from alightsize.common.lock import output_folder
from alightsize.common.staging import Stage
from alightsize.common.resources import data_dir


def _wrote(stage: Stage, files: list[Path]) -> str:
    """The `wrote ...` line: each file at the path it has once published."""
    return "wrote " + ", ".join(str(stage.final(f)) for f in files)


def _design(args, stage: Stage) -> int:
    from alightsize.pipeline.design import run_design
    from alightsize.pipeline.lander import read_input
    from alightsize.reports.design_report import write_design
    res = run_design(read_input(args.config), Path(args.out) / "landings", progress=True)
    files = write_design(res, stage.path)
    lines = res.summary_lines(res.config.units)
    print(f"{res.config.configuration}: {lines[0]}")
    print("\n".join("  " + line for line in lines[1:]))
    print(_wrote(stage, files))
    return 0 if res.ok else 1


def _audit(args) -> int:
    from alightsize.common.atomic import write_atomic
    from alightsize.pipeline.audit import audit_table, junit_xml
    from alightsize.pipeline.design import audit, below_one_line
    from alightsize.pipeline.lander import read_input
    from alightsize.reports.design_report import audit_json
    res = audit(read_input(args.config))                # every section as written: sizing is `design`'s
    print(audit_table(res.records))
    print("OK" if res.checks_ok else "FAILED: " + ", ".join(r.failure_label for r in res.records if not r.ok))
    if res.below_one:
        print("note: " + below_one_line(res.below_one))
    if not res.landings_ok:                            # the audit judges design factors; say what else fails
        print(f"note: the design fails beyond its design factors ({res.verdict()}); see alightsize design")
    if args.json:
        write_atomic(args.json, json.dumps(audit_json(res), indent=2) + "\n")
    if args.junit:
        write_atomic(args.junit, junit_xml(res.config, res.records))
    return 0 if res.checks_ok else 1


def _loads(args, stage: Stage) -> int:
    import time
    from alightsize.loads.quasi_static import run_loads
    from alightsize.loads.config import read_loads
    from alightsize.reports.loads_report import write_loads
    cfg = read_loads(args.config)
    t0 = time.perf_counter()
    res = run_loads(cfg)
    wall = time.perf_counter() - t0
    n = sum(cfg.grid.size(c.psi_initial, c.psi_final) for c in cfg.cases)
    files = write_loads(res, stage.path, args.units)
    print(f"{len(cfg.cases)} configuration(s), {n:,} positions in {wall:.2f} s; "
          f"{len(cfg.combined)} combination(s){'; telescoping free body' if cfg.telescoping else ''}")
    print(_wrote(stage, files))
    return 0


def _simulate(args, stage: Stage) -> int:
    from alightsize.landings.output import land
    from alightsize.model.scene_config import read_scene
    from alightsize.reports.landing_report import write_landing
    cfg = read_scene(args.scene)
    landing = land(cfg)
    res, s = landing.result, landing.summary
    files = write_landing(landing, stage.path)
    print(f"{cfg.name}: {s['outcome']} at {s['t_end_s']:.4f} s ({s['reason']}); "
          f"peak XDD(3) {s['peak']['xdd_g'][2]:.2f} g; "
          f"energy closure {s['energy']['closure_rel']:.2e}; {res.steps} steps, {res.rhs_evals} evaluations, "
          f"{res.wall_s * 1e3:.1f} ms")
    print(_wrote(stage, files))
    return 1 if (args.require_success and s["outcome"] == "failed") else 0


def _sweep(args, stage: Stage) -> int:
    from alightsize.landings.study import read_study
    from alightsize.landings.sweep import run_sweep
    from alightsize.reports.sweep_report import write_results
    study = read_study(args.study)
    out = Path(args.out)
    backend, workers = _backend(args)
    where = ("" if backend == "serial" else f" at {args.scheduler}" if args.scheduler
             else f", {workers or os.cpu_count()} workers")
    print(f"{study.name}: {len(study.runs)} runs -> {out / 'runs.sqlite'} ({backend}{where})", flush=True)
    try:
        stats = run_sweep(study, out, backend, workers, args.scheduler, quiet=args.quiet)
    except KeyboardInterrupt:
        print(f"alightsize: interrupted; every finished run is stored in {out / 'runs.sqlite'}: "
              "run the same command again to finish", file=sys.stderr)
        return 130
    files = write_results(study, out, stage.path)
    print(f"{stats.computed} run(s) computed in {stats.wall_s:.1f} s, {stats.skipped} already done"
          f"{f' ({stats.reused} of them stored under another id)' if stats.reused else ''}, "
          f"{stats.failed} failed")
    print(_wrote(stage, files))
    failed = json.loads(files[0].read_text())["failed"]
    return 1 if (args.require_success and failed) else 0


def _backend(args) -> tuple[str, int | None]:
    """(backend, workers) of the --serial/--workers/--scheduler/--dask-local options."""
    backend = "serial" if args.serial else "dask" if (args.scheduler or args.dask_local) else "pool"
    workers = args.dask_local or args.workers
    if workers is not None and workers < 1:
        raise InputError("(command line)", "--workers/--dask-local", "a worker count >= 1", str(workers))
    return backend, workers


def _synthesize(args, stage: Stage) -> int:
    from alightsize.reports.synthesis_report import write_synthesis
    from alightsize.synthesis.search import synthesize
    from alightsize.synthesis.spec import parse_start, read_synthesis
    backend, workers = _backend(args)
    out = Path(args.out)
    spec = read_synthesis(args.lander)
    start = parse_start(spec, args.start)
    try:
        res = synthesize(spec, out, start, trade=not args.no_trade, backend=backend, workers=workers,
                         scheduler=args.scheduler, log=lambda msg: print(msg, flush=True), progress=True)
    except KeyboardInterrupt:
        print(f"alightsize: interrupted; every landing and candidate is stored in {out / 'runs.sqlite'}: "
              "run the same command again to resume", file=sys.stderr)
        return 130
    files = write_synthesis(res, stage.path)
    b, st = res.best, res.stats
    every = res.check_rates[-1] if res.check_rates else None
    print(f"{'PASS' if res.ok else 'FAIL'}: " + (f"lightest feasible system {100 * b.fraction:.3f} % of the capsule "
          f"({b.weight_kg:.4g} kg; start {100 * res.start.fraction:.3f} %"
          f"{' on the search sample' if res.check_rates else ''})" if b.feasible
          else "no candidate met every criterion within the bounds"))
    if every is not None:
        print(f"  fresh check: {every.passed} of {every.n} landings meet every criterion "
              f"(95 % interval {every.low:.4f} - {every.high:.4f})")
    for p, v in zip(res.spec.free, b.x):
        print(f"  {p.key} = {p.show(v)}")
    print(f"  {st['candidates']} candidates, {st['landings_computed']} landings computed, "
          f"{st['landings_stored']} found stored, {st['wall_s']:.0f} s")
    print(f"{_wrote(stage, files[:4])} and charts; the chosen design in {out / 'chosen'}")
    return 0 if res.ok else 1


def _bench(args, stage: Stage) -> int:
    from alightsize.landings.bench import run_bench
    from alightsize.reports.bench_report import write_bench
    data = run_bench(quick=args.quick, progress=lambda msg: print(msg, flush=True), only=tuple(args.scene or ()))
    files = write_bench(data, stage.path)
    print(_wrote(stage, files))
    return 0


def _scale(args) -> int:
    from alightsize.common.atomic import write_atomic
    from alightsize.weights.scaling import SCALE_RANGE, SCHEMA, table27
    low, high = SCALE_RANGE
    if not all(low <= v <= high for v in (args.length, args.mass)):      # NaN fails both comparisons
        raise InputError("(command line)", "--length/--mass", f"scale factors from {low:g} to {high:g}",
                         f"length {args.length:g}, mass {args.mass:g}")
    factors = table27(args.length, args.mass)
    width = max(map(len, factors))
    print(f"Model-to-full-scale factors (acceleration scale 1), length {args.length:g}, mass {args.mass:g}")
    for k, v in factors.items():
        print(f"  {k.replace('_', ' '):<{width}}  {v:.4g}")
    if args.json:
        doc = {"schema": SCHEMA, "length": args.length, "mass": args.mass, "factors": factors}
        write_atomic(args.json, json.dumps(doc, indent=2) + "\n")
    return 0


def _reports(args, stage: Stage) -> int:
    from alightsize.pipeline.design import run_design
    from alightsize.reports.design_report import write_design
    from alightsize.pipeline.config import read_design
    configs = sorted(Path(args.examples).glob("*.toml"))
    if not configs:
        raise InputError(args.examples, "", "a folder of design configs (*.toml)", "none")
    for cfg in configs:
        res = run_design(read_design(cfg))
        write_design(res, stage.path / cfg.stem)
        print(f"{cfg.stem}: {res.verdict()}")
    if (Path(args.examples) / "drops").is_dir():
        from alightsize.reports.drop_report import write_drop_report
        write_drop_report(stage.path / "drops", Path(args.examples) / "drops")
        print("drops: simulated drop tests beside Tables 6-13 (drops.html, drops.md, drops.json)")
    return 0


def _executor_options(p: argparse.ArgumentParser) -> None:
    """--out and where the landings run (the sweep executors)."""
    p.add_argument("--out", required=True, help="output folder (runs.sqlite is kept there and resumed)")
    p.add_argument("--workers", type=int, help="local process pool size (default: all cores)")
    p.add_argument("--serial", action="store_true", help="run in this process, one landing at a time")
    p.add_argument("--scheduler", help="address of a Dask distributed scheduler to run on")
    p.add_argument("--dask-local", type=int, metavar="N", help="start a local Dask cluster of N workers")


EXITS = ("exit status: 0 done (and PASS); 1 a check or criterion failed (design, audit, synthesize) or a landing "
         "failed where success was required; 2 bad input (the message names the file, the key path, what was "
         "expected and what was found); 3 internal error (please report it with the input)")

# each command: (one-line help, what it reads, does and writes; shown by `alightsize COMMAND --help`)
COMMANDS = {
    "design": ("design a landing system from a lander file or a design config",
               "Reads CONFIG.toml: a lander file ([lander] table; docs/reference/lander.md) or a design config "
               "([design] table; docs/reference/design.md). Runs the landing cases (stored and resumed in "
               "OUT/landings/), the load envelopes, every member's checks, the sizing of items with a `size` table, "
               "the weights and the verdict per criterion. Writes OUT/summary.json (alightsize.design/1), "
               "report.html, report.md, the workbooks (*.xlsx) and plots. Prints the verdict, the landing nearest to "
               "failing each criterion, the governing check with its margin of safety and the weight."),
    "audit": ("design-factor audit of the members as written (for CI)",
              "Reads CONFIG.toml (a lander file or a design config) and judges every member at the section written "
              "in the file (no sizing: that is `design`'s). Prints one line per check with its design factor and "
              "margin; --json writes alightsize.audit/1, --junit a JUnit XML report for CI."),
    "loads": ("quasi-static member-load envelopes over (alpha, beta, psi) (App. III)",
              "Reads CONFIG.toml (a loads config, docs/reference/loads.md, or a design config's [loads]). Solves "
              "the leg's equilibrium at every grid position and writes OUT/max_member_loads.json "
              "(alightsize.loads/1) and max_member_loads.xlsx."),
    "simulate": ("one landing of a scene",
                 "Reads SCENE.toml (docs/reference/scene.md; a lander file gives its nominal landing). Simulates "
                 "the landing to its outcome and writes OUT/summary.json (alightsize.simulate/1), "
                 "history.parquet and plots (accelerations, strokes, energy, footprints, shock spectrum)."),
    "sweep": ("a parametric or Monte Carlo study of landings (resumable run store)",
              "Reads STUDY.toml (docs/reference/study.md). Runs every landing of the study into OUT/runs.sqlite "
              "(an interrupted sweep resumes where it stopped) and writes OUT/outcomes.json (alightsize.sweep/1), "
              "outcomes.xlsx and report.html."),
    "synthesize": ("the lightest landing system meeting a lander file's requirements",
                   "Reads LANDER.toml with its [synthesis] table (docs/synthesis.md). Searches the free "
                   "parameters for the lightest system meeting every criterion, checks the winner on fresh "
                   "landings, and writes OUT/synthesis.json (alightsize.synthesis/1), report.html, report.md, "
                   "synthesis.xlsx, plots and OUT/chosen/ (the winner's design report); resumable in OUT."),
    "bench": ("landing simulator speed against error, with the solve_ivp-style baseline",
              "Times shipped scenes at several tolerances against a tight reference and a baseline timed in the "
              "same run; writes OUT/bench.json (alightsize.bench/1) and bench.html."),
    "scale": ("test-model scaling factors (Table 27)",
              "Prints the factors that scale a full-size landing to a drop-test model (acceleration scale 1); "
              "--json writes alightsize.scale/1."),
    "reports": ("regenerate the reference reports of the shipped examples",
                "Runs every design config of the 1966 examples and the drop tests and writes their reports "
                "(the reference reports shipped in reports/)."),
}


def _command(sub, name: str, run, **inputs: str) -> argparse.ArgumentParser:
    """A sub-command with its help, description and the exit statuses; `inputs` name its positional arguments."""
    short, long = COMMANDS[name]
    c = sub.add_parser(name, help=short, description=f"{short[0].upper()}{short[1:]}. {long}", epilog=EXITS)
    for arg, text in inputs.items():
        c.add_argument(arg, help=text)
    c.set_defaults(run=run)
    return c


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="alightsize", description=__doc__.split("(")[0].strip(), epilog=EXITS)
    p.add_argument("--version", action="version", version=f"alightsize {__version__}")
    sub = p.add_subparsers(dest="command", required=True)
    d = _command(sub, "design", _design, config="a lander file or a design config (TOML)")
    d.add_argument("--out", required=True, help="output folder (made if missing; landings are resumed from it)")
    a = _command(sub, "audit", _audit, config="a lander file or a design config (TOML)")
    a.add_argument("--json", help="write the audit as JSON (alightsize.audit/1)")
    a.add_argument("--junit", help="write a JUnit XML report")
    lo = _command(sub, "loads", _loads, config="a loads config or a design config (TOML)")
    lo.add_argument("--out", required=True, help="output folder")
    lo.add_argument("--units", choices=("US", "SI"), help="display units of the reports (default: the config's)")
    si = _command(sub, "simulate", _simulate, scene="a scene file or a lander file (TOML)")
    si.add_argument("--out", required=True, help="output folder")
    si.add_argument("--require-success", action="store_true", help="exit 1 when the landing fails numerically")
    sw = _command(sub, "sweep", _sweep, study="a study file (TOML)")
    _executor_options(sw)
    sw.add_argument("--quiet", action="store_true", help="no progress bar")
    sw.add_argument("--require-success", action="store_true", help="exit 1 when a run failed")
    sy = _command(sub, "synthesize", _synthesize, lander="a lander file with a [synthesis] table (TOML)")
    _executor_options(sy)
    sy.add_argument("--start", action="append", default=[], metavar="KEY=VALUE",
                    help="start a free parameter elsewhere than the file's value (repeatable)")
    sy.add_argument("--no-trade", action="store_true", help="skip the trade curves")
    b = _command(sub, "bench", _bench)
    b.add_argument("--out", required=True, help="output folder")
    b.add_argument("--quick", action="store_true", help="fewer scenes and settings")
    b.add_argument("--scene", action="append", metavar="NAME",
                   help="bench only this scene of the set (repeatable; e.g. flat_drop, telescoping_config2)")
    s = _command(sub, "scale", _scale)
    s.add_argument("--length", type=float, required=True, help="length scale, full / model")
    s.add_argument("--mass", type=float, required=True, help="mass scale, full / model")
    s.add_argument("--json", help="write the factors as JSON (alightsize.scale/1)")
    r = _command(sub, "reports", _reports)
    r.add_argument("--examples", default=str(data_dir("examples") / "affdl-tr-66-33"),
                   help="folder of design configs (default: the shipped 1966 examples)")
    r.add_argument("--out", default="reports/affdl-tr-66-33", help="output folder")
    return p


def _print_input_warnings() -> None:
    """Within a catch_warnings block: each distinct InputWarning once, as `alightsize: warning: FILE: KEY: ...`."""
    warnings.simplefilter("default", InputWarning)
    show = warnings.showwarning

    def _show(message: Warning | str, category: type[Warning], filename: str, lineno: int, file=None,
              line: str | None = None) -> None:
        if isinstance(message, InputWarning):
            print(f"alightsize: warning: {message}", file=sys.stderr)
        else:
            show(message, category, filename, lineno, file, line)
    warnings.showwarning = _show


def _writable(option: str, path: Path, folder: bool) -> None:
    """An output path that can be written, checked before any work: `path` a folder (or one to make) when
    `folder`, else a file in one; the nearest existing ancestor a writable folder."""
    if path.exists() and path.is_dir() != folder:
        raise InputError("(command line)", option, "a folder" if folder else "a file path", f"{str(path)!r}, "
                         + ("a file" if folder else "a folder"))
    base = path if folder else path.parent
    existing = next(p for p in (base, *base.parents) if p.exists())
    if not existing.is_dir() or not os.access(existing, os.W_OK | os.X_OK):
        raise InputError("(command line)", option, "a path in a writable folder", f"{str(path)!r}: {str(existing)!r} "
                         + ("is a file" if not existing.is_dir() else "is not writable"))


def _check_outputs(args) -> None:
    for option, folder in (("out", True), ("json", False), ("junit", False)):
        value = getattr(args, option, None)
        if value:
            _writable(f"--{option}", Path(value), folder)


def main(argv: list[str] | None = None) -> int:
    args = parser().parse_args(argv)
    try:
        with warnings.catch_warnings(), compile_notice():
            _print_input_warnings()
            _check_outputs(args)
            if getattr(args, "out", None) is None:
                return args.run(args)
            with output_folder(Path(args.out)) as stage:
                code = args.run(args, stage)
                if code in (0, 1):                 # written whole (a failed check included): publish
                    stage.publish()
                return code
    except InputError as exc:
        print(f"alightsize: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("alightsize: interrupted", file=sys.stderr)
        return 130
    except Exception:  # noqa: BLE001 - last resort: exit 3 with the trace for a bug report
        traceback.print_exc()
        print("alightsize: internal error (exit 3); please report it with the input", file=sys.stderr)
        return 3
