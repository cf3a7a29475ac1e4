"""Synthesis over a tripod leg's geometry: every tripod key of a lander file is a free parameter through the
scene-key overrides, and a candidate's geometry reaches the lander (closed form: the primary strut's length)."""

from __future__ import annotations

from math import hypot
from pathlib import Path

import numpy as np

from alightsize.pipeline.lander import read_lander
from alightsize.synthesis.spec import overrides, read_synthesis
from conftest import ROOT

EXAMPLE = ROOT / "examples" / "lunar_tripod.toml"

FREE = """
[synthesis]
[synthesis.free]
"legs.footpad_radius" = ["2.0 m", "3.0 m"]
"legs.radius" = ["0.8 m", "1.2 m"]
"legs.height" = ["0.2 m", "0.6 m"]
"legs.footpad_height" = ["-1.5 m", "-1.0 m"]
"legs.secondary_radius" = ["0.8 m", "1.2 m"]
"legs.secondary_height" = ["-0.6 m", "-0.2 m"]
"legs.secondary_half_angle" = ["25 deg", "45 deg"]
"legs.secondary_attach" = ["0 m", "0.1 m"]
"cells.primary.crush_force" = ["10 kN", "20 kN"]
"cells.primary.stroke" = ["0.4 m", "0.8 m"]
"cells.secondary_compression.crush_force" = ["8 kN", "16 kN"]
"cells.secondary_compression.stroke" = ["0.1 m", "0.2 m"]
"cells.secondary_tension.crush_force" = ["8 kN", "16 kN"]
"cells.secondary_tension.stroke" = ["0.1 m", "0.2 m"]
"""


def _file(tmp_path: Path) -> Path:
    text = EXAMPLE.read_text()
    if "[synthesis]" in text:                         # the example's own table replaced by every tripod key
        text = text[:text.index("[synthesis]")]
    path = tmp_path / "tripod.toml"
    path.write_text(text + FREE)
    return path


def test_free_tripod_keys_move_the_lander(tmp_path):
    path = _file(tmp_path)
    spec = read_synthesis(path)
    assert [p.key for p in spec.free] == [line.split('"')[1] for line in FREE.splitlines() if line.startswith('"')]
    x = [p.start for p in spec.free]
    x[0], x[1], x[3] = 2.8, 1.1, -1.4                 # footpad radius, primary hardpoint radius, footpad height
    x[7] = 1e-7                                       # next to the zero bound: below the parsers' 1e-6 m, reads 0
    leg = read_lander(path, overrides(spec.free, x)).scene.scene.legs[0]
    # Closed form: the primary runs from the hardpoint (radius 1.1 m, 0.4 m above the CG) to the footpad (radius
    # 2.8 m, 1.4 m below it) in the leg's vertical plane; round-off only (1e-12 m).
    length = float(np.linalg.norm(leg.footpad - leg.primary_hardpoint))
    assert abs(length - hypot(2.8 - 1.1, 0.4 + 1.4)) < 1e-12
    assert leg.secondary_attach == 0.0
