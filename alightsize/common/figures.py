"""Every chart of alightsize, drawn from a result's tables and arrays into a matplotlib Figure (the object API, no
pyplot state, so they work headless and in notebooks). Results call these from `.plot(kind)`; reports save them.
Nothing here computes a result: each function takes what it draws."""

from __future__ import annotations

from math import degrees
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.figure import Figure

LINE_STYLES = ("-", "--", ":", "-.")  # the stroke plot's cell kinds; the colour is the leg


def literal(text: str) -> str:
    """User text (an item, a title, a parameter) as matplotlib draws it literally: each `$` escaped, so no name is
    read as mathtext (an unbalanced `$\\foo{$` would raise while drawing). matplotlib shows `\\$` as `$`."""
    return str(text).replace("$", r"\$")


def save_png(fig: Figure, path: Path, dpi: int) -> None:
    """`fig` as a PNG without matplotlib's version stamp, so the same figure gives the same bytes."""
    fig.savefig(path, format="png", dpi=dpi, metadata={"Software": None})


def pick(figures: dict, kind: str):
    """The figure function of `kind`, or ValueError naming the kinds there are."""
    if kind not in figures:
        raise ValueError(f"plot kind {kind!r}: expected one of {', '.join(figures)}")
    return figures[kind]


# ------------------------------------------------------------------ design
def design_factor_figure(checks: pd.DataFrame, configuration: str) -> Figure:
    """Horizontal bars of each item's governing design factor (the "checks" table of a DesignResult, items in
    their order), the required factor as a dashed line."""
    rows = []
    for item, recs in checks.groupby("item", sort=False):
        recs = recs[np.isfinite(recs["design_factor"].astype(float))]
        if len(recs):
            gov = recs.loc[recs["design_factor"].astype(float).idxmin()]
            rows.append((literal(item), float(gov["design_factor"]), float(gov["required_design_factor"]),
                         bool(gov["ok"])))
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
    ax.set_title(f"Configuration {literal(configuration)}: design factors (dashed: required)")
    return fig


def weight_figure(weights: pd.DataFrame, configuration: str, system: str) -> Figure:
    """Horizontal bars of each item's weight per leg (the "weights" table of a DesignResult), in the display unit."""
    from alightsize.common.units import to_display, unit_label
    rows = weights.sort_values("weight_per_leg_kg", kind="stable")
    fig = Figure(figsize=(7, 0.35 * len(rows) + 1.2), layout="tight")
    ax = fig.subplots()
    ax.barh([literal(w) for w in rows["item"]], [to_display(w, "mass", system) for w in rows["weight_per_leg_kg"]],
            color="#468")
    ax.set_xlabel(f"weight per leg ({unit_label('mass', system)})")
    ax.set_title(f"Configuration {literal(configuration)}: weight breakdown")
    return fig


# ------------------------------------------------------------------ loads
def heatmap_figure(fields: pd.DataFrame, case_name: str, system: str, labels: dict[str, str]) -> Figure:
    """Each member's load over alpha-beta at the psi of its largest magnitude (LoadsResult.fields: one row per
    member and grid point at that psi, load_N NaN where a cell has bottomed), panels in the members' order,
    titled with `labels` (member -> label, default the member)."""
    from alightsize.common.units import to_display, unit_label
    fig = Figure(figsize=(20, 6.5), layout="constrained")
    axes = fig.subplots(2, 6, sharex=True, sharey=True)
    for ax in axes.flat[fields["member"].nunique():]:
        ax.set_axis_off()
    bottomed = False
    for ax, (member, f) in zip(axes.flat, fields.groupby("member", sort=False)):
        a, b = pd.unique(f["alpha_deg"]), pd.unique(f["beta_deg"])
        grid = to_display(f["load_N"].to_numpy(float), "force", system).reshape(len(a), len(b))
        lim = float(np.nanmax(np.abs(grid))) or 1.0
        bottomed |= bool(np.isnan(grid).any())
        ax.set_facecolor("0.8")
        im = ax.imshow(grid.T, origin="lower", extent=(a[0], a[-1], b[0], b[-1]), aspect="auto", cmap="RdBu_r",
                       vmin=-lim, vmax=lim, interpolation="nearest")
        ax.set_title(f"{labels.get(member, member)} at psi = {f['psi_deg'].iloc[0]:+.0f} deg", fontsize=9)
        fig.colorbar(im, ax=ax)
    for ax in axes[1]:
        ax.set_xlabel("alpha (deg)")
    for ax in axes[:, 0]:
        ax.set_ylabel("beta (deg)")
    fig.suptitle(f"Configuration {case_name}: member loads, {unit_label('force', system)} (tension +), over alpha-beta "
                 "at the governing psi" + ("; grey: a cell has bottomed" if bottomed else ""))
    return fig


# ------------------------------------------------------------------ one landing
def body_figure(t: np.ndarray, data: np.ndarray, label: str, unit: str, title: str) -> Figure:
    """XDD (g) or OMD (rad/s²) about the three body axes against time (cf. Figs. 33-38)."""
    fig = Figure(figsize=(7, 7), layout="constrained")
    axes = fig.subplots(3, 1, sharex=True)
    for k in range(3):
        axes[k].plot(t, data[:, k], lw=0.9)
        axes[k].set_ylabel(f"{label}({k + 1}), {unit}")
        axes[k].grid(alpha=0.3)
    axes[-1].set_xlabel("time, s")
    fig.suptitle(f"{literal(title)}: {label} (cf. Figs. 33-38)")
    return fig


def strokes_figure(t: np.ndarray, deflections: np.ndarray, cell_names: list[list[str]]) -> Figure:
    """Every cell's deflection (mm) against time: colour the leg, line style the cell kind ("rot" for rot1-rot4)."""
    from matplotlib.lines import Line2D
    fig = Figure(figsize=(7, 4), layout="constrained")
    ax = fig.subplots()
    kinds: dict[str, str] = {}
    for i, names in enumerate(cell_names):
        for j, name in enumerate(names):
            d = deflections[:, i, j]
            if np.nanmax(np.abs(np.nan_to_num(d))) > 0:
                style = kinds.setdefault(name.rstrip("0123456789"), LINE_STYLES[len(kinds) % len(LINE_STYLES)])
                ax.plot(t, d * 1000, lw=0.8, color=f"C{i}", ls=style)
    ax.set_xlabel("time, s")
    ax.set_ylabel("cell deflection, mm")
    ax.grid(alpha=0.3)
    handles = [Line2D([], [], color=f"C{i}", label=f"leg {i + 1}") for i in range(len(cell_names))]
    handles += [Line2D([], [], color="k", ls=style, lw=0.8, label=kind) for kind, style in kinds.items()]
    fig.legend(handles=handles, loc="outside right upper", fontsize=8)
    return fig


def energy_figure(t: np.ndarray, kinetic: np.ndarray, potential: np.ndarray, leg_work: np.ndarray) -> Figure:
    """Kinetic, potential (from first contact) and leg work against time, and their sum (conserved)."""
    fig = Figure(figsize=(7, 4), layout="constrained")
    ax = fig.subplots()
    ax.plot(t, kinetic, label="kinetic")
    ax.plot(t, potential - potential[0], label="potential (from first contact)")
    ax.plot(t, leg_work, label="work taken by the legs")
    ax.plot(t, kinetic + potential - potential[0] + leg_work, "k--", label="sum (conserved)")
    ax.set_xlabel("time, s")
    ax.set_ylabel("energy, J")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return fig


def footprints_figure(terrain, tracks: list[np.ndarray], cg: np.ndarray) -> Figure:
    """Plan view in terrain axes: the height field shaded, steps (edge, raised side hatched), rocks outlined, each
    leg's footpad track on the ground (`tracks`, its colour) with its first touchdown marked, and the CG track."""
    import matplotlib.patches as mp
    fig = Figure(figsize=(6, 6), layout="constrained")
    ax = fig.subplots()
    pts = np.vstack([t for t in tracks if len(t)] + [cg])
    lo, hi = pts.min(axis=0) - 0.5, pts.max(axis=0) + 0.5
    f = terrain.height_field
    if f is not None:
        ny, nx = f.z.shape
        ax.imshow(f.z, origin="lower", extent=(f.x0, f.x0 + (nx - 1) * f.dx, f.y0, f.y0 + (ny - 1) * f.dy),
                  cmap="Greys", alpha=0.5)
    span = float(np.hypot(*(hi - lo)))
    for k, s in enumerate(terrain.steps):
        d = np.array([np.cos(np.radians(s.direction_deg)), np.sin(np.radians(s.direction_deg))])
        left = np.array([-d[1], d[0]])
        a, b = np.array([s.x, s.y]) - span * d, np.array([s.x, s.y]) + span * d
        ax.plot(*np.c_[a, b], color="k", lw=1.2)
        ax.add_patch(mp.Polygon([a, b, b + 0.15 * span * left, a + 0.15 * span * left], closed=True, fill=False,
                                hatch="//", lw=0, edgecolor="0.6"))
        ax.annotate(f"step {k + 1}: {s.height * 1000:+.0f} mm", (s.x, s.y), fontsize=7)
    for k, r in enumerate(terrain.hemispheres):
        ax.add_patch(mp.Circle((r.x, r.y), r.radius, fill=False, color="k", lw=1.0))
        ax.annotate(f"rock {k + 1}", (r.x, r.y), fontsize=7, ha="center")
    for k, b in enumerate(terrain.boxes):
        ax.add_patch(mp.Rectangle((b.x - b.length / 2, b.y - b.width / 2), b.length, b.width, angle=b.yaw_deg,
                                  rotation_point="center", fill=False, color="k", lw=1.0))
        ax.annotate(f"box {k + 1}", (b.x, b.y), fontsize=7, ha="center")
    for i, t in enumerate(tracks):
        if len(t):
            ax.plot(t[:, 0], t[:, 1], color=f"C{i}", lw=1.5, label=f"leg {i + 1}")
            ax.plot(*t[0], "o", color=f"C{i}", ms=4)
    ax.plot(cg[:, 0], cg[:, 1], "k--", lw=0.8, label="CG")
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal")
    ax.set_xlabel("terrain x, m")
    ax.set_ylabel("terrain y, m")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    ax.set_title("Footprints on the terrain (plan, terrain axes)")
    return fig


def srs_figure(spectrum: pd.DataFrame, damping: float, title: str = "", layout: str | None = "constrained") -> Figure:
    """Maximax shock response spectrum of XDD(3) (columns frequency_Hz, acceleration_g; cf. Fig. 39)."""
    fig = Figure(figsize=(7, 4), layout=layout)
    ax = fig.subplots()
    ax.loglog(spectrum["frequency_Hz"], spectrum["acceleration_g"])
    ax.set_xlabel("frequency, Hz")
    ax.set_ylabel("maximax absolute acceleration, g")
    ax.set_title(title or f"Shock spectrum of XDD(3), {damping:.0%} damping (cf. Fig. 39)")
    ax.grid(alpha=0.3, which="both")
    if layout is None:
        fig.subplots_adjust(bottom=0.14)
    return fig


def drop_histories_figure(t: np.ndarray, xdd: np.ndarray, omd: np.ndarray, title: str) -> Figure:
    """XDD(1..3) (g) and OMD(1..3) (rad/s²) side by side against time (cf. Figs. 33-100)."""
    fig = Figure(figsize=(10, 7))
    axes = fig.subplots(3, 2, sharex=True)
    for k in range(3):
        for col, (data, label) in enumerate(((xdd, f"XDD({k + 1}), g"), (omd, f"OMD({k + 1}), rad/s²"))):
            axes[k, col].plot(t, data[:, k], lw=0.9)
            axes[k, col].set_ylabel(label)
            axes[k, col].grid(alpha=0.3)
    for ax in axes[-1]:
        ax.set_xlabel("time, s")
    fig.suptitle(title)
    fig.subplots_adjust(wspace=0.3)
    return fig


def drop_energy_figure(drops: pd.DataFrame) -> Figure:
    """Total cell energy against the drop energy (ft-lb) per drop, simulated, analytical and experimental, with
    the 1:1 line (Fig. 102); columns drop, drop_energy, simulated, analytical, experimental."""
    x = drops["drop_energy"].to_numpy(float)
    fig = Figure(figsize=(6, 6))
    ax = fig.subplots()
    for src, marker, label in (("simulated", "o", "this simulation"), ("analytical", "s", "analytical (printed)"),
                               ("experimental", "^", "experimental (printed)")):
        ax.scatter(x, drops[src], marker=marker, label=label, facecolors="C0" if src == "simulated" else "none",
                   edgecolors="C0" if src == "simulated" else "k")
    for n, xi, yi in zip(drops["drop"], x, drops["simulated"]):
        ax.annotate(str(n), (xi, yi), fontsize=7, xytext=(4, -10), textcoords="offset points")
    lim = (0.0, 1.1 * float(x.max()))
    ax.plot(lim, lim, "k--", lw=0.8, label="1:1")
    ax.set_xlim(lim)
    ax.set_ylim(lim)
    ax.set_xlabel("drop energy (Tables 6-13), ft-lb")
    ax.set_ylabel("total cell energy, ft-lb")
    ax.set_title("Comparison of energy absorption (cf. Fig. 102)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return fig


# ------------------------------------------------------------------ sweeps
def boundary_figure(points: pd.DataFrame, labels: tuple[str, str]) -> Figure:
    """Success fraction at each (x, y) of two parameters (columns x, y, fraction): green successful, red not; the
    50 % contour on a full grid."""
    xy, frac = points[["x", "y"]].to_numpy(float), points["fraction"].to_numpy(float)
    fig = Figure(figsize=(6.4, 4.8))
    ax = fig.subplots()
    sc = ax.scatter(xy[:, 0], xy[:, 1], c=frac, cmap="RdYlGn", vmin=0, vmax=1, s=60 if len(xy) < 400 else 12,
                    edgecolors="k", linewidths=0.3)
    fig.colorbar(sc, ax=ax, label="fraction of runs successful")
    xs, ys = np.unique(xy[:, 0]), np.unique(xy[:, 1])
    full = len(xs) * len(ys) == len(xy)
    if len(xs) > 1 and len(ys) > 1 and full:                          # a full grid: the 50 % contour
        z = np.full((len(ys), len(xs)), np.nan)
        z[np.searchsorted(ys, xy[:, 1]), np.searchsorted(xs, xy[:, 0])] = frac
        ax.contour(xs, ys, z, levels=[0.5], colors="k", linewidths=1.2)
    ax.set_xlabel(literal(labels[0]))
    ax.set_ylabel(literal(labels[1]))
    ax.set_title("Successful runs over two parameters" + (" (line: half successful)" if full else ""))
    fig.tight_layout()
    return fig


def distribution_figure(runs: pd.DataFrame) -> Figure:
    """Histograms of peak XDD(3) and the largest cell stroke of every run in `runs` (the stored rows)."""
    fig = Figure(figsize=(9, 3.6))
    axs = fig.subplots(1, 2)
    for ax, key, label in zip(axs, ("peak_xdd3_g", "max_stroke_m"), ("peak XDD(3) (g)", "largest cell stroke (m)")):
        x = runs[key].dropna().to_numpy(float) if key in runs else np.array([])
        ax.hist(x, bins=min(40, max(5, int(np.sqrt(len(x))))), color="#4a7", edgecolor="k", linewidth=0.3)
        ax.set_xlabel(label)
        ax.set_ylabel("runs")
    fig.tight_layout()
    return fig


# ------------------------------------------------------------------ synthesis
def convergence_figure(candidates: pd.DataFrame, convergence: pd.DataFrame) -> Figure:
    """Every candidate's weight fraction by generation (feasible filled, infeasible hollow) and the best so far."""
    fig = Figure(figsize=(7, 4), layout="tight")
    ax = fig.subplots()
    for feasible, style in ((True, {"color": "#4a7"}), (False, {"facecolors": "none", "edgecolors": "#c33"})):
        pts = candidates[(candidates["feasible"] == feasible) & candidates["weight_fraction"].notna()]
        if len(pts):
            ax.scatter(pts["generation"], 100 * pts["weight_fraction"].astype(float), s=14,
                       label="feasible" if feasible else "infeasible", **style)
    conv = convergence[convergence["best_weight_fraction"].notna()] if len(convergence) else convergence
    if len(conv):
        ax.step(conv["generation"], 100 * conv["best_weight_fraction"].astype(float), where="post", color="k",
                label="best feasible")
    ax.set_xlabel("generation")
    ax.set_ylabel("leg system, % of the capsule")
    ax.legend()
    return fig


def trade_figure(trade: pd.DataFrame, axis: str) -> Figure:
    """The lightest feasible system's weight fraction at each limit of one trade axis (rows of that axis)."""
    from alightsize.common.units import registry
    if axis == "slope":
        scale, unit = degrees(1.0), "deg"
    else:
        scale, unit = registry().Quantity(1.0, "m/s").to("knot").magnitude, "kn"
    fig = Figure(figsize=(6, 4), layout="tight")
    ax = fig.subplots()
    ok = trade[trade["feasible"].astype(bool)]
    if len(ok):
        ax.plot(ok["value"] * scale, 100 * ok["weight_fraction"].astype(float), "o-", color="#357")
    for v in trade.loc[~trade["feasible"].astype(bool), "value"]:
        ax.axvline(v * scale, color="#c33", ls=":", lw=1)
    ax.set_xlabel(f"{axis.replace('_', ' ')} limit ({unit}); dotted: no feasible design within the bounds")
    ax.set_ylabel("lightest leg system, % of the capsule")
    return fig


def pareto_figure(feasible: pd.DataFrame, front: pd.DataFrame) -> Figure:
    """Weight fraction against peak g of every feasible candidate, the Pareto set joined (columns peak_g,
    weight_fraction)."""
    fig = Figure(figsize=(6, 4), layout="tight")
    ax = fig.subplots()
    if len(feasible):
        ax.scatter(feasible["peak_g"], 100 * feasible["weight_fraction"], s=12, color="#aaa", label="feasible")
    if len(front):
        ax.plot(front["peak_g"], 100 * front["weight_fraction"], "o-", color="#357", label="Pareto set")
    ax.set_xlabel("peak acceleration over the sample (g)")
    ax.set_ylabel("leg system, % of the capsule")
    ax.legend()
    return fig


# ------------------------------------------------------------------ bench
def bench_figure(data: dict) -> Figure:
    """Wall time per simulated second against the relative error in peak XDD(3), per scene and method
    (bench.json)."""
    scenes = list(data["references"])
    methods = sorted({c["method"] for c in data["cases"]})
    ncol = min(3, len(scenes))
    nrow = -(-len(scenes) // ncol)
    fig = Figure(figsize=(4.2 * ncol, 3.4 * nrow + 0.8), layout="constrained")
    axes = fig.subplots(nrow, ncol, squeeze=False)
    for ax in axes.flat[len(scenes):]:
        ax.set_axis_off()
    for ax, scene in zip(axes.flat, scenes):
        for k, method in enumerate(methods):
            pts = [(c["err_peak_xdd3_rel"], c["wall_s"] * 1000 / c["t_sim_s"]) for c in data["cases"]
                   if c["scene"] == scene and c["method"] == method]
            if pts:
                e, w = zip(*pts)
                ax.loglog(np.maximum(e, 1e-16), w, "o-", color=f"C{k}", label=method)
        ax.axvline(data["target_error"], color="grey", lw=0.8, ls=":")
        lo, hi = ax.get_xlim()
        unc = data["reference_uncertainty"][scene]["err_peak_xdd3_rel"]
        if unc > lo:
            ax.axvspan(lo, unc, color="grey", alpha=0.15, lw=0, label="below the reference's uncertainty")
            ax.set_xlim(lo, hi)
        ax.axhline(data["target_ms_per_simulated_s"][scene], color="grey", lw=0.8, ls=":")
        ax.set_title(scene, fontsize=9)
        ax.set_xlabel("relative error in peak XDD(3)")
        ax.set_ylabel("wall ms per simulated second")
        ax.grid(alpha=0.3, which="both")
    handles: dict = {}
    for ax in axes.flat:
        for h, label in zip(*ax.get_legend_handles_labels()):
            handles.setdefault(label, h)
    fig.legend(handles.values(), handles.keys(), loc="outside lower center", ncol=min(4, len(handles)), fontsize=8)
    return fig

