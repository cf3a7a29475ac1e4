"""Writing `alightsize bench`'s measurements: bench.json (alightsize.bench/1), the work-precision chart and
bench.html."""

from __future__ import annotations

import json
from pathlib import Path

from alightsize.common.atomic import write_atomic
from alightsize.common.figures import bench_figure, save_png


def _setting_text(kw: dict) -> str:
    """Solver controls as words: 'rtol 1e-11, atol 1e-14, max_step 0.0005, event_tol 1e-09'."""
    return ", ".join(f"{k} {v:g}" for k, v in kw.items())


def _html(data: dict) -> str:
    from jinja2 import Environment, select_autoescape
    env = Environment(autoescape=select_autoescape(default=True))
    env.filters["setting"] = _setting_text
    return env.from_string("""<!doctype html><meta charset="utf-8"><title>alightsize bench</title>
<style>body{font-family:sans-serif;max-width:75em;margin:1em auto;padding:0 1em} img{max-width:100%;height:auto}
table{border-collapse:collapse;font-size:90%} td,th{border:1px solid #bbb;padding:2px 6px}
td.num{text-align:right}</style>
<h1>Landing simulator: speed against error</h1>
<p>{{ m.cores }} cores, Python {{ m.python }}, numpy {{ m.numpy }}, numba {{ m.numba }}. Compiled code loaded in
{{ '%.2f' % d.compile_or_cache_load_s }} s (excluded below). Every case, compiled or not, is run once untimed and then
timed {{ d.cases[0].repeats }} times: wall is the median, with the least and largest in brackets. Errors are against
a reference run of the same scene:</p>
<ul>{% for name, ref in d.references.items() %}<li>{{ name }}: {{ ref | setting }}; its own uncertainty
{{ '%.1e' % d.reference_uncertainty[name].err_peak_xdd3_rel }}</li>{% endfor %}</ul>
<p>The reference's uncertainty is its difference in peak XDD(3) from the same run at twice its fixed step or ten
times its tolerances: errors below it are not resolved.</p>
<h2>Fastest at or below {{ '%g' % (100 * d.target_error) }} % peak-XDD(3) error</h2>
<table><tr><th>scene<th>fastest<th>setting<th>ms per simulated s<th>target ms
<th>error<th>reference uncertainty<th>compiled simulator's speed-up over it</tr>
{% for t in d.targets %}{% for kind, b in t.best.items() %}<tr><td>{{ t.scene }}<td>{{ b.method }}<td>{{ b.setting }}
<td class=num>{{ '%.1f' % b.ms_per_simulated_s }}<td class=num>{{ '%.0f' % d.target_ms_per_simulated_s[t.scene] }}
<td class=num>{{ '%.1e' % b.err_peak_xdd3_rel }}
<td class=num>{{ '%.1e' % d.reference_uncertainty[t.scene].err_peak_xdd3_rel }}
<td class=num>{{ '%.1fx' % t.speedup[kind] if t.speedup and kind in t.speedup else '' }}</tr>
{% else %}<tr><td>{{ t.scene }}
<td colspan=7>no setting at or below {{ '%g' % (100 * d.target_error) }} % (reference uncertainty
{{ '%.1e' % d.reference_uncertainty[t.scene].err_peak_xdd3_rel }})</tr>
{% endfor %}{% endfor %}</table>
<p><img src="work_precision.png" alt="wall time per simulated second against error, per scene and method"></p>
<h2>Every case</h2>
<table><tr><th>scene<th>method<th>setting<th>simulated s<th>wall ms (least-largest)
<th>ms per simulated s<th>rhs evals<th>steps<th>peak XDD(3) err<th>max stroke err<th>final state err</tr>
{% for c in d.cases %}<tr><td>{{ c.scene }}<td>{{ c.method }}<td>{{ c.setting }}<td class=num>{{ '%.3f' % c.t_sim_s }}
<td class=num>{{ '%.2f' % (c.wall_s * 1000) }}
({{ '%.2f' % (c.wall_min_s * 1000) }}-{{ '%.2f' % (c.wall_max_s * 1000) }})
<td class=num>{{ '%.1f' % (c.wall_s * 1000 / c.t_sim_s) }}<td class=num>{{ '{:,}'.format(c.rhs_evals) }}
<td class=num>{{ '{:,}'.format(c.steps) }}<td class=num>{{ '%.1e' % c.err_peak_xdd3_rel }}
<td class=num>{{ '%.1e' % c.err_max_stroke_rel }}<td class=num>{{ '%.1e' % c.err_final_state_rel }}</tr>
{% endfor %}</table>""").render(d=data, m=data["machine"])


def write_bench(data: dict, out: Path) -> list[Path]:
    """bench.json, work_precision.png and bench.html in `out`."""
    out.mkdir(parents=True, exist_ok=True)
    files = [write_atomic(out / "bench.json", json.dumps(data, indent=2) + "\n")]
    write_atomic(out / "work_precision.png", lambda tmp: save_png(bench_figure(data), tmp, 100))
    files += [out / "work_precision.png", write_atomic(out / "bench.html", _html(data))]
    return files
