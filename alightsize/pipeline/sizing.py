"""Sizing: the lightest dimension of an item that meets its required design factor in every check."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from itertools import groupby, pairwise

import numpy as np
from scipy.optimize import minimize_scalar

from alightsize.pipeline.items import Item

Fn = Callable[[float], float]                   # the governing factor, or the weight, of a dimension's value


@dataclass(frozen=True)
class Sizing:
    """Result of sizing one item: printed and sized dimension (m), factors and weights (kg); `at_bound` when
    the sized value is the range's min or max (the first or last gauge)."""

    item: str
    dimension: str
    printed: float
    sized: float
    factor_printed: float
    factor_sized: float
    weight_printed: float | None
    weight_sized: float | None
    feasible: bool
    at_bound: bool = False


class _Found(Exception):
    """A search for a feasible point met one: stop it there."""


def size_item(item: Item, grid: int = 64, rtol: float = 1e-9) -> Sizing:
    """The lightest value of the item's size dimension with min design factor >= required.

    Lightest by the item's weight (Item.weight_each); an item with no weight gets the smallest passing value,
    and among values of equal weight the smaller is taken. With standard gauges: the lightest passing gauge.
    Continuously: a scan of `grid` points, then a bounded search for the peak of the factor around each scan
    point that is a local maximum below the requirement (a feasible band narrower than the scan spacing that
    peaks between two points is found; one hump of the factor between two points at most), then within each
    feasible band the lightest point: the band's edge, located by bisection to `rtol`, where the weight is
    monotone over the band's points, else a bounded minimisation of the weight. The sized value is always one
    at which the factor was evaluated. When no value passes: infeasible, sized at the largest factor found.
    """
    spec, sec = item.size, item.section
    if spec is None or sec is None:
        raise ValueError(f"{item.name}: nothing to size (no [size] table or no section)")
    name = spec.dimension
    seen: dict[float, float] = {}

    def f(x: float) -> float:
        if x not in seen:
            seen[x] = item.governing_factor(sec.with_dim(name, x))
        return seen[x]

    def weight(x: float) -> float | None:
        w = item.weight_each(sec.with_dim(name, x))
        return None if w is None else w[0]

    def key(x: float) -> float:
        """The weight at x; x itself when the item has nothing to weigh (the smallest wins)."""
        w = weight(x)
        return x if w is None else w

    need = item.required
    if spec.gauges:
        order = sorted(spec.gauges, key=lambda g: (key(g), g))
        best = next((g for g in order if f(g) >= need), None)
        feasible = best is not None
        ends = (spec.gauges[0], spec.gauges[-1])
    else:
        best = _lightest(f, seen, key, spec.low, spec.high, need, grid, rtol)
        feasible = best is not None
        ends = (spec.low, spec.high)
    if best is None:
        best = max(seen, key=lambda x: (seen[x], x))
    w0 = item.weight_each()
    return Sizing(item.name, name, sec.dims[name], best, item.governing_factor(), f(best),
                  w0[0] if w0 else None, weight(best), feasible, best in ends)


def _lightest(f: Fn, seen: dict[float, float], key: Fn, low: float, high: float, need: float, grid: int,
              rtol: float) -> float | None:
    """The lightest x in [low, high] with f(x) >= need (by `key`), or None when no band is found; `seen` is
    f's record of every value it evaluated."""
    xs = [float(x) for x in np.linspace(low, high, grid)]
    fs = [f(x) for x in xs]
    for i, v in enumerate(fs):
        nb = fs[max(i - 1, 0):i] + fs[i + 1:i + 2]
        if v < need and all(v >= u for u in nb) and any(v > u for u in nb):
            _peak(f, xs[max(i - 1, 0)], xs[min(i + 1, grid - 1)], need, rtol)
    pts = sorted(seen)                          # the scan and every point the peak searches evaluated
    best, k = None, 0
    for passing, group in groupby(pts, key=lambda x: seen[x] >= need):
        run = list(group)
        if passing:                             # a band, with the infeasible points beyond it (None at an end)
            left = pts[k - 1] if k else None
            right = pts[k + len(run)] if k + len(run) < len(pts) else None
            x = _band_lightest(f, key, run, left, right, need, rtol)
            if best is None or (key(x), x) < (key(best), best):
                best = x
        k += len(run)
    return best


def _band_lightest(f: Fn, key: Fn, band: list[float], left: float | None, right: float | None,
                   need: float, rtol: float) -> float:
    """The lightest point of a feasible band given by its feasible points and the infeasible points beyond
    them: its lower or upper edge when the weight is monotone over these points, else the lightest of both
    edges and the weight's bounded minimum between them (when that passes)."""
    ws = [key(x) for x in ([left] if left is not None else []) + band + ([right] if right is not None else [])]
    if all(a <= b for a, b in pairwise(ws)):
        return _edge(f, band[0], left, need, rtol)
    if all(a >= b for a, b in pairwise(ws)):
        return _edge(f, band[-1], right, need, rtol)
    lo, hi = _edge(f, band[0], left, need, rtol), _edge(f, band[-1], right, need, rtol)
    x = float(minimize_scalar(key, bounds=(lo, hi), method="bounded", options={"xatol": rtol * hi}).x)
    return min((c for c in (lo, hi, x) if f(c) >= need), key=lambda c: (key(c), c))


def _edge(f: Fn, good: float, bad: float | None, need: float, rtol: float) -> float:
    """Bisection between a feasible and an infeasible point to `rtol`: the feasible end (`good` itself when
    there is no infeasible point beyond it)."""
    if bad is None:
        return good
    while abs(good - bad) > rtol * max(abs(good), abs(bad)):
        mid = 0.5 * (good + bad)
        if f(mid) >= need:
            good = mid
        else:
            bad = mid
    return good


def _peak(f: Fn, a: float, b: float, need: float, rtol: float) -> None:
    """Search [a, b] for the factor's maximum (bounded Brent, scipy), stopping at the first feasible point;
    every point it evaluates is kept in `f`'s record."""
    def neg(x: float) -> float:
        v = f(x)
        if v >= need:
            raise _Found
        return -v

    try:
        minimize_scalar(neg, bounds=(a, b), method="bounded", options={"xatol": rtol * b})
    except _Found:
        pass
