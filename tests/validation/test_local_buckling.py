"""`local_buckling`: NASA SP-8007 (1968) or App. IV's 0.4 E t/D for thin walls, capped at the compressive yield;
a thick wall (r/t < 10) at the yield; outside the formulas' r/t ranges refused."""

from math import exp, pi, sqrt

import pytest
from member_cases import PSI, outcome, step, tube

from alightsize.common.errors import InputError

LOWER_LEG = {"shape": "tube", "outside_diameter": "3.00 in", "wall": "0.050 in", "inertia": "0.478 in^4"}
APP_IV = {"kind": "local_buckling", "load": "3750 lbf", "moment_force": "1045 lbf", "moment_arm": "15.5 in",
          "wall": "0.0436 in", "formula": "app_iv"}
E, FCY, NU = 10e6, 69_000, 1 / 3.33             # 7178-T6 as App. IV (psi)


def sp8007(od: float, t: float) -> float:
    """gamma E t/(r sqrt(3 (1 - nu^2))), gamma = 1 - 0.901 (1 - exp(-sqrt(r/t)/16)) (NASA SP-8007 1968), psi."""
    r = (od - t) / 2
    return (1 - 0.901 * (1 - exp(-sqrt(r / t) / 16))) * E * t / (r * sqrt(3 * (1 - NU ** 2)))


def check(load: str = "1000 lbf", formula: str = "sp8007", **extra) -> dict:
    return {"kind": "local_buckling", "load": load, "formula": formula, **extra}


def test_app_iv_telescoping_lower_leg_is_capped_at_yield():
    """App. IV telescoping leg, Lower Leg Tube: sigma_LB = 0.4 (34e6)(0.0436)/3.0 = 198,000 psi (the line, 0.5 % for
    its three figures), above Be(31)Al's 74,000 psi yield: the allowable is 74,000. The check's wall is the wall of its
    P/A too: 3750/(pi 2.9564 0.0436) + 16,197.5 (1.5)/0.478 = 60,090 psi, f = 1.232 (hand, 1e-9)."""
    o = outcome(APP_IV, LOWER_LEG, "be-31al", rules="app_iv")
    assert step(o, "σLB") / PSI == pytest.approx(198_000, rel=0.005)
    assert o.allowable / PSI == pytest.approx(74_000, rel=1e-12)
    applied = 3750 / (pi * (3.0 - 0.0436) * 0.0436) + 1045 * 15.5 * 1.5 / 0.478
    assert o.stress / PSI == pytest.approx(applied, rel=1e-9)
    assert o.factor == pytest.approx(74_000 / applied, rel=1e-9)


def test_the_checks_wall_is_the_wall_of_its_applied_stress():
    """One wall per check: a 60 x 2 mm tube checked with wall = 1 mm carries P/(pi (D - t) t) on the 1 mm wall."""
    o = outcome(check("50 kN", wall="1 mm"), {"shape": "tube", "outside_diameter": "60 mm", "wall": "2 mm"})
    assert o.stress == pytest.approx(50e3 / (pi * 0.059 * 0.001), rel=1e-12)


def test_thin_wall_sp8007_elastic():
    """A 7178-T6 tube 6 in x 0.0075 in (r/t = 399): elastic, below the yield; the hand value of SP-8007's
    formula (1e-9), gamma = 0.357."""
    o = outcome(check(), tube(6.0, 0.0075))
    assert o.allowable / PSI == pytest.approx(sp8007(6.0, 0.0075), rel=1e-9)
    assert step(o, "γ") == pytest.approx(0.357, abs=0.001) and o.allowable / PSI < FCY


def test_moderate_wall_is_capped_at_yield():
    """6 in x 0.1 in (r/t = 29.5): SP-8007 gives 111,400 psi > 69,000: capped at the yield."""
    o = outcome(check(), tube(6.0, 0.1))
    assert sp8007(6.0, 0.1) > FCY and o.allowable / PSI == pytest.approx(FCY, rel=1e-12)


def test_thick_wall_yields():
    """r/t = 4.5 (2 in x 0.2 in): the thin-shell formulas do not apply; the critical stress is the yield."""
    o = outcome(check(formula="app_iv"), tube(2.0, 0.2))
    assert o.allowable / PSI == pytest.approx(FCY, rel=1e-12)
    assert any("Thick wall" in s.label for s in o.steps)


def test_sp8007_range_ends_at_r_over_t_1500():
    """NASA SP-8007 states its knockdown for r/t < 1500: r/t = 1999 (a 20 x 0.005 in wall) is refused naming
    the section's wall; 1499 passes."""
    with pytest.raises(InputError) as err:
        outcome(check(), tube(20.0, 0.005))
    assert err.value.key == "item[0].section.wall" and "1500" in err.value.found
    outcome(check(), tube(20.0, 20.0 / 2999.0))


def test_app_iv_range_ends_where_it_reaches_sp8007():
    """0.4 E t/D is at most SP-8007's curve for r/t up to 474 (nu = 0.3): at r/t 600 a check's own wall is
    refused by name; the same tube with formula = "sp8007" is accepted."""
    od, t = 6.0, 6.0 / 1201
    assert 0.4 * E * t / od > sp8007(od, t)
    with pytest.raises(InputError) as err:
        outcome(check(formula="app_iv", wall=f"{t!r} in"), tube(od, 0.1))
    assert err.value.key == 'item[0].check["local_buckling"].wall' and "474" in err.value.found
    outcome(check(wall=f"{t!r} in"), tube(od, 0.1))


def test_a_wall_at_the_outside_radius_is_refused():
    with pytest.raises(InputError) as err:
        outcome(check(wall="1.5 in"), tube(3.0, 0.05))
    assert err.value.key.endswith(".wall")


def test_signs_give_the_worst_fibre():
    """Tension with the moment, or the moment reversed: the same |P/A| + |M c/I| and f."""
    base = outcome(APP_IV, LOWER_LEG, "be-31al", rules="app_iv")
    o = outcome({**APP_IV, "load": "-3750 lbf", "moment_force": "-1045 lbf"}, LOWER_LEG, "be-31al", rules="app_iv")
    assert (o.stress, o.factor) == (base.stress, base.factor)
