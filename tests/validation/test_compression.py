"""`compression`: sigma = P/A against yield (AFFDL-TR-66-33 App. IV)."""

from math import inf, pi

import pytest
from member_cases import LBF, PSI, outcome, tube

UPPER_TRUSS = tube(2.75, 0.0675)          # App. IV configurations 3-5, 7 upper truss, Be(31)Al


def test_app_iv_upper_truss():
    """App. IV configs 3-5, 7, Upper Truss: 33,784 lb on pi (2.67)(0.0675) = 0.566 in^2, sigma = 59,700 psi, f =
    74,000/59,700 = 1.24. The report takes d = 2.67 for 2.75 - 0.0675 = 2.6825 in (0.47 % low) and rounds A: 1 % on
    sigma, and one unit of f's last printed digit (0.01)."""
    o = outcome({"kind": "compression", "load": "33784 lbf"}, UPPER_TRUSS, "be-31al")
    assert o.stress / PSI == pytest.approx(59_700, rel=0.01)
    assert o.factor == pytest.approx(1.24, abs=0.01)


def test_a_negative_load_is_judged_on_its_magnitude():
    """A compression component written negative (a tension-positive convention) gives the same f, exactly."""
    plus = outcome({"kind": "compression", "load": "33784 lbf"}, UPPER_TRUSS, "be-31al")
    minus = outcome({"kind": "compression", "load": "-33784 lbf"}, UPPER_TRUSS, "be-31al")
    assert minus.stress == -plus.stress and minus.factor == plus.factor


def test_a_zero_load_is_unloaded():
    assert outcome({"kind": "compression", "load": "0 lbf"}, UPPER_TRUSS, "be-31al").factor == inf


def test_a_thick_wall_area_is_exact():
    """A = pi d t on the mean diameter equals pi (OD^2 - ID^2)/4 for any wall (the difference of squares): a
    2.75 x 0.5 in tube, 1e-12 (float rounding)."""
    o = outcome({"kind": "compression", "load": "33784 lbf"}, tube(2.75, 0.5), "be-31al")
    assert o.stress == pytest.approx(33784 * LBF / (pi / 4 * (2.75 ** 2 - 1.75 ** 2) * 0.0254 ** 2), rel=1e-12)
