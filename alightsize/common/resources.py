"""Where the shipped data folders (materials/, templates/, examples/) are, installed or in a source checkout."""

from __future__ import annotations

from pathlib import Path

_PACKAGE = Path(__file__).resolve().parents[1]           # the alightsize package


def data_dir(name: str) -> Path:
    """`materials`, `templates` or `examples`: inside the installed wheel (alightsize/_data/NAME) or the checkout
    root."""
    for candidate in (_PACKAGE / "_data" / name, _PACKAGE.parent / name):
        if candidate.is_dir():
            return candidate
    raise FileNotFoundError(f"alightsize data folder {name!r} not found next to {_PACKAGE}")
