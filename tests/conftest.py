"""Shared fixtures (paths of the shipped examples) and the folder markers: tests/unit/ is `unit`, tests/validation/
(the report's numbers, textbook cases, closed forms) is `validation`; `pytest -m validation` runs those alone."""

from pathlib import Path

import pytest
from hypothesis import settings

# Property tests draw the same examples on every run and machine (seeded randomness only): a failure reproduces.
settings.register_profile("alightsize", derandomize=True, deadline=None, database=None)
settings.load_profile("alightsize")

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples" / "affdl-tr-66-33"
CONFIGS = ["telescoping", "articulated_3457", "articulated_68", "articulated_9"]


@pytest.fixture(params=CONFIGS)
def example(request) -> Path:
    return EXAMPLES / f"{request.param}.toml"


def pytest_collection_modifyitems(config, items):
    for item in items:
        folder = Path(str(item.fspath)).parent.name
        if folder in ("unit", "validation"):
            item.add_marker(folder)
