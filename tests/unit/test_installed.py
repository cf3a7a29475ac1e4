"""Every command from a plain (non-editable) install: the wheel is built from this checkout, installed into a
scratch folder and run from a folder that is not the checkout, so nothing can fall back on the source tree."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import zipfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

from conftest import ROOT


@pytest.fixture(scope="module")
def installed(tmp_path_factory):
    """(site folder holding only the installed wheel, the wheel's path)."""
    base = tmp_path_factory.mktemp("wheel")
    subprocess.run([sys.executable, "-m", "pip", "wheel", "-q", "--no-deps", "--no-build-isolation", "-w", str(base),
                    str(ROOT)], check=True, capture_output=True)
    wheel = next(base.glob("alightsize-*.whl"))
    site = base / "site"
    subprocess.run([sys.executable, "-m", "pip", "install", "-q", "--no-deps", "--target", str(site), str(wheel)],
                   check=True, capture_output=True)
    return site, wheel


def _env(site: Path) -> dict[str, str]:
    """The install alone on the path; numba's cache in the scratch folder's user cache (not the user's)."""
    env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    return {**env, "PYTHONPATH": str(site), "PYTHONSAFEPATH": "1", "XDG_CACHE_HOME": str(site.parent / "cache")}


def _run(site: Path, cwd: Path, *args: str) -> subprocess.CompletedProcess:
    env = _env(site)
    return subprocess.run([sys.executable, "-m", "alightsize", *args], cwd=cwd, env=env, capture_output=True, text=True,
                          timeout=900)


def test_the_wheel_carries_its_own_namespace_data_and_licence(installed):
    """Top-level packages are alightsize and alightsize_sim only (no 'sim'); the examples, materials, templates
    and LICENSE travel with it."""
    _, wheel = installed
    names = zipfile.ZipFile(wheel).namelist()
    top = {n.split("/")[0] for n in names if not n.split("/")[0].endswith(".dist-info")}
    assert top == {"alightsize", "alightsize_sim"}
    for folder in ("examples/affdl-tr-66-33/scenes", "examples/affdl-tr-66-33/drops", "materials", "templates"):
        assert any(n.startswith(f"alightsize/_data/{folder}/") for n in names), folder
    assert any(n.endswith(".dist-info/licenses/LICENSE") or n.endswith(".dist-info/LICENSE") for n in names)


@pytest.fixture(scope="module")
def ran(installed, tmp_path_factory):
    """design, audit, loads, simulate, sweep, scale, reports and bench, each from the install alone, in a
    scratch folder: (that folder, {command: completed process, expected exit status and output file})."""
    site, _ = installed
    tmp_path = tmp_path_factory.mktemp("cwd")
    shipped = site / "alightsize" / "_data" / "examples" / "affdl-tr-66-33"
    where = subprocess.run([sys.executable, "-c", "import alightsize, alightsize_sim; print(alightsize.__file__); "
                            "print(alightsize_sim.__file__)"], cwd=tmp_path, capture_output=True, text=True,
                           env=_env(site), check=True)
    assert all(Path(p).is_relative_to(site) for p in where.stdout.split())
    study = tmp_path / "study.toml"
    study.write_text(f'[study]\nname = "tiny"\nseed = 1\nsamples = 2\n\n[scenes]\n2 = "{shipped}/scenes/'
                     'telescoping_config2.toml"\n\n[dispersions]\n"initial.velocity[2]" = { dist = "uniform", '
                     'low = "-32 ft/s", high = "-28 ft/s" }\n')
    expected = {  # command -> (exit status, a file it must write)
        ("design", str(shipped / "telescoping.toml"), "--out", "d"): (0, "d/report.html"),
        ("audit", str(shipped / "telescoping.toml"), "--json", "audit.json"): (0, "audit.json"),
        ("loads", str(shipped / "loads" / "telescoping.toml"), "--out", "l"): (0, "l/max_member_loads.json"),
        ("simulate", str(shipped / "scenes" / "flat_drop.toml"), "--out", "s"): (0, "s/summary.json"),
        ("sweep", str(study), "--out", "w", "--workers", "1"): (0, "w/outcomes.json"),
        ("scale", "--length", "2", "--mass", "8", "--json", "scale.json"): (0, "scale.json"),
        ("reports", "--out", "r"): (0, "r/drops/drops.json"),
        ("bench", "--quick", "--scene", "flat_drop", "--out", "b"): (0, "b/bench.json"),
    }
    with ThreadPoolExecutor(2) as pool:                 # two commands at a time: one per core of the CI machine
        done = dict(zip(expected, pool.map(lambda args: _run(site, tmp_path, *args), expected)))
    return tmp_path, {args: (done[args], status, output) for args, (status, output) in expected.items()}


def test_every_command_runs_from_the_installed_wheel(ran):
    cwd, runs = ran
    for args, (run, status, output) in runs.items():
        assert run.returncode == status, (args, run.stdout[-2000:], run.stderr[-2000:])
        assert "Traceback" not in run.stderr, args
        assert (cwd / output).stat().st_size > 0, args
    assert json.loads((cwd / "b" / "bench.json").read_text())["schema"] == "alightsize.bench/1"
    assert {p.name for p in (cwd / "r").iterdir()} >= {"telescoping", "articulated_3457", "drops"}


def test_the_installed_commands_write_nothing_into_the_package(installed, ran):
    """numba's compiled code goes to the user cache folder, never into the installed packages."""
    site, _ = installed
    assert not [p for p in site.rglob("*") if p.suffix in (".nbi", ".nbc")]
    if sys.platform.startswith("linux"):                          # platformdirs follows XDG_CACHE_HOME there
        assert any((site.parent / "cache" / "alightsize").rglob("*.nbi"))


def test_the_bench_times_every_case_alike_and_states_its_spread(ran):
    """Baselines and compiled cases get the same repeats after a warm-up call; each case gives the median
    between its least and largest; the page rounds every figure (no 0.25120438168280024), keeps the picture
    in the column and speaks of the method, not of the project's history."""
    cwd, _ = ran
    data = json.loads((cwd / "b" / "bench.json").read_text())
    assert len({c["repeats"] for c in data["cases"]}) == 1 and data["cases"][0]["repeats"] >= 3
    assert {c["compiled"] for c in data["cases"]} == {True, False}
    for c in data["cases"]:
        assert c["wall_min_s"] <= c["wall_s"] <= c["wall_max_s"], c
    page = (cwd / "b" / "bench.html").read_text()
    text = re.sub(r"<[^>]+>", " ", page.split("</style>")[1])
    assert not re.findall(r"\d\.\d{5,}", text)
    assert "issue" not in text.lower()
    assert re.search(r"img\s*\{[^}]*max-width:\s*100%", page)
    from PIL import Image
    assert Image.open(cwd / "b" / "work_precision.png").size[0] <= 1400
