"""Drop-test comparison report: drops 1-11 of AFFDL-TR-66-33 Sec. VI (Table 5, no drop 7) simulated with the test
model (`landings.drops`), beside the printed Tables 6-13 (permanent strokes and absorbed energies per leg and cell,
totals, percent error against the drop energy), the energy comparison of Fig. 102, and per drop XDD(1..3) and
OMD(1..3) against time with the shock spectrum of XDD(3).

`python -m alightsize.reports.drop_report --out DIR` writes DIR/drops.json (alightsize.drops/1, SI, unit-suffixed
fields), DIR/drops.html and DIR/drops.md (US units, as the report prints) and the PNGs; `alightsize reports`
regenerates reports/affdl-tr-66-33/drops/ with it. It needs the source checkout: the scenes are
examples/affdl-tr-66-33/drops/ and the printed tables alightsize/landings/drop_tables.py.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import pandas as pd

from alightsize.common.version import __version__
from alightsize.common.atomic import write_atomic
from alightsize.common.lock import output_folder
from alightsize.common.figures import drop_energy_figure, drop_histories_figure, save_png, srs_figure
from alightsize.landings.drops import DROP_NUMBERS, DROPS_DIR, FT, FT_LB, SOURCES, Drop, document, run_drop
from alightsize.landings.output import LandingResult
from alightsize.reports.rendering import template_env

# AFFDL-TR-66-33 List of Figures: drop -> (figure of XDD(1), the six run on to OMD(3); shock spectra)
FIGURES = {1: (33, 39), 2: (40, 46), 3: (47, 53), 4: (54, 60), 5: (61, None), 6: (67, 73), 8: (74, 80),
           9: (81, 87), 10: (88, 94), 11: (95, 101)}
NOTES = (
    "Simulated stroke: the permanent set of each cell, its largest deflection less the spring-back "
    "force / unloading rate (alightsize_sim/crush_cell.permanent_set); the report's analytical strokes are the "
    "permanent "
    "positions at the end of its simulation converted to absorber deflections (Sec. VI.D). The largest "
    "deflections are in drops.json (simulated_max_deflection_m).",
    "Simulated energy: the work each cell dissipated (crushing and damping). Analytical energy: the report's "
    "simulation, corrected for the different loading and unloading slopes (Sec. VI.D). Experimental energy: "
    "the mean static crushing force times the measured permanent deflection (Sec. VI.D).",
    "Percent error = (total cell energy - drop energy) / drop energy, as the Percent Error rows of Tables 6-13; "
    "the drop energy is the printed one (horizontal kinetic energy plus weight times the nominal height, the "
    "nutation and the alightment-system deflection terms, Sec. VI.D). Difference columns: (simulated - printed) / "
    "printed; '-' where the printed value is 0.",
    "Test-model cells (not printed; examples/affdl-tr-66-33/drops/test_model_*.toml and dropNN.toml): per drop "
    "the crushing forces of the report's own simulation of it (one measured curve per cell type and drop, Sec. "
    "VI.A; recovered from the analytical energies, or for the flat drops 1 and 6 the experimental ones: "
    "alightsize/landings/drop_tables.simulation_cell_force), the scaled plateaus for drops 5 and 11, loading ramps of "
    "0.04 ft (upper) and 0.005 ft (lower) and unloading rates such that the report's analytical energies follow "
    "from its analytical strokes (E = F (s - d), d = F/2 (1/k_load - 1/k_unload), Sec. VI.D; "
    "docs/notes/drop-test-data.md section 5); capsule bottom 0.5 ft below the CG.",
    "Table 12 (drop 9): the analytical energy rows of the upper and lower cells are printed swapped (GUIDE); "
    "they are shown swapped back (alightsize/landings/drop_tables.CORRECTIONS); the total 2,680 ft-lb is unchanged.",
    "Units: ft and ft-lb as the report prints; drops.json is SI. Upper cell = parallelogram (psi) cell, lower "
    "cell = peg-leg (alpha) cell; legs numbered as Fig. 14 (docs/notes/drop-test-data.md 4.3).",
)


# ------------------------------------------------------------------ human-facing: US units, as the report prints
def _ft(v: float | None) -> str:
    """m -> ft, 4 decimals as Tables 6-13."""
    return "-" if v is None else f"{v / FT:.4f}"


def _ftlb(v: float | None) -> str:
    """J -> ft-lb, whole as Tables 6-13."""
    return "-" if v is None else f"{v / FT_LB:,.0f}"


def _pct(v: float | None) -> str:
    """A fraction as a signed percent, 1 decimal as the Percent Error rows."""
    return "-" if v is None else f"{100 * v:+.1f}"


def _row(r: dict) -> dict:
    """A cell row of a drop's table, formatted."""
    out = {"leg": r["leg"], "cell": r["cell"], "max": _ft(r["simulated_max_deflection_m"])}
    for q, unit, f in (("stroke", "m", _ft), ("energy", "J", _ftlb)):
        out |= {f"{q}_{src}": f(r[f"{src}_{q}_{unit}"]) for src in SOURCES}
        out |= {f"{q}_diff_{src}": _pct(r[f"{q}_diff_{src}_rel"]) for src in SOURCES[1:]}
    return out


def _drop_context(e: dict) -> dict:
    """One drop's section of the report, formatted."""
    t = e["totals"]
    first, spectrum = FIGURES[e["drop"]]
    total = {"leg": "Total", "cell": "", "max": _ft(sum(r["simulated_max_deflection_m"] for r in e["cells"]))}
    for src in SOURCES:
        total |= {f"stroke_{src}": _ft(t[src]["stroke_m"]) if src in t else "-",
                  f"energy_{src}": _ftlb(t[src]["energy_J"]) if src in t else "-"}
    for src in SOURCES[1:]:
        total |= {f"stroke_diff_{src}": _pct(t["simulated"].get(f"stroke_diff_{src}_rel")),
                  f"energy_diff_{src}": _pct(t["simulated"].get(f"energy_diff_{src}_rel"))}
    en = e["energy"]
    return {"number": e["drop"], "title": e["title"], "scene": e["scene"], "table": e["table"], "note": e["note"],
            "report_text": e["report_text"], "outcome": e["outcome"], "reason": e["reason"],
            "t_end": f"{e['t_end_s']:.4f}", "rows": [_row(r) for r in e["cells"]], "total": total,
            "drop_energy": _ftlb(e["drop_energy_J"]),
            "error": _pct(t["simulated"]["energy_error_rel"]),
            "printed_error": {src: _pct(t[src]["printed_energy_error_rel"]) if src in t else "-"
                              for src in SOURCES[1:]},
            # released energy: kinetic at first contact + potential change (docs/contracts.md, alightsize.simulate/1)
            "released": _ftlb(en["initial_J"] + en["potential_change_J"]), "closure": f"{en['closure_rel']:.1e}",
            "peak_xdd": ", ".join(f"{v:.1f}" for v in e["peak"]["xdd_g"]),
            "peak_omd": ", ".join(f"{v:,.0f}" for v in e["peak"]["omd_rad_s2"]),
            "histories": f"drop{e['drop']:02d}_xdd_omd.png", "srs": f"drop{e['drop']:02d}_srs_xdd3.png",
            "figures": f"{first}-{first + 5}", "srs_figure": spectrum,
            "damping": f"{100 * e['srs_xdd3']['damping_rel']:.0f}"}


def context(doc: dict) -> dict:
    """Everything the drops templates show, formatted in US units."""
    c = doc["closure"]
    overview = [{"drop": e["drop"], "table": e["table"] or "-", "outcome": e["outcome"],
                 "drop_energy": _ftlb(e["drop_energy_J"]), "energy": _ftlb(e["totals"]["simulated"]["energy_J"]),
                 "error": _pct(e["totals"]["simulated"]["energy_error_rel"]),
                 "analytical_error": _pct(e["totals"].get("analytical", {}).get("printed_energy_error_rel")),
                 "experimental_error": _pct(e["totals"].get("experimental", {}).get("printed_energy_error_rel")),
                 "stroke": _ft(e["totals"]["simulated"]["stroke_m"]),
                 "analytical_stroke": _ft(e["totals"].get("analytical", {}).get("stroke_m")),
                 "stroke_diff": _pct(e["totals"]["simulated"].get("stroke_diff_analytical_rel")),
                 "xdd3": f"{e['peak']['xdd_g'][2]:.1f}"} for e in doc["drops"]]
    return {"title": "AFFDL-TR-66-33 drop tests: simulation beside Tables 6-13", "version": __version__,
            "overview": overview, "drops": [_drop_context(e) for e in doc["drops"]], "notes": NOTES,
            "closure": {src: {"mean": f"{100 * c[src]['mean_abs_energy_error_rel']:.1f}",
                              "max": f"{100 * c[src]['max_abs_energy_error_rel']:.1f}"} for src in SOURCES},
            "stroke_closure": {"mean": f"{100 * c['simulated']['mean_abs_stroke_diff_analytical_rel']:.1f}",
                               "max": f"{100 * c['simulated']['max_abs_stroke_diff_analytical_rel']:.1f}"}}


def render(doc: dict, kind: str) -> str:
    """The report as HTML (autoescaped) or Markdown (kind "html" or "md")."""
    return template_env(kind == "html").get_template(f"drops_report.{kind}.j2").render(**context(doc))


# ------------------------------------------------------------------ plots
def _save(fig, path: Path) -> Path:
    write_atomic(path, lambda tmp: save_png(fig, tmp, 100))
    return path


def plot_histories(drop: Drop, path: Path) -> Path:
    """XDD(1..3) (g) and OMD(1..3) (rad/s^2) in geometric body axes against time (cf. the report's Figs. 33-100)."""
    xdd, omd = LandingResult(drop.cfg, drop.res).body()
    first = FIGURES[drop.number][0]
    title = f"{drop.cfg.title}: simulated accelerations (cf. Figs. {first}-{first + 5})"
    return _save(drop_histories_figure(drop.res.t, xdd, omd, title), path)


def plot_srs(entry: dict, path: Path) -> Path:
    """Maximax shock response spectrum of XDD(3) (cf. the report's Shock Spectra Comparison figures)."""
    spec = entry["srs_xdd3"]
    figure = FIGURES[entry["drop"]][1]
    title = (f"{entry['title']}: shock spectrum of XDD(3), {spec['damping_rel']:.0%} damping"
             + (f" (cf. Fig. {figure})" if figure else ""))
    table = pd.DataFrame({"frequency_Hz": spec["frequency_Hz"], "acceleration_g": spec["acceleration_g"]})
    return _save(srs_figure(table, spec["damping_rel"], title, layout=None), path)


def plot_energy(doc: dict, path: Path) -> Path:
    """Total cell energy against the drop energy for every drop with a table, with the 1:1 line (Fig. 102)."""
    tabled = [e for e in doc["drops"] if e["table"] is not None]
    table = pd.DataFrame({"drop": [e["drop"] for e in tabled],
                          "drop_energy": [e["drop_energy_J"] / FT_LB for e in tabled],
                          **{src: [e["totals"][src][key] / FT_LB for e in tabled]
                             for src, key in (("simulated", "energy_J"), ("analytical", "printed_energy_J"),
                                              ("experimental", "printed_energy_J"))}})
    return _save(drop_energy_figure(table), path)


def write_drop_report(out_dir: Path, folder: Path = DROPS_DIR) -> list[Path]:
    """Simulate every drop of `folder` and write drops.json, drops.html, drops.md and the PNGs into out_dir."""
    out_dir = Path(out_dir)
    drops = [run_drop(n, folder) for n in DROP_NUMBERS]
    doc = document(drops)
    files = [write_atomic(out_dir / "drops.json", json.dumps(doc, indent=2) + "\n"),
             write_atomic(out_dir / "drops.html", render(doc, "html")),
             write_atomic(out_dir / "drops.md", render(doc, "md")),
             plot_energy(doc, out_dir / "fig102_energy.png")]
    for d, e in zip(drops, doc["drops"]):
        files += [plot_histories(d, out_dir / f"drop{d.number:02d}_xdd_omd.png"),
                  plot_srs(e, out_dir / f"drop{d.number:02d}_srs_xdd3.png")]
    return files


def main(argv: list[str] | None = None) -> int:
    """`python -m alightsize.reports.drop_report --out DIR [--drops FOLDER]`."""
    p = argparse.ArgumentParser(prog="python -m alightsize.reports.drop_report", description=__doc__.split("\n\n")[0])
    p.add_argument("--out", required=True, help="output folder")
    p.add_argument("--drops", default=str(DROPS_DIR), help="folder of the drop scenes drop01.toml ... drop11.toml")
    args = p.parse_args(argv)
    with output_folder(Path(args.out)) as stage:           # the files appear together, as the CLI's do
        files = write_drop_report(stage.path, Path(args.drops))
        doc = json.loads(files[0].read_text())
        stage.publish()
    for e in doc["drops"]:
        t = e["totals"]["simulated"]
        print(f"drop {e['drop']:2d}: {e['outcome']:<12} cell energy {_ftlb(t['energy_J']):>6} ft-lb, error "
              f"{_pct(t['energy_error_rel']):>5} %, total stroke vs analytical "
              f"{_pct(t.get('stroke_diff_analytical_rel')):>5} %")
    print(f"wrote {len(files)} files to {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
