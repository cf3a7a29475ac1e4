"""`alightsize sweep`: run a study's landings on a backend (serial, local process pool, Dask distributed) into
the run store, skipping runs already done with the same inputs.

A run is a pure function of its task (scene as read, overrides, criteria), so results are identical whatever
the backend, worker count or order. The parent process alone writes the store, one commit per finished
run. A run that raises is stored `failed` with its message; a worker that dies takes no finished run with
it (the runs it held are retried alone, and one that kills its worker twice is stored `failed`).
"""

from __future__ import annotations

import dataclasses
import json
import multiprocessing
import os
import signal
import sys
import time
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Iterable, Iterator

from alightsize.common.errors import InputError
from alightsize.landings.run_store import RunStore
from alightsize.landings.study import Run, Study, agrees, outcome_class, parameter_columns, scene_hash

# (scene config, landing result) -> member-load extremes along the history, stored as JSON with each run
MemberLoads = Callable[[object, object], dict]     # (scene config, result) -> {column stem: JSON-able}


@dataclass(frozen=True)
class SweepStats:
    total: int
    skipped: int               # already stored done with the same inputs (`reused` of them under another id)
    computed: int
    failed: int
    wall_s: float
    backend: str
    reused: int = 0


def task_of(study: Study, run: Run, out: Path, member_loads: MemberLoads | None = None) -> dict:
    """What a worker needs for one run (picklable, no open handles); with `member_loads` (a module-level
    function or a partial of one) the run also stores the loads it gives for the history, each under its key +
    "_json" (`alightsize.loads.interface.landing_loads`: member_loads_json, interface_loads_json)."""
    history = str(out / "history" / f"{run.run_id}.parquet") if study.history else None
    return {"run_id": run.run_id, "scene_key": run.scene_key, "scene": run.scene, "overrides": run.overrides,
            "scene_hash": scene_hash(run) + ("" if member_loads is None else "+loads+interface"), "params": run.params,
            "reference": run.reference, "criteria": study.criteria, "history": history,
            "member_loads": member_loads}


NEWEST_FIGURE = "peak_nutation_deg"    # the last column `_figures` gained: a stored row without it lands again


def _figures(s: dict) -> dict:
    """The summary figures of one landing as flat, unit-suffixed columns (docs/contracts.md)."""
    row = {"outcome": s["outcome"], "reason": s["reason"], "t_end_s": s["t_end_s"]}
    for name, key, unit in (("xdd", "xdd_g", "g"), ("omd", "omd_rad_s2", "rad_s2"), ("onset_xdd", "onset_g_s", "g_s")):
        for i, v in enumerate(s["peak"][key]):
            row[f"peak_{name}{i + 1}_{unit}"] = float(v)
    cells = [c for leg in s["legs"] for c in leg["cells"]]
    row["peak_nutation_deg"] = s["peak"]["nutation_deg"]
    row["max_stroke_m"] = max(c["max_deflection_m"] for c in cells)
    row["max_ground_force_N"] = max(leg["max_ground_force_N"] for leg in s["legs"])
    row["any_bottomed"] = int(any(c["bottomed"] for c in cells))
    for k in ("initial_J", "absorbed_J", "elastic_J", "friction_J", "kinetic_end_J", "potential_change_J"):
        row[f"energy_{k}"] = s["energy"][k]
    row["closure_rel"] = s["energy"]["closure_rel"]
    row["cells_json"] = json.dumps(s["legs"])
    row["steps"], row["rhs_evals"] = s["solver"]["steps"], s["solver"]["rhs_evals"]
    return row


def _judged(row: dict, task: dict) -> dict:
    """The columns that depend on the study rather than on the landing: agreement with the printed class and
    the criteria (judged on the stored peaks and outcome, so a changed criterion needs no new landing)."""
    out = {"agrees": None if task["reference"] is None else int(agrees(row["outcome_class"], task["reference"]))}
    if task["criteria"] is not None:
        peak = {"xdd_g": [row[f"peak_xdd{i}_g"] for i in (1, 2, 3)],
                "onset_g_s": [row[f"peak_onset_xdd{i}_g_s"] for i in (1, 2, 3)]}
        failures = task["criteria"].failures({"peak": peak, "outcome": row["outcome"]})
        out["criteria_ok"], out["criteria_failed"] = int(not failures), "; ".join(failures)
    return out


def _inputs(task: dict) -> dict:
    """The columns a run's row has whatever becomes of it: id, scene, inputs hash, parameters."""
    return {"run_id": task["run_id"], "scene": task["scene_key"], "scene_hash": task["scene_hash"],
            **parameter_columns(task["overrides"]), "params_json": json.dumps(task["params"], default=str),
            "reference_class": task["reference"]}


def execute(task: dict) -> dict:
    """One run: read its scene, land it, summarize. Any exception becomes a `failed` row with its message."""
    from alightsize_sim.landing import simulate
    from alightsize.common.atomic import write_atomic
    from alightsize.landings.output import history_frame, summary
    from alightsize.model.scene_config import read_scene
    row = {**_inputs(task), "worker": f"{os.uname().nodename}:{os.getpid()}"}
    t0 = time.perf_counter()
    try:
        cfg = read_scene(task["scene"], task["overrides"])
        res = simulate(cfg.scene, cfg.controls)
        s = summary(cfg, res)
        row.update(_figures(s))
        row["outcome_class"] = outcome_class(cfg, res)
        row.update(_judged(row, task))
        if task["member_loads"] is not None:
            row.update({f"{k}_json": json.dumps(v) for k, v in task["member_loads"](cfg, res).items()})
        if task["history"]:
            frame = history_frame(cfg, res)
            write_atomic(task["history"], lambda p: frame.to_parquet(p, index=False))
            row["history_file"] = f"history/{Path(task['history']).name}"
        row["status"], row["message"] = "done", ""
    except InputError as exc:
        row.update(status="failed", outcome=None, message=f"bad input: {exc}")
    except Exception as exc:                           # noqa: BLE001 - stored with the run, the study goes on
        row.update(status="failed", outcome=None, message=f"{type(exc).__name__}: {exc}")
    row["wall_s"] = time.perf_counter() - t0
    row["finished_at"] = time.time()
    return row


def _serial(tasks: list[dict]) -> Iterator[dict]:
    for t in tasks:
        yield execute(t)


def _pool_context() -> multiprocessing.context.BaseContext:
    """fork where there is one (workers inherit the compiled simulator), spawn elsewhere."""
    methods = multiprocessing.get_all_start_methods()
    return multiprocessing.get_context("fork" if "fork" in methods else "spawn")


def _died(task: dict) -> dict:
    return {**_inputs(task), "status": "failed", "outcome": None,
            "message": "the worker process died while running it (twice)", "wall_s": 0.0, "worker": "",
            "finished_at": time.time()}


def _ignore_sigint() -> None:
    signal.signal(signal.SIGINT, signal.SIG_IGN)       # Ctrl-C is the parent's to handle


def _executor(workers: int) -> ProcessPoolExecutor:
    return ProcessPoolExecutor(workers, mp_context=_pool_context(), initializer=_ignore_sigint)


def _warm(task: dict) -> None:
    """Compile the simulator for a task's scene here, before the workers start: forked workers inherit it (spawned
    ones load it from numba's disk cache) instead of each compiling it. A 10 us landing; any error is left for
    the task itself to report."""
    from alightsize_sim.landing import simulate
    from alightsize.model.scene_config import read_scene
    try:
        cfg = read_scene(task["scene"], task["overrides"])
        simulate(cfg.scene, dataclasses.replace(cfg.controls, t_final=1e-5))
    except Exception:                                  # noqa: BLE001 - the task's own run reports it
        pass


def _pool(tasks: list[dict], workers: int) -> Iterator[dict]:
    """A local process pool, the simulator compiled before it forks; after a worker dies, the runs it may have
    held are retried one at a time."""
    pending, suspects = list(tasks), []
    _warm(pending[0])
    while pending or suspects:
        if suspects:                                   # alone in a fresh worker: a crash now is this run's
            task, pool = suspects.pop(0), _executor(1)
            try:
                yield pool.submit(execute, task).result()
            except BrokenProcessPool:
                yield _died(task)
            finally:
                pool.shutdown(wait=False, cancel_futures=True)
            continue
        pool = _executor(workers)
        futures = {pool.submit(execute, t): k for k, t in enumerate(pending)}
        left, broken = set(futures), []
        try:
            while left and not broken:
                finished, left = wait(left, return_when=FIRST_COMPLETED)
                for f in sorted(finished, key=futures.get):
                    if f.exception() is None:
                        yield f.result()
                    else:
                        broken.append(f)
        finally:
            pool.shutdown(wait=False, cancel_futures=True)
        order = sorted(futures[f] for f in left | set(broken))     # the pool hands out tasks in order:
        suspects = [pending[k] for k in order[:workers + 1]]        # the first unfinished ones were running
        pending = [pending[k] for k in order[workers + 1:]]


def _dask(tasks: list[dict], workers: int, scheduler: str | None) -> Iterator[dict]:
    """Dask distributed: an existing scheduler, or a local cluster of `workers` single-threaded processes."""
    try:
        from distributed import Client, LocalCluster, as_completed
    except ImportError:
        raise InputError("(command line)", "--scheduler/--dask-local", "dask.distributed installed "
                         "(pip install 'alightsize[dask]')", "it is not installed") from None
    cluster = None if scheduler else LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                                  dashboard_address=None)
    try:
        try:
            client = Client(scheduler or cluster, timeout="20s")
        except (OSError, TimeoutError) as exc:
            raise InputError("(command line)", "--scheduler", "the address of a running Dask scheduler",
                             f"{scheduler!r} ({exc})") from None
        with client:
            keys = [f"run-{t['run_id']}" for t in tasks]
            by_key = dict(zip(keys, tasks))
            futures = client.map(execute, tasks, pure=False, key=keys)
            try:
                for f in as_completed(futures):
                    try:
                        yield f.result()
                    except Exception as exc:           # noqa: BLE001 - e.g. KilledWorker: stored, study goes on
                        yield {**_died(by_key[f.key]), "message": f"{type(exc).__name__}: {exc}"}
            finally:
                client.cancel(futures)
    finally:
        if cluster is not None:
            cluster.close()


def _progress(total: int, quiet: bool):
    """A tqdm bar with rate and ETA on a terminal; nothing when quiet or not a terminal (CI logs)."""
    from tqdm import tqdm
    tqdm.monitor_interval = 0                          # no monitor thread: the pool forks
    return tqdm(total=total, unit="run", disable=quiet or not sys.stderr.isatty(), dynamic_ncols=True,
                smoothing=0.05)


def run_sweep(study: Study, out: Path, backend: str = "pool", workers: int | None = None,
              scheduler: str | None = None, quiet: bool = False,
              on_row: Callable[[dict], None] | None = None, member_loads: MemberLoads | None = None) -> SweepStats:
    """Run every run of the study not already done into out/runs.sqlite; return the counts. With
    `member_loads` each run also stores its load extremes (`member_loads_json` and `interface_loads_json` of
    alightsize.loads.interface.landing_loads)."""
    tasks = [task_of(study, r, out, member_loads) for r in study.runs]
    meta = {"study": study.name, "title": study.title, "seed": study.seed, "study_file": str(study.path)}
    return run_tasks(tasks, out, backend, workers, scheduler, quiet, on_row, meta)


def run_tasks(tasks: list[dict], out: Path, backend: str = "pool", workers: int | None = None,
              scheduler: str | None = None, quiet: bool = False, on_row: Callable[[dict], None] | None = None,
              meta: dict | None = None) -> SweepStats:
    """Run the tasks (`task_of`, ids unique) not already done into out/runs.sqlite; return the counts."""
    out.mkdir(parents=True, exist_ok=True)
    workers = workers or os.cpu_count() or 1
    store = RunStore(out / "runs.sqlite")
    if meta:
        store.set_meta(**meta)
    todo, reused = _stored(store, tasks)
    t0 = time.perf_counter()
    runner: Iterable[dict]
    if backend == "serial" or not todo:
        runner = _serial(todo)
    elif backend == "pool":
        runner = _pool(todo, min(workers, len(todo)))
    elif backend == "dask":
        runner = _dask(todo, workers, scheduler)
    else:
        raise InputError("(command line)", "--backend", "serial, pool or dask", repr(backend))
    failed = 0
    bar = _progress(len(todo), quiet)
    try:
        for row in runner:
            store.put(row)
            failed += row["status"] == "failed"
            bar.update(1)
            bar.set_postfix_str(f"last {row['run_id']}: {row.get('outcome_class') or row['status']}", refresh=False)
            if on_row:
                on_row(row)
    finally:
        bar.close()
        store.close()
    return SweepStats(len(tasks), len(tasks) - len(todo), len(todo), failed, time.perf_counter() - t0, backend,
                      reused)


def _stored(store: RunStore, tasks: list[dict]) -> tuple[list[dict], int]:
    """(the tasks left to compute, how many took a stored run under another id). Runs are keyed by their
    inputs: a task whose inputs hash a stored `done` run has takes that row, re-judged by the study's criteria;
    the row moves to the task's id unless its old id is still a run of the study (then it is copied), so a
    grown grid whose ids were renumbered computes only its new points and leaves no orphaned rows."""
    done = store.done()
    by_hash = {h: rid for rid, h in sorted(done.items())}
    ids = {t["run_id"] for t in tasks}
    wanted = [t["run_id"] if done.get(t["run_id"]) == t["scene_hash"] else by_hash.get(t["scene_hash"]) for t in tasks]
    rows = {r["run_id"]: r for r in store.rows([w for w in wanted if w is not None])}
    todo, reused = [], 0
    for t, old in zip(tasks, wanted):
        if old is not None and rows[old].get(NEWEST_FIGURE) is None:
            old = None                                 # stored by an earlier version that lacks a figure: land again
        if old is None:
            todo.append(t)
            continue
        row = {**rows[old], **_inputs(t)}
        row.update(_judged(row, t))
        if old != t["run_id"] or any(rows[old].get(k) != v for k, v in row.items()):
            store.put(row)
        if old != t["run_id"]:
            reused += 1
            if old not in ids:
                store.delete(old)
                by_hash[t["scene_hash"]] = t["run_id"]
                rows[t["run_id"]] = row
    return todo, reused
