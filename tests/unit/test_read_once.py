"""A lander file is read once per command: the scene it implies is built from the parsed file, and the landing
tasks get the parsed scene, not a path to read again (forked workers included: the spy logs to a file)."""

import importlib
import pkgutil
import sys
from pathlib import Path

import pytest

import alightsize
import alightsize.common.config as config
from alightsize.cli import main
from conftest import ROOT

# A level lunar drop at 3 m/s, its 2 corners and 2 Monte Carlo landings per candidate, one generation of 3: a
# search of seconds (as tests/test_synthesis.py cuts the example)
SMALL_SEARCH = """
[requirements.envelope]
vertical_speed = "3 m/s"

[requirements.monte_carlo]
samples = 2
seed = 5

[synthesis]
seed = 11
generations = 1
population = 3
check_samples = 2

[synthesis.free]
"cells.axial.crush_force" = ["4 kN", "16 kN"]
"""


@pytest.fixture
def reads(tmp_path, monkeypatch):
    """The paths load_toml reads from now on, wherever it was imported (a file, so forked workers count)."""
    log = tmp_path / "reads.log"
    original = config.load_toml
    for info in pkgutil.walk_packages(alightsize.__path__, "alightsize."):     # every importer of load_toml
        if info.name != "alightsize.__main__":
            importlib.import_module(info.name)

    def spy(path):
        with open(log, "a", encoding="utf-8") as f:
            f.write(f"{Path(path).resolve()}\n")
        return original(path)
    for module in list(sys.modules.values()):
        if getattr(module, "load_toml", None) is original:
            monkeypatch.setattr(module, "load_toml", spy)
    return lambda p: log.read_text(encoding="utf-8").splitlines().count(str(p.resolve())) if log.exists() else 0


@pytest.fixture
def lander(tmp_path) -> Path:
    """The lunar example with 4 Monte Carlo landings (16 envelope corners and 4 samples: 20 landing tasks)."""
    text = (ROOT / "examples" / "lunar_lander.toml").read_text(encoding="utf-8")
    assert "samples = 100" in text
    p = tmp_path / "lander.toml"
    p.write_text(text.replace("samples = 100", "samples = 4"), encoding="utf-8")
    return p


def test_design_reads_the_lander_file_once(lander, reads, tmp_path):
    assert main(["design", str(lander), "--out", str(tmp_path / "out")]) in (0, 1)     # 1: a design that fails
    assert reads(lander) == 1


def test_simulate_reads_the_lander_file_once(lander, reads, tmp_path):
    assert main(["simulate", str(lander), "--out", str(tmp_path / "out")]) == 0
    assert reads(lander) == 1


def test_synthesize_reads_the_lander_file_once(reads, tmp_path):
    text = (ROOT / "examples" / "lunar_lander.toml").read_text(encoding="utf-8")
    assert "[requirements.envelope]" in text and 't_final = "20 s"' in text
    lander = tmp_path / "small.toml"
    lander.write_text(text[:text.index("[requirements.envelope]")].replace('t_final = "20 s"', 't_final = "3 s"')
                      + SMALL_SEARCH, encoding="utf-8")
    assert main(["synthesize", str(lander), "--out", str(tmp_path / "out"), "--serial", "--no-trade"]) == 0
    assert reads(lander) == 1


def test_design_reads_each_item_table_once(monkeypatch, tmp_path):
    """An [[item]] table is read once: envelope references are resolved from the computed loads afterwards, not by
    reading the table again (the 1966 telescoping config: its items, each read exactly once)."""
    import tomllib

    import alightsize.pipeline.config as design_config
    path = ROOT / "examples" / "affdl-tr-66-33" / "telescoping.toml"
    names = [i["name"] for i in tomllib.loads(path.read_text(encoding="utf-8"))["item"]]
    read = []
    original = design_config.read_item

    def spy(node, *args):
        read.append(node.data["name"])
        return original(node, *args)
    monkeypatch.setattr(design_config, "read_item", spy)
    assert main(["design", str(path), "--out", str(tmp_path / "out")]) in (0, 1)      # 1: a design that fails
    assert sorted(read) == sorted(names)
