"""`alightsize loads` (CONTRACTS.md), envelope references in design configs, bad loads input."""

import json
import shutil
import subprocess
import sys

import numpy as np
import pytest
from openpyxl import load_workbook

from alightsize.cli import main
from alightsize.loads.envelopes import member_fields
from alightsize.loads.quasi_static import run_loads
from alightsize.loads.config import read_loads
from alightsize_sim.articulated_statics import MEMBERS

from conftest import EXAMPLES

LOADS = EXAMPLES / "loads" / "articulated.toml"
LBF = 4.4482216152605


def test_loads_writes_the_contract(tmp_path):
    assert main(["loads", str(LOADS), "--out", str(tmp_path)]) == 0
    doc = json.loads((tmp_path / "max_member_loads.json").read_text())
    assert doc["schema"] == "alightsize.loads/1"
    assert list(doc["configurations"]) == ["3", "4", "5", "6", "7", "8", "9", "3457", "68"]
    for rows in doc["configurations"].values():
        assert [r["member"] for r in rows] == list(MEMBERS)
        for r in rows:
            assert r["tension_N"] is None or (r["tension_N"] > 0 and len(r["tension_at_deg"]) == 3)
            assert r["compression_N"] is None or r["compression_N"] < 0
        by = {r["member"]: r for r in rows}
        assert by["R123"]["compression_N"] is None and by["R1213"]["compression_N"] is None
    wb = load_workbook(tmp_path / "max_member_loads.xlsx")
    assert wb.sheetnames == ["3", "4", "5", "6", "7", "8", "9", "3457", "68"]
    assert (tmp_path / "heatmap_3.png").stat().st_size > 10_000


def test_envelope_is_the_grid_extreme_and_combined_takes_the_worst():
    cfg = read_loads(LOADS)
    res = run_loads(cfg)
    case = cfg.cases[0]
    _, fields = member_fields(case, cfg.grid)
    for row in res.envelopes[case.name]:
        f = fields[row.member]
        assert row.tension.value == np.nanmax(f)
        if row.compression is not None:
            assert row.compression.value == np.nanmin(f)
    for row in res.envelopes["3457"]:
        parts = [next(r for r in res.envelopes[n] if r.member == row.member) for n in ("3", "4", "5", "7")]
        assert row.tension.value == max(p.tension.value for p in parts)


def _copy_examples(tmp_path):
    shutil.copytree(EXAMPLES, tmp_path / "ex")
    return tmp_path / "ex"


def _upper_truss_load(summary):
    return next(c["load_N"] for c in summary["audit"]["checks"]
                if c["item"] == "Upper Truss" and c["check"] == "compression")


def test_design_follows_a_changed_cell_force(tmp_path):
    # Issue 3: raising configuration 3's upper cell force by 20 % changes the Upper Truss check.
    ex = _copy_examples(tmp_path)
    cfg = ex / "articulated_3457_envelopes.toml"
    main(["design", str(cfg), "--out", str(tmp_path / "before")])
    loads = ex / "loads" / "articulated.toml"
    text = loads.read_text()
    marker = 'name = "3"\n'
    i = text.index(marker)
    j = text.index("upper = {", i)
    loads.write_text(text[:j] + text[j:].replace(" }", ", factor = 1.2 }", 1))
    main(["design", str(cfg), "--out", str(tmp_path / "after")])
    before = json.loads((tmp_path / "before" / "summary.json").read_text())
    after = json.loads((tmp_path / "after" / "summary.json").read_text())
    p0, p1 = _upper_truss_load(before), _upper_truss_load(after)
    assert p1 > p0                   # PU1 grows with the upper cell force (not by 20 %: AF2 also loads it)
    env = after["loads"]["configurations"]["3457"]
    pu1 = next(r for r in env if r["member"] == "PU1")
    assert pu1["compression_configuration"] == "3" and -pu1["compression_N"] == pytest.approx(p1, rel=1e-12)


@pytest.mark.parametrize("edit,key", [
    ('member = "PU1"', 'member = "PU9"'),
    ('envelope = "3457", member = "PU1"', 'envelope = "34", member = "PU1"'),
    ('sense = "compression" }', 'sense = "squash" }'),
])
def test_bad_envelope_reference_exits_2(tmp_path, capsys, edit, key):
    ex = _copy_examples(tmp_path)
    cfg = ex / "articulated_3457_envelopes.toml"
    cfg.write_text(cfg.read_text().replace(edit, key, 1))
    assert main(["design", str(cfg), "--out", str(tmp_path / "o")]) == 2        # the command line, in process
    err = capsys.readouterr().err
    assert "Traceback" not in err
    assert "articulated_3457_envelopes.toml" in err and 'item["Upper Truss"].check["compression"].load' in err
    assert not (tmp_path / "o").exists()


@pytest.mark.parametrize("old,new,key", [
    ('"0.16 ft", "0.97 ft"', '"0.97 ft", "0.16 ft"', "configuration[0].upper.deflection"),
    ('AU = "44 in"', 'AU = "44 lbf"', "geometry.AU"),
    ('psi_final = "30 deg"', 'psi_final = "-30 deg"', "configuration[0].psi_final"),
    ('configurations = ["3", "4", "5", "7"]', 'configurations = ["3", "11"]', "combined[0].configurations"),
    ('theta = ', 'thetta = ', "truss.thetta"),
    ('name = "3"', 'name = "3/../x"', "configuration[0].name"),
])
def test_bad_loads_config_exits_2(tmp_path, old, new, key):
    ex = _copy_examples(tmp_path)
    loads = ex / "loads" / "articulated.toml"
    text = loads.read_text()
    assert old in text
    loads.write_text(text.replace(old, new, 1))
    r = subprocess.run([sys.executable, "-m", "alightsize", "loads", str(loads), "--out", str(tmp_path / "o")],
                       capture_output=True, text=True)
    assert r.returncode == 2 and "Traceback" not in r.stderr and key in r.stderr, r.stderr
    assert not (tmp_path / "o").exists()


def test_loads_are_deterministic(tmp_path):
    text = LOADS.read_text()
    one = tmp_path / "one.toml"                    # configuration 3 only: one heat map
    one.write_text(text[:text.index("[[configuration]]", text.index('name = "3"'))])
    for d in ("a", "b"):
        assert main(["loads", str(one), "--out", str(tmp_path / d)]) == 0
    for f in ("max_member_loads.json", "loads.md", "heatmap_3.png"):
        assert (tmp_path / "a" / f).read_bytes() == (tmp_path / "b" / f).read_bytes()
