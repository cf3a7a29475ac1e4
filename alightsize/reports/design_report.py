"""Appendix IV-style stress sheets and Appendix V-style weight sheets: HTML, Markdown and XLSX."""

from __future__ import annotations

import itertools
import json
import re
from collections import Counter
from math import degrees, isfinite
from pathlib import Path

import pandas as pd
from openpyxl import Workbook

from alightsize.common.version import __version__
from alightsize.common.figures import save_png
from alightsize.common.trace import Step
from alightsize.common.units import fmt, to_display, unit_label
from alightsize.pipeline.design import CLOSEST_HEAD, FOOTPAD_MASS_TOLERANCE, DesignResult
from alightsize.loads.quasi_static import TELESCOPING
from alightsize.pipeline.landings import LANDING
from alightsize.reports.loads_report import context as loads_context
from alightsize.reports.loads_report import heatmap, loads_json, write_workbook as write_loads_workbook
from alightsize.reports.rendering import frame_sheet, json_records, save_workbook, template_env
from alightsize.common.atomic import write_atomic

SCHEMA = "alightsize.design/1"
AUDIT_SCHEMA = "alightsize.audit/1"


_POWERED = re.compile(r"\{([^{}]+)\}(?=[²³⁴])")


def _substituted(formula: str, values: dict[str, str]) -> str:
    """The formula with each input's display value; a raised value with a unit or sign in parentheses, so
    t² reads (4.980 in)², not 4.980 in²."""
    def wrap(m: re.Match) -> str:
        text = values[m.group(1)]
        return f"({m.group(0)})" if " " in text or text.startswith("-") else m.group(0)
    return _POWERED.sub(wrap, formula).format(**values)


def _step(step: Step, system: str) -> dict:
    names = {n: n for n, _, _ in step.inputs}
    values = {n: fmt(v, d, system) for n, v, d in step.inputs}
    return {"label": step.label, "symbol": step.symbol, "formula": step.formula.format(**names),
            "substituted": _substituted(step.formula, values), "value": fmt(step.value, step.dim, system),
            "given": step.formula == f"{{{step.symbol}}}"}


def _factor(f: float) -> str:
    return f"{f:.2f}" if isfinite(f) else "∞"


def _check_title(kind: str, mode: str) -> str:
    """"column buckling", or "plate fixed center load (plate bending)" where the failure mode differs."""
    words = kind.replace("_", " ")
    return words if kind == mode else f"{words} ({mode.replace('_', ' ')})"


def _dims(item, system: str) -> str:
    s = item.section
    if s is None:
        return ""
    parts = [f"{k.replace('_', ' ')} {fmt(v, 'length', system)}" for k, v in s.dims.items()]
    parts += [f"{k} {fmt(v, {'area': 'area', 'inertia': 'second_moment', 'c': 'length'}[k], system)} (printed)"
              for k, v in s.overrides.items()]
    return f"{s.shape}: " + ", ".join(parts)


def context(res) -> dict:
    """Everything the templates show, already formatted in the config's display units."""
    cfg, system = res.config, res.config.units
    sheets = []
    for item in res.items:
        recs = [r for r in res.records if r.item is item]
        sheets.append({
            "name": item.name, "count": item.count, "material": item.material.name, "size": _dims(item, system),
            "note": item.note,
            "checks": [{"title": _check_title(item.checks[r.index].kind, r.outcome.mode),
                        "note": item.checks[r.index].note,
                        "steps": [_step(s, system) for s in r.outcome.steps],
                        "allowable": fmt(r.outcome.allowable, "stress", system) if r.outcome.allowable else "",
                        "factor": r.stated_factor, "required": f"{r.required:.2f}", "ok": r.ok,
                        "margin": r.stated_margin,
                        "flips": r.rounding_flips}
                       for r in recs]})
    weights = [{"label": w.label, "count": w.count, "each": fmt(w.each, "mass", system),
                "total": fmt(w.count * w.each, "mass", system), "steps": [_step(s, system) for s in w.steps]}
               for w in res.weights]
    total = res.per_leg * cfg.legs
    sizing = [{"item": s.item, "dimension": s.dimension.replace("_", " "), "printed": fmt(s.printed, "length", system),
               "sized": fmt(s.sized, "length", system), "f_printed": _factor(s.factor_printed),
               "f_sized": _factor(s.factor_sized), "feasible": s.feasible, "at_bound": s.at_bound,
               "w_printed": fmt(s.weight_printed, "mass", system) if s.weight_printed else "",
               "w_sized": fmt(s.weight_sized, "mass", system) if s.weight_sized else "",
               "saved": fmt(s.weight_printed - s.weight_sized, "mass", system)
               if s.weight_printed and s.weight_sized else ""} for s in res.sizings]
    return {"loads": _loads_context(res, system), "references": _references(res, system),
            "interface": _interface(res, system),
            "verdict": res.verdict(), "checks_ok": res.checks_ok, "landings": _landings(cfg, system),
            "headlines": res.headlines(system), "closest_head": CLOSEST_HEAD,
            "closest": [{"line": c.line(), "failed": c.margin.failed, "anchor": _anchor(c.run_id) if c.run_id else None}
                        for c in (cfg.landings.closest if cfg.landings else ())],
            "title": cfg.title, "configuration": cfg.configuration, "source": cfg.path.name, "units": system,
            "version": __version__, "ok": res.ok, "sheets": sheets, "weights": weights, "sizing": sizing,
            "per_leg": fmt(res.per_leg, "mass", system), "legs": cfg.legs, "total": fmt(total, "mass", system),
            "capsule": fmt(cfg.capsule_mass, "mass", system) if cfg.capsule_mass else "",
            "percent": f"{100 * total / cfg.capsule_mass:.2f}" if cfg.capsule_mass else "",
            "failed": [r.failure_label for r in res.records if not r.ok]}


def _conditions(c: dict, system: str) -> str:
    """"35.0 ft/s down, 15.0 ft/s horizontal downhill on a 20° slope, μ 1.5 / 1.0" (friction above 100 reads
    "non-slip"; the direction is downhill, uphill or across within 45° of each)."""
    mu = "non-slip" if c["mu_static"] >= 100 else f"μ {c['mu_static']:.3g} / {c['mu_dynamic']:.3g}"
    heading = c.get("from_downhill_deg")
    horizontal = c["horizontal_m_s"] if abs(c["horizontal_m_s"]) > 1e-9 else 0.0      # round-off of a level approach
    way = ("" if heading is None or not horizontal else " downhill" if heading < 45 else " uphill" if heading > 135
           else " across")
    ground = f"on a {c['slope_deg']:.0f}° slope" if round(c["slope_deg"]) else "on level ground"
    return (f"{fmt(c['vertical_m_s'], 'velocity', system, 3)} down, {fmt(horizontal, 'velocity', system, 3)} "
            f"horizontal{way} {ground}, {mu}")


def _parameter(value) -> str:
    """A landing parameter as the report shows it: numbers to 4 significant digits ("-2.57 m/s"), a per-cell
    table as its range ("0.845 to 1.16")."""
    if isinstance(value, list):
        flat = list(itertools.chain.from_iterable(v if isinstance(v, list) else [v] for v in value))
        if flat and all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in flat):
            return f"{min(flat):.3g} to {max(flat):.3g}"
        return str(value)
    if isinstance(value, float):
        return f"{value:.4g}"
    if isinstance(value, str):
        number, _, unit = value.partition(" ")
        try:
            return f"{float(number):.4g} {unit}".rstrip()
        except ValueError:
            return value
    return str(value)


def _anchor(run_id: str) -> str:
    return "landing-" + re.sub(r"[^A-Za-z0-9_-]", "_", run_id)


def landing_rows(cfg, system: str) -> dict[str, dict]:
    """run id -> what the report shows of a landing case: parameters as written, conditions, outcome, peaks
    (g of standard gravity, as the criteria), onset rates and the criteria it violates."""
    land = cfg.landings
    out = {}
    for r, c in zip(land.rows, land.conditions):
        params = {k: v for k, v in json.loads(r["params_json"]).items() if k != "scene"}
        out[r["run_id"]] = {
            "id": r["run_id"], "scene": r["scene"], "anchor": _anchor(r["run_id"]),
            "parameters": ", ".join(f"{k.split('.')[-1].replace('_', ' ')} {_parameter(v)}" for k, v in params.items()),
            "conditions": _conditions(c, system), "outcome": r["outcome"],
            "outcome_class": r["outcome_class"].replace("_", " "),
            "peak": [f"{r[f'peak_xdd{i}_g']:.2f}" for i in (1, 2, 3)],
            "onset": [f"{r[f'peak_onset_xdd{i}_g_s']:,.0f}" for i in (1, 2, 3)],
            "ok": r.get("criteria_ok") != 0,
            "failures": [f for f in (r.get("criteria_failed") or "").split("; ") if f]}
    return out


def _landings(cfg, system: str) -> dict | None:
    """The landing section: every case, the criteria, how many fail and why, the role of the landings."""
    land = cfg.landings
    if land is None:
        return None
    crit = land.study.criteria
    limits = []
    if crit is not None:
        if crit.max_xdd_g:
            limits.append("peak XDD(1, 2, 3) at most " + " / ".join(f"{x:g}" for x in crit.max_xdd_g) + " g")
        if crit.max_onset_g_s:
            limits.append("onset at most " + " / ".join(f"{x:,.0f}" for x in crit.max_onset_g_s) + " g/s")
        limits += [text for flag, text in ((crit.no_bottoming, "no cell bottoms"), (crit.no_tumbling, "no tipping"),
                                           (crit.no_body_contact, "no body contact")) if flag]
    rows = list(landing_rows(cfg, system).values())
    return {"role": land.role, "study": land.study.name, "count": len(rows), "rows": rows,
            "criteria": "; ".join(limits) or "none given", "failing": len(land.failing),
            "counts": land.criteria_counts(),
            "outcomes": ", ".join(f"{k} {n}" for k, n in Counter(r["outcome"] for r in land.rows).most_common())}


def _interface(res: DesignResult, system: str) -> list[dict]:
    """The interface loads (the "interface_loads" table): each body hardpoint's largest force, its components along
    the body's geometric axes and the landing that produced it."""
    tables = res.tables
    if "interface_loads" not in tables:
        return []
    return [{"leg": r.leg, "hardpoint": r.hardpoint, "force": fmt(r.force_N, "force", system),
             "components": " / ".join(fmt(getattr(r, f"force_{i}_N"), "force", system) for i in (1, 2, 3)),
             "t": f"{r.t_s:.3f} s", "landing": r.run_id, "anchor": _anchor(r.run_id)}
            for r in tables["interface_loads"].itertuples()]


def _loads_context(res: DesignResult, system: str) -> dict | None:
    cfg = res.config
    if cfg.loads is None:          # a tripod lander's loads are the landings': only their references to show
        return {"telescoping": [], "tables": [], "heatmaps": []} if "load_references" in res.tables else None
    landed = cfg.landings is not None and cfg.loads.telescoping is not None and TELESCOPING in cfg.landings.envelopes
    return loads_context(cfg.loads, system, res.governing_cases(),
                         cfg.landings.quasi_static.telescoping if landed else None)


def _references(res: DesignResult, system: str) -> list[dict]:
    """The checks' envelope loads (the "load_references" table); with landing cases also the quasi-static load,
    which governed and, for a landing, its conditions and outcome."""
    if "load_references" not in res.tables:
        return []
    landings = landing_rows(res.config, system) if res.config.landings is not None else {}
    out = []
    for r in res.tables["load_references"].to_dict("records"):
        dynamic, checked = isinstance(r["governs"], str), isinstance(r["item"], str)      # else None or NaN
        configuration = r["configuration"] if isinstance(r["configuration"], str) else ""
        out.append({
            "key": f"{r['item']} / {r['kind'].replace('_', ' ')} ({r['key']})" if checked else r["load_key"],
            "envelope": r["envelope"], "member": r["member"], "sense": r["sense"], "factor": f"{r['factor']:g}",
            "value": fmt(r["value_N"], "force", system),
            "at": ", ".join(f"{degrees(a):+.0f}" for a in r["at_rad"]) if isinstance(r["at_rad"], tuple) else "",
            "configuration": configuration,
            "quasi_static": (fmt(r["quasi_static_N"], "force", system) if pd.notna(r["quasi_static_N"]) else "-")
            if dynamic else None, "governs": r["governs"] if dynamic else "",
            "landing": landings.get(configuration.removeprefix(LANDING)) if dynamic else None})
    return out


def render_html(res) -> str:
    return template_env(True).get_template("design_report.html.j2").render(**context(res))


def render_markdown(res) -> str:
    return template_env(False).get_template("design_report.md.j2").render(**context(res))


def write_workbook(res, path: Path) -> None:
    """Stress sheet and weight sheet (and with them Sizing and Landings), values in the display units, numbers as
    numbers, user text as text."""
    system = res.config.units
    wb = Workbook()
    wb.remove(wb.active)
    frame_sheet(wb, "Stress", stress_frame(res, system))
    frame_sheet(wb, "Weights", weights_frame(res, system))
    if res.sizings:
        frame_sheet(wb, "Sizing", sizing_frame(res, system))
    if res.config.landings is not None:
        frame_sheet(wb, "Landings", landings_frame(res.config.landings.cases(), system))
        frame_sheet(wb, "Interface loads", interface_frame(res, system))
    save_workbook(wb, path)


def stress_frame(res: DesignResult, system: str) -> pd.DataFrame:
    """One row per check (the "checks" table): stress and allowable in the display unit to 0.1, f and MS to 4
    places (empty where infinite)."""
    checks, su = res.tables["checks"], unit_label("stress", system)

    def stress(col: str) -> list:
        return [round(to_display(v, "stress", system), 1) if pd.notna(v) else None for v in checks[col]]

    def four(col: str) -> list:
        return [round(v, 4) if pd.notna(v) else None for v in checks[col]]
    return pd.DataFrame({"Item": checks["item"], "Count per leg": [r.item.count for r in res.records],
                         "Material": [r.item.material.name for r in res.records], "Check": checks["kind"],
                         "Failure mode": checks["check"], f"Stress ({su})": stress("stress_Pa"),
                         f"Allowable ({su})": stress("allowable_Pa"), "Design factor": four("design_factor"),
                         "Required": checks["required_design_factor"], "Margin of safety": four("margin_of_safety"),
                         "OK": ["yes" if ok else "NO" for ok in checks["ok"]]}, dtype=object)


def weights_frame(res: DesignResult, system: str) -> pd.DataFrame:
    """One row per weight entry (the "weights" table) in the display unit, then the totals per leg, for all legs
    and as a percentage of the capsule."""
    cfg, weights, wu = res.config, res.tables["weights"], unit_label("mass", system)
    rows = []
    for w in weights.to_dict("records"):
        each = round(to_display(w["weight_each_kg"], "mass", system), 4)
        rows.append([w["item"], w["count_per_leg"], each, round(each * w["count_per_leg"], 4)])
    per_leg = to_display(res.per_leg, "mass", system)
    rows += [["Total each leg", None, None, round(per_leg, 4)],
             [f"Total {cfg.legs} legs", None, None, round(per_leg * cfg.legs, 4)]]
    if cfg.capsule_mass:
        rows.append(["Percent of capsule", None, None, round(100 * res.per_leg * cfg.legs / cfg.capsule_mass, 3)])
    return pd.DataFrame(rows, columns=["Item", "Count per leg", f"Weight each ({wu})", f"Weight per leg ({wu})"],
                        dtype=object)


def sizing_frame(res: DesignResult, system: str) -> pd.DataFrame:
    """One row per sized item (the "sizing" table), lengths and weights in the display units."""
    t = res.tables["sizing"]
    lu, wu = unit_label("length", system), unit_label("mass", system)
    length = lambda v: to_display(v, "length", system)                                    # noqa: E731
    mass = lambda v: to_display(v, "mass", system) if pd.notna(v) and v else None          # noqa: E731
    return pd.DataFrame({"Item": t["item"], "Dimension": t["dimension"].str.replace("_", " "),
                         f"Printed ({lu})": t["printed_m"].map(length), f"Sized ({lu})": t["sized_m"].map(length),
                         "f printed": t["design_factor_printed"], "f sized": t["design_factor_sized"],
                         f"Weight printed ({wu})": t["weight_printed_kg"].map(mass),
                         f"Weight sized ({wu})": t["weight_sized_kg"].map(mass),
                         "Meets the required factor": ["yes" if ok else "NO" for ok in t["feasible"]],
                         "At an end of its range": ["yes" if b else "" for b in t["at_bound"]]})


def landings_frame(rows: list[dict], system: str) -> pd.DataFrame:
    """One row per landing case (`Landings.cases`): its conditions in the display units, outcome, criteria and peak
    accelerations."""
    vu = unit_label("velocity", system)
    speed = lambda v: to_display(v, "velocity", system) if v is not None else None    # noqa: E731
    return pd.DataFrame({
        "Landing": [r["run_id"] for r in rows],
        f"Vertical speed ({vu})": [speed(r["conditions"].get("vertical_m_s")) for r in rows],
        f"Horizontal speed ({vu})": [speed(r["conditions"].get("horizontal_m_s")) for r in rows],
        "Slope (deg)": [r["conditions"].get("slope_deg") for r in rows],
        "Heading from downhill (deg)": [r["conditions"].get("from_downhill_deg") for r in rows],
        "mu static": [r["conditions"].get("mu_static") for r in rows],
        "mu dynamic": [r["conditions"].get("mu_dynamic") for r in rows],
        "Outcome": [r["outcome_class"] or r["outcome"] for r in rows],
        "Criteria": ["met" if not r["criteria_failed"] else "fails: " + "; ".join(r["criteria_failed"]) for r in rows],
        **{f"Peak XDD({k + 1}) (g)": [r["peak"]["xdd_g"][k] for r in rows] for k in range(3)}})


def interface_frame(res: DesignResult, system: str) -> pd.DataFrame:
    """One row per leg and body hardpoint (the "interface_loads" table): its largest force and the components, in
    the display unit, with the landing and the time into it."""
    t, fu = res.to_pandas()["interface_loads"], unit_label("force", system)
    force = lambda col: [to_display(v, "force", system) for v in t[col]]    # noqa: E731
    return pd.DataFrame({"Leg": t["leg"], "Hardpoint": t["hardpoint"], f"Force ({fu})": force("force_N"),
                         **{f"Component {i} ({fu})": force(f"force_{i}_N") for i in (1, 2, 3)},
                         "Landing": t["run_id"], "Time (s)": t["t_s"]})


def _png(fig, path: Path) -> None:
    save_png(fig, path, 90)


def audit_json(res: DesignResult) -> dict:
    """The audit (alightsize.audit/1): the required factor, the verdict and every check (the "checks" table)."""
    return {"schema": AUDIT_SCHEMA, "required_design_factor": res.config.required, "ok": all(r.ok for r in res.records),
            "checks": json_records(res.tables["checks"])}


def summary_json(res: DesignResult) -> dict:
    """summary.json (alightsize.design/1, docs/contracts.md) from the result and its tables."""
    cfg, tables = res.config, res.tables
    total = res.per_leg * cfg.legs
    items = tables["weights"][["item", "count_per_leg", "weight_each_kg"]]
    out = {"schema": SCHEMA, "ok": res.ok, "configuration": cfg.configuration, "verdict": res.verdict(),
           "checks_ok": res.checks_ok, "landings_ok": res.landings_ok,
           "required_below_one": [{"item": n, "required_design_factor": f} for n, f in res.below_one],
           "audit": {k: v for k, v in audit_json(res).items() if k != "schema"},
           "weights": {cfg.configuration: {
               "items": json_records(items), "per_leg_kg": res.per_leg, "legs": cfg.legs, "total_kg": total,
               "capsule_kg": cfg.capsule_mass,
               "fraction_of_capsule": total / cfg.capsule_mass if cfg.capsule_mass else None}}}
    if cfg.loads is not None:
        out["loads"] = {k: v for k, v in loads_json(cfg.loads).items() if k != "schema"}
    if cfg.landings is not None:
        out["landings"] = cfg.landings.cases()
        out["landing_margins"] = [c.as_json() for c in cfg.landings.closest]
        out["interface_loads"] = json_records(tables["interface_loads"])
    if "sizing" in tables:
        out["sizing"] = json_records(tables["sizing"])
    if res.footpad_sized is not None:
        out["footpad_mass"] = {"sized_kg": res.footpad_sized, "simulated_kg": cfg.footpad_mass,
                               "tolerance": FOOTPAD_MASS_TOLERANCE, "ok": res.footpad_ok}
    return out


def write_design(res: DesignResult, out: Path) -> list[Path]:
    """summary.json, report.html, report.md, design.xlsx and charts in `out`, each written atomically."""
    out.mkdir(parents=True, exist_ok=True)
    summary = json.dumps(summary_json(res), indent=2, allow_nan=False) + "\n"
    return [write_atomic(out / "summary.json", summary),
            write_atomic(out / "report.html", render_html(res)),
            write_atomic(out / "report.md", render_markdown(res)),
            write_atomic(out / "design.xlsx", lambda p: write_workbook(res, p)),
            write_atomic(out / "design_factors.png", lambda p: _png(res.plot("factors"), p)),
            write_atomic(out / "weights.png", lambda p: _png(res.plot("weights"), p))] + _loads_files(res, out)


def _loads_files(res: DesignResult, out: Path) -> list[Path]:
    """The envelopes' workbook, and heat maps of the governing configurations, beside the design report."""
    loads, system = res.config.loads, res.config.units
    if loads is None:
        return []
    files = [write_atomic(out / "max_member_loads.xlsx", lambda p: write_loads_workbook(loads, p, system))]
    for name in res.governing_cases():
        files.append(write_atomic(out / f"heatmap_{name}.png", lambda p, n=name: heatmap(loads, n, p, system)))
    return files
