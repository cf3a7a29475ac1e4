"""Design inputs: what a design config or a lander file says (`DesignSpec`, read and validated, nothing run),
and the prepared design (`DesignConfig`: envelopes computed, landings run, every check's load resolved)."""

from __future__ import annotations

import copy
from dataclasses import dataclass
from pathlib import Path

from alightsize.common.config import Node, is_file, load_toml
from alightsize.checks.rules import DEFAULT_RULES, RULES
from alightsize.loads.config import LoadsConfig, read_loads
from alightsize.loads.quasi_static import LoadReference, LoadsResult, attach, run_loads, validate_references
from alightsize.model.materials import Material, library, material_paths
from alightsize.pipeline.items import Item, read_item, read_required
from alightsize.pipeline.landings import Landings, LandingSpec, landed, read_landing_spec, run_landings

UNIT_SYSTEMS = ("US", "SI")


@dataclass(frozen=True)
class DesignSpec:
    """A design as read: the items as TOML tables (their loads may reference envelopes not yet computed),
    the quasi-static loads to compute and the landing cases to run."""

    path: Path
    configuration: str
    title: str
    capsule_mass: float | None
    legs: int
    units: str
    required: float
    decimals: int | None
    materials: dict[str, Material]
    items: tuple[Node, ...]
    loads: LoadsConfig | None = None
    landings: LandingSpec | None = None
    weight_goal: float | None = None          # leg-system weight as a fraction of the capsule
    rules: str = DEFAULT_RULES                # the checks' formulas where a check names none (checks.rules)


@dataclass(frozen=True)
class DesignConfig:
    """A prepared design: items with resolved loads, the envelopes and the landings they came from."""

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
    weight_goal: float | None = None


def read_items(nodes: tuple[Node, ...], mats: dict[str, Material], required: float, root: Node,
               rules: str) -> tuple[Item, ...]:
    """Read item tables (copies: a node can be read again once loads are known); names unique."""
    items = tuple(read_item(Node(n.file, n.path, copy.deepcopy(n.data), root.context), mats, required, RULES[rules])
                  for n in nodes)
    names = [i.name for i in items]
    dup = next((n for n in names if names.count(n) > 1), None)
    if dup:
        raise root.error("item", "item names unique within a configuration", f"{dup!r} twice")
    return items


def read_design(path: str | Path, root: Node | None = None) -> DesignSpec:
    """Read and validate a design config (or its TOML `root`, already loaded); any problem is an InputError naming
    file and key path. Nothing is computed: the envelopes and landing cases it names run in `prepare`."""
    path = Path(path)
    root = load_toml(path) if root is None else root
    d = root.table("design")
    configuration = d.string("configuration")
    title = d.string("title", configuration)
    capsule = d.quantity("capsule_mass", "mass", default=None)
    legs = d.integer("legs", 4)
    rules = d.string("rules", DEFAULT_RULES, choices=tuple(RULES))
    extra = material_paths(d, "materials", path.parent)
    d.finish()
    rep = root.table("report", optional=True)
    units = rep.string("units", "US", choices=UNIT_SYSTEMS) if rep else "US"
    if rep:
        rep.finish()
    aud = root.table("audit", optional=True)
    required = read_required(aud, 1.2) if aud else 1.2
    decimals = aud.integer("decimals", None, minimum=0, maximum=12) if aud else None
    if aud:
        aud.finish()
    mats = library(extra)
    loads = _loads_config(root, path)
    validate_references(root, loads)
    land_node = root.table("landings", optional=True)
    landings = read_landing_spec(land_node, path, loads) if land_node is not None else None
    nodes = tuple(root.tables("item", label="name"))
    read_items(nodes, mats, required, root, rules)
    root.finish()
    return DesignSpec(path, configuration, title, capsule, legs, units, required, decimals, mats, nodes, loads,
                      landings, rules=rules)


def _loads_config(root: Node, path: Path) -> LoadsConfig | None:
    """[loads] file = "...": the loads config whose envelopes the checks reference (App. III -> App. IV)."""
    node = root.table("loads", optional=True)
    if node is None:
        return None
    file = path.parent / node.string("file")
    node.finish()
    if not is_file(file):
        raise node.error("file", "the path of an existing loads config", str(file))
    return read_loads(file)


def prepare(spec: DesignSpec, landings_dir: Path | None = None, progress: bool = False,
            rows: tuple[dict, ...] | None = None) -> DesignConfig:
    """Compute the quasi-static envelopes, run the landing cases (into `landings_dir`, resumable; a temporary
    folder when None; or take their stored `rows`, one per run in study order), merge their member loads and
    resolve every check's load."""
    loads = run_loads(spec.loads) if spec.loads is not None else None
    landings = None
    if spec.landings is not None:
        loads, landings = (landed(spec.landings, loads, rows) if rows is not None
                           else run_landings(spec.landings, loads, landings_dir, progress))
    root = Node(spec.path, "", {})
    if loads is not None:
        attach(root, loads)
    else:
        validate_references(root, None)
    items = read_items(spec.items, spec.materials, spec.required, root, spec.rules)
    return DesignConfig(spec.path, spec.configuration, spec.title, spec.capsule_mass, spec.legs, spec.units,
                        spec.required, spec.decimals, items, loads, tuple(root.context.get("load_references", ())),
                        landings, spec.weight_goal)

