"""Landing cases in `alightsize design` (issues 5 and 6): the study runs through the sweep runner, each
member takes the larger of the App. III envelope and the landings, and the report says which governed."""

from __future__ import annotations

import json
import shutil

import pytest

from alightsize.pipeline.config import prepare, read_design
from alightsize.common.errors import InputError
from alightsize.pipeline.landings import LANDING

from conftest import EXAMPLES

CONFIG = EXAMPLES / "articulated_3457_envelopes.toml"


@pytest.fixture(scope="module")
def design(tmp_path_factory):
    return prepare(read_design(CONFIG), tmp_path_factory.mktemp("landings"))


def test_every_landing_case_runs_and_closes_energy(design):
    """24 cases (configurations 3, 4, 5, 7 x three slopes x two inclinations), all done, closure < 1e-4."""
    rows = design.landings.rows
    assert len(rows) == 24 and {r["status"] for r in rows} == {"done"}
    assert max(r["closure_rel"] for r in rows) < 1e-4
    assert all(json.loads(r["member_loads_json"]) for r in rows)


def test_each_check_takes_the_larger_of_sweep_and_landings(design):
    """The load a check uses is exactly max(quasi-static extreme, every landing's extreme) times its factor
    (same numbers, so equality to round-off), and it is attributed to a landing exactly when a landing's is
    the larger."""
    sense_key = {"tension": ("tension_N",), "compression": ("compression_N",),
                 "magnitude": ("tension_N", "compression_N")}
    governed_by_landing = 0
    for ref in design.load_refs:
        qs = design.landings.quasi_static_load(ref.envelope, ref.member, ref.sense) or 0.0
        landing = max(abs(d[k]) for r in design.landings.rows for d in json.loads(r["member_loads_json"])
                      if d["member"] == ref.member for k in sense_key[ref.sense] if d[k] is not None)
        assert ref.value == pytest.approx(max(qs, landing) * ref.factor, rel=1e-12)
        assert ref.extreme.configuration.startswith(LANDING) == (landing > qs)
        governed_by_landing += landing > qs
    assert governed_by_landing >= 1                  # PU1 compression (measured 33,088 vs 32,745 lbf)


def test_unknown_envelope_is_bad_input(tmp_path):
    """[landings] envelopes naming no envelope of the loads file is an InputError naming the key."""
    shutil.copytree(EXAMPLES, tmp_path / "ex")
    bad = tmp_path / "ex" / CONFIG.name
    bad.write_text(CONFIG.read_text().replace('envelopes = ["3457"]', 'envelopes = ["3458"]'))
    with pytest.raises(InputError) as e:
        read_design(bad)
    assert "landings.envelopes" in str(e.value) and "3458" in str(e.value)


# AFFDL-TR-66-33 Sec. II.A.1 (human, couch facing up): 10 / 10 / 20 g and 1,000 / 1,000 / 10,000 g/s onset on
# body axes 1, 2, 3; the study's preset "human".
SEC_II_G, SEC_II_ONSET = (10.0, 10.0, 20.0), (1000.0, 1000.0, 10000.0)


def _meets_sec_ii(r: dict) -> bool:
    """A landing meets the human criteria: peaks and onsets within Sec. II.A.1, no bottoming or tumbling."""
    return (all(r[f"peak_xdd{i}_g"] <= SEC_II_G[i - 1] for i in (1, 2, 3))
            and all(r[f"peak_onset_xdd{i}_g_s"] <= SEC_II_ONSET[i - 1] for i in (1, 2, 3))
            and r["outcome"] not in ("bottomed", "tipped", "body_contact", "failed", "time_out"))


@pytest.fixture(scope="module")
def rendered(tmp_path_factory):
    """`alightsize design` of the example, as a user runs it: (exit status, stdout, report.html, summary)."""
    import subprocess
    import sys
    out = tmp_path_factory.mktemp("design")
    r = subprocess.run([sys.executable, "-m", "alightsize", "design", str(CONFIG), "--out", str(out)],
                       capture_output=True, text=True)
    return r.returncode, r.stdout, (out / "report.html").read_text(), json.loads((out / "summary.json").read_text())


def test_a_design_whose_landings_fail_their_criteria_does_not_pass(design, rendered):
    """The verdict counts the landings that fail Sec. II (recomputed here from the stored peaks), exits 1
    and never opens with the checks' pass."""
    status, stdout, html, summary = rendered
    failing = [r for r in design.landings.rows if not _meets_sec_ii(r)]
    assert [r["run_id"] for r in failing] == [r["run_id"] for r in design.landings.failing]
    assert failing                                   # measured: all 24 (onset above 1,000 g/s on axis 1)
    assert status == 1 and summary["ok"] is False and summary["landings_ok"] is False
    assert stdout.startswith("3457: FAIL: ") and f"{len(failing)} of 24 landings fail their criteria" in stdout
    result = html.split("Result:")[1].split("</p>")[0]
    assert 'class="fail"' in result and "PASS" not in result
    assert [case["criteria_ok"] for case in summary["landings"]] == [_meets_sec_ii(r) for r in design.landings.rows]


def test_the_report_defines_every_landing_and_names_the_governing_one(design, rendered):
    """A landing section with each case's conditions, outcome, peaks and criteria; every landing a load
    table names links to its row and carries its outcome and conditions."""
    _, _, html, _ = rendered
    section = html.split('<h2 id="landings">')[1].split("<h2")[0]
    for r in design.landings.rows:
        row = section.split(f'<tr id="landing-{r["run_id"]}">')[1].split("</tr>")[0]
        assert r["outcome_class"].replace("_", " ") in row and "35.0 ft/s down, 15.0 ft/s horizontal" in row
        assert f"{r['peak_xdd3_g']:.2f}" in row and ("fails" in row) == (not _meets_sec_ii(r))
    governing = {ref.extreme.configuration.removeprefix(LANDING) for ref in design.load_refs
                 if ref.extreme and ref.extreme.configuration.startswith(LANDING)}
    assert governing                                  # landing 3-03 governs PU1 (see above)
    for run_id in governing:
        outcome = next(r["outcome_class"] for r in design.landings.rows if r["run_id"] == run_id)
        assert f'<a href="#landing-{run_id}">landing {run_id}</a> ({outcome.replace("_", " ")}; 35.0 ft/s down' in html


def test_landings_declared_as_load_cases_only_say_so_and_are_judged_on_the_checks_alone(tmp_path):
    """role = "load_cases": the same failing landings are reported, the page says plainly that they are load
    cases only, and the verdict is the checks' alone: the landings meet nothing they are asked to, and the only
    failures are the two columns below Euler's range (tests/unit/test_cli_audit.py, COLUMN_FAILURES), exit 1."""
    import subprocess
    import sys
    shutil.copytree(EXAMPLES, tmp_path / "ex")
    cfg = tmp_path / "ex" / CONFIG.name
    cfg.write_text(CONFIG.read_text().replace('envelopes = ["3457"]', 'envelopes = ["3457"]\nrole = "load_cases"'))
    r = subprocess.run([sys.executable, "-m", "alightsize", "design", str(cfg), "--out", str(tmp_path / "o")],
                       capture_output=True, text=True)
    summary = json.loads((tmp_path / "o" / "summary.json").read_text())
    assert r.returncode == 1 and "landings used as load cases only" in r.stdout
    assert summary["landings_ok"] is True and summary["checks_ok"] is False
    assert {(c["item"], c["check"]) for c in summary["audit"]["checks"] if not c["ok"]} == {
        ("Lower Truss", "column_buckling"), ("Peg Leg Strut", "column_buckling")}
    html = (tmp_path / "o" / "report.html").read_text()
    assert "These landings are load cases only" in html and 'fail">fails</span>' in html


def test_a_landing_says_whether_it_runs_downhill_or_uphill():
    """The study's slope sign (-20 deg: the horizontal velocity runs into the slope, Sec. IV.B) and the
    conditions the report prints agree: uphill at -20, downhill at +20, level ground at 0; the slope itself is
    the angle between the terrain normal and the vertical, 20 deg (tolerance: float rounding)."""
    from alightsize.pipeline.design import run_design
    from alightsize.pipeline.config import read_design
    from alightsize.reports.design_report import landing_rows
    landed = run_design(read_design(EXAMPLES / "articulated_3457_envelopes.toml")).config
    for row, c in zip(landing_rows(landed, "US").values(), landed.landings.conditions):
        slope = float(row["parameters"].split("slope ")[1].split(" deg")[0])
        assert c["slope_deg"] == pytest.approx(abs(slope), abs=1e-9)
        want = {-20.0: "uphill on a 20° slope", 0.0: "horizontal on level ground", 20.0: "downhill on a 20° slope"}
        assert want[slope] in row["conditions"], row


def test_the_landing_nearest_each_criterion_failing_ones_first():
    """Margins of synthetic landing rows in closed form (1 - used / allowed; tolerance: float round-off):
    a stable landing with the highest peak (19 of 20 g, margin 0.05) is named only for the acceleration
    criterion; the tumbling landing (nutation 66 of 60 deg, -0.1) and the deeper of two bottomed ones
    (0.42 of 0.4 m, -0.05) come first."""
    import json as _json

    from alightsize.landings.criteria import Criteria, LandingLimits, closest

    def row(run_id, outcome, xdd, strokes, nutation):
        return {"run_id": run_id, "outcome": outcome, "peak_nutation_deg": nutation,
                **{f"peak_xdd{i + 1}_g": x for i, x in enumerate(xdd)},
                **{f"peak_onset_xdd{i + 1}_g_s": 0.0 for i in range(3)},
                "cells_json": _json.dumps([{"leg": 1, "cells": [{"max_deflection_m": d} for d in strokes]}])}
    rows = [row("high-g", "stable", (2.0, 1.0, 19.0), (0.2, 0.1), 6.0),
            row("bottomed", "bottomed", (1.0, 1.0, 8.0), (0.42, 0.1), 10.0),
            row("tipped", "tipped", (3.0, 1.0, 4.0), (0.1, 0.27), 66.0),
            row("bottomed-2", "bottomed", (1.0, 1.0, 8.0), (0.41, 0.0), 10.0)]
    limits = [LandingLimits(((0.4, 0.3),), (("axial", "rot1"),), 60.0)] * len(rows)
    got = closest(rows, Criteria((10.0, 10.0, 20.0), None), limits)
    assert [(c.margin.criterion, c.run_id, c.failing) for c in got] == [
        ("tumbling", "tipped", 1), ("bottoming", "bottomed", 2), ("acceleration", "high-g", 0),
        ("body_contact", None, 0), ("settling", None, 0)]
    for c, want in zip(got, (1 - 66 / 60, 1 - 0.42 / 0.4, 1 - 19 / 20)):
        assert c.margin.margin == pytest.approx(want, rel=1e-12)
    assert got[0].line().startswith("no tumbling: tipped, margin -0.100 (nutation 66 deg of 60 deg); 1 of 4 fail")


def test_the_first_screen_names_the_landing_nearest_each_criterion(design, rendered):
    """The example's summary.json and first screen: for the peak and onset criteria the landing of the
    smallest margin 1 - max_i(value_i / limit_i) (recomputed from the stored peaks; float round-off), every
    criterion some landing violates before those none does, and the same lines on stdout and atop the page."""
    import html as _html
    _, stdout, page, summary = rendered
    rows = design.landings.rows
    margins = {m["criterion"]: m for m in summary["landing_margins"]}
    for name, col, caps in (("acceleration", "peak_xdd{}_g", SEC_II_G),
                            ("onset", "peak_onset_xdd{}_g_s", SEC_II_ONSET)):
        each = [1 - max(r[col.format(i)] / caps[i - 1] for i in (1, 2, 3)) for r in rows]
        k = min(range(len(rows)), key=each.__getitem__)
        assert margins[name]["run_id"] == rows[k]["run_id"]
        assert margins[name]["margin"] == pytest.approx(each[k], rel=1e-12)
        assert margins[name]["failing"] == sum(m < 0 for m in each)
    failing = [m["failing"] > 0 for m in summary["landing_margins"]]
    assert failing == sorted(failing, reverse=True) and failing[0]
    top = page.split("<h2")[0]
    for c in design.landings.closest:
        assert c.line() in stdout and _html.escape(c.line(), quote=False) in top
