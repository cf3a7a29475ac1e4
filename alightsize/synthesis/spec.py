"""`[synthesis]` of a lander file: the free parameters with their bounds, the optimizer's budget and seed, the
fresh re-check sample and the trade curves. Reading only reads and validates.

```
[synthesis]
seed = 1                   # differential evolution's seed: same file, same result
generations = 10           # at most this many generations after the initial population
population = 5             # candidates per generation per free parameter
check_samples = 1000       # fresh Monte Carlo landings the winner is re-checked on (never seen in the search)
check_seed = 2             # their seed
stroke_margin = 0.1        # in the search, a cell using more than 90 % of its stroke fails its landing
[synthesis.free]           # each: [low, high]; the file's own value is the starting design
"cells.axial.crush_force" = ["4 kN", "16 kN"]   # a cell's crushing force (its force curve scaled)
"cells.axial.stroke" = ["0.3 m", "0.6 m"]       # a cell's stroke to bottoming (its deflections scaled)
"legs.radius" = ["1.6 m", "3.2 m"]              # any scene quantity: attach radius, leg length, psi_initial
[synthesis.trade]          # trade curves: one synthesis per value
horizontal_speed = ["0 kn", "10 kn", "20 kn", "30 kn"]
slope = ["0 deg", "15 deg", "30 deg"]
generations = 4            # the budget of each point (default: half the main search's)
population = 4
samples = 20               # Monte Carlo landings per candidate at each point (default: the requirements')
```
Members with a `size` table are sized for every candidate (the lightest section meeting the required design
factor), so their sections are free without being listed.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from math import isfinite
from pathlib import Path

from alightsize.common.config import SEED_MAX, Node, load_toml
from alightsize.common.errors import InputError
from alightsize.common.units import registry
from alightsize.pipeline.lander import cell_curve, crush_stroke

CELL_KEYS = ("crush_force", "stroke")          # "cells.NAME.crush_force" / "cells.NAME.stroke"
TRADE_AXES = {"horizontal_speed": "velocity", "slope": "angle"}


@dataclass(frozen=True)
class FreeParameter:
    """One free parameter: its key, bounds and starting value in SI (angles in rad), and the unit it is shown in."""

    key: str
    low: float
    high: float
    start: float
    unit: str
    per_si: float                 # display units per SI unit

    @property
    def cell(self) -> tuple[str, str] | None:
        """(cell name, "crush_force" | "stroke") for a cell parameter, else None."""
        parts = self.key.split(".")
        return (parts[1], parts[2]) if len(parts) == 3 and parts[0] == "cells" and parts[2] in CELL_KEYS else None

    def show(self, value: float) -> str:
        return f"{value * self.per_si:.4g} {self.unit}"

    def toml(self, value: float) -> str:
        """The value as a TOML quantity in the parameter's own unit, to full precision."""
        return f"{value * self.per_si!r} {self.unit}"


@dataclass(frozen=True)
class Budget:
    generations: int
    population: int
    samples: int | None              # Monte Carlo landings per candidate (None: the requirements')


@dataclass(frozen=True)
class SynthesisSpec:
    path: Path
    free: tuple[FreeParameter, ...]
    seed: int
    budget: Budget
    check_samples: int
    check_seed: int
    trade: dict[str, tuple[tuple[float, str], ...]]      # axis -> ((SI value, as written), ...)
    trade_budget: Budget
    stroke_margin: float = 0.0          # search only: the fraction of each cell's stroke kept unused
    data: dict = field(default_factory=dict, repr=False)     # the lander file as read (each candidate varies it)


def _quantity(node: Node, key: str, text) -> tuple[float, str, float]:
    """(SI value, unit as written, display units per SI unit) of a bound; angles in rad."""
    try:
        q = registry().Quantity(str(text))
    except Exception:                                  # noqa: BLE001 - pint raises many kinds on garbage
        raise node.error(key, "a quantity with its unit, like \"2 m\" or \"8 kN\"", repr(text)) from None
    unit = str(text).strip().partition(" ")[2].strip()
    if not hasattr(q, "units") or not unit:
        raise node.error(key, "a quantity with its unit, like \"2 m\" or \"8 kN\"", repr(text))
    base = float(q.to_base_units().magnitude)
    if not isfinite(base):
        raise node.error(key, "a finite quantity", repr(text))
    return base, unit, 1.0 / float(registry().Quantity(1.0, unit).to_base_units().magnitude)


def _lookup(data: dict, key: str):
    for part in key.split("."):
        if not isinstance(data, dict) or part not in data:
            return None
        data = data[part]
    return data


def _free(node: Node, root: Node) -> tuple[FreeParameter, ...]:
    out = []
    for key in node.data:
        raw = node.raw(key)
        if not (isinstance(raw, list) and len(raw) == 2):
            raise node.error(key, "bounds [low, high] with units", repr(raw))
        (lo, unit, per_si), (hi, unit_hi, _) = (_quantity(node, key, v) for v in raw)
        if registry().Quantity(1.0, unit).dimensionality != registry().Quantity(1.0, unit_hi).dimensionality:
            raise node.error(key, "both bounds of one dimension", repr(raw))
        if not lo < hi:
            raise node.error(key, "low < high", repr(raw))
        parts = key.split(".")
        if parts[0] == "cells":
            if len(parts) != 3 or parts[2] not in CELL_KEYS or parts[1] not in (root.data.get("cells") or {}):
                raise node.error(key, "cells.NAME.crush_force or cells.NAME.stroke of a [cells.NAME] table", repr(key))
            force, stroke = crush_stroke(*cell_curve(root, parts[1]))
            start = force if parts[2] == "crush_force" else stroke
        else:
            if parts[0] not in ("capsule", "legs", "terrain", "initial", "controls"):
                raise node.error(key, "a cell parameter or a scene key (capsule.*, legs.*, ...)", repr(key))
            value = _lookup(root.data, key)
            if value is None:
                raise node.error(key, "a key the lander file sets (its value is the start)", "no such key in the file")
            start, _, _ = _quantity(node, key, value)
        out.append(FreeParameter(key, lo, hi, start, unit, per_si))
    node.finish()
    if not out:
        raise node.error("", "at least one free parameter with bounds", "none")
    return tuple(out)


def _budget(node: Node, default: Budget) -> Budget:
    return Budget(node.integer("generations", default.generations, minimum=0, maximum=1000),
                  node.integer("population", default.population, minimum=2, maximum=200),
                  node.integer("samples", default.samples, minimum=0, maximum=5000) if node.has("samples")
                  else default.samples)


def read_synthesis(path: str | Path) -> SynthesisSpec:
    """The `[synthesis]` table of a lander file (InputError when it has none or it is malformed)."""
    path = Path(path)
    root = load_toml(path)
    if "synthesis" not in root.data:
        raise InputError(str(path), "synthesis", "a [synthesis] table with [synthesis.free] bounds", "none")
    node = root.table("synthesis")
    node.allow(("seed", "generations", "population", "samples", "check_samples", "check_seed", "stroke_margin",
                "free", "trade", "note"))
    seed = node.integer("seed", 1, minimum=0, maximum=SEED_MAX)
    budget = _budget(node, Budget(10, 5, None))
    check_samples = node.integer("check_samples", 1000, minimum=0, maximum=100_000)
    check_seed = node.integer("check_seed", seed + 1, minimum=0, maximum=SEED_MAX + 1)
    margin = node.number("stroke_margin", 0.0, positive=False)
    if not 0 <= margin < 1:
        raise node.error("stroke_margin", "a fraction of the stroke in [0, 1)", repr(margin))
    free = _free(node.table("free"), root)
    trade, trade_budget = {}, Budget(max(1, budget.generations // 2), budget.population, budget.samples)
    tnode = node.table("trade", optional=True)
    if tnode:
        tnode.allow((*TRADE_AXES, "generations", "population", "samples", "note"))
        for axis, dim in TRADE_AXES.items():
            if tnode.has(axis):
                values = tnode.raw(axis)
                if not isinstance(values, list) or not values:
                    raise tnode.error(axis, "a list of values with units", repr(values))
                trade[axis] = tuple((tnode.parse_quantity(f"{axis}[{i}]", v, dim, positive=False), str(v))
                                    for i, v in enumerate(values))
        trade_budget = _budget(tnode, trade_budget)
        tnode.string("note", "")
        tnode.finish()
    node.string("note", "")
    node.finish()
    for p in free:
        if not p.low <= p.start <= p.high:
            raise InputError(str(path), f"synthesis.free.{p.key}",
                             f"bounds that hold the file's own value {p.show(p.start)} (the starting design)",
                             f"[{p.show(p.low)}, {p.show(p.high)}]")
    return SynthesisSpec(path, free, seed, budget, check_samples, check_seed, trade, trade_budget, margin, root.data)


def free_parameter(spec: SynthesisSpec, key: str) -> FreeParameter:
    """The free parameter named `key` (InputError naming the ones there are)."""
    for p in spec.free:
        if p.key == key:
            return p
    raise InputError("(start)", key,
                     "a free parameter of [synthesis.free] (" + ", ".join(p.key for p in spec.free) + ")", repr(key))


def parse_start(spec: SynthesisSpec, items: list[str]) -> dict[str, float]:
    """Command-line starts `KEY=VALUE` ("cells.axial.crush_force=4 kN") as SI values, each in its free
    parameter's dimension."""
    out = {}
    for item in items:
        key, sep, text = item.partition("=")
        p = free_parameter(spec, key.strip()) if sep else None
        try:
            q = registry().Quantity(text.strip())
            ok = p is not None and hasattr(q, "units") and \
                q.dimensionality == registry().Quantity(1.0, p.unit).dimensionality and isfinite(q.magnitude)
        except Exception:                              # noqa: BLE001 - pint raises many kinds on garbage
            ok = False
        if not ok:
            raise InputError("(command line)", "--start", "KEY=VALUE with the parameter's unit, e.g. "
                             f"{spec.free[0].key}={spec.free[0].show(spec.free[0].start)}", repr(item))
        out[p.key] = float(q.to_base_units().magnitude)
    return out


def overrides(free: tuple[FreeParameter, ...], x, root: Node) -> dict:
    """The lander-file overrides of a candidate `x` (SI, one value per free parameter): a cell's crushing
    force scales its force curve and its stroke its deflections; a scene key takes the value in its unit."""
    out, scale = {}, {}
    for p, v in zip(free, x):
        if p.cell is None:
            out[p.key] = p.toml(float(v))
        else:
            scale.setdefault(p.cell[0], {})[p.cell[1]] = float(v) / p.start
    for cell, s in scale.items():
        defl, force = cell_curve(root, cell)
        if "crush_force" in s:
            out[f"cells.{cell}.force"] = [f"{f * s['crush_force']!r} N" for f in force]
        if "stroke" in s:
            out[f"cells.{cell}.deflection"] = [f"{d * s['stroke']!r} m" for d in defl]
    return out
