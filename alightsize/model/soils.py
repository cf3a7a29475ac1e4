"""Soil files: one TOML file per soil (materials/soils/ ships the presets; docs/soil.md), read to
alightsize_sim.soil.Soil in SI. Scenes name a preset by its file stem or give a path to a file of their own."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Annotated, Any

from alightsize_sim.soil import Soil

from pydantic import PlainValidator, model_validator

from alightsize.common.config import is_file, load_toml
from alightsize.common.typed import Number, Quantity, Table, refuse, validate
from alightsize.common.errors import InputError
from alightsize.common.resources import data_dir

_UNITS = {"k_c": "N/m^(n+1)", "k_phi": "N/m^(n+2)", "c": "Pa", "gamma": "N/m^3"}   # SI base unit of each key
_PREFIX = {"": 1.0, "k": 1e3, "M": 1e6}
N_MAX = 3.0              # sinkage exponent: Bekker fits of real soils lie from 0 to about 1.6 (Wong 2008 Ch. 2)
VALUE_RANGE = (1e-6, 1e12)   # k_c, k_phi, c, gamma in SI, or 0: every soil's (gamma: 1e3-3e4 N/m^3) with room
PHI_MAX_DEG = 60.0       # friction angle: soils lie below about 50 deg; tan^2(45 + phi/2) grows without bound


def _soil_value(value: Any, key: str) -> float:
    """A value as the file states it, "NUMBER UNIT" with the key's SI unit, optionally prefixed k or M (the
    unit of k_c and k_phi depends on n, so it is spelled with n)."""
    low, high = VALUE_RANGE
    expected = f'a value like "1.4 k{_UNITS[key]}" (prefix k or M allowed), 0 or {low:g} to {high:g} {_UNITS[key]}'
    try:
        number, unit = str(value).split(maxsplit=1)
        si = float(number)
    except ValueError:
        raise refuse(expected, repr(value)) from None
    si *= _PREFIX.get(unit[: len(unit) - len(_UNITS[key])], math.nan)
    if not unit.endswith(_UNITS[key]) or not (si == 0 or low <= si <= high):      # NaN fails too
        raise refuse(expected, repr(value))
    return si


def SoilValue(key: str) -> PlainValidator:  # noqa: N802 - a type's validator: Annotated[float, SoilValue("c")]
    return PlainValidator(lambda v: _soil_value(v, key))


class SoilFile(Table):
    """A soil file (docs/soil.md): Bekker's n, k_c, k_phi and the Mohr-Coulomb c, phi, with the unit weight."""

    name: str
    n: Annotated[float, Number("any")]
    k_c: Annotated[float, SoilValue("k_c")]
    k_phi: Annotated[float, SoilValue("k_phi")]
    c: Annotated[float, SoilValue("c")]
    phi: Annotated[float, Quantity("angle", "any")]
    gamma: Annotated[float, SoilValue("gamma")]
    source: dict[str, str] = {}

    @model_validator(mode="after")
    def _ranges(self):
        if not 0 <= self.n <= N_MAX:
            raise refuse(f"a sinkage exponent from 0 to {N_MAX:g} (Bekker fits: 0 to about 1.6)", repr(self.n), "n")
        if self.k_c + self.k_phi <= 0:
            raise refuse("k_c + k_phi above zero (a soil that bears a load)", "both zero", "k_phi")
        if not 0 <= self.phi <= math.radians(PHI_MAX_DEG):
            raise refuse(f"a friction angle from 0 to {PHI_MAX_DEG:g} deg", f"{math.degrees(self.phi):.4g} deg",
                         "phi")
        return self


def read_soil(path: str | Path) -> Soil:
    """One soil file: name, n, k_c, k_phi, c, phi, gamma with their units, and a [source] table."""
    f = validate(SoilFile, load_toml(path).data, str(path))
    return Soil(f.n, f.k_c, f.k_phi, f.c, f.phi, f.gamma, f.name, f.source)


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
