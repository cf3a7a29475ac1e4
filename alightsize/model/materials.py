"""Material property data: one TOML file per material under materials/, users add more by path."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from alightsize.common.config import Node, is_dir, is_file, load_toml
from alightsize.common.errors import InputError
from alightsize.common.resources import data_dir

_PROPS = {"yield_strength": "stress", "density": "density", "elastic_modulus": "stress", "crush_strength": "stress"}


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
    source: dict = field(default_factory=dict)

    def value(self, prop: str) -> float:
        """A property a formula uses. A design refuses a material without the properties its checks need before
        any check runs (alightsize.pipeline.items), so a missing one here is a programming error."""
        v = getattr(self, prop)
        if v is None:
            raise ValueError(f"material {self.key} has no {prop}")
        return v


def read_material(path: str | Path) -> Material:
    node = load_toml(path)
    values = {p: node.quantity(p, dim, default=None) for p, dim in _PROPS.items()}
    if values["density"] is None:
        raise node.error("density", "a density like \"0.100 lb/in^3\"", "nothing")
    m = node.number("poisson_m", default=None)
    eta = node.number("stroke_fraction", default=None)
    if eta is not None and not 0 < eta <= 1:
        raise node.error("stroke_fraction", "the usable stroke as a fraction of the core length, in (0, 1]", repr(eta))
    src = node.table("source", optional=True)
    source = {k: src.string(k) for k in list(src.data)} if src else {}
    if src:
        src.finish()
    mat = Material(Path(path).stem, node.string("name"), poisson_m=m, stroke_fraction=eta, source=source, **values)
    node.finish()
    return mat


def material_paths(node: Node, key: str, base: Path) -> list[Path]:
    """The extra material files or folders a config lists at `key`, relative to `base` (its folder)."""
    out = []
    for text in node.strings(key, []):
        path = base / text
        if not text.strip() or not (path.suffix == ".toml" and is_file(path) or is_dir(path)):
            raise node.error(key, "paths of material files (.toml) or folders of them, relative to this file",
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
