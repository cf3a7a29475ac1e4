"""Soil files: one TOML file per soil (materials/soils/ ships the presets; docs/soil.md), read to
alightsize_sim.soil.Soil in SI. Scenes name a preset by its file stem or give a path to a file of their own."""

from __future__ import annotations

import math
from pathlib import Path

from alightsize_sim.soil import Soil

from alightsize.common.config import Node, is_file, load_toml
from alightsize.common.errors import InputError
from alightsize.common.resources import data_dir

_UNITS = {"k_c": "N/m^(n+1)", "k_phi": "N/m^(n+2)", "c": "Pa", "gamma": "N/m^3"}   # SI base unit of each key
_PREFIX = {"": 1.0, "k": 1e3, "M": 1e6}
N_MAX = 3.0              # sinkage exponent: Bekker fits of real soils lie from 0 to about 1.6 (Wong 2008 Ch. 2)
VALUE_RANGE = (1e-6, 1e12)   # k_c, k_phi, c, gamma in SI, or 0: every soil's (gamma: 1e3-3e4 N/m^3) with room
PHI_MAX_DEG = 60.0       # friction angle: soils lie below about 50 deg; tan^2(45 + phi/2) grows without bound


def _quantity(node: Node, key: str) -> float:
    """A value as the file states it, "NUMBER UNIT" with the key's SI unit, optionally prefixed k or M (the
    unit of k_c and k_phi depends on n, so it is spelled with n)."""
    text = node.raw(key)
    low, high = VALUE_RANGE
    expected = f'a value like "1.4 k{_UNITS[key]}" (prefix k or M allowed), 0 or {low:g} to {high:g} {_UNITS[key]}'
    try:
        number, unit = str(text).split(maxsplit=1)
        value = float(number)
    except ValueError:
        raise node.error(key, expected, repr(text)) from None
    prefix = unit[: len(unit) - len(_UNITS[key])]
    si = value * _PREFIX.get(prefix, math.nan)
    if not unit.endswith(_UNITS[key]) or not (si == 0 or low <= si <= high):      # NaN fails too
        raise node.error(key, expected, repr(text))
    return si


def read_soil(path: str | Path) -> Soil:
    """One soil file: name, n, k_c, k_phi, c, phi, gamma with their units, and a [source] table."""
    node = load_toml(path)
    node.allow(("name", "n", "k_c", "k_phi", "c", "phi", "gamma", "source"))
    name = node.string("name")
    n = node.number("n", positive=False)
    if not 0 <= n <= N_MAX:
        raise node.error("n", f"a sinkage exponent from 0 to {N_MAX:g} (Bekker fits: 0 to about 1.6)", repr(n))
    values = {k: _quantity(node, k) for k in ("k_c", "k_phi", "c", "gamma")}
    if values["k_c"] + values["k_phi"] <= 0:
        raise node.error("k_phi", "k_c + k_phi above zero (a soil that bears a load)", "both zero")
    phi = node.quantity("phi", "angle", positive=False)
    if not 0 <= phi <= math.radians(PHI_MAX_DEG):
        raise node.error("phi", f"a friction angle from 0 to {PHI_MAX_DEG:g} deg", repr(node.raw("phi")))
    src = node.table("source", optional=True)
    source = {k: src.string(k) for k in list(src.data)} if src else {}
    if src:
        src.finish()
    node.finish()
    return Soil(n, values["k_c"], values["k_phi"], values["c"], phi, values["gamma"], name, source)


def soil_presets() -> dict[str, Soil]:
    """The shipped soils, keyed by file stem (materials/soils/*.toml)."""
    return {p.stem: read_soil(p) for p in sorted((data_dir("materials") / "soils").glob("*.toml"))}


def find_soil(name: str, base: Path, file: str, key: str) -> Soil:
    """The soil a scene names at `key`: a preset's name or a soil file's path (relative to `base`)."""
    presets = soil_presets()
    if name in presets:
        return presets[name]
    path = base / name
    if not is_file(path):
        raise InputError(file, key, "a shipped soil (" + ", ".join(sorted(presets)) + ") or a soil file's path",
                         repr(name))
    return read_soil(path)
