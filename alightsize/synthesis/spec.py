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

import copy
from dataclasses import dataclass, field
from math import isfinite
from pathlib import Path
from typing import Annotated, Any

from pydantic import PlainValidator, model_validator

from alightsize.common.config import SEED_MAX, Node, load_toml
from alightsize.common.errors import InputError
from alightsize.common.typed import Integer, Number, Quantities, Table, refuse, validate
from alightsize.common.units import DIMS, RANGES, dimension_of, registry
from alightsize.model.scene_config import Cell
from alightsize.pipeline.lander import crush_stroke, read_lander

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
    curve: tuple[tuple[float, ...], tuple[float, ...]] | None = None    # a cell's (deflections m, forces N) as read

    @property
    def cell(self) -> tuple[str, str] | None:
        """(cell name, "crush_force" | "stroke") for a cell parameter, else None."""
        parts = self.key.split(".")
        return (parts[1], parts[2]) if len(parts) == 3 and parts[0] == "cells" and parts[2] in CELL_KEYS else None

    def show(self, value: float) -> str:
        return f"{value * self.per_si:.4g} {self.unit}"

    def toml(self, value: float) -> str:
        """The value as a TOML quantity in the parameter's own unit, to full precision; a magnitude below the
        smallest nonzero one the file's parsers take in its dimension (alightsize.common.units.RANGES, 1e-6 m for
        a length) reads 0, as a candidate drawn next to a zero bound would otherwise be refused."""
        if abs(value) < _floor(self.unit):
            value = 0.0
        return f"{value * self.per_si!r} {self.unit}"


def _floor(unit: str) -> float:
    """The largest of the parsers' smallest nonzero magnitudes (SI) among the dimensions of `unit`."""
    dims = dimension_of(registry().Quantity(1.0, unit))
    return max((RANGES[d.name][0] for d in DIMS.values() if (d.mass, d.length, d.time) == dims and d.name in RANGES),
               default=0.0)


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


def _quantity(text) -> tuple[float, str, float]:
    """(SI value, unit as written, display units per SI unit) of a quantity of any dimension; angles in rad. A
    ValueError says what was expected."""
    try:
        q = registry().Quantity(str(text))
    except Exception:                                  # noqa: BLE001 - pint raises many kinds on garbage
        raise ValueError("a quantity with its unit, like \"2 m\" or \"8 kN\"") from None
    unit = str(text).strip().partition(" ")[2].strip()
    if not hasattr(q, "units") or not unit:
        raise ValueError("a quantity with its unit, like \"2 m\" or \"8 kN\"")
    base = float(q.to_base_units().magnitude)
    if not isfinite(base):
        raise ValueError("a finite quantity")
    return base, unit, 1.0 / float(registry().Quantity(1.0, unit).to_base_units().magnitude)


def _bounds(raw: Any) -> tuple[float, float, str, float]:
    """(low, high, unit, display units per SI unit) of a free parameter's [low, high]."""
    if not (isinstance(raw, list) and len(raw) == 2):
        raise refuse("bounds [low, high] with units", repr(raw))
    parsed = []
    for v in raw:
        try:
            parsed.append(_quantity(v))
        except ValueError as exc:
            raise refuse(str(exc), repr(v)) from None
    (lo, unit, per_si), (hi, unit_hi, _) = parsed
    if registry().Quantity(1.0, unit).dimensionality != registry().Quantity(1.0, unit_hi).dimensionality:
        raise refuse("both bounds of one dimension", repr(raw))
    if not lo < hi:
        raise refuse("low < high", repr(raw))
    return lo, hi, unit, per_si


class Trade(Table):
    horizontal_speed: Annotated[tuple[float, ...], Quantities(TRADE_AXES["horizontal_speed"], minimum=1)] = ()
    slope: Annotated[tuple[float, ...], Quantities(TRADE_AXES["slope"], minimum=1)] = ()
    generations: Annotated[int, Integer(0, 1000)] | None = None
    population: Annotated[int, Integer(2, 200)] | None = None
    samples: Annotated[int, Integer(0, 5000)] | None = None
    note: str = ""


class Synthesis(Table):
    """The `[synthesis]` table (docs/synthesis.md)."""

    seed: Annotated[int, Integer(0, SEED_MAX)] = 1
    generations: Annotated[int, Integer(0, 1000)] = 10
    population: Annotated[int, Integer(2, 200)] = 5
    samples: Annotated[int, Integer(0, 5000)] | None = None
    check_samples: Annotated[int, Integer(0, 100_000)] = 1000
    check_seed: Annotated[int, Integer(0, SEED_MAX + 1)] | None = None
    stroke_margin: Annotated[float, Number("nonnegative")] = 0.0
    free: dict[str, Annotated[tuple[float, float, str, float], PlainValidator(_bounds)]]
    trade: Trade | None = None
    note: str = ""

    @model_validator(mode="after")
    def _ranges(self):
        if self.stroke_margin >= 1:
            raise refuse("a fraction of the stroke in [0, 1)", repr(self.stroke_margin), "stroke_margin")
        if not self.free:
            raise refuse("at least one free parameter with bounds", "none", "free")
        return self


def _lookup(data: dict, key: str):
    for part in key.split("."):
        if not isinstance(data, dict) or part not in data:
            return None
        data = data[part]
    return data


def free_parameters(bounds: dict[str, tuple[float, float, str, float]], root: Node,
                    cells: dict[str, Cell]) -> tuple[FreeParameter, ...]:
    """The free parameters, each starting at the lander file's own value: a cell's crushing force or stroke from
    its curve (`cells`, the file's as read), any other scene key as written; a key the file does not set, or
    bounds that do not hold its value, are bad input."""
    out = []
    for key, (lo, hi, unit, per_si) in bounds.items():
        where = f"synthesis.free.{key}"
        parts = key.split(".")
        curve = None
        if parts[0] == "cells":
            if len(parts) != 3 or parts[2] not in CELL_KEYS or parts[1] not in cells:
                raise InputError(root.file, where, "cells.NAME.crush_force or cells.NAME.stroke of a [cells.NAME] "
                                 "table", repr(key))
            curve = cells[parts[1]].deflection, cells[parts[1]].force
            force, stroke = crush_stroke(*curve)
            start = force if parts[2] == "crush_force" else stroke
        else:
            if parts[0] not in ("capsule", "legs", "terrain", "initial", "controls"):
                raise InputError(root.file, where, "a cell parameter or a scene key (capsule.*, legs.*, ...)",
                                 repr(key))
            value = _lookup(root.data, key)
            if value is None:
                raise InputError(root.file, where, "a key the lander file sets (its value is the start)",
                                 "no such key in the file")
            try:
                start, _, _ = _quantity(value)
            except ValueError as exc:
                raise InputError(root.file, where, str(exc), repr(value)) from None
        p = FreeParameter(key, lo, hi, start, unit, per_si, curve)
        if not p.low <= p.start <= p.high:
            raise InputError(root.file, where, f"bounds that hold the file's own value {p.show(p.start)} (the "
                             "starting design)", f"[{p.show(p.low)}, {p.show(p.high)}]")
        out.append(p)
    return tuple(out)


def read_synthesis(path: str | Path) -> SynthesisSpec:
    """The `[synthesis]` table of a lander file, the file read once and validated whole (`read_lander`: the
    starting design); InputError when it has none or either is malformed."""
    path = Path(path)
    root = load_toml(path)
    if "synthesis" not in root.data:
        raise InputError(str(path), "synthesis", "a [synthesis] table with [synthesis.free] bounds", "none")
    s = validate(Synthesis, root.data["synthesis"], str(path), "synthesis")
    budget = Budget(s.generations, s.population, s.samples)
    t, written = s.trade or Trade(), root.data["synthesis"].get("trade", {})
    trade = {axis: tuple(zip(getattr(t, axis), map(str, written[axis]))) for axis in TRADE_AXES if axis in written}
    trade_budget = Budget(max(1, budget.generations // 2) if t.generations is None else t.generations,
                          budget.population if t.population is None else t.population,
                          budget.samples if t.samples is None else t.samples)
    check_seed = s.seed + 1 if s.check_seed is None else s.check_seed
    cells = read_lander(path, root=Node(path, "", copy.deepcopy(root.data))).cells
    return SynthesisSpec(path, free_parameters(s.free, root, cells), s.seed, budget, s.check_samples, check_seed, trade,
                         trade_budget, s.stroke_margin, root.data)


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


def overrides(free: tuple[FreeParameter, ...], x) -> dict:
    """The lander-file overrides of a candidate `x` (SI, one value per free parameter): a cell's crushing
    force scales its force curve and its stroke its deflections; a scene key takes the value in its unit."""
    out, scale, curves = {}, {}, {}
    for p, v in zip(free, x):
        if p.cell is None:
            out[p.key] = p.toml(float(v))
        else:
            assert p.curve is not None                  # `free_parameters` gives a cell's parameter its curve
            scale.setdefault(p.cell[0], {})[p.cell[1]] = float(v) / p.start
            curves[p.cell[0]] = p.curve
    for cell, s in scale.items():
        defl, force = curves[cell]
        if "crush_force" in s:
            out[f"cells.{cell}.force"] = [f"{f * s['crush_force']!r} N" for f in force]
        if "stroke" in s:
            out[f"cells.{cell}.deflection"] = [f"{d * s['stroke']!r} m" for d in defl]
    return out
