"""The design-factor audit: every check of every item against its required design factor (App. IV)."""

from __future__ import annotations

from dataclasses import dataclass
from math import isfinite
from xml.sax.saxutils import escape, quoteattr

from .checks import Outcome
from .design_config import DesignConfig
from .items import Item

SCHEMA = "alightsize.audit/1"


@dataclass(frozen=True)
class CheckRecord:
    configuration: str
    item: Item
    index: int
    outcome: Outcome
    required: float
    ok: bool

    def as_json(self) -> dict:
        o = self.outcome
        return {"configuration": self.configuration, "item": self.item.name, "check": o.mode,
                "kind": self.item.checks[self.index].kind, "load_N": o.load, "stress_Pa": o.stress,
                "allowable_Pa": o.allowable, "design_factor": o.factor if isfinite(o.factor) else None,
                "required_design_factor": self.required, "ok": self.ok}


def passes(factor: float, required: float, decimals: int | None) -> bool:
    """f >= required, comparing f as stated to `decimals` places when the config asks (the report states two)."""
    if not isfinite(factor):
        return True
    return (round(factor, decimals) if decimals is not None else factor) >= required


def run_audit(cfg: DesignConfig, items: tuple[Item, ...] | None = None) -> list[CheckRecord]:
    out = []
    for item in items or cfg.items:
        for j, o in enumerate(item.evaluate()):
            out.append(CheckRecord(cfg.configuration, item, j, o, item.required,
                                   passes(o.factor, item.required, cfg.decimals)))
    return out


def audit_json(cfg: DesignConfig, records: list[CheckRecord]) -> dict:
    return {"schema": SCHEMA, "required_design_factor": cfg.required, "ok": all(r.ok for r in records),
            "checks": [r.as_json() for r in records]}


def audit_table(records: list[CheckRecord]) -> str:
    rows = [("configuration", "item", "check", "f", "required", "result")]
    for r in records:
        f = r.outcome.factor
        rows.append((r.configuration, r.item.name, r.item.checks[r.index].kind,
                     f"{f:.3f}" if isfinite(f) else "inf", f"{r.required:.2f}", "ok" if r.ok else "FAIL"))
    widths = [max(len(row[i]) for row in rows) for i in range(len(rows[0]))]
    lines = ["  ".join(c.ljust(w) for c, w in zip(row, widths)).rstrip() for row in rows]
    lines.insert(1, "  ".join("-" * w for w in widths))
    return "\n".join(lines)


def junit_xml(cfg: DesignConfig, records: list[CheckRecord]) -> str:
    failures = sum(not r.ok for r in records)
    parts = [f'<?xml version="1.0" encoding="UTF-8"?>',
             f'<testsuite name={quoteattr("alightsize audit " + cfg.configuration)} tests="{len(records)}" '
             f'failures="{failures}" errors="0">']
    for r in records:
        name = f"{r.item.name} / {r.item.checks[r.index].kind}"
        f = r.outcome.factor
        parts.append(f'  <testcase classname={quoteattr(cfg.configuration)} name={quoteattr(name)}>')
        if not r.ok:
            msg = f"design factor {f:.3f} below required {r.required:.2f}"
            parts.append(f'    <failure message={quoteattr(msg)}>{escape(msg)}</failure>')
        parts.append('  </testcase>')
    parts.append('</testsuite>')
    return "\n".join(parts) + "\n"
