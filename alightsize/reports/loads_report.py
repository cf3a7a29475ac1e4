"""Writing the loads results: JSON, an XLSX laid out like Tables 14-22, heat maps, Appendix III reports."""

from __future__ import annotations

import json
from math import degrees
from pathlib import Path

import pandas as pd
from openpyxl import Workbook

from alightsize.common.atomic import write_atomic
from alightsize.common.figures import save_png
from alightsize.loads.envelopes import MEMBER_LABELS, Extreme
from alightsize.loads.quasi_static import LoadsResult
from alightsize.common.units import fmt, to_display, unit_label
from alightsize.common.version import __version__
from alightsize.reports.rendering import frame_sheet, save_workbook, template_env

SCHEMA = "alightsize.loads/1"


def label(member: str) -> str:
    """Member label as the tables print it (mirror-image members in parentheses)."""
    return MEMBER_LABELS.get(member, member)


def _row(e: Extreme | None, system: str, with_config: bool) -> dict | None:
    if e is None:
        return None
    a, b, p = (degrees(x) for x in e.at)
    return {"load": to_display(e.value, "force", system), "text": fmt(e.value, "force", system),
            "alpha": f"{a:.1f}", "beta": f"{b:+.0f}" if abs(b) > 1e-9 else "0",
            "psi": f"{p:+.0f}" if abs(p) > 1e-9 else "0",
            "configuration": e.configuration if with_config else ""}


def tables(res: LoadsResult, system: str) -> list[dict]:
    """Tables 14-22 as rows: member label, tension and compression with positions."""
    out = []
    for name, rows in res.envelopes.items():
        combined = name in res.combined
        title = (f"Maximum loads, combined configurations {', '.join(res.combined[name])}" if combined
                 else f"Maximum loads, configuration {name}")
        out.append({"name": name, "title": title, "combined": combined,
                    "rows": [{"member": label(r.member), "tension": _row(r.tension, system, combined),
                              "compression": _row(r.compression, system, combined)} for r in rows]})
    return out


TELESCOPING_ROWS = {"AF1": "force", "P1": "force", "P2": "force", "w2": "spring_rate", "w1": "spring_rate",
                   "P4": "force", "P3": "force"}         # w: force per length (spring_rate units)
FROM_P1 = {"w1": "w1 = P1 / chi", "w2": "w2 = 6 P1 (rho - a) / chi^2", "P4": "P4 = mu (w1 + w2 / 2) chi"}


def telescoping_rows(res: LoadsResult, system: str, quasi_static: dict[str, float] | None = None) -> list[dict]:
    """The free-body table: each load as the design uses it, where it comes from (the App. III free body, a
    landing, or App. III's relations on the P1 beside it) and, with landings (`quasi_static`: the free body
    before they joined), the App. III value."""
    if res.telescoping is None:
        return []
    since = res.telescoping_from or {}
    out = []
    for k, d in TELESCOPING_ROWS.items():
        source = (since[k].configuration if k in since else FROM_P1[k] + " (App. III)" if k in FROM_P1
                  else "App. III free body")
        out.append({"name": k, "value": fmt(res.telescoping[k], d, system),
                    "number": to_display(res.telescoping[k], d, system), "unit": unit_label(d, system),
                    "source": source,
                    "quasi_static": fmt(quasi_static[k], d, system) if quasi_static is not None else None})
    return out


def context(res: LoadsResult, system: str, heatmaps: list[str] | None = None,
            quasi_static: dict[str, float] | None = None) -> dict:
    """Template context; `heatmaps` names the configurations whose heat maps are shown (default all);
    `quasi_static` the telescoping free body before landings joined it (a design with landings)."""
    names = [c.name for c in res.config.cases] if heatmaps is None else heatmaps
    return {"tables": tables(res, system), "telescoping": telescoping_rows(res, system, quasi_static),
            "heatmaps": [f"heatmap_{n}.png" for n in names]}


def envelope_frame(table: dict, system: str) -> pd.DataFrame:
    """One envelope of `tables` as the workbook shows it: a row per member and sense, the member named on its
    first row, the load in the display unit, alpha, beta, psi in degrees (and the configuration of a
    combination)."""
    rows = []
    for r in table["rows"]:
        for k, sense in enumerate(("tension", "compression")):
            e = r[sense]
            if e is not None:
                rows.append([r["member"] if k == 0 or r["tension"] is None else "", round(e["load"]),
                             float(e["alpha"]), float(e["beta"]), float(e["psi"])]
                            + ([e["configuration"]] if table["combined"] else []))
    return pd.DataFrame(rows, dtype=object, columns=["Member", f"Load ({unit_label('force', system)})", "alpha (deg)",
                                                     "beta (deg)", "psi (deg)"]
                        + (["Configuration"] if table["combined"] else []))


def write_workbook(res: LoadsResult, path: Path, system: str) -> None:
    """One sheet per configuration and per combination, laid out like Tables 14-22, and the telescoping free
    body; user text is always a string cell (never a formula)."""
    wb = Workbook()
    wb.remove(wb.active)
    for t in tables(res, system):
        frame_sheet(wb, t["name"], envelope_frame(t, system), t["title"])
    if res.telescoping is not None:
        free_body = pd.DataFrame([[r["name"], round(r["number"], 3), r["unit"]] for r in telescoping_rows(res, system)],
                                 columns=["Load", "Value", "Unit"], dtype=object)
        frame_sheet(wb, "telescoping", free_body, "Telescoping leg free body (App. III)")
    save_workbook(wb, path)


def heatmap(res: LoadsResult, case_name: str, path: Path, system: str) -> None:
    """The heat map of configuration `case_name` (LoadsResult.plot) as a PNG."""
    save_png(res.plot(case_name, system), path, 72)


def _extreme_json(row: pd.Series, key: str, combined: bool) -> dict:
    if pd.isna(row[f"{key}_N"]):
        return {f"{key}_N": None, f"{key}_at_deg": None}
    out = {f"{key}_N": float(row[f"{key}_N"]),
           f"{key}_at_deg": [float(row[f"{key}_{ax}_deg"]) for ax in ("alpha", "beta", "psi")]}
    if combined:
        out[f"{key}_configuration"] = row[f"{key}_configuration"]
    return out


def loads_json(res: LoadsResult) -> dict:
    """max_member_loads.json (docs/contracts.md, alightsize.loads/1) from the result's tables."""
    tables = res.to_pandas()
    confs: dict[str, list] = {}
    for _, r in tables["envelopes"].iterrows():
        confs.setdefault(r["envelope"], []).append({"member": r["member"],
                                                    **_extreme_json(r, "tension", r["combined"]),
                                                    **_extreme_json(r, "compression", r["combined"])})
    out = {"schema": SCHEMA, "title": res.config.title, "configurations": confs,
           "combined": {k: list(v) for k, v in res.combined.items()}}
    if "telescoping" in tables:
        out["telescoping"] = {k: float(v) for k, v in tables["telescoping"].iloc[0].items()}
    return out


def write_loads(res: LoadsResult, out: Path, system: str | None = None) -> list[Path]:
    """max_member_loads.json and .xlsx, heat maps and the Appendix III report, each written atomically."""
    system = system or res.config.units
    out.mkdir(parents=True, exist_ok=True)
    files = [write_atomic(out / "max_member_loads.json", json.dumps(loads_json(res), indent=2, allow_nan=False) + "\n"),
             write_atomic(out / "max_member_loads.xlsx", lambda p: write_workbook(res, p, system))]
    for c in res.config.cases:
        files.append(write_atomic(out / f"heatmap_{c.name}.png", lambda p, n=c.name: heatmap(res, n, p, system)))
    files.append(write_atomic(out / "loads.md", render_loads(res, system, "md")))
    files.append(write_atomic(out / "loads.html", render_loads(res, system, "html")))
    return files


def render_loads(res, system: str, kind: str) -> str:
    """The Appendix III report of `alightsize loads` (kind "md" or "html")."""
    ctx = {"title": res.config.title, "source": res.config.path.name, "units": system, "version": __version__,
           "loads": context(res, system), "references": []}
    return template_env(kind == "html").get_template(f"loads_report.{kind}.j2").render(**ctx)
