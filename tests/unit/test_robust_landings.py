"""No landing of valid input ends `failed` (the step size collapsing or switches looping at one instant): the
reported cases, and a seeded draw of the mixed robustness sweep (benchmarks/random_scenes.py). Each asserts the
outcome and the energy audit: work in = work out (kinetic and potential energy against cells, friction, soil and
what is left), closed within 1e-4 of the energy in; the integration error at these tolerances is 1e-6 to 1e-5
(docs/notes/simulator-log.md), so 1e-4 fails only on a term the audit does not account for."""

import dataclasses
import importlib.util

import pytest

from alightsize.common.resources import data_dir
from alightsize.landings.random_landings import random_landing
from alightsize.model.scene_config import read_scene
from alightsize.pipeline.lander import read_lander
from alightsize_sim.landing import simulate

EXAMPLES = data_dir("examples")
ROOT = EXAMPLES.parent if (EXAMPLES.parent / "benchmarks").is_dir() else None
CLOSURE = 1e-4


def _cases(lander, overrides, ids):
    study = read_lander(EXAMPLES / lander, overrides).spec.landings.study
    cases = [read_scene(r.scene, r.overrides) for r in study.runs if r.run_id in ids]
    assert len(cases) == len(ids)
    return cases


def _lands(cfg):
    res = simulate(cfg.scene, cfg.controls)
    assert res.status != "failed", f"{cfg.name}: failed at t = {res.t[-1]:.6g} s"
    assert res.energy["closure_rel"] < CLOSURE
    return res


@pytest.mark.parametrize("soil", ["dry-sand", "lunar-regolith"])
def test_non_slip_footpads_on_soil_land(soil):
    """The report's telescoping lander (non-slip friction 1.5e6) on soil with 5 lb, 1 ft footpads: corners 9
    and 12 failed (a friction limit of 1e6 FE3 taken literally at zero load; the soil's start to sink undone
    at the next step, 860 steps of 1e-9 s)."""
    over = {"legs.footpad_mass": "5 lb", "legs.footpad_diameter": "1 ft", "terrain.soil": soil}
    for cfg in _cases("affdl-tr-66-33/landers/telescoping.toml", over, {"corner-09", "corner-12"}):
        _lands(cfg)


def test_free_play_axial_cell_with_footpad_mass_lands():
    """The lunar example with 8 kg footpads and an axial cell carrying 1e-9 N over its first centimetre (the least
    force an input takes): corners 30 and 32 failed, two footpads starting and stopping a slide at one instant."""
    over = {"cells.axial.deflection": ["0 m", "0.01 m", "0.02 m", "0.45 m", "0.46 m"],
            "cells.axial.force": ["0 kN", "1e-12 kN", "8 kN", "8 kN", "40 kN"], "legs.footpad_mass": "8 kg",
            "requirements.monte_carlo.samples": 0, "controls.t_final": "2 s"}
    for cfg in _cases("lunar_lander.toml", over, {"corner-30", "corner-32"}):
        _lands(cfg)


def test_slides_stopped_by_an_empty_step_land():
    """Landing 870 of the configuration-1 sweep (benchmarks/random_scenes.py, seed 20261121; massless footpads,
    mu_D 0.70): legs 1 and 3 slid at their dynamic limit; an event at a step's start stopped both where their
    slides had ended, and each one's restart stopped the other's at t = 0.4995 s until the step size collapsed.
    It comes to rest (quiescence)."""
    cfg = read_scene(EXAMPLES / "affdl-tr-66-33" / "scenes" / "telescoping_config1.toml")
    scene = random_landing(cfg.scene, 20261121, 870)
    res = _lands(dataclasses.replace(cfg, scene=scene, controls=dataclasses.replace(cfg.controls, t_final=1.0)))
    assert res.status == "quiet"


def _sweep():
    spec = importlib.util.spec_from_file_location("random_scenes", ROOT / "benchmarks" / "random_scenes.py")
    sweep = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(sweep)
    return sweep


@pytest.mark.skipif(ROOT is None, reason="needs the repository's benchmarks/")
@pytest.mark.parametrize("k", [673, 1403, 1150, 549, 933])
def test_mixed_landings_that_failed_land(k):
    """Articulated landings of the mixed sweep that failed, run to 1 s: 673 (massless, 0.38 m/s^2, two rocks or
    steps: slides stopped by an empty step, then a leg caught on a step's face short of its set leaving at once),
    1403 and 1150 (massless, 2.5 and 8e-6 m/s^2), 549 (11 kg footpads on regolith, 2e-5 m/s^2), 933 (18 kg
    footpads, 8.1 m/s^2)."""
    r = _sweep().one(k, 1.0, former=False)
    assert r["kind"] == "articulated_1966"
    assert r["status"] != "failed" and r["finite"], f"landing {k}: {r}"
    assert r["closure_rel"] < CLOSURE


@pytest.mark.skipif(ROOT is None, reason="needs the repository's benchmarks/")
def test_seeded_mixed_landings_never_fail():
    """24 landings of the mixed sweep (leg kinds, footpad masses, soils, rocks and steps, gravity, drawn cell
    curves), 0.3 s each."""
    sweep = _sweep()
    for k in range(24):
        r = sweep.one(k, 0.3, former=False)
        assert r["status"] != "failed" and r["finite"], f"landing {k}: {r}"
        assert r["closure_rel"] < CLOSURE


@pytest.mark.skipif(ROOT is None, reason="needs the repository's benchmarks/")
@pytest.mark.parametrize("k", [874, 536, 450, 3437])
def test_footpad_lifted_on_a_rock_flank_closes(k):
    """Landings of the mixed sweep with footpads that have mass sliding up a rock's flank while their leg lifts
    them (fe3 < 0 with the leg still on the ground): the surface's normal force that balances the footpad across
    the plane was held at zero, so the lift fe3 u3 was missing from the footpad's energy; closure 2.3e-4, 1.9e-4,
    1.1e-4 and 7.4e-4 (874 and 3437 telescoping on the LM surface, 4.3 and 25 kg footpads; 536 articulated on
    rigid ground, 9.8 kg; 450 telescoping on regolith, 34 kg). Run to 1 s or their outcome."""
    r = _sweep().one(k, 1.0, former=False)
    assert r["footpad_mass"] > 0.0 and r["features"] > 0
    assert r["status"] != "failed" and r["finite"], f"landing {k}: {r}"
    assert r["closure_rel"] < CLOSURE
