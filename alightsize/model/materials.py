"""Material property data: one TOML file per material under materials/, users add more by path."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Annotated

from pydantic import model_validator

from alightsize.common.config import Node, is_dir, is_file, load_toml
from alightsize.common.typed import Number, Quantity, Table, refuse, validate
from alightsize.common.errors import InputError
from alightsize.common.resources import data_dir


@dataclass(frozen=True)
class Material:
    """Properties in SI; a property the file does not give is None."""

    key: str
    name: str
    density: float
    yield_strength: float | None = None
    elastic_modulus: float | None = None
    poisson_m: float | None = None
    crush_strength: float | None = None        # crushable cores: the crushing stress
    stroke_fraction: float | None = None       # crushable cores: usable stroke / core length
    compressive_strength: float | None = None  # sandwich cores: flatwise (stabilised) compressive strength
    shear_strength: float | None = None        # sandwich cores: transverse shear strength (the weaker direction)
    shear_modulus: float | None = None         # sandwich cores: transverse shear modulus (the weaker direction)
    cell_size: float | None = None             # honeycomb cores: the cell's inscribed circle diameter
    source: dict = field(default_factory=dict)

    def value(self, prop: str) -> float:
        """A property a formula uses. A design refuses a material without the properties its checks need before
        any check runs (alightsize.pipeline.items), so a missing one here is a programming error."""
        v = getattr(self, prop)
        if v is None:
            raise ValueError(f"material {self.key} has no {prop}")
        return v


class MaterialFile(Table):
    """A material file (docs/reference/materials.md)."""

    name: str
    density: Annotated[float, Quantity("density")]
    yield_strength: Annotated[float, Quantity("stress")] | None = None
    elastic_modulus: Annotated[float, Quantity("stress")] | None = None
    poisson_m: Annotated[float, Number()] | None = None
    crush_strength: Annotated[float, Quantity("stress")] | None = None
    stroke_fraction: Annotated[float, Number()] | None = None
    compressive_strength: Annotated[float, Quantity("stress")] | None = None
    shear_strength: Annotated[float, Quantity("stress")] | None = None
    shear_modulus: Annotated[float, Quantity("stress")] | None = None
    cell_size: Annotated[float, Quantity("length")] | None = None
    source: dict[str, str] = {}

    @model_validator(mode="after")
    def _stroke(self):
        if self.stroke_fraction is not None and not 0 < self.stroke_fraction <= 1:
            raise refuse("the usable stroke as a fraction of the core length, in (0, 1]", repr(self.stroke_fraction),
                         "stroke_fraction")
        return self


def read_material(path: str | Path) -> Material:
    f = validate(MaterialFile, load_toml(path).data, str(path))
    return Material(Path(path).stem, **f.model_dump())


def material_paths(texts: list[str], base: Path, file: str, key: str) -> list[Path]:
    """The extra material files or folders a config lists at `key`, relative to `base` (its folder)."""
    out = []
    for text in texts:
        path = base / text
        if not text.strip() or not (path.suffix == ".toml" and is_file(path) or is_dir(path)):
            raise InputError(file, key, "paths of material files (.toml) or folders of them, relative to this file",
                             repr(text))
        out.append(path)
    return out


def library(extra_paths: Iterable[str | Path] = ()) -> dict[str, Material]:
    """The shipped materials plus those at `extra_paths` (files or folders), keyed by file stem."""
    files = sorted(data_dir("materials").glob("*.toml"))
    for p in extra_paths:
        p = Path(p)
        files += sorted(p.glob("*.toml")) if p.is_dir() else [p]
    return {Path(f).stem: read_material(f) for f in files}


def lookup(mats: dict[str, Material], node: Node, key: str = "material") -> Material:
    name = node.string(key)
    if name not in mats:
        raise node.error(key, "one of the materials " + ", ".join(sorted(mats)), repr(name))
    return mats[name]


def require(mat: Material, prop: str, where: InputError) -> float:
    """A property a check needs; missing is an input error naming the material."""
    value = getattr(mat, prop)
    if value is None:
        raise InputError(where.file, where.key, f"material {mat.key!r} to define {prop}", "no value")
    return value
