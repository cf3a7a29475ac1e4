"""The LM-class example (examples/lm_class.toml) reads to the gear it describes: four cantilever legs whose
footpads stand 31 ft (9.45 m) apart across the lander (NASA TN D-6850), in lunar gravity, with the knee where the
file puts it. Closed-form geometry from the file's radii and heights."""

import math

import numpy as np
import pytest

import alightsize
from alightsize_sim.tripod_leg import TripodLeg
from conftest import ROOT

LM = ROOT / "examples" / "lm_class.toml"
# Round-off of the parse and of the rotation to principal axes (a few ulps of metre-sized values).
RTOL = 1e-12


@pytest.fixture(scope="module")
def lander():
    return alightsize.read_lander(LM)


def test_four_cantilever_legs_with_the_lm_footpad_span(lander):
    legs = lander.scene.scene.legs
    assert len(legs) == 4 and all(isinstance(leg, TripodLeg) and leg.is_cantilever for leg in legs)
    pads = np.array([leg.footpad for leg in legs])
    # Footpads at 4.725 m from the roll axis, 90 deg apart: opposite ones 2 x 4.725 = 9.45 m (31 ft) apart,
    # neighbours 4.725 sqrt(2) m.
    np.testing.assert_allclose([np.linalg.norm(pads[0] - pads[2]), np.linalg.norm(pads[1] - pads[3])], 9.45,
                               rtol=RTOL)
    np.testing.assert_allclose(np.linalg.norm(pads - np.roll(pads, 1, axis=0), axis=1), 4.725 * math.sqrt(2),
                               rtol=RTOL)
    # TN D-6850's figures, to the file's rounding (9.45 m for 9.449 m, 0.94 m for 0.9398 m: below 3e-4).
    assert np.linalg.norm(pads[0] - pads[2]) == pytest.approx(31 * 0.3048, rel=1e-3)   # 31 ft
    assert all(leg.footpad_diameter == pytest.approx(37 * 0.0254, rel=1e-3) for leg in legs)   # 37 in


def test_the_primary_and_the_knee_where_the_file_puts_them(lander):
    leg = lander.scene.scene.legs[0]
    # Primary hardpoint (2.1 m out, 0.8 m up) to footpad (4.725 m out, 2.2 m down): hypot(2.625, 3.0) m.
    length = math.hypot(4.725 - 2.1, 0.8 + 2.2)
    assert leg.rest_primary_length == pytest.approx(length, rel=RTOL)
    # The knee 0.95 m up the primary from the footpad: a = L0 - 0.95 m from the hardpoint, above the primary
    # cartridge's 0.83 m curve (the cantilever's overhang strokes below the knee).
    assert leg.knee_offset == pytest.approx(length - 0.95, rel=RTOL)
    assert leg.primary.curve.deflection[-1] < 0.95
    # Each secondary: from its hardpoint (2.0 m out at +-35 deg, 1.0 m down) to the knee, in the leg's plane
    # at radius 4.725 - 0.95 (2.625 / L0) and height -2.2 + 0.95 (3.0 / L0).
    r, z = 4.725 - 0.95 * 2.625 / length, -2.2 + 0.95 * 3.0 / length
    h = np.array([2.0 * math.cos(math.radians(35)), 2.0 * math.sin(math.radians(35)), -1.0])
    np.testing.assert_allclose(leg.rest_lengths[1:], np.linalg.norm(h - [r, 0.0, z]), rtol=RTOL)


def test_lunar_gravity_and_the_lm_mass(lander):
    g = np.asarray(lander.scene.scene.gravity)
    assert np.linalg.norm(g) == pytest.approx(1.62, rel=RTOL)         # NASA Moon fact sheet, as gravity.py
    assert lander.scene.scene.mass == pytest.approx(7300.0, rel=RTOL)   # about 16,000 lb (7,257 kg)


def test_the_lm_sloped_envelope_and_its_2_ft_terrain(lander):
    # TN D-6850: 10 ft/s (3.048 m/s) down at rest to 7 ft/s (2.134 m/s) down at 4 ft/s (1.219 m/s) across, to the
    # file's rounding (3.05, 2.13, 1.22 m/s: to 0.01 m/s, so within 0.005); the speed corners are that region's 4
    # vertices (no landing at the box's 3.05 m/s down and 1.22 m/s across) and every Monte Carlo landing lies below
    # the limit (1e-12 m/s of round-off); the 2 ft (0.6096 m) rock lands the two vertices on the limit.
    def speed(r, i):
        return abs(float(r.overrides[f"initial.velocity[{i}]"].split()[0]))

    speeds = {(r.run_id.split("-")[1] if r.run_id.count("-") == 2 else "corner", speed(r, 1), speed(r, 2))
              for r in lander.study.runs if r.run_id.startswith("corner-")}
    assert {(h, v) for kind, h, v in speeds if kind == "corner"} == {(0.0, 0.3), (1.22, 0.3), (1.22, 2.13), (0.0, 3.05)}
    assert {(h, v) for kind, h, v in speeds if kind == "rock"} == {(1.22, 2.13), (0.0, 3.05)}
    assert (3.05, 2.13, 1.22) == pytest.approx((10 * 0.3048, 7 * 0.3048, 4 * 0.3048), abs=0.005)
    for r in lander.study.runs:
        if r.run_id.startswith("mc-"):
            h, v = speed(r, 1), speed(r, 2)
            assert 0 <= h <= 1.22 and 0.3 <= v <= 3.05 - (3.05 - 2.13) * h / 1.22 + 1e-12
    rocks = {r.overrides["terrain.rocks"][-1]["radius"] for r in lander.study.runs if "rock" in r.run_id}
    assert rocks == {"0.6096 m"}
