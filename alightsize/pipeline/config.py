"""Design inputs: what a design config or a lander file says (`DesignSpec`, read and validated, nothing run),
and the prepared design (`DesignConfig`: envelopes computed, landings run, every check's load resolved)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, Callable, Literal

from alightsize.common.config import Node, is_file, load_toml
from alightsize.common.errors import InputError
from alightsize.common.typed import Integer, Quantity, Table, validate
from alightsize.checks.rules import DEFAULT_RULES, RULES, RuleSet
from alightsize.loads.config import LoadsConfig, read_loads
from alightsize.loads.quasi_static import LoadReference, LoadsResult, check_references, run_loads
from alightsize.model.materials import Material, library, material_paths
from alightsize.pipeline.items import Item, RequiredFactor, read_item, references, with_loads
from alightsize.pipeline.landings import Landings, LandingSpec, LandingsTable, landed, landing_spec, run_landings

UnitSystem = Literal["US", "SI"]


@dataclass(frozen=True)
class DesignSpec:
    """A design as read: the items (their loads may reference envelopes not yet computed: `ForceRef`), the
    quasi-static loads to compute and the landing cases to run."""

    path: Path
    configuration: str
    title: str
    capsule_mass: float | None
    legs: int
    units: str
    required: float
    decimals: int | None
    materials: dict[str, Material]
    items: tuple[Item, ...]
    loads: LoadsConfig | None = None
    landings: LandingSpec | None = None
    weight_goal: float | None = None          # leg-system weight as a fraction of the capsule
    rules: str = DEFAULT_RULES                # the checks' formulas where a check names none (checks.rules)
    # items whose loads the landings give (a tripod leg's members): stored landing rows -> the items that
    # replace `items` (which hold them under stand-in loads, validated when read) and the loads' references
    landing_items: Callable[[tuple[dict, ...]], tuple[tuple[Item, ...], tuple[LoadReference, ...]]] | None = None
    footpad_mass: float | None = None         # kg: the landings' footpad mass the sized `footpad` item must match


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
    footpad_mass: float | None = None         # kg, as DesignSpec's


def read_items(nodes: tuple[Node, ...], mats: dict[str, Material], required: float, root: Node,
               rules: str) -> tuple[Item, ...]:
    """Read item tables (their envelope references as read: `check_references` checks them); names unique."""
    items = tuple(read_item(n, mats, required, RULES[rules]) for n in nodes)
    names = [i.name for i in items]
    dup = next((n for n in names if names.count(n) > 1), None)
    if dup:
        raise root.error("item", "item names unique within a configuration", f"{dup!r} twice")
    return items


class DesignHead(Table):
    configuration: str
    title: str | None = None
    capsule_mass: Annotated[float, Quantity("mass")] | None = None
    legs: Annotated[int, Integer(1)] = 4
    rules: RuleSet = DEFAULT_RULES
    materials: list[str] = []


class DesignReport(Table):
    units: UnitSystem = "US"


class Audit(RequiredFactor):
    decimals: Annotated[int, Integer(0, 12)] | None = None


class LoadsFileRef(Table):
    file: str


class DesignFile(Table):
    """A design config's tables (docs/reference/design.md); its [[item]] tables are read by read_items."""

    design: DesignHead
    report: DesignReport = DesignReport()
    audit: Audit = Audit()
    loads: LoadsFileRef | None = None
    landings: LandingsTable | None = None
    item: list


def read_design(path: str | Path, root: Node | None = None) -> DesignSpec:
    """Read and validate a design config (or its TOML `root`, already loaded); any problem is an InputError naming
    file and key path. Nothing is computed: the envelopes and landing cases it names run in `prepare`."""
    path = Path(path)
    root = load_toml(path) if root is None else root
    f = validate(DesignFile, root.data, str(path))
    d, aud = f.design, f.audit
    required = 1.2 if aud.required_design_factor is None else aud.required_design_factor
    mats = library(material_paths(d.materials, path.parent, str(path), "design.materials"))
    loads = None
    if f.loads is not None:
        file = path.parent / f.loads.file
        if not is_file(file):
            raise InputError(str(path), "loads.file", "the path of an existing loads config", str(file))
        loads = read_loads(file)
    landings = landing_spec(f.landings, path, loads) if f.landings is not None else None
    for t in ("design", "report", "audit", "loads", "landings"):
        root.raw(t, None)                          # read above
    items = read_items(tuple(root.tables("item", label="name")), mats, required, root, d.rules)
    root.finish()
    check_references(references(items), loads, str(path))
    return DesignSpec(path, d.configuration, d.title if d.title is not None else d.configuration, d.capsule_mass,
                      d.legs, f.report.units, required, aud.decimals, mats, items, loads, landings, rules=d.rules)


def prepare(spec: DesignSpec, landings_dir: Path | None = None, progress: bool = False,
            rows: tuple[dict, ...] | None = None) -> DesignConfig:
    """Compute the quasi-static envelopes, run the landing cases (into `landings_dir`, resumable; a temporary
    folder when None; or take their stored `rows`, one per run in study order), merge their member loads and
    resolve every check's load (`with_loads`)."""
    loads = run_loads(spec.loads) if spec.loads is not None else None
    landings = None
    items = spec.items
    derived: tuple[LoadReference, ...] = ()
    if spec.landings is not None:
        loads, landings = (landed(spec.landings, loads, rows) if rows is not None
                           else run_landings(spec.landings, loads, landings_dir, progress))
        if spec.landing_items is not None:
            items, derived = spec.landing_items(landings.rows)
    resolved = [with_loads(item, loads, str(spec.path)) for item in items]
    items = tuple(item for item, _ in resolved)
    refs = derived + tuple(r for _, item_refs in resolved for r in item_refs)
    return DesignConfig(spec.path, spec.configuration, spec.title, spec.capsule_mass, spec.legs, spec.units,
                        spec.required, spec.decimals, items, loads, refs, landings, spec.weight_goal,
                        spec.footpad_mass)

