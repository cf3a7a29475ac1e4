"""Shipped scenes, footpad slip and a randomized robustness sweep of the landing simulator."""

import dataclasses
import os
import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from alightsize.cli import main
from alightsize.landings.output import history_frame
from alightsize.landings.random_landings import random_landing
from alightsize.model.scene_config import read_scene
from alightsize_sim.landing import G0, simulate
from alightsize_sim.rigid_body import quat_matrix

SCENES = "examples/affdl-tr-66-33/scenes"
N_RANDOM = int(os.environ.get("ALIGHTSIZE_RANDOM_SCENES", "3"))   # issue 4 asks 1,000: see docs/simulator.md


@pytest.mark.parametrize("name", ["flat_drop", "telescoping_config0", "telescoping_config1", "telescoping_config2",
                                  "telescoping_config1_run12101"])
def test_energy_closes_on_every_example_scene(name):
    cfg = read_scene(f"{SCENES}/{name}.toml")
    res = simulate(cfg.scene, cfg.controls)
    # Issue 4: closure below 1e-4 of the impact energy at default settings.
    assert res.status != "failed" and res.energy["closure_rel"] < 1e-4


def test_slipping_footpads_sit_on_the_friction_cone():
    cfg = read_scene(f"{SCENES}/telescoping_config1_run12101.toml")
    res = simulate(cfg.scene, cfg.controls)
    R = np.array([quat_matrix(q) for q in res.y[:, 6:10]])
    fe = np.einsum("nij,nlj->nli", R, res.leg_force)            # ground force on each leg, terrain axes
    on = res.contact > 0
    stays = np.zeros_like(on)
    stays[:-1] = on[:-1] & on[1:]              # not a lift-off point (the leg leaves with its forces there)
    fe12, fe3 = np.hypot(fe[..., 0], fe[..., 1])[stays], fe[..., 2][stays]
    # eq. 33-34: in-plane force never exceeds mu_S = 1.5 times the normal force (sticking; the slide is solved
    # to mu_D = 1.0). The bracketing solver closes the excess to 1e-3 rtol = 1e-9 of the forces, far inside
    # mu_S; near a located lift-off the forces are within the event tolerance of zero, about
    # k v event_tol = 1e6 N/m x 10 m/s x 1e-10 s = 1e-3 N, hence the absolute 1e-2 N.
    assert np.all(fe12 <= 1.5 * fe3 * (1 + 1e-9) + 1e-2)
    moved = np.linalg.norm(np.diff(res.footpad, axis=0), axis=2)[on[1:] & on[:-1]]
    assert moved.max() > 1e-3                                     # the footpads did slide on the 20 deg slope
    assert res.energy["friction_J"] > 0                           # and friction took energy


@pytest.mark.parametrize("name", ["telescoping_config1_run12101", "articulated_config5_slope35",
                                  "articulated_config5"])
def test_the_footpad_terrain_interface_never_gives_energy(name):
    """The massless legs pass on the work they take from the capsule: what the cells do not take goes into the
    footpad-terrain interface (slip, pads unloading at lift-off), which can only take energy. Closure cannot
    see a slide that loads the cells without leg work, since it counts friction as that remainder; here each
    step's interface work, leg work (the integrated state) less the cells' work (trapezoidal in the recorded
    forces and deflections), must not be negative beyond the trapezoid's error: 1e-4 of the impact energy,
    8x the worst measured (1.3e-5, run 12101; a slide projected against the push gave -1.3e-2)."""
    cfg = read_scene(f"{SCENES}/{name}.toml")
    res = simulate(cfg.scene, cfg.controls)
    F, D = np.nan_to_num(res.forces), res.deflections
    cells = (0.5 * (F[1:] + F[:-1]) * np.nan_to_num(np.diff(D, axis=0))).sum(axis=(1, 2))
    interface = np.diff(res.y[:, 13]) - cells
    impact = res.energy["initial_J"] + max(res.energy["potential_change_J"], 0.0)
    assert interface.min() >= -1e-4 * impact
    # The same remainder as the energy balance's friction: within 1 % of the impact energy (measured 0.45 %: the
    # steps where a leg touches down or lifts off have no recorded deflection at one end and are left out here).
    assert interface.sum() == pytest.approx(res.energy["friction_J"], abs=0.01 * impact)


@pytest.mark.parametrize("k", [170, 199, 489])
def test_no_cell_gives_back_more_than_it_stored(k):
    """A passive cell gives back at most the energy it stored: its work less the elastic energy it still holds is
    not negative beyond the integration error of that work (1e-4 of the impact energy, the sweep's criterion;
    energy closure cannot see it with massless legs). Landings 170, 199 and 489 of the seeded configuration-1
    sweep (massless sliding footpads): grazing touchdowns whose slide jumped centimetres to the edge of the leg's
    reach left their cells stroked uncommitted and gave back 52, 75 and 83 J; then the damper's force (from the
    leg's rate with the footpad held) times a slide's falling deflection counted up to -0.25 J (measured now
    0 to -1e-3 J)."""
    cfg = read_scene(f"{SCENES}/telescoping_config1.toml")
    scene = dataclasses.replace(random_landing(cfg.scene, 20261121, k), footpad_mass=0.0, footpad_diameter=0.5)
    res = simulate(scene, dataclasses.replace(cfg.controls, t_final=1.0))
    impact = res.energy["initial_J"] + max(res.energy["potential_change_J"], 0.0)
    assert res.status != "failed"
    assert res.energy["cell_absorbed_min_J"] >= -1e-4 * impact
    assert res.energy["friction_J"] >= -1e-4 * impact           # the interface only takes energy


def test_adaptive_steps_follow_a_sliding_footpad_near_lift_off():
    """Run 12101: leg 1 slides within ~0.1 mm of lift-off at 0.03 s, and if it lifts early the legs touch in
    another order and peak XDD(3) is 5 % lower. The footpad path error control (the straight slide's sagitta in
    the error norm) keeps rtol 1e-4 on the branch of fine fixed steps: peak XDD(3) within 0.1 % (issue 4's
    accuracy criterion) of fixed steps of 5e-5 s, which agree with 1e-4 s to 1e-5; without the control every
    rtol down to 1e-5 lost 5 %."""
    cfg = read_scene(f"{SCENES}/telescoping_config1_run12101.toml")
    span = dict(t_final=0.3, energy_check_from=None, taus=0.0, tip_angle=np.pi, stop_on_bottoming=False)
    fine = simulate(cfg.scene, dataclasses.replace(cfg.controls, fixed_step=5e-5, **span))
    adaptive = simulate(cfg.scene, dataclasses.replace(cfg.controls, rtol=1e-4, atol=1e-7, **span))
    peak = [np.max(np.abs(r.accel_g[:, 2])) for r in (fine, adaptive)]
    assert peak[1] == pytest.approx(peak[0], rel=1e-3)


def test_footpad_path_error_falls_as_the_step_squared():
    """The path error of a straight slide (sagitta: half the slide times the turn of the push along it) is
    second order: with the slide and the turn both proportional to h, halving the step quarters it. Run
    12101's sliding leg 1 at 0.033 s, one Dormand-Prince step of 1e-4 and of 5e-5 s: ratio 4 within 0.7
    (measured 3.8; the turn is not yet exactly linear in h at 1e-4 s: 2.9 from 2e-4 s)."""
    from alightsize_sim import landing_kernel as lk
    from alightsize_sim.landing import _Run, initial_state
    cfg = read_scene(f"{SCENES}/telescoping_config1_run12101.toml")
    s = cfg.scene
    run = _Run(s, dataclasses.replace(cfg.controls, t_final=0.033, energy_check_from=None, taus=0.0))
    y = initial_state(s, run)
    run.loop(y, 0.0)
    assert run.sliding[0] == 1
    path = []
    for h in (1e-4, 5e-5):
        K, y1, err = np.zeros((7, 14)), np.empty(14), np.empty(14)
        lk.rhs(run.arrays, y, K[0], run.work)
        lk.stage(run.arrays, y, h, K, y1, err, run.work, False)
        path.append(run.work[5][0, 5])
    assert path[1] > 0 and path[0] / path[1] == pytest.approx(4.0, abs=0.7)


def test_randomized_scenes_never_fail():
    """Seeded random landings (N_RANDOM here; benchmarks/random_scenes.py runs the 1,000 issue 4 asks) over
    slope, velocities, inclination, roll rate and friction: no numerical failure, energy closes."""
    base = read_scene(f"{SCENES}/telescoping_config1.toml")
    for k in range(N_RANDOM):
        res = simulate(random_landing(base.scene, 20261121, k), dataclasses.replace(base.controls, t_final=0.25))
        assert res.status != "failed", k
        assert np.isfinite(res.y).all() and np.isfinite(res.energy["closure_rel"]), k
        # Issue 4 asks 1e-4 of the impact energy at default settings; these scenes hold it too.
        assert res.energy["closure_rel"] < 1e-4, (k, res.energy)


def test_simulate_cli_writes_the_contract_outputs(tmp_path):
    out = tmp_path / "run"
    assert main(["simulate", f"{SCENES}/telescoping_config2.toml", "--out", str(out)]) == 0
    s = json.loads((out / "summary.json").read_text())
    assert s["schema"] == "alightsize.simulate/1" and s["outcome"] in ("stable", "bottomed", "tipped", "walking",
                                                                         "body_contact", "time_out")
    assert [c["cell"] for c in s["legs"][0]["cells"]] == ["axial", "rot1", "rot2", "rot3", "rot4"]
    h = pd.read_parquet(out / "history.parquet")
    # Sec. IV.A: the axial cell crushes at 3750 lbf (unbottomed: the plateau is the largest loading force),
    # and four legs on that plateau give 4 x 3750 / 300 = 50 g along the roll axis (the pads only add).
    plateau = 3750 * 4.4482216152605
    assert h["leg1_axial_force_N"].max() == pytest.approx(plateau, rel=1e-12)
    assert s["peak"]["xdd_g"][2] >= 50.0 * (1 - 1e-9)
    assert {"t_s", "xdd3_g", "omd1_rad_s2", "roll_deg", "leg1_axial_deflection_m", "leg4_force3_N"} <= set(h.columns)
    for png in ("xdd.png", "omd.png", "strokes.png", "energy.png", "srs_xdd3.png"):
        assert (out / png).stat().st_size > 1000


@pytest.mark.parametrize("edit, key", [
    ('slope = "-20 deg"', "terrain.slope"), ('mu_dynamic = 2.0', "terrain.mu_dynamic"),
    ('axial = "axal"', "legs.axial"), ('taus = -1', "controls.taus"), ('height = "1 lbf"', "legs.height")])
def test_bad_scene_input_exits_2_naming_the_key(tmp_path, capsys, edit, key):
    text = open(f"{SCENES}/telescoping_config1_run12101.toml").read()
    name = edit.split(" = ")[0]
    lines = [edit if ln.strip().startswith(name + " ") or ln.strip().startswith(name + "=") else ln
             for ln in text.splitlines()]
    if edit.startswith("slope"):
        lines = [ln.replace('"-20 deg"', '"95 deg"') for ln in lines]
    bad = tmp_path / "bad.toml"
    bad.write_text("\n".join(lines) + "\n")
    assert main(["simulate", str(bad), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert str(bad) in err and key in err and "Traceback" not in err
    assert not (tmp_path / "o").exists()


def test_cells_take_all_the_leg_work_when_nothing_slips():
    """No slip: the work the legs take from the capsule (integrated with the state) equals the cells' work
    (exact antiderivatives of the curves, accumulated step by step), so the interface term is ~0."""
    cfg = read_scene(f"{SCENES}/flat_drop.toml")
    res = simulate(cfg.scene, cfg.controls)
    assert abs(res.energy["friction_J"]) < 1e-8 * res.energy["initial_J"]


def test_slope_follows_eq_1_and_4():
    """Eq. 1 (LEPK) and eq. 4-5: gravity in terrain axes is (0, g sin gamma, -g cos gamma), so for a negative
    slope and +V2 (the report's "into the slope") the terrain rises ahead of the capsule: a point 1 m ahead
    horizontally (+kappa-2) lies sin(gamma) below the terrain plane through the start. Exact to round-off."""
    cfg = read_scene(f"{SCENES}/telescoping_config1_run12101.toml")       # gamma = -20 deg, V2 = +10 ft/s
    gamma = np.radians(-20.0)
    assert cfg.scene.gravity == pytest.approx(G0 * np.array([0.0, np.sin(gamma), -np.cos(gamma)]), abs=1e-12)
    assert (cfg.terrain_from_vertical @ [0.0, 1.0, 0.0])[2] == pytest.approx(np.sin(gamma), abs=1e-15)


def test_unloading_footpads_do_not_stall_at_a_tight_event_tolerance():
    """Four footpads unloading to zero at once (flat drop, mu_S > mu_D) once re-crossed the static-slip margin
    0 - 0 at every lift-off, in 1e-16 s steps, with event_tol 1e-9 s. The run must reach its end (the stall
    guard would end it as failed) and close energy (conservation, 1e-4 of the impact energy as issue 4)."""
    cfg = read_scene(f"{SCENES}/flat_drop.toml")
    ctl = dataclasses.replace(cfg.controls, t_final=0.12, rtol=1e-11, atol=1e-14, max_step=5e-4, event_tol=1e-9,
                              energy_check_from=None, taus=0.0)
    res = simulate(cfg.scene, ctl)
    assert res.status == "end" and res.t[-1] == pytest.approx(0.12, abs=1e-12)
    assert res.energy["closure_rel"] < 1e-4


def test_history_reports_the_input_attitude(tmp_path):
    """Roll, yaw and pitch in the history at t = 0 are the scene's inputs (eq. 2 read back through the slope
    of eq. 1 and the principal axes)."""
    text = open(f"{SCENES}/telescoping_config1_run12101.toml").read()
    text = text.replace('inclination = "0 deg"', 'yaw = "7 deg"\npitch = "-3 deg"')
    path = tmp_path / "s.toml"
    path.write_text(text)
    cfg = read_scene(path)
    res = simulate(cfg.scene, dataclasses.replace(cfg.controls, t_final=0.001))
    h = history_frame(cfg, res)
    assert h.loc[0, ["roll_deg", "yaw_deg", "pitch_deg"]].to_numpy(float) == pytest.approx([67.5, 7.0, -3.0], abs=1e-9)


def test_pads_without_a_cell_name_is_an_input_error(tmp_path, capsys):
    text = open(f"{SCENES}/flat_drop.toml").read().replace('pads = "pad"\n', "")
    bad = tmp_path / "bad.toml"
    bad.write_text(text)
    assert main(["simulate", str(bad), "--out", str(tmp_path / "o")]) == 2
    assert "legs.pads" in capsys.readouterr().err


def test_table2_study_runs_every_run_and_reports_agreement(tmp_path):
    """The Table 2 example study (56 runs, configurations 0-2) through the sweep runner: no failed run,
    energy closes on each, and the outcome classes agree with the printed symbols on at least 40 runs.
    docs/simulator.md lists the 45 of 56 (80 %) measured with the scene values chosen there; the floor of
    40 lets harmless numerical changes move a marginal run or two, while losing the calibration (16 of 56
    with the attachment 0.5 ft below the CG) or the slope sign of eq. 1 (at most 32 of 56 with it
    reversed) fails."""
    from alightsize.landings.study import read_study
    from alightsize.landings.sweep import run_sweep
    from alightsize.reports.sweep_report import write_results
    study = read_study("examples/affdl-tr-66-33/studies/table2.toml")
    assert len(study.runs) == 56 and len({r.run_id for r in study.runs}) == 56
    stats = run_sweep(study, tmp_path, "pool", workers=2, quiet=True)
    assert stats.computed == 56 and stats.failed == 0
    doc = json.loads(write_results(study, tmp_path)[0].read_text())
    runs = doc["run_list"]
    assert not doc["failed"]
    assert max(r["closure_rel"] for r in runs) < 1e-4
    assert doc["agreement"]["compared"] == 56 and doc["agreement"]["agree"] == sum(r["agrees"] for r in runs)
    assert doc["agreement"]["agree"] >= 40
    assert {c["row"][0] for c in doc["matrix"]["cells"]} == {"0", "-10", "-20", "-35"}


def test_study_input_errors_name_file_and_key(tmp_path):
    """A study whose run table names a configuration with no scene is an InputError (exit 2 material)."""
    from alightsize.common.errors import InputError
    from alightsize.landings.study import read_study
    (tmp_path / "runs.csv").write_text("run,configuration\nA,7\n")
    (tmp_path / "s.toml").write_text(f'[study]\nname = "s"\n[scenes]\n0 = "{Path(SCENES).resolve()}/flat_drop.toml"\n'
                                     '[runs]\ntable = "runs.csv"\nscene = "configuration"\n')
    with pytest.raises(InputError) as e:
        read_study(tmp_path / "s.toml")
    assert "runs.csv" in str(e.value) and "configuration" in str(e.value) and "'7'" in str(e.value)


def test_study_bad_value_fails_only_its_run(tmp_path):
    """A run-table value that makes a bad scene value fails that run, stored with a message naming the scene
    key; the study goes on."""
    from alightsize.landings.study import read_study
    from alightsize.landings.sweep import run_sweep
    (tmp_path / "runs.csv").write_text("run,configuration,slope\nR1,0,steep\nR2,0,5\n")
    (tmp_path / "s.toml").write_text(f'[study]\nname = "s"\n[scenes]\n0 = "{Path(SCENES).resolve()}/flat_drop.toml"\n'
                                     '[runs]\ntable = "runs.csv"\nscene = "configuration"\n'
                                     '[runs.set]\n"terrain.slope" = "{slope} deg"\n')
    stats = run_sweep(read_study(tmp_path / "s.toml"), tmp_path / "o", "serial", quiet=True)
    assert (stats.computed, stats.failed) == (2, 1)
    import sqlite3
    rows = dict(sqlite3.connect(tmp_path / "o" / "runs.sqlite").execute("SELECT run_id, message FROM runs"))
    assert "terrain.slope" in rows["R1"] and rows["R2"] == ""


@pytest.mark.parametrize("name", ["telescoping_config2", "articulated_config5"])
def test_cell_rates_are_the_time_derivatives_of_the_deflections(name):
    """The deflection rates a leg writes (the turning-point events follow their sign, the dampers use them) equal
    the central difference of its deflections as the capsule translates and rotates over a held footpad
    (d R / dt = R [w]x): step 1e-6 s, truncation ~1e-12 relative, tolerance 1e-6 of the largest rate."""
    from scipy.linalg import expm
    from alightsize_sim.legs import initial_shape, leg_force, pack
    cfg = read_scene(f"{SCENES}/{name}.toml")
    legs = cfg.scene.legs
    geo, cells = pack(legs)
    C = cells[2].shape[1]
    mem, shape = np.zeros((C, 2)), initial_shape(legs)[0]
    R0 = quat_matrix(np.array([0.99, 0.05, -0.08, 0.03]) / np.linalg.norm([0.99, 0.05, -0.08, 0.03]))
    v, w = np.array([0.4, -0.3, -2.0]), np.array([0.5, -0.7, 0.2])
    hanging = np.array(free_footpad_of(geo, cells, mem, shape, R0))
    attach = R0 @ geo[0][0]
    P = attach + 0.95 * (hanging - attach) + np.array([0.02, -0.01, 0.0])   # pressed toward the attachment
    wx = np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])

    def deflections(t):
        defl, frc, rte, X = np.zeros(C), np.zeros(C), np.zeros(C), np.zeros(3)
        out = leg_force(geo, cells, 0, mem, shape, P, (v * t, R0 @ expm(wx * t), v, w), (defl, frc, rte, X))
        return defl, rte, out

    d0, rate, out = deflections(0.0)
    assert d0[0] > 0.0 and np.isfinite(out[0])                   # the leg is on the ground and loaded
    h = 1e-6
    numeric = (deflections(h)[0] - deflections(-h)[0]) / (2 * h)
    m = len(legs[0].cells)
    assert np.max(np.abs(rate[:m])) > 0.1
    assert np.max(np.abs(rate[:m] - numeric[:m])) < 1e-6 * np.max(np.abs(rate[:m]))


def free_footpad_of(geo, cells, mem, shape, R):
    """Leg 0's unloaded footpad under a capsule at the origin with attitude R (terrain axes)."""
    from alightsize_sim.legs import free_footpad
    return free_footpad(geo, cells, 0, mem, shape, np.zeros(3), R)


@pytest.mark.parametrize("name", ["telescoping_config2", "articulated_config5"])
def test_a_scene_that_cannot_slip_holds_its_footpads_without_a_slip_search(name, monkeypatch):
    """The report's non-slip friction (1.5e6) runs the held-footpad model (no slip search compiled or run):
    every footpad stays where it touched while on the ground. Until the step before the first lift-off the slip
    model at that friction never slides a loaded footpad, so the two landings are the same to round-off (1e-9) and
    so is the peak XDD(3), which falls in the first impact (1e-6). They part where a leg unloads through
    lift-off: the slip model lets its footpad slide once the normal force is gone, the held one keeps it."""
    from alightsize_sim import landing
    cfg = read_scene(f"{SCENES}/{name}.toml")
    assert landing.holds(cfg.scene)
    held = simulate(cfg.scene, cfg.controls)
    on = held.contact[1:] & held.contact[:-1]
    assert np.array_equal(held.footpad[1:][on], held.footpad[:-1][on])
    monkeypatch.setattr(landing, "HELD_FRICTION", np.inf)
    slip = simulate(cfg.scene, cfg.controls)
    assert np.max(np.abs(held.accel_g[:, 2])) == pytest.approx(np.max(np.abs(slip.accel_g[:, 2])), rel=1e-6)
    lift = int(np.argmax(np.any(held.contact[:-1] & ~held.contact[1:].astype(bool), axis=1)))
    assert lift > 10
    assert np.array_equal(held.t[:lift - 1], slip.t[:lift - 1])      # the last step to lift-off differs
    assert np.allclose(held.y[:lift - 1], slip.y[:lift - 1], rtol=1e-9, atol=1e-12)
    assert held.energy["closure_rel"] < 1e-6


@pytest.mark.parametrize("name, kind", [("telescoping_config2", "telescoping_leg"),
                                        ("articulated_config5", "articulated_leg")])
def test_compiled_code_for_one_leg_kind_takes_that_kind_alone(name, kind):
    """A set of legs of one kind packs the other kind's arrays as None, and the compiled dispatch (numba
    overload on geo's type) resolves to that kind's functions: the other kind is never compiled. A held
    scene (mu None) resolves to the held contact, a slipping one to the slip search, footpads with mass to
    their own model."""
    import numba
    from alightsize_sim import articulated_leg, footpad_mass, footpad_slip, legs, telescoping_leg
    from alightsize_sim.footpad_mass import pad_model
    geo, _ = legs.pack(read_scene(f"{SCENES}/{name}.toml").scene.legs)
    assert (geo[4] is None) == (kind == "articulated_leg") and (geo[8] is None) == (kind == "telescoping_leg")
    module = {"telescoping_leg": telescoping_leg, "articulated_leg": articulated_leg}[kind]
    t = numba.typeof(geo)
    assert legs._leg_force(t, *[None] * 7) is module.leg_force.py_func
    assert legs._free_footpad(t, *[None] * 6) is module.free_footpad.py_func
    assert legs._lift_shape(t, *[None] * 7) is module.lift_shape.py_func
    none, arr, pad = numba.types.none, numba.typeof(np.zeros(3)), numba.typeof(pad_model(0.5, 0.5, 1.0, 1e-3))
    args = [None] * 3
    assert footpad_slip._contact_force(*args, none, *[None] * 3) is footpad_slip._held
    assert footpad_slip._contact_force(*args, arr, *[None] * 3) is footpad_slip._slipping
    assert footpad_slip._contact_force(*args, pad, *[None] * 3) is footpad_mass.pad_force.py_func


@pytest.mark.parametrize("gravity", ['"0 m/s^2"', '"0 g_0"', '"200 m/s^2"'])
def test_a_gravity_outside_its_range_exits_2_naming_the_key(tmp_path, capsys, gravity):
    """Zero gravity leaves no down for the tip-over and rest criteria: refused by the documented range
    (1e-6 to 100 m/s^2), not a ZeroDivisionError in every landing."""
    text = open(f"{SCENES}/telescoping_config1_run12101.toml").read()
    bad = tmp_path / "bad.toml"
    bad.write_text(text.replace("[scene]\n", f"[scene]\ngravity = {gravity}\n", 1))
    assert main(["simulate", str(bad), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert "gravity" in err and "1e-06 to 100" in err and "Traceback" not in err


@pytest.mark.parametrize("mass", ['"1e-30 kg"', '"1 g"', '"-1 kg"'])
def test_a_footpad_lighter_than_its_range_exits_2(tmp_path, capsys, mass):
    """0 or at least 0.01 kg: a lighter footpad asked for gigabytes of history before (its ringing)."""
    text = open(f"{SCENES}/articulated_config5_slope35_footpads.toml").read()
    bad = tmp_path / "bad.toml"
    bad.write_text(text.replace('footpad_mass = "5 lb"', f"footpad_mass = {mass}").replace(
        'base = "articulated_config5_slope35.toml"',
        f'base = "{Path(SCENES).resolve()}/articulated_config5_slope35.toml"'))
    assert main(["simulate", str(bad), "--out", str(tmp_path / "o")]) == 2
    assert "legs.footpad_mass" in capsys.readouterr().err
