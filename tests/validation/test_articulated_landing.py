"""Articulated-leg landings (AFFDL-TR-66-33 Sec. V.F, Tables 3-4): the leg's root tracking and equilibrium,
energy closure on every configuration, the Table 3-4 matrices against the printed outcome classes, and the
hard cases of issue 5 (seated peg leg, 3 rad/s roll, walking down a 35 deg slope)."""

from __future__ import annotations

from multiprocessing import Pool

import numpy as np
import pytest

from alightsize.landings.output import outcome
from alightsize.model.scene_config import read_scene
from alightsize.landings.study import agrees, outcome_class, read_study
from alightsize_sim import articulated_leg
from alightsize_sim.articulated_cells import upper_length
from alightsize_sim.articulated_kinematics import footpad, nearest_root, roots
from alightsize_sim.landing import simulate
from alightsize_sim.legs import pack
from conftest import ROOT

EX = ROOT / "examples" / "affdl-tr-66-33"
SCENES = sorted((EX / "scenes").glob("articulated_*.toml"))


def _config5():
    return read_scene(EX / "scenes" / "articulated_config5.toml")


def test_nearest_root_follows_the_branch_of_the_previous_alpha():
    """The simulator's SINALP returns the root of eq. 41 nearest the last alpha among all the bracketed roots
    (`roots`, 2,000 samples): alpha to 1e-9 rad (the bracket closes to 1e-13; 1e-9 covers the residual's
    conditioning near a double root). The root crossing along a path is in test_articulated_kinematics."""
    g = _config5().scene.legs[0].geometry
    rng = np.random.default_rng(5)
    for _ in range(200):
        alpha, beta, psi = rng.uniform(0, 0.8), rng.uniform(-np.pi, np.pi), rng.uniform(-0.5, 0.5)
        s = footpad(g, alpha, beta, psi)
        prev = alpha + rng.normal(0, 0.05)
        found = nearest_root(g, *s, prev)
        every = roots(g, s, np.pi / 2, samples=2000)
        assert found >= 0 and every
        assert found == pytest.approx(min(every, key=lambda a: abs(a - prev)), abs=1e-9)


def _leg_at(alpha, beta, psi, rate=(0.0, 0.0, 0.0)):
    """Leg 0 of configuration 5 with its footpad at the tip of (alpha, beta, psi), capsule at rest at the
    origin (principal = terrain axes), moving at `rate`: (X, deflections, forces, power, shape)."""
    cfg = _config5()
    leg = cfg.scene.legs[0]
    geo, cells = pack(cfg.scene.legs)
    s = np.array(footpad(leg.geometry, alpha, beta, psi))
    P = leg.attach + leg.to_body @ s
    mem = np.zeros((2, 2))
    mem[:, 0], mem[:, 1] = 1.0, 1e9          # far past both cells' maxima: unloading springs, no plateau jumps
    defl, frc, rte, X = np.zeros(2), np.zeros(2), np.zeros(2), np.zeros(3)
    out = articulated_leg.leg_force(geo, cells, 0, mem, np.array([alpha, beta, psi]), P,
                                    (np.zeros(3), np.eye(3), np.array(rate, float), np.zeros(3)), (defl, frc, rte, X))
    return X, defl, frc, out[0], out[1:], leg


def test_ground_force_is_the_virtual_work_equilibrium_past_the_seat():
    """Past the seat the ground force satisfies F . d(tip)/dq = Q_q (eq. 59-61): for q = psi with Q_psi =
    AF1 dDelta_1/dpsi, for q = beta with 0, checked by central differences (step 1e-6 rad: error ~1e-10
    relative, tolerance 1e-6)."""
    alpha, beta, psi = 0.2, 0.7, -0.1
    X, defl, frc, _, shape, leg = _leg_at(alpha, beta, psi)
    assert shape == pytest.approx((alpha, beta, psi), abs=1e-10)
    F = leg.to_body.T @ X
    g, h = leg.geometry, 1e-6
    d_psi = (np.array(footpad(g, alpha, beta, psi + h)) - np.array(footpad(g, alpha, beta, psi - h))) / (2 * h)
    d_beta = (np.array(footpad(g, alpha, beta + h, psi)) - np.array(footpad(g, alpha, beta - h, psi))) / (2 * h)
    q_psi = frc[0] * (upper_length(g, psi + h) - upper_length(g, psi - h)) / (2 * h)
    assert abs(frc[0]) > 1e3
    assert F @ d_psi == pytest.approx(q_psi, rel=1e-6)
    assert F @ d_beta == pytest.approx(0.0, abs=1e-6 * np.linalg.norm(F) * np.linalg.norm(d_psi))


def test_seated_peg_leg_is_finite_and_continuous():
    """At alpha = 0 (beta undefined) the force is FORCE's seated one, vertical only, Q_psi / (AU cos psi),
    with no NaN; through the seat band it changes continuously: the jump between alpha and alpha + 1e-9 is
    below 1e-5 of the force (the blend's slope times 1e-9 rad is ~1e-6)."""
    X0, *_ = _leg_at(0.0, 0.3, -0.1)
    assert np.all(np.isfinite(X0))
    leg = _leg_at(0.0, 0.3, -0.1)[-1]
    F0 = leg.to_body.T @ X0
    assert np.hypot(F0[0], F0[1]) <= 1e-9 * abs(F0[2])
    for a in (0.0, 0.5 * articulated_leg.SEAT, articulated_leg.SEAT):
        Xa, Xb = _leg_at(a, 0.3, -0.1)[0], _leg_at(a + 1e-9, 0.3, -0.1)[0]
        assert np.linalg.norm(Xb - Xa) <= 1e-5 * np.linalg.norm(Xa)


@pytest.mark.parametrize("path", SCENES, ids=lambda p: p.stem)
def test_articulated_scenes_close_energy(path):
    """Every shipped articulated scene (configurations 3-9, special forces 1-6) at default settings: energy
    closure below 1e-4 of the impact energy (issue 5), no failure."""
    cfg = read_scene(path)
    res = simulate(cfg.scene, cfg.controls)
    assert res.status != "failed"
    assert res.energy["closure_rel"] < 1e-4


def test_flat_vertical_drop_is_symmetric():
    """Four identical legs, level, vertical, no rates: every leg strokes alike (1e-9 relative: the four legs
    see the same numbers up to rounding in the attitude) and the lateral acceleration stays below 1e-9 g."""
    cfg = read_scene(EX / "scenes" / "articulated_config5.toml",
                     {"initial.velocity": ["0 ft/s", "0 ft/s", "-35 ft/s"], "initial.roll": "45 deg"})
    res = simulate(cfg.scene, cfg.controls)
    dmax = np.nanmax(res.deflections, axis=0)
    assert np.all(np.ptp(dmax, axis=0) <= 1e-9 * dmax.max(axis=0))
    assert np.abs(res.accel_g[:, :2]).max() < 1e-9
    assert res.energy["closure_rel"] < 1e-4


def _run(run):
    cfg = read_scene(run.scene, run.overrides)
    res = simulate(cfg.scene, cfg.controls)
    return run.run_id, outcome_class(cfg, res), run.reference, res.energy["closure_rel"], run.params


def test_tables_3_and_4():
    """All 242 runs of Tables 3-4: no failed run, closure below 1e-4 on every run (issue 5), and the outcome
    classes read as the printed ones (time-out and walking share the printed "+") on at least 166 runs
    (measured 171 of 242: 104/130 and 67/112; the 4 "ND" runs cannot agree since no run here fails; the floor
    is 6 runs under the measurement, for floating-point differences between machines on runs near a class
    boundary). The matrices include the 3 rad/s roll runs (issue 5's hard case)."""
    runs = [r for t in ("table3", "table4") for r in read_study(EX / "studies" / f"{t}.toml").runs]
    with Pool(2) as pool:
        rows = pool.map(_run, runs, chunksize=4)
    assert len(rows) == 242
    assert not [r for r in rows if r[1] == "failed"]
    assert max(r[3] for r in rows) < 1e-4
    assert sum(float(r[4]["roll_rate_rad_s"]) == 3.0 for r in rows) >= 100
    assert sum(agrees(r[1], r[2]) for r in rows) >= 166


def test_walking_down_a_35_degree_slope_for_5_seconds():
    """Configuration 5 down a 35 deg slope with mu_D 0.5 < tan 35 deg: the capsule slides and walks downhill
    for the full 5 s with its footpads slipping, without failing and with closure below 1e-4. Friction takes
    the share of the released potential energy a sliding block gives up, mu_D cot(gamma) = 0.714, within
    15 % (measured 0.656: the legs hop, so the normal load is at times below m g cos(gamma), and the cells
    take 5 % of the energy)."""
    cfg = read_scene(EX / "scenes" / "articulated_config5.toml",
                     {"terrain.slope": "35 deg", "terrain.mu_static": 0.6, "terrain.mu_dynamic": 0.5,
                      "initial.velocity": ["0 ft/s", "5 ft/s", "-10 ft/s"], "initial.roll": "0 deg"})
    res = simulate(cfg.scene, cfg.controls)
    assert outcome(cfg, res)[0] == "walking"
    assert res.t[-1] == pytest.approx(5.0)
    share = res.energy["friction_J"] / res.energy["potential_change_J"]
    assert share == pytest.approx(0.5 / np.tan(np.radians(35.0)), rel=0.15)
    assert res.energy["closure_rel"] < 1e-4
