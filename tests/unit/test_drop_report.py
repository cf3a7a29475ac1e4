"""The drop-test comparison report (alightsize.reports.drop_report): printed Tables 6-13 read as printed, the simulated
energy error against the drop energy, drops without a table, SI unit-suffixed JSON, escaping, and the shipped
reports/affdl-tr-66-33/drops/ current. The landings are the ones tests/validation/test_drops.py runs (run_drop
caches them)."""

from __future__ import annotations

import copy
import dataclasses
import json
import re

import pytest

from alightsize.model.scene_config import read_scene
from alightsize.landings.drops import DROP_NUMBERS, DROPS_DIR, Drop, document, run_drop
from alightsize.reports.drop_report import plot_energy, render
from alightsize_sim.landing import simulate
from conftest import ROOT
from alightsize.landings.drop_tables import STROKES_ENERGIES

REPORT = ROOT / "reports" / "affdl-tr-66-33" / "drops"
J_PER_FT_LB = 0.3048 * 0.45359237 * 9.80665          # ft x lbf (lb 0.45359237 kg, g0 9.80665 m/s^2), exact
UNIT_SUFFIXES = ("_m", "_J", "_s", "_g", "_rad_s2", "_Hz", "_rel")


@pytest.fixture(scope="module")
def doc() -> dict:
    return document([run_drop(n) for n in DROP_NUMBERS])


def _entry(doc: dict, n: int) -> dict:
    return next(e for e in doc["drops"] if e["drop"] == n)


def test_printed_totals_of_table_10_are_read_as_printed(doc):
    """Table 10 (drop 6): experimental 1,712 ft-lb / -27.0 %, analytical 2,416 ft-lb /
    +3.0 %; the analytical total is the sum of its eight cells (4 x 578 + 4 x 26)."""
    t = _entry(doc, 6)["totals"]
    assert t["analytical"]["printed_energy_J"] == pytest.approx(2416 * J_PER_FT_LB, rel=1e-12)
    assert t["analytical"]["printed_energy_error_rel"] == pytest.approx(0.030)
    assert t["experimental"]["printed_energy_J"] == pytest.approx(1712 * J_PER_FT_LB, rel=1e-12)
    assert t["experimental"]["printed_energy_error_rel"] == pytest.approx(-0.270)
    assert t["analytical"]["energy_J"] == pytest.approx((4 * 578 + 4 * 26) * J_PER_FT_LB, rel=1e-12)
    assert t["analytical"]["stroke_m"] == pytest.approx(4 * (0.1523 + 0.0086) * 0.3048, rel=1e-12)


def test_table_12_analytical_energies_are_shown_swapped_back(doc):
    """GUIDE: Table 12's analytical upper / lower energy rows are printed swapped; upper leg 1 carries 899 ft-lb."""
    rows = {(r["leg"], r["cell"]): r for r in _entry(doc, 9)["cells"]}
    assert rows[1, "upper"]["analytical_energy_J"] == pytest.approx(899 * J_PER_FT_LB, rel=1e-12)
    assert rows[1, "lower"]["analytical_energy_J"] == pytest.approx(147 * J_PER_FT_LB, rel=1e-12)


@pytest.mark.parametrize("n", sorted(STROKES_ENERGIES))
def test_energy_error_is_the_cell_energy_against_the_drop_energy(doc, n):
    """(sum of the simulated cell energies - printed drop energy) / drop energy, computed here from the landing;
    within the issue's 5 % on every drop."""
    drop_energy = STROKES_ENERGIES[n]["drop_energy_ft_lb"] * J_PER_FT_LB
    expected = (run_drop(n).res.cell_energy.sum() - drop_energy) / drop_energy
    e = _entry(doc, n)
    assert e["drop_energy_J"] == pytest.approx(drop_energy, rel=1e-12)
    assert e["totals"]["simulated"]["energy_error_rel"] == pytest.approx(expected, rel=1e-9)
    assert abs(expected) < 0.05


def test_drop_1_cell_row_against_table_6(doc):
    """Leg 1 upper cell of drop 1: the permanent set dmax - F/k against the analytical 0.1356 ft (Table 6)."""
    _, cfg, res = run_drop(1)
    dmax, fmax = res.memory[0, 0]
    stroke = dmax - fmax / cfg.scene.legs[0].cells[0].k
    row = _entry(doc, 1)["cells"][0]
    assert (row["leg"], row["cell"]) == (1, "upper")
    assert row["simulated_stroke_m"] == pytest.approx(stroke, rel=1e-12)
    assert row["stroke_diff_analytical_rel"] == pytest.approx(stroke / (0.1356 * 0.3048) - 1, rel=1e-9)


def test_drops_5_and_11_have_no_table_and_say_so(doc):
    md = render(doc, "md")
    for n in (5, 11):
        e = _entry(doc, n)
        assert e["table"] is None and e["drop_energy_J"] is None and set(e["totals"]) == {"simulated"}
        assert e["outcome"] == "body_contact" and "no table in the report" in e["note"]
        assert e["totals"]["simulated"]["energy_J"] == pytest.approx(run_drop(n).res.cell_energy.sum())
        assert f"## Drop {n}: no table" in md


def test_json_is_si_with_a_unit_in_every_numeric_field(doc):
    """CONTRACTS.md: every numeric field name ends in its unit (integers here are drop, table and leg numbers)."""
    assert doc["schema"] == "alightsize.drops/1"

    def walk(node, key=""):
        if isinstance(node, dict):
            for k, v in node.items():
                walk(v, k)
        elif isinstance(node, list) and node and not isinstance(node[0], (int, float)):
            for v in node:
                walk(v, key)
        elif isinstance(node, (float, list)):
            assert key.endswith(UNIT_SUFFIXES), key
        elif isinstance(node, int) and not isinstance(node, bool):
            assert key in ("drop", "table", "leg"), key

    walk(json.loads(json.dumps(doc)))


def test_html_and_markdown_escape_text(doc):
    hostile = copy.deepcopy(doc)
    hostile["drops"][0]["title"] = "<script>alert(1)</script>|*"
    html = render(hostile, "html")
    assert "<script>" not in html and "&lt;script&gt;alert(1)&lt;/script&gt;" in html
    md = render(hostile, "md")
    assert "<script>" not in md and "\\<script\\>" in md and "\\|\\*" in md


def test_fig_102_plot(doc, tmp_path):
    assert plot_energy(doc, tmp_path / "f.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


_NUMBER = re.compile(r"\d[\d.,]*(e[-+]?\d+)?")


def _tight(n: int) -> Drop:
    """Drop n at a tenth of its scene's rtol and atol."""
    cfg = read_scene(DROPS_DIR / f"drop{n:02d}.toml")
    controls = dataclasses.replace(cfg.controls, rtol=cfg.controls.rtol / 10, atol=cfg.controls.atol / 10)
    return Drop(n, cfg, simulate(cfg.scene, controls))


def _mismatches(shipped, ours, tight, path="") -> list[str]:
    """Where the shipped report and this machine's differ by more than the solver can tell apart.

    The global error of a number at the scene's tolerance is estimated by its change at a tenth of that
    tolerance, |ours - tight| (the error scales with the tolerance: Hairer, Norsett & Wanner 1993 II.4).
    Another CPU or compiler rounds differently; the landing amplifies that as it amplifies the tolerance-sized
    error, so two machines agree to a few such estimates: 4 of them (on this report the shipped numbers of
    another machine came within 2.2), plus 1e-6 relative (the scene's rtol), 1e-3 relative for the shock
    spectrum (its accuracy against the dense solution, docs/notes/shock-spectrum-log.md)."""
    if isinstance(shipped, dict):
        if shipped.keys() != ours.keys():
            return [f"{path}: keys {sorted(shipped)} != {sorted(ours)}"]
        return [m for k in shipped for m in _mismatches(shipped[k], ours[k], tight[k], f"{path}.{k}")]
    if isinstance(shipped, list):
        if not len(shipped) == len(ours) == len(tight):
            return [f"{path}: {len(shipped)} items != {len(ours)}"]
        return [m for j, (a, b, c) in enumerate(zip(shipped, ours, tight))
                for m in _mismatches(a, b, c, f"{path}[{j}]")]
    if isinstance(shipped, float) and isinstance(ours, float):
        floor = (1e-3 if ".srs_" in path else 1e-6) * abs(ours) + 1e-12
        return [] if abs(shipped - ours) <= 4 * abs(ours - tight) + floor else [f"{path}: {shipped!r} != {ours!r}"]
    if isinstance(shipped, str) and isinstance(ours, str):      # a reason's wording, without its figures
        shipped, ours = _NUMBER.sub("#", shipped), _NUMBER.sub("#", ours)
    return [] if shipped == ours else [f"{path}: {shipped!r} != {ours!r}"]


def test_shipped_report_is_current(doc):
    """reports/affdl-tr-66-33/drops/ as `alightsize reports` writes it, on any CPU: its numbers within what the
    solver can tell apart from this machine's (_mismatches), its pages rendered from its own drops.json; rerun
    that command when this fails."""
    shipped = json.loads((REPORT / "drops.json").read_text())
    tight = document([_tight(n) for n in DROP_NUMBERS])
    bad = _mismatches(shipped, doc, tight)
    assert not bad, f"drops.json is stale ({len(bad)} values): " + "; ".join(bad[:5])
    assert render(shipped, "md") == (REPORT / "drops.md").read_text(), "drops.md is stale"
    assert render(shipped, "html") == (REPORT / "drops.html").read_text(), "drops.html is stale"
    for n in DROP_NUMBERS:
        for png in (f"drop{n:02d}_xdd_omd.png", f"drop{n:02d}_srs_xdd3.png"):
            assert (REPORT / png).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_staleness_tolerance_flags_a_change_beyond_the_solver_error(doc):
    """The comparison is not vacuous: a stroke moved by 1 % (far beyond rtol 1e-6 x any amplification seen) and
    a changed outcome are flagged; the same document passes against itself."""
    tight = document([_tight(n) for n in DROP_NUMBERS])
    assert _mismatches(doc, doc, tight) == []
    moved = copy.deepcopy(doc)
    moved["drops"][0]["cells"][0]["simulated_stroke_m"] *= 1.01
    moved["drops"][1]["outcome"] = "tumbled"
    bad = _mismatches(moved, doc, tight)
    assert len(bad) == 2 and "simulated_stroke_m" in bad[0] and "outcome" in bad[1]
