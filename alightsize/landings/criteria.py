"""Study criteria for one landing (AFFDL-TR-66-33 Sec. II): acceleration limits and onset rates per body
axis, no bottoming of any cell, no tumbling, no body contact. Walking counts as a successful alightment
(Sec. II.B: "these runs were considered successful")."""

from __future__ import annotations

from dataclasses import dataclass

from alightsize.common.config import Node

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
        limits = ((self.max_xdd_g, summary["peak"]["xdd_g"], "g"), (self.max_onset_g_s, summary["peak"]["onset_g_s"], "g/s"))
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


def _triple(node: Node, key: str) -> tuple[float, float, float]:
    v = node.raw(key)
    if not (isinstance(v, list) and len(v) == 3 and all(isinstance(x, (int, float)) and not isinstance(x, bool)
                                                       and x > 0 for x in v)):
        raise node.error(key, "three positive limits, one per body axis (1, 2, 3 = roll axis)", repr(v))
    return tuple(float(x) for x in v)


def read_criteria(node: Node | None) -> Criteria | None:
    """`[criteria]`: a preset ("human", "instrument") and/or explicit limits; None when absent."""
    if node is None:
        return None
    node.allow(("preset", "max_xdd_g", "max_onset_g_s", "no_bottoming", "no_tumbling", "no_body_contact", "note"))
    xdd, onset = PRESETS[node.string("preset", choices=tuple(PRESETS))] if node.has("preset") else (None, None)
    xdd = _triple(node, "max_xdd_g") if node.has("max_xdd_g") else xdd
    onset = _triple(node, "max_onset_g_s") if node.has("max_onset_g_s") else onset
    flags = {k: node.boolean(k, True) for k in ("no_bottoming", "no_tumbling", "no_body_contact")}
    node.string("note", "")
    node.finish()
    return Criteria(xdd, onset, **flags)


def violation_kinds(failed: str | None) -> list[str]:
    """The kinds of a stored `criteria_failed` ("; "-joined failures) without their figures
    ("XDD(1) onset 2112 g/s > 1000 g/s" -> "XDD(1) onset > 1000 g/s"; "a cell bottomed" as it is)."""
    out = []
    for f in (failed or "").split("; "):
        if f:
            head, sep, limit = f.partition(" > ")
            out.append(" ".join(head.split(" ")[:-2]) + sep + limit if sep else f)
    return out
