"""`ring_bending`: the ring as a centrally loaded beam, M = P L/4, sigma = M c/I (AFFDL-TR-66-33 App. IV), for
R/c >= 2 (R = L/2)."""

import pytest
from member_cases import PSI, outcome

from alightsize.common.errors import InputError

RING = {"shape": "given", "inertia": "8.55 in^4", "c": "2.80 in"}          # App. IV configurations 3-5, 7


def test_app_iv_peg_leg_ring():
    """App. IV configs 3-5, 7, Peg Leg Ring: M = 49,000 (12.8)/4 = 157,000 lb-in, sigma = 157,000 (2.8)/8.55 = 51,400
    psi, f = 69,000/51,400 = 1.34. M printed 157,000 for 156,800 (0.13 %): 0.5 % on sigma; f to its printed digit."""
    o = outcome({"kind": "ring_bending", "load": "49000 lbf", "span": "12.8 in"}, RING)
    assert o.stress / PSI == pytest.approx(51_400, rel=0.005)
    assert o.factor == pytest.approx(1.34, abs=0.005)


def test_a_negative_load_bends_the_same():
    plus = outcome({"kind": "ring_bending", "load": "49000 lbf", "span": "12.8 in"}, RING)
    minus = outcome({"kind": "ring_bending", "load": "-49000 lbf", "span": "12.8 in"}, RING)
    assert minus.factor == plus.factor


def test_a_thick_ring_is_refused():
    """R/c = 1.9 (span 10.64 in on c = 2.8 in): the straight-beam model no longer covers the curved-beam inner
    fibre (Young & Budynas 2002 Table 9.1: 1.52 at R/c = 2 for a rectangle): refused naming `span`."""
    with pytest.raises(InputError) as err:
        outcome({"kind": "ring_bending", "load": "49000 lbf", "span": "10.64 in"}, RING)
    assert err.value.key == 'item[0].check["ring_bending"].span'
    outcome({"kind": "ring_bending", "load": "49000 lbf", "span": "11.2 in"}, RING)      # R/c = 2.0 exactly
