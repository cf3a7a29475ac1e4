"""`bending`: sigma = M c/I against yield (AFFDL-TR-66-33 App. IV), on every section shape."""

from math import pi

import pytest
from member_cases import IN, LBF, PSI, outcome, rod

from alightsize.common.config import Node
from alightsize.model.sections import read_section


def test_rod_second_moment_is_the_solid_circle():
    """I = pi d^4/64 and c = d/2 (Young & Budynas 2002 Table A.1); equivalently I = A k^2 with k = d/4, and the
    tube formula pi (OD^4 - ID^4)/64 at ID = 0 (closed forms, 1e-15)."""
    d = 0.818 * IN
    s = read_section(Node("case.toml", "section", rod(0.818)))
    assert s.inertia() == pytest.approx(pi * d ** 4 / 64, rel=1e-15)
    assert s.inertia() == pytest.approx(s.area() * (d / 4) ** 2, rel=1e-15)
    assert s.c() == d / 2


def test_rod_bending_is_32_m_over_pi_d_cubed():
    """A 0.818 in rod under 1,000 lbf x 2 in: sigma = 32 M/(pi d^3) (section modulus pi d^3/32), 1e-12."""
    o = outcome({"kind": "bending", "moment_force": "1000 lbf", "moment_arm": "2 in"}, rod(0.818))
    assert o.stress / PSI == pytest.approx(32 * 2000 / (pi * 0.818 ** 3), rel=1e-12)


def test_rectangle_bending_is_6_m_over_b_h_squared():
    """App. IV swivel and lugs section: b = 0.40, h = 0.50 in, M = 1,075 x 0.5 lb-in: sigma = 6 M/(b h^2) =
    32,250 psi (the report printed 30,000 for this, App. IV telescoping leg, Upper Cap Lugs; 32,250 is its own
    substitution)."""
    o = outcome({"kind": "bending", "moment_force": "1075 lbf", "moment_arm": "0.5 in"},
                {"shape": "rectangle", "width": "0.40 in", "height": "0.50 in"})
    assert o.stress / PSI == pytest.approx(32_250, rel=1e-12)


def test_a_negative_moment_is_the_other_fibre():
    """M = -P l stresses the opposite fibre to the same magnitude: the same f, exactly."""
    plus = outcome({"kind": "bending", "moment": "2000 lbf*in"}, rod(0.818))
    minus = outcome({"kind": "bending", "moment": "-2000 lbf*in"}, rod(0.818))
    force = outcome({"kind": "bending", "moment_force": "-1000 lbf", "moment_arm": "2 in"}, rod(0.818))
    assert plus.factor == minus.factor == pytest.approx(force.factor, rel=1e-15)
    assert plus.stress == pytest.approx(2000 * LBF * IN * (0.409 * IN) / (pi * (0.818 * IN) ** 4 / 64), rel=1e-12)
