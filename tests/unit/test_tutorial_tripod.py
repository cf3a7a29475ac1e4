"""The tripod lander docs/tutorial.md builds from an empty file reads as the tutorial says: four inverted
tripods, footpads 4.8 m apart across the lander, primaries hypot(1.4, 1.6) m long (closed-form geometry)."""

import math
import re

import numpy as np

import alightsize
from alightsize_sim.tripod_leg import TripodLeg
from conftest import ROOT

SECTION = "## Tripod and cantilever legs from an empty file"


def _tutorial_file() -> str:
    text = (ROOT / "docs" / "tutorial.md").read_text()
    blocks = re.findall(r"```toml\n(.*?)```", text.split(SECTION, 1)[1], flags=re.S)
    assert len(blocks) == 1                           # the section shows one file, whole
    return blocks[0]


def test_the_tutorial_tripod_lander_reads_to_the_legs_it_describes(tmp_path):
    path = tmp_path / "tripod.toml"
    path.write_text(_tutorial_file())
    lander = alightsize.read_lander(path)
    legs = lander.scene.scene.legs
    assert len(legs) == 4 and all(isinstance(leg, TripodLeg) and not leg.is_cantilever for leg in legs)
    pads = np.array([leg.footpad for leg in legs])
    # Footpads 2.4 m out and 1.6 m below the hardpoints (1.0 m out): 2 x 2.4 m apart across the lander, the
    # primary hypot(2.4 - 1.0, 0.4 + 1.2) long. 1e-12: round-off of the parse and the rotation to principal axes.
    np.testing.assert_allclose(np.linalg.norm(pads[0] - pads[2]), 4.8, rtol=1e-12)
    np.testing.assert_allclose([leg.rest_primary_length for leg in legs], math.hypot(1.4, 1.6), rtol=1e-12)
    np.testing.assert_allclose(np.linalg.norm(lander.scene.scene.gravity), 1.62, rtol=1e-12)   # "moon"
