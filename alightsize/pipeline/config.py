"""A design config: the items of one leg configuration, the capsule, the audit rule and the display units."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from alightsize.common.config import Node, load_toml
from alightsize.pipeline.items import Item, read_item
from alightsize.pipeline.landings import Landings, run_landings
from alightsize.loads.quasi_static import LoadReference, LoadsResult, attach, load_from
from alightsize.model.materials import library

UNIT_SYSTEMS = ("US", "SI")


@dataclass(frozen=True)
class DesignConfig:
    path: Path
    configuration: str
    title: str
    capsule_mass: float | None
    legs: int
    units: str
    required: float
    decimals: int | None
    items: tuple[Item, ...]
    loads: LoadsResult | None = None
    load_refs: tuple[LoadReference, ...] = ()
    landings: Landings | None = None


def _loads(root: Node, path: Path) -> LoadsResult | None:
    """[loads] file = "...": envelopes computed now, so checks can reference them (App. III -> App. IV)."""
    node = root.table("loads", optional=True)
    if node is None:
        def refuse(n: Node, name: str, ref: dict) -> float:
            raise n.error(name, "a force with units, or an envelope reference with [loads] file = ... in the design "
                          "config", "an envelope reference but no [loads] file")
        root.context["force_reference"] = refuse
        return None
    file = path.parent / node.string("file")
    node.finish()
    if not file.exists():
        raise node.error("file", "the path of an existing loads config", str(file))
    res = load_from(file)
    attach(root, res)
    return res


def read_design(path: str | Path, landings_dir: Path | None = None) -> DesignConfig:
    """Read and validate a design config; any problem is an InputError naming file and key path. Landing
    cases (`[landings]`) run before the checks read their loads, into `landings_dir` (resumable) or a
    temporary folder."""
    path = Path(path)
    root = load_toml(path)
    d = root.table("design")
    configuration = d.string("configuration")
    title = d.string("title", configuration)
    capsule = d.quantity("capsule_mass", "mass", default=None)
    legs = d.integer("legs", 4)
    extra = [path.parent / p for p in d.strings("materials", [])]
    d.finish()
    rep = root.table("report", optional=True)
    units = rep.string("units", "US", choices=UNIT_SYSTEMS) if rep else "US"
    if rep:
        rep.finish()
    aud = root.table("audit", optional=True)
    required = aud.number("required_design_factor", 1.2) if aud else 1.2
    decimals = aud.integer("decimals", None, minimum=0) if aud else None
    if aud:
        aud.finish()
    for p in extra:
        if not p.exists():
            raise d.error("materials", "paths of existing material files or folders", str(p))
    mats = library(extra)
    loads = _loads(root, path)
    land_node = root.table("landings", optional=True)
    items = tuple(read_item(n, mats, required) for n in root.tables("item", label="name"))
    names = [i.name for i in items]
    dup = next((n for n in names if names.count(n) > 1), None)
    if dup:
        raise root.error("item", "item names unique within a configuration", f"{dup!r} twice")
    root.finish()
    landings = None
    if land_node is not None:                  # the config is valid: land, then read the checks' loads again
        loads, landings = run_landings(land_node, path, loads, landings_dir)
        attach(root, loads)
        root.context["load_references"] = []
        items = tuple(read_item(n, mats, required) for n in root.tables("item", label="name"))
    return DesignConfig(path, configuration, title, capsule, legs, units, required, decimals, items, loads,
                        tuple(root.context.get("load_references", ())), landings)
