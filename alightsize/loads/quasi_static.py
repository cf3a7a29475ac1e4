"""`alightsize loads`: member-load envelopes of every configuration, the combined envelopes and the
telescoping free body (App. III), and the references through which design checks take their loads."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from math import degrees
from typing import Annotated, Literal

import numpy as np
import pandas as pd

from alightsize_sim.articulated_statics import MEMBERS

from alightsize.common.errors import InputError
from alightsize.common.typed import Number, Table
from alightsize.loads.envelopes import MEMBER_LABELS, Extreme, MemberEnvelope, combine, envelope, member_fields
from alightsize.loads.config import LoadsConfig, read_loads
from alightsize.loads.telescoping import free_body

TELESCOPING = "telescoping"
TELESCOPING_FORCES = ("AF1", "P1", "P2", "P3", "P4")
Sense = Literal["tension", "compression", "magnitude"]


@dataclass(frozen=True)
class LoadsResult:
    config: LoadsConfig
    envelopes: dict[str, tuple[MemberEnvelope, ...]]     # configurations in file order, then combinations
    telescoping: dict[str, float] | None                 # App. III free body (AF1 and P1-P4, w1, w2), SI
    telescoping_from: dict[str, Extreme] | None = None   # free-body forces a landing exceeded, and where

    @property
    def combined(self) -> dict[str, tuple[str, ...]]:
        return dict(self.config.combined)

    def to_pandas(self) -> dict[str, pd.DataFrame]:
        """The envelopes as tables, SI with the unit in each column name: "envelopes" (one row per envelope and
        member: each sense's extreme load, where it occurs, alpha, beta, psi in degrees to 9 places, and for a
        combination the configuration it comes from) and, with a telescoping leg, "telescoping" (the App. III
        free body, one row)."""
        rows = []
        for name, members in self.envelopes.items():
            for r in members:
                row = {"envelope": name, "combined": name in self.combined, "member": r.member}
                for key, e in (("tension", r.tension), ("compression", r.compression)):
                    at = [round(degrees(a), 9) for a in e.at] if e is not None else [None] * 3
                    row |= {f"{key}_N": e.value if e is not None else None,
                            **{f"{key}_{ax}_deg": v for ax, v in zip(("alpha", "beta", "psi"), at)},
                            f"{key}_configuration": e.configuration if e is not None else None}
                rows.append(row)
        columns = ["envelope", "combined", "member"] + [
            f"{key}_{field}" for key in ("tension", "compression")
            for field in ("N", "alpha_deg", "beta_deg", "psi_deg", "configuration")]
        out = {"envelopes": pd.DataFrame(rows, columns=columns)}
        if self.telescoping is not None:
            t = self.telescoping
            out["telescoping"] = pd.DataFrame([{**{f"{k}_N": t[k] for k in TELESCOPING_FORCES},
                                                "w1_N_per_m": t["w1"], "w2_N_per_m": t["w2"]}])
        return out

    def fields(self, case_name: str) -> pd.DataFrame:
        """Each member's load over the alpha-beta grid of configuration `case_name` at the psi where its magnitude
        is largest: one row per member and grid point (member, psi_deg, alpha_deg, beta_deg, load_N; NaN where a
        cell has bottomed)."""
        case = next(c for c in self.config.cases if c.name == case_name)
        (psi, alpha, beta), fields = member_fields(case, self.config.grid)
        a, b = np.meshgrid(np.degrees(alpha), np.degrees(beta), indexing="ij")
        parts = []
        for m in MEMBERS:
            f = np.asarray(fields[m])
            k = int(np.unravel_index(np.nanargmax(np.abs(f)), f.shape)[0])
            parts.append(pd.DataFrame({"member": m, "psi_deg": float(np.degrees(psi[k])), "alpha_deg": a.ravel(),
                                       "beta_deg": b.ravel(), "load_N": f[k].ravel()}))
        return pd.concat(parts, ignore_index=True)

    def plot(self, kind: str | None = None, system: str | None = None):
        """A matplotlib Figure: the heat map of configuration `kind` (default the first): each member's load over
        alpha-beta at its governing psi, in `system`'s units (default the config's)."""
        from alightsize.common import figures
        names = [c.name for c in self.config.cases]
        name = figures.pick(dict(zip(names, names)), names[0] if kind is None else kind)
        return figures.heatmap_figure(self.fields(name), name, system or self.config.units, MEMBER_LABELS)


def run_loads(cfg: LoadsConfig) -> LoadsResult:
    env = {}
    for case in cfg.cases:
        try:
            env[case.name] = envelope(case, cfg.grid)
        except ValueError as exc:
            raise InputError(str(cfg.path), f"configuration {case.name!r}", "a geometry whose equilibrium is defined "
                             "over the whole grid", str(exc)) from None
    for name, members in cfg.combined:
        env[name] = combine([env[m] for m in members])
    tele = {"AF1": cfg.telescoping.axial_crush, **free_body(cfg.telescoping)} if cfg.telescoping else None
    return LoadsResult(cfg, env, tele)


class Unloaded(Exception):
    """An optional force reference to a member not loaded in that sense: the check that reads it is dropped."""


@dataclass(frozen=True)
class LoadReference:
    """A design check load taken from an envelope: where it is used and what it resolved to."""

    key: str
    envelope: str
    member: str
    sense: str
    factor: float
    value: float                      # N, magnitude times factor
    extreme: Extreme | None           # None for the telescoping free body


def pick(res: LoadsResult, env: str, member: str, sense: str) -> Extreme | None:
    """The extreme of `member` in envelope `env` for a sense (magnitude: the larger of the two)."""
    row = next(r for r in res.envelopes[env] if r.member == member)
    cands = {"tension": [row.tension], "compression": [row.compression],
             "magnitude": [row.tension, row.compression]}[sense]
    present = [e for e in cands if e is not None]
    return max(present, key=lambda e: abs(e.value)) if present else None


class Reference(Table):
    """A force written as an envelope reference, as read (its names are checked by `check_references`);
    optional = true: a member never loaded in that sense drops the check (`Unloaded`)."""

    envelope: str
    member: str
    sense: Sense = "magnitude"
    factor: Annotated[float, Number()] = 1.0
    optional: bool = False


class ForceRef(float):
    """A force key written as an envelope reference: it stands for 1 N until `resolve` gives it its envelope's
    value (reading computes nothing)."""

    key: str                          # the force key as written, `item["Upper Truss"].check[0].load`
    ref: Reference

    def __new__(cls, key: str, ref: Reference) -> "ForceRef":
        out = super().__new__(cls, 1.0)
        out.key, out.ref = key, ref
        return out


def resolve(res: LoadsResult, ref: ForceRef, file: str) -> LoadReference:
    """The envelope value `ref` stands for (magnitude times factor); `Unloaded` when an optional reference's member
    is never loaded in its sense."""
    r = ref.ref
    if r.envelope == TELESCOPING:
        assert res.telescoping is not None          # `check_references` refuses it without a [telescoping] table
        value, extreme = abs(res.telescoping[r.member]) * r.factor, (res.telescoping_from or {}).get(r.member)
    else:
        extreme = pick(res, r.envelope, r.member, r.sense)
        if extreme is None and r.optional:
            raise Unloaded(ref.key)
        if extreme is None:
            raise InputError(file, f"{ref.key}.sense", f"a sense in which {r.member} is loaded in envelope "
                             f"{r.envelope!r}", repr(r.sense))
        value = abs(extreme.value) * r.factor
    return LoadReference(ref.key, r.envelope, r.member, r.sense, r.factor, value, extreme)


def check_references(refs: Iterable[ForceRef], cfg: LoadsConfig | None, file: str) -> None:
    """The envelope references of a design as read, checked against `cfg`'s envelope and member names before any
    envelope is computed; without a loads config a reference is an input error."""
    envelopes = () if cfg is None else tuple(c.name for c in cfg.cases) + tuple(c[0] for c in cfg.combined)
    for ref in refs:
        if cfg is None:
            raise InputError(file, ref.key, "a force with units, or an envelope reference with [loads] file = ... "
                             "in the design config", "an envelope reference but no [loads] file")
        env, member = ref.ref.envelope, ref.ref.member
        if env == TELESCOPING:
            if cfg.telescoping is None:
                raise InputError(file, f"{ref.key}.envelope", "a loads file with a [telescoping] table", "none")
            if member not in TELESCOPING_FORCES:
                raise InputError(file, f"{ref.key}.member", "one of " + ", ".join(TELESCOPING_FORCES), repr(member))
        else:
            if env not in envelopes:
                raise InputError(file, f"{ref.key}.envelope",
                                 "one of " + ", ".join(repr(k) for k in [*envelopes, TELESCOPING]), repr(env))
            if member not in MEMBERS:
                raise InputError(file, f"{ref.key}.member", "one of " + ", ".join(MEMBERS), repr(member))


def load_from(path) -> LoadsResult:
    return run_loads(read_loads(path))
