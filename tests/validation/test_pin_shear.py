"""`pin_shear`: P = sqrt(sum P_i^2) against a bolt's shear capacity (AFFDL-TR-66-33 App. IV)."""

from math import hypot, inf

import pytest
from member_cases import LBF, outcome


def test_app_iv_double_pin_swivel():
    """App. IV telescoping leg, Double Pin Swivel: 9,300 lb (0.25 in internal-wrenching bolts in double shear) / 3,930
    lb = 2.37; exact arithmetic of the printed resultant: 1e-12."""
    o = outcome({"kind": "pin_shear", "loads": ["3930 lbf"], "allowable_load": "9300 lbf"}, None)
    assert o.factor == pytest.approx(9300 / 3930, rel=1e-12) and round(o.factor, 2) == 2.37


@pytest.mark.parametrize("loads", [["3750 lbf", "1075 lbf"], ["-3750 lbf", "1075 lbf"], ["3750 lbf", "-1075 lbf"]])
def test_components_of_either_sign_take_the_resultant(loads):
    """The components the report names, AF1 = 3,750 and P2 = 1,075 lb: sqrt(3750^2 + 1075^2) = 3,901 lb (it
    printed 3,930), any signs; f = 9,300/3,901 = 2.384 (1e-12)."""
    o = outcome({"kind": "pin_shear", "loads": loads, "allowable_load": "9300 lbf"}, None)
    assert o.load / LBF == pytest.approx(hypot(3750, 1075), rel=1e-12)
    assert o.factor == pytest.approx(9300 / hypot(3750, 1075), rel=1e-12)


def test_zero_components_are_unloaded():
    assert outcome({"kind": "pin_shear", "loads": ["0 lbf", "0 lbf"], "allowable_load": "9300 lbf"}, None).factor == inf
