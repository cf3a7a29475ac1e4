"""One landing's results as docs/contracts.md asks: the summary (alightsize.simulate/1), the history table, and
the LandingResult that holds them as tables and draws them (XDD and OMD against time as Figs. 33-38, cell
strokes, the energy balance, footprints, the shock spectrum of XDD(3) as Fig. 39)."""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
import pandas as pd

from alightsize_sim import crush_cell
from alightsize_sim.landing import Result, kinetic, simulate
from alightsize_sim.rigid_body import quat_matrices, roll_yaw_pitch
from alightsize_sim.terrain import height
from alightsize_sim.terrain import pack as pack_terrain

from alightsize.model.scene_config import SceneConfig
from alightsize.landings.footprints import features_met
from alightsize.landings.shock_spectrum import default_frequencies, srs

ONSET_WINDOW = 1e-3        # s: onset rates are slopes of the acceleration sampled at this interval
WALK_WINDOW = 1.0          # s: a landing still moving at t_final walks if its CG moved along the terrain over this


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
    if st == "folded_flat":
        return "failed", (f"leg {res.struck + 1} folded flat: its struts met coplanar at the footpad or knee, or a "
                          "cantilever's primary stroked to its knee")
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
        if res.struts is not None and not np.isnan(res.struts[:, i]).all():     # a tripod leg
            for k, strut in enumerate(("primary", "secondary1", "secondary2")):
                cols[f"{p}{strut}_axial_N"] = res.struts[:, i, k]
    cols["leg_work_J"] = res.y[:, 13]
    cols["kinetic_J"], cols["potential_J"] = energies(cfg, res)
    df = pd.DataFrame(cols)
    if cfg.output_interval:
        grid = np.arange(res.t[0], res.t[-1] + 0.5 * cfg.output_interval, cfg.output_interval)
        df = pd.DataFrame({c: (np.interp(grid, res.t, df[c].to_numpy(float)) if c != "t_s" else grid)
                           for c in df.columns})
    return df


@dataclass(frozen=True)
class LandingResult:
    """One landing of a scene: the scene as read, the simulator's Result, and what alightsize reads from them."""

    config: SceneConfig
    result: Result

    @cached_property
    def summary(self) -> dict:
        """summary.json (alightsize.simulate/1, docs/contracts.md)."""
        return summary(self.config, self.result)

    @cached_property
    def history(self) -> pd.DataFrame:
        """The history table (history.parquet): SI, unit-suffixed columns."""
        return history_frame(self.config, self.result)

    def body(self) -> tuple[np.ndarray, np.ndarray]:
        """XDD (g) and OMD (rad/s^2) in geometric body axes at every accepted step."""
        return body_histories(self.config, self.result)

    def spectrum(self) -> pd.DataFrame:
        """The maximax shock response spectrum of XDD(3) at the scene's damping, 1 Hz to 1 kHz (empty for a
        landing that ended at its start)."""
        res = self.result
        if not res.t[-1] > 0:
            return pd.DataFrame({"frequency_Hz": [], "acceleration_g": []})
        f = default_frequencies(1.0, 1000.0)
        xdd = self.body()[0]
        return pd.DataFrame({"frequency_Hz": f, "acceleration_g": srs(res.t, xdd[:, 2], f, self.config.srs_damping)})

    def to_pandas(self) -> dict[str, pd.DataFrame]:
        """The landing as tables, SI with the unit in each column name: "history" (every point), "cells" (one row
        per leg and cell), "legs" (one row per leg; features met joined by "; "), "peak", "energy" and "solver"
        (one row each: the summary's figures, XDD/OMD/onset per body axis 1-3) and "srs" (the shock spectrum of
        XDD(3))."""
        s = self.summary
        peak = s["peak"]
        return {
            "history": self.history,
            "cells": pd.DataFrame([{"leg": leg["leg"], **c} for leg in s["legs"] for c in leg["cells"]]),
            "legs": pd.DataFrame([{"leg": leg["leg"], "max_ground_force_N": leg["max_ground_force_N"],
                                   "max_sinkage_m": leg["max_sinkage_m"], "features": "; ".join(leg["features"])}
                                  for leg in s["legs"]]),
            "peak": pd.DataFrame([{**{f"xdd{k + 1}_g": v for k, v in enumerate(peak["xdd_g"])},
                                   **{f"omd{k + 1}_rad_s2": v for k, v in enumerate(peak["omd_rad_s2"])},
                                   **{f"onset_xdd{k + 1}_g_s": v for k, v in enumerate(peak["onset_g_s"])},
                                   "nutation_deg": peak["nutation_deg"], "t_end_s": s["t_end_s"],
                                   "outcome": s["outcome"], "reason": s["reason"]}]),
            "energy": pd.DataFrame([s["energy"]]),
            "solver": pd.DataFrame([s["solver"]]),
            "srs": self.spectrum()}

    def plot(self, kind: str = "xdd"):
        """A matplotlib Figure: "xdd" or "omd" (body-axis accelerations against time), "strokes", "energy",
        "footprints" or "srs_xdd3" (the shock spectrum of XDD(3))."""
        from alightsize.common import figures
        cfg, res = self.config, self.result

        def body(k: int, label: str, unit: str):
            return figures.body_figure(res.t, self.body()[k], label, unit, cfg.title)

        def energy():
            ke, pe = energies(cfg, res)
            return figures.energy_figure(res.t, ke, pe, res.y[:, 13])
        tracks = lambda: [res.footpad[res.contact[:, i] > 0, i, :2] for i in range(len(cfg.scene.legs))]  # noqa: E731
        draw = figures.pick({
            "xdd": lambda: body(0, "XDD", "g"), "omd": lambda: body(1, "OMD", "rad/s²"),
            "strokes": lambda: figures.strokes_figure(res.t, res.deflections, cfg.cell_names), "energy": energy,
            "footprints": lambda: figures.footprints_figure(cfg.scene.terrain, tracks(), res.y[:, :2]),
            "srs_xdd3": lambda: figures.srs_figure(self.spectrum(), cfg.srs_damping)}, kind)
        return draw()


def land(cfg: SceneConfig) -> LandingResult:
    """Simulate the scene's landing to its outcome."""
    return LandingResult(cfg, simulate(cfg.scene, cfg.controls))
