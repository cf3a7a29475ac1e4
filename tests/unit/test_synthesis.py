"""Landing-system synthesis: the free parameters' mapping and the crushable-core weight (closed forms), the
Wilson interval (closed forms), and a small synthesis of the lunar example that must find a feasible design
no heavier than its start, give the same result twice and resume an interrupted search without re-landing
a stored candidate."""

from __future__ import annotations

import json
import re
import sqlite3
from math import pi
from pathlib import Path

import pytest
from scipy.stats import norm

from alightsize.cli import main
from alightsize.common.errors import InputError
from alightsize.landings.probability import wilson_interval
from alightsize.model.materials import library
from alightsize.pipeline.lander import read_lander
from alightsize.synthesis.evaluate import stroke_used
from alightsize.synthesis.search import synthesize
from alightsize.synthesis.spec import FreeParameter, overrides, read_synthesis
from conftest import ROOT

EXAMPLE = ROOT / "examples" / "lunar_lander.toml"

# A level lunar drop at 3 m/s, two corners (a leg leading, two straddling) and two Monte Carlo landings per
# candidate; one free parameter and a tiny budget, so the whole search runs in seconds.
SMALL = """
[requirements.envelope]
vertical_speed = "3 m/s"

[requirements.monte_carlo]
samples = 2
seed = 5

[synthesis]
seed = 11
generations = 2
population = 3
check_samples = 4

[synthesis.free]
"cells.axial.crush_force" = ["4 kN", "16 kN"]
"legs.radius" = ["1.6 m", "3.2 m"]
"""


def _small(tmp_path: Path) -> Path:
    text = EXAMPLE.read_text()
    text = text[:text.index("[requirements.envelope]")] + SMALL
    text = text.replace('t_final = "20 s"', 't_final = "3 s"')
    path = tmp_path / "small.toml"
    path.write_text(text)
    return path


def test_wilson_closed_forms():
    """k = n: (n / (n + z²), 1); k = 0: (0, z² / (n + z²)); k = n/2: centred on 1/2 with half-width
    z sqrt(n/4 + z²/4) / (n + z²) (Wilson 1927); exact to rounding (1e-15)."""
    Z95 = norm.ppf(0.975)                  # two-sided 95 % normal quantile
    n, z2 = 1000, Z95 ** 2
    assert wilson_interval(n, n) == pytest.approx((n / (n + z2), 1.0), abs=1e-15)
    assert wilson_interval(0, n) == pytest.approx((0.0, z2 / (n + z2)), abs=1e-15)
    lo, hi = wilson_interval(50, 100)
    half = Z95 * (100 / 4 + z2 / 4) ** 0.5 / (100 + z2)
    assert (lo, hi) == pytest.approx((0.5 - half, 0.5 + half), abs=1e-15)
    assert wilson_interval(0, 0) == (0.0, 1.0)


def test_free_cell_parameters_and_crushable_weight():
    """Setting a cell's crushing force and stroke scales its curve so that its plateau and bottoming stroke
    are those values (1e-12), and the crushable core then weighs rho F s / (sigma_c eta) (App. V prism)."""
    spec = read_synthesis(EXAMPLE)
    stroke = FreeParameter("cells.axial.stroke", 0.2, 0.8, 0.45, "m", 1.0, spec.free[0].curve)
    free = (spec.free[0], stroke)
    over = overrides(free, [12e3, 0.6])
    lander = read_lander(EXAMPLE, over)
    curve = lander.scene.scene.legs[0].axial.curve
    assert max(curve.force[:-1]) == pytest.approx(12e3, rel=1e-12)
    assert curve.deflection[-2] == pytest.approx(0.6, rel=1e-12)
    hc = library()["al-honeycomb"]
    item = next(i for i in lander.spec.items if i.name == "Axial honeycomb")
    assert item.weight is not None
    area, length = (item.weight.params[k] for k in ("area", "length"))
    expected = hc.density * 12e3 * 0.6 / (hc.crush_strength * hc.stroke_fraction)
    assert area * length * hc.density == pytest.approx(expected, rel=1e-12)
    # the report's own axial core: 3750 lbf over a 1.074 in diameter is the material's crush strength (0.1 %,
    # the printed strength is rounded to 4 digits)
    assert 3750 * 4.4482216 / (pi / 4 * (1.074 * 0.0254) ** 2) == pytest.approx(hc.crush_strength, rel=1e-3)


def test_stroke_margin_reads_the_cells_stroke_used(tmp_path):
    """stroke_used is each cell's peak deflection over its stroke to bottoming (exact: a ratio of the row's
    numbers); a margin of 1 is refused, naming the key."""
    lander = read_lander(EXAMPLE)
    legs = lander.scene.scene.legs
    bottom = legs[1].cells[2].curve.bottoming
    row = {"cells_json": json.dumps([{"leg": 2, "cells": [{"max_deflection_m": 0.0}] * 2
                                      + [{"max_deflection_m": 0.75 * bottom}]}])}
    assert stroke_used(row, legs) == pytest.approx(0.75, rel=1e-15)
    bad = tmp_path / "bad.toml"
    text = EXAMPLE.read_text()
    assert "stroke_margin = 0.1 " in text
    bad.write_text(text.replace("stroke_margin = 0.1 ", "stroke_margin = 1.0 "))
    with pytest.raises(InputError, match="synthesis.stroke_margin"):
        read_synthesis(bad)


@pytest.mark.parametrize("key, value", [("samples", "1000000000000000000"), ("population", "100000"),
                                        ("seed", "-1"), ("check_samples", "1e18")])
def test_a_search_budget_beyond_its_documented_range_exits_2(tmp_path, key, value):
    """Every count has a finite range (docs/synthesis.md): a budget of 1e18 landings is refused, not attempted."""
    bad = tmp_path / "bad.toml"
    text = re.sub(rf"(\[synthesis\]\n(?:.*\n)*?){key} = .*\n", r"\1", EXAMPLE.read_text(), count=1)
    bad.write_text(text.replace("[synthesis]\n", f"[synthesis]\n{key} = {value}\n", 1))
    with pytest.raises(InputError, match=f"synthesis.{key}"):
        read_synthesis(bad)


@pytest.mark.parametrize("old, new, message", [
    ('"legs.radius" = ["1.6 m", "3.2 m"]', '"legs.radius" = ["3.2 m", "1.6 m"]',
     "synthesis.free.legs.radius: expected low < high"),
    ('"legs.radius" = ["1.6 m", "3.2 m"]', '"legs.radius" = ["2.5 m", "3.2 m"]',
     "synthesis.free.legs.radius: expected bounds that hold the file's own value 2.4 m"),
    ('"cells.axial.crush_force" = ["4 kN", "16 kN"]\n"cells.pad.crush_force" = ["2 kN", "8 kN"]\n'
     '"legs.radius" = ["1.6 m", "3.2 m"]\n', "", "synthesis.free: expected at least one free parameter"),
    ('slope = ["0 deg", "6 deg"', 'slope = ["0 deg", "6 m"', "synthesis.trade.slope[1]: expected an angle"),
])
def test_a_bad_synthesis_table_names_the_key_as_written(tmp_path, old, new, message):
    """[synthesis] errors name the key as written (the file's start 2.4 m lies outside [2.5, 3.2] m)."""
    text = EXAMPLE.read_text()
    assert old in text
    bad = tmp_path / "bad.toml"
    bad.write_text(text.replace(old, new, 1))
    with pytest.raises(InputError) as err:
        read_synthesis(bad)
    assert f"{bad}: {message}" in str(err.value)


def test_small_synthesis_is_feasible_reproducible_and_resumes(tmp_path):
    """The winner meets every criterion on its sample and on the fresh check sample, is no heavier than the
    start on the search sample, and the chosen design is judged on its corners and the fresh sample (its
    members sized there: every check at the required 1.25); a second run (same seed) lands nothing new and
    chooses the same design bit for bit. A search interrupted after its first generation resumes: the rerun
    lands only what was not stored and ends on the same design."""
    from alightsize.synthesis.search import _best
    lander = _small(tmp_path)
    res = synthesize(lander, tmp_path / "a", backend="serial")
    assert res.best.feasible and res.ok
    assert _best(res.history).objective <= res.start.objective
    assert all(r.passed == r.n for r in res.rates + res.check_rates)
    assert len(res.check_rows) == 4
    corners = sum(r["run_id"].startswith("corner-") for r in res.best_rows)
    assert res.best.landings == corners + 4 and res.best_design is not None
    assert all(r.outcome.factor >= 1.25 * (1 - 1e-6) for r in res.best_design.records)   # sizing's 1e-9 bisection
    again = synthesize(lander, tmp_path / "a", backend="serial")
    assert again.stats["landings_computed"] == 0
    assert again.best.x == res.best.x

    class Stop(Exception):
        pass

    def stop_after_first(msg: str) -> None:
        if msg.startswith("  generation 1"):
            raise Stop
    with pytest.raises(Stop):
        synthesize(lander, tmp_path / "b", backend="serial", log=stop_after_first)
    with sqlite3.connect(tmp_path / "b" / "runs.sqlite") as db:
        landed_before = db.execute("SELECT COUNT(*) FROM runs").fetchone()[0]
    resumed = synthesize(lander, tmp_path / "b", backend="serial")
    assert resumed.best.x == res.best.x
    assert 0 < landed_before < res.stats["landings_computed"]
    assert resumed.stats["landings_computed"] == res.stats["landings_computed"] - landed_before


def test_synthesize_cli_writes_report_and_rejects_bad_bounds(tmp_path, capsys):
    lander = _small(tmp_path)
    assert main(["synthesize", str(lander), "--out", str(tmp_path / "o"), "--serial", "--no-trade"]) == 0
    for name in ("synthesis.json", "report.md", "report.html", "synthesis.xlsx", "convergence.png", "chosen/report.md"):
        assert (tmp_path / "o" / name).is_file()
    bad = tmp_path / "bad.toml"
    bad.write_text(lander.read_text().replace('"legs.radius" = ["1.6 m", "3.2 m"]', '"legs.radius" = ["1.6 m", "2 m"]'))
    assert main(["synthesize", str(bad), "--out", str(tmp_path / "p"), "--serial"]) == 2
    err = capsys.readouterr().err
    assert "synthesis.free.legs.radius" in err and "2.4 m" in err
    for start in ("cells.axial.crush_force=4 m", "cells.axial.crush_force=4000", "legs.width=2 m"):
        assert main(["synthesize", str(lander), "--out", str(tmp_path / "q"), "--start", start]) == 2
        assert "Traceback" not in capsys.readouterr().err


def test_criteria_kinds_name_every_violation():
    """Each violation a landing can have is one of the criteria the pass rates count (else a failing landing
    would count as meeting every criterion)."""
    from alightsize.landings.criteria import PRESETS, Criteria, violation_kinds
    crit = Criteria(*PRESETS["human"])
    for outcome in ("bottomed", "tipped", "body_contact", "failed", "time_out"):
        failures = crit.failures({"peak": {"xdd_g": [99.0] * 3, "onset_g_s": [1e6] * 3}, "outcome": outcome})
        assert set(violation_kinds("; ".join(failures))) <= set(crit.kinds())
        assert len(failures) == 7
