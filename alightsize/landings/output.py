"""One landing's results as docs/contracts.md asks: summary.json (alightsize.simulate/1), history.parquet and plots
(XDD and OMD against time as Figs. 33-38, cell strokes, the energy balance, the shock spectrum of XDD(3) as
Fig. 39)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pandas as pd

from alightsize_sim import crush_cell
from alightsize_sim.landing import Result, kinetic
from alightsize_sim.rigid_body import quat_matrices, roll_yaw_pitch
from alightsize_sim.terrain import height
from alightsize_sim.terrain import pack as pack_terrain

from alightsize.common.atomic import write_atomic
from alightsize.common.figures import literal
from alightsize.model.scene_config import SceneConfig
from alightsize.landings.footprints import features_met, plot_footprints
from alightsize.landings.shock_spectrum import default_frequencies, srs

ONSET_WINDOW = 1e-3        # s: onset rates are slopes of the acceleration sampled at this interval
WALK_WINDOW = 1.0          # s: a landing still moving at t_final walks if its CG moved along the terrain over this
LINE_STYLES = ("-", "--", ":", "-.")  # the stroke plot's cell kinds; the colour is the leg


def body_histories(cfg: SceneConfig, res: Result) -> tuple[np.ndarray, np.ndarray]:
    """XDD (g) and OMD (rad/s^2) in geometric body axes at every history point."""
    E = cfg.to_geometric
    return res.accel_g @ E.T, res.dy[:, 10:13] @ E.T


def energies(cfg: SceneConfig, res: Result) -> tuple[np.ndarray, np.ndarray]:
    """Kinetic and potential (from r = 0) energy at every history point (J)."""
    ke = np.array([kinetic(cfg.scene, y) for y in res.y])
    return ke, -cfg.scene.mass * res.y[:, 0:3] @ cfg.scene.gravity


def nutation_deg(cfg: SceneConfig, res: Result) -> np.ndarray:
    """Nutation (deg) at every history point: the angle of the capsule's up axis from the vertical, the angle the
    tip test compares with `tip_angle` (main program stmt 367)."""
    g = cfg.scene.gravity / np.linalg.norm(cfg.scene.gravity)
    up = quat_matrices(np.ascontiguousarray(res.y[:, 6:10])) @ cfg.scene.up
    return np.degrees(np.arccos(np.clip(-up @ g, -1.0, 1.0)))


def outcome(cfg: SceneConfig, res: Result) -> tuple[str, str]:
    """(outcome, reason) per docs/contracts.md from the loop's status."""
    if res.bottomed is not None:
        t, leg, cell = res.bottomed
        return "bottomed", (f"leg {leg + 1} {cfg.cell_names[leg][cell]} cell stroked past its crushing plateau "
                            f"at {t:.4f} s")
    st = res.status
    if st == "stable":
        return "stable", "energy criterion (eq. 89-95) satisfied over the footpads on the ground, no leg left to land"
    if st == "quiet":
        return "stable", "quiescence: motion below 2.5 % of the initial momentum for TAUS periods"
    if st == "tipped":
        return "tipped", f"nutation past the critical angle ({np.degrees(cfg.controls.tip_angle):.4g} deg)"
    if st == "body_contact":
        return "body_contact", "the body came within the clearance of the terrain"
    if st == "member_strike":
        return "body_contact", f"the intermediate member of leg {res.struck + 1} struck the terrain"
    if st == "failed":
        return "failed", "the step size collapsed or the state became non-finite"
    speed = terrain_speed(res.t, res.y)
    if speed > 0.025 * max(float(np.hypot(*cfg.scene.v0[:2])), 1.0):
        return "walking", f"still moving along the terrain at a mean {speed:.3g} m/s over the last {WALK_WINDOW:g} s"
    return "time_out", "final time reached before the capsule settled"


def terrain_speed(t: np.ndarray, y: np.ndarray) -> float:
    """Mean speed of the CG along the terrain over the last WALK_WINDOW seconds (the last half of a shorter run;
    the final speed for a single point), so that a capsule hopping down a slope does not read as at rest at a
    hop's slow instant."""
    k = int(np.searchsorted(t, t[-1] - min(WALK_WINDOW, 0.5 * (t[-1] - t[0]))))
    if k >= len(t) - 1:
        return float(np.hypot(*y[-1, 3:5]))
    return float(np.hypot(*(y[-1, 0:2] - y[k, 0:2])) / (t[-1] - t[k]))


def onset(t: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Largest |dx/dt| per column, x resampled every ONSET_WINDOW seconds (0 if the run is shorter)."""
    if t[-1] - t[0] < 2 * ONSET_WINDOW:
        return np.zeros(x.shape[1])
    grid = np.arange(t[0], t[-1], ONSET_WINDOW)
    return np.array([np.max(np.abs(np.diff(np.interp(grid, t, x[:, k])))) / ONSET_WINDOW for k in range(x.shape[1])])


def max_sinkage(cfg: SceneConfig, res: Result) -> np.ndarray:
    """Per leg, the deepest its footpad went below the surface under it while on the ground (m; 0 without soil)."""
    n = len(cfg.scene.legs)
    if cfg.scene.soil is None:
        return np.zeros(n)
    packed = pack_terrain(cfg.scene.terrain)
    depth = np.zeros(n)
    for k, i in zip(*np.nonzero(res.contact)):
        x, y, z = res.footpad[k, i]
        depth[i] = max(depth[i], height(packed, x, y) - z)
    return depth


def summary(cfg: SceneConfig, res: Result) -> dict:
    xdd, omd = body_histories(cfg, res)
    kind, reason = outcome(cfg, res)
    legs = []
    met, sunk = features_met(cfg.scene, res), max_sinkage(cfg, res)
    for i, leg in enumerate(cfg.scene.legs):
        cells = []
        for j, cell in enumerate(leg.cells):
            dmax, fmax = res.memory[i, j]
            cells.append({"cell": cfg.cell_names[i][j], "max_deflection_m": float(dmax),
                          "permanent_set_m": float(crush_cell.permanent_set(cell.k, dmax, fmax)),
                          "energy_J": float(res.cell_energy[i, j]), "bottomed": bool(dmax > cell.curve.bottoming)})
        legs.append({"leg": i + 1, "cells": cells,
                     "max_ground_force_N": float(np.max(np.linalg.norm(res.leg_force[:, i], axis=1))),
                     "features": met[i], "max_sinkage_m": float(sunk[i])})
    return {"schema": "alightsize.simulate/1", "scene": cfg.name, "outcome": kind, "reason": reason,
            "t_end_s": float(res.t[-1]),
            "peak": {"xdd_g": np.max(np.abs(xdd), axis=0).tolist(), "omd_rad_s2": np.max(np.abs(omd), axis=0).tolist(),
                     "onset_g_s": onset(res.t, xdd).tolist(), "nutation_deg": float(np.max(nutation_deg(cfg, res)))},
            "legs": legs, "energy": {k: float(v) for k, v in res.energy.items()},
            "solver": {"method": "dopri5" if cfg.controls.fixed_step is None else "dopri5-fixed",
                       "steps": res.steps, "rejected_steps": res.rejected, "rhs_evals": res.rhs_evals,
                       "wall_s": res.wall_s}}


def history_frame(cfg: SceneConfig, res: Result) -> pd.DataFrame:
    """The history table of docs/contracts.md (SI, unit-suffixed columns), at every accepted step or resampled
    at the scene's output interval."""
    xdd, omd = body_histories(cfg, res)
    E = cfg.to_geometric
    cols: dict[str, np.ndarray] = {"t_s": res.t}
    for k, ax in enumerate("123"):
        cols[f"r{ax}_m"] = res.y[:, k]
    for k, ax in enumerate("123"):
        cols[f"rd{ax}_m_s"] = res.y[:, 3 + k]
    for k, ax in enumerate("123"):
        cols[f"rdd{ax}_m_s2"] = res.dy[:, 3 + k]
    for k, ax in enumerate("123"):
        cols[f"xdd{ax}_g"] = xdd[:, k]
    omega = res.y[:, 10:13] @ E.T
    for k, ax in enumerate("123"):
        cols[f"omega{ax}_rad_s"] = omega[:, k]
    for k, ax in enumerate("123"):
        cols[f"omd{ax}_rad_s2"] = omd[:, k]
    to_vertical = cfg.terrain_from_vertical.T
    attitude = to_vertical @ quat_matrices(np.ascontiguousarray(res.y[:, 6:10])) @ E.T
    att = np.array([roll_yaw_pitch(m) for m in attitude])
    for k, name in enumerate(("roll", "yaw", "pitch")):
        cols[f"{name}_deg"] = np.degrees(att[:, k])
    for i, leg in enumerate(cfg.scene.legs):
        p = f"leg{i + 1}_"
        cols[p + "contact"] = res.contact[:, i].astype(np.int8)
        for k, ax in enumerate("123"):
            cols[f"{p}footpad{ax}_m"] = np.where(res.contact[:, i] > 0, res.footpad[:, i, k], np.nan)
        for j, name in enumerate(cfg.cell_names[i]):
            cols[f"{p}{name}_deflection_m"] = res.deflections[:, i, j]
            cols[f"{p}{name}_force_N"] = res.forces[:, i, j]
        f_leg = res.leg_force[:, i] @ leg.to_body          # principal -> leg axes
        for k, ax in enumerate("123"):
            cols[f"{p}force{ax}_N"] = f_leg[:, k]
    cols["leg_work_J"] = res.y[:, 13]
    cols["kinetic_J"], cols["potential_J"] = energies(cfg, res)
    df = pd.DataFrame(cols)
    if cfg.output_interval:
        grid = np.arange(res.t[0], res.t[-1] + 0.5 * cfg.output_interval, cfg.output_interval)
        df = pd.DataFrame({c: (np.interp(grid, res.t, df[c].to_numpy(float)) if c != "t_s" else grid)
                           for c in df.columns})
    return df


def plots(cfg: SceneConfig, res: Result, out: Path) -> list[Path]:
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D
    xdd, omd = body_histories(cfg, res)
    files = []

    def save(fig, name):
        path = out / name
        write_atomic(path, lambda tmp: fig.savefig(tmp, format="png", dpi=110, metadata={"Software": None}))
        files.append(path)

    for data, label, unit, name in ((xdd, "XDD", "g", "xdd.png"), (omd, "OMD", "rad/s²", "omd.png")):
        fig = Figure(figsize=(7, 7), layout="constrained")
        axes = fig.subplots(3, 1, sharex=True)
        for k in range(3):
            axes[k].plot(res.t, data[:, k], lw=0.9)
            axes[k].set_ylabel(f"{label}({k + 1}), {unit}")
            axes[k].grid(alpha=0.3)
        axes[-1].set_xlabel("time, s")
        fig.suptitle(f"{literal(cfg.title)}: {label} (cf. Figs. 33-38)")
        save(fig, name)
    fig = Figure(figsize=(7, 4), layout="constrained")
    ax = fig.subplots()
    kinds = {}                              # cell kind ("rot" for rot1-rot4) -> line style
    for i in range(len(cfg.scene.legs)):
        for j, name in enumerate(cfg.cell_names[i]):
            d = res.deflections[:, i, j]
            if np.nanmax(np.abs(np.nan_to_num(d))) > 0:
                style = kinds.setdefault(name.rstrip("0123456789"), LINE_STYLES[len(kinds) % len(LINE_STYLES)])
                ax.plot(res.t, d * 1000, lw=0.8, color=f"C{i}", ls=style)
    ax.set_xlabel("time, s")
    ax.set_ylabel("cell deflection, mm")
    ax.grid(alpha=0.3)
    handles = [Line2D([], [], color=f"C{i}", label=f"leg {i + 1}") for i in range(len(cfg.scene.legs))]
    handles += [Line2D([], [], color="k", ls=style, lw=0.8, label=kind) for kind, style in kinds.items()]
    fig.legend(handles=handles, loc="outside right upper", fontsize=8)
    save(fig, "strokes.png")
    fig = Figure(figsize=(7, 4), layout="constrained")
    ax = fig.subplots()
    ke, pe = energies(cfg, res)
    ax.plot(res.t, ke, label="kinetic")
    ax.plot(res.t, pe - pe[0], label="potential (from first contact)")
    ax.plot(res.t, res.y[:, 13], label="work taken by the legs")
    ax.plot(res.t, ke + pe - pe[0] + res.y[:, 13], "k--", label="sum (conserved)")
    ax.set_xlabel("time, s")
    ax.set_ylabel("energy, J")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, "energy.png")
    fig = Figure(figsize=(6, 6), layout="constrained")
    ax = fig.subplots()
    plot_footprints(cfg.scene, res, ax)
    ax.set_title("Footprints on the terrain (plan, terrain axes)")
    save(fig, "footprints.png")
    if res.t[-1] > 0:
        f = default_frequencies(1.0, 1000.0)
        spec = srs(res.t, xdd[:, 2], f, cfg.srs_damping)
        fig = Figure(figsize=(7, 4), layout="constrained")
        ax = fig.subplots()
        ax.loglog(f, spec)
        ax.set_xlabel("frequency, Hz")
        ax.set_ylabel("maximax absolute acceleration, g")
        ax.set_title(f"Shock spectrum of XDD(3), {cfg.srs_damping:.0%} damping (cf. Fig. 39)")
        ax.grid(alpha=0.3, which="both")
        save(fig, "srs_xdd3.png")
    return files


def write_landing(cfg: SceneConfig, res: Result, out: Path) -> list[Path]:
    out.mkdir(parents=True, exist_ok=True)
    summ = summary(cfg, res)
    files = [write_atomic(out / "summary.json", json.dumps(summ, indent=2) + "\n")]
    df = history_frame(cfg, res)
    files.append(write_atomic(out / "history.parquet", lambda tmp: df.to_parquet(tmp, index=False)))
    files += plots(cfg, res, out)
    return files
