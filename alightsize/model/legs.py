"""Models of a leg's input tables: crush-cell curves, the articulated leg's geometry (App. III lengths) and its
truss angles. Read and validated at the boundary; SI inside."""

from __future__ import annotations

from math import radians
from typing import Annotated

import numpy as np

from alightsize_sim.articulated_kinematics import ArticulatedGeometry
from alightsize_sim.articulated_statics import TrussAngles
from alightsize_sim.crush_curve import CrushCurve

from pydantic import model_validator

from alightsize.common.typed import Number, Quantities, Quantity, Table, refuse

LENGTHS = ("AU", "AD", "AS", "AL", "AO", "AE", "AA", "AB", "AG", "AH", "AP", "AQ")


Length = Annotated[float, Quantity("length")]
LengthSigned = Annotated[float, Quantity("length", "any")]


class CurveTable(Table):
    """A crush cell's loading curve: force against deflection through the points given (Fig. 19)."""

    deflection: Annotated[tuple[float, ...], Quantities("length", minimum=2)]
    force: Annotated[tuple[float, ...], Quantities("force", minimum=2)]
    factor: Annotated[float, Number()] = 1.0
    note: str = ""

    @model_validator(mode="after")
    def _shape(self):
        d, f = self.deflection, self.force
        if len(d) != len(f):
            raise refuse(f"as many forces as deflections ({len(d)})", f"{len(f)}", "force")
        if d[0] < 0 or any(b < a for a, b in zip(d, d[1:])):
            raise refuse("deflections from 0 upward, never decreasing", repr(list(d)), "deflection")
        if any(x < 0 for x in f):
            raise refuse("forces of 0 or more (a cell never pulls)", repr(list(f)), "force")
        return self

    def curve(self) -> CrushCurve:
        return CrushCurve(self.deflection, tuple(self.factor * x for x in self.force))


class GeometryTable(Table):
    """The articulated leg's geometry, FORTRAN names of Fig. 22-25 (docs/reference/scene.md)."""

    AU: Length
    AD: Length
    AS: Length
    AL: Length
    AO: LengthSigned = 0.0
    AE: LengthSigned = 0.0
    AA: LengthSigned = 0.0
    AB: LengthSigned = 0.0
    AG: LengthSigned = 0.0
    AH: LengthSigned = 0.0
    AP: LengthSigned = 0.0
    AQ: LengthSigned = 0.0
    PHI: Annotated[float, Quantity("angle", "any")] = 0.0
    return_spring_rate: Annotated[float, Quantity("spring_rate", "any")] = 0.0
    return_spring_preload: Annotated[float, Quantity("force", "any")] = 0.0
    note: str = ""

    @model_validator(mode="after")
    def _springs(self):
        sprg, pld = self.return_spring_rate, self.return_spring_preload
        if sprg < 0 or pld < 0:
            raise refuse("a return spring rate and preload of 0 or more", f"{sprg}, {pld}", "return_spring_rate")
        return self

    def geometry(self, scale: float = 1.0) -> ArticulatedGeometry:
        return ArticulatedGeometry(PHI=self.PHI, SPRG=self.return_spring_rate, PLD=self.return_spring_preload,
                                   **{k: scale * getattr(self, k) for k in LENGTHS})


class TrussTable(Table):
    """The parallelogram truss's member angles (Fig. 104-105)."""

    theta: Annotated[float, Quantity("angle")]
    gamma: Annotated[float, Quantity("angle")]
    rho: Annotated[float, Quantity("angle")]
    note: str = ""

    @model_validator(mode="after")
    def _angles(self):
        a = (self.theta, self.gamma, self.rho)
        if not all(0 < v < radians(90) for v in a) or self.gamma + self.rho >= radians(180):
            raise refuse("truss angles between 0 and 90 deg", ", ".join(f"{np.degrees(v):.4g} deg" for v in a), "theta")
        return self

    def truss(self) -> TrussAngles:
        return TrussAngles(self.theta, self.gamma, self.rho)
