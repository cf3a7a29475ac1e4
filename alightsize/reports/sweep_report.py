"""Results of a sweep from its run store: outcome probabilities with 95 % intervals, the outcome matrix in
the layout of AFFDL-TR-66-33 Tables 1-4 (printed symbols), distributions of peak g and strokes, a
stability-boundary plot over two parameters; outcomes.json (alightsize.sweep/1), outcomes.xlsx, report.html.
"""

from __future__ import annotations

import json
from pathlib import Path

import pandas as pd
from openpyxl import Workbook

from alightsize.common.version import __version__
from alightsize.common.atomic import write_atomic
from alightsize.common.figures import save_png
from alightsize.landings.outcomes import MEANING, SYMBOL, SweepResult
from alightsize.reports.rendering import frame_sheet, save_workbook, template_env
from alightsize.landings.study import Study


def matrix_legend(doc: dict) -> list[str]:
    """"X stable", "● bottomed rotational pad", ...: the symbols of the classes simulated or printed in this
    study only (a telescoping study has no α or ψ cells)."""
    present = {r[k] for r in doc["run_list"] for k in ("outcome_class", "reference_class") if r.get(k)}
    by_symbol: dict[str, list[str]] = {}
    for cls, symbol in SYMBOL.items():
        if cls in present:
            by_symbol.setdefault(symbol, []).append(MEANING[cls])
    return [f"{symbol} {' / '.join(words)}" for symbol, words in by_symbol.items()]


def write_workbook(res: SweepResult, path: Path) -> Path:
    """Runs, outcome statistics and the outcome matrix; text cells never become formulas."""
    wb = Workbook()
    wb.remove(wb.active)
    tables, doc = res.to_pandas(), res.document
    runs = tables["runs"]
    first = ("run_id", "scene", "status", "outcome", "outcome_class")
    frame_sheet(wb, "Runs", runs[sorted(runs.columns, key=lambda k: (k not in first, k))].astype(object))
    frame_sheet(wb, "Outcomes", tables["outcomes"].set_axis(["outcome", "runs", "probability", "95 % low", "95 % high"],
                                                            axis=1))
    mat = doc["matrix"]
    if mat:
        marks = [[cell["values"].get(c) for c in mat["columns"]] for cell in mat["cells"]]
        frame_sheet(wb, "Matrix", pd.DataFrame(
            [cell["row"] + ["" if v is None else v["symbol"] + ("" if v["agrees"] in (None, True)
                                                                 else f" ({v['reference']})") for v in row]
             for cell, row in zip(mat["cells"], marks)],
            columns=mat["rows"] + [f"{mat['column']} {c}" for c in mat["columns"]], dtype=object))
    write_atomic(path, lambda p: save_workbook(wb, p))
    return path


def write_results(study: Study, out: Path, reports: Path | None = None) -> list[Path]:
    """outcomes.json, outcomes.xlsx, report.html and plots (in `reports`, default `out`) for the study's runs
    stored in out/runs.sqlite."""
    res = SweepResult.load(study, out)
    folder = reports or out
    doc = {}
    for k, v in res.document.items():                  # the writer's version after the seed, as the schema lists it
        doc[k] = v
        if k == "seed":
            doc["version"] = __version__
    files = [write_atomic(folder / "outcomes.json", json.dumps(doc, indent=1, default=str) + "\n"),
             write_workbook(res, folder / "outcomes.xlsx")]
    plots = []
    if res.plot_axes():
        plots.append("boundary.png")
    if len(res.done) >= 20:
        plots.append("distributions.png")
    for name in plots:
        write_atomic(folder / name, lambda p, k=name[:-4]: save_png(res.plot(k), p, 110))
    html = template_env(True).get_template("sweep_report.html.j2").render(
        doc=doc, plots=plots, version=__version__, symbols=SYMBOL, legend=matrix_legend(doc), source=study.path.name)
    files.append(write_atomic(folder / "report.html", html))
    return files + [folder / p for p in plots]
