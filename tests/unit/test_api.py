"""The Python API: read, design, tables and figures from a notebook, the same verdict as the CLI."""

from __future__ import annotations

import json
import math

import pytest

import alightsize
from alightsize.cli import main
from conftest import EXAMPLES


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
