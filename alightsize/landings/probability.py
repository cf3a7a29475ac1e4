"""How likely a design is to meet each criterion, from a sample of landings: the pass fraction with its
Wilson score interval (a binomial proportion's interval that stays inside [0, 1] and is not empty at 0 or n
successes)."""

from __future__ import annotations

from dataclasses import dataclass

from scipy.stats import binomtest

from alightsize.landings.criteria import Criteria, violation_kinds

RAN = "the simulation ran to its end"


def wilson_interval(k: int, n: int) -> tuple[float, float]:
    """95 % Wilson score interval of a proportion k/n (Wilson 1927, J. Am. Stat. Assoc. 22 p. 209), by
    scipy.stats.binomtest; (0, 1) without trials."""
    if n == 0:
        return 0.0, 1.0
    ci = binomtest(k, n).proportion_ci(0.95, method="wilson")
    return float(ci.low), float(ci.high)


@dataclass(frozen=True)
class Rate:
    criterion: str
    passed: int
    n: int
    low: float
    high: float

    @property
    def p(self) -> float:
        return self.passed / self.n if self.n else float("nan")

    def as_json(self) -> dict:
        return {"criterion": self.criterion, "passed": self.passed, "landings": self.n,
                "p": self.p if self.n else None, "wilson95": [self.low, self.high]}


def pass_rates(rows: list[dict], criteria: Criteria) -> list[Rate]:
    """Per criterion (and for all of them together), the landings of `rows` (stored runs) that meet it; a run
    that failed to simulate meets none."""
    done = [r for r in rows if r["status"] == "done"]
    kinds = [set(violation_kinds(r.get("criteria_failed"))) for r in done]
    n, crashed = len(rows), len(rows) - len(done)
    out = [Rate(text, *_counted(sum(c not in k for k in kinds), n)) for c, text in criteria.kinds().items()]
    out.append(Rate(RAN, *_counted(n - crashed, n)))
    out.append(Rate("every criterion", *_counted(sum(not k for k in kinds), n)))
    return out


def _counted(k: int, n: int) -> tuple[int, int, float, float]:
    return (k, n, *wilson_interval(k, n))
