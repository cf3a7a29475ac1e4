"""Range-aware formulas of derived checks against their closed forms (alightsize.checks.stress / plates)."""

from math import exp, pi, sqrt

import pytest

from alightsize.checks import plates, stress
from alightsize.checks.kinds import read_check
from alightsize.common.config import Node
from alightsize.model.materials import library
from alightsize.model.sections import read_section

E, FY = 71.0e9, 476.0e6          # a 7000-series aluminium, Pa


def test_johnson_meets_euler_at_the_transition():
    """Continuity to round-off (1e-12) at (L/k)_T = pi sqrt(2E/Fcy); Johnson at zero slenderness is Fcy."""
    lt = stress.transition_slenderness(E, FY)
    assert stress.johnson_stress(E, FY, lt) == pytest.approx(pi ** 2 * E / lt ** 2, rel=1e-12)
    assert stress.johnson_stress(E, FY, 0.0) == FY
    assert stress.column_stress(E, FY, 0.5 * lt)[1] == "johnson"
    assert stress.column_stress(E, FY, 2.0 * lt) == (pytest.approx(pi ** 2 * E / (2 * lt) ** 2, rel=1e-15), "euler")


def test_knockdown_hand_value_and_limit():
    """SP-8007 eq. 4 at r/t = 100: phi = 0.625, gamma = 1 - 0.901 (1 - e^-0.625) (hand value, 1e-12); -> 1 as
    r/t -> 0."""
    assert stress.thin_wall_knockdown(100.0) == pytest.approx(1 - 0.901 * (1 - exp(-0.625)), rel=1e-12)
    assert stress.thin_wall_knockdown(0.0) == 1.0


def test_equivalent_radius_applies_only_below_half_the_thickness():
    t = 0.01
    assert plates.equivalent_radius(0.006, t) == 0.006
    assert plates.equivalent_radius(0.0, t) == pytest.approx(0.325 * t, rel=1e-12)        # sqrt(t^2) - 0.675 t
    r = 0.002
    assert plates.equivalent_radius(r, t) == pytest.approx(sqrt(1.6 * r * r + t * t) - 0.675 * t, rel=1e-15)


def test_equivalent_stresses_on_equal_biaxial_stress():
    """A plate centre (s, s, 0): Tresca and von Mises both give s (exact)."""
    assert stress.tresca_stress(3.0, 3.0) == 3.0
    assert stress.von_mises_stress(3.0, 3.0) == pytest.approx(3.0, rel=1e-15)


def _check(data: dict, section: dict):
    sec = read_section(Node("t.toml", "section", section))
    return read_check(Node("t.toml", "check", data)).evaluate(sec, library()["7178-t6"])


def test_app_iv_plate_rule_is_twice_as_conservative_at_the_centre():
    """(sigma_r + sigma_t)/2 against Fcy/2 versus Tresca against Fcy on sigma_r = sigma_t: factor ratio 2."""
    plate = {"shape": "plate", "diameter": "60 mm", "thickness": "5 mm"}
    base = {"kind": "plate_fixed_center_load", "load": "8 kN", "load_radius": "10 mm"}
    old = _check({**base, "theory": "app_iv"}, plate)
    new = _check({**base, "theory": "tresca"}, plate)
    assert new.factor == pytest.approx(2 * old.factor, rel=1e-12)


def test_euler_alone_is_unconservative_for_a_stocky_strut():
    """A short tube (L/k ~ 20, below the transition ~ 77 for 7178-T6): Euler's stress, still shown on App. IV's
    line, is above Johnson's, and the check judges on Johnson's whichever formula it names (exact)."""
    tube = {"shape": "tube", "outside_diameter": "60 mm", "wall": "2 mm"}
    base = {"kind": "column_buckling", "load": "50 kN", "length": "0.4 m"}
    euler = _check({**base, "formula": "euler"}, tube)
    johnson = _check({**base, "formula": "johnson_euler"}, tube)
    shown = next(s.value for s in euler.steps if s.symbol == "σcB")
    assert johnson.allowable < shown
    assert (euler.allowable, euler.factor) == (johnson.allowable, johnson.factor)


def test_pin_double_shear_by_hand():
    """tau = sqrt(P1^2 + P2^2) / (2 pi d^2 / 4) against Fcy/2 (7178-T6 69 ksi), exact arithmetic."""
    out = _check({"kind": "pin_double_shear", "loads": ["3 kN", "4 kN"]}, {"shape": "rod", "diameter": "10 mm"})
    tau = 5000.0 / (2 * pi * 0.01 ** 2 / 4)
    assert out.stress == pytest.approx(tau, rel=1e-12)
    assert out.factor == pytest.approx(69000 * 6894.757293168361 / 2 / tau, rel=1e-9)
