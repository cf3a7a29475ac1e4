"""Interface loads (alightsize.loads.interface) on real landing histories of the shipped examples: the hardpoint
forces of each massless leg balance the force the leg carries at every step on the ground, and the telescoping
split agrees with the App. III free-body forces computed along the same history."""

import json

import numpy as np
import pytest

from alightsize.loads.config import read_loads
from alightsize.loads.histories import telescoping_member_histories
from alightsize.loads.interface import (articulated_hardpoints, articulated_landing_loads, body_footpads,
                                        telescoping_hardpoints, telescoping_landing_loads)
from alightsize.loads.telescoping import TelescopingLeg as FreeBody
from alightsize.model.scene_config import read_scene
from alightsize_sim.landing import simulate

from conftest import ROOT

AFFDL = ROOT / "examples" / "affdl-tr-66-33"
# the lunar example landing across a 12 deg slope at 1 m/s: every leg takes side load (its worst envelope corner)
LUNAR = read_scene(ROOT / "examples" / "lunar_lander.toml",
                   {"initial.velocity[1]": "1 m/s", "initial.velocity[2]": "-3 m/s", "terrain.slope": "12 deg"})
CONFIG5 = read_scene(AFFDL / "scenes" / "articulated_config5.toml")


@pytest.fixture(scope="module")
def lunar():
    return simulate(LUNAR.scene, LUNAR.controls)


@pytest.fixture(scope="module")
def config5():
    return simulate(CONFIG5.scene, CONFIG5.controls)


def _scale(res) -> float:
    return float(np.nanmax(np.abs(res.leg_force[res.contact.astype(bool)])))


def test_telescoping_hardpoints_balance_the_leg_force(lunar):
    # Massless leg: pivot + pads = the force the leg carries (the history's leg_force), and their moments about the
    # CG equal the footpad's (pivot at the attachment, pads a down the leg): 1e-9 of the largest force (N, N m
    # per m of lever); round-off is ~1e-12.
    res = lunar
    h = telescoping_hardpoints(LUNAR, res)
    tol = 1e-9 * _scale(res)
    assert res.contact.any(axis=0).all()
    for i, leg in enumerate(LUNAR.scene.legs):
        k = np.flatnonzero(res.contact[:, i])
        pivot, pads = h.forces[k, i, 0], h.forces[k, i, 1]
        np.testing.assert_allclose(pivot + pads, res.leg_force[k, i], rtol=0, atol=tol)
        foot = body_footpads(res, i, k)
        u = (foot - leg.attach) / np.linalg.norm(foot - leg.attach, axis=1)[:, None]
        moment = np.cross(leg.attach, pivot) + np.cross(leg.attach + leg.pad_lever * u, pads)
        np.testing.assert_allclose(moment, np.cross(foot, res.leg_force[k, i]), rtol=0, atol=tol * 5)
        np.testing.assert_allclose(np.einsum("ki,ki->k", pads, u), 0.0, rtol=0, atol=tol)    # pads: across u only
        off = np.flatnonzero(res.contact[:, i] == 0)
        assert np.isnan(h.forces[off, i]).all()


def test_telescoping_hardpoints_carry_the_free_body_forces(lunar):
    # App. III: the pads' resultant is P1 al / a = P1 + P2 and the pivot's part across the leg is P2 (P2 < 0 once
    # the leg has stroked above its pads, al < a), with P1 and P2 from `telescoping_member_histories` (the free
    # body along the history, computed apart): 1e-9 relative.
    res = lunar
    h = telescoping_hardpoints(LUNAR, res)
    free = telescoping_member_histories(LUNAR, res, FreeBody(8000.0, 4000.0, 0.8, 1.6, 0.1, 0.05))
    for i, leg in enumerate(LUNAR.scene.legs):
        k = np.flatnonzero(res.contact[:, i])
        foot = body_footpads(res, i, k)
        u = (foot - leg.attach) / np.linalg.norm(foot - leg.attach, axis=1)[:, None]
        pivot, pads = h.forces[k, i, 0], h.forces[k, i, 1]
        across = pivot - np.einsum("ki,ki->k", pivot, u)[:, None] * u
        tol = 1e-9 * _scale(res)
        np.testing.assert_allclose(np.linalg.norm(pads, axis=1), free["P1"][k, i] + free["P2"][k, i], rtol=1e-9,
                                   atol=tol)
        np.testing.assert_allclose(np.linalg.norm(across, axis=1), np.abs(free["P2"][k, i]), rtol=1e-9, atol=tol)


def test_articulated_hardpoints_balance_the_ground_force(config5):
    # Configuration 5 (App. III geometry) landing: upper + lower attachment forces (eq. 53-61 reactions and the
    # upper cell) equal the history's leg force at every step on the ground, 1e-9 of the largest force: the
    # member loads already balance the simulated ground force to round-off (alightsize.loads.histories).
    res = config5
    h = articulated_hardpoints(CONFIG5, res)
    on = res.contact.astype(bool)               # stored as integers
    assert on.any()
    np.testing.assert_allclose(h.forces[on].sum(axis=1), res.leg_force[on], rtol=0, atol=1e-9 * _scale(res))
    assert np.isnan(h.forces[~on]).all()


def test_landing_loads_store_the_largest_hardpoint_force(lunar, config5):
    # What a landing stores (JSON, as the sweep writes it): per leg and hardpoint the largest |force| of the
    # history and its components at that step along the geometric body axes (the principal-axes force turned
    # by the scene's matrix; 1e-12 relative: one rotation's round-off); the member extremes beside them.
    truss = next(c for c in read_loads(AFFDL / "loads" / "articulated.toml").cases if c.name == "5").truss
    for cfg, res, stored, hist in (
            (LUNAR, lunar, telescoping_landing_loads(LUNAR, lunar, FreeBody(8000.0, 4000.0, 0.8, 1.6, 0.1, 0.05)),
             telescoping_hardpoints(LUNAR, lunar)),
            (CONFIG5, config5, articulated_landing_loads(CONFIG5, config5, truss),
             articulated_hardpoints(CONFIG5, config5))):
        stored = json.loads(json.dumps(stored))
        assert stored["member_loads"]
        rows = stored["interface_loads"]
        assert len(rows) == res.contact.any(axis=0).sum() * len(hist.names)
        for r in rows:
            f = hist.forces[:, r["leg"] - 1, hist.names.index(r["hardpoint"])]
            mag = np.linalg.norm(f, axis=1)
            k = int(np.nanargmax(mag))
            assert r["force_N"] == pytest.approx(mag[k], rel=1e-12) and r["t_s"] == res.t[k]
            np.testing.assert_allclose(r["components_N"], cfg.to_geometric @ f[k], rtol=0, atol=1e-12 * mag[k])
