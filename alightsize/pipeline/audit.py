"""The design-factor audit: every check of every item against its required design factor (App. IV)."""

from __future__ import annotations

from dataclasses import dataclass
from math import isfinite
from xml.sax.saxutils import escape, quoteattr

from alightsize.checks.kinds import Outcome
from alightsize.pipeline.config import DesignConfig
from alightsize.pipeline.items import Item


@dataclass(frozen=True)
class CheckRecord:
    configuration: str
    item: Item
    index: int
    outcome: Outcome
    required: float
    decimals: int | None = None     # the places f is stated to (display only; the verdict is exact)

    @property
    def ok(self) -> bool:
        """f >= required on the exact factor: rounding never turns a failure into a pass."""
        return passes(self.outcome.factor, self.required)

    @property
    def margin(self) -> float:
        """Margin of safety MS = f / f_required - 1 (>= 0 passes; Bruhn 1973 A3.0: allowable / (applied x
        factor) - 1, with f = allowable / applied); inf where the check has no stress."""
        return self.outcome.factor / self.required - 1.0

    @property
    def stated_margin(self) -> str:
        """MS as the report states it: signed, two decimals ('+0.06', '-0.00' for a failure rounding to 0)."""
        ms = self.margin
        if not isfinite(ms):
            return "∞"
        text = f"{ms:+.2f}"
        return text.replace("+", "-") if ms < 0 and text == "+0.00" else text

    @property
    def ok_as_stated(self) -> bool:
        """The verdict on f rounded to `decimals`, as the report states it (the exact verdict without decimals)."""
        f = self.outcome.factor
        return passes(round(f, self.decimals) if self.decimals is not None and isfinite(f) else f, self.required)

    @property
    def rounding_flips(self) -> bool:
        """The stated (rounded) and exact verdicts differ: the stated f alone would mislead."""
        return self.ok != self.ok_as_stated

    @property
    def stated_factor(self) -> str:
        """f as the report states it: to `decimals` places (default 2), with the exact value where rounding
        would flip the verdict."""
        f = self.outcome.factor
        if not isfinite(f):
            return "∞"
        text = f"{f:.{2 if self.decimals is None else self.decimals}f}"
        return f"{text} (exact {f:.4f})" if self.rounding_flips else text

    @property
    def failure_label(self) -> str:
        """"Item / kind", with a note when the stated (rounded) factor would read as a pass."""
        label = f"{self.item.name} / {self.item.checks[self.index].kind}"
        return f"{label} (f = {self.stated_factor}: passes only as rounded)" if self.rounding_flips else label

    def as_json(self) -> dict:
        o = self.outcome
        return {"configuration": self.configuration, "item": self.item.name, "check": o.mode,
                "kind": self.item.checks[self.index].kind, "load_N": o.load, "stress_Pa": o.stress,
                "allowable_Pa": o.allowable, "design_factor": o.factor if isfinite(o.factor) else None,
                "required_design_factor": self.required,
                "margin_of_safety": self.margin if isfinite(self.margin) else None, "ok": self.ok,
                "ok_as_stated": self.ok_as_stated}


def passes(factor: float, required: float) -> bool:
    """f >= required (an unloaded check, f infinite, passes)."""
    return not isfinite(factor) or factor >= required


def run_audit(cfg: DesignConfig, items: tuple[Item, ...] | None = None) -> list[CheckRecord]:
    return [CheckRecord(cfg.configuration, item, j, o, item.required, cfg.decimals)
            for item in items or cfg.items for j, o in enumerate(item.evaluate())]


def audit_table(records: list[CheckRecord]) -> str:
    rows = [("configuration", "item", "check", "f", "required", "MS", "result")]
    for r in records:
        f = r.outcome.factor
        rows.append((r.configuration, r.item.name, r.item.checks[r.index].kind,
                     f"{f:.3f}" if isfinite(f) else "inf", f"{r.required:.2f}",
                     f"{r.margin:+.3f}" if isfinite(r.margin) else "inf",
                     ("ok" if r.ok else "FAIL") + (" (passes only as rounded)" if r.rounding_flips else "")))
    widths = [max(len(row[i]) for row in rows) for i in range(len(rows[0]))]
    lines = ["  ".join(c.ljust(w) for c, w in zip(row, widths)).rstrip() for row in rows]
    lines.insert(1, "  ".join("-" * w for w in widths))
    return "\n".join(lines)


def junit_xml(cfg: DesignConfig, records: list[CheckRecord]) -> str:
    failures = sum(not r.ok for r in records)
    parts = ['<?xml version="1.0" encoding="UTF-8"?>',
             f'<testsuite name={quoteattr("alightsize audit " + cfg.configuration)} tests="{len(records)}" '
             f'failures="{failures}" errors="0">']
    for r in records:
        name = f"{r.item.name} / {r.item.checks[r.index].kind}"
        f = r.outcome.factor
        parts.append(f'  <testcase classname={quoteattr(cfg.configuration)} name={quoteattr(name)}>')
        if not r.ok:
            msg = f"design factor {f:.4f} below required {r.required:.2f}"
            if r.rounding_flips:
                msg += f" (it reads {round(f, r.decimals):.{r.decimals}f} to {r.decimals} decimals)"
            parts.append(f'    <failure message={quoteattr(msg)}>{escape(msg)}</failure>')
        parts.append('  </testcase>')
    parts.append('</testsuite>')
    return "\n".join(parts) + "\n"
