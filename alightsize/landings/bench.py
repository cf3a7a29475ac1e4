"""Speed against error of the landing simulator (`alightsize bench`): each scene with each method over a
ladder of tolerances or steps, errors against a tight-tolerance reference, and the same equations under
scipy.integrate (RK45, DOP853 stepped one accepted step at a time, memory committed between steps, events
located on their dense output) as the baseline a user would write (written by alightsize.reports.bench_report)."""

from __future__ import annotations

import dataclasses
import json
import os
import platform
import subprocess
import sys
import time

import numpy as np
from scipy import integrate, optimize

from alightsize_sim import landing_kernel as lk
from alightsize_sim.articulated_leg import ArticulatedLeg
from alightsize_sim.footpad_mass import ground_event
from alightsize_sim.landing import Controls, Result, _Run, accel_g, initial_state, simulate

from alightsize.common.errors import InputError
from alightsize.common.resources import data_dir
from alightsize.model.scene_config import SceneConfig, read_scene

EXAMPLES = data_dir("examples") / "affdl-tr-66-33" / "scenes"
TARGET_ERROR = 1e-3   # the accuracy every method is timed at: 0.1 % in peak XDD(3)


REFERENCE = dict(rtol=1e-11, atol=1e-14, max_step=5e-4, event_tol=1e-9)
# Slipping articulated footpads slide from where they were at the last accepted step, so the path depends on
# the step size to first order (docs/simulator.md): there the rtol 1e-11 run is 6e-4 off the finest fixed-step
# runs in peak XDD(3), and fixed steps of 2.5e-6 s differ from 5e-6 s by 1.4e-4.
FINE_STEP = dict(fixed_step=2.5e-6, event_tol=1e-9)
LONG_STEP = 1e-2      # s: the ladder's largest step besides the scene's own (2 ms by default)


def _scenes(quick: bool) -> list[tuple[SceneConfig, float | None, dict]]:
    """(scene, simulated time, reference controls): the flat drop, configuration 2 flat and configuration 1
    slipping into a 20 deg slope (run 12101), run for fixed times with the early stops off so every method
    covers the same span (the impact, the hardest part); configuration 2 as a whole landing and the articulated
    configuration 5 slipping down a 35 deg slope (the hardest speed case), each to its outcome (None: the
    scene's own stops; the scipy baselines cover the reference's span). The articulated landing tips at about
    0.25 s; with the tip stop off it would go on with a leg lying flat, where one slide runs to the edge of the
    leg's reach in a step and its force spikes (docs/simulator.md); the same landing with 5 lb footpads whose
    slide is integrated (footpad_mass). Quick: the flat drop, configuration 2 and the two articulated cases."""
    cfg2 = read_scene(EXAMPLES / "telescoping_config2.toml")
    flat = (read_scene(EXAMPLES / "flat_drop.toml"), 0.12, REFERENCE)
    config2 = (cfg2, 0.3, REFERENCE)
    cfg5 = read_scene(EXAMPLES / "articulated_config5_slope35.toml")
    articulated = (dataclasses.replace(cfg5, name=f"{cfg5.name} (whole landing)"), None, FINE_STEP)
    footpads = (read_scene(EXAMPLES / "articulated_config5_slope35_footpads.toml"), None, REFERENCE)
    if quick:
        return [flat, config2, articulated, footpads]
    return [flat, config2, (read_scene(EXAMPLES / "telescoping_config1_run12101.toml"), 0.3, REFERENCE), articulated,
            footpads, (dataclasses.replace(cfg2, name="telescoping_config2 (whole landing)"), None, REFERENCE)]


def _controls(cfg: SceneConfig, t_sim: float | None, **kw) -> Controls:
    if t_sim is None:
        return dataclasses.replace(cfg.controls, **kw)
    return dataclasses.replace(cfg.controls, t_final=t_sim, energy_check_from=None, taus=0.0, tip_angle=np.pi,
                               stop_on_bottoming=False, **kw)


def _metrics(res: Result) -> dict:
    return {"peak": float(np.max(np.abs(res.accel_g[:, 2]))), "stroke": float(np.max(res.memory[:, :, 0])),
            "final": res.y[-1, :13].copy(), "t_end": float(res.t[-1])}


def _errors(m: dict, ref: dict) -> dict:
    scale = np.maximum(np.abs(ref["final"]), 1.0)
    return {"err_peak_xdd3_rel": abs(m["peak"] - ref["peak"]) / ref["peak"],
            "err_max_stroke_rel": abs(m["stroke"] - ref["stroke"]) / max(ref["stroke"], 1e-12),
            "err_final_state_rel": float(np.max(np.abs(m["final"] - ref["final"]) / scale))}


def _coarser(ref_kw: dict) -> dict:
    """The reference's own check: twice its fixed step, or ten times its tolerances. Their difference in peak
    XDD(3) bounds how far the reference itself may be from the converged landing (a smaller error is not
    resolved)."""
    if ref_kw.get("fixed_step"):
        return {**ref_kw, "fixed_step": 2.0 * ref_kw["fixed_step"]}
    return {**ref_kw, "rtol": 10.0 * ref_kw["rtol"], "atol": 10.0 * ref_kw["atol"]}


def _timed(fn, repeats: int) -> tuple[dict, object]:
    """One untimed warm-up call (first-call dispatch, caches), then `repeats` timed calls: their median, least
    and largest wall time in s, and the last call's result."""
    out = fn()
    walls = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = fn()
        walls.append(time.perf_counter() - t0)
    return {"wall_s": float(np.median(walls)), "wall_min_s": min(walls), "wall_max_s": max(walls),
            "repeats": repeats}, out


def scipy_landing(cfg: SceneConfig, ctl: Controls, method: str) -> tuple[dict, int, int]:
    """The same equations (the compiled right-hand side, cell memory, slip and switching functions of the
    simulator) stepped by scipy's OdeSolver: memory committed after each accepted step, touchdown and
    lift-off and stick-to-slip located with brentq on the solver's dense output, the solver restarted after a
    switch."""
    s = cfg.scene
    run = _Run(s, ctl)
    y = initial_state(s, run)
    for i in np.flatnonzero(run.armed == lk.TOUCH):
        lk.switch(run.arrays, y, int(i), run.work)
    n = run.n
    n_g = lk.n_events(n, run.C)
    work, g_prev, g = run.work, np.empty(n_g), np.empty(n_g)
    nfev = steps = 0
    peak, t = 0.0, 0.0

    def f(_t, yy):
        dy = np.zeros(run.ny)
        lk.rhs(run.arrays, yy, dy, work)
        return dy

    def events(yy, out):
        f(0.0, yy)
        return _events(yy, out)

    def _events(yy, out):
        """Event values at yy from the leg state the last evaluation of f left in `work`."""
        lk.events(run.arrays, yy, work, out, 0.0)
        return out

    def accept(tt, yy, which):
        """Commit memory at an accepted state (event `which` if >= 0: a contact switch below n, a slide from
        n on, which the commit starts, a footpad's soil mode from 2n on, a cell's turn or loading-curve corner from
        3n on); the peak acceleration there."""
        dy = f(tt, yy)
        started = lk.commit(run.arrays, yy, work, g)
        if which >= 3 * n:
            lk.cell_event(run.cells, run.cev, which, n)
        elif which >= 2 * n:
            ground_event(run.mu, yy, which - 2 * n, run.sliding, run.geo[9])
        elif 0 <= which < n:
            lk.switch(run.arrays, yy, which, work)
        if which >= 0 or started:
            dy = f(tt, yy)
        _events(yy, g_prev)
        return abs(float(accel_g(yy, dy, s.gravity)[0, 2]))

    Solver = {"RK45": integrate.RK45, "DOP853": integrate.DOP853}[method]
    events(y, g_prev)
    while t < ctl.t_final - 1e-12:
        solver = Solver(f, t, y, ctl.t_final, rtol=ctl.rtol, atol=ctl.atol, max_step=ctl.max_step)
        while solver.status == "running":
            solver.step()
            steps += 1
            y1 = solver.y.copy()
            crossed = (g_prev > 0) & (events(y1, g) <= 0)
            which = int(np.argmax(crossed)) if crossed.any() else -1
            t1 = solver.t
            if which >= 0:
                dense = solver.dense_output()
                t1 = solver.t_old                     # re-evaluated there, the function may already be past zero
                if events(dense(t1), g.copy())[which] > 0:
                    t1 = optimize.brentq(lambda tt: events(dense(tt), g.copy())[which], solver.t_old, solver.t,
                                         xtol=ctl.event_tol)
                if events(dense(t1), g.copy())[which] > 0:   # take the side past the crossing
                    t1 = min(t1 + ctl.event_tol, solver.t)
                y1 = dense(t1)
            y1[6:10] /= np.linalg.norm(y1[6:10])
            peak = max(peak, accept(t1, y1, which))
            t, y = t1, y1
            if which >= 0:
                break                                  # restart the solver after the switch
        nfev += solver.nfev
        if solver.status == "failed":
            break
    return {"peak": peak, "stroke": float(np.max(run.mem[:, :, 0])), "final": y[:13].copy(), "t_end": t}, nfev, steps


def python_baseline(scene_path: str, t_sim: float, method: str, rtol: float, repeats: int) -> dict:
    """scipy_landing timed in this process; run under NUMBA_DISABLE_JIT=1 it is the plain-numpy baseline (the
    equations as interpreted Python/numpy, no compilation)."""
    cfg = read_scene(scene_path)
    ctl = _controls(cfg, t_sim, rtol=rtol, atol=rtol * 1e-3)
    wall, (m, nfev, steps) = _timed(lambda: scipy_landing(cfg, ctl, method), repeats)
    return {**wall, "nfev": nfev, "steps": steps, "peak": m["peak"], "stroke": m["stroke"],
            "final": m["final"].tolist(), "t_end": m["t_end"]}


def _uncompiled(cfg: SceneConfig, t_sim: float, method: str, rtol: float, repeats: int) -> dict:
    """python_baseline in a subprocess with numba's JIT disabled."""
    code = ("import json, sys; from alightsize.landings.bench import python_baseline; "
            f"print(json.dumps(python_baseline({str(cfg.path)!r}, {t_sim!r}, {method!r}, {rtol!r}, {repeats!r})))")
    out = subprocess.run([sys.executable, "-c", code], env={**os.environ, "NUMBA_DISABLE_JIT": "1"},
                         capture_output=True, text=True, check=True)
    r = json.loads(out.stdout.strip().splitlines()[-1])
    r["final"] = np.array(r["final"])
    return r


def _targets(cases: list[dict]) -> list[dict]:
    """Per scene: the fastest case of each kind at or below TARGET_ERROR in peak XDD(3), in ms per simulated
    second (median of the repeats), and the speed-ups of the compiled simulator over the baselines."""
    out = []
    for scene in sorted({c["scene"] for c in cases}):
        best = {}
        for c in cases:
            if c["scene"] == scene and c["err_peak_xdd3_rel"] <= TARGET_ERROR:
                kind = "ours" if c["compiled"] else c["method"]
                ms = 1e3 * c["wall_s"] / c["t_sim_s"]
                if kind not in best or ms < best[kind]["ms_per_simulated_s"]:
                    best[kind] = {"method": c["method"], "setting": c["setting"], "ms_per_simulated_s": ms,
                                  "err_peak_xdd3_rel": c["err_peak_xdd3_rel"]}
        row = {"scene": scene, "best": best}
        if "ours" in best:
            row["speedup"] = {k: v["ms_per_simulated_s"] / best["ours"]["ms_per_simulated_s"]
                              for k, v in best.items() if k != "ours"}
        out.append(row)
    return out


def _said(case: dict) -> str:
    """A case's median wall time with its spread over the repeats, and its error."""
    return (f"{case['wall_s'] * 1e3:.1f} ms ({case['wall_min_s'] * 1e3:.1f}-{case['wall_max_s'] * 1e3:.1f} over "
            f"{case['repeats']}), peak XDD(3) error {case['err_peak_xdd3_rel']:.1e}")


def _chosen(scenes: list, only: tuple[str, ...]) -> list:
    """The scenes named in `only` (a scene's name without its parenthesis), all when it is empty; an unknown
    name is an InputError listing the known ones."""
    names = [cfg.name.split(" (")[0] for cfg, _, _ in scenes]
    unknown = [n for n in only if n not in names]
    if unknown:
        raise InputError("(command line)", "--scene", f"one of {', '.join(dict.fromkeys(names))}", unknown[0])
    return [s for s, name in zip(scenes, names) if not only or name in only]


def run_bench(quick: bool = False, progress=print, only: tuple[str, ...] = ()) -> dict:
    ladder = [1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7] if not quick else [1e-3, 1e-5, 1e-7]
    fixed = [4e-4, 2e-4, 1e-4, 5e-5] if not quick else [1e-4]
    scipy_ladder = [1e-3, 1e-5, 1e-7] if not quick else [1e-4]
    repeats = 5 if not quick else 3                                 # every case, compiled or not, alike
    t0 = time.perf_counter()
    scenes = _chosen(_scenes(quick), only)
    cfg0 = scenes[0][0]
    simulate(cfg0.scene, _controls(cfg0, 0.01))                      # load the compiled code
    compile_s = time.perf_counter() - t0
    cases, references, uncertainty, goal = [], {}, {}, {}
    for cfg, t_sim, ref_kw in scenes:
        ref = _metrics(simulate(cfg.scene, _controls(cfg, t_sim, **ref_kw)))
        references[cfg.name] = ref_kw
        # the speed targets in ms per simulated second: 10 for a telescoping landing, 50 for an articulated one
        goal[cfg.name] = 50.0 if any(isinstance(leg, ArticulatedLeg) for leg in cfg.scene.legs) else 10.0
        check = _metrics(simulate(cfg.scene, _controls(cfg, t_sim, **_coarser(ref_kw))))
        uncertainty[cfg.name] = _errors(check, ref)
        span = t_sim or ref["t_end"]
        progress(f"{cfg.name}: reference done ({span:.3f} s; peak XDD(3) within "
                 f"{uncertainty[cfg.name]['err_peak_xdd3_rel']:.1e} of its check)")
        runs = [("dopri5", f"rtol={r:g}", dict(rtol=r, atol=r * 1e-3)) for r in ladder]
        # the largest step, not the tolerance, sets a telescoping impact's step count (docs/notes/simulator-log.md)
        runs += [("dopri5", f"rtol={r:g}, max_step={LONG_STEP:g}", dict(rtol=r, atol=r * 1e-3, max_step=LONG_STEP))
                 for r in ladder[:2]]
        runs += [("dopri5-fixed", f"h={h:g}", dict(fixed_step=h)) for h in fixed]
        for method, setting, kw in runs:
            ctl = _controls(cfg, t_sim, **kw)
            wall, res = _timed(lambda: simulate(cfg.scene, ctl), repeats)
            cases.append({"scene": cfg.name, "method": method, "setting": setting, "t_sim_s": float(res.t[-1]),
                          **wall, "rhs_evals": res.rhs_evals, "steps": res.steps, **_errors(_metrics(res), ref),
                          "compiled": True})
            progress(f"  {method} {setting}: {_said(cases[-1])}")
        for method in ("RK45", "DOP853"):
            for r in scipy_ladder:
                ctl = _controls(cfg, span, rtol=r, atol=r * 1e-3)
                wall, (m, nfev, steps) = _timed(lambda: scipy_landing(cfg, ctl, method), repeats)
                cases.append({"scene": cfg.name, "method": f"scipy-{method}", "setting": f"rtol={r:g}", "t_sim_s": span,
                              **wall, "rhs_evals": nfev, "steps": steps, **_errors(m, ref), "compiled": False})
                progress(f"  scipy-{method} rtol={r:g}: {_said(cases[-1])}")
        for r in ([1e-3, 1e-5] if not quick else []):
            b = _uncompiled(cfg, span, "RK45", r, repeats)
            cases.append({"scene": cfg.name, "method": "scipy-RK45-uncompiled", "setting": f"rtol={r:g}",
                          "t_sim_s": span, **{k: b[k] for k in ("wall_s", "wall_min_s", "wall_max_s", "repeats")},
                          "rhs_evals": b["nfev"], "steps": b["steps"], **_errors(b, ref), "compiled": False})
            progress(f"  scipy-RK45 plain numpy rtol={r:g}: {_said(cases[-1])}")
    import numba
    return {"schema": "alightsize.bench/1",
            "machine": {"cores": os.cpu_count(), "python": platform.python_version(), "numpy": np.__version__,
                        "numba": numba.__version__, "processor": platform.processor() or platform.machine()},
            "compile_or_cache_load_s": compile_s, "references": references,
            "reference_uncertainty": uncertainty, "target_error": TARGET_ERROR,
            "target_ms_per_simulated_s": goal, "cases": cases,
            "targets": _targets(cases)}
