"""The outrigger of a telescoping leg attached outside the body: its length from the geometry, its root moment
against the statics of the leg's forces (r x F), its loads from the App. III free body, and the inputs refused."""

from math import pi, sqrt

import numpy as np
import pytest
from conftest import ROOT

from alightsize.common.config import load_toml
from alightsize.common.errors import InputError
from alightsize.loads.quasi_static import run_loads
from alightsize.loads.telescoping import TelescopingLeg
from alightsize.pipeline.items import with_loads
from alightsize.pipeline.lander import read_lander
from alightsize.pipeline.outrigger import outrigger_arms

LUNAR = ROOT / "examples" / "lunar_lander.toml"


def _unit(v):
    return v / np.linalg.norm(v)


def test_root_moment_bound_against_the_statics_of_the_legs_forces():
    """The leg brings AF1 along its axis (through the pivot, L out from the root) and P1 across it at the footpad
    (rho down the leg): M = |r_pivot x AF1 e_leg + r_foot x P1 e_p|. Over 2,000 random swings (up to 30 deg) and
    side-force directions it never exceeds AF1 L + P1 (L + rho) (float rounding: 1e-12); at rest, an outward side
    force reaches AF1 L + P1 rho exactly (1e-12: two terms of one sign)."""
    rng = np.random.default_rng(43)
    L, rho, af1, p1 = 1.4, 1.6, 8000.0, 2828.0
    leg = TelescopingLeg(af1, 4000.0, 0.8, rho, 0.1, 0.05)
    arm_a, arm_p = outrigger_arms(L, leg)
    er = np.array([1.0, 0.0, 0.0])
    for _ in range(2000):
        tilt = rng.uniform(0, np.radians(30))
        az = rng.uniform(0, 2 * pi)
        e_leg = np.array([np.sin(tilt) * np.cos(az), np.sin(tilt) * np.sin(az), np.cos(tilt)])   # footpad to pivot
        e_p = _unit(np.cross(e_leg, rng.normal(size=3)))
        m = np.cross(L * er, af1 * e_leg) + np.cross(L * er - rho * e_leg, p1 * e_p)
        assert np.linalg.norm(m) <= (af1 * arm_a + p1 * arm_p) * (1 + 1e-12)
    at_rest = np.cross(L * er, af1 * np.array([0, 0, 1.0])) + np.cross(L * er - rho * np.array([0, 0, 1.0]),
                                                                       p1 * er)
    assert np.linalg.norm(at_rest) == pytest.approx(af1 * L + p1 * rho, rel=1e-12)


def test_lunar_outrigger_length_weight_and_loads():
    """The lunar example: legs at 2.4 m, body radius 1 m, so L = 1.4 m; the tube weighs rho pi (OD - t) t L (App. V);
    its loads are the App. III free body's AF1 = 8 kN (axial crush) and P1 = sqrt(2) AF2 a / rho =
    sqrt(2) 4 kN 0.8/1.6 = 2.828 kN, with arms L and L + rho = 3.0 m, and a fixed-free column of 2 L. 1e-12."""
    spec = read_lander(LUNAR).spec
    loads = run_loads(spec.loads)
    items = {i.name: with_loads(i, loads, str(LUNAR))[0] for i in spec.items}
    out = items["outrigger"]
    assert out.length == pytest.approx(1.4, rel=1e-12)
    rho_al = spec.materials["7178-t6"].density
    assert out.weight_each()[0] == pytest.approx(rho_al * pi * (0.150 - 0.003) * 0.003 * 1.4, rel=1e-12)
    combined = next(c for c in out.checks if c.kind == "combined")
    p1 = sqrt(2) * 4000 * 0.8 / 1.6
    assert combined.params["Mf"] == pytest.approx((8000, p1), rel=1e-12)
    assert combined.params["arm"] == pytest.approx((1.4, 3.0), rel=1e-12)
    assert combined.params["P"] == pytest.approx(p1, rel=1e-12)
    column = next(c for c in out.checks if c.kind == "column_buckling")
    assert column.params["L"] == pytest.approx(2.8, rel=1e-12)


def _lunar(edit) -> None:
    root = load_toml(LUNAR)
    edit(root.data)
    read_lander(LUNAR, root=root)


def test_an_attachment_outside_the_body_needs_its_outrigger():
    with pytest.raises(InputError, match="members.outrigger"):
        _lunar(lambda d: d["members"].pop("outrigger"))


def test_no_outrigger_without_a_body_radius_or_on_the_body():
    with pytest.raises(InputError, match="outrigger only"):
        _lunar(lambda d: d["structure"].pop("body_radius"))
    with pytest.raises(InputError, match="outrigger only"):
        _lunar(lambda d: d["structure"].update(body_radius="2.4 m"))


def test_a_stub_shorter_than_its_diameter_is_refused():
    """L = 2.4 - 2.3 = 0.1 m below the 150 mm tube: the beam formula's shear is no longer negligible."""
    with pytest.raises(InputError, match="outrigger's length"):
        _lunar(lambda d: d["structure"].update(body_radius="2.3 m"))


def _combined(moment_force, moment_arm):
    from alightsize.checks.rules import RULES
    from alightsize.common.config import Node
    from alightsize.model.materials import library
    from alightsize.pipeline.items import read_item
    data = {"name": "beam", "material": "7178-t6",
            "section": {"shape": "tube", "outside_diameter": "100 mm", "wall": "3 mm"},
            "check": [{"kind": "combined", "load": "1 kN", "moment_force": moment_force, "moment_arm": moment_arm}]}
    return read_item(Node("case.toml", "item[0]", data), library(), 1.2, RULES["current"])


def test_a_moment_of_several_force_arm_terms_adds_their_magnitudes():
    """M = |P1| l1 + |P2| l2 = 2 kN x 1 m + 3 kN x 0.5 m = 3.5 kN m (either sign of a force): exact in floats."""
    o = _combined(["2 kN", "-3 kN"], ["1 m", "0.5 m"]).evaluate()[0]
    assert next(s.value for s in o.steps if s.symbol == "M") == pytest.approx(3500.0, rel=1e-15)
    with pytest.raises(InputError, match="moment_arm"):
        _combined(["2 kN", "3 kN"], ["1 m"])
