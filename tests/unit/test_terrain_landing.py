"""Landings on terrain with steps and rocks (alightsize_sim.terrain in the step loop)."""

import dataclasses
import json

import numpy as np
import pytest

from alightsize.cli import main
from alightsize.common.errors import InputError
from alightsize.common.resources import data_dir
from alightsize.landings.random_landings import random_landing
from alightsize.model.scene_config import read_scene
import alightsize_sim.landing_kernel as lk
from alightsize_sim.landing import G0, _Run, initial_state, kinetic, simulate
from alightsize_sim.landing_kernel import FACE_GAP
from alightsize_sim.rigid_body import quat_matrix
from alightsize_sim.terrain import Box, Hemisphere, Step, Terrain, height, pack

SCENES = data_dir("examples") / "affdl-tr-66-33" / "scenes"
H = 0.05                                    # m: the step under leg 1 of the flat drop (footpad at x = 0.8 m)
STEP = Step(0.4, 0.0, -90.0, H)              # the edge at x = 0.4 m running -y: the side x > 0.4 m is raised


@pytest.fixture(scope="module")
def flat():
    return read_scene(SCENES / "flat_drop.toml")


def _lowered(scene, h):
    """The scene with leg 1's attachment lowered by h along the capsule's axis (the leg otherwise unchanged)."""
    legs = list(scene.legs)
    legs[0] = dataclasses.replace(legs[0], attach=legs[0].attach - h * scene.up)
    return dataclasses.replace(scene, legs=tuple(legs))


def test_a_step_under_one_leg_is_that_leg_lowered_on_flat_ground(flat):
    """Level drop (7 m/s, no slip) with a 5 cm step under leg 1: with the capsule's rotation suppressed
    (inertia x 1e9, so that the leg's geometry relative to the ground is the same in both), the landing equals
    the flat-ground drop with leg 1 lowered by 5 cm: peak XDD(3), the largest stroke and the final state to
    1e-6 (measured 1e-10; the two step sequences differ only through the round-off rotation). With its real
    inertia the capsule pitches and the two part (measured 1e-5 in peak, 7e-4 in stroke)."""
    stiff = dataclasses.replace(flat.scene, inertia=flat.scene.inertia * 1e9)
    on_step = simulate(dataclasses.replace(stiff, terrain=Terrain(steps=(STEP,))), flat.controls)
    lowered = simulate(_lowered(stiff, H), flat.controls)
    assert np.abs(on_step.accel_g[:, 2]).max() == pytest.approx(np.abs(lowered.accel_g[:, 2]).max(), rel=1e-6)
    assert on_step.memory[:, :, 0].max() == pytest.approx(lowered.memory[:, :, 0].max(), rel=1e-6)
    assert on_step.t[-1] == lowered.t[-1] == pytest.approx(flat.controls.t_final)
    assert np.abs(on_step.y[-1, :6] - lowered.y[-1, :6]).max() < 1e-6
    assert on_step.footpad[-1, 0, 2] == pytest.approx(H, abs=1e-15)     # held on the step's top


@pytest.mark.parametrize("rock, top", [(Box(0.8, 0.0, 0.4, 0.4, H), H), (Hemisphere(0.8, 0.0, 0.3), 0.3)])
def test_a_footpad_on_a_rock_lands_as_on_a_step_of_its_height(flat, rock, top):
    """A box under leg 1 and a hemisphere with its crown under it: held on the top, the footpad meets the same
    height as on a step of that height, so the landings are the same to round-off (1e-12; measured equal)."""
    kind = "boxes" if isinstance(rock, Box) else "hemispheres"
    on_rock = simulate(dataclasses.replace(flat.scene, terrain=Terrain(**{kind: (rock,)})), flat.controls)
    on_step = simulate(dataclasses.replace(flat.scene, terrain=Terrain(steps=(dataclasses.replace(STEP, height=top),))),
                       flat.controls)
    assert len(on_rock.t) == len(on_step.t)
    assert np.abs(on_rock.y - on_step.y).max() <= 1e-12
    assert on_rock.footpad[-1, 0, 2] == pytest.approx(top, abs=1e-15)


def test_slipping_footpads_on_rocks_and_steps_close_the_energy_balance():
    """Run 12101 (slipping into a 20 deg slope) with 5 lb footpads, a rock and a step within the leg span:
    every energy term is computed on its own (footpads with mass), and the audit closes below 1e-4."""
    cfg = read_scene(SCENES / "telescoping_config1_run12101.toml", {"legs.footpad_mass": "5 lb"})
    terrain = Terrain(steps=(Step(-0.5, 0.0, 90.0, 0.1),), hemispheres=(Hemisphere(0.9, 0.9, 0.25),))
    res = simulate(dataclasses.replace(cfg.scene, terrain=terrain), cfg.controls)
    assert res.status != "failed"
    assert res.energy["closure_rel"] < 1e-4


def test_scene_files_place_steps_rocks_and_a_height_field(tmp_path):
    """[terrain] steps, rocks and height_field with units; a bad rock is refused with its key path."""
    grid = tmp_path / "grid.csv"
    grid.write_text("0, 0.1\n0.2, 0.3\n")
    scene = tmp_path / "s.toml"
    scene.write_text(f'[scene]\nbase = "{SCENES / "flat_drop.toml"}"\n\n[terrain]\n'
                     'steps = [{ x = "1 ft", y = "0 ft", direction = "-90 deg", height = "2 in" }]\n'
                     'rocks = [{ shape = "hemisphere", x = "0.8 m", y = "0 m", radius = "10 cm" },\n'
                     '         { shape = "box", x = "-0.8 m", y = "0 m", length = "1 ft", width = "1 ft", '
                     'height = "3 in", yaw = "30 deg" }]\n'
                     'height_field = { file = "grid.csv", spacing = ["1 m", "2 m"], origin = ["5 m", "5 m"] }\n')
    t = read_scene(scene).scene.terrain
    assert dataclasses.astuple(t.steps[0]) == pytest.approx((0.3048, 0.0, -90.0, 0.0508), rel=1e-12)
    assert t.hemispheres == (Hemisphere(0.8, 0.0, 0.1),)
    assert t.boxes[0].yaw_deg == pytest.approx(30.0) and t.boxes[0].height == pytest.approx(0.0762)
    assert t.height_field.dx == 1.0 and t.height_field.dy == 2.0 and t.height_field.z[1, 1] == 0.3
    with pytest.raises(InputError, match=r"terrain\.rocks\[0\]\.radius"):
        read_scene(scene, {"terrain.rocks[0].radius": "-1 m"})
    with pytest.raises(InputError, match=r"terrain\.rocks\[1\]\.shape"):
        read_scene(scene, {"terrain.rocks[1].shape": "cone"})
    with pytest.raises(InputError, match=r"terrain\.height_field\.file"):
        read_scene(scene, {"terrain.height_field.file": "missing.csv"})


def test_simulate_names_the_features_each_leg_met_and_draws_the_footprints(tmp_path):
    """The shipped terrain example (the lunar lander on a rock under leg 1 and a step raising leg 3's side):
    summary.json lists per leg what its footpad met, and footprints.png is written."""
    example = data_dir("examples") / "terrain" / "lunar_rock_under_leg.toml"
    assert main(["simulate", str(example), "--out", str(tmp_path)]) == 0
    doc = json.loads((tmp_path / "summary.json").read_text())
    assert [leg["features"] for leg in doc["legs"]] == [["hemisphere rock 1"], ["plane"], ["step 1"], ["plane"]]
    assert doc["energy"]["closure_rel"] < 1e-4
    assert (tmp_path / "footprints.png").stat().st_size > 0


@pytest.mark.parametrize("mass", [0.0, 2.26796])
def test_a_footpad_swept_into_a_box_side_is_caught_on_the_face(mass):
    """Random landing 9 of the terrain sweep (configuration 1, mu_D 0.32, a 0.30 m box within the leg span): a footpad
    swept sideways into the box's side is caught on the face, more than FACE_GAP above the ground under it (the step
    loop's definition of meeting a face; 0.11 m measured), and held there; the landing runs to its outcome (it
    stalled and failed while footpads were put on the box's top) with the energy audit closed below 1e-4, massless
    and with 5 lb footpads."""
    base = read_scene(SCENES / "telescoping_config1.toml")
    scene = dataclasses.replace(random_landing(base.scene, 20261121, 9, True), footpad_mass=mass)
    res = simulate(scene, dataclasses.replace(base.controls, t_final=1.0))
    assert res.status != "failed" and res.energy["closure_rel"] < 1e-4
    packed = pack(scene.terrain)
    gaps = [res.footpad[k, i, 2] - height(packed, *res.footpad[k, i, :2]) for k, i in zip(*np.nonzero(res.contact))]
    assert max(gaps) > FACE_GAP


@pytest.mark.parametrize("k", [261, 405])
def test_a_free_footpad_swept_into_a_box_base_at_ground_level_is_caught_on_the_face(k):
    """Random landings 261 and 405 of the massless terrain sweep: a free footpad skimming the ground (unarmed,
    so it touches only BAND inside the surface) is swept into a box's base. Its clearance jumps there while the
    footpad is still above the lower ground, within FACE_GAP of it; put down on that ground it was beyond its
    leg's reach, left at once and touched again at the same instant (53,000 and 696,000 events until the
    watchdog failed the run). Caught on the face, the landings run to their outcome (157 and 383 events), and
    the energy audit closes below 1e-4."""
    base = read_scene(SCENES / "telescoping_config1.toml")
    scene = random_landing(base.scene, 20261121, k, True)
    res = simulate(scene, dataclasses.replace(base.controls, t_final=1.0))
    assert res.status != "failed" and res.energy["closure_rel"] < 1e-4


ROCK = 0.1                                  # m: radius of the rock under leg 1 (its height)


@pytest.mark.parametrize("offset", [0.0, 0.6, 0.98, 1.02], ids=["top", "flank", "edge", "off"])
@pytest.mark.parametrize("mass", [0.0, 2.26796], ids=["massless", "5 lb"])
def test_a_footpad_on_a_rocks_flank_slides_off_or_holds_and_the_body_stays_clear(flat, offset, mass):
    """The flat drop at 4 m/s down and 0.5 m/s toward leg 1, friction 0.5 / 0.3, with a 0.1 m rock whose centre is
    `offset` radii beyond leg 1's footpad (on its top, on its flank, at its edge, just off it), massless and 5 lb
    footpads. A footpad on the flank slides down it or is held as friction and its slope say, and never enters
    the rock or the ground: checked every 10 ms, each footpad on the ground is on or above the surface under it
    (1e-9 m: round-off of the relief's height; a massless one that touched again the grazing band past zero stays
    where its leg put it, within the band) and each free one above it (by the grazing band, where it touches).
    The landing settles (energy criterion) on all four legs. Energy rules out body contact: three legs stroking to
    the end of their 30 kN plateau take more work than the landing brings falling that far, and that fall is short
    of the body point's clearance over the rock (asserted from the scene's numbers), so the body cannot touch
    while the legs carry the capsule. Before, at the edge and just off, the footpad slid at its touchdown
    height into the rock's rising flank, its leg lifted off inside the rock and never touched again, and the
    capsule rolled onto its body at 1.4 s. Energy closes within 1e-6 for massless footpads (integration error
    only) and 1e-4 with mass (the bound of the footpad-mass tests above: their Karnopp band's transients), and the
    footpad-terrain interface takes energy, never gives it (within the closure)."""
    scene = dataclasses.replace(flat.scene, terrain=Terrain(hemispheres=(Hemisphere(0.8 + offset * ROCK, 0.0, ROCK),)),
                                mu_static=0.5, mu_dynamic=0.3, v0=np.array([0.5, 0.0, -4.0]), footpad_mass=mass,
                                body_points=np.array([[0.0, 0.0, -0.55]]))
    ctl = dataclasses.replace(flat.controls, t_final=1.5, rtol=1e-6, atol=1e-9, max_step=2e-3, energy_check_from=0.05)
    run = _Run(scene, ctl)
    y = initial_state(scene, run)
    packed = pack(scene.terrain)
    cell = scene.legs[0].axial.curve
    plateau, ramp, end = cell.force[2], cell.deflection[1], cell.deflection[2]
    # Three legs stroking to their plateau's end take more than the landing brings falling that far: the CG stops
    # short of it, above the fall that brings the body point (which tilting only raises) to the rock's height.
    assert 3 * plateau * (end - ramp) > kinetic(scene, y) + scene.mass * G0 * end and end < y[2] - 0.55 - ROCK
    t, status = 0.0, lk.END
    for stop in np.arange(0.01, ctl.t_final + 1e-9, 0.01):
        run.ctl_arr[lk.C_TFINAL] = stop
        status, t = run.loop(y, t)
        on = run.contact == 1
        gaps = run.P[:, 2] - np.array([height(packed, *p[:2]) for p in run.P])
        assert np.all(gaps[on] >= (-1e-9 if mass > 0.0 else -lk.BAND - 1e-9)), (t, gaps, run.contact)
        assert np.all(run.heights(y[0:3], quat_matrix(y[6:10]))[~on] >= -ctl.contact_band - 1e-9), t
        if status != lk.END:
            break
    assert status == lk.STABLE and np.all(run.contact == 1)
    res = simulate(scene, ctl)
    assert res.status == "stable" and np.all(res.contact[-1] == 1)
    assert res.energy["closure_rel"] < (1e-6 if mass == 0.0 else 1e-4)
    assert res.energy["friction_J"] >= -1e-6 * res.energy["initial_J"]
