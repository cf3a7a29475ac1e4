"""Footpads with mass (alightsize_sim.footpad_mass): limits, conservation laws and input."""

import dataclasses

import numpy as np
import pytest

from alightsize.common.errors import InputError
from alightsize.common.resources import data_dir
from alightsize.landings.output import outcome
from alightsize.model.scene_config import read_scene
from alightsize_sim.landing import simulate

SCENES = data_dir("examples") / "affdl-tr-66-33" / "scenes"
TIGHT = dict(rtol=1e-10, atol=1e-14, max_step=5e-4, event_tol=1e-9)


def _undamped(scene, mu):
    """The scene with its cells' unloading dampers removed and static friction equal to dynamic: where the
    massless footpad's slide is self-consistent (it takes the cells' rates with the footpad held, and jumps
    to the dynamic limit when mu_S > mu_D)."""
    legs = tuple(dataclasses.replace(leg, axial=dataclasses.replace(leg.axial, c=0.0),
                                     pads=tuple(dataclasses.replace(p, c=0.0) for p in leg.pads))
                 for leg in scene.legs)
    return dataclasses.replace(scene, legs=legs, mu_static=mu, mu_dynamic=mu)


def _peak(res):
    return float(np.max(np.abs(res.accel_g[:, 2])))


@pytest.fixture(scope="module")
def run12101():
    cfg = read_scene(SCENES / "telescoping_config1_run12101.toml")
    return cfg, _undamped(cfg.scene, 0.5)


def test_footpads_converge_to_the_massless_model_as_their_mass_goes_to_zero(run12101):
    """Run 12101 (configuration 1 slipping into a 20 deg slope) over its impact (0.1 s), undamped, mu 0.5:
    the peak XDD(3) with footpads of 1, 0.1 and 0.01 kg approaches the massless model's converged value
    (fixed steps of 5e-6 s, within 3e-7 of 2.5e-6 s). Measured 4.6 %, 0.75 %, 0.043 %: each step down in mass
    closes the gap, and 0.01 kg is within 0.1 % (the footpad's inertia, m/M ~ 1e-5, is all that differs)."""
    cfg, scene = run12101
    ctl = dataclasses.replace(cfg.controls, t_final=0.1)
    ref = _peak(simulate(scene, dataclasses.replace(ctl, fixed_step=5e-6, event_tol=1e-9)))
    gaps = [abs(_peak(simulate(dataclasses.replace(scene, footpad_mass=m), dataclasses.replace(ctl, **TIGHT)))
                / ref - 1) for m in (1.0, 0.1, 0.01)]
    assert gaps[0] > gaps[1] > gaps[2]
    assert gaps[2] < 1e-3


def test_footpads_with_mass_close_the_energy_balance(run12101):
    """Without dampers every joule is accounted for exactly: kinetic and potential energy of the capsule =
    cells (absorbed + elastic) + friction work + footpads' kinetic energy + capsule kinetic energy at the end.
    At rtol 1e-10 the residual is 5e-11 .. 7e-10 of the energy in (measured); 1e-8 leaves room for round-off
    over 0.3 s of repeated touchdowns and slides."""
    cfg, scene = run12101
    res = simulate(dataclasses.replace(scene, footpad_mass=1.0), dataclasses.replace(cfg.controls, t_final=0.3,
                                                                                      **TIGHT))
    assert res.energy["friction_J"] > 1.0                    # the footpads slid (9.2 J measured)
    assert res.energy["closure_rel"] < 1e-8


def test_a_frictionless_slope_keeps_the_momentum_along_it():
    """Configuration 2 landing on a frictionless (mu = 0) 20 deg slope with 1 kg footpads: the ground can only
    push along its normal, so the in-plane momentum of capsule and footpads grows at M g_t exactly:
    M (v_t - v_t0 - g_t t) + sum m u = 0 until a footpad lifts off (taking its momentum away). The forces
    between capsule and footpads cancel in every Runge-Kutta stage, and Runge-Kutta methods keep linear
    invariants to round-off: 1e-12 of M max|v_t| (measured 1.5e-15)."""
    cfg = read_scene(SCENES / "telescoping_config2.toml",
                     {"terrain.slope": "20 deg", "terrain.mu_static": 0.0, "terrain.mu_dynamic": 0.0})
    m, M, g = 1.0, cfg.scene.mass, cfg.scene.gravity
    res = simulate(dataclasses.replace(cfg.scene, footpad_mass=m), dataclasses.replace(cfg.controls, t_final=0.5))
    assert res.status in ("bottomed", "body_contact", "tipped", "end", "stable", "quiet")
    momentum = (M * (res.y[:, 3:5] - cfg.scene.v0[:2] - np.outer(res.t, g[:2]))
                + m * res.footpad_velocity[:, :, :2].sum(axis=1))
    lift = np.flatnonzero(np.any(np.diff(res.contact, axis=0) < 0, axis=1))
    k = lift[0] + 1 if len(lift) else len(res.t)
    assert np.any(res.footpad_velocity[:k] != 0.0)           # the footpads did slide
    assert np.abs(momentum[:k]).max() <= 1e-12 * M * np.abs(res.y[:, 3:5]).max()


def test_scene_files_take_a_footpad_mass_and_any_friction_from_zero(tmp_path):
    """`[legs] footpad_mass` and `footpad_band` with units (default 0: massless, the report's model; 1 cm/s); a
    negative mass or a band not above zero is refused with its key path; mu = 0 is a legal (icy) surface."""
    cfg = read_scene(SCENES / "telescoping_config2.toml", {"legs.footpad_mass": "5 lb", "terrain.mu_static": 0.0,
                                                           "terrain.mu_dynamic": 0.0})
    assert cfg.scene.footpad_mass == pytest.approx(5 * 0.45359237, rel=1e-12)
    assert cfg.scene.mu_dynamic == 0.0
    assert read_scene(SCENES / "telescoping_config2.toml").scene.footpad_mass == 0.0
    with pytest.raises(InputError, match="legs.footpad_mass"):
        read_scene(SCENES / "telescoping_config2.toml", {"legs.footpad_mass": "-1 kg"})
    with pytest.raises(InputError, match="terrain.mu_dynamic"):
        read_scene(SCENES / "telescoping_config2.toml", {"terrain.mu_static": 0.0, "terrain.mu_dynamic": -0.1})
    # The Karnopp band: 1 cm/s unless given, with units; zero or negative is refused with its key path.
    assert cfg.scene.footpad_band == 0.01
    assert read_scene(SCENES / "telescoping_config2.toml", {"legs.footpad_band": "2 mm/s"}).scene.footpad_band == \
        pytest.approx(0.002, rel=1e-12)
    for bad in ("0 m/s", ["1 cm/s"]):               # an array where a quantity belongs: still an input error
        with pytest.raises(InputError, match="legs.footpad_band"):
            read_scene(SCENES / "telescoping_config2.toml", {"legs.footpad_band": bad})


def test_walking_down_a_35_degree_slope_with_5_lb_footpads_loses_what_a_sliding_block_loses():
    """Configuration 5 walking 5 s down 35 deg (mu_D 0.5 < tan 35 deg) with 5 lb footpads: friction takes
    mu_D cot(gamma) = 0.714 of the released potential energy, as for a block sliding down the slope (measured
    0.714 at rtol 1e-4 and 1e-6; the massless model gives 0.67-0.72 as its tolerance changes). 2 % allows for
    the cells' share and the hops. Closure below 1e-4."""
    cfg = read_scene(SCENES / "articulated_config5.toml",
                     {"terrain.slope": "35 deg", "terrain.mu_static": 0.6, "terrain.mu_dynamic": 0.5,
                      "initial.velocity": ["0 ft/s", "5 ft/s", "-10 ft/s"], "initial.roll": "0 deg",
                      "legs.footpad_mass": "5 lb"})
    res = simulate(cfg.scene, dataclasses.replace(cfg.controls, rtol=1e-4))
    assert outcome(cfg, res)[0] == "walking" and res.t[-1] == pytest.approx(5.0)
    share = res.energy["friction_J"] / res.energy["potential_change_J"]
    assert share == pytest.approx(0.5 / np.tan(np.radians(35.0)), rel=0.02)
    assert res.energy["closure_rel"] < 1e-4
