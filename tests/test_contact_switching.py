"""Touchdown and lift-off on hard cases of the lunar example (examples/lunar_lander.toml): two legs touching
at one instant, and a lift-off located at a jump of its event function (a slide leaving the leg's reach)."""

from pathlib import Path

import numpy as np

import alightsize_sim.landing as landing
import alightsize_sim.landing_kernel as lk
from alightsize.model.scene_config import read_scene
from alightsize_sim.rigid_body import quat_matrix

LUNAR = Path(__file__).resolve().parents[1] / "examples" / "lunar_lander.toml"
# Two legs across a 12 deg slope touch at the same instant; each touchdown, located to event_tol, leaves its
# footpad a hair above the terrain and out of its leg's reach, so it leaves at once.
SYMMETRIC = {"terrain.slope": "-12 deg", "terrain.mu_static": 1.0, "terrain.mu_dynamic": 0.4,
             "initial.velocity[2]": "-1 m/s", "initial.velocity[1]": "0 m/s", "initial.roll": "0 deg"}
# Monte Carlo landing mc-68 of the example, rounded: a pad slides out of its leg's reach within a step while
# the axial cell still holds 4 mm of elastic compression.
JUMP = {"terrain.mu_static": 1.0, "terrain.mu_dynamic": 0.698, "terrain.slope": "-11.67 deg",
        "initial.velocity[2]": "-2.79 m/s", "initial.velocity[1]": "0.398 m/s", "initial.heading": "141.2 deg",
        "initial.roll": "87.9 deg",
        "legs.cell_factors": [[1.0, 1.02, 1.0, 0.99, 1.1], [0.94, 1.0, 0.97, 1.05, 0.94], [0.94, 0.97, 1.02, 1.0, 0.93],
                              [1.03, 0.99, 0.98, 1.05, 0.97]]}


def test_legs_touching_at_one_instant_do_not_trade_places():
    """Before the fix each re-armed the other and the run died on the stall guard at 0.297 s. Now it settles
    (energy criterion) with energy closure at round-off (1e-6 is the suite's closure bound for settled runs)."""
    cfg = read_scene(LUNAR, SYMMETRIC)
    res = landing.simulate(cfg.scene, cfg.controls)
    assert res.status == "stable"
    assert res.energy["closure_rel"] < 1e-6


def test_a_free_footpad_never_starts_below_the_terrain():
    """Geometric invariant, checked every 10 ms: a leg in the air has its free footpad above the terrain or
    at most the grazing band (BAND, 1e-4 m) into it, at which it touches down. Before the fix the leg that
    left at the jump hung 4 mm into the terrain, never touched down again and went 2.3 m under it while the
    lander rolled over it onto its body (body_contact at 6.8 s); now it settles at 2.2 s."""
    cfg = read_scene(LUNAR, JUMP)
    run = landing._Run(cfg.scene, cfg.controls)
    y = landing.initial_state(cfg.scene, run)
    t, status = 0.0, lk.END
    for stop in np.arange(0.01, cfg.controls.t_final + 1e-9, 0.01):
        run.ctl_arr[lk.C_TFINAL] = stop
        status, t = run.loop(y, t)
        heights = run.heights(y[0:3], quat_matrix(y[6:10]))
        assert np.all(heights[run.contact == 0] >= -lk.BAND - 1e-9), (t, heights, run.contact)
        if status != lk.END:
            break
    assert status == lk.STABLE
