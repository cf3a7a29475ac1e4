"""Tripod legs in scene and lander files: the example reads to the legs it describes, bad values exit 2 naming the
key, and `design` refuses a tripod lander (its members are not derived yet) naming legs.kind."""

import numpy as np
import pytest

from alightsize.common.errors import InputError
from alightsize.model.scene_config import read_scene
from alightsize.pipeline.lander import read_lander
from alightsize_sim.tripod_leg import TripodLeg
from conftest import ROOT

TRIPOD = ROOT / "examples" / "lunar_tripod.toml"


def test_the_example_reads_to_four_inverted_tripods_at_the_radii_it_gives():
    """Footpads 2.4 m from the roll axis and 1.6 m below the primary hardpoints, 90 deg apart, as written (the
    rotation to principal axes keeps distances: |P - A| = hypot(1.4, 1.6) m)."""
    cfg = read_scene(TRIPOD)
    legs = cfg.scene.legs
    assert len(legs) == 4 and all(isinstance(leg, TripodLeg) and not leg.is_cantilever for leg in legs)
    np.testing.assert_allclose([leg.rest_primary_length for leg in legs], np.hypot(1.4, 1.6), rtol=1e-12)
    pads = np.array([leg.footpad for leg in legs])
    np.testing.assert_allclose(np.linalg.norm(pads[0] - pads[2]), 4.8, rtol=1e-12)     # across the footpads
    assert cfg.cell_names[0] == ("primary", "secondary1_compression", "secondary1_tension", "secondary2_compression",
                                 "secondary2_tension")


@pytest.mark.parametrize("key, value, named", [
    ("legs.count", 9, "legs.count"),
    ("legs.count", 2, "legs.count"),
    ("legs.secondary_half_angle", "190 deg", "legs.secondary_half_angle"),
    ("legs.secondary_half_angle", "0 deg", "legs.secondary_half_angle"),
    ("legs.footpad_height", "0.5 m", "legs.footpad_height"),
    ("legs.footpad_diameter", "0 m", "legs.footpad_diameter"),
    ("legs.footpad_radius", "-1 m", "legs.footpad_radius"),
    ("legs.secondary_attach", "3 m", "legs.secondary_attach"),       # past the primary's 2.13 m
    ("legs.secondary_attach", "0.3 m", "legs.secondary_attach"),     # a knee the primary's 0.61 m curve strokes past
    ("legs.secondary_half_angle", "0.5 deg", "legs.secondary_half_angle"),   # struts nearly coplanar at the footpad
    ("legs.primary", "none", "legs.primary"),
    ("legs.azimuths", ["0 deg", "90 deg"], "legs.azimuths"),
    ("legs.cell_factors", [[1, 1, 1, 1, 1]], "legs.cell_factors"),
])
def test_a_bad_tripod_value_exits_2_naming_its_key(key, value, named):
    with pytest.raises(InputError) as err:
        read_scene(TRIPOD, {key: value})
    assert err.value.key.startswith(named)


def test_given_azimuths_place_the_legs():
    """Three legs at 0, 100 and 220 deg: the angles between their footpads about the roll axis (turned into
    principal axes with the footpads) are 100, 120 and 140 deg."""
    cfg = read_scene(TRIPOD, {"legs.azimuths": ["0 deg", "100 deg", "220 deg"], "legs.count": 3})
    legs = cfg.scene.legs
    axis = cfg.to_geometric.T @ np.array([0.0, 0.0, 1.0])
    pads = [leg.footpad - (leg.footpad @ axis) * axis for leg in legs]
    angles = [np.degrees(np.arccos(pads[i] @ pads[j] / np.linalg.norm(pads[i]) / np.linalg.norm(pads[j])))
              for i, j in ((0, 1), (1, 2), (2, 0))]
    np.testing.assert_allclose(angles, [100.0, 120.0, 140.0], rtol=1e-12)


def test_design_refuses_a_tripod_lander_naming_the_leg_kind():
    with pytest.raises(InputError) as err:
        read_lander(TRIPOD)
    assert err.value.key == "legs.kind" and err.value.found == "tripod"


def test_massless_tripod_footpads_are_refused_where_they_can_slip():
    """Held footpads (the default friction, 1.5e6) may be massless; on ground with friction below 1,000 a tripod's
    footpads need a mass (docs/simulator.md: their massless slide does not converge)."""
    assert read_scene(TRIPOD, {"legs.footpad_mass": "0 kg"}).scene.footpad_mass == 0.0
    with pytest.raises(InputError) as err:
        read_scene(TRIPOD, {"legs.footpad_mass": "0 kg", "terrain.mu_static": 0.4, "terrain.mu_dynamic": 0.4})
    assert err.value.key == "legs.footpad_mass"
