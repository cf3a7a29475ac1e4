"""Crush-cell loading curve: force against deflection through the given points (AFFDL-TR-66-33 Fig. 19,
subroutine CURVE, loading branch). Zero force at or below zero deflection (a cell never pulls); past
the last point the force holds at its last value (bottomed; a stiffer branch is the caller's choice)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class CrushCurve:
    """Points of the dynamic force-deflection characteristic, SI (m, N); deflections increasing."""

    deflection: tuple[float, ...]
    force: tuple[float, ...]

    def __post_init__(self):
        d = np.asarray(self.deflection)
        if len(d) < 2 or len(d) != len(self.force) or np.any(np.diff(d) < 0) or d[0] < 0:
            raise ValueError("a curve needs two or more points, deflections starting at or above 0 and not decreasing")

    def loading_force(self, delta):
        """Force on the loading branch at deflection delta (vectorized)."""
        delta = np.asarray(delta, float)
        f = np.interp(delta, self.deflection, self.force)
        return np.where(delta > 0, f, 0.0)

    @property
    def bottoming(self) -> float:
        """Deflection at the end of the crushing plateau: the second-to-last point when the last segment
        rises (the bottoming ramp), else the last point."""
        if len(self.force) >= 3 and self.force[-1] > self.force[-2]:
            return self.deflection[-2]
        return self.deflection[-1]

    def scaled(self, factor: float) -> "CrushCurve":
        """The same curve with every force times `factor` (the report's special forces, Sec. VI.C)."""
        return CrushCurve(self.deflection, tuple(factor * f for f in self.force))
