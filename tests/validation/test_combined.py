"""`combined`: sigma_max = |P/A| + |M c/I| at the worst fibre, against yield (AFFDL-TR-66-33 App. IV)."""

import math

import pytest
from member_cases import PSI, outcome

LOWER_LEG = {"shape": "tube", "outside_diameter": "3.00 in", "wall": "0.050 in", "inertia": "0.478 in^4"}
CHECK = {"kind": "combined", "load": "3750 lbf", "moment_force": "1045 lbf", "moment_arm": "15.5 in"}


def test_app_iv_telescoping_lower_leg_tube():
    """App. IV telescoping leg, Lower Leg Tube: sigma_B = 16,150 (1.50)/0.478 = 50,500, sigma_C = 3750/0.463 = 8,100,
    sigma_max = 58,600 psi, f = 74,000/58,600 = 1.26. The printed M is 16,150 for 1045 x 15.5 = 16,197.5 (-0.3 %): 1
    %."""
    o = outcome(CHECK, LOWER_LEG, "be-31al")
    assert o.stress / PSI == pytest.approx(58_600, rel=0.01)
    assert o.factor == pytest.approx(1.26, abs=0.005)


def test_app_iv_upper_cap_lugs_from_the_printed_inputs():
    """App. IV telescoping leg, Upper Cap Lugs, lugs 0.40 x 0.50 in under 3,750 lb and 1,075 lb x 0.5 in: sigma_B =
    32,250 (printed 30,000, a slip) + sigma_C = 18,750 = 51,000 psi, f = 69,000/51,000 = 1.353 (the report's 1.42 does
    not follow; tests/validation/test_reference_appendix_iv_v.py records it). Exact arithmetic: 1e-12."""
    o = outcome({"kind": "combined", "load": "3750 lbf", "moment_force": "1075 lbf", "moment_arm": "0.5 in"},
                {"shape": "rectangle", "width": "0.40 in", "height": "0.50 in"})
    assert o.stress / PSI == pytest.approx(32_250 + 18_750, rel=1e-12)


@pytest.mark.parametrize("load, force", [("-3750 lbf", "1045 lbf"), ("3750 lbf", "-1045 lbf"),
                                         ("-3750 lbf", "-1045 lbf")])
def test_signs_give_the_worst_fibre(load, force):
    """Tension with bending, or a reversed moment: the worst fibre still carries |P/A| + |M c/I| (a tension
    load with a moment adds on the tension side), so f is the same to the bit."""
    base = outcome(CHECK, LOWER_LEG, "be-31al")
    o = outcome({**CHECK, "load": load, "moment_force": force}, LOWER_LEG, "be-31al")
    assert o.stress == base.stress and o.factor == base.factor


def test_cantilevered_tube_outrigger_against_roark():
    """An outrigger as the check takes it, a thin tube cantilevered from the body (outside the 1966 report's cases):
    Young & Budynas, Roark's Formulas 7th ed. (2002), Table 8.1 case 1a, end load W on a cantilever of length l:
    M_max = W l at the wall; Table A.1 case 16, hollow circle: A = pi (D^2 - d^2) / 4, I = pi (D^4 - d^4) / 64,
    c = D / 2. A 100 x 3 mm tube, 10 kN along it, W = 2 kN at l = 0.6 m: sigma = P/A + W l c / I = 10.94 + 55.75
    MPa. The check takes App. IV's thin-tube I = pi r^3 t (r the mean radius), low by the factor 1 + t^2 / (4 r^2)
    (9.6e-4 here), so its bending stress is that much above Roark's: conservative. Closed form: 1e-9 (round-off)."""
    D, d, P, W, length = 0.100, 0.094, 10e3, 2e3, 0.6
    r, t = (D + d) / 4, (D - d) / 2
    area, inertia = math.pi * (D ** 2 - d ** 2) / 4, math.pi * (D ** 4 - d ** 4) / 64
    o = outcome({"kind": "combined", "load": "10 kN", "moment_force": "2 kN", "moment_arm": "0.6 m"},
                {"shape": "tube", "outside_diameter": "100 mm", "wall": "3 mm"})
    bending = W * length * (D / 2) / inertia
    assert o.stress == pytest.approx(P / area + bending * (1 + t ** 2 / (4 * r ** 2)), rel=1e-9)
    assert o.stress > P / area + bending
