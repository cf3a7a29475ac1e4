"""`cone_tension`: a strip ten thicknesses wide in direct tension, sigma = P/(10 t^2) (AFFDL-TR-66-33 App. IV)."""

import pytest
from member_cases import PSI, outcome


def test_app_iv_peg_leg_cone():
    """App. IV configs 3-5, 7, Peg Leg Cone: 30,000/(10 (0.25)^2) = 48,000 psi, f = 69,000/48,000 = 1.4375, printed
    1.43 (the report truncates): exact arithmetic, 1e-12; f to one unit of its printed digit."""
    o = outcome({"kind": "cone_tension", "load": "30000 lbf", "thickness": "0.25 in"}, None)
    assert o.stress / PSI == pytest.approx(48_000, rel=1e-12)
    assert o.factor == pytest.approx(1.43, abs=0.01)


def test_a_negative_load_is_its_magnitude():
    plus = outcome({"kind": "cone_tension", "load": "30000 lbf", "thickness": "0.25 in"}, None)
    minus = outcome({"kind": "cone_tension", "load": "-30000 lbf", "thickness": "0.25 in"}, None)
    assert minus.factor == plus.factor
