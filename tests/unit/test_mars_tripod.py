"""examples/mars_tripod.toml reads as a three-legged lander under Mars gravity, its legs evenly spaced."""

from __future__ import annotations

from math import atan2, degrees

import numpy as np
import pytest

from alightsize.pipeline.lander import read_lander
from conftest import ROOT


def test_mars_tripod_reads_three_legs_in_mars_gravity():
    scene = read_lander(ROOT / "examples" / "mars_tripod.toml").scene.scene
    assert len(scene.legs) == 3
    # NASA Mars fact sheet: 3.71 m/s^2, the value `gravity = "mars"` stands for; exact as parsed (round-off only).
    assert scene.gravity == pytest.approx([0.0, 0.0, -3.71], abs=1e-12)
    # Evenly spaced: footpads 120 deg apart about the roll axis, all 1.8 m out (round-off only).
    feet = np.array([leg.footpad for leg in scene.legs])
    azimuths = sorted(degrees(atan2(y, x)) % 360 for x, y, _ in feet)
    assert np.diff(azimuths) == pytest.approx([120.0, 120.0], abs=1e-9)
    assert np.hypot(feet[:, 0], feet[:, 1]) == pytest.approx([1.8] * 3, abs=1e-12)
