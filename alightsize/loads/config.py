"""Loads config: leg geometry, truss angles, sweep grid, configurations with their cell curves, combined
envelopes and the telescoping free body. Read and validated at the boundary; everything SI inside."""

from __future__ import annotations

import re
from dataclasses import dataclass
from math import radians
from pathlib import Path
from typing import Annotated, Any, ClassVar, Literal

import numpy as np
from pydantic import Field, PlainValidator, model_validator

from alightsize.common.config import Node, load_toml
from alightsize.common.typed import Number, Quantity, Table, refuse, validate
from alightsize.model.legs import CurveTable, GeometryTable, TrussTable
from alightsize.loads.envelopes import Grid, LegCase, default_grid
from alightsize.loads.telescoping import TelescopingLeg

NAME = re.compile(r"[A-Za-z0-9_.-]{1,31}")     # used in file and sheet names


@dataclass(frozen=True)
class LoadsConfig:
    path: Path
    title: str
    units: str
    grid: Grid
    cases: tuple[LegCase, ...]
    combined: tuple[tuple[str, tuple[str, ...]], ...]
    telescoping: TelescopingLeg | None


def _name(value: Any) -> str:
    if not isinstance(value, str):
        raise refuse("a string")
    if not NAME.fullmatch(value):
        raise refuse("1-31 letters, digits, '_', '.' or '-' (it names files and sheets)", repr(value))
    return value


Name = Annotated[str, PlainValidator(_name)]       # a name of files and sheets
Angle = Annotated[float, Quantity("angle", "any")]


class Span(Table):
    """Angles `from` `to` (inclusive) by `step`, within the class's [LOW, HIGH]."""

    LOW: ClassVar[float]
    HIGH: ClassVar[float]
    start: Angle = Field(alias="from")
    to: Angle
    step: Annotated[float, Quantity("angle")]

    @model_validator(mode="after")
    def _within(self):
        if not (self.LOW - 1e-12 <= self.start <= self.to <= self.HIGH + 1e-12):
            raise refuse(f"{np.degrees(self.LOW):g} deg <= from <= to <= {np.degrees(self.HIGH):g} deg",
                         f"from {np.degrees(self.start):g} to {np.degrees(self.to):g} deg", "to")
        return self

    def values(self) -> tuple[float, ...]:
        n = int(np.floor((self.to - self.start) / self.step + 1e-9))
        return tuple(self.start + self.step * np.arange(n + 1))


class AlphaSpan(Span):
    LOW, HIGH = 0.0, radians(90)


class BetaSpan(Span):
    LOW, HIGH = radians(-360), radians(360)


_GRID = default_grid()


class GridTable(Table):
    alpha: AlphaSpan | None = None
    beta: BetaSpan | None = None
    psi_step: Annotated[float, Quantity("angle")] = _GRID.psi_step
    bottomed: Literal["exclude", "include"] = "exclude"

    def grid(self) -> Grid:
        return Grid(self.alpha.values() if self.alpha else _GRID.alpha, self.beta.values() if self.beta else _GRID.beta,
                    self.psi_step, self.bottomed == "include")


class Configuration(Table):
    """One articulated configuration: its psi range and cells, over the file's geometry and truss."""

    name: Name
    note: str = ""
    psi_initial: Angle
    psi_final: Angle
    upper: CurveTable
    lower: CurveTable
    length_scale: Annotated[float, Number()] = 1.0
    return_spring_rate: Annotated[float, Quantity("spring_rate", "nonnegative")] | None = None
    return_spring_preload: Annotated[float, Quantity("force", "nonnegative")] | None = None

    @model_validator(mode="after")
    def _psi(self):
        p0, p1 = self.psi_initial, self.psi_final
        if not (radians(-90) < p0 < p1 < radians(90)):
            raise refuse("-90 deg < psi_initial < psi_final < 90 deg", f"{np.degrees(p0):g} and {np.degrees(p1):g} deg",
                         "psi_final")
        return self

    def case(self, geometry: GeometryTable, truss: TrussTable) -> LegCase:
        g = geometry.geometry(self.length_scale)
        g = g._replace(SPRG=g.SPRG if self.return_spring_rate is None else self.return_spring_rate,
                       PLD=g.PLD if self.return_spring_preload is None else self.return_spring_preload)
        return LegCase(self.name, g, truss.truss(), self.upper.curve(), self.lower.curve(), self.psi_initial,
                       self.psi_final)


class Combined(Table):
    name: Name
    configurations: list[str]
    note: str = ""


class TelescopingTable(Table):
    """The App. III free body of the telescoping leg."""

    axial_crush: Annotated[float, Quantity("force")]
    rotational_crush: Annotated[float, Quantity("force")]
    pad_lever: Annotated[float, Quantity("length")]
    length: Annotated[float, Quantity("length")]
    bearing_length: Annotated[float, Quantity("length")]
    friction: Annotated[float, Number("any")]
    note: str = ""

    @model_validator(mode="after")
    def _ranges(self):
        if self.pad_lever >= self.length:
            raise refuse(f"a pad lever shorter than the leg ({self.length:.4g} m)", f"{self.pad_lever:.4g} m",
                         "pad_lever")
        if not 0 <= self.friction < 1:
            raise refuse("a friction coefficient in [0, 1)", f"{self.friction}", "friction")
        return self

    def leg(self) -> TelescopingLeg:
        return TelescopingLeg(self.axial_crush, self.rotational_crush, self.pad_lever, self.length,
                              self.bearing_length, self.friction)


class LoadsHead(Table):
    title: str | None = None


class LoadsReport(Table):
    units: Literal["US", "SI"] = "US"


class LoadsFile(Table):
    """A loads config (docs/reference/loads.md)."""

    loads: LoadsHead = LoadsHead()
    report: LoadsReport = LoadsReport()
    geometry: GeometryTable | None = None
    truss: TrussTable | None = None
    grid: GridTable = GridTable()
    configuration: list[Configuration] = []
    combined: list[Combined] = []
    telescoping: TelescopingTable | None = None

    @model_validator(mode="after")
    def _consistent(self):
        if self.configuration and (self.geometry is None or self.truss is None):
            raise refuse("a [geometry] and a [truss] table for the articulated configurations", "none",
                         "geometry" if self.geometry is None else "truss")
        names = [c.name for c in self.configuration]
        dup = next((n for n in names if names.count(n) > 1), None)
        if dup:
            raise refuse("configuration names unique", f"{dup!r} twice", "configuration")
        check_combined(names, self.combined)
        if not self.configuration and self.telescoping is None:
            raise refuse("at least one [[configuration]] or a [telescoping] table", "neither", "configuration")
        return self


def check_combined(names: list[str], combined: list[Combined]) -> None:
    """Each combination names configurations of `names` and is named apart from them and the others."""
    taken = set(names)
    for i, c in enumerate(combined):
        missing = [m for m in c.configurations if m not in names]
        if missing or not c.configurations:
            raise refuse("names of configurations in this file (" + ", ".join(names) + ")",
                         repr(missing or c.configurations), f"combined[{i}].configurations")
        if c.name in taken:
            raise refuse("a name not used by a configuration or another combination", repr(c.name),
                         f"combined[{i}].name")
        taken.add(c.name)


def read_loads(path: str | Path, root: Node | None = None) -> LoadsConfig:
    """Read and validate a loads config (or the tables `root` holds, e.g. derived from a lander file);
    problems are InputErrors naming file and key path."""
    path = Path(path)
    root = load_toml(path) if root is None else root
    f = validate(LoadsFile, root.data, root.file, root.path)
    cases = tuple(c.case(f.geometry, f.truss) for c in f.configuration)
    return LoadsConfig(path, f.loads.title if f.loads.title is not None else path.stem, f.report.units,
                       f.grid.grid(), cases, tuple((c.name, tuple(c.configurations)) for c in f.combined),
                       f.telescoping.leg() if f.telescoping else None)
