"""Shared fixtures: paths of the shipped examples."""

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples" / "affdl-tr-66-33"
CONFIGS = ["telescoping", "articulated_3457", "articulated_68", "articulated_9"]


@pytest.fixture(params=CONFIGS)
def example(request) -> Path:
    return EXAMPLES / f"{request.param}.toml"
