"""A traced calculation: each line of a stress or weight sheet keeps its formula, its inputs and its value, so
reports show how a number came out (after the Appendix IV and V sheets)."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Step:
    """One line of a stress sheet: `formula` uses {names} of `inputs`, each (name, SI value, dimension)."""

    label: str
    symbol: str
    formula: str
    inputs: tuple[tuple[str, float, str], ...]
    value: float
    dim: str
