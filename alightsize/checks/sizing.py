"""Sizing: the lightest dimension of an item that meets its required design factor in every check."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:                               # it sizes a design's item; it never builds one
    from alightsize.pipeline.items import Item


@dataclass(frozen=True)
class Sizing:
    """Result of sizing one item: printed and sized dimension (m), factors and weights (kg)."""

    item: str
    dimension: str
    printed: float
    sized: float
    factor_printed: float
    factor_sized: float
    weight_printed: float | None
    weight_sized: float | None
    feasible: bool


class SizingError(ValueError):
    pass


def size_item(item: Item, grid: int = 64, rtol: float = 1e-9) -> Sizing:
    """Smallest value of the item's size dimension with min design factor >= required.

    With standard gauges, the first gauge (ascending) that passes. Continuously: a scan of `grid`
    points locates the first feasible interval, bisection narrows it to `rtol`; the scan guards against
    a factor that is not monotonic in the dimension (a thin tube's buckling, for example).
    """
    spec, sec = item.size, item.section
    name = spec.dimension
    f = lambda x: item.governing_factor(sec.with_dim(name, x))  # noqa: E731
    need = item.required
    if spec.gauges:
        candidates = list(spec.gauges)
        best = next((g for g in candidates if f(g) >= need), None)
        feasible = best is not None
        best = candidates[-1] if best is None else best
    else:
        xs = [float(x) for x in np.linspace(spec.low, spec.high, grid)]
        ok = [f(x) >= need for x in xs]
        if not any(ok):
            best, feasible = spec.high, False
        elif ok[0]:
            best, feasible = spec.low, True
        else:
            j = ok.index(True)
            lo, hi = xs[j - 1], xs[j]
            while hi - lo > rtol * hi:
                mid = 0.5 * (lo + hi)
                lo, hi = (lo, mid) if f(mid) >= need else (mid, hi)
            best, feasible = hi, True
    sized = sec.with_dim(name, best)
    w0, w1 = item.weight_each(), item.weight_each(sized)
    return Sizing(item.name, name, sec.dims[name], best, item.governing_factor(), f(best),
                  w0[0] if w0 else None, w1[0] if w1 else None, feasible)
