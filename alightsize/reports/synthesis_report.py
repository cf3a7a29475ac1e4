"""The synthesis report: the chosen design beside the start (parameters, criteria with Wilson intervals,
members, weight), the convergence history, the landings that bound the design, trade curves and the Pareto
set; as synthesis.json (alightsize.synthesis/1), report.md/.html, synthesis.xlsx and charts, and the chosen
design's own design report in chosen/."""

from __future__ import annotations

import json
from math import degrees, isfinite
from pathlib import Path

from openpyxl import Workbook

from alightsize.common.version import __version__
from alightsize.common.atomic import write_atomic
from alightsize.common.units import registry
from alightsize.reports.design_report import _png, write_design
from alightsize.reports.rendering import frame_sheet, save_workbook, template_env
from alightsize.synthesis.search import SynthesisResult

SCHEMA = "alightsize.synthesis/1"


def _pct(x: float | None) -> str:
    return "–" if x is None else f"{100 * x:.3f} %"


def _rate(r) -> dict:
    return {"criterion": r.criterion, "passed": r.passed, "n": r.n,
            "p": f"{r.p:.4f}" if r.n else "–", "interval": f"{r.low:.4f} – {r.high:.4f}"}


def bounding(res: SynthesisResult) -> list[dict]:
    """The landings that bound the chosen design: for each figure with a margin, the worst landing."""
    rows = [r for r in res.best_rows if r["status"] == "done"]
    if not rows:
        return []
    crit = res.best_design.config.landings.study.criteria if res.best_design else None
    out = []
    figures = [(f"XDD({i})", f"peak_xdd{i}_g", "g", crit.max_xdd_g[i - 1] if crit and crit.max_xdd_g else None)
               for i in (1, 2, 3)]
    figures += [(f"XDD({i}) onset", f"peak_onset_xdd{i}_g_s", "g/s",
                 crit.max_onset_g_s[i - 1] if crit and crit.max_onset_g_s else None) for i in (1, 2, 3)]
    figures += [("largest cell stroke", "max_stroke_m", "m", None),
                ("largest footpad force", "max_ground_force_N", "N", None)]
    for name, col, unit, limit in figures:
        worst = max(rows, key=lambda r: r[col] or 0.0)
        out.append({"figure": name, "landing": worst["run_id"], "value": f"{worst[col]:.4g} {unit}",
                    "limit": "–" if limit is None else f"{limit:g} {unit}", "outcome": worst["outcome"],
                    "parameters": _conditions(json.loads(worst["params_json"]))})
    return out


def _conditions(params: dict) -> str:
    """A landing's drawn parameters, short: numbers to 4 digits, per-cell factors left out."""
    out = []
    for k, v in params.items():
        if isinstance(v, list):
            continue
        head, _, unit = str(v).partition(" ")
        try:
            v = f"{float(head):.4g}{' ' + unit if unit else ''}"
        except ValueError:
            pass
        out.append(f"{k} = {v}")
    return ", ".join(out)


def _members(res: SynthesisResult) -> list[dict]:
    """Each sized member: dimension and weight at the start and in the chosen design."""
    if res.start_design is None or res.best_design is None:
        return []
    start = {s.item: s for s in res.start_design.sizings}
    out = []
    for s in res.best_design.sizings:
        a = start.get(s.item)
        out.append({"member": s.item, "dimension": s.dimension,
                    "start": f"{1e3 * a.sized:.3f} mm" if a else "–", "chosen": f"{1e3 * s.sized:.3f} mm",
                    "start_kg": f"{a.weight_sized:.4g}" if a else "–", "chosen_kg": f"{s.weight_sized:.4g}",
                    "factor": f"{s.factor_sized:.3g}" if isfinite(s.factor_sized) else "∞"})
    return out


def _trade_label(axis: str, value: float) -> str:
    knots = registry().Quantity(value, "m/s").to("knot").magnitude
    return f"{degrees(value):.4g} deg" if axis == "slope" else f"{knots:.4g} kn ({value:.4g} m/s)"


def document(res: SynthesisResult) -> dict:
    """synthesis.json: everything the report shows, SI."""
    free = res.spec.free
    goal = res.best_design.config.weight_goal if res.best_design else None
    return {
        "schema": SCHEMA, "lander": str(res.spec.path), "ok": res.ok, "seed": res.spec.seed,
        "parameters": [{"key": p.key, "unit_si": _si_unit(p.unit), "low_si": p.low, "high_si": p.high,
                        "start_si": s, "chosen_si": c} for p, s, c in zip(free, res.start.x, res.best.x)],
        "start": _evaluation(res.start), "chosen": _evaluation(res.best), "weight_goal_fraction": goal,
        "search_rates": [r.as_json() for r in res.rates], "start_rates": [r.as_json() for r in res.start_rates],
        "check": {"samples": len(res.check_rows), "seed": res.spec.check_seed,
                  "rates": [r.as_json() for r in res.check_rates]},
        "convergence": res.convergence(),
        "trade": {axis: [{f"limit_{'rad' if axis == 'slope' else 'm_s'}": p.value, "label": p.label,
                          "feasible": p.best.feasible, "weight_fraction": p.best.fraction, "x_si": list(p.best.x)}
                         for p in pts] for axis, pts in res.trade.items()},
        "pareto": [{"weight_kg": e.weight_kg, "weight_fraction": e.fraction, "peak_g": e.peak_g, "x_si": list(e.x)}
                   for e in res.pareto()],
        "bounding_landings": bounding(res),
        "stats": {k: v for k, v in res.stats.items() if k != "wall_s"},
    }


def _si_unit(unit: str) -> str:
    return f"{registry().Quantity(1.0, unit).to_base_units().units:~}" or "1"


def _evaluation(e) -> dict:
    """An Evaluation for synthesis.json: the candidate as `x_si`, the rest as stored."""
    d = e.as_json()
    d["x_si"] = d.pop("x")
    d["weight_fraction"] = d.pop("fraction")
    return d


def _context(res: SynthesisResult) -> dict:
    free = res.spec.free
    goal = res.best_design.config.weight_goal if res.best_design else None
    frac = res.best.fraction
    return {
        "title": f"Synthesis of {res.spec.path.stem}", "source": res.spec.path.name, "version": __version__,
        "ok": res.ok, "seed": res.spec.seed,
        "verdict": (f"the lightest feasible system found weighs {_pct(frac)} of the capsule "
                    f"(start {_pct(res.start.fraction)}{', infeasible' if not res.start.feasible else ''}"
                    f"{' on the search sample' if res.check_rates else ''})"
                    if res.best.feasible else "no candidate met every criterion within the bounds"),
        "goal": None if goal is None
        else f"{100 * goal:.2f} % ({'met' if frac is not None and frac <= goal else 'not met'})",
        "parameters": [{"key": p.key, "bounds": f"{p.show(p.low)} – {p.show(p.high)}", "start": p.show(s),
                        "chosen": p.show(c)} for p, s, c in zip(free, res.start.x, res.best.x)],
        "weights": {"start": f"{res.start.weight_kg:.4g} kg" if res.start.weight_kg else "–",
                    "chosen": f"{res.best.weight_kg:.4g} kg" if res.best.weight_kg else "–",
                    "start_pct": _pct(res.start.fraction), "chosen_pct": _pct(frac)},
        "criteria": [{"start": _rate(a), "chosen": _rate(b), "check": _rate(c)}
                     for a, b, c in zip(res.start_rates, res.rates, res.check_rates or res.rates)],
        "check_samples": len(res.check_rows), "check_seed": res.spec.check_seed,
        "members": _members(res), "convergence": res.convergence(),
        "bounding": bounding(res),
        "trade": {axis: [{"label": _trade_label(axis, p.value), "feasible": p.best.feasible,
                          "weight": _pct(p.best.fraction) if p.best.feasible else "no feasible design",
                          "x": ", ".join(q.show(v) for q, v in zip(free, p.best.x))} for p in pts]
                  for axis, pts in res.trade.items()},
        "pareto": [{"weight": f"{e.weight_kg:.4g} kg", "pct": _pct(e.fraction), "peak_g": f"{e.peak_g:.3g}",
                    "x": ", ".join(q.show(v) for q, v in zip(free, e.x))} for e in res.pareto()],
        "stats": res.stats, "plots": plot_names(res),
    }


def plot_names(res: SynthesisResult) -> list[str]:
    return ["convergence.png", "pareto.png"] + [f"trade_{axis}.png" for axis in res.trade]


def write_workbook(res: SynthesisResult, path: Path) -> None:
    """One sheet per table of the result (`to_pandas`)."""
    wb = Workbook()
    wb.remove(wb.active)
    for name, frame in res.to_pandas().items():
        frame_sheet(wb, name, frame)
    save_workbook(wb, path)


def write_synthesis(res: SynthesisResult, out: str | Path) -> list[Path]:
    """Write the synthesis report into `out` (each file atomically); the chosen design's report in chosen/."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    ctx = _context(res)
    md, html = template_env(False), template_env(True)
    files = [write_atomic(out / "synthesis.json", json.dumps(document(res), indent=2, allow_nan=False) + "\n"),
             write_atomic(out / "report.md", md.get_template("synthesis_report.md.j2").render(**ctx)),
             write_atomic(out / "report.html", html.get_template("synthesis_report.html.j2").render(**ctx)),
             write_atomic(out / "synthesis.xlsx", lambda p: write_workbook(res, p))]
    for name in plot_names(res):
        kind = name[:-4].removeprefix("trade_")
        files.append(write_atomic(out / name, lambda p, k=kind: _png(res.plot(k), p)))
    if res.best_design is not None:
        files += write_design(res.best_design, out / "chosen")
    return files
