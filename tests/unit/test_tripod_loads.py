"""Tripod strut loads along a landing history (alightsize.loads.histories.tripod_member_histories) and the tripod's
interface loads, on synthetic histories: a body moved and turned at random, footpads placed through the leg's
forward kinematics and footpad forces drawn at random, so every step's answer follows from statics alone."""

from types import SimpleNamespace

import numpy as np
import pytest

from alightsize.loads.histories import TRIPOD_FORCES, tripod_member_histories
from alightsize.loads.interface import interface_extremes, tripod_hardpoints
from alightsize_sim.crush_cell import CellModel
from alightsize_sim.crush_curve import CrushCurve
from alightsize_sim.rigid_body import quat_matrix
from alightsize_sim.tripod_leg import footpad_force, footpad_position, tripod_from_params

CELL = CellModel(CrushCurve((0.0, 0.01, 0.3, 0.31), (0.0, 1e4, 1e4, 5e4)), 1e6)
N_STEPS, N_LEGS = 40, 4


def _legs(attach: float) -> list:
    return [tripod_from_params(2.0, 0.8, 0.5, secondary_spread=np.radians(40), primary=CELL,
                               secondary_compression=CELL, secondary_tension=CELL, footpad_diameter=0.5,
                               footpad_height=-1.0, secondary_attach=attach, secondary_height=0.2,
                               azimuth=np.radians(90 * i + 10)) for i in range(N_LEGS)]


def _history(legs: list, seed: int):
    """A Result-like history (y, footpad in terrain axes, leg_force in principal axes, contact) with each leg's
    footpad at strut lengths up to 10 cm short of rest, and the footpad positions in body axes it was built from."""
    rng = np.random.default_rng(seed)
    q = rng.normal(size=(N_STEPS, 4))
    q /= np.linalg.norm(q, axis=1)[:, None]
    y = np.zeros((N_STEPS, 14))
    y[:, 0:3], y[:, 6:10] = rng.normal(size=(N_STEPS, 3)), q
    contact = rng.random((N_STEPS, N_LEGS)) < 0.8
    contact[0] = True
    body = np.full((N_STEPS, N_LEGS, 3), np.nan)
    foot = np.zeros((N_STEPS, N_LEGS, 3))
    for k in range(N_STEPS):
        R = quat_matrix(q[k])
        for i, leg in enumerate(legs):
            body[k, i] = footpad_position(leg, leg.rest_lengths - rng.uniform(0, 0.1, 3))
            foot[k, i] = y[k, 0:3] + R @ body[k, i]
    force = rng.normal(scale=1e4, size=(N_STEPS, N_LEGS, 3))
    res = SimpleNamespace(t=np.linspace(0, 1, N_STEPS), y=y, footpad=foot, leg_force=force, contact=contact)
    return res, body


@pytest.mark.parametrize("attach", [0.0, 0.3], ids=["inverted", "cantilever"])
def test_strut_loads_balance_the_footpad_force(attach):
    # The massless leg in equilibrium (Hibbeler, Statics, sec. 6.5): the hardpoint forces sum to the footpad
    # force and their moments about the CG to the footpad force's; the cartridge and secondary forces give the
    # footpad force back by virtual work (G^T T, `footpad_force`); the knee moment is |F_perp| (Lp - a) (0 for
    # the inverted tripod, whose primary is a two-force member); each hardpoint force runs along its strut (the
    # cantilever primary's pin aside). Tolerance 1e-9 of the force (N) or moment scale (N m): round-off of 3x3
    # solves at condition numbers below 1e3 is ~1e-12.
    legs = _legs(attach)
    res, body = _history(legs, 7)
    h = tripod_member_histories(res, legs)
    scale = np.max(np.abs(res.leg_force))
    for k in range(N_STEPS):
        for i, leg in enumerate(legs):
            if not res.contact[k, i]:
                assert np.isnan(h.hardpoints[k, i]).all() and np.isnan(h.knee_moment[k, i])
                assert all(np.isnan(h.forces[m][k, i]) for m in TRIPOD_FORCES)
                continue
            F, P, H = res.leg_force[k, i], body[k, i], h.hardpoints[k, i]
            np.testing.assert_allclose(H.sum(axis=0), F, rtol=0, atol=1e-9 * scale)
            np.testing.assert_allclose(np.cross(leg.hardpoints, H).sum(axis=0), np.cross(P, F), rtol=0,
                                       atol=1e-9 * scale * 5.0)
            T = [h.forces[m][k, i] for m in ("primary", "secondary1", "secondary2")]
            np.testing.assert_allclose(footpad_force(leg, T, P), F, rtol=0, atol=1e-9 * scale)
            u = (P - leg.primary_hardpoint) / np.linalg.norm(P - leg.primary_hardpoint)
            arm = np.linalg.norm(P - leg.primary_hardpoint) - leg.knee_offset if leg.is_cantilever else 0.0
            assert h.knee_moment[k, i] == pytest.approx(np.linalg.norm(F - (F @ u) * u) * arm, rel=1e-12, abs=1e-9)
            joint = leg.primary_hardpoint + leg.knee_offset * u if leg.is_cantilever else P
            for j in range(1 if leg.is_cantilever else 0, 3):
                e = joint - leg.hardpoints[j]
                assert np.linalg.norm(np.cross(H[j], e)) <= 1e-9 * scale * np.linalg.norm(e)


def test_interface_extremes_name_the_largest_hardpoint_force():
    # The largest |force| of each leg's hardpoint over the history, at its step, components as stored (exact:
    # the same array read back).
    legs = _legs(0.0)
    res, _ = _history(legs, 3)
    h = tripod_hardpoints(res, legs)
    rows = interface_extremes(h, res.t)
    assert [(r["leg"], r["hardpoint"]) for r in rows] == [(i + 1, n) for i in range(N_LEGS) for n in h.names]
    for r in rows:
        f = h.forces[:, r["leg"] - 1, h.names.index(r["hardpoint"])]
        mag = np.linalg.norm(f, axis=1)
        k = int(np.nanargmax(mag))
        assert r["force_N"] == mag[k] and r["components_N"] == list(f[k]) and r["t_s"] == res.t[k]
