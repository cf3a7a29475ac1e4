"""The package's layers: data goes down the pipeline, never back up. alightsize's folders in pipeline order; a
module imports only its own layer or lower ones (function-level imports included), and the simulator
alightsize_sim never imports alightsize."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

import alightsize
import alightsize_sim

ORDER = ("common", "model", "landings", "loads", "checks", "weights", "pipeline", "synthesis", "reports", "cli")
PACKAGE = Path(alightsize.__file__).parent
SIMULATOR = Path(alightsize_sim.__file__).parent


def _imports(path: Path) -> set[str]:
    """Every module a file names in an import, with `from a import b` read as both a and a.b."""
    out: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            out |= {node.module} | {f"{node.module}.{a.name}" for a in node.names}
        elif isinstance(node, ast.Import):
            out |= {a.name for a in node.names}
    return out


def _layer(module: str) -> int | None:
    """The index in ORDER of an alightsize module's folder (cli.py is the cli layer); None outside them."""
    parts = module.split(".")
    return ORDER.index(parts[1]) if parts[0] == "alightsize" and len(parts) > 1 and parts[1] in ORDER else None


def _module(path: Path) -> str:
    return ".".join(("alightsize",) + path.relative_to(PACKAGE).with_suffix("").parts)


def test_the_layer_rule_sees_an_upward_import(tmp_path):
    """The rule itself: a checks module importing pipeline is flagged, one importing model is not."""
    up, down = tmp_path / "up.py", tmp_path / "down.py"
    up.write_text("def f():\n    from alightsize.pipeline.design import design\n")
    down.write_text("from alightsize.model import scene_config\n")
    here = ORDER.index("checks")
    assert sorted(m for m in _imports(up) if (_layer(m) or -1) > here) == ["alightsize.pipeline.design",
                                                                           "alightsize.pipeline.design.design"]
    assert not [m for m in _imports(down) if (_layer(m) or -1) > here]


@pytest.mark.parametrize("path", sorted(PACKAGE.rglob("*.py")), ids=lambda p: str(p.relative_to(PACKAGE)))
def test_no_module_imports_a_higher_layer(path):
    here = _layer(_module(path))
    if here is None:                                   # alightsize/__init__.py and __main__.py sit above all layers
        return
    upward = sorted(m for m in _imports(path) if (_layer(m) or -1) > here)
    assert not upward, f"{_module(path)} ({ORDER[here]}) imports {upward}"


def test_the_simulator_never_imports_alightsize():
    named = {str(p.relative_to(SIMULATOR)): sorted(m for m in _imports(p) if m.split(".")[0] == "alightsize")
             for p in SIMULATOR.rglob("*.py")}
    assert not {k: v for k, v in named.items() if v}
