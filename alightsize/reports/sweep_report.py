"""Results of a sweep from its run store: outcome probabilities with 95 % intervals, the outcome matrix in
the layout of AFFDL-TR-66-33 Tables 1-4 (printed symbols), distributions of peak g and strokes, a
stability-boundary plot over two parameters; outcomes.json (alightsize.sweep/1), outcomes.xlsx, report.html.
"""

from __future__ import annotations

import json
from collections import Counter
from pathlib import Path

import numpy as np
from openpyxl import Workbook
from openpyxl.styles import Font

from alightsize import __version__
from alightsize.common.atomic import write_atomic
from alightsize.common.figures import literal
from alightsize.landings.criteria import violation_kinds
from alightsize.landings.probability import wilson_interval
from alightsize.reports.rendering import save_workbook, template_env, text_cell
from alightsize.landings.run_store import RunStore
from alightsize.landings.study import Study
from alightsize.common.units import registry

SCHEMA = "alightsize.sweep/1"
# The printed legends: Table 2, Tables 3-4; axial, body contact and
# failed have no printed symbol.
SYMBOL = {"stable": "X", "bottomed_alpha": "●", "bottomed_psi": "■", "bottomed_rotational_pad": "●",
          "bottomed_axial": "▲", "walking": "+", "time_out": "+", "tipped": "◆", "body_contact": "▼",
          "failed": "F", None: "F"}
# What each symbol of the outcome matrix means, in the words of its legend.
MEANING = {"stable": "stable", "bottomed_alpha": "bottomed α", "bottomed_psi": "bottomed ψ",
           "bottomed_rotational_pad": "bottomed rotational pad", "bottomed_axial": "bottomed axial",
           "walking": "walking", "time_out": "time-out", "tipped": "tipped", "body_contact": "body contact",
           "failed": "failed"}


def matrix_legend(doc: dict) -> list[str]:
    """"X stable", "● bottomed rotational pad", ...: the symbols of the classes simulated or printed in this
    study only (a telescoping study has no α or ψ cells)."""
    present = {r[k] for r in doc["run_list"] for k in ("outcome_class", "reference_class") if r.get(k)}
    by_symbol: dict[str, list[str]] = {}
    for cls, symbol in SYMBOL.items():
        if cls in present:
            by_symbol.setdefault(symbol, []).append(MEANING[cls])
    return [f"{symbol} {' / '.join(words)}" for symbol, words in by_symbol.items()]


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


def boundary_plot(rows: list[dict], axes: tuple[str, str], path: Path) -> Path:
    """Success fraction at each (x, y) of the two parameters in the study's units: green stable/met, red not."""
    from matplotlib.figure import Figure
    params = [json.loads(r["params_json"]) for r in rows]
    (xs_run, x_unit), (ys_run, y_unit) = (_as_written(params, k) for k in axes)
    cells: dict = {}
    for r, xy in zip(rows, zip(xs_run, ys_run)):
        if None not in xy:
            cells.setdefault(xy, []).append(_success(r))
    xy = np.array(list(cells))
    frac = np.array([np.mean(v) for v in cells.values()])
    fig = Figure(figsize=(6.4, 4.8))
    ax = fig.subplots()
    sc = ax.scatter(xy[:, 0], xy[:, 1], c=frac, cmap="RdYlGn", vmin=0, vmax=1, s=60 if len(xy) < 400 else 12,
                    edgecolors="k", linewidths=0.3)
    fig.colorbar(sc, ax=ax, label="fraction of runs successful")
    xs, ys = np.unique(xy[:, 0]), np.unique(xy[:, 1])
    if len(xs) > 1 and len(ys) > 1 and len(xs) * len(ys) == len(xy):          # a full grid: the 50 % contour
        z = np.full((len(ys), len(xs)), np.nan)
        z[np.searchsorted(ys, xy[:, 1]), np.searchsorted(xs, xy[:, 0])] = frac
        ax.contour(xs, ys, z, levels=[0.5], colors="k", linewidths=1.2)
    ax.set_xlabel(literal(f"{axes[0]} ({x_unit})" if x_unit else axes[0]))
    ax.set_ylabel(literal(f"{axes[1]} ({y_unit})" if y_unit else axes[1]))
    ax.set_title("Successful runs over two parameters" + (" (line: half successful)" if len(xs) * len(ys) == len(xy) else ""))
    fig.tight_layout()
    write_atomic(path, lambda p: fig.savefig(p, dpi=110, format="png"))
    return path


def distribution_plot(rows: list[dict], path: Path) -> Path:
    """Histograms of peak XDD(3) and the largest cell stroke of every done run."""
    from matplotlib.figure import Figure
    fig = Figure(figsize=(9, 3.6))
    axs = fig.subplots(1, 2)
    for ax, key, label in zip(axs, ("peak_xdd3_g", "max_stroke_m"), ("peak XDD(3) (g)", "largest cell stroke (m)")):
        x = np.array([r[key] for r in rows if r.get(key) is not None], float)
        ax.hist(x, bins=min(40, max(5, int(np.sqrt(len(x))))), color="#4a7", edgecolor="k", linewidth=0.3)
        ax.set_xlabel(label)
        ax.set_ylabel("runs")
    fig.tight_layout()
    write_atomic(path, lambda p: fig.savefig(p, dpi=110, format="png"))
    return path


def results(study: Study, rows: list[dict]) -> dict:
    """outcomes.json content (alightsize.sweep/1) from the stored rows of this study's runs."""
    done = [r for r in rows if r["status"] == "done"]
    n = len(done)
    doc = {"schema": SCHEMA, "study": study.name, "title": study.title, "seed": study.seed, "version": __version__,
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
        doc["criteria"] = {"limits": {"max_xdd_g": study.criteria.max_xdd_g, "max_onset_g_s": study.criteria.max_onset_g_s,
                                      "no_bottoming": study.criteria.no_bottoming,
                                      "no_tumbling": study.criteria.no_tumbling,
                                      "no_body_contact": study.criteria.no_body_contact},
                           "violations": _proportions([v for r in done for v in violation_kinds(r["criteria_failed"])], n)}
    doc["run_list"] = [{"run_id": r["run_id"], "scene": r["scene"], "params": json.loads(r["params_json"]),
                        "status": r["status"], "outcome": r.get("outcome"), "outcome_class": r.get("outcome_class"),
                        "reference_class": r.get("reference_class"),
                        "agrees": None if r.get("agrees") is None else bool(r["agrees"]),
                        "criteria_ok": None if r.get("criteria_ok") is None else bool(r["criteria_ok"]),
                        "peak_xdd_g": [r.get(f"peak_xdd{i}_g") for i in (1, 2, 3)], "max_stroke_m": r.get("max_stroke_m"),
                        "t_end_s": r.get("t_end_s"), "closure_rel": r.get("closure_rel"), "message": r.get("message")}
                       for r in rows]
    return doc


def _put(sheet, row: int, values: list) -> None:
    """One row of cells at a known row number (ws.max_row is a scan: quadratic over thousands of runs)."""
    for j, v in enumerate(values):
        text_cell(sheet.cell(row, j + 1), v)


def write_workbook(doc: dict, rows: list[dict], path: Path) -> Path:
    """Runs, outcome statistics and the outcome matrix; text cells never become formulas."""
    wb = Workbook()
    ws = wb.active
    ws.title = "Runs"
    names = sorted({k for r in rows for k in r}, key=lambda k: (k not in ("run_id", "scene", "status", "outcome",
                                                                         "outcome_class"), k))
    _put(ws, 1, names)
    for i, r in enumerate(rows):
        _put(ws, i + 2, [r.get(k) for k in names])
    st = wb.create_sheet("Outcomes")
    _put(st, 1, ["outcome", "runs", "probability", "95 % low", "95 % high"])
    for i, (k, v) in enumerate(doc["outcome_classes"].items()):
        _put(st, i + 2, [k, v["count"], v["probability"], *v["ci95"]])
    mat = doc["matrix"]
    if mat:
        sm = wb.create_sheet("Matrix")
        _put(sm, 1, mat["rows"] + [f"{mat['column']} {c}" for c in mat["columns"]])
        for i, cell in enumerate(mat["cells"]):
            marks = [cell["values"].get(c) for c in mat["columns"]]
            _put(sm, i + 2, cell["row"] + ["" if v is None else v["symbol"] + (
                "" if v["agrees"] in (None, True) else f" ({v['reference']})") for v in marks])
    for sheet in wb.worksheets:
        for c in sheet[1]:
            c.font = Font(bold=True)
    write_atomic(path, lambda p: save_workbook(wb, p))
    return path


def write_results(study: Study, out: Path, reports: Path | None = None) -> list[Path]:
    """outcomes.json, outcomes.xlsx, report.html and plots (in `reports`, default `out`) for the study's runs
    stored in out/runs.sqlite."""
    store = RunStore(out / "runs.sqlite")
    try:
        rows = store.rows([r.run_id for r in study.runs])
    finally:
        store.close()
    folder = reports or out
    doc = results(study, rows)
    files = [write_atomic(folder / "outcomes.json", json.dumps(doc, indent=1, default=str) + "\n"),
             write_workbook(doc, rows, folder / "outcomes.xlsx")]
    done = [r for r in rows if r["status"] == "done"]
    plots = []
    axes = plot_axes(study, done) if done else None
    if axes:
        plots.append(boundary_plot(done, axes, folder / "boundary.png").name)
    if len(done) >= 20:
        plots.append(distribution_plot(done, folder / "distributions.png").name)
    html = template_env(True).get_template("sweep_report.html.j2").render(doc=doc, plots=plots, version=__version__, symbols=SYMBOL,
                                                                  legend=matrix_legend(doc),
                                                                  source=study.path.name)
    files.append(write_atomic(folder / "report.html", html))
    return files + [folder / p for p in plots]
