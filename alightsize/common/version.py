"""The installed package's version, from its metadata (a source tree without installing: "0+unknown")."""

from __future__ import annotations

from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("alightsize")
except PackageNotFoundError:                           # run from a source tree without installing
    __version__ = "0+unknown"
