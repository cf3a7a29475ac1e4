"""`pin_double_shear`: tau = P/(n pi d^2/4) (Bruhn 1973 D1.4) against yield/2 (maximum shear, Roark 1954 p. 79)."""

from math import hypot, pi

import pytest
from member_cases import PSI, outcome


def test_swivel_pin_by_hand():
    """The App. IV swivel's components (3,750 and 1,075 lb) on a 0.25 in 4130 pin in two planes: tau =
    3,901/(2 pi 0.25^2/4) = 39,740 psi against 180,000/2, f = 2.265 (hand, 1e-12)."""
    o = outcome({"kind": "pin_double_shear", "loads": ["3750 lbf", "-1075 lbf"], "diameter": "0.25 in"}, None,
                "4130-steel")
    tau = hypot(3750, 1075) / (2 * pi * 0.25 ** 2 / 4)
    assert o.stress / PSI == pytest.approx(tau, rel=1e-12)
    assert o.factor == pytest.approx(90_000 / tau, rel=1e-12)


def test_single_shear_is_half_the_capacity():
    """planes = 1 doubles tau (exact)."""
    base = {"kind": "pin_double_shear", "loads": ["5 kN"]}
    two = outcome(base, {"shape": "rod", "diameter": "10 mm"})
    one = outcome({**base, "planes": 1}, {"shape": "rod", "diameter": "10 mm"})
    assert one.stress == pytest.approx(2 * two.stress, rel=1e-15) and one.factor == pytest.approx(two.factor / 2)
