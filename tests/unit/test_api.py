"""The Python API: read, design, tables and figures from a notebook, the same verdict as the CLI. Each
top-level function on a small shipped example returns a result whose `to_pandas()` tables hold the numbers the
CLI writes to its JSON, and whose `.plot()` draws a matplotlib Figure.

Tolerance of the table-JSON comparisons: the tables and the JSON are the same doubles (JSON writes Python's
shortest round-trip repr), so they agree to rounding at most; 1e-12 relative allows nothing more (a table
built by different arithmetic than the JSON would differ far beyond it)."""

from __future__ import annotations

import json
import math
import shutil

import pandas as pd
import pytest
from matplotlib.figure import Figure

import alightsize
from alightsize.cli import main
from conftest import EXAMPLES

TOL = 1e-12


@pytest.mark.parametrize("name, ok", [("telescoping", True), ("articulated_9", False)])
def test_design_from_python_gives_the_clis_verdict_and_files(name, ok, tmp_path):
    res = alightsize.design(EXAMPLES / f"{name}.toml", out=tmp_path / "api")
    assert res.ok is ok
    assert main(["design", str(EXAMPLES / f"{name}.toml"), "--out", str(tmp_path / "cli")]) == (0 if ok else 1)
    for f in ("summary.json", "report.html"):
        assert (tmp_path / "api" / f).read_text() == (tmp_path / "cli" / f).read_text()
    assert json.loads((tmp_path / "api" / "summary.json").read_text())["ok"] is ok


def test_tables_hold_every_check_weight_and_landing():
    """One row per check with MS = f / f_required - 1 (float rounding), one per weight entry whose sum is
    the per-leg weight, one per landing case."""
    res = alightsize.design(alightsize.read_design(EXAMPLES / "articulated_3457_envelopes.toml"))
    t = res.to_pandas()
    assert len(t["checks"]) == len(res.records) and len(t["landings"]) == len(res.config.landings.rows)
    finite = t["checks"].dropna(subset=["design_factor"])
    margin = finite["design_factor"] / finite["required_design_factor"] - 1
    assert (finite["margin_of_safety"] - margin).abs().max() < 1e-12
    assert t["weights"]["weight_per_leg_kg"].sum() == pytest.approx(res.per_leg, rel=1e-12)
    assert list(t["checks"]["ok"]) == [r.ok for r in res.records]


def test_plot_draws_one_bar_per_checked_item():
    res = alightsize.design(EXAMPLES / "telescoping.toml")
    fig = res.plot()
    items = {r.item.name for r in res.records if math.isfinite(r.outcome.factor)}
    assert len(fig.axes[0].patches) == len(items)
    assert len(res.plot("weights").axes[0].patches) == len(res.weights)
    with pytest.raises(ValueError, match="expected one of factors, weights"):
        res.plot("colours")


def _same(table_value, json_value) -> None:
    """A table cell equals a JSON value: null as NaN or None, numbers within TOL relative, the rest exactly."""
    if json_value is None:
        assert table_value is None or (isinstance(table_value, float) and math.isnan(table_value))
    elif isinstance(json_value, bool) or isinstance(json_value, str):
        assert table_value == json_value
    else:
        assert table_value == pytest.approx(json_value, rel=TOL, abs=0.0)


def _rows_agree(frame: pd.DataFrame, rows: list[dict], keys=None) -> None:
    assert len(frame) == len(rows)
    for rec, row in zip(frame.to_dict("records"), rows):
        for k in keys or row:
            _same(rec[k], row[k])


def test_design_and_audit_tables_agree_with_the_cli_json(tmp_path):
    cfg = EXAMPLES / "telescoping.toml"
    assert main(["design", str(cfg), "--out", str(tmp_path / "d")]) == 0
    summary = json.loads((tmp_path / "d" / "summary.json").read_text())
    res = alightsize.design(cfg)
    tables = res.to_pandas()
    _rows_agree(tables["checks"], summary["audit"]["checks"])
    _rows_agree(tables["weights"], summary["weights"][res.config.configuration]["items"])
    for kind in ("factors", "weights"):
        assert isinstance(res.plot(kind), Figure)

    assert main(["audit", str(cfg), "--json", str(tmp_path / "audit.json")]) == 0
    audit = json.loads((tmp_path / "audit.json").read_text())
    checked = alightsize.audit(cfg)
    _rows_agree(checked.to_pandas()["checks"], audit["checks"])
    assert checked.checks_ok == audit["ok"]
    assert isinstance(checked.plot(), Figure)


def test_loads_tables_agree_with_the_cli_json(tmp_path):
    cfg = EXAMPLES / "loads" / "articulated.toml"
    assert main(["loads", str(cfg), "--out", str(tmp_path / "l")]) == 0
    doc = json.loads((tmp_path / "l" / "max_member_loads.json").read_text())
    res = alightsize.loads(cfg)
    tables = res.to_pandas()
    env = tables["envelopes"]
    rows = [r for name, members in doc["configurations"].items() for r in members]
    assert list(env["envelope"]) == [name for name, members in doc["configurations"].items() for _ in members]
    for rec, row in zip(env.to_dict("records"), rows):
        assert rec["member"] == row["member"]
        for sense in ("tension", "compression"):
            _same(rec[f"{sense}_N"], row[f"{sense}_N"])
            at = row[f"{sense}_at_deg"] or [None] * 3
            for ax, v in zip(("alpha", "beta", "psi"), at):
                _same(rec[f"{sense}_{ax}_deg"], v)
    if "telescoping" in doc:
        for k, v in doc["telescoping"].items():
            _same(tables["telescoping"][k].iloc[0], v)
    assert isinstance(res.plot(res.config.cases[0].name), Figure)


def test_simulate_tables_agree_with_the_cli_json(tmp_path):
    scene = EXAMPLES / "scenes" / "telescoping_config2.toml"
    assert main(["simulate", str(scene), "--out", str(tmp_path / "s")]) == 0
    s = json.loads((tmp_path / "s" / "summary.json").read_text())
    res = alightsize.simulate(scene)
    t = res.to_pandas()
    peak = t["peak"].iloc[0]
    for k in range(3):
        _same(peak[f"xdd{k + 1}_g"], s["peak"]["xdd_g"][k])
        _same(peak[f"omd{k + 1}_rad_s2"], s["peak"]["omd_rad_s2"][k])
        _same(peak[f"onset_xdd{k + 1}_g_s"], s["peak"]["onset_g_s"][k])
    _same(peak["nutation_deg"], s["peak"]["nutation_deg"])
    _same(peak["t_end_s"], s["t_end_s"])
    assert peak["outcome"] == s["outcome"]
    _rows_agree(t["cells"], [{"leg": leg["leg"], **c} for leg in s["legs"] for c in leg["cells"]])
    _rows_agree(t["legs"], s["legs"], ("leg", "max_ground_force_N", "max_sinkage_m"))
    _rows_agree(t["energy"], [s["energy"]])
    history = pd.read_parquet(tmp_path / "s" / "history.parquet")
    pd.testing.assert_frame_equal(t["history"], history, rtol=TOL, atol=0.0)
    for kind in ("xdd", "omd", "strokes", "energy", "footprints", "srs_xdd3"):
        assert isinstance(res.plot(kind), Figure)


def test_sweep_tables_agree_with_the_cli_json(tmp_path):
    from test_sweep import _study
    study = _study(tmp_path, samples=2)
    out = tmp_path / "w"
    assert main(["sweep", str(study), "--out", str(out), "--serial", "--quiet"]) == 0
    doc = json.loads((out / "outcomes.json").read_text())
    res = alightsize.sweep(study, out, backend="serial")           # every run stored: nothing is landed again
    t = res.to_pandas()
    runs = t["runs"]
    assert list(runs["run_id"]) == [r["run_id"] for r in doc["run_list"]]
    for rec, row in zip(runs.to_dict("records"), doc["run_list"]):
        assert rec["outcome"] == row["outcome"] and rec["outcome_class"] == row["outcome_class"]
        for k in range(3):
            _same(rec[f"peak_xdd{k + 1}_g"], row["peak_xdd_g"][k])
        _same(rec["max_stroke_m"], row["max_stroke_m"])
    _rows_agree(t["outcomes"], [{"outcome_class": k, "count": v["count"], "probability": v["probability"],
                                 "ci95_low": v["ci95"][0], "ci95_high": v["ci95"][1]}
                                for k, v in doc["outcome_classes"].items()])
    assert isinstance(res.plot("distributions"), Figure)
    assert isinstance(res.plot("boundary"), Figure)


def test_synthesize_tables_agree_with_the_cli_json(tmp_path):
    from test_synthesis import _small
    lander = _small(tmp_path)
    out = tmp_path / "y"
    assert main(["synthesize", str(lander), "--out", str(out), "--serial", "--no-trade"]) == 0
    doc = json.loads((out / "synthesis.json").read_text())
    shutil.rmtree(out / "chosen")
    res = alightsize.synthesize(lander, out, trade=False, backend="serial")   # resumed: the same design
    t = res.to_pandas()
    _rows_agree(t["convergence"], doc["convergence"])
    _rows_agree(t["check"], doc["check"]["rates"])
    chosen = t["candidates"][t["candidates"]["objective"] == res.best.objective].iloc[0]
    for p in doc["parameters"]:
        _same(chosen[p["key"]], p["chosen_si"])
    for kind in ("convergence", "pareto"):
        assert isinstance(res.plot(kind), Figure)
