"""Crush cell with memory (CURVE, Fig. 19): loading, unloading spring, damper limit, set, bottoming."""

import pytest
from scipy.integrate import quad

from alightsize_sim import crush_cell as cc
from alightsize_sim.crush_cell import CellModel
from alightsize_sim.crush_curve import CrushCurve

CURVE = CrushCurve((0.0, 0.02, 0.30, 0.35), (0.0, 30_000.0, 30_000.0, 60_000.0))
K = 5e6


def _arrays(**kw):
    return CellModel(CURVE, K, **kw).arrays


def test_loading_follows_the_curve_and_bottoming_continues_or_yields():
    d, f, k, c, y = _arrays()
    assert cc.force(d, f, k, c, y, (0.0, 0.0), 0.01, 0.0) == pytest.approx(15_000.0)
    assert cc.force(d, f, k, c, y, (0.0, 0.0), -0.01, 0.0) == 0.0              # never pulls
    assert cc.force(d, f, k, c, y, (0.0, 0.0), 0.40, 0.0) == pytest.approx(60_000 + 6e5 * 0.05)   # stiff stop
    d, f, k, c, y = _arrays(yield_force=65_000.0)
    assert cc.force(d, f, k, c, y, (0.0, 0.0), 0.40, 0.0) == 65_000.0           # yield plateau after bottoming
    assert CURVE.bottoming == 0.30


def test_unloading_spring_set_and_energy():
    d, f, k, c, y = _arrays()
    dmax, fmax = cc.commit(d, f, y, 0.0, 0.0, 0.2)
    assert (dmax, fmax) == (0.2, 30_000.0)
    assert cc.force(d, f, k, c, y, (dmax, fmax), 0.199, 0.0) == pytest.approx(30_000 - K * 0.001)
    zset = cc.permanent_set(k, dmax, fmax)
    assert zset == pytest.approx(0.2 - 30_000 / K)
    assert cc.force(d, f, k, c, y, (dmax, fmax), zset - 1e-6, 0.0) == 0.0
    # Energy the spring gives back from dmax to the set: fmax^2 / (2k) in closed form.
    back, _ = quad(lambda x: cc.force(d, f, k, c, y, (dmax, fmax), x, 0.0), zset, dmax, epsabs=1e-9)
    assert back == pytest.approx(cc.elastic_energy(k, dmax, fmax, dmax), rel=1e-9)
    assert cc.elastic_energy(k, dmax, fmax, dmax) == pytest.approx(30_000 ** 2 / (2 * K))


def test_damper_is_limited_below_the_spring_and_never_above_fmax():
    d, f, k, c, y = _arrays(c=1e6)
    dmax, fmax = 0.2, 30_000.0
    spring = fmax - K * 0.004
    assert cc.force(d, f, k, c, y, (dmax, fmax), 0.196, -10.0) == pytest.approx(0.1 * spring)   # 0.9 limit
    assert cc.force(d, f, k, c, y, (dmax, fmax), 0.196, +10.0) == pytest.approx(min(1.9 * spring, fmax))
    assert cc.force(d, f, k, c, y, (dmax, fmax), 0.1999, +10.0) <= fmax


def test_cell_model_checks_its_inputs():
    with pytest.raises(ValueError):
        CellModel(CURVE, 0.0)
    with pytest.raises(ValueError):
        CellModel(CURVE, K, c=-1.0)
