"""Tripod legs in the landing simulator: the compiled leg force against the leg's statics (tripod_leg's numpy
functions, themselves checked against an independent space truss in test_tripod_statics.py), a symmetric drop's
primary stroke against energy balance with N = 3, 4 and 6 legs, the energy audit, convergence of maxima over a
tolerance ladder against a fixed-step reference, and the compiled variant naming only the kinds a scene uses."""

from dataclasses import replace

import numpy as np
import pytest
from numba import typeof
from scipy.optimize import brentq

from alightsize.model.scene_config import read_scene
from alightsize.pipeline.lander import read_lander
from alightsize_sim import legs as legs_mod
from alightsize_sim import tripod_leg
from alightsize_sim.crush_cell import CellModel
from alightsize_sim.crush_curve import CrushCurve
from alightsize_sim.landing import Controls, Scene, simulate, variant
from alightsize_sim.legs import leg_force, pack, with_terrain
from alightsize_sim.rigid_body import quat_matrix
from alightsize_sim.telescoping_leg import TelescopingLeg
from alightsize_sim.terrain import Terrain
from alightsize_sim.terrain import pack as pack_terrain
from alightsize_sim.tripod_leg import (TripodLeg, cell_deflections, footpad_force, strut_lengths,
                                       tripod_from_params)
from conftest import ROOT

MASS, G_MOON = 1500.0, 1.62
K_SEC = 2.0e6                                        # N/m: the secondaries' elastic line


def _elastic(k):
    """A cell that stays elastic: a straight loading line unloaded at its own slope (crush_cell: the unloading
    spring from (dmax, fmax) at rate k follows the line back), past its last point the same slope."""
    return CellModel(CrushCurve((0.0, 0.5), (0.0, 0.5 * k)), k)


def _primary(force=1.6e4):
    return CellModel(CrushCurve((0.0, 0.01, 0.6, 0.61), (0.0, force, force, 5.0 * force)), force / 0.01)


def _gear(n, cantilever=0.0, primary=None):
    sec = _elastic(K_SEC)
    return tuple(tripod_from_params(2.4, 1.0, 0.4, secondary_spread=np.radians(35.0), primary=primary or _primary(),
                                    secondary_compression=sec, secondary_tension=sec, footpad_diameter=0.6,
                                    footpad_height=-1.2, secondary_radius=1.0, secondary_height=-0.4,
                                    secondary_attach=cantilever, azimuth=2.0 * np.pi * k / n) for k in range(n))


def _scene(gear, v0=(0.0, 0.0, -3.0)):
    return Scene(MASS, np.array([900.0, 900.0, 750.0]), gear, np.array([0.0, 0.0, -G_MOON]), np.array(v0),
                 np.array([1.0, 0.0, 0.0, 0.0]), np.zeros(3))


@pytest.mark.parametrize("cantilever", [0.0, 0.3])
def test_compiled_leg_force_matches_the_statics(cantilever):
    """legs.leg_force (compiled) against cell_deflections and footpad_force (numpy) at random footpad positions,
    capsule positions, attitudes and rates, to 1e-12: the deflections of the strut lengths L (a deflection is a
    difference of lengths, so its round-off scales with L, and a cell force's with k L), the force on the capsule
    of the cell forces relative to its size; the cells' power equals X . (footpad velocity relative to the body),
    virtual work (Hibbeler, Statics, sec. 11.2)."""
    rng = np.random.default_rng(43)
    cells_ = (_elastic(3e6), _elastic(K_SEC), _elastic(1.5e6), _elastic(2.5e6), _elastic(1e6))
    base = _gear(4, cantilever)[1]
    leg = TripodLeg(base.primary_hardpoint, base.secondary_hardpoints, base.footpad, base.secondary_attach,
                    cells_[0], (cells_[1], cells_[3]), (cells_[2], cells_[4]), 0.6)
    geo, cells = pack((leg,))
    geo = with_terrain(geo, pack_terrain(Terrain()))
    mem = np.zeros((5, 2))
    for _ in range(50):
        q = rng.normal(size=4)
        q /= np.linalg.norm(q)
        R, r = quat_matrix(q), rng.normal(size=3)
        b = leg.footpad + rng.uniform(0.0, 0.05) * rng.normal(size=3)        # footpad, principal axes
        P = r + R @ b
        v, w = rng.normal(size=3), rng.normal(size=3)
        defl, frc, rte, X = np.zeros(5), np.zeros(5), np.zeros(5), np.zeros(3)
        power, *lengths = leg_force(geo, cells, 0, mem, np.zeros(3), P, (r, R, v, w), (defl, frc, rte, X))
        L = strut_lengths(leg, b)
        np.testing.assert_allclose(lengths, L, rtol=1e-12)
        np.testing.assert_allclose(defl, cell_deflections(leg, L), rtol=1e-12, atol=1e-12 * L.max())
        expected_f = [c.k * max(d, 0.0) for c, d in zip(leg.cells, cell_deflections(leg, L))]
        np.testing.assert_allclose(frc, expected_f, rtol=0, atol=1e-12 * 3e6 * L.max())
        T = tripod_leg.strut_axial_forces(frc)
        F = footpad_force(leg, T, b)
        np.testing.assert_allclose(X, F, rtol=1e-12, atol=1e-12 * np.abs(F).max())
        rel = -np.cross(w, b) - R.T @ v                                      # d(b)/dt with the footpad held
        assert power == pytest.approx(X @ rel, rel=1e-10, abs=1e-10 * np.abs(frc).max() * np.abs(rel).max())


def _drop_stroke(gear, v0):
    """Energy balance of a symmetric vertical drop (held footpads, one degree of freedom: the CG's descent z):
    0.5 m v0^2 + m g z = N (W_primary(dp(z)) + 2 * 0.5 K_SEC ds(z)^2) at the largest stroke, where the capsule
    stops; dp, ds from the strut lengths with the body moved down by z (principal axes = body axes here)."""
    leg = gear[0]
    d, f = leg.primary.curve.deflection, leg.primary.curve.force

    def work(x):                                     # area under the piecewise-linear loading curve
        xs = np.r_[np.array(d)[np.array(d) < x], x]
        return float(np.trapezoid(np.interp(xs, d, f), xs))

    def strokes(z):
        L = strut_lengths(leg, leg.footpad + np.array([0.0, 0.0, z]))     # footpad rises z relative to the body
        return leg.rest_lengths - L

    def balance(z):
        dp, ds1, ds2 = strokes(z)
        return 0.5 * MASS * v0 ** 2 + MASS * G_MOON * z - len(gear) * (work(dp) + 0.5 * K_SEC * (ds1 ** 2 + ds2 ** 2))

    z = brentq(balance, 1e-6, 0.5, xtol=1e-15, rtol=1e-15)
    return strokes(z)


@pytest.mark.parametrize("n", [3, 4, 6])
def test_symmetric_drop_strokes_each_primary_as_energy_balance_predicts(n):
    """A vertical 3 m/s drop on N legs with elastic secondaries (their force stays on the elastic line well below
    the primary's crushing load): each primary's largest stroke equals the energy balance's to 1e-6 of the stroke,
    the same in every leg; the run's energy audit closes below 1e-6."""
    gear = _gear(n)
    expected = _drop_stroke(gear, 3.0)
    res = simulate(_scene(gear), Controls(t_final=0.6, rtol=1e-10, atol=1e-12, energy_check_from=None))
    assert res.status in ("end", "stable")
    strokes = res.memory[:, 0, 0]
    assert expected[0] > 0.02                        # the primary crushes on its plateau (past 0.01 m)
    np.testing.assert_allclose(strokes, expected[0], rtol=1e-6)
    assert res.energy["closure_rel"] < 1e-6
    # the secondaries' largest strokes (tension or compression) as the balance's, in every leg
    sec = np.maximum(res.memory[:, 1, 0], res.memory[:, 2, 0])
    np.testing.assert_allclose(sec, abs(expected[1]), rtol=1e-5)
    assert np.all(np.isfinite(res.struts[res.contact > 0]))


def _oblique(**ctl):
    """A four-legged landing at 3 m/s down and 1 m/s across, leg 1 leading, the capsule rolled 5 deg: every leg
    touches at its own time and every cell works."""
    gear = _gear(4)
    q = np.array([np.cos(np.radians(2.5)), np.sin(np.radians(2.5)), 0.0, 0.0])
    scene = Scene(MASS, np.array([900.0, 900.0, 750.0]), gear, np.array([0.0, 0.0, -G_MOON]),
                  np.array([1.0, 0.0, -3.0]), q, np.zeros(3))
    return simulate(scene, Controls(t_final=0.8, energy_check_from=None, **ctl))


def _maxima(res):
    """Peak acceleration (at accepted steps), the largest primary stroke and the largest secondary stroke (both
    located as events: a cell's turn)."""
    return np.array([np.abs(res.accel_g).max(), res.memory[:, 0, 0].max(), res.memory[:, 1:, 0].max()])


def test_maxima_converge_with_tolerance_and_agree_with_fixed_steps():
    """Peak acceleration, largest primary and secondary strokes of an oblique landing over rtol 1e-7, 1e-8, 1e-9:
    each within 1e-4 of a fixed-step run (5 us steps, 35,000 of them, events located as in every run), the
    finest rung nearer than the coarsest to a run at rtol 1e-11 (they converge); the audit closes below 1e-6 on
    every run. The peak acceleration is sampled at accepted steps: the 5 us grid's sample stands 3.1e-6 from the
    adaptive runs' limit (2.5 us steps: the same to 3e-10), more than the rungs' own errors (1.8e-6 to 6e-8), so
    convergence is judged against the tighter adaptive run."""
    reference = _oblique(fixed_step=5e-6)
    assert reference.energy["closure_rel"] < 1e-6
    ref = _maxima(reference)
    limit = _maxima(_oblique(rtol=1e-11, atol=1e-14))
    errors = []
    for rtol in (1e-7, 1e-8, 1e-9):
        res = _oblique(rtol=rtol, atol=1e-3 * rtol)
        assert res.energy["closure_rel"] < 1e-6
        np.testing.assert_allclose(_maxima(res), ref, rtol=1e-4)
        errors.append(np.abs(_maxima(res) / limit - 1.0))
    assert np.all(errors[-1] <= errors[0])


def test_the_compiled_variant_names_only_the_kinds_a_scene_uses():
    """The compile notice's variant and the compiled leg dispatch of a tripod scene hold the tripod alone; a
    telescoping scene's geo has no tripod array, so its dispatch is the telescoping leg's alone as before."""
    gear = _gear(4)
    assert variant(_scene(gear)) == "tripod legs, footpads that hold"
    geo, _ = pack(gear)
    geo = with_terrain(geo, pack_terrain(Terrain()))
    assert geo[4] is None and geo[8] is None and geo[10].shape == (4, 5, 3)
    assert legs_mod._pick(typeof(geo), None, "leg_force") is tripod_leg.leg_force.py_func


def test_a_sliding_landing_on_footpads_with_mass_closes_its_energy_audit():
    """The example lander down a 12 deg slope at mu 0.4, 1 m/s across: its 2.1 kg footpads slide (friction's work
    is part of the audit), and the audit closes below 1e-6 at rtol 1e-8."""
    cfg = read_scene(ROOT / "examples" / "lunar_tripod.toml",
                     {"terrain.slope": "12 deg", "terrain.mu_static": 0.4, "terrain.mu_dynamic": 0.4,
                      "initial.velocity": ["1 m/s", "0 m/s", "-3 m/s"]})
    res = simulate(cfg.scene, replace(cfg.controls, rtol=1e-8, atol=1e-11, t_final=1.0, energy_check_from=None))
    assert res.energy["friction_J"] > 100.0                   # the footpads slid
    assert res.energy["closure_rel"] < 1e-6


@pytest.mark.parametrize("run_id", ["corner-15", "mc-19", "mc-42", "mc-53", "mc-67"])
def test_the_example_designs_landings_close_their_audit_at_default_controls(run_id):
    """Landings of `alightsize design examples/lunar_tripod.toml` (its envelope's corners and Monte Carlo draws)
    at the default controls, the five whose audit closed worst (1.05e-6 to 2.16e-6 with events located to 1e-6 s):
    the audit closes below 1e-6 (energy conservation; events located to 1e-7 s, the default)."""
    study = read_lander(ROOT / "examples" / "lunar_tripod.toml").spec.landings.study
    run = next(r for r in study.runs if r.run_id == run_id)
    cfg = read_scene(run.scene, run.overrides)
    res = simulate(cfg.scene, cfg.controls)
    assert res.status != "failed" and res.energy["closure_rel"] < 1e-6


def test_a_scene_mixing_tripod_and_telescoping_legs_lands_and_closes_its_audit():
    """Two tripods and two telescoping legs (the per-leg dispatch, each kind's functions compiled): the landing
    ends, the audit closes below 1e-6, strut forces are recorded for the tripods only."""
    gear = _gear(4)
    axial = _primary()
    tel = [TelescopingLeg(np.array([2.4 * np.cos(a), 2.4 * np.sin(a), 0.4]), np.eye(3), 1.6, 0.0, (), axial, ())
           for a in (0.5 * np.pi, 1.5 * np.pi)]
    scene = Scene(MASS, np.array([900.0, 900.0, 750.0]), (gear[0], tel[0], gear[2], tel[1]),
                  np.array([0.0, 0.0, -G_MOON]), np.array([0.5, 0.0, -3.0]), np.array([1.0, 0.0, 0.0, 0.0]),
                  np.zeros(3))
    assert variant(scene) == "telescoping and tripod legs, footpads that hold"
    res = simulate(scene, Controls(t_final=0.6, energy_check_from=None))
    assert res.status == "end" and res.energy["closure_rel"] < 1e-6
    assert np.all(res.memory[:, 0, 0] > 0.01)                  # every leg's main cell crushed
    assert np.isnan(res.struts[:, [1, 3]]).all() and np.isfinite(res.struts[res.contact[:, 0] > 0, 0]).all()


def test_a_leg_whose_struts_meet_in_their_hardpoints_plane_counts_as_folded_flat():
    """With the footpad in the plane of the three hardpoints the unit strut vectors are coplanar (u . (e1 x e2)
    = 0): legs.folded names the leg; at rest (|u . (e1 x e2)| >= MIN_DET by validation) it names none."""
    leg = _gear(4)[0]
    geo, _ = pack((leg,))
    geo = with_terrain(geo, pack_terrain(Terrain()))
    h = leg.hardpoints
    flat = h.mean(axis=0) + 0.5 * (h[0] - h[1])                 # in the hardpoints' plane
    contact = np.ones(1, np.int64)
    assert legs_mod.folded(geo, contact, flat[None, :], np.zeros(3), np.eye(3)) == 0
    assert legs_mod.folded(geo, contact, leg.footpad[None, :], np.zeros(3), np.eye(3)) == -1
