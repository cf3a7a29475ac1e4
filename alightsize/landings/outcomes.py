"""A sweep's results from its stored runs: outcome probabilities with 95 % (Wilson) intervals, statistics of the
peaks, the outcome matrix in the layout of AFFDL-TR-66-33 Tables 1-4 (printed symbols), and the SweepResult that
holds them as tables and draws them (the stability boundary over two parameters, the distributions)."""

from __future__ import annotations

import json
from collections import Counter
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path

import numpy as np
import pandas as pd

from alightsize.common.units import registry
from alightsize.landings.criteria import violation_kinds
from alightsize.landings.probability import wilson_interval
from alightsize.landings.run_store import RunStore
from alightsize.landings.study import Study

SCHEMA = "alightsize.sweep/1"
# The printed legends: Table 2, Tables 3-4; axial, the tripod's struts, body contact and
# failed have no printed symbol.
SYMBOL = {"stable": "X", "bottomed_alpha": "●", "bottomed_psi": "■", "bottomed_rotational_pad": "●",
          "bottomed_axial": "▲", "bottomed_primary_strut": "▲", "bottomed_secondary_strut": "△", "walking": "+",
          "time_out": "+", "tipped": "◆", "body_contact": "▼", "failed": "F", None: "F"}
# What each symbol of the outcome matrix means, in the words of its legend.
MEANING = {"stable": "stable", "bottomed_alpha": "bottomed α", "bottomed_psi": "bottomed ψ",
           "bottomed_rotational_pad": "bottomed rotational pad", "bottomed_axial": "bottomed axial",
           "bottomed_primary_strut": "bottomed primary strut", "bottomed_secondary_strut": "bottomed secondary strut",
           "walking": "walking", "time_out": "time-out", "tipped": "tipped", "body_contact": "body contact",
           "failed": "failed"}


OUTCOMES = ("stable", "walking", "time_out", "tipped", "bottomed", "body_contact", "failed")   # docs/contracts.md


def _proportions(values: list, n: int, every: tuple[str, ...] = ()) -> dict:
    """Count, share and Wilson 95 % interval of each value, most frequent first; the values in `every` are listed
    even when none occurred (a zero count still bounds the probability: 0 of 1,000 is at most 0.38 %)."""
    counts = Counter(values)
    for k in every:
        counts.setdefault(k, 0)
    return {str(k): {"count": c, "probability": c / n if n else 0.0, "ci95": list(wilson_interval(c, n))}
            for k, c in sorted(counts.items(), key=lambda kv: -kv[1])}


def _stats(x: np.ndarray) -> dict | None:
    x = x[np.isfinite(x)]
    if not len(x):
        return None
    q = np.percentile(x, [5, 50, 95])
    return {"mean": float(x.mean()), "sd": float(x.std(ddof=1)) if len(x) > 1 else 0.0, "p05": float(q[0]),
            "p50": float(q[1]), "p95": float(q[2]), "max": float(x.max())}


def _success(r: dict) -> bool:
    """Criteria met where the study has criteria, else the report's success: stable or walking (Sec. II.B)."""
    if r.get("criteria_ok") is not None:
        return bool(r["criteria_ok"])
    return r.get("outcome") in ("stable", "walking")


def matrix(study: Study, rows: list[dict]) -> dict | None:
    """Outcome symbols with one row per combination of the row parameters and one column per value of the
    column parameter (the layout of Tables 1-4); None for Monte Carlo studies."""
    if not rows or any("sample" in json.loads(r["params_json"]) for r in rows):
        return None
    cols, table = [], {}
    for r in rows:
        p = json.loads(r["params_json"])
        key = tuple(str(p.get(k, "")) for k in study.matrix_rows)
        col = str(p.get(study.matrix_column, ""))
        if col not in cols:
            cols.append(col)
        sim = SYMBOL.get(r.get("outcome_class"), "?")
        ref = r.get("reference_class")
        table.setdefault(key, {})[col] = {"symbol": sim, "reference": SYMBOL.get(ref, ref) if ref else None,
                                          "agrees": None if r.get("agrees") is None else bool(r["agrees"])}
    return {"rows": list(study.matrix_rows), "column": study.matrix_column, "columns": cols,
            "cells": [{"row": list(k), "values": v} for k, v in table.items()]}


def _as_written(values: list, name: str) -> tuple[list[float | None], str]:
    """The parameter `name` of each run's params as a number in the unit it is written in (that of its first
    quantity, "ft/s"), and that unit ("" for plain numbers); None where it is not a number."""
    ureg = registry()
    unit, out = None, []
    for p in values:
        v = p.get(name)
        try:
            q = ureg.Quantity(v if isinstance(v, (int, float)) and not isinstance(v, bool) else str(v))
            unit = unit if unit is not None else q.units
            out.append(float(q.to(unit).magnitude))
        except Exception:                          # noqa: BLE001 - text, lists, other dimensions: not plotted
            out.append(None)
    return out, "" if unit is None or unit == registry().dimensionless else f"{unit:~P}"


def plot_axes(study: Study, rows: list[dict]) -> tuple[str, str] | None:
    """The two parameters of the boundary plot: the study's first two candidates with more than one
    numeric value among the runs."""
    params = [json.loads(r["params_json"]) for r in rows]
    varied = [k for k in study.plot_params if len(set(_as_written(params, k)[0]) - {None}) > 1]
    return tuple(varied[:2]) if len(varied) >= 2 else None


def outcomes_json(study: Study, rows: list[dict]) -> dict:
    """outcomes.json content (alightsize.sweep/1) from the stored rows of this study's runs, but for the
    `version` of the program that writes it (the report's)."""
    done = [r for r in rows if r["status"] == "done"]
    n = len(done)
    doc = {"schema": SCHEMA, "study": study.name, "title": study.title, "seed": study.seed,
           "runs": len(study.runs), "stored": len(rows), "done": n,
           "failed": [r["run_id"] for r in rows if r["status"] == "failed" or r.get("outcome") == "failed"],
           "outcomes": _proportions([r["outcome"] for r in done], n, OUTCOMES),
           "outcome_classes": _proportions([r["outcome_class"] for r in done], n),
           "successful": _proportions([_success(r) for r in done], n).get("True", {"count": 0, "probability": 0.0,
                                                                                 "ci95": list(wilson_interval(0, n))}),
           "statistics": {k: _stats(np.array([r.get(k) for r in done], float))
                          for k in ("peak_xdd1_g", "peak_xdd2_g", "peak_xdd3_g", "max_stroke_m", "closure_rel")},
           "matrix": matrix(study, rows)}
    compared = [r for r in done if r.get("agrees") is not None]
    if compared:
        agree = sum(r["agrees"] for r in compared)
        doc["agreement"] = {"compared": len(compared), "agree": agree, "fraction": agree / len(compared)}
    if study.criteria is not None:
        crit = study.criteria
        doc["criteria"] = {"limits": {"max_xdd_g": crit.max_xdd_g, "max_onset_g_s": crit.max_onset_g_s,
                                      "no_bottoming": crit.no_bottoming, "no_tumbling": crit.no_tumbling,
                                      "no_body_contact": crit.no_body_contact},
                           "violations": _proportions([v for r in done for v in violation_kinds(r["criteria_failed"])],
                                                      n)}
    doc["run_list"] = [{"run_id": r["run_id"], "scene": r["scene"], "params": json.loads(r["params_json"]),
                        "status": r["status"], "outcome": r.get("outcome"), "outcome_class": r.get("outcome_class"),
                        "reference_class": r.get("reference_class"),
                        "agrees": None if r.get("agrees") is None else bool(r["agrees"]),
                        "criteria_ok": None if r.get("criteria_ok") is None else bool(r["criteria_ok"]),
                        "peak_xdd_g": [r.get(f"peak_xdd{i}_g") for i in (1, 2, 3)],
                        "max_stroke_m": r.get("max_stroke_m"),
                        "t_end_s": r.get("t_end_s"), "closure_rel": r.get("closure_rel"), "message": r.get("message")}
                       for r in rows]
    return doc




def boundary_points(rows: list[dict], axes: tuple[str, str]) -> tuple[pd.DataFrame, tuple[str, str]]:
    """The success fraction at each (x, y) of two parameters in the units the study writes them in (columns x, y,
    fraction, runs), and the axis labels ("name (unit)")."""
    params = [json.loads(r["params_json"]) for r in rows]
    (xs_run, x_unit), (ys_run, y_unit) = (_as_written(params, k) for k in axes)
    cells: dict = {}
    for r, xy in zip(rows, zip(xs_run, ys_run)):
        if None not in xy:
            cells.setdefault(xy, []).append(_success(r))
    points = pd.DataFrame([{"x": x, "y": y, "fraction": float(np.mean(v)), "runs": len(v)}
                           for (x, y), v in cells.items()], columns=["x", "y", "fraction", "runs"])
    return points, (f"{axes[0]} ({x_unit})" if x_unit else axes[0], f"{axes[1]} ({y_unit})" if y_unit else axes[1])


@dataclass(frozen=True)
class SweepResult:
    """A study and its stored runs (the rows of runs.sqlite, study order)."""

    study: Study
    rows: list[dict]

    @classmethod
    def load(cls, study: Study, out: Path) -> "SweepResult":
        """The study's runs stored in out/runs.sqlite."""
        store = RunStore(Path(out) / "runs.sqlite")
        try:
            return cls(study, store.rows([r.run_id for r in study.runs]))
        finally:
            store.close()

    @property
    def done(self) -> list[dict]:
        return [r for r in self.rows if r["status"] == "done"]

    @cached_property
    def document(self) -> dict:
        """outcomes.json (alightsize.sweep/1, docs/contracts.md) without the writer's `version`."""
        return outcomes_json(self.study, self.rows)

    def plot_axes(self) -> tuple[str, str] | None:
        """The two parameters of the boundary plot (None: fewer than two vary)."""
        return plot_axes(self.study, self.done) if self.done else None

    def to_pandas(self) -> dict[str, pd.DataFrame]:
        """"runs" (one row per stored run: parameters as written in `params_json`, outcome, peaks, SI) and
        "outcomes" (per outcome class of the done runs: count, probability and its Wilson 95 % interval)."""
        classes = self.document["outcome_classes"]
        return {"runs": pd.DataFrame(self.rows),
                "outcomes": pd.DataFrame([{"outcome_class": k, "count": v["count"], "probability": v["probability"],
                                           "ci95_low": v["ci95"][0], "ci95_high": v["ci95"][1]}
                                          for k, v in classes.items()],
                                         columns=["outcome_class", "count", "probability", "ci95_low", "ci95_high"])}

    def plot(self, kind: str = "boundary"):
        """A matplotlib Figure: "boundary" (the share of successful runs over the study's first two varied
        parameters) or "distributions" (peak XDD(3) and the largest stroke)."""
        from alightsize.common import figures

        def boundary():
            axes = self.plot_axes()
            if axes is None:
                raise ValueError("plot kind 'boundary': fewer than two parameters of the study vary")
            return figures.boundary_figure(*boundary_points(self.done, axes))
        draw = figures.pick({"boundary": boundary,
                             "distributions": lambda: figures.distribution_figure(pd.DataFrame(self.done))}, kind)
        return draw()
