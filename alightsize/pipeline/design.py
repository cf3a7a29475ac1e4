"""`alightsize design`: stress checks and sizing -> weights -> summary and reports for one config."""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass
from functools import cached_property
from math import isfinite

import pandas as pd

from alightsize.pipeline.audit import CheckRecord, run_audit
from alightsize.pipeline.sizing import Sizing, size_item
from alightsize.common.units import fmt
from alightsize.landings.criteria import violation_kinds
from alightsize.pipeline.config import DesignConfig, DesignSpec, prepare
from alightsize.pipeline.items import Item
from alightsize.pipeline.landings import LANDING

REFERENCE_COLUMNS = ["load_key", "item", "kind", "key", "envelope", "member", "sense", "factor", "value_N", "at_rad",
                     "configuration", "quasi_static_N", "governs"]
CHECK_COLUMNS = ["configuration", "item", "check", "kind", "load_N", "stress_Pa", "allowable_Pa", "design_factor",
                 "required_design_factor", "margin_of_safety", "ok", "ok_as_stated"]     # CheckRecord.as_json


# The sized footpad may weigh this much more than the footpad mass the landings simulated (a fraction of it): the
# footpad's mass enters the landings only through its own inertia and momentum at contact, a few percent of a
# footpad's mass changes the strut loads by far less than the design factor's margin, and without a band the
# write-the-mass-and-rerun loop (the new mass moves the loads, the loads move the sized mass) would not settle.
FOOTPAD_MASS_TOLERANCE = 0.05


@dataclass(frozen=True)
class WeightRow:
    label: str
    item: Item
    count: int
    each: float          # kg
    steps: tuple


@dataclass(frozen=True)
class DesignResult:
    config: DesignConfig
    items: tuple[Item, ...]        # as designed: sized items carry their sized section
    records: list[CheckRecord]
    sizings: list[Sizing]
    weights: list[WeightRow]

    @property
    def checks_ok(self) -> bool:
        """Every check at or above its required design factor, every sized item feasible."""
        return all(r.ok for r in self.records) and all(s.feasible for s in self.sizings)

    @property
    def landings_ok(self) -> bool:
        """Every landing case meets the study's criteria (or the landings are load cases only, or none)."""
        return self.config.landings is None or self.config.landings.ok

    @property
    def weight_fraction(self) -> float | None:
        """Leg-system weight (all legs) as a fraction of the capsule's mass, when both are known."""
        m = self.config.capsule_mass
        return self.per_leg * self.config.legs / m if m else None

    @property
    def weight_ok(self) -> bool:
        """The leg system within its weight goal (always, without a goal)."""
        goal, frac = self.config.weight_goal, self.weight_fraction
        return goal is None or frac is None or frac <= goal

    @property
    def footpad_sized(self) -> float | None:
        """The sized footpad's weight, kg, when the landings simulated a footpad mass (a tripod lander's
        `[members.footpad]` with `[legs] footpad_mass`)."""
        if self.config.footpad_mass is None:
            return None
        return next((w.each for w in self.weights if w.item.name == "footpad"), None)

    @property
    def footpad_ok(self) -> bool:
        """The sized footpad no heavier than the landings' footpad_mass by more than FOOTPAD_MASS_TOLERANCE."""
        sized, simulated = self.footpad_sized, self.config.footpad_mass
        return sized is None or simulated is None or sized <= simulated * (1 + FOOTPAD_MASS_TOLERANCE)

    @property
    def ok(self) -> bool:
        return self.checks_ok and self.landings_ok and self.weight_ok and self.footpad_ok

    def governing_cases(self) -> list[str]:
        """Configurations whose envelope extremes the checks use, in the order of the loads file."""
        cfg = self.config
        used = {r.extreme.configuration for r in cfg.load_refs if r.extreme is not None}
        return [c.name for c in cfg.loads.config.cases if c.name in used] if cfg.loads else []

    def governing(self) -> CheckRecord | None:
        """The check with the smallest margin of safety."""
        return min(self.records, key=lambda r: r.margin, default=None)

    @property
    def below_one(self) -> list[tuple[str, float]]:
        """(item, required factor) of every item required less than 1 (allowed only by allow_below_one)."""
        return [(i.name, i.required) for i in self.items if i.required < 1]

    def summary_lines(self, system: str = "SI") -> list[str]:
        """The one-screen summary: verdict (naming any required factor below 1), each criterion with the landing
        nearest to violating it, then the headlines (governing check, weight, members at a size bound)."""
        lines = [self.verdict()]
        land = self.config.landings
        if land is not None:
            n = len(land.rows)
            kinds = Counter(k for r in land.failing for k in dict.fromkeys(violation_kinds(r["criteria_failed"])))
            lines.append(f"landings: {n - len(land.failing)} of {n} meet every criterion" +
                         "".join(f"; {k}: {c}" for k, c in kinds.most_common()))
            if land.closest:
                lines.append(CLOSEST_HEAD)
                lines += ["  " + c.line() for c in land.closest]
        return lines + self.headlines(system)

    def headlines(self, system: str = "SI") -> list[str]:
        """The first screen's lines after the landings: the governing check with its margin of safety, the leg
        system's weight against its goal, and the sized items that stopped at a bound of their range."""
        out = []
        gov = self.governing()
        if gov is not None:
            out.append(f"governing check: {gov.item.name} {gov.outcome.mode}, f = {gov.outcome.factor:.3g} "
                       f"(required {gov.required:g}; MS {gov.margin:+.3f})")
        frac, goal = self.weight_fraction, self.config.weight_goal
        if frac is not None:
            out.append(f"leg system: {fmt(self.per_leg * self.config.legs, 'mass', system)}, {100 * frac:.2f} % of "
                       "the capsule" + (f" (goal {100 * goal:.2f} %: {'met' if self.weight_ok else 'exceeded'})"
                                        if goal else ""))
        sized, simulated = self.footpad_sized, self.config.footpad_mass
        if sized is not None and simulated is not None:
            out.append(f"footpad: sized {fmt(sized, 'mass', system)}, simulated {fmt(simulated, 'mass', system)} "
                       f"([legs] footpad_mass: {'consistent' if self.footpad_ok else 'too light'})")
        bound = [s for s in self.sizings if s.at_bound]
        if bound:
            out.append("sized to an end of its range: " + ", ".join(
                f"{s.item} {s.dimension.replace('_', ' ')} {fmt(s.sized, 'length', system)}" for s in bound))
        return out

    def verdict(self) -> str:
        """One line: whether the design passes, and what fails."""
        failed = [r for r in self.records if not r.ok]
        parts = [f"{len(failed)} of {len(self.records)} checks below the required design factor" if failed
                 else f"all {len(self.records)} checks meet their required design factor"]
        if self.below_one:
            parts.append(below_one_line(self.below_one))
        if any(not s.feasible for s in self.sizings):
            parts.append("sizing cannot meet the required factor for " +
                         ", ".join(s.item for s in self.sizings if not s.feasible))
        land = self.config.landings
        if land is not None:
            n, bad = len(land.rows), land.failing
            if land.role == "load_cases":
                parts.append(f"{n} landings used as load cases only (criteria not required: {len(bad)} of them "
                             "violate the study's criteria)")
            elif bad:
                parts.append(f"{len(bad)} of {n} landings fail their criteria ({land.criteria_counts()})")
            else:
                parts.append(f"all {n} landings meet their criteria")
        if not self.footpad_ok:
            sized, simulated = self.footpad_sized, self.config.footpad_mass
            assert sized is not None and simulated is not None      # `footpad_ok` holds without either
            parts.append(f"the sized footpad weighs {sized:.4g} kg, above the {simulated:.4g} kg the landings "
                         f"simulated ([legs] footpad_mass, +{FOOTPAD_MASS_TOLERANCE:.0%} allowed): write "
                         f'footpad_mass = "{sized:.4g} kg" and run again')
        if not self.weight_ok:
            frac, goal = self.weight_fraction, self.config.weight_goal
            assert frac is not None and goal is not None      # `weight_ok` holds without either
            parts.append(f"the leg system weighs {100 * frac:.2f} % of the capsule, over its goal of "
                         f"{100 * goal:.2f} %")
        return ("PASS: " if self.ok else "FAIL: ") + "; ".join(parts)

    @property
    def per_leg(self) -> float:
        return sum(w.count * w.each for w in self.weights)

    def to_pandas(self) -> dict[str, pd.DataFrame]:
        """The result as tables, SI with the unit in each column name: "checks" (one row per check, with f,
        MS and verdict; None where f is infinite), "weights" (per item), with landing cases "landings" (one row per
        landing as stored) and "interface_loads" (each body hardpoint's largest force), with sized items "sizing"
        (one row per sized item) and with envelope loads "load_references" (one row per check load taken from an
        envelope; a tripod lander's: one per strut-load extreme over its landings, envelope "landings"). Copies:
        the result keeps its own."""
        return {name: frame.copy() for name, frame in self.tables.items()}

    @cached_property
    def tables(self) -> dict[str, pd.DataFrame]:
        """The tables of `to_pandas`, built once; the reports render from them (never modified)."""
        checks = pd.DataFrame([r.as_json() for r in self.records], columns=CHECK_COLUMNS)
        weights = pd.DataFrame([{"item": w.label, "count_per_leg": w.count, "weight_each_kg": w.each,
                                 "weight_per_leg_kg": w.count * w.each} for w in self.weights],
                               columns=["item", "count_per_leg", "weight_each_kg", "weight_per_leg_kg"])
        out = {"checks": checks, "weights": weights}
        if self.config.landings is not None:
            out["landings"] = pd.DataFrame(self.config.landings.rows)
            out["interface_loads"] = self.config.landings.interface_loads
        if self.sizings:
            out["sizing"] = pd.DataFrame([{"item": s.item, "dimension": s.dimension, "printed_m": s.printed,
                                           "sized_m": s.sized, "design_factor_printed": _finite(s.factor_printed),
                                           "design_factor_sized": _finite(s.factor_sized),
                                           "weight_printed_kg": s.weight_printed, "weight_sized_kg": s.weight_sized,
                                           "feasible": s.feasible, "at_bound": s.at_bound} for s in self.sizings])
        if self.config.load_refs:
            out["load_references"] = pd.DataFrame([self._reference_row(r) for r in self.config.load_refs],
                                                  columns=REFERENCE_COLUMNS)
        return out

    def _reference_row(self, r) -> dict:
        """A check's envelope load: the check it loads, where the envelope peaked and, with landing cases, the
        quasi-static load it had before they joined and which of the two governs."""
        cfg = self.config
        check = next(((i, c) for i in cfg.items for c in i.checks if r.key.startswith(c.where + ".")), None)
        row = {"load_key": r.key, "item": check[0].name if check else None, "kind": check[1].kind if check else None,
               "key": r.key[len(check[1].where) + 1:] if check else None, "envelope": r.envelope,
               "member": r.member, "sense": r.sense, "factor": r.factor, "value_N": r.value,
               "at_rad": tuple(r.extreme.at) if r.extreme and r.extreme.at else None,
               "configuration": r.extreme.configuration if r.extreme else None, "quasi_static_N": None,
               "governs": None}
        if cfg.landings is not None and r.extreme is not None and r.envelope in cfg.landings.envelopes:
            qs = cfg.landings.quasi_static_load(r.envelope, r.member, r.sense)
            row["quasi_static_N"] = qs * r.factor if qs is not None else None
            row["governs"] = "landing" if r.extreme.configuration.startswith(LANDING) else "quasi-static"
        elif cfg.landings is not None and r.extreme is not None and r.extreme.configuration.startswith(LANDING):
            row["governs"] = "landing"                  # a load of the landings alone (a tripod's)
        return row

    def plot(self, kind: str = "factors"):
        """A matplotlib Figure: "factors" (each item's governing design factor against the requirement) or
        "weights" (the weight breakdown per leg), drawn from `to_pandas()`."""
        from alightsize.common import figures
        tables, name = self.tables, self.config.configuration
        draw = figures.pick({"factors": lambda: figures.design_factor_figure(tables["checks"], name),
                             "weights": lambda: figures.weight_figure(tables["weights"], name, self.config.units)},
                            kind)
        return draw()


CLOSEST_HEAD = "nearest to failing, per criterion (margin = 1 - used / allowed, below 0 fails):"


def below_one_line(items: list[tuple[str, float]]) -> str:
    """"required design factor below 1 (allow_below_one): lower_tube 0.5, ..."."""
    return "required design factor below 1 (allow_below_one): " + ", ".join(f"{n} {f:g}" for n, f in items)


def _finite(x: float) -> float | None:
    return x if isfinite(x) else None


def run_design(cfg: DesignConfig | DesignSpec, landings_dir=None, progress: bool = False,
               rows: tuple[dict, ...] | None = None, *, size: bool = True) -> DesignResult:
    """Size (`size=True`, what `alightsize design` does), check and weigh a design; with `size=False` every
    item is judged at its section as written (`audit`). A design as read (`DesignSpec`) is prepared first
    (envelopes, landings into `landings_dir` or from their stored `rows`, loads resolved)."""
    if isinstance(cfg, DesignSpec):
        cfg = prepare(cfg, landings_dir, progress, rows)
    sizings, judged = [], []
    for item in cfg.items:
        if size and item.size is not None:
            assert item.section is not None          # `_size_spec` refuses a size without a section
            s = size_item(item)
            sizings.append(s)
            item = item.with_section(item.section.with_dim(s.dimension, s.sized))
        judged.append(item)
    items = tuple(judged)
    records = run_audit(cfg, items)
    weights = []
    for item in items:
        w = item.weight_each()
        if w is not None and item.weight is not None:       # an item with a weight entry has a weight
            weights.append(WeightRow(item.weight.label or item.name, item, item.count, w[0], tuple(w[1])))
    return DesignResult(cfg, items, records, sizings, weights)


def audit(cfg: DesignConfig | DesignSpec, landings_dir=None, rows: tuple[dict, ...] | None = None) -> DesignResult:
    """The design-factor audit (`alightsize audit`): every item's checks at its section as written, never sized
    (a `size` table is what `alightsize design` does with the item)."""
    return run_design(cfg, landings_dir, rows=rows, size=False)
