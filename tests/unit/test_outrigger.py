"""The outrigger of a leg attached outside the body, telescoping and articulated: its length from the geometry,
its root moment bound against the statics of the leg's forces (r x F), its loads from the App. III free body or
envelopes, and the inputs refused."""

import subprocess
import sys
from math import hypot, pi, sqrt

import numpy as np
import pytest
from conftest import ROOT

from alightsize.common.config import load_toml
from alightsize.common.errors import InputError
from alightsize.loads.quasi_static import run_loads
from alightsize.loads.telescoping import TelescopingLeg
from alightsize.pipeline.items import with_loads
from alightsize.pipeline.lander import read_lander
from alightsize.pipeline.outrigger import articulated_reach, telescoping_outrigger
from alightsize_sim.articulated_cells import upper_angle
from alightsize_sim.articulated_kinematics import footpad
from alightsize_sim.articulated_statics import reactions

LUNAR = ROOT / "examples" / "lunar_lander.toml"
ARTICULATED = ROOT / "examples" / "affdl-tr-66-33" / "landers" / "articulated_3457.toml"
IN, FT = 0.0254, 0.3048


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
    (_, arm_a), (_, arm_p) = telescoping_outrigger(L, leg).moment
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


def test_a_stub_shorter_than_its_largest_gauge_is_refused():
    """Sized over gauges, the tube reaches its largest one: a 2 m gauge on L = 1.4 m is refused as a 2 m size max
    is (the smaller section alone would pass)."""
    gauges = {"dimension": "outside_diameter", "gauges": ["100 mm", "2 m"]}
    with pytest.raises(InputError, match="outrigger's length") as err:
        _lunar(lambda d: d["members"]["outrigger"].update(size=gauges))
    assert (err.value.key, err.value.found) == ("members.outrigger.section", "2 m")


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


def test_an_envelope_reference_in_a_force_array_is_named_by_its_element():
    """A reference table among moment_force's terms is read as written (no envelope looked up) and a bad key in it
    is named with the element's index."""
    with pytest.raises(InputError) as err:
        _combined(["2 kN", {"envelope": 34, "member": "PU1"}], ["1 m", "0.5 m"])
    assert (err.value.key, err.value.expected) == ('item[0].check["combined"].moment_force[1].envelope', "a string")
    force = _combined(["2 kN", {"envelope": "any", "member": "PU1"}], ["1 m", "0.5 m"]).checks[0].params["Mf"][1]
    assert force.key == 'item[0].check["combined"].moment_force[1]' and force.ref.envelope == "any"


# ------------------------------------------------------------------ articulated legs

def _articulated(structure: dict | None = None, members: dict | None = None):
    root = load_toml(ARTICULATED)
    root.data["structure"].update(structure or {})
    if members is not None:
        root.data["members"] = members
    return read_lander(ARTICULATED, root=root).spec


TUBE = {"material": "7178-t6", "section": {"shape": "tube", "outside_diameter": "4 in", "wall": "0.12 in"}}


def test_articulated_ground_force_is_the_resultant_of_the_attachment_forces_and_bounds_the_root_moment():
    """Configuration 5's leg (the example's geometry) at 2,000 random positions and cell forces. App. III's forces
    on the body, -(Q1 e_psi + RB e2) at the lower hinge, -(Q2 e_psi + RA e2) at the upper and AF1 e_eta at the
    upper cell's pivot (the cell stretched as psi rises), sum to the ground force F (massless leg; 1e-9 of |F|,
    round-off of eq. 96 found ~1e-15); their moments about the lower hinge match r_foot x F about S1 and S2 but
    not about S3 (the couple App. III's pinned trusses leave to the hinges), hence the outrigger's moment from F:
    |(L0 e1 + S') x F| <= |F| (L0 + reach) for a tube root L0 inboard of the hinge (rounding: 1e-12)."""
    g = _articulated().loads.cases[-1].geometry
    rng = np.random.default_rng(43)
    e1, e2 = np.eye(3)[0], np.eye(3)[1]
    up = np.array([-g.AD * np.sin(g.PHI), 0.0, g.AD * np.cos(g.PHI)])
    cell = np.array([g.AA, 0.0, g.AB])
    L0, reach = 0.4, articulated_reach(g)
    s3_miss = 0.0
    for _ in range(2000):
        a, b, p = rng.uniform(0.0, pi / 2), rng.uniform(-pi, pi), rng.uniform(-0.5, 0.6)
        af1, af2 = rng.uniform(0.0, 3e5, size=2)
        r = reactions(g, a, b, p, af1, af2)
        F = np.array([r.F1, r.F2, r.F3], float)
        e_psi = np.array([np.cos(p), 0.0, np.sin(p)])
        eta = upper_angle(g, p)
        lower, upper = -(r.Q1 * e_psi + r.RB * e2), -(r.Q2 * e_psi + r.RA * e2)
        af = af1 * np.array([np.cos(eta), 0.0, np.sin(eta)])
        assert np.linalg.norm(lower + upper + af - F) <= 1e-9 * np.linalg.norm(F)
        foot = np.array(footpad(g, a, b, p), float)
        moment = (np.cross(g.AU * e_psi, -r.RB * e2) + np.cross(up, -r.Q2 * e_psi)
                  + np.cross(up + g.AU * e_psi, -r.RA * e2) + np.cross(cell, af))
        miss = moment - np.cross(foot, F)
        assert np.all(np.abs(miss[:2]) <= 1e-9 * np.linalg.norm(F) * reach)
        s3_miss = max(s3_miss, abs(miss[2]) / (np.linalg.norm(F) * reach))
        assert np.linalg.norm(foot) <= reach
        root = np.linalg.norm(np.cross(L0 * e1 + foot, F))
        assert root <= np.linalg.norm(F) * (L0 + reach) * (1 + 1e-12)
    assert s3_miss > 0.01                 # the S3 couple is not round-off (measured 0.068 of |F| reach)


def test_articulated_outrigger_length_weight_and_loads():
    """Body radius 2.5 ft under the example's legs at 3.0 ft: the outermost attachment is the upper cell's pivot,
    AA = 5.2912 in out (the upper hinge -AD sin PHI = 24 sin 8.8768 deg = 3.70 in), so L = 6 + 5.2912 in; the moment
    arm is 6 in + AU + hypot(AO, AE) + AS + hypot(AS, AL) = 6 + 44 + 0.3054 + 8 + hypot(8, 25) in; the tube weighs
    rho pi (OD - t) t L (App. V); its load is the envelope's largest ground force |F|; column 2 L. 1e-12 (the
    radius 3.0 ft and the inch dimensions are exact in SI to rounding)."""
    spec = _articulated({"body_radius": "2.5 ft"}, {"outrigger": TUBE})
    loads = run_loads(spec.loads)
    items = {i.name: with_loads(i, loads, str(ARTICULATED))[0] for i in spec.items}
    out = items["outrigger"]
    L = (6 + 5.2912) * IN
    assert out.length == pytest.approx(L, rel=1e-12)
    rho_al = spec.materials["7178-t6"].density
    assert out.weight_each()[0] == pytest.approx(rho_al * pi * (4 - 0.12) * 0.12 * IN ** 2 * L, rel=1e-12)
    f = max(abs(e.value) for r in loads.envelopes["3457"] if r.member == "F" for e in (r.tension, r.compression) if e)
    combined = next(c for c in out.checks if c.kind == "combined")
    arm = (6 + 44 + hypot(0.3054, 0.0003) + 8 + hypot(8, 25)) * IN
    assert combined.params["P"] == pytest.approx(f, rel=1e-12)
    assert combined.params["Mf"] == pytest.approx((f,), rel=1e-12)
    assert combined.params["arm"] == pytest.approx((arm,), rel=1e-12)
    column = next(c for c in out.checks if c.kind == "column_buckling")
    assert column.params["L"] == pytest.approx(2 * L, rel=1e-12)


def test_articulated_outrigger_refusals():
    with pytest.raises(InputError, match="members.outrigger"):
        _articulated({"body_radius": "2.5 ft"})
    with pytest.raises(InputError, match="outrigger only"):
        _articulated(members={"outrigger": TUBE})
    with pytest.raises(InputError, match="outrigger only"):
        _articulated({"body_radius": "3.5 ft"}, {"outrigger": TUBE})     # every attachment on the body


def test_a_body_wall_between_the_hinges_exits_2_naming_the_key(tmp_path):
    """3.2 ft: outside the lower hinge (3.0 ft, the tube's tip) but inside the upper cell's pivot (3.44 ft)."""
    text = ARTICULATED.read_text()
    old = '[structure]\n'
    assert text.count(old) == 1
    path = tmp_path / "lander.toml"
    path.write_text(text.replace(old, old + 'body_radius = "3.2 ft"\n'))
    r = subprocess.run([sys.executable, "-m", "alightsize", "design", str(path), "--out", str(tmp_path / "out")],
                       capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 2, r.stderr
    assert "Traceback" not in r.stderr
    assert f"{path}: structure.body_radius: expected a body radius below the lower hinge" in r.stderr
