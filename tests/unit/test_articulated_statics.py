"""Articulated-leg equilibrium (eq. 53-61, 96-106): the 6x6 system against the closed form, virtual work
against the footpad kinematics, truss joint equilibrium."""

import numpy as np
import pytest

from alightsize.loads.config import read_loads
from alightsize_sim.articulated_cells import lower_deflection, upper_deflection
from alightsize_sim.articulated_kinematics import footpad
from alightsize_sim.articulated_statics import member_loads, reactions, residuals

from conftest import EXAMPLES

CFG = read_loads(EXAMPLES / "loads" / "articulated.toml")
G = CFG.cases[0].geometry
TRUSS = CFG.cases[0].truss
NAMES = ("F1", "F2", "F3", "Q1", "Q2", "R11", "R12", "R13", "RA", "RB")


def _random(n, seed):
    rng = np.random.default_rng(seed)
    return (rng.uniform(0, np.radians(45), n), rng.uniform(-np.pi, np.pi, n),
            rng.uniform(np.radians(-30), np.radians(30), n), rng.uniform(1e4, 6e5, n), rng.uniform(1e4, 6e5, n))


def test_matrix_and_closed_form_agree_at_10000_positions():
    a, b, p, f1, f2 = _random(10_000, 3)
    closed, matrix = reactions(G, a, b, p, f1, f2), reactions(G, a, b, p, f1, f2, method="matrix")
    scale = np.maximum(f1, f2)
    # Issue 3: residuals of eq. 53-58 below 1e-9 of the cell forces, and the two routes equal to 1e-9
    # (both are exact in exact arithmetic; double rounding leaves ~1e-15).
    for r in (closed, matrix):
        assert np.max(np.abs(residuals(G, a, b, p, f1, f2, r)) / scale[:, None]) < 1e-9
    for n in NAMES:
        assert np.max(np.abs(getattr(closed, n) - getattr(matrix, n)) / scale) < 1e-9, n


def test_ground_force_does_the_cells_virtual_work():
    # Independent of eq. 53-61: with massless links, F . dS' = AF1 dDelta1 + AF2 dDelta2 for any virtual
    # displacement (central differences, h = 1e-6 rad: truncation ~1e-12 relative, well inside 1e-6).
    a, b, p, f1, f2 = _random(200, 4)
    a = np.maximum(a, 0.02)
    r = reactions(G, a, b, p, f1, f2)
    F = np.array([r.F1, r.F2, r.F3])
    h = 1e-6
    p0 = np.radians(-15.0)
    for da, db, dp in ((h, 0, 0), (0, h, 0), (0, 0, h)):
        ds = (np.array(footpad(G, a + da, b + db, p + dp)) - np.array(footpad(G, a - da, b - db, p - dp))) / 2
        work_cells = f1 * (upper_deflection(G, p + dp, p0) - upper_deflection(G, p - dp, p0)) / 2 \
            + f2 * (lower_deflection(G, a + da) - lower_deflection(G, a - da)) / 2
        work_ground = np.sum(F * ds, axis=0)
        assert np.max(np.abs(work_ground - work_cells) / (np.maximum(f1, f2) * G.AU * h)) < 1e-6


def test_truss_joints_balance():
    # Eq. 101-106 solve the joints: PU1 + PU2 = -Q2 / cos(theta), (PU1 - PU2) sin(theta) = RA, where PU2
    # is PU1 with RA reversed (the mirror member); likewise PL1/PL3 and PL2/PL6 with RB.
    a, b, p, f1, f2 = _random(500, 5)
    r = reactions(G, a, b, p, f1, f2)
    m = member_loads(r, TRUSS)
    mirror = member_loads(type(r)(**{**r.__dict__, "RA": -r.RA, "RB": -r.RB}), TRUSS)
    t = TRUSS.theta
    np.testing.assert_allclose((m["PU1"] + mirror["PU1"]) * np.cos(t), -r.Q2, rtol=1e-12, atol=1e-6)
    np.testing.assert_allclose((m["PU1"] - mirror["PU1"]) * np.sin(t), r.RA, rtol=1e-12, atol=1e-6)
    # Lower joints: PL1 (angle rho) with PL6 (gamma), PL2 (gamma) with PL3 (rho), each taking Q1/2, RB/2.
    g_, r_ = TRUSS.gamma, TRUSS.rho
    pl6 = mirror["PL2"]
    np.testing.assert_allclose(m["PL1"] * np.cos(r_) + pl6 * np.cos(g_), -r.Q1 / 2, rtol=1e-12, atol=1e-6)
    np.testing.assert_allclose(m["PL1"] * np.sin(r_) - pl6 * np.sin(g_), r.RB / 2, rtol=1e-12, atol=1e-6)


def test_method_is_checked():
    with pytest.raises(ValueError):
        reactions(G, 0.1, 0.0, 0.0, 1.0, 1.0, method="lu")


def test_envelopes_follow_the_scaling_laws():
    # Statics is homogeneous: lengths x L and forces x F leave the angles alone and scale every member
    # load by F (Table 27: force ~ L^2 at acceleration scale 1). Config 9's geometry is the full-scale one
    # x 1.825/4 (length_scale); scaling config 3 the same way must give config-3 loads x F at the same
    # positions (to rounding, 1e-12).
    from dataclasses import replace
    from alightsize.loads.envelopes import envelope
    from alightsize.model.legs import LENGTHS
    from alightsize_sim.crush_curve import CrushCurve
    L, F = 1.825 / 4, 0.1                      # F arbitrary (the 300 lb capsule: mass ratio 0.1)
    case = CFG.cases[0]
    g = case.geometry._replace(**{k: L * getattr(case.geometry, k) for k in LENGTHS}, PLD=F * case.geometry.PLD,
                SPRG=F / L * case.geometry.SPRG)
    scaled = replace(case, geometry=g,
                     upper=CrushCurve(tuple(L * d for d in case.upper.deflection),
                                      tuple(F * f for f in case.upper.force)),
                     lower=CrushCurve(tuple(L * d for d in case.lower.deflection),
                                      tuple(F * f for f in case.lower.force)))
    assert CFG.cases[-1].geometry.AU == pytest.approx(L * G.AU, rel=1e-15)          # config 9, as shipped
    for a, b in zip(envelope(case, CFG.grid), envelope(scaled, CFG.grid)):
        for e, s in ((a.tension, b.tension), (a.compression, b.compression)):
            assert (e is None) == (s is None)
            if e is not None:
                assert s.value == pytest.approx(F * e.value, rel=1e-12) and s.at == e.at
