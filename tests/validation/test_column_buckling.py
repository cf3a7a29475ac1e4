"""`column_buckling`: pinned ends, Johnson's parabola below the transition slenderness pi sqrt(2E/Fcy), Euler's
curve at or above it (Bruhn 1973 C2.4-C2.6), against P/A."""

from math import pi, sqrt

import pytest
from member_cases import LBF, PSI, outcome, step, tube

STRUT = tube(2.0, 0.058)                      # 6061-T6, 34 in, 9,000 lbf
E, FCY = 9.9e6, 35_000                        # psi (MIL-HDBK-5J 6061-T6)
D, T = 2.0 - 0.058, 0.058                     # mean diameter and wall, in
A = pi * D * T                                # 0.3539 in^2
K = D / (2 * sqrt(2))                         # sqrt(I/A) of I = pi r^3 t: 0.6866 in
TRANSITION = pi * sqrt(2 * E / FCY)           # 74.72


def check(length: float, load: float = 9000, formula: str | None = None) -> dict:
    out = {"kind": "column_buckling", "load": f"{load!r} lbf", "length": f"{length!r} in"}
    return out | ({"formula": formula} if formula else {})


def johnson(lk: float) -> float:
    """Bruhn 1973 eq. C2.6: Fcy - (Fcy / 2 pi)^2 (L/k)^2 / E, psi."""
    return FCY - (FCY / (2 * pi)) ** 2 * lk ** 2 / E


def test_6061_strut_below_the_transition_is_johnson():
    """A 2.0 x 0.058 in 6061-T6 tube, 34 in, 9,000 lb: L/k = 49.5 below the transition 74.7, so Johnson's
    parabola: sigma_cr = 27,300 psi against P/A = 25,430 psi, f = 1.07, where Euler's 39,850 psi would give 1.57.
    Hand arithmetic of the same formulas: 1e-9 (unit round trips)."""
    lk = 34 / K
    assert lk == pytest.approx(49.52, abs=0.01) and TRANSITION == pytest.approx(74.72, abs=0.01)
    o = outcome(check(34), STRUT, "6061-t6")
    assert o.allowable / PSI == pytest.approx(johnson(lk), rel=1e-9)
    assert o.factor == pytest.approx(johnson(lk) / (9000 / A), rel=1e-9)
    assert o.factor == pytest.approx(1.074, abs=0.001)
    assert pi ** 2 * E / lk ** 2 / (9000 / A) == pytest.approx(1.567, abs=0.001)        # Euler's, not used


def test_app_iv_euler_lines_are_shown_but_johnson_judges_below_the_transition():
    """`formula = "euler"` (App. IV) keeps the Euler stress on its line (pi^2 E/(L/k)^2, 39,850 psi) and judges
    on Johnson's parabola, exactly as `johnson_euler`."""
    euler = outcome(check(34, formula="euler"), STRUT, "6061-t6")
    johnson_euler = outcome(check(34, formula="johnson_euler"), STRUT, "6061-t6")
    assert step(euler, "σcB") / PSI == pytest.approx(pi ** 2 * E / (34 / K) ** 2, rel=1e-9)
    assert (euler.allowable, euler.factor) == (johnson_euler.allowable, johnson_euler.factor)


@pytest.mark.parametrize("ratio", [0.99, 1.0, 1.01])
def test_around_the_transition_both_curves_give_half_the_yield(ratio):
    """At L/k = (L/k)_T the two curves meet at Fcy/2 (Bruhn 1973 C2.4): 1 % either side the critical stress
    is within 2 % of Fcy/2 (d sigma / d(L/k) = -Fcy/(L/k)_T there, so 1 % of L/k moves it 1 % of Fcy)."""
    length = ratio * TRANSITION * K
    o = outcome(check(length), STRUT, "6061-t6")
    assert o.allowable / PSI == pytest.approx(FCY / 2, rel=0.02)
    label = next(s.label for s in o.steps if s.symbol == "σcr")
    assert ("Johnson" in label) is (ratio < 1)


def test_a_long_column_is_euler():
    """L/k = 150 (twice the transition): sigma_cr = pi^2 E/150^2 = 4,343 psi (closed form, 1e-9)."""
    o = outcome(check(150 * K, 1000), STRUT, "6061-t6")
    assert o.allowable / PSI == pytest.approx(pi ** 2 * E / 150 ** 2, rel=1e-9)


def test_app_iv_telescoping_leg_euler_load():
    """App. IV telescoping leg, Lower Leg Tube: P_cr = pi^2 (34e6)(0.478)/30.5^2, printed 167,000 lb; the substitution
    gives 172,400 (the printed value is 3.2 % low): our line is the substitution, 1e-9."""
    o = outcome(check(30.5, 3750, "euler"), {"shape": "tube", "outside_diameter": "3.00 in", "wall": "0.050 in",
                                               "inertia": "0.478 in^4"}, "be-31al")
    assert step(o, "Pcr") / LBF == pytest.approx(pi ** 2 * 34e6 * 0.478 / 30.5 ** 2, rel=1e-9)


def test_a_tension_load_is_judged_as_its_magnitude():
    """A negative (tension) load gives the compression factor: conservative, never infinite."""
    assert outcome(check(34, -9000), STRUT, "6061-t6").factor == outcome(check(34), STRUT, "6061-t6").factor
