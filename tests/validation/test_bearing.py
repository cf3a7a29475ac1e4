"""`bearing`: sigma = P/(d t) (AFFDL-TR-66-33 App. IV) against the weaker yield of the pin and the part it bears
on (Bruhn 1973 D1); P the resultant of orthogonal components, or the sum of loads on one surface."""

import pytest
from member_cases import LBF, PSI, item, outcome

from alightsize.common.errors import InputError

LUGS = {"shape": "rectangle", "width": "0.40 in", "height": "0.50 in"}


def test_app_iv_lower_leg_slip_joint_adds_collinear_loads():
    """App. IV telescoping leg, Lower Leg Tube: (w1 + w2)/d = (261 + 6070)/3.00 = 2,110 psi (a load per inch: 1 in of
    bearing reproduces it); the two loads press the same surface, combine = "sum". Exact arithmetic: 1e-12."""
    o = outcome({"kind": "bearing", "loads": ["261 lbf", "6070 lbf"], "combine": "sum", "diameter": "3.00 in",
                 "bearing_length": "1 in"}, None, "be-31al")
    assert o.stress / PSI == pytest.approx((261 + 6070) / 3.00, rel=1e-12)


def test_app_iv_upper_cap_lugs():
    """App. IV telescoping leg, Upper Cap Lugs: 3,930/(0.25 x 0.40) = 39,300 psi (printed 39,400), f = 69,000/39,400 =
    1.75; one unit of the printed stress's third figure: 0.3 %; f (1.756 from 39,300) to one unit of its printed
    digit."""
    o = outcome({"kind": "bearing", "loads": ["3930 lbf"], "diameter": "0.25 in", "bearing_length": "0.40 in"}, LUGS)
    assert o.stress / PSI == pytest.approx(39_400, rel=0.003)
    assert o.factor == pytest.approx(1.75, abs=0.01)


@pytest.mark.parametrize("loads", [["3 kN", "4 kN"], ["-3 kN", "4 kN"], ["3 kN", "-4 kN"]])
def test_orthogonal_components_take_their_resultant(loads):
    """Default: P = sqrt(3^2 + 4^2) = 5 kN whatever the signs, the load the pin's shear check takes too."""
    bearing = outcome({"kind": "bearing", "loads": loads, "diameter": "10 mm", "bearing_length": "10 mm"}, None)
    shear = outcome({"kind": "pin_double_shear", "loads": loads, "diameter": "10 mm"}, None)
    assert bearing.load == pytest.approx(5000.0, rel=1e-15) == shear.load
    assert outcome({"kind": "bearing", "loads": loads, "combine": "sum", "diameter": "10 mm",
                    "bearing_length": "10 mm"}, None).load == pytest.approx(7000.0, rel=1e-15)


def test_a_steel_pin_in_an_aluminium_lug_is_judged_on_the_lug():
    """4130 pin (180 ksi) in a 7178-T6 lug (69 ksi): the allowable is the lug's yield, f = 69,000/sigma; the lug
    named as the item and the pin as `material` gives the same (the weaker of the two, exact)."""
    base = {"kind": "bearing", "loads": ["3930 lbf"], "diameter": "0.25 in", "bearing_length": "0.40 in"}
    on_lug = outcome({**base, "material": "7178-t6"}, None, "4130-steel")
    alone = outcome(base, None, "4130-steel")
    assert alone.allowable / PSI == pytest.approx(180_000, rel=1e-12)
    assert on_lug.allowable / PSI == pytest.approx(69_000, rel=1e-12)
    assert on_lug.factor == outcome({**base, "material": "4130-steel"}, None, "7178-t6").factor
    assert on_lug.factor == pytest.approx(69_000 / (3930 / (0.25 * 0.40)), rel=1e-9)


def test_an_unknown_lug_material_names_the_key():
    with pytest.raises(InputError) as err:
        item({"kind": "bearing", "loads": ["1 kN"], "diameter": "10 mm", "bearing_length": "5 mm",
              "material": "unobtainium"}, None)
    assert err.value.key == 'item[0].check["bearing"].material' and "unobtainium" in err.value.found


def test_the_load_is_in_newtons():
    o = outcome({"kind": "bearing", "loads": ["3930 lbf"], "diameter": "0.25 in", "bearing_length": "0.40 in"}, LUGS)
    assert o.load == pytest.approx(3930 * LBF, rel=1e-15)
