"""Sweep runner (issue 6): study configs, Monte Carlo draws, the run store, backends, resumption."""

from __future__ import annotations

import json
import os
import signal
import sqlite3
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from alightsize.cli import main
from alightsize.common.typed import validate
from alightsize.landings.dispersions import DispersionTable, dispersion
from alightsize.common.errors import InputError
from alightsize.landings.run_store import TIMING
from alightsize.landings.study import read_study
from alightsize.landings.sweep import NEWEST_FIGURE, run_sweep
from alightsize.landings.probability import wilson_interval
from alightsize.reports.sweep_report import write_results
from conftest import ROOT

SCENE = ROOT / "examples" / "affdl-tr-66-33" / "scenes" / "telescoping_config2.toml"


def _study(tmp_path: Path, samples: int = 12, extra: str = "") -> Path:
    """A small Monte Carlo study about telescoping configuration 2 (about 50 ms per landing)."""
    path = tmp_path / "study.toml"
    path.write_text(f'''[study]
name = "mc"
seed = 7
samples = {samples}
[scenes]
c2 = "{SCENE}"
[grid]
"terrain.slope" = ["-10 deg", "10 deg"]
[dispersions]
"initial.velocity[1]" = {{ dist = "uniform", low = "0 ft/s", high = "10 ft/s" }}
"initial.heading" = {{ dist = "uniform", low = "-90 deg", high = "90 deg" }}
"terrain.mu_dynamic" = {{ dist = "truncated_normal", mean = 0.8, sd = 0.2, low = 0.4, high = 1.0 }}
"legs.cell_factors" = {{ dist = "normal", mean = 1.0, sd = 0.05, per_cell = true }}
[criteria]
preset = "instrument"
{extra}''')
    return path


def _contents(db: Path) -> list[tuple]:
    """Every stored run, timing columns left out, in run-id order."""
    con = sqlite3.connect(db)
    cur = con.execute("SELECT * FROM runs ORDER BY run_id")
    names = [d[0] for d in cur.description]
    rows = [tuple((k, v) for k, v in zip(names, r) if k not in TIMING) for r in cur]
    con.close()
    return rows


def test_truncated_normal_draws_have_the_closed_form_mean():
    """Mean of N(10, 1.146) truncated to [5, 12]: mu - sd (phi(b) - phi(a)) / (Phi(b) - Phi(a)) (closed form).
    200,000 draws: standard error sd_trunc / sqrt(n) < 0.003, so 0.01 is over three standard errors."""
    from scipy.stats import norm
    table = {"dist": "truncated_normal", "mean": "10 deg", "sd": "0.02 rad", "low": "5 deg", "high": "12 deg"}
    d = dispersion("s.toml", "x", validate(DispersionTable, table, "s.toml"))
    mu, sd, lo, hi = d.params
    a, b = (lo - mu) / sd, (hi - mu) / sd
    exact = mu - sd * (norm.pdf(b) - norm.pdf(a)) / (norm.cdf(b) - norm.cdf(a))
    x = d.draw(np.random.default_rng(1), (200_000,))
    assert d.unit == "degree" and x.min() >= lo and x.max() <= hi
    assert x.mean() == pytest.approx(exact, abs=0.01)


def test_a_dispersion_bound_beyond_any_float_is_bad_input():
    """An integer bound no float holds (TOML integers are unbounded here) is refused naming its key, not an
    internal error."""
    table = validate(DispersionTable, {"dist": "uniform", "low": 10 ** 400, "high": 1}, "s.toml")
    with pytest.raises(InputError, match=r"dispersions\.x\.low: expected a finite value"):
        dispersion("s.toml", "x", table)


def test_runs_depend_only_on_seed_and_sample(tmp_path):
    """Sample k draws the same values at every grid point and in every study size (default_rng([seed, k]))."""
    small = read_study(_study(tmp_path, samples=3))
    big = read_study(_study(tmp_path, samples=30))
    by_id = {r.run_id: r for r in big.runs}
    assert len(small.runs) == 6 and len(big.runs) == 60
    for r in small.runs:
        head, k = r.run_id.rsplit("-", 1)
        twin = by_id[f"{head}-{int(k):02d}"]
        assert r.overrides == twin.overrides
    first, second = big.runs[0], big.runs[30]
    assert first.overrides["initial.heading"] == second.overrides["initial.heading"]
    assert first.overrides["terrain.slope"] != second.overrides["terrain.slope"]


def test_backends_store_identical_runs(tmp_path):
    """Serial, a 2-process pool and a 2-worker Dask LocalCluster store the same runs.sqlite rows (every
    column but the timing ones), and outcomes.json agrees."""
    distributed = pytest.importorskip("distributed")
    study = read_study(_study(tmp_path))
    outs = {b: tmp_path / b for b in ("serial", "pool", "dask")}
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None) as cluster:
        for backend, out in outs.items():                   # dask through --scheduler's path: an address
            address = cluster.scheduler_address if backend == "dask" else None
            stats = run_sweep(study, out, backend, workers=2, scheduler=address, quiet=True)
            assert stats.computed == 24 and stats.failed == 0
    ref = _contents(outs["serial"] / "runs.sqlite")
    assert len(ref) == 24
    assert _contents(outs["pool"] / "runs.sqlite") == ref
    assert _contents(outs["dask"] / "runs.sqlite") == ref


def test_rerun_skips_done_runs_and_reruns_changed_ones(tmp_path):
    """A second sweep into the same folder computes nothing; changing a scene value reruns only the runs it
    changes (a new inputs hash)."""
    study = read_study(_study(tmp_path, samples=2))
    assert run_sweep(study, tmp_path / "o", "serial", quiet=True).computed == 4
    assert run_sweep(study, tmp_path / "o", "serial", quiet=True).computed == 0
    text = _study(tmp_path, samples=2).read_text().replace('"-10 deg", "10 deg"', '"-10 deg", "12 deg"')
    (tmp_path / "study.toml").write_text(text)
    changed = read_study(tmp_path / "study.toml")
    stats = run_sweep(changed, tmp_path / "o", "serial", quiet=True)
    assert (stats.computed, stats.skipped) == (2, 2)
    # a row stored by an earlier version, without the newest summary figure, lands again (and gains it)
    db = sqlite3.connect(tmp_path / "o" / "runs.sqlite")
    with db:
        db.execute(f"UPDATE runs SET {NEWEST_FIGURE} = NULL WHERE rowid IN (SELECT rowid FROM runs LIMIT 1)")
    stats = run_sweep(changed, tmp_path / "o", "serial", quiet=True)
    assert (stats.computed, stats.skipped) == (1, 3)
    assert db.execute(f"SELECT COUNT(*) FROM runs WHERE {NEWEST_FIGURE} IS NULL").fetchone() == (0,)
    db.close()


def test_a_run_that_raises_is_stored_failed_and_the_study_goes_on(tmp_path):
    """A dispersion that makes a bad scene value (mu_dynamic above mu_static) fails its run only."""
    path = _study(tmp_path, samples=4, extra="")
    text = path.read_text().replace("mean = 0.8, sd = 0.2, low = 0.4, high = 1.0",
                                    "mean = 1.6, sd = 0.2, low = 1.2, high = 2.0")
    text = text.replace("[grid]\n", '[grid]\n"terrain.mu_static" = [1.5]\n')
    path.write_text(text)
    study = read_study(path)
    stats = run_sweep(study, tmp_path / "o", "pool", workers=2, quiet=True)
    con = sqlite3.connect(tmp_path / "o" / "runs.sqlite")
    rows = con.execute("SELECT status, message, terrain_mu_dynamic FROM runs").fetchall()
    bad = [r for r in rows if r[2] > 1.5]
    assert bad and stats.failed == len(bad) and stats.computed == 8
    assert all(r[0] == "failed" and "terrain.mu_dynamic" in r[1] for r in bad)
    assert all(r[0] == "done" for r in rows if r[2] <= 1.5)
    doc = json.loads(write_results(study, tmp_path / "o")[0].read_text())
    assert sorted(doc["failed"]) == sorted(r.run_id for r in study.runs
                                           if r.overrides["terrain.mu_dynamic"] > 1.5)


def _crash_on_one_run(task):
    """A worker that dies (as on an out-of-memory kill) on one run; the others run normally."""
    from alightsize.landings import sweep
    if task["run_id"] == "c2-1-1":
        os._exit(9)
    return sweep._real_execute(task)


def test_a_dying_worker_loses_no_finished_run(tmp_path, monkeypatch):
    """The run that kills its worker is stored failed (after a retry alone); every other run is done."""
    from alightsize.landings import sweep
    if "fork" not in __import__("multiprocessing").get_all_start_methods():
        pytest.skip("the injected crash reaches the workers through fork")
    monkeypatch.setattr(sweep, "_real_execute", sweep.execute, raising=False)
    monkeypatch.setattr(sweep, "execute", _crash_on_one_run)
    study = read_study(_study(tmp_path, samples=4))
    stats = run_sweep(study, tmp_path / "o", "pool", workers=2, quiet=True)
    rows = dict(sqlite3.connect(tmp_path / "o" / "runs.sqlite").execute("SELECT run_id, status FROM runs"))
    assert len(rows) == 8 and stats.failed == 1
    assert rows.pop("c2-1-1") == "failed" and set(rows.values()) == {"done"}


def test_sigkill_mid_sweep_loses_nothing_and_recomputes_nothing(tmp_path):
    """kill -9 of a running sweep: every run committed before the kill survives with its finish time, and
    the re-run computes exactly the others."""
    path = _study(tmp_path, samples=40)
    out = tmp_path / "o"
    cmd = [sys.executable, "-m", "alightsize", "sweep", str(path), "--out", str(out), "--workers", "2", "--quiet"]
    proc = subprocess.Popen(cmd, cwd=ROOT, start_new_session=True, stdout=subprocess.DEVNULL)
    db = out / "runs.sqlite"
    deadline = time.time() + 120
    done = 0
    while time.time() < deadline and done < 10:
        time.sleep(0.2)
        if db.exists():
            try:
                done = sqlite3.connect(db).execute("SELECT count(*) FROM runs WHERE status='done'").fetchone()[0]
            except sqlite3.OperationalError:          # table not created yet
                pass
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    before = dict(sqlite3.connect(db).execute("SELECT run_id, finished_at FROM runs WHERE status='done'"))
    assert 10 <= len(before) < 80
    study = read_study(path)
    stats = run_sweep(study, out, "pool", workers=2, quiet=True)
    after = dict(sqlite3.connect(db).execute("SELECT run_id, finished_at FROM runs WHERE status='done'"))
    assert stats.skipped == len(before) and stats.computed == 80 - len(before)
    assert len(after) == 80 and all(after[k] == v for k, v in before.items())


def test_sweep_command_writes_the_contract_outputs(tmp_path):
    """`alightsize sweep --dask-local 2` writes runs.sqlite, outcomes.json (probabilities with Wilson intervals
    summing to the done runs), outcomes.xlsx and report.html; user text in the study is escaped in the report."""
    path = _study(tmp_path, samples=4)
    text = path.read_text().replace('name = "mc"', 'name = "mc"\ntitle = "<b>MC</b> =1+1"')
    path.write_text(text)
    pytest.importorskip("distributed")
    assert main(["sweep", str(path), "--out", str(tmp_path / "o"), "--dask-local", "2", "--quiet"]) == 0
    doc = json.loads((tmp_path / "o" / "outcomes.json").read_text())
    assert doc["schema"] == "alightsize.sweep/1" and doc["done"] == 8
    assert sum(v["count"] for v in doc["outcomes"].values()) == 8
    assert set(doc["outcomes"]) >= {"stable", "walking", "time_out", "tipped", "bottomed", "body_contact", "failed"}
    for v in doc["outcomes"].values():
        assert v["ci95"] == pytest.approx(list(wilson_interval(v["count"], 8)))
    html = (tmp_path / "o" / "report.html").read_text()
    assert "&lt;b&gt;MC&lt;/b&gt;" in html and "<b>MC" not in html
    from openpyxl import load_workbook
    ws = load_workbook(tmp_path / "o" / "outcomes.xlsx")["Runs"]
    assert all(c.data_type != "f" for row in ws.iter_rows() for c in row)


def test_study_input_errors_exit_2(tmp_path, capsys):
    """A dispersion without a seed, or of an unknown kind, is bad input naming the key."""
    path = _study(tmp_path).read_text()
    (tmp_path / "a.toml").write_text(path.replace("seed = 7\n", ""))
    assert main(["sweep", str(tmp_path / "a.toml"), "--out", str(tmp_path / "o")]) == 2
    assert "study.seed" in capsys.readouterr().err
    (tmp_path / "b.toml").write_text(path.replace('dist = "uniform"', 'dist = "lognormal"', 1))
    with pytest.raises(InputError) as e:
        read_study(tmp_path / "b.toml")
    assert "dispersions.initial.velocity[1].dist" in str(e.value) and "lognormal" in str(e.value)


@pytest.mark.parametrize("old, new, where, key, found", [
    ('"-10 deg", "10 deg"]', '"-10 deg", "abc"]', 'grid."terrain.slope"[1]', "terrain.slope", "found 'abc'"),
    ('"-10 deg", "10 deg"]', 'true, "10 deg"]', 'grid."terrain.slope"[0]', "terrain.slope", "found True"),
    ('"-10 deg", "10 deg"]', '"-10 deg", "3 ft/s"]', 'grid."terrain.slope"[1]', "terrain.slope", "found '3 ft/s'"),
    ('"terrain.slope" = [', '" " = [', 'grid." "[0]', '" "', "found '-10 deg'"),
    ('low = "0 ft/s", high = "10 ft/s"', 'low = "0 deg", high = "10 deg"', 'dispersions."initial.velocity[1]"',
     "initial.velocity[1]", "found a uniform distribution in degree centred on '5.0 degree'"),
    ('low = "-90 deg", high = "90 deg"', 'low = 0, high = 1', 'dispersions."initial.heading"', "initial.heading",
     "found a uniform distribution in plain numbers centred on 0.5"),
    ('low = "-90 deg", high = "90 deg"', 'low = "-90 deg", high = "1e30 deg"', 'dispersions."initial.heading"',
     "initial.heading", "found a uniform distribution in degree centred on '5e+29 degree'")])
def test_a_grid_or_dispersion_value_the_scene_refuses_exits_2_before_any_run(tmp_path, capsys, old, new, where, key,
                                                                             found):
    """A value its scene key does not take (a word, true, another dimension, an unknown key, an angle of 5e29
    deg at the centre of a dispersion) is named as written in the study, with what the scene key takes; nothing
    is run (no run store)."""
    path = _study(tmp_path, samples=2)
    path.write_text(path.read_text().replace(old, new, 1))
    assert main(["sweep", str(path), "--out", str(tmp_path / "o"), "--serial"]) == 2
    err = capsys.readouterr().err
    assert f"{path}: {where}: expected what the scene key {key} of {SCENE.name} takes: " in err and found in err
    assert not (tmp_path / "o").exists()


def test_history_per_run_on_request(tmp_path):
    """`history = true` keeps each run's history Parquet beside the store; its last time is the run's end."""
    import pandas as pd
    path = _study(tmp_path, samples=1)
    path.write_text(path.read_text().replace("samples = 1\n", "samples = 1\nhistory = true\n"))
    study = read_study(path)
    run_sweep(study, tmp_path / "o", "serial", quiet=True)
    rows = sqlite3.connect(tmp_path / "o" / "runs.sqlite").execute("SELECT history_file, t_end_s FROM runs").fetchall()
    assert len(rows) == 2
    for rel, t_end in rows:
        h = pd.read_parquet(tmp_path / "o" / rel)
        assert h["t_s"].iloc[-1] == pytest.approx(t_end, abs=1e-12)


def _grid_study(tmp_path: Path, slopes: list[str], criteria: str = "instrument") -> Path:
    path = tmp_path / "grid.toml"
    values = ", ".join(f'"{s}"' for s in slopes)
    path.write_text(f'''[study]
name = "ml"
[scenes]
ML = "{SCENE}"
[grid]
"terrain.slope" = [{values}]
"initial.velocity[1]" = ["0 ft/s", "10 ft/s", "15 ft/s"]
[criteria]
preset = "{criteria}"
''')
    return path


def test_a_grown_grid_computes_only_its_new_points_and_keeps_no_orphaned_rows(tmp_path):
    """Runs are keyed by their inputs: growing an axis from 3 to 4 values renumbers ML-1 ... ML-9 as
    ML-01 ... ML-12, yet only the 3 new points are landed, the 9 stored rows move to their new ids with the
    same figures, and the store holds exactly the study's 12 runs. A changed criterion re-judges stored runs
    without landing them again."""
    out = tmp_path / "out"
    first = run_sweep(read_study(_grid_study(tmp_path, ["-10 deg", "0 deg", "10 deg"])), out, "serial", quiet=True)
    assert (first.computed, first.skipped) == (9, 0)
    before = {json.loads(r[1])["terrain.slope"] + json.loads(r[1])["initial.velocity[1]"]: r[2:] for r in
              sqlite3.connect(out / "runs.sqlite").execute("SELECT run_id, params_json, scene_hash, peak_xdd3_g "
                                                           "FROM runs")}
    study = read_study(_grid_study(tmp_path, ["-10 deg", "0 deg", "10 deg", "20 deg"]))
    assert [r.run_id for r in study.runs][:2] == ["ML-01", "ML-02"]
    grown = run_sweep(study, out, "serial", quiet=True)
    assert (grown.computed, grown.skipped, grown.reused) == (3, 9, 9)
    con = sqlite3.connect(out / "runs.sqlite")
    rows = con.execute("SELECT run_id, params_json, scene_hash, peak_xdd3_g FROM runs").fetchall()
    assert sorted(r[0] for r in rows) == sorted(r.run_id for r in study.runs)
    for run_id, params, h, peak in rows:
        p = json.loads(params)
        key = p["terrain.slope"] + p["initial.velocity[1]"]
        if key in before:
            assert (h, peak) == before[key]                 # the same stored landing, under its new id
    assert not any("onset" in v for (v,) in con.execute("SELECT criteria_failed FROM runs"))   # no onset limit
    strict = run_sweep(read_study(_grid_study(tmp_path, ["-10 deg", "0 deg", "10 deg", "20 deg"], "human")), out,
                       "serial", quiet=True)
    assert (strict.computed, strict.skipped) == (0, 12)
    # The human preset limits onset to 1000 g/s on axes 1-2 (Sec. II.A.1): stored runs are judged by it now.
    onsets = dict(con.execute("SELECT run_id, max(peak_onset_xdd1_g_s, peak_onset_xdd2_g_s) FROM runs"))
    judged = dict(con.execute("SELECT run_id, criteria_failed FROM runs"))
    assert any(v > 1000 for v in onsets.values())
    assert all(("XDD(1) onset" in judged[k] or "XDD(2) onset" in judged[k]) == (v > 1000) for k, v in onsets.items())


@pytest.mark.parametrize("key", ["../../x", "/tmp/x", "a/b", "a\\b", ".hidden", "-x", ""])
def test_a_scene_key_that_would_name_a_file_outside_the_output_exits_2(tmp_path, key, capsys):
    """Scene keys and run ids name history files: separators, '..' and absolute paths are refused, so no
    file can be written outside --out."""
    study = _study(tmp_path, 1).read_text().replace('c2 = "', f'{json.dumps(key)} = "')
    path = tmp_path / "bad.toml"
    path.write_text(study.replace("[study]", "[study]\nhistory = true"))
    assert main(["sweep", str(path), "--out", str(tmp_path / "out"), "--serial"]) == 2
    assert "scenes." in capsys.readouterr().err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.toml", "study.toml"]


def test_a_run_table_id_with_a_separator_exits_2(tmp_path, capsys):
    (tmp_path / "runs.csv").write_text("run,scene\n../../x,c2\n")
    path = tmp_path / "t.toml"
    path.write_text(f'[study]\nhistory = true\n[scenes]\nc2 = "{SCENE}"\n[runs]\ntable = "runs.csv"\n')
    assert main(["sweep", str(path), "--out", str(tmp_path / "out"), "--serial"]) == 2
    assert "runs.csv line 2, run" in capsys.readouterr().err
    assert not (tmp_path / "out").exists()


def test_a_run_table_that_is_not_utf8_exits_2(tmp_path, capsys):
    (tmp_path / "runs.csv").write_bytes("run,scene\nr\xe9,c2\n".encode("latin-1"))
    path = tmp_path / "t.toml"
    path.write_text(f'[study]\n[scenes]\nc2 = "{SCENE}"\n[runs]\ntable = "runs.csv"\n')
    assert main(["sweep", str(path), "--out", str(tmp_path / "out"), "--serial"]) == 2
    assert "runs.table" in capsys.readouterr().err


def test_column_names_from_user_input_are_quoted_identifiers(tmp_path):
    """A parameter or cell name with quotes and SQL in it is stored as a column of exactly that name."""
    from alightsize.landings.run_store import RunStore
    name = 'a"b); DROP TABLE runs; --'
    store = RunStore(tmp_path / "runs.sqlite")
    store.put({"run_id": "r1", "status": "done", name: 1.5})
    store.put({"run_id": "r2", "status": "done", name: 2.5})
    assert [r[name] for r in store.rows(["r1", "r2"])] == [1.5, 2.5]
    store.close()


def test_a_second_command_on_the_same_output_folder_is_refused(tmp_path, capsys):
    """A folder another alightsize command is writing (its lock held here) is refused with exit 2, the store
    untouched; leftovers of an interrupted write are removed by the next command that takes the folder."""
    from alightsize.common.lock import output_folder
    out = tmp_path / "out"
    with output_folder(out):
        assert main(["sweep", str(_study(tmp_path, 1)), "--out", str(out), "--serial"]) == 2
        assert "in use by another alightsize process" in capsys.readouterr().err
        assert list(out.iterdir()) == []
    (out / "sub").mkdir(parents=True)          # (the lock removed the folder it made and left empty)
    (out / "sub" / ".history.parquet.k3j.tmp").write_bytes(b"half")
    with output_folder(out):
        assert not (out / "sub" / ".history.parquet.k3j.tmp").exists()


def test_a_repeated_grid_value_exits_2_naming_it(tmp_path, capsys):
    """A grid value written twice would make the same landings twice: refused at its second place, naming the
    first; nothing is run."""
    path = _grid_study(tmp_path, ["0 deg", "5 deg", "0 deg"])
    assert main(["sweep", str(path), "--out", str(tmp_path / "o"), "--serial"]) == 2
    err = capsys.readouterr().err
    assert f'{path}: grid."terrain.slope"[2]: expected distinct values' in err and "[0] is the same" in err
    assert not (tmp_path / "o").exists()
