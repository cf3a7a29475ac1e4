"""A crushable cell with memory (AFFDL-TR-66-33 Sec. V.E.3, Fig. 19, subroutine CURVE).

Loading (deflection at or past the previous maximum) follows the loading curve; past its last point the
cell is bottomed and the force either keeps the last segment's slope (a stiff stop) or holds an optional
yield plateau (Sec. II.E, "yield after bottoming"). Unloading and reloading short of the maximum follow a
spring of rate k from (dmax, fmax) with a parallel damper whose force is held below 0.9 of the spring
force, as CURVE does; the force never exceeds fmax and never pulls. The permanent set is dmax - fmax / k.

The state (dmax, fmax) changes only when a step is accepted (`commit`), so trial stages of an
integrator never leave memory behind. Scalars in, scalars out: the functions are compiled with numba
(NUMBA_DISABLE_JIT=1 runs them as plain Python).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
from numba import njit

from .crush_curve import CrushCurve


@dataclass(frozen=True)
class CellModel:
    """Loading curve, unloading spring rate k (N/m), damping c (N s/m), force factor (per-cell scatter,
    Sec. VI.C) and an optional yield plateau after bottoming (N, None for a stiff stop)."""

    curve: CrushCurve
    k: float
    c: float = 0.0
    factor: float = 1.0
    yield_force: float | None = None

    def __post_init__(self):
        if not self.k > 0:
            raise ValueError("the unloading spring rate must be positive")
        if self.c < 0 or self.factor <= 0:
            raise ValueError("damping must be >= 0 and the force factor > 0")

    @cached_property
    def arrays(self):
        """(deflections, forces x factor, k, c, yield force or -1): the numba-friendly form, built once."""
        return (np.asarray(self.curve.deflection, float), self.factor * np.asarray(self.curve.force, float),
                self.k, self.c, -1.0 if self.yield_force is None else self.yield_force)


@njit(cache=True)
def loading_force(d: np.ndarray, f: np.ndarray, yield_force: float, delta: float) -> float:
    """Force on the loading curve at deflection delta, bottoming branch included."""
    if delta <= 0.0:
        return 0.0
    if delta <= d[-1]:
        i = 1
        while d[i] < delta:
            i += 1
        span = d[i] - d[i - 1]
        return f[i] if span <= 0.0 else f[i - 1] + (f[i] - f[i - 1]) * (delta - d[i - 1]) / span
    if yield_force >= 0.0:
        return yield_force
    slope = (f[-1] - f[-2]) / (d[-1] - d[-2]) if d[-1] > d[-2] else 0.0
    return f[-1] + slope * (delta - d[-1])


@njit(cache=True)
def force(d, f, k, c, yield_force, memory, delta, rate) -> float:
    """Cell force at deflection delta and rate (1/s of deflection), given the committed memory = (dmax, fmax)."""
    dmax, fmax = memory
    if delta >= dmax:
        return loading_force(d, f, yield_force, delta)
    spring = fmax - k * (dmax - delta)
    if spring <= 0.0:
        return 0.0
    damper = c * rate
    if abs(damper) > 0.9 * spring:
        damper = 0.9 * spring if damper > 0 else -0.9 * spring
    return min(max(spring + damper, 0.0), fmax)


@njit(cache=True)
def commit(d, f, yield_force, dmax, fmax, delta) -> tuple[float, float]:
    """(dmax, fmax) after an accepted step ending at deflection delta."""
    if delta > dmax:
        return delta, loading_force(d, f, yield_force, delta)
    return dmax, fmax


@njit(cache=True)
def elastic_energy(k, dmax, fmax, delta) -> float:
    """Energy the unloading spring would give back from deflection delta (J)."""
    spring = fmax - k * (dmax - delta) if delta < dmax else fmax
    return 0.5 * spring * spring / k if spring > 0 else 0.0


@njit(cache=True)
def permanent_set(k, dmax, fmax) -> float:
    """Deflection left when the cell is fully unloaded, dmax - fmax / k (0 before any crushing)."""
    return max(dmax - fmax / k, 0.0)


@njit(cache=True)
def _loading_area(d, f, yield_force, x):
    """Area under the loading branch from 0 to x (exact for the piecewise-linear curve and its bottoming)."""
    if x <= d[0]:
        return 0.0
    area = 0.0
    for i in range(len(d) - 1):
        if x <= d[i + 1]:
            return area + 0.5 * (f[i] + loading_force(d, f, yield_force, x)) * (x - d[i])
        area += 0.5 * (f[i] + f[i + 1]) * (d[i + 1] - d[i])
    return area + 0.5 * (f[-1] + loading_force(d, f, yield_force, x)) * (x - d[-1])


@njit(cache=True)
def _static_antiderivative(d, f, k, yield_force, dmax, fmax, x):
    """Antiderivative of the rate-free force at fixed memory (dmax, fmax): the spring branch below dmax,
    the loading branch above; zero at the permanent set."""
    if x < dmax:
        spring = fmax - k * (dmax - x)
        return 0.5 * spring * spring / k if spring > 0.0 else 0.0
    return 0.5 * fmax * fmax / k + _loading_area(d, f, yield_force, x) - _loading_area(d, f, yield_force, dmax)


@njit(cache=True)
def static_work(d, f, k, yield_force, dmax, fmax, delta0, delta1) -> float:
    """Work of the rate-free cell force over a step from delta0 to delta1 with the memory held, exact for the
    piecewise-linear curve whatever the path in between (the force is a function of the deflection)."""
    return (_static_antiderivative(d, f, k, yield_force, dmax, fmax, delta1)
            - _static_antiderivative(d, f, k, yield_force, dmax, fmax, delta0))
