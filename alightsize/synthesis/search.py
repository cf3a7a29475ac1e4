"""`alightsize synthesize`: the lightest landing system for a lander file's requirements.

Seeded differential evolution (scipy.optimize.differential_evolution, Storn & Price 1997) over the free
parameters, each generation's candidates landed together through the sweep executors; an infeasible
candidate's objective is above every feasible one's (alightsize.synthesis.evaluate.Evaluation). The winner is
then judged on a fresh, larger Monte Carlo sample it never saw, each criterion's pass probability with its
Wilson interval; trade curves rerun the synthesis with the envelope's horizontal-speed or slope limit set to
each value, and the Pareto set of weight against peak g is read from every feasible candidate evaluated.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np
import pandas as pd
from scipy.optimize import differential_evolution

from alightsize.common.errors import InputError
from alightsize.landings.probability import Rate, pass_rates
from alightsize.pipeline.design import DesignResult
from alightsize.synthesis.evaluate import CORNER, Evaluation, Evaluator, convergence
from alightsize.synthesis.spec import Budget, SynthesisSpec, free_parameter, read_synthesis

TRADE_KEYS = {"horizontal_speed": "requirements.envelope.horizontal_speed", "slope": "requirements.envelope.slope"}


@dataclass(frozen=True)
class TradePoint:
    axis: str
    value: float                   # SI (slope in rad)
    label: str                     # as written in the lander file
    best: Evaluation


@dataclass
class SynthesisResult:
    spec: SynthesisSpec
    history: list[tuple[int, Evaluation]]          # (generation, candidate), in evaluation order
    start: Evaluation
    best: Evaluation
    start_design: DesignResult | None
    best_design: DesignResult | None
    start_rates: list[Rate]
    rates: list[Rate]                              # the winner on the search sample
    check_rates: list[Rate]                        # the winner on the fresh sample
    best_rows: list[dict]
    check_rows: list[dict]
    trade: dict[str, list[TradePoint]] = field(default_factory=dict)
    stats: dict = field(default_factory=dict)

    @property
    def ok(self) -> bool:
        """A feasible winner that meets every criterion on every landing of the fresh sample too."""
        return self.best.feasible and all(r.passed == r.n for r in self.check_rates)

    def pareto(self) -> list[Evaluation]:
        """Feasible candidates no other feasible one beats in both weight and peak g, by weight."""
        feas = sorted({e.key: e for _, e in self.history if e.feasible and e.peak_g is not None}.values(),
                      key=lambda e: (e.weight_kg, e.peak_g))
        out, best_g = [], float("inf")
        for e in feas:
            if e.peak_g < best_g:
                out.append(e)
                best_g = e.peak_g
        return out

    def convergence(self) -> list[dict]:
        """The best feasible candidate after each generation (synthesis.evaluate.convergence)."""
        return convergence(self.history)

    def to_pandas(self) -> dict[str, pd.DataFrame]:
        """"candidates" (every evaluation, SI), "convergence" (best feasible per generation), "trade" and
        "check" (pass rates of the winner on the fresh sample)."""
        names = [p.key for p in self.spec.free]
        cand = pd.DataFrame([{"generation": g, **dict(zip(names, e.x)), "feasible": e.feasible, "stage": e.stage,
                              "weight_kg": e.weight_kg, "weight_fraction": e.fraction, "objective": e.objective,
                              "landings": e.landings, "failing": e.failing, "peak_g": e.peak_g}
                             for g, e in self.history])
        return {"candidates": cand, "convergence": pd.DataFrame(self.convergence()),
                "trade": pd.DataFrame([{"axis": p.axis, "value": p.value, "label": p.label,
                                        "feasible": p.best.feasible, "weight_fraction": p.best.fraction,
                                        **dict(zip(names, p.best.x))} for pts in self.trade.values() for p in pts]),
                "check": pd.DataFrame([r.as_json() for r in self.check_rates])}

    def plot(self, kind: str = "convergence"):
        """A matplotlib Figure: "convergence", "pareto", or a trade axis ("horizontal_speed", "slope"), drawn from
        `to_pandas()`."""
        from alightsize.common import figures
        t = self.to_pandas()
        cand = t["candidates"]
        front = pd.DataFrame([{"peak_g": e.peak_g, "weight_fraction": e.fraction} for e in self.pareto()],
                             columns=["peak_g", "weight_fraction"])
        draw = figures.pick({"convergence": lambda: figures.convergence_figure(cand, t["convergence"]),
                             "pareto": lambda: figures.pareto_figure(cand[cand["feasible"].astype(bool)
                                                                          & cand["peak_g"].notna()], front),
                             **{axis: lambda a=axis: figures.trade_figure(t["trade"][t["trade"]["axis"] == a], a)
                                for axis in self.trade}}, kind)
        return draw()


def _zero(x) -> float:
    return 0.0


def search(ev: Evaluator, spec: SynthesisSpec, budget: Budget, x0,
           log: Callable[[str], None]) -> list[tuple[int, Evaluation]]:
    """Differential evolution from `x0` (in the initial population); every candidate judged through `ev`."""
    history: list[tuple[int, Evaluation]] = []
    gen = [0]

    def batch(_func, population) -> list[float]:
        t0, before = time.perf_counter(), ev.computed
        evs = ev.evaluate([np.asarray(x, dtype=float) for x in population])
        history.extend((gen[0], e) for e in evs)
        feas = [e for _, e in history if e.feasible]
        best = f"best {100 * min(e.fraction for e in feas):.3f} %" if feas else "no feasible candidate yet"
        log(f"  generation {gen[0]}: {len(evs)} candidates, {sum(e.feasible for e in evs)} feasible, "
            f"{ev.computed - before} landings in {time.perf_counter() - t0:.1f} s; {best}")
        gen[0] += 1
        return [e.objective for e in evs]

    differential_evolution(_zero, [(p.low, p.high) for p in spec.free], x0=np.asarray(x0, dtype=float),
                           seed=spec.seed, popsize=budget.population, maxiter=budget.generations, polish=False,
                           init="latinhypercube", updating="deferred", workers=batch, tol=0.0)
    return history


def _best(history: list[tuple[int, Evaluation]]) -> Evaluation:
    return min((e for _, e in history), key=lambda e: e.objective)


def synthesize(path: str | Path | SynthesisSpec, out: str | Path, start: dict[str, float] | None = None, *,
               trade: bool = True, backend: str = "pool", workers: int | None = None, scheduler: str | None = None,
               log: Callable[[str], None] = lambda s: None, progress: bool = False) -> SynthesisResult:
    """Search the lightest landing system of a lander file's `[synthesis]` (a path, or the spec already read;
    resumable in `out`). `start` replaces free parameters' starting values (SI, by key); `progress` shows a bar
    over each batch of landings on a terminal."""
    spec = path if isinstance(path, SynthesisSpec) else read_synthesis(path)
    out = Path(out)
    t0 = time.perf_counter()
    x0 = [p.start for p in spec.free]
    for k, v in (start or {}).items():
        p = free_parameter(spec, k)
        if not p.low <= v <= p.high:
            raise InputError("(start)", k, f"a start within [{p.show(p.low)}, {p.show(p.high)}]", p.show(v))
        x0[spec.free.index(p)] = v
    samples = {} if spec.budget.samples is None else {"requirements.monte_carlo.samples": spec.budget.samples}
    run = {"backend": backend, "workers": workers, "scheduler": scheduler, "stroke_margin": spec.stroke_margin,
           "quiet": not progress, "data": spec.data}
    ev = Evaluator(spec.path, spec.free, out, context=samples, **run)
    log(f"{spec.path.name}: {len(spec.free)} free parameters, up to {spec.budget.generations + 1} generations "
        f"of {spec.budget.population * len(spec.free)} candidates -> {out / 'runs.sqlite'}")
    history = search(ev, spec, spec.budget, x0, log)
    best = _best(history)
    start_ev, start_res, start_rows = ev.design(x0)
    best_ev, best_res, best_rows = ev.design(best.x)
    criteria = ev.lander(best.x).study.criteria
    check_rows: list[dict] = []
    if spec.check_samples:
        log(f"re-check of the winner on {spec.check_samples} fresh landings (seed {spec.check_seed})")
        searched_kg = best_ev.weight_kg
        fresh = {"requirements.monte_carlo.samples": spec.check_samples,
                 "requirements.monte_carlo.seed": spec.check_seed}
        best_ev, best_res, fresh_rows = ev.design(best.x, fresh, margin=False)     # the requirement, as design
        check_rows = [r for r in fresh_rows if not r["run_id"].startswith(CORNER)]
        if searched_kg is not None and best_ev.weight_kg is not None:
            log(f"  its members sized on its corners and the fresh landings: {best_ev.weight_kg:.4g} kg "
                f"(on the search's sample: {searched_kg:.4g} kg)")
    result = SynthesisResult(spec, history, start_ev, best_ev, start_res, best_res,
                             pass_rates(start_rows, criteria), pass_rates(best_rows, criteria),
                             pass_rates(check_rows, criteria), best_rows, check_rows)
    searched = ev.computed
    if trade:
        for axis, values in spec.trade.items():
            result.trade[axis] = []
            for value, label in values:
                log(f"trade point {axis} = {label}")
                context = {**_trade_context(ev, axis, value), **_samples(spec)}
                tev = Evaluator(spec.path, spec.free, out, context=context, **run)
                hist = search(tev, spec, spec.trade_budget, best.x, log)
                result.trade[axis].append(TradePoint(axis, value, label, _best(hist)))
                ev.computed += tev.computed
                ev.stored += tev.stored
                tev.close()
    result.stats = {"wall_s": time.perf_counter() - t0, "landings_computed": ev.computed,
                    "landings_stored": ev.stored, "search_landings": searched, "candidates": len(history)}
    ev.close()
    return result


def _samples(spec: SynthesisSpec) -> dict:
    n = spec.trade_budget.samples
    return {} if n is None else {"requirements.monte_carlo.samples": n}


def _trade_context(ev: Evaluator, axis: str, value: float) -> dict:
    """The envelope with its horizontal-speed limit (the low speed kept, or 0) or its slope magnitude set to
    `value` (a signed slope range scaled to it, so an into-the-slope envelope stays one); an envelope the file
    cannot have at `value` (a sloped envelope's limit not spanning it) is an InputError here, not a point of
    invalid candidates."""
    start = [p.start for p in ev.free]
    env = ev.lander(start).requirements.envelope
    if axis == "slope":
        lo, hi = env.slope
        m = max(abs(lo), abs(hi))
        rng = (lo * value / m, hi * value / m) if m > 0 else (-value, value)
        return {TRADE_KEYS[axis]: [f"{rng[0]!r} rad", f"{rng[1]!r} rad"]}
    context = {TRADE_KEYS[axis]: [f"{min(env.horizontal_speed[0], value)!r} m/s", f"{value!r} m/s"]}
    ev.lander(start, context)
    return context
