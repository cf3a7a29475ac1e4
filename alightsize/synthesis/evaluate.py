"""Evaluating candidate designs. A candidate is the lander file with its free parameters set; its landings run
through the sweep executors (process pool or Dask) into the synthesis's run store, keyed by their inputs, so
a landing two candidates share runs once and a rerun after a kill finds every stored one; the design
pipeline then sizes, checks and weighs it on those landings. Each evaluation is stored too (`candidates`).

With a stroke margin m, a search landing in which any cell strokes past (1 - m) of its stroke to bottoming
fails too (a design margin that keeps the winner off the bottoming edge; the fresh re-check judges the
criteria alone).

A candidate first lands the envelope's corners; only if it meets every criterion there does it land the
Monte Carlo sample (a candidate that fails a corner is infeasible whatever the sample says).
"""

from __future__ import annotations

import copy
import hashlib
import json
import sqlite3
from collections import Counter
from dataclasses import asdict, dataclass, replace
from pathlib import Path

from alightsize.common.version import __version__
from alightsize.common.config import Node, load_toml
from alightsize.common.errors import InputError
from alightsize.landings.criteria import violation_kinds
from alightsize.landings.run_store import RunStore
from alightsize.landings.study import Run
from alightsize.landings.sweep import run_tasks, task_of
from alightsize.pipeline.design import DesignResult, run_design
from alightsize.pipeline.lander import Lander, read_lander
from alightsize.synthesis.spec import FreeParameter, overrides

CORNER = "corner-"
INVALID = 10.0                 # the objective of a candidate the lander file cannot take


@dataclass(frozen=True)
class Evaluation:
    """One candidate judged. `objective` is the leg-system weight fraction when feasible, else above 1:
    1 + fraction + (landings failing + criterion violations / criteria) / landings + the fraction of checks
    failing + the fraction of members that cannot be sized."""

    key: str
    x: tuple[float, ...]
    stage: str                      # "full": every landing judged; "screen": failed a corner; "invalid"
    objective: float
    feasible: bool
    weight_kg: float | None
    fraction: float | None
    landings: int
    failing: int
    kinds: dict
    checks_failing: int
    sizing_infeasible: tuple[str, ...]
    peak_g: float | None
    message: str = ""

    def as_json(self) -> dict:
        return {**asdict(self), "x": list(self.x), "sizing_infeasible": list(self.sizing_infeasible)}

    @classmethod
    def from_json(cls, d: dict) -> "Evaluation":
        return cls(**{**d, "x": tuple(d["x"]), "sizing_infeasible": tuple(d["sizing_infeasible"])})


def stroke_used(row: dict, legs) -> float:
    """The largest fraction of its stroke to bottoming any cell used in a landing row (cells_json), with
    `legs` the scene's legs (their cells in the row's order)."""
    used = 0.0
    for leg in json.loads(row.get("cells_json") or "[]"):
        cells = legs[leg["leg"] - 1].cells
        for j, c in enumerate(leg["cells"]):
            used = max(used, c["max_deflection_m"] / cells[j].curve.bottoming)
    return used


def _peak_g(rows: list[dict]) -> float | None:
    peaks = [max(r[f"peak_xdd{i}_g"] or 0.0 for i in (1, 2, 3)) for r in rows if r["status"] == "done"]
    return max(peaks) if peaks else None


class Evaluator:
    """Candidates of one lander file under one context (requirement overrides, e.g. a trade point's
    envelope), landed into `out`/runs.sqlite on a sweep backend."""

    def __init__(self, path: Path, free: tuple[FreeParameter, ...], out: Path, *, context: dict | None = None,
                 backend: str = "pool", workers: int | None = None, scheduler: str | None = None,
                 stroke_margin: float = 0.0, quiet: bool = True, data: dict | None = None):
        self.path, self.free, self.out = Path(path), free, Path(out)
        self.context = dict(context or {})
        self.backend, self.workers, self.scheduler, self.quiet = backend, workers, scheduler, quiet
        self.stroke_margin = stroke_margin
        self.root = load_toml(self.path) if data is None else Node(self.path, "", data)    # `data`: as read
        self.file_hash = hashlib.sha256(self.path.read_bytes()).hexdigest()
        self.out.mkdir(parents=True, exist_ok=True)
        RunStore(self.out / "runs.sqlite").close()                 # creates it in WAL mode
        self.db = sqlite3.connect(self.out / "runs.sqlite", isolation_level=None)
        self.db.execute("CREATE TABLE IF NOT EXISTS candidates (key TEXT PRIMARY KEY, evaluation TEXT)")
        self.computed = self.stored = 0                            # landings run / found stored

    def overrides(self, x) -> dict:
        return {**self.context, **overrides(self.free, x)}

    def key(self, x) -> str:
        text = json.dumps({"overrides": self.overrides(x), "file": self.file_hash, "version": __version__},
                          sort_keys=True)
        return hashlib.sha256(text.encode()).hexdigest()[:16]

    def lander(self, x, extra: dict | None = None) -> Lander:
        root = Node(self.root.file, "", copy.deepcopy(self.root.data))     # the file as read, not read again
        return read_lander(self.path, {**self.overrides(x), **(extra or {})}, root)

    def rows(self, lander: Lander, runs: list[Run]) -> list[dict]:
        """Land `runs` of a candidate (those not stored) and return their rows under the study's run ids."""
        return self._land([(lander, runs)])[0]

    def _land(self, groups: list[tuple[Lander, list[Run]]]) -> list[list[dict]]:
        """Land every group's runs in one batch; rows per group, in run order."""
        ids, tasks = [], {}
        for lander, runs in groups:
            study, loads = lander.study, lander.spec.landings.member_loads
            group = []
            for run in runs:
                t = task_of(study, run, self.out, loads)
                t["run_id"] = "L" + hashlib.sha256(t["scene_hash"].encode()).hexdigest()[:20]
                tasks.setdefault(t["run_id"], t)
                group.append(t["run_id"])
            ids.append(group)
        stats = run_tasks(list(tasks.values()), self.out, self.backend, self.workers, self.scheduler, self.quiet)
        self.computed += stats.computed
        self.stored += stats.skipped
        store = RunStore(self.out / "runs.sqlite")
        found = {r["run_id"]: r for r in store.rows(list(tasks))}
        store.close()
        return [[{**found[i], "run_id": run.run_id} for i, run in zip(group, runs)]
                for group, (_, runs) in zip(ids, groups)]

    def _judge(self, key: str, x, lander: Lander, runs: list[Run], rows: list[dict],
               stage: str, margin: bool = True) -> tuple[Evaluation, DesignResult | None]:
        """Size, check and weigh the candidate on its landed rows."""
        n = len(rows)
        bad = [r["status"] != "done" or r.get("criteria_ok") != 1 for r in rows]
        kinds = Counter(k for r in rows for k in dict.fromkeys(violation_kinds(r.get("criteria_failed"))))
        if margin and self.stroke_margin > 0:
            limit = 1.0 - self.stroke_margin
            over = [r["status"] == "done" and stroke_used(r, lander.scene.scene.legs) > limit for r in rows]
            kinds.update({f"a cell stroked past {100 * limit:.3g} % of its stroke": sum(over)})
            bad = [b or o for b, o in zip(bad, over)]
        failing = sum(bad)
        kinds.update({"the simulation failed": sum(r["status"] != "done" for r in rows)} if failing else {})
        spec = lander.spec
        study = replace(lander.study, runs=tuple(runs))
        spec = replace(spec, landings=replace(spec.landings, study=study))
        try:
            res = run_design(spec, rows=tuple(rows))
        except InputError as exc:
            ev = Evaluation(key, tuple(map(float, x)), stage, 2.0 + failing / max(n, 1), False, None, None, n,
                            failing, dict(+kinds), 0, (), _peak_g(rows), str(exc))
            return ev, None
        checks = sum(not r.ok for r in res.records)
        unsized = tuple(s.item for s in res.sizings if not s.feasible)
        frac = res.weight_fraction
        # a sized footpad heavier than the landings simulated fails the design (DesignResult.footpad_ok)
        pad = 0 if res.footpad_ok else 1
        feasible = stage == "full" and failing == 0 and checks == 0 and not unsized and not pad
        graded = sum(kinds.values()) / max(len(lander.study.criteria.kinds()), 1)    # how many criteria fail
        violation = ((failing + graded) / max(n, 1) + checks / max(len(res.records), 1)
                     + len(unsized) / max(len(res.sizings), 1) + pad)
        objective = frac if feasible else 1.0 + frac + violation
        ev = Evaluation(key, tuple(map(float, x)), stage, objective, feasible, res.per_leg * res.config.legs, frac,
                        n, failing, dict(+kinds), checks, unsized, _peak_g(rows))
        return ev, res

    def evaluate(self, xs, full: bool = False) -> list[Evaluation]:
        """Judge the candidates `xs` (stored ones are read back); with `full` every candidate lands the whole
        sample, else one failing a corner stops there."""
        keys = [self.key(x) for x in xs]
        known = self._load(keys)
        todo = {k: x for k, x in zip(keys, xs) if k not in known or (full and known[k].stage == "screen")}
        landers, out = {}, {}
        for k, x in todo.items():
            try:
                landers[k] = self.lander(x)
            except InputError as exc:
                out[k] = Evaluation(k, tuple(map(float, x)), "invalid", INVALID, False, None, None, 0, 0, {}, 0, (),
                                    None, str(exc))
        corners = {k: [r for r in lan.study.runs if r.run_id.startswith(CORNER)] for k, lan in landers.items()}
        rest = {k: [r for r in lan.study.runs if not r.run_id.startswith(CORNER)] for k, lan in landers.items()}
        first = dict(zip(landers, self._land([(landers[k], corners[k]) for k in landers])))
        passed = [k for k in landers
                  if full or all(r["status"] == "done" and r.get("criteria_ok") == 1 for r in first[k])]
        second = dict(zip(passed, self._land([(landers[k], rest[k]) for k in passed])))
        for k, lan in landers.items():
            runs, rows = corners[k], first[k]
            if k in second:
                runs, rows = runs + rest[k], rows + second[k]
            out[k] = self._judge(k, todo[k], lan, runs, rows, "full" if k in second or not rest[k] else "screen")[0]
        with self.db:
            self.db.executemany("INSERT OR REPLACE INTO candidates VALUES (?, ?)",
                                [(k, json.dumps(e.as_json())) for k, e in out.items()])
        known.update(out)
        return [known[k] for k in keys]

    def design(self, x, extra: dict | None = None,
               margin: bool = True) -> tuple[Evaluation, DesignResult | None, list[dict]]:
        """A candidate judged on its whole sample (or the one `extra`'s overrides give; without the search's
        stroke margin if not `margin`), with its design result and landing rows (reports)."""
        lander = self.lander(x, extra)
        runs = list(lander.study.runs)
        rows = self.rows(lander, runs)
        ev, res = self._judge(self.key(x), x, lander, runs, rows, "full", margin)
        return ev, res, rows

    def _load(self, keys: list[str]) -> dict[str, Evaluation]:
        wanted = list(dict.fromkeys(keys))
        found = {}
        for k in range(0, len(wanted), 500):
            chunk = wanted[k:k + 500]
            marks = ", ".join("?" * len(chunk))
            cur = self.db.execute(f"SELECT key, evaluation FROM candidates WHERE key IN ({marks})", chunk)
            found.update((key, Evaluation.from_json(json.loads(text))) for key, text in cur)
        return found

    def close(self) -> None:
        self.db.close()


def convergence(history: list[tuple[int, Evaluation]]) -> list[dict]:
    """Per generation: candidates, feasible ones, and the best feasible weight fraction so far."""
    out, best = [], None
    for g in sorted({g for g, _ in history}):
        evs = [e for h, e in history if h == g]
        feas = [e.fraction for e in evs if e.feasible]
        if feas:
            best = min(feas) if best is None else min(best, min(feas))
        out.append({"generation": g, "candidates": len(evs), "feasible": len(feas),
                    "best_weight_fraction": best, "generation_best": min(feas) if feas else None})
    return out
