"""Synthesis charts as matplotlib Figures (no pyplot state): the convergence history, a trade curve and the
Pareto set of weight against peak g."""

from __future__ import annotations

from math import degrees

from matplotlib.figure import Figure

from alightsize.common.units import registry
from alightsize.synthesis.evaluate import convergence


def convergence_figure(res) -> Figure:
    """Every candidate's weight fraction by generation (feasible filled, infeasible hollow) and the best so far."""
    fig = Figure(figsize=(7, 4), layout="tight")
    ax = fig.subplots()
    for feasible, style in ((True, {"color": "#4a7"}), (False, {"facecolors": "none", "edgecolors": "#c33"})):
        pts = [(g, 100 * e.fraction) for g, e in res.history if e.feasible == feasible and e.fraction is not None]
        if pts:
            ax.scatter(*zip(*pts), s=14, label="feasible" if feasible else "infeasible", **style)
    conv = [(c["generation"], 100 * c["best_weight_fraction"]) for c in convergence(res.history)
            if c["best_weight_fraction"] is not None]
    if conv:
        ax.step(*zip(*conv), where="post", color="k", label="best feasible")
    ax.set_xlabel("generation")
    ax.set_ylabel("leg system, % of the capsule")
    ax.legend()
    return fig


def trade_figure(res, axis: str) -> Figure:
    """The lightest feasible system's weight fraction at each limit of one trade axis."""
    pts = res.trade[axis]
    if axis == "slope":
        scale, unit = degrees(1.0), "deg"
    else:
        scale, unit = registry().Quantity(1.0, "m/s").to("knot").magnitude, "kn"
    fig = Figure(figsize=(6, 4), layout="tight")
    ax = fig.subplots()
    ok = [(p.value * scale, 100 * p.best.fraction) for p in pts if p.best.feasible]
    if ok:
        ax.plot(*zip(*ok), "o-", color="#357")
    for p in pts:
        if not p.best.feasible:
            ax.axvline(p.value * scale, color="#c33", ls=":", lw=1)
    ax.set_xlabel(f"{axis.replace('_', ' ')} limit ({unit}); dotted: no feasible design within the bounds")
    ax.set_ylabel("lightest leg system, % of the capsule")
    return fig


def pareto_figure(res) -> Figure:
    """Weight against peak g of every feasible candidate, the Pareto set joined."""
    fig = Figure(figsize=(6, 4), layout="tight")
    ax = fig.subplots()
    feas = [e for _, e in res.history if e.feasible and e.peak_g is not None]
    if feas:
        ax.scatter([e.peak_g for e in feas], [100 * e.fraction for e in feas], s=12, color="#aaa", label="feasible")
    front = res.pareto()
    if front:
        ax.plot([e.peak_g for e in front], [100 * e.fraction for e in front], "o-", color="#357", label="Pareto set")
    ax.set_xlabel("peak acceleration over the sample (g)")
    ax.set_ylabel("leg system, % of the capsule")
    ax.legend()
    return fig
