"""Footpads on soil in the step loop (footpad_mass with a soil): the closed-form sinking of a constant bearing
pressure, depth against work, energy closure, and the soil's place in scene files."""

import numpy as np
import pytest

from alightsize_sim.crush_cell import CellModel
from alightsize_sim.crush_curve import CrushCurve
from alightsize_sim.landing import Controls, Scene, simulate
from alightsize_sim.soil import Soil, sinkage_work
from alightsize_sim.telescoping_leg import TelescopingLeg

from alightsize.cli import main
from alightsize.common.resources import data_dir
from alightsize.model.scene_config import read_scene
from alightsize.model.soils import soil_presets

G = 9.80665
MASS, V, PAD_MASS, DIAMETER = 1000.0, 3.0, 10.0, 0.5
F_CELL = 20e3                                                   # N: the axial cells crush at this from 0
P0 = 50e3                                                       # Pa: the soil's constant bearing pressure
AREA = np.pi * DIAMETER ** 2 / 4
CTL = Controls(t_final=1.0, rtol=1e-10, atol=1e-12, event_tol=1e-12)
EXAMPLES = data_dir("examples")


def _scene(soil, v0=(0.0, 0.0, -V)):
    """Four legs hanging straight down, each an axial cell of constant crushing force (no pads, no damper)."""
    cell = CellModel(CrushCurve((0.0, 0.5), (F_CELL, F_CELL)), 1e8)
    legs = tuple(TelescopingLeg(np.array([np.cos(a), np.sin(a), 0.0]), np.eye(3), 1.0, 0.0, (), cell, ())
                 for a in np.arange(4) * np.pi / 2)
    return Scene(MASS, np.array([400.0, 400.0, 300.0]), legs, np.array([0.0, 0.0, -G]), np.array(v0, float),
                 np.array([1.0, 0, 0, 0]), np.zeros(3), 0.8, 0.6, footpad_mass=PAD_MASS, soil=soil,
                 footpad_diameter=DIAMETER)


def test_a_pad_sinks_into_constant_bearing_pressure_as_the_closed_form():
    """Phase one of a level drop onto soil of constant bearing pressure p0: each cell crushes at F_c > p0 A, so
    the footpad sinks from rest at a_p = (F_c - p0 A) / m while the capsule's quarter M/4 slows at
    a_c = 4 F_c / M - g; the cell turns when they move together, t1 = V / (a_c + a_p), at the stroke V t1 / 2
    and the sinkage a_p t1^2 / 2 (its first turn; the stiff unloading spring rings after it). Both to 1e-6
    (the turn is a located event, event_tol 1e-12 s)."""
    res = simulate(_scene(Soil.rigid_plastic(P0)), CTL)
    a_p, a_c = (F_CELL - P0 * AREA) / PAD_MASS, 4 * F_CELL / MASS - G
    t1 = V / (a_c + a_p)
    stroke = res.deflections[:, 0, 0]
    k = int(np.argmax(np.diff(stroke) < 0))                                     # the first turn
    assert res.t[k] == pytest.approx(t1, rel=1e-6)
    assert res.deflections[k, 0, 0] == pytest.approx(0.5 * V * t1, rel=1e-6)
    assert -res.footpad[k, :, 2] == pytest.approx(np.full(4, 0.5 * a_p * t1 ** 2), rel=1e-6)


@pytest.mark.parametrize("soil", [Soil.rigid_plastic(P0), soil_presets()["lunar-regolith"]],
                         ids=["constant", "bekker"])
def test_a_pad_stops_where_the_soil_work_equals_its_energy_and_energy_closes(soil):
    """At rest, the footpads' depths are those at which the soil's work equals the energy it took: the sum of
    sinkage_work (closed form, A (k_c/b + k_phi) s^(n+1)/(n+1), b the pad's radius) over the four final depths
    equals the soil's work integrated with the state from its power R(s) w, to 1e-6. The stiff legs ring, so each
    footpad leaves and re-enters its hole many times: the legs, identical, are switched one per step when they cross
    together, which parts their depths by up to 1e-3. The energy audit closes to 1e-6 at rtol 1e-10."""
    res = simulate(_scene(soil), CTL)
    assert res.status in ("stable", "end")
    depth = -res.footpad[-1, :, 2]
    assert depth == pytest.approx(np.full(4, depth.mean()), rel=1e-3)
    work = sum(sinkage_work(soil.packed, AREA, DIAMETER / 2, s) for s in depth)
    assert work == pytest.approx(res.energy["soil_J"], rel=1e-6)
    assert res.energy["soil_J"] > 0.3 * res.energy["initial_J"]
    assert res.energy["closure_rel"] < 1e-6


@pytest.mark.parametrize("legs, soil, key, expected", [
    ('footpad_diameter = "0.6 m"', '"lunar-regolith"', "terrain.soil", "footpads with mass"),
    ('footpad_mass = "8 kg"', '"lunar-regolith"', "terrain.soil", "footpad_diameter"),
    ('footpad_mass = "8 kg"\nfootpad_diameter = "0.6 m"', '"moon-dust"', "terrain.soil", "lunar-regolith"),
    ('footpad_mass = "8 kg"\nfootpad_diameter = "-0.6 m"', '"lunar-regolith"', "legs.footpad_diameter", "positive")])
def test_bad_soil_input_exits_2_naming_the_key(tmp_path, capsys, legs, soil, key, expected):
    """A soil needs footpads with mass and a diameter, and a soil that exists; each fault exits 2 naming the file,
    the key and what was expected, with no traceback and no output."""
    bad = tmp_path / "bad.toml"
    bad.write_text(f'[scene]\nbase = "{EXAMPLES}/lunar_lander.toml"\nname = "bad"\n\n[legs]\n{legs}\n\n'
                   f'[terrain]\nsoil = {soil}\n')
    assert main(["simulate", str(bad), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert str(bad) in err and key in err and expected in err and "Traceback" not in err
    assert not (tmp_path / "o").exists()


def test_a_scene_reads_a_soil_file_of_its_own(tmp_path):
    """`soil` also takes a soil file's path, relative to the scene: read in SI like the presets."""
    (tmp_path / "clay.toml").write_text('name = "stiff clay"\nn = 0.0\nk_c = "0 N/m^(n+1)"\nk_phi = "150 kN/m^(n+2)"\n'
                                        'c = "20 kPa"\nphi = "5 deg"\ngamma = "18 kN/m^3"\n')
    scene = tmp_path / "clay_landing.toml"
    scene.write_text(f'[scene]\nbase = "{EXAMPLES}/terrain/lunar_regolith.toml"\nname = "clay"\n\n'
                     '[terrain]\nsoil = "clay.toml"\n')
    soil = read_scene(scene).scene.soil
    assert (soil.name, soil.n, soil.k_phi, soil.c, soil.gamma) == ("stiff clay", 0.0, 150e3, 20e3, 18e3)
