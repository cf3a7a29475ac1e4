"""Design charts as matplotlib Figures (no pyplot state, so they work headless and in notebooks): each item's
governing design factor against the requirement, and the weight breakdown."""

from __future__ import annotations

from math import isfinite

from matplotlib.figure import Figure

from alightsize.common.figures import literal
from alightsize.common.units import to_display, unit_label


def design_factor_figure(res) -> Figure:
    """Horizontal bars of each item's governing design factor, the required factor as a line."""
    rows = []
    for item in res.items:
        recs = [r for r in res.records if r.item is item and isfinite(r.outcome.factor)]
        if recs:
            gov = min(recs, key=lambda r: r.outcome.factor)
            rows.append((literal(item.name), gov.outcome.factor, gov.required, gov.ok))
    fig = Figure(figsize=(7, 0.35 * len(rows) + 1.2), layout="tight")
    ax = fig.subplots()
    names = [r[0] for r in rows][::-1]
    vals = [r[1] for r in rows][::-1]
    colors = ["#4a7" if r[3] else "#c33" for r in rows][::-1]
    ax.barh(names, vals, color=colors)
    for req in sorted({r[2] for r in rows}):
        ax.axvline(req, color="k", lw=1, ls="--")
    right = min(max(vals + [1.6]) * 1.05, 2.5)
    for y, v in enumerate(vals):
        ax.text(min(v, right) + 0.01, y, f"{v:.2f}", va="center", fontsize=8)
    ax.set_xlabel("governing design factor f = allowable / stress")
    ax.set_xlim(0.8, right + 0.15)
    ax.set_title(f"Configuration {literal(res.config.configuration)}: design factors (dashed: required)")
    return fig


def weight_figure(res) -> Figure:
    """Horizontal bars of each item's weight per leg, in the display unit."""
    system = res.config.units
    rows = sorted(res.weights, key=lambda w: w.count * w.each)
    fig = Figure(figsize=(7, 0.35 * len(rows) + 1.2), layout="tight")
    ax = fig.subplots()
    ax.barh([literal(w.label) for w in rows], [to_display(w.count * w.each, "mass", system) for w in rows],
            color="#468")
    ax.set_xlabel(f"weight per leg ({unit_label('mass', system)})")
    ax.set_title(f"Configuration {literal(res.config.configuration)}: weight breakdown")
    return fig
