"""Landing cases of a design (`[landings]` in a design config): a study run through the sweep runner, each
landing's member-load extremes along its history (alightsize.loads.histories) merged into the quasi-static
envelopes the checks reference, so each member takes the larger of the App. III sweep and the landings,
and the report says which governed.

```
[landings]
study = "studies/design_landings.toml"   # relative to the design config
envelopes = ["3457"]                      # the envelopes of the [loads] file the landings extend
role = "criteria"                         # default: every landing must meet the study's [criteria];
                                          # "load_cases": the landings only supply member loads
```
"""

from __future__ import annotations

import dataclasses
from collections import Counter
import json
import tempfile
from dataclasses import dataclass
from functools import cached_property
from math import degrees, radians
from pathlib import Path
from typing import Callable, Literal

import pandas as pd

from alightsize.common.config import is_file
from alightsize.common.typed import Table
from alightsize.common.errors import InputError
from alightsize.loads.config import LoadsConfig
from alightsize.loads.interface import landing_loads
from alightsize.loads.envelopes import Extreme
from alightsize.landings.criteria import Closest, LandingLimits, closest, violation_kinds
from alightsize.loads.quasi_static import TELESCOPING, TELESCOPING_FORCES, LoadsResult, pick
from alightsize.loads.telescoping import sliding_loads
from alightsize.landings.run_store import RunStore
from alightsize.model.scene_config import impact_conditions, read_scene
from alightsize.landings.study import Study, read_study
from alightsize.landings.sweep import run_sweep

LANDING = "landing "        # prefix of the `configuration` of an extreme that a landing set
INTERFACE_COLUMNS = ["leg", "hardpoint", "force_N", "force_1_N", "force_2_N", "force_3_N", "t_s", "run_id"]
Role = Literal["criteria", "load_cases"]


@dataclass(frozen=True)
class Landings:
    study: Study
    envelopes: tuple[str, ...]
    rows: tuple[dict, ...]            # the stored runs, study order
    quasi_static: LoadsResult         # the envelopes before the landings joined them
    role: str = "criteria"            # "criteria": the design passes only if every landing meets them

    @cached_property
    def scenes(self) -> tuple:
        """Per run: its scene config (read when a report asks)."""
        return tuple(read_scene(r.scene, r.overrides) for r in self.study.runs)

    @property
    def conditions(self) -> tuple[dict, ...]:
        """Per run: scene_config.impact_conditions."""
        return tuple(impact_conditions(s) for s in self.scenes)

    @cached_property
    def closest(self) -> tuple[Closest, ...]:
        """Per criterion of the study, the landing nearest to violating it, violated criteria first
        (landings.criteria.closest); none without criteria."""
        crit = self.study.criteria
        if crit is None:
            return ()
        limits = [LandingLimits(tuple(tuple(c.curve.bottoming for c in leg.cells) for leg in s.scene.legs),
                                tuple(map(tuple, s.cell_names)), degrees(s.controls.tip_angle)) for s in self.scenes]
        return tuple(closest(self.rows, crit, limits))

    @property
    def failing(self) -> tuple[dict, ...]:
        """The runs that violate the study's criteria."""
        return tuple(r for r in self.rows if r.get("criteria_ok") == 0)

    @property
    def ok(self) -> bool:
        """Whether the landings let the design pass: always as load cases, else when every one meets them."""
        return self.role == "load_cases" or not self.failing

    @cached_property
    def interface_loads(self) -> pd.DataFrame:
        """Each body hardpoint's largest force over every landing (the interface loads; docs/contracts.md): one row
        per leg and hardpoint (INTERFACE_COLUMNS), the force's magnitude and its components along the body's
        geometric axes at that instant, the time into the landing and the landing; ties go to the earlier
        landing."""
        best: dict[tuple[int, str], dict] = {}
        order: dict[str, int] = {}                        # hardpoints in the order the leg kind lists them
        for r in self.rows:
            for d in json.loads(r.get("interface_loads_json") or "[]"):
                key = (d["leg"], d["hardpoint"])
                order.setdefault(d["hardpoint"], len(order))
                if key not in best or d["force_N"] > best[key]["force_N"]:
                    best[key] = {"leg": d["leg"], "hardpoint": d["hardpoint"], "force_N": d["force_N"],
                                 **{f"force_{i + 1}_N": c for i, c in enumerate(d["components_N"])},
                                 "t_s": d["t_s"], "run_id": r["run_id"]}
        keys = sorted(best, key=lambda k: (k[0], order[k[1]]))
        return pd.DataFrame([best[k] for k in keys], columns=INTERFACE_COLUMNS)

    def criteria_counts(self) -> str:
        """"a cell bottomed 8, XDD(1) > 1000 g/s 24": how many landings violate each kind of criterion."""
        kinds = Counter(k for r in self.failing for k in dict.fromkeys(violation_kinds(r["criteria_failed"])))
        return ", ".join(f"{k} {n}" for k, n in kinds.most_common())

    def quasi_static_load(self, envelope: str, member: str, sense: str) -> float | None:
        """The load magnitude an envelope reference had before the landings joined (None: not loaded so)."""
        if envelope == TELESCOPING:
            tele = self.quasi_static.telescoping
            assert tele is not None                 # the "telescoping" envelope is a telescoping leg's free body
            return abs(tele[member])
        qs = pick(self.quasi_static, envelope, member, sense)
        return abs(qs.value) if qs else None

    def cases(self) -> list[dict]:
        """design summary.json `landings` (docs/contracts.md): scene, conditions, outcome, criteria, peak and
        energy per landing case."""
        out = []
        for r, c in zip(self.rows, self.conditions):
            out.append({"run_id": r["run_id"], "scene": r["scene"], "parameters": json.loads(r["params_json"]),
                        "conditions": c, "outcome": r["outcome"], "outcome_class": r["outcome_class"],
                        "criteria_ok": None if r.get("criteria_ok") is None else bool(r["criteria_ok"]),
                        "criteria_failed": [f for f in (r.get("criteria_failed") or "").split("; ") if f],
                        "peak": {"xdd_g": [r[f"peak_xdd{i}_g"] for i in (1, 2, 3)],
                                 "omd_rad_s2": [r[f"peak_omd{i}_rad_s2"] for i in (1, 2, 3)],
                                 "onset_g_s": [r[f"peak_onset_xdd{i}_g_s"] for i in (1, 2, 3)]},
                        "energy": {k: r[f"energy_{k}"] for k in ("initial_J", "absorbed_J", "elastic_J",
                                                                "friction_J", "kinetic_end_J", "potential_change_J")}
                        | {"closure_rel": r["closure_rel"]},
                        "member_loads": json.loads(r["member_loads_json"])})
        return out


def _extreme(value: float | None, at: dict | None, run_id: str) -> Extreme | None:
    if value is None:
        return None
    assert at is not None                           # a member's extreme is stored with where it occurs
    return Extreme(value, (radians(at["alpha_deg"]), radians(at["beta_deg"]), radians(at["psi_deg"])),
                   LANDING + run_id)


def _larger(a: Extreme | None, b: Extreme | None) -> Extreme | None:
    """The larger magnitude; a quasi-static extreme keeps a tie."""
    if a is None or b is None:
        return a or b
    return b if abs(b.value) > abs(a.value) else a


def _landing_extremes(rows: tuple[dict, ...]):
    """(member, tension extreme, compression extreme) of every landing row."""
    for r in rows:
        for d in json.loads(r.get("member_loads_json") or "[]"):
            yield (d["member"], _extreme(d["tension_N"], d["tension_at"], r["run_id"]),
                   _extreme(d["compression_N"], d["compression_at"], r["run_id"]))


def merge(loads: LoadsResult, rows: tuple[dict, ...], names: tuple[str, ...]) -> LoadsResult:
    """The envelopes `names` extended by every landing's member extremes (others unchanged). "telescoping"
    extends the App. III free body: AF1, P1, P2 and P3 each the larger of the free body's and every landing's;
    the bearing reactions w1, w2 then follow from that P1 by App. III's equilibrium of the lower tube
    (`sliding_loads`: w1 = P1 / chi, w2 = 6 P1 (rho - a) / chi^2, so the table never prints w1, w2 of another
    P1), and P4 = mu (w1 + w2 / 2) chi from them (a landing's own P4, at its shorter length, is never larger;
    the larger is kept)."""
    env = dict(loads.envelopes)
    found = list(_landing_extremes(rows))
    for name in (n for n in names if n != TELESCOPING):
        members = []
        for m in env[name]:
            t, c = m.tension, m.compression
            for member, lt, lc in found:
                if member == m.member:
                    t, c = _larger(t, lt), _larger(c, lc)
            members.append(dataclasses.replace(m, tension=t, compression=c))
        env[name] = tuple(members)
    out = dataclasses.replace(loads, envelopes=env)
    if TELESCOPING in names:
        leg, free_body = loads.config.telescoping, loads.telescoping
        assert leg is not None and free_body is not None    # "telescoping": a telescoping leg's free body
        tele, since = dict(free_body), dict(loads.telescoping_from or {})
        for member, lt, _ in found:
            if member in TELESCOPING_FORCES and lt is not None and abs(lt.value) > abs(tele[member]):
                tele[member], since[member] = abs(lt.value), lt
        slide = sliding_loads(leg, tele["P1"])
        tele["w1"], tele["w2"] = slide["w1"], slide["w2"]
        if slide["P4"] >= tele["P4"]:
            tele["P4"] = slide["P4"]
            since.pop("P4", None)
        out = dataclasses.replace(out, telescoping=tele, telescoping_from=since)
    return out


@dataclass(frozen=True)
class LandingSpec:
    """Landing cases as read: the study, the envelopes their member loads extend and the role they play.
    `member_loads` (scene config, result) -> {"member_loads": member extremes, "interface_loads": hardpoint
    extremes} (alightsize.loads.interface.landing_loads)."""

    study: Study
    envelopes: tuple[str, ...]
    role: str = "criteria"
    member_loads: Callable | None = None


class LandingsTable(Table):
    """`[landings]` of a design config."""

    study: str
    envelopes: list[str]
    role: Role = "criteria"
    note: str = ""


def landing_spec(t: LandingsTable, design: Path, loads: LoadsConfig | None) -> LandingSpec:
    """The landing cases `[landings]` names, checked against the loads config's envelope names."""
    file = str(design)
    if loads is None or not loads.cases:
        raise InputError(file, "landings.study", "landing cases beside an articulated [loads] file (its truss angles "
                         "and envelopes)", "no articulated [loads] configuration")
    known = [c.name for c in loads.cases] + [c[0] for c in loads.combined]
    for n in t.envelopes:
        if n not in known:
            raise InputError(file, "landings.envelopes", "names of envelopes of the [loads] file (" + ", ".join(known)
                             + ")", repr(n))
    path = design.parent / t.study
    if not is_file(path):
        raise InputError(file, "landings.study", "the path of a study TOML (relative to the design config)",
                         f"{str(path)!r}: no such file")
    study = read_study(path)
    if t.role == "criteria" and study.criteria is None:
        raise InputError(file, "landings.role", f"role = \"load_cases\", or [criteria] in {path.name} for the "
                         "landings to meet", "role = \"criteria\" (the default) and a study without [criteria]")
    return LandingSpec(study, tuple(t.envelopes), t.role, landing_loads(truss=loads.cases[0].truss))


def run_landings(spec: LandingSpec, loads: LoadsResult, out: Path | None,
                 progress: bool = False) -> tuple[LoadsResult, Landings]:
    """Run the landing cases into `out` (resumable; a temporary folder when None) and merge their member loads
    into the envelopes."""
    study = spec.study
    with tempfile.TemporaryDirectory() as tmp:
        folder = out or Path(tmp)
        run_sweep(study, folder, member_loads=spec.member_loads, quiet=not progress)
        store = RunStore(folder / "runs.sqlite")
        rows = tuple(store.rows([r.run_id for r in study.runs]))
        store.close()
    return landed(spec, loads, rows)


def landed(spec: LandingSpec, loads: LoadsResult, rows: tuple[dict, ...]) -> tuple[LoadsResult, Landings]:
    """The landings of stored rows (one per run of the study, in its order) merged into the envelopes."""
    failed = [r for r in rows if r["status"] != "done"]
    if failed:
        raise InputError(str(spec.study.path), "landings", "landing cases that all run",
                         f"runs {', '.join(r['run_id'] for r in failed)} failed: {failed[0]['message']}")
    return merge(loads, rows, spec.envelopes), Landings(spec.study, spec.envelopes, rows, loads, spec.role)
