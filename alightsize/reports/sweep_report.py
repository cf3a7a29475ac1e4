"""Results of a sweep from its run store: outcome probabilities with 95 % intervals, the outcome matrix in
the layout of AFFDL-TR-66-33 Tables 1-4 (printed symbols), distributions of peak g and strokes, a
stability-boundary plot over two parameters; outcomes.json (alightsize.sweep/1), outcomes.xlsx, report.html.
"""

from __future__ import annotations

import json
from pathlib import Path

from openpyxl import Workbook
from openpyxl.styles import Font

from alightsize import __version__
from alightsize.common.atomic import write_atomic
from alightsize.common.figures import save_png
from alightsize.landings.outcomes import MEANING, SYMBOL, SweepResult
from alightsize.reports.rendering import save_workbook, template_env, text_cell
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
    res = SweepResult.load(study, out)
    folder = reports or out
    doc, rows = res.document, res.rows
    files = [write_atomic(folder / "outcomes.json", json.dumps(doc, indent=1, default=str) + "\n"),
             write_workbook(doc, rows, folder / "outcomes.xlsx")]
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
