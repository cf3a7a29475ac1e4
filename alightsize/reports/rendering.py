"""What every report shares: the jinja2 environment over the shipped templates (autoescaped HTML, escaped
Markdown) and spreadsheet cells that keep user text as text."""

from __future__ import annotations

import datetime
import io
import json
import re
import zipfile
from pathlib import Path

import jinja2
import numpy as np
import pandas as pd
from openpyxl import Workbook
from openpyxl.styles import Font
from openpyxl.writer.excel import ExcelWriter

from alightsize.common.resources import data_dir


def _md_escape(text: str) -> str:
    out = str(text)
    for ch in "\\`*_[]<>|#":
        out = out.replace(ch, "\\" + ch)
    return out


def _md_code(text: str) -> str:
    """User text as a Markdown code span that it cannot close: a fence of one backtick more than its longest
    run, padded with a space where it starts or ends with one (CommonMark 0.31 §6.1)."""
    out = str(text).replace("\n", " ")
    fence = "`" * (max((len(run) for run in re.findall("`+", out)), default=0) + 1)
    pad = " " if out[:1] == "`" or out[-1:] == "`" else ""
    return f"{fence}{pad}{out}{pad}{fence}"


def template_env(autoescape: bool) -> jinja2.Environment:
    env = jinja2.Environment(loader=jinja2.FileSystemLoader(str(data_dir("templates"))),
                             autoescape=autoescape, undefined=jinja2.StrictUndefined,
                             trim_blocks=True, lstrip_blocks=True, keep_trailing_newline=True)
    env.filters["md"] = _md_escape
    env.filters["code"] = _md_code
    return env


def json_value(value):
    """A table cell as JSON holds it: NaN and None as null, numpy scalars as Python numbers."""
    if isinstance(value, np.generic):
        value = value.item()
    return None if isinstance(value, float) and not np.isfinite(value) else value


def json_records(frame: pd.DataFrame) -> list[dict]:
    """A table as a JSON list of objects, one per row, column names as keys."""
    return [{k: json_value(v) for k, v in row.items()} for row in frame.to_dict("records")]


def text_cell(cell, value) -> None:
    """Put user text in a cell as text, never as a formula."""
    cell.value = value
    if isinstance(value, str):
        cell.data_type = "s"


def frame_sheet(wb: Workbook, title: str, frame: pd.DataFrame, heading: str | None = None) -> None:
    """`frame` as a new sheet: a bold header (below a bold `heading` line, if given), numbers as numbers (NaN and
    None as empty cells), text as text, a list or mapping as its JSON text."""
    ws = wb.create_sheet(title)
    if heading is not None:
        text_cell(ws.cell(1, 1), heading)
        ws.cell(1, 1).font = Font(bold=True)
    top = 1 + (heading is not None)
    for j, name in enumerate(frame.columns, start=1):
        text_cell(ws.cell(top, j), str(name))
        ws.cell(top, j).font = Font(bold=True)
    for r, row in enumerate(frame.itertuples(index=False), start=top + 1):
        for c, value in enumerate(row, start=1):
            if isinstance(value, (float, np.floating)) and not np.isfinite(value):
                value = None
            elif isinstance(value, (list, tuple, dict)):
                value = json.dumps(value)                    # a list in one cell, as JSON text
            text_cell(ws.cell(r, c), value.item() if isinstance(value, np.generic) else value)
    for col in ws.iter_cols(min_row=top):
        ws.column_dimensions[col[0].column_letter].width = max(12, max(len(str(c.value or "")) for c in col) + 2)


_EPOCH = datetime.datetime(2000, 1, 1)          # stands in for every timestamp a workbook would carry


def save_workbook(wb: Workbook, path: Path) -> None:
    """Save `wb` so that the same workbook gives the same bytes: openpyxl stamps the save time into the
    document properties and every zip entry; both are set to a fixed date here."""
    wb.properties.created = wb.properties.modified = _EPOCH
    raw = io.BytesIO()
    ExcelWriter(wb, zipfile.ZipFile(raw, "w", zipfile.ZIP_DEFLATED)).save()
    with zipfile.ZipFile(raw) as src, zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as dst:
        for info in src.infolist():
            dst.writestr(zipfile.ZipInfo(info.filename, date_time=_EPOCH.timetuple()[:6]), src.read(info.filename),
                         compress_type=zipfile.ZIP_DEFLATED)
