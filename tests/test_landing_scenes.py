"""Shipped scenes, footpad slip and a randomized robustness sweep of the landing simulator."""

import dataclasses
import os
import json

import numpy as np
import pandas as pd
import pytest

from alightsize.cli import main
from alightsize.scene_config import read_scene
from sim.landing import simulate
from sim.rigid_body import quat_matrix

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
    ratio = np.hypot(fe[..., 0], fe[..., 1])[on] / np.maximum(fe[..., 2][on], 1e-9)
    # eq. 33-34: in-plane / normal never exceeds mu_S = 1.5 (sticking) and the slide is solved to mu_D = 1.0;
    # the bracketing solver closes |h| to 1e-12 of the forces, so 1e-9 is a safe margin.
    assert np.max(ratio) <= 1.5 * (1 + 1e-9)
    moved = np.linalg.norm(np.diff(res.footpad, axis=0), axis=2)[on[1:] & on[:-1]]
    assert moved.max() > 1e-3                                     # the footpads did slide on the 20 deg slope
    assert res.energy["friction_J"] > 0                           # and friction took energy


def test_randomized_scenes_never_fail():
    """Seeded random landings (N_RANDOM; issue 4 asks 1,000) (slope, velocities, inclination, roll rate, friction, cell scatter): no
    numerical failure, finite energy audit (issue 4: the slip solver converges on every scene)."""
    base = read_scene(f"{SCENES}/telescoping_config1.toml")
    rng = np.random.default_rng(20261121)
    outcomes = {}
    for k in range(N_RANDOM):
        slope = np.radians(rng.uniform(-35, 35))
        c, s = np.cos(slope), np.sin(slope)
        lepk = np.array([[1, 0, 0], [0, c, s], [0, -s, c]])
        v = np.array([rng.uniform(-2, 2), rng.uniform(0, 15), -rng.uniform(5, 35)]) * 0.3048
        tilt = np.radians(rng.uniform(0, 12))
        az = rng.uniform(0, 2 * np.pi)
        axis = np.array([np.cos(az), np.sin(az), 0.0])
        from sim.rigid_body import axis_rotation, matrix_quat
        q0 = matrix_quat(lepk @ axis_rotation(axis, tilt) @ quat_matrix(base.scene.q0))
        mu_d = rng.uniform(0.3, 1.2)
        scene = dataclasses.replace(base.scene, gravity=lepk @ np.array([0, 0, -9.80665]), v0=lepk @ v, q0=q0,
                                    omega0=np.array([0, 0, rng.choice([0.0, 3.0])]), mu_dynamic=mu_d,
                                    mu_static=1.5 * mu_d)
        res = simulate(scene, dataclasses.replace(base.controls, t_final=0.25))
        outcomes[res.status] = outcomes.get(res.status, 0) + 1
        assert res.status != "failed", k
        assert np.isfinite(res.y).all() and np.isfinite(res.energy["closure_rel"]), k
        assert res.energy["closure_rel"] < 1e-3, (k, res.energy)
    assert sum(outcomes.values()) == N_RANDOM


def test_simulate_cli_writes_the_contract_outputs(tmp_path):
    out = tmp_path / "run"
    assert main(["simulate", f"{SCENES}/telescoping_config2.toml", "--out", str(out)]) == 0
    s = json.loads((out / "summary.json").read_text())
    assert s["schema"] == "alightsize.simulate/1" and s["outcome"] in ("stable", "bottomed", "tipped", "walking",
                                                                         "body_contact", "time_out")
    assert [c["cell"] for c in s["legs"][0]["cells"]] == ["axial", "rot1", "rot2", "rot3", "rot4"]
    # 4 legs x 3750 lbf on the axial plateau over a 300 lbf capsule: 50 g plus the damper share (Sec. IV.A).
    assert 50.0 <= s["peak"]["xdd_g"][2] < 50.5
    h = pd.read_parquet(out / "history.parquet")
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
