"""`tension`: sigma = P/A against yield (AFFDL-TR-66-33 App. IV)."""

import pytest
from member_cases import PSI, outcome, rod


def test_app_iv_peg_leg_absorber_rod():
    """App. IV configs 3-5, 7, Peg Leg Energy Absorber Rod: 30,000 lb on 0.785 (0.818)^2 = 0.525 in^2: sigma = 57,000
    psi, f = 69,000/57,000 = 1.21. pi/4 for 0.785 and the three-figure area move sigma by 0.1 %: 0.5 %; f to its
    printed digit."""
    o = outcome({"kind": "tension", "load": "30000 lbf"}, rod(0.818))
    assert o.mode == "tension"
    assert o.stress / PSI == pytest.approx(57_000, rel=0.005)
    assert o.factor == pytest.approx(1.21, abs=0.005)


def test_a_load_given_as_a_compression_component_is_judged_on_its_magnitude():
    plus = outcome({"kind": "tension", "load": "30000 lbf"}, rod(0.818))
    minus = outcome({"kind": "tension", "load": "-30000 lbf"}, rod(0.818))
    assert minus.factor == plus.factor
