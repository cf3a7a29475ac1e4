"""`[requirements.terrain]` of a lander file: the landing cases it adds (a rock under a footpad, a footpad into a
hole, landings on a soil) at the envelope's fastest corners, where they put the feature, and bad values."""

import numpy as np
import pytest

import alightsize
from alightsize.cli import main
from alightsize.common.errors import InputError
from alightsize.model.scene_config import read_scene
from alightsize.pipeline.lander import rest_footpad
from alightsize_sim.rigid_body import quat_matrix
from alightsize_sim.terrain import height, pack

from conftest import ROOT

LUNAR = ROOT / "examples" / "lunar_lander.toml"
TABLE = '[requirements.terrain]\nrock_height = "0.3 m"\nhole_depth = "0.2 m"\n'
MASSIVE_FEET = {'pads = "pad"\n': 'pads = "pad"\nfootpad_mass = "8 kg"\nfootpad_diameter = "0.6 m"\n'}


def variant(tmp_path, subs: dict, table: str = TABLE):
    text = LUNAR.read_text()
    text = text.split("[requirements.terrain]")[0] if "[requirements.terrain]" in text else text
    for old, new in subs.items():
        assert old in text, old
        text = text.replace(old, new)
    p = tmp_path / "lander.toml"
    p.write_text(text.replace("[requirements.monte_carlo]", table + "\n[requirements.monte_carlo]"))
    return p


def _without_terrain(tmp_path):
    return variant(tmp_path, {}, "")


def test_each_key_adds_the_fastest_corners_on_its_ground(tmp_path):
    # 32 corners, 16 of them at the largest descent speed (3 m/s): each key lands those 16 again.
    base = alightsize.read_lander(_without_terrain(tmp_path)).study.runs
    runs = alightsize.read_lander(variant(tmp_path, MASSIVE_FEET, TABLE + 'soil = "lunar-regolith"\n')).study.runs
    fast = [r for r in base if r.run_id.startswith("corner-") and r.overrides["initial.velocity[2]"] == "-3 m/s"]
    assert len(fast) == 16
    for kind, key in (("rock", "terrain.rocks"), ("hole", "terrain.steps"), ("soil", "terrain.soil")):
        added = [r for r in runs if r.run_id.startswith(f"corner-{kind}-")]
        assert [r.run_id.removeprefix(f"corner-{kind}-") for r in added] == [r.run_id.removeprefix("corner-")
                                                                           for r in fast]
        for a, f in zip(added, fast):
            assert {k: v for k, v in a.overrides.items() if k != key} == f.overrides
    assert len(runs) == len(base) + 3 * 16


def test_the_rock_is_under_leg_1_and_the_hole_takes_leg_1_only(tmp_path):
    # The scene the simulator starts from (read with the case's overrides): the terrain under leg 1's footpad,
    # placed by the initial attitude (roll, slope), is the rock's top (its radius, 0.3 m) or the hole's floor
    # (-0.2 m), and under every other footpad the plane (0): exact but for the rendering of positions to 12
    # digits (1e-9 m).
    runs = alightsize.read_lander(variant(tmp_path, {})).study.runs
    for r in runs:
        kind = r.run_id.split("-")[1]
        if kind not in ("rock", "hole"):
            continue
        cfg = read_scene(r.scene, r.overrides)
        R = quat_matrix(cfg.scene.q0)
        feet = [(R @ rest_footpad(leg))[:2] for leg in cfg.scene.legs]
        z = [height(pack(cfg.scene.terrain), x, y) for x, y in feet]
        assert z[0] == pytest.approx(0.3 if kind == "rock" else -0.2, abs=1e-9)
        assert np.allclose(z[1:], 0.0, atol=1e-9)


@pytest.mark.parametrize("table, key", [
    ('[requirements.terrain]\nrock_height = "-0.3 m"\n', "requirements.terrain.rock_height"),
    ('[requirements.terrain]\nhole_depth = "0.2 kg"\n', "requirements.terrain.hole_depth"),
    ('[requirements.terrain]\nhole_depth = 0.2\n', "requirements.terrain.hole_depth"),
    ('[requirements.terrain]\nsoil = "cheese"\n', "requirements.terrain.soil"),
    ('[requirements.terrain]\nsoil = "lunar-regolith"\n', "requirements.terrain.soil"),   # massless footpads
    ('[requirements.terrain]\nrock = "0.3 m"\n', "requirements.terrain.rock"),
    ('', "legs.pad_lever"),                  # with the substitution below: pads at the pivot carry no moment
])
def test_bad_values_exit_2_naming_the_key(tmp_path, capsys, table, key):
    p = variant(tmp_path, {'pad_lever = "0.8 m"': 'pad_lever = "0 m"'} if key == "legs.pad_lever" else {}, table)
    with pytest.raises(InputError) as err:
        alightsize.read_lander(p)
    assert key in str(err.value) and str(p) in str(err.value)
    assert main(["design", str(p), "--out", str(tmp_path / "o")]) == 2
    assert key in capsys.readouterr().err


SEARCH = """
[requirements.envelope]
vertical_speed = "3 m/s"

[requirements.terrain]
rock_height = "5 cm"
hole_depth = "5 cm"

[requirements.monte_carlo]
samples = 2
seed = 5

[synthesis]
seed = 11
generations = 0
population = 2
check_samples = 2

[synthesis.free]
"cells.axial.crush_force" = ["4 kN", "16 kN"]
"""


def test_synthesize_lands_the_terrain_cases_as_corners(tmp_path):
    # The search reads its candidates as lander files, so each candidate lands the envelope's 2 corners (one
    # descent speed, level, the roll at 0 and 45 deg) and their 2 rock and 2 hole repeats as its screening
    # corners before any Monte Carlo landing: the store holds as many rock as hole landings, 2 per candidate.
    import sqlite3
    from alightsize.synthesis.search import synthesize
    text = LUNAR.read_text()
    p = tmp_path / "small.toml"
    p.write_text(text[:text.index("[requirements.envelope]")].replace('t_final = "20 s"', 't_final = "3 s"') + SEARCH)
    synthesize(p, tmp_path / "o", trade=False, backend="serial")
    with sqlite3.connect(tmp_path / "o" / "runs.sqlite") as db:
        cols = [r[1] for r in db.execute("PRAGMA table_info(runs)")]
        rocks = db.execute("SELECT COUNT(*) FROM runs WHERE terrain_rocks_0 IS NOT NULL").fetchone()[0]
        holes = db.execute("SELECT COUNT(*) FROM runs WHERE terrain_steps_0 IS NOT NULL").fetchone()[0]
        plain = db.execute("SELECT COUNT(*) FROM runs WHERE terrain_rocks_0 IS NULL AND terrain_steps_0 IS NULL "
                           "AND run_id IS NOT NULL").fetchone()[0]
    assert "terrain_rocks_0" in cols and rocks > 0 and rocks % 2 == 0 and holes == rocks
    assert plain >= rocks                  # the open-ground corners of the same candidates, and Monte Carlo
