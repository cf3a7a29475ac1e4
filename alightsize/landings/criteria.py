"""Study criteria for one landing (AFFDL-TR-66-33 Sec. II): acceleration limits and onset rates per body
axis, no bottoming of any cell, no tumbling, no body contact. Walking counts as a successful alightment
(Sec. II.B: "these runs were considered successful"). Each landing's margin to each criterion (`margins`)
and, over a set of landings, the one nearest to violating each (`closest`)."""

from __future__ import annotations

import json
from dataclasses import dataclass
from math import inf
from typing import Annotated, Any, Literal

from pydantic import PlainValidator

from alightsize.common.typed import Table, refuse

# Sec. II.A.1 (human, couch facing up): 20 g at <= 10,000 g/s vertically (body axis 3), 10 g at <= 1000 g/s
# in the other directions; Sec. II.A.2 (instrument capsule): 50 g.
PRESETS = {"human": ((10.0, 10.0, 20.0), (1000.0, 1000.0, 10000.0)),
           "instrument": ((50.0, 50.0, 50.0), None)}


@dataclass(frozen=True)
class Criteria:
    max_xdd_g: tuple[float, float, float] | None
    max_onset_g_s: tuple[float, float, float] | None
    no_bottoming: bool = True
    no_tumbling: bool = True
    no_body_contact: bool = True

    def failures(self, summary: dict) -> list[str]:
        """The criteria a landing summary (alightsize.simulate/1) violates, in words; [] when it meets all."""
        out = []
        limits = ((self.max_xdd_g, summary["peak"]["xdd_g"], "g"),
                  (self.max_onset_g_s, summary["peak"]["onset_g_s"], "g/s"))
        for lim, peak, unit in limits:
            for axis, (x, cap) in enumerate(zip(peak, lim or ())):
                if x > cap:
                    out.append(f"XDD({axis + 1}) {'onset ' if unit == 'g/s' else ''}{x:.4g} {unit} > {cap:g} {unit}")
        oc = summary["outcome"]
        if self.no_bottoming and oc == "bottomed":
            out.append("a cell bottomed")
        if self.no_tumbling and oc == "tipped":
            out.append("the capsule tumbled")
        if self.no_body_contact and oc == "body_contact":
            out.append("the body struck the terrain")
        if oc in ("failed", "time_out"):
            out.append(f"the landing ended {oc}")
        return out

    def kinds(self) -> dict[str, str]:
        """Every criterion: its violation as `violation_kinds` names it ("XDD(3) > 20 g") -> the requirement
        ("XDD(3) <= 20 g")."""
        out = {f"XDD({i + 1}) {'onset ' if unit == 'g/s' else ''}> {cap:g} {unit}":
               f"XDD({i + 1}) {'onset ' if unit == 'g/s' else ''}<= {cap:g} {unit}"
               for lim, unit in ((self.max_xdd_g, "g"), (self.max_onset_g_s, "g/s")) for i, cap in enumerate(lim or ())}
        flags = ((self.no_bottoming, "a cell bottomed", "no cell bottoms"),
                 (self.no_tumbling, "the capsule tumbled", "no tumbling"),
                 (self.no_body_contact, "the body struck the terrain", "no body contact"))
        out.update((kind, text) for on, kind, text in flags if on)
        out.update({"the landing ended failed": "no numerical failure",
                    "the landing ended time_out": "at rest within t_final"})
        return out


LIMIT_MAX = 1e6     # g or g/s: far above any structure's (crewed limits are 10-40 g, 1000 g/s)


def _triple(value: Any) -> tuple[float, float, float]:
    if not (isinstance(value, list) and len(value) == 3 and all(
            isinstance(x, (int, float)) and not isinstance(x, bool) and 0 < x <= LIMIT_MAX for x in value)):
        raise refuse(f"three limits from above 0 to {LIMIT_MAX:g}, one per body axis (1, 2, 3 = roll axis)",
                     repr(value))
    return tuple(float(x) for x in value)


Triple = Annotated[tuple[float, float, float], PlainValidator(_triple)]


class CriteriaTable(Table):
    """`[criteria]`: a preset ("human", "instrument") and/or explicit limits."""

    preset: Literal[tuple(PRESETS)] | None = None
    max_xdd_g: Triple | None = None
    max_onset_g_s: Triple | None = None
    no_bottoming: bool = True
    no_tumbling: bool = True
    no_body_contact: bool = True
    note: str = ""

    def criteria(self) -> Criteria:
        xdd, onset = PRESETS[self.preset] if self.preset else (None, None)
        return Criteria(self.max_xdd_g or xdd, self.max_onset_g_s or onset, self.no_bottoming, self.no_tumbling,
                        self.no_body_contact)


def violation_kinds(failed: str | None) -> list[str]:
    """The kinds of a stored `criteria_failed` ("; "-joined failures) without their figures
    ("XDD(1) onset 2112 g/s > 1000 g/s" -> "XDD(1) onset > 1000 g/s"; "a cell bottomed" as it is)."""
    out = []
    for f in (failed or "").split("; "):
        if f:
            head, sep, limit = f.partition(" > ")
            out.append(" ".join(head.split(" ")[:-2]) + sep + limit if sep else f)
    return out


@dataclass(frozen=True)
class Margin:
    """How near one landing came to violating one criterion: `margin` = 1 - used / allowed (its largest
    ratio over the axes or cells the criterion covers; 0 at the limit, below 0 past it), None for a
    criterion judged pass/fail only (the row records no measure of it); `failed` as the study's criteria
    judge the landing (`Criteria.failures`); `detail` the governing figure in words."""

    criterion: str          # "bottoming", "tumbling", "acceleration", "onset", "body_contact", "settling"
    requirement: str        # "no cell bottoms", "XDD <= 10 / 10 / 20 g", ...
    margin: float | None
    failed: bool
    detail: str


@dataclass(frozen=True)
class LandingLimits:
    """What a landing's measures are compared with, from its scene: each leg's cells' strokes to bottoming
    (m, in the row's cell order) and the tip angle the nutation is tested against (deg)."""

    strokes: tuple[tuple[float, ...], ...]
    cell_names: tuple[tuple[str, ...], ...]
    tip_angle_deg: float


def _ratio_margin(values, limits, names, unit: str) -> tuple[float, str]:
    """(1 - largest value / limit, "XDD(3) 12.1 g of 10 g") over paired values and limits."""
    k = max(range(len(values)), key=lambda i: values[i] / limits[i])
    return 1.0 - values[k] / limits[k], f"{names[k]} {values[k]:.4g} {unit} of {limits[k]:g} {unit}"


def margins(row: dict, criteria: Criteria, limits: LandingLimits) -> list[Margin]:
    """Every criterion the study applies, for one stored landing row (alightsize.landings.sweep columns):
    cell stroke / stroke to bottoming (per cell, from cells_json), peak nutation / tip angle, peak XDD / limit
    and onset / limit (per body axis); body contact and settling (no numerical failure, at rest within t_final)
    pass/fail only."""
    oc = row["outcome"]
    out = []
    if criteria.no_bottoming:
        used = [(c["max_deflection_m"], limits.strokes[leg["leg"] - 1][j],
                 f"leg {leg['leg']} {limits.cell_names[leg['leg'] - 1][j]}")
                for leg in json.loads(row.get("cells_json") or "[]") for j, c in enumerate(leg["cells"])]
        m, detail = _ratio_margin([u[0] for u in used], [u[1] for u in used], [u[2] for u in used], "m")
        out.append(Margin("bottoming", "no cell bottoms", m, oc == "bottomed", f"{detail} stroke"))
    if criteria.no_tumbling:
        nut, tip = row["peak_nutation_deg"], limits.tip_angle_deg
        out.append(Margin("tumbling", "no tumbling", 1.0 - nut / tip, oc == "tipped",
                          f"nutation {nut:.4g} deg of {tip:.4g} deg"))
    for name, caps, col, unit, word in (("acceleration", criteria.max_xdd_g, "peak_xdd{}_g", "g", ""),
                                        ("onset", criteria.max_onset_g_s, "peak_onset_xdd{}_g_s", "g/s", " onset")):
        if caps:
            values = [row[col.format(i)] for i in (1, 2, 3)]
            m, detail = _ratio_margin(values, caps, [f"XDD({i}){word}" for i in (1, 2, 3)], unit)
            out.append(Margin(name, f"XDD{word} <= {' / '.join(f'{c:g}' for c in caps)} {unit}", m,
                              any(v > c for v, c in zip(values, caps)), detail))
    if criteria.no_body_contact:
        out.append(Margin("body_contact", "no body contact", None, oc == "body_contact", f"outcome {oc}"))
    out.append(Margin("settling", "at rest within t_final, no numerical failure", None,
                      oc in ("failed", "time_out"), f"outcome {oc}"))
    return out


@dataclass(frozen=True)
class Closest:
    """Per criterion, the landing nearest to violating it (a violating one first): its run, `Margin` and how
    many of the `landings` violate the criterion."""

    run_id: str | None      # None for a pass/fail-only criterion that every landing meets (none is nearer)
    margin: Margin
    failing: int
    landings: int

    def as_json(self) -> dict:
        m = self.margin
        return {"criterion": m.criterion, "requirement": m.requirement, "run_id": self.run_id, "margin": m.margin,
                "failed": m.failed, "detail": m.detail, "failing": self.failing, "landings": self.landings}

    def line(self) -> str:
        """"no cell bottoms: mc-21, margin -0.021 (leg 2 rot1 0.3063 m of 0.3 m stroke); 2 of 116 fail"."""
        m = self.margin
        if self.run_id is None:
            return f"{m.requirement}: met by all {self.landings} (pass/fail only)"
        head = f"{m.requirement}: {self.run_id}, " + (f"margin {m.margin:+.3f} ({m.detail})" if m.margin is not None
                                                        else m.detail)
        return head + (f"; {self.failing} of {self.landings} fail" if self.failing else "")


def closest(rows, criteria: Criteria, limits) -> list[Closest]:
    """For each criterion, the landing row nearest to violating it: among the rows that violate it, else
    among all, the smallest margin (rows with `limits` alongside, one `LandingLimits` per row). Criteria
    that a landing violates come first, then by margin, smallest first (pass/fail-only criteria last of
    their group)."""
    table = [(r["run_id"], margins(r, criteria, lim)) for r, lim in zip(rows, limits)]
    if not table:
        return []
    out = []
    for k in range(len(table[0][1])):
        col = [(run_id, ms[k]) for run_id, ms in table]
        run_id, m = min(col, key=lambda c: (not c[1].failed, inf if c[1].margin is None else c[1].margin))
        unranked = m.margin is None and not m.failed
        out.append(Closest(None if unranked else run_id, m, sum(c[1].failed for c in col), len(col)))
    return sorted(out, key=lambda c: (not c.margin.failed, c.margin.margin is None,
                                      0.0 if c.margin.margin is None else c.margin.margin))
