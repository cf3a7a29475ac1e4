"""Lander files: one file from which the scene, the App. III envelopes, the landing cases and the member checks
derive (alightsize.pipeline.lander), on the shipped lunar example."""

import json
import re
import subprocess
import sys
from math import pi, sqrt
from pathlib import Path

import numpy as np
import pytest

import alightsize
from alightsize.cli import main
from alightsize.common.errors import InputError
from alightsize.pipeline.config import prepare
from alightsize.pipeline.design import run_design
from conftest import ROOT

LUNAR = ROOT / "examples" / "lunar_lander.toml"
FEW = {"samples = 100": "samples = 4"}           # the 16 envelope corners and 4 Monte Carlo landings


def variant(tmp_path: Path, subs: dict, name: str = "lander.toml") -> Path:
    text = LUNAR.read_text()
    for old, new in subs.items():
        assert old in text, old
        text = text.replace(old, new)
    p = tmp_path / name
    p.write_text(text)
    return p


@pytest.fixture(scope="module")
def lunar(tmp_path_factory):
    path = variant(tmp_path_factory.mktemp("lunar"), FEW)
    return run_design(alightsize.read_lander(path).spec)


def test_reading_runs_nothing_and_derives_the_cases():
    """read_lander only reads: 16 corners (2 horizontal speeds x 2 rolls x 2 slopes x 2 frictions x 1 vertical
    range of 2) + 100 Monte Carlo landings, and the App. III free body from the lander's own cells."""
    lander = alightsize.read_lander(LUNAR)
    assert len(lander.study.runs) == 2 * 2 * 2 * 2 * 2 + 100
    leg = lander.spec.loads.telescoping
    assert (leg.axial_crush, leg.rotational_crush, leg.pad_lever, leg.length) == (8000.0, 4000.0, 0.8, 1.6)
    assert lander.scene.scene.gravity[2] == pytest.approx(-1.62)     # NASA lunar fact sheet, level nominal scene


def test_signed_envelope_lands_into_the_slope_only(tmp_path):
    """A signed slope range [-12, 0] deg gives corners at its two ends and Monte Carlo slopes inside it, and a
    heading range bounds every sampled heading (the draws are uniform, so 100 of them reach both halves)."""
    p = variant(tmp_path, {'slope = "12 deg"': 'slope = ["-12 deg", "0 deg"]\nheading = ["-20 deg", "20 deg"]'})
    runs = alightsize.read_lander(p).study.runs
    corners = {r.overrides["terrain.slope"] for r in runs if r.run_id.startswith("corner-")}
    assert corners == {"-12 deg", "0 deg"}
    mc = [r.overrides for r in runs if not r.run_id.startswith("corner-")]
    slopes = [float(o["terrain.slope"].split()[0]) for o in mc]
    headings = [float(o["initial.heading"].split()[0]) for o in mc]
    assert len(mc) == 100 and -12 <= min(slopes) and max(slopes) <= 0 and min(slopes) < -6 < max(slopes)
    assert -20 <= min(headings) < 0 < max(headings) <= 20


def test_derived_column_is_the_leg_and_johnson_or_euler_applies(lunar):
    """The lower tube's column length is the leg's rho (1.6 m); its critical stress is Euler's pi^2 E/(L/k)^2 or
    Johnson's parabola by the transition slenderness pi sqrt(2E/Fcy) (closed forms, to 1e-12)."""
    rec = next(r for r in lunar.records if r.item.name == "lower_tube" and r.outcome.mode == "column_buckling")
    item = rec.item
    a, i = item.section.area(), item.section.inertia()
    k = sqrt(i / a)
    e, fy = item.material.elastic_modulus, item.material.yield_strength
    lk = 1.6 / k
    expected = pi ** 2 * e / lk ** 2 if lk >= pi * sqrt(2 * e / fy) else fy - (fy / (2 * pi)) ** 2 * lk ** 2 / e
    assert rec.outcome.allowable == pytest.approx(expected, rel=1e-12)
    assert any("Euler" in s.label or "Johnson" in s.label for s in rec.outcome.steps)


def test_every_member_sized_to_its_factor_and_ms_given(lunar):
    """Members marked for sizing meet 1.25 (bisection to 1e-9, so f within 1e-6 of 1.25 unless the lower bound
    governs); every check has MS = f / 1.25 - 1."""
    for s in lunar.sizings:
        assert s.feasible and s.factor_sized >= 1.25
        assert s.factor_sized == pytest.approx(1.25, rel=1e-6) or s.sized == pytest.approx(0.004)
    for r in lunar.records:
        assert r.margin == pytest.approx(r.outcome.factor / 1.25 - 1, rel=1e-12)


def test_swivel_pin_bears_on_its_lug_with_the_load_its_shear_takes(lunar):
    """The swivel pin's bearing takes the resultant of AF1 and P2, as its shear does, and is judged on the weaker
    of the pin's 4130 steel (180 ksi) and the lug's 7178-T6 (69 ksi): the lug's yield, exactly."""
    recs = {r.outcome.mode: r.outcome for r in lunar.records if r.item.name == "swivel_pin"}
    lug = alightsize.read_lander(LUNAR).spec.materials["7178-t6"]
    assert recs["bearing"].load == recs["shear"].load
    assert recs["bearing"].allowable == lug.yield_strength


def test_level_drop_of_the_example_matches_its_closed_form():
    """The example itself (1,500 kg, four vertical legs, the moon's 1.62 m/s^2) dropped level at 3 m/s with its
    dampers off: each axial cell takes a quarter of the load, so the largest stroke d closes the energy balance
    m v^2 / 2 + m g d = 4 (F r / 2 + F (d - r)) on the cell's ramp r = 0.01 m and plateau F = 8 kN, i.e.
    d = (m v^2 / 2 + 2 F r) / (4 F - m g) = 0.233683 m. Hermite peak of an rtol 1e-10 run: within 1e-6."""
    from alightsize.model.scene_config import read_scene
    from alightsize_sim.landing import simulate
    from test_landing import _hermite_peak
    cfg = read_scene(LUNAR, {"terrain.slope": "0 deg", "initial.velocity[1]": "0 m/s", "initial.velocity[2]": "-3 m/s",
                             "cells.axial.damping": "0 N*s/m", "cells.pad.damping": "0 N*s/m",
                             "controls.t_final": "0.2 s", "controls.rtol": 1e-10, "controls.atol": 1e-12,
                             "controls.max_step": "1 ms"})
    m, g, f, r = 1500.0, 1.62, 8000.0, 0.01
    assert cfg.scene.gravity[2] == pytest.approx(-g, abs=1e-15)
    res = simulate(cfg.scene, cfg.controls)
    stroke = res.y[0, 2] - res.y[:, 2]
    x_max, _ = _hermite_peak(res.t, stroke, -res.y[:, 5])
    exact = (0.5 * m * 3.0 ** 2 + 2 * f * r) / (4 * f - m * g)
    assert exact == pytest.approx(0.233683, abs=1e-6)
    assert abs(x_max - exact) / exact < 1e-6
    assert np.nanmax(np.abs(res.deflections[:, :, 0] - stroke[:, None])) < 1e-9     # every leg strokes with the CG


def test_landing_energy_closes(lunar):
    """Every landing that ends settled closes its energy balance to 1e-3 (the simulator's tolerance class)."""
    rows = [r for r in lunar.config.landings.rows if r["outcome"] == "stable"]
    assert rows
    assert max(r["closure_rel"] for r in rows) < 1e-3


def test_landing_member_loads_reach_the_checks(lunar):
    """AF1 of the checks is the larger of the App. III crush load (8 kN) and the landings' peak axial force,
    and the report says which landing when one governs."""
    peak = max(d["tension_N"] or 0.0 for r in lunar.config.landings.rows
               for d in json.loads(r["member_loads_json"]) if d["member"] == "AF1")
    assert lunar.config.loads.telescoping["AF1"] == pytest.approx(max(8000.0, peak), rel=1e-12)


def test_interface_loads_are_each_hardpoints_largest_over_the_landings(lunar):
    """The design's interface loads: one row per leg and hardpoint (pivot, pads of four legs), each the largest
    force any landing stored for it, named by that landing, its magnitude the norm of its components (1e-12
    relative: the same float64 numbers), and summary.json carries the same table."""
    table = lunar.to_pandas()["interface_loads"]
    assert list(zip(table.leg, table.hardpoint)) == [(i, h) for i in (1, 2, 3, 4) for h in ("pivot", "pads")]
    stored = {}
    for r in lunar.config.landings.rows:
        for d in json.loads(r["interface_loads_json"]):
            key = (d["leg"], d["hardpoint"])
            stored[key] = max(stored.get(key, (0.0, "")), (d["force_N"], r["run_id"]), key=lambda v: v[0])
    for row in table.itertuples():
        assert (row.force_N, row.run_id) == stored[(row.leg, row.hardpoint)]
        assert row.force_N == pytest.approx(np.linalg.norm([row.force_1_N, row.force_2_N, row.force_3_N]), rel=1e-12)
    from alightsize.reports.design_report import summary_json
    assert summary_json(lunar)["interface_loads"] == table.to_dict("records")


def test_crushing_force_change_reaches_landings_envelopes_and_checks(tmp_path):
    """One edit of the axial cell's crushing force changes the landings, the App. III envelope and the checks
    in a single run."""
    def run(force):
        p = variant(tmp_path, {**FEW, '"8 kN", "8 kN"': f'"{force} kN", "{force} kN"'}, f"l{force}.toml")
        return run_design(prepare(alightsize.read_lander(p).spec))
    a, b = run(8), run(10)
    assert b.config.loads.config.telescoping.axial_crush == 10000.0
    assert [r["peak_xdd3_g"] for r in a.config.landings.rows] != [r["peak_xdd3_g"] for r in b.config.landings.rows]
    fa = {(r.item.name, r.outcome.mode): r.outcome.factor for r in a.records}
    fb = {(r.item.name, r.outcome.mode): r.outcome.factor for r in b.records}
    assert fa[("axial_cap", "plate_bending")] != fb[("axial_cap", "plate_bending")]


@pytest.mark.parametrize("subs, key", [
    ({'gravity = "moon"': 'gravity = "pluto"'}, "lander.gravity"),
    ({"[members.swivel_pin]": "[members.swivel]"}, "members.swivel"),
    ({', lug_material = "7178-t6" }': " }"}, "members.swivel_pin.pin.lug_material"),
    ({"lug_thickness": "lug_thicknes"}, "members.swivel_pin.pin.lug_thicknes"),
    ({'vertical_speed = ["1 m/s", "3 m/s"]': 'vertical_speed = ["3 m/s", "1 m/s"]'},
     "requirements.envelope.vertical_speed"),
    ({'load_radius = "10 mm"': 'load_radius = "10 kg"'}, "members.axial_cap.load_radius:"),   # as written
    ({'load_radius = "10 mm"': 'load_radius = "10 mm"\nrole = "rod"'}, "members.axial_cap.role:"),   # not ignored
    ({'[members.upper_tube]\n': '[members.upper_tube]\ncolumn_length = "1 m"\n'}, "members.upper_tube.column_length:"),
    ({"[structure]\n": "[structure]\nbearing = 1\n"}, "structure"),
    ({'slope = "12 deg"': 'slope = ["0 deg", "-12 deg"]'}, "requirements.envelope.slope"),
    # a scatter whose normal force factors go negative (runs that cannot start): refused as read, not as run
    ({"cell_scatter = 0.05": "cell_scatter = 5e10"}, "requirements.monte_carlo.cell_scatter"),
])
def test_bad_lander_file_exits_2_naming_the_key(tmp_path, capsys, subs, key):
    p = variant(tmp_path, subs)
    with pytest.raises(InputError) as err:
        alightsize.read_lander(p)
    assert key in str(err.value) and str(p) in str(err.value)
    assert main(["design", str(p), "--out", str(tmp_path / "o")]) == 2        # the command line, in process
    err = capsys.readouterr().err
    assert "Traceback" not in err and key in err


@pytest.mark.parametrize("subs, key", [
    ({"required_design_factor = 1.25": "required_design_factor = 0.5"}, "requirements.required_design_factor"),
    ({'[members.upper_tube]\n': '[members.upper_tube]\nrequired_design_factor = 0.8\n'},
     "members.upper_tube.required_design_factor"),
])
def test_a_required_factor_below_one_is_refused_without_its_override(tmp_path, subs, key):
    """Below 1 a member passes above its allowable: refused naming the key, read with allow_below_one = true
    beside it (the factor then reaches the items as written: 0.5 for every item, or 0.8 for the one member;
    prepared without landings, which play no part here)."""
    from dataclasses import replace
    with pytest.raises(InputError) as err:
        alightsize.read_lander(variant(tmp_path, subs))
    assert key in str(err.value) and "allow_below_one" in str(err.value)
    ((old, new),) = subs.items()
    spec = alightsize.read_lander(variant(tmp_path, {old: new + "\nallow_below_one = true\n"}, "ok.toml")).spec
    required = {i.name: i.required for i in prepare(replace(spec, landings=None)).items}
    if key.startswith("requirements"):
        assert set(required.values()) == {0.5}
    else:
        assert required.pop("upper_tube") == 0.8 and set(required.values()) == {1.25}


def test_cli_design_prints_a_one_screen_summary(tmp_path):
    p = variant(tmp_path, FEW)
    out = subprocess.run([sys.executable, "-m", "alightsize", "design", str(p), "--out", str(tmp_path / "o")],
                         capture_output=True, text=True)
    assert out.returncode == 0, out.stdout + out.stderr          # the shipped design meets its requirements
    head = out.stdout.splitlines()
    assert re.match(r"lunar_lander: PASS: ", head[0])
    summary = json.loads((tmp_path / "o" / "summary.json").read_text())
    # verdict, landings, then each criterion's nearest landing, the governing check and the weight: one screen
    criteria = [h.strip() for h in head if h.startswith("    ")]
    assert len(criteria) == len(summary["landing_margins"]) == 5        # stroke, tumbling, XDD, contact, settling
    assert any(h.strip().startswith("governing check:") for h in head[1:12])
    assert any("of the capsule" in h for h in head[1:12])
    assert summary["ok"] == (out.returncode == 0)
    assert all("margin_of_safety" in c for c in summary["audit"]["checks"])


@pytest.mark.parametrize("name", ["telescoping", "articulated_3457", "articulated_68", "articulated_9"])
def test_1966_lander_files_reproduce_their_design_configs(name):
    """Each report configuration as a lander file gives exactly the design config's App. IV outcomes (every
    factor, stress and allowable, to the bit) and App. V weights, which tests/validation/test_reference_appendix_iv_v.py
    asserts against the report. The landing cases are left out here: the printed App. IV loads are written
    out in both files, so no landing can change a check (test_crushing_force_change... covers the landings)."""
    from dataclasses import replace
    examples = ROOT / "examples" / "affdl-tr-66-33"
    old = run_design(prepare(alightsize.read_design(examples / f"{name}.toml")))
    spec = alightsize.read_lander(examples / "landers" / f"{name}.toml").spec
    new = run_design(prepare(replace(spec, landings=None)))

    def key(r):
        return r.item.name, r.index, r.outcome.mode, r.outcome.factor, r.outcome.stress, r.outcome.allowable

    assert [key(r) for r in new.records] == [key(r) for r in old.records]
    assert [(w.label, w.count, w.each) for w in new.weights] == [(w.label, w.count, w.each) for w in old.weights]
    assert new.checks_ok == old.checks_ok


@pytest.mark.parametrize("written, found", [('[0.5, 2.4]', "vertical_speed[0]"),
                                            ('["1 m", "3 m"]', "vertical_speed[0]"), ('"2 m"', "vertical_speed")])
def test_an_envelope_error_names_the_envelope_key(tmp_path, written, found):
    """A speed without a unit or with the wrong one is reported at the key written, not at the scene key the
    nominal landing is derived from (`initial.velocity`)."""
    p = variant(tmp_path, {'vertical_speed = ["1 m/s", "3 m/s"]': f"vertical_speed = {written}"})
    with pytest.raises(InputError) as e:
        alightsize.read_lander(p)
    assert f"requirements.envelope.{found}:" in str(e.value) and "initial" not in str(e.value)


def test_first_screen_and_workbook_give_what_the_terminal_gives(lunar, tmp_path):
    """The report's first screen (before its first section) holds the verdict and the terminal's headlines
    (governing check with its MS, weight against the goal); design.xlsx has a Sizing and a Landings sheet whose
    rows are the summary's, speeds converted to the display unit (m/s here: equal to the SI value, 1e-12)."""
    import pandas as pd
    from alightsize.reports.design_report import write_design
    write_design(lunar, tmp_path)
    first = (tmp_path / "report.md").read_text().split("\n## ")[0]
    lines = lunar.headlines(lunar.config.units)
    assert any(h.startswith("governing check:") and "MS" in h for h in lines)
    assert any(h.startswith("leg system:") and "goal" in h for h in lines)
    for h in lines:
        assert h.replace("_", "\\_") in first, h
    summary = json.loads((tmp_path / "summary.json").read_text())
    sizing = pd.read_excel(tmp_path / "design.xlsx", sheet_name="Sizing")
    assert list(sizing["Item"]) == [s["item"] for s in summary["sizing"]]
    landings = pd.read_excel(tmp_path / "design.xlsx", sheet_name="Landings")
    assert list(landings["Landing"]) == [r["run_id"] for r in summary["landings"]]
    np.testing.assert_allclose(landings["Vertical speed (m/s)"],
                               [r["conditions"]["vertical_m_s"] for r in summary["landings"]], rtol=1e-12)
    np.testing.assert_allclose(landings["Peak XDD(3) (g)"], [r["peak"]["xdd_g"][2] for r in summary["landings"]],
                               rtol=1e-12)
