"""Studies: a run table over base scenes, run one landing at a time (the plain loop issue 4 asks for until
the sweep runner exists), outcomes compared run by run with the report's printed ones.

A study TOML names its base scenes and a CSV run table; each row picks a scene and sets scene keys from
its columns (templates "{column} unit"), optionally through a choice table (a column value -> a set of
keys). `python -m alightsize.study STUDY.toml --out DIR` writes outcomes.json (alightsize.study/1),
comparison.csv and comparison.md.
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import sys
import time
from dataclasses import dataclass
from pathlib import Path

from .atomic import write_atomic
from .config import Node, load_toml
from .errors import InputError
from .landing_output import outcome, summary
from .scene_config import SceneConfig, read_scene

BOTTOMED_KIND = {"axial": "axial", "rot": "rotational_pad", "upper": "psi", "lower": "alpha"}


@dataclass(frozen=True)
class Run:
    run_id: str
    scene: Path
    overrides: dict
    params: dict
    reference: str | None


@dataclass(frozen=True)
class Study:
    path: Path
    name: str
    title: str
    runs: tuple[Run, ...]


def _fill(template, row: dict, node: Node, key: str):
    """A TOML value with "{column}" placeholders filled from the row (lists element by element)."""
    if isinstance(template, list):
        return [_fill(t, row, node, key) for t in template]
    if not isinstance(template, str):
        return template
    try:
        return template.format(**row)
    except (KeyError, IndexError, ValueError) as exc:
        raise node.error(key, "a template naming columns of the run table", f"{template!r} ({exc})") from None


def read_study(path: str | Path) -> Study:
    """Read a study; problems are InputErrors naming the file and key path."""
    path = Path(path)
    root = load_toml(path)
    root.allow(("study", "scenes", "runs", "compare"))
    head = root.table("study")
    head.allow(("name", "title"))
    name, title = head.string("name", path.stem), head.string("title", path.stem)
    head.finish()
    scenes_node = root.table("scenes")
    scenes = {k: path.parent / str(v) for k, v in scenes_node.data.items()}
    for k, f in scenes.items():
        if not f.is_file():
            raise scenes_node.error(k, "the path of a scene TOML (relative to the study)", f"{str(f)!r}: no such file")
    scenes_node.allow(tuple(scenes))
    runs_node = root.table("runs")
    runs_node.allow(("table", "id", "scene", "set", "choose"))
    table = path.parent / runs_node.string("table")
    if not table.is_file():
        raise runs_node.error("table", "a CSV run table (relative to the study)", f"{str(table)!r}: no such file")
    id_col, scene_col = runs_node.string("id", "run"), runs_node.string("scene", "scene")
    setters = runs_node.table("set", optional=True)
    choose = runs_node.table("choose", optional=True)
    compare = root.table("compare", optional=True)
    ref_col = compare.string("column") if compare else None
    if compare:
        compare.finish()
    with open(table, newline="", encoding="utf-8") as fh:
        rows = list(csv.DictReader(fh))
    runs = []
    for n, row in enumerate(rows, start=2):
        where = f"{table.name} line {n}"
        for col in (id_col, scene_col) + ((ref_col,) if ref_col else ()):
            if col not in row:
                raise InputError(str(table), where, f"a column {col!r}", f"columns {list(row)}")
        if row[scene_col] not in scenes:
            raise InputError(str(table), f"{where}, {scene_col}", f"one of {sorted(scenes)}", repr(row[scene_col]))
        over = {k: _fill(v, row, setters, k) for k, v in (setters.data.items() if setters else ())}
        for col, options in (choose.data.items() if choose else ()):
            if row.get(col) not in options:
                raise InputError(str(table), f"{where}, {col}", f"one of {sorted(options)}", repr(row.get(col)))
            over.update(options[row[col]])
        runs.append(Run(row[id_col], scenes[row[scene_col]], over, row, row[ref_col] if ref_col else None))
    return Study(path, name, title, tuple(runs))


def outcome_class(cfg: SceneConfig, res) -> str:
    """The outcome as the report's tables class it: bottomed is split by the cell (axial, rotational pad,
    psi, alpha)."""
    out, _ = outcome(cfg, res)
    if out != "bottomed":
        return out
    cell = cfg.cell_names[res.bottomed[1]][res.bottomed[2]]
    return "bottomed_" + next(v for k, v in BOTTOMED_KIND.items() if cell.startswith(k))


def run_study(study: Study, progress=None) -> list[dict]:
    """Every run of the study, one after the other: outcome, class, the report's class, key figures."""
    from sim.landing import simulate
    rows = []
    t0 = time.perf_counter()
    for k, run in enumerate(study.runs):
        try:
            cfg = read_scene(run.scene, run.overrides)
        except InputError as exc:                      # a value the run table put into the scene
            raise InputError(exc.file, f"{exc.key} (run {run.run_id} of {study.path.name})", exc.expected,
                             exc.found) from None
        res = simulate(cfg.scene, cfg.controls)
        s = summary(cfg, res)
        cls = outcome_class(cfg, res)
        rows.append({"run_id": run.run_id, "scene": cfg.name, "params": run.params, "outcome": s["outcome"],
                     "outcome_class": cls, "reference_class": run.reference,
                     "agrees": None if run.reference is None else cls == run.reference, "reason": s["reason"],
                     "t_end_s": s["t_end_s"], "peak_xdd_g": s["peak"]["xdd_g"],
                     "closure_rel": s["energy"]["closure_rel"], "wall_s": res.wall_s})
        if progress:
            el = time.perf_counter() - t0
            eta = el / (k + 1) * (len(study.runs) - k - 1)
            progress(f"[{k + 1}/{len(study.runs)}] {run.run_id}: {cls} (report: {run.reference}) "
                     f"{res.wall_s * 1e3:.0f} ms; elapsed {el:.1f} s, eta {eta:.0f} s")
    return rows


def write_study(study: Study, rows: list[dict], out: Path) -> list[Path]:
    """outcomes.json, comparison.csv and comparison.md (written atomically)."""
    out.mkdir(parents=True, exist_ok=True)
    compared = [r for r in rows if r["agrees"] is not None]
    agree = sum(r["agrees"] for r in compared)
    doc = {"schema": "alightsize.study/1", "study": study.name, "title": study.title, "runs": rows,
           "agreement": {"compared": len(compared), "agree": agree,
                         "fraction": agree / len(compared) if compared else None},
           "failed": [r["run_id"] for r in rows if r["outcome"] == "failed"]}
    files = [out / "outcomes.json", out / "comparison.csv", out / "comparison.md"]
    write_atomic(files[0], json.dumps(doc, indent=1) + "\n")
    buf = io.StringIO()
    w = csv.writer(buf)
    w.writerow(["run", "scene", "outcome_class", "reference_class", "agrees", "t_end_s", "peak_xdd3_g",
                "closure_rel", "reason"])
    for r in rows:
        w.writerow([r["run_id"], r["scene"], r["outcome_class"], r["reference_class"], r["agrees"],
                    f"{r['t_end_s']:.4f}", f"{r['peak_xdd_g'][2]:.2f}", f"{r['closure_rel']:.1e}", r["reason"]])
    write_atomic(files[1], buf.getvalue())
    lines = [f"# {study.title}", "", f"Agreement with the printed outcome classes: {agree} of {len(compared)}"
             + (f" ({100 * agree / len(compared):.0f} %)" if compared else ""), "",
             "| run | simulated | report | agrees | end (s) | peak XDD(3) (g) |", "|---|---|---|---|---|---|"]
    lines += [f"| {r['run_id']} | {r['outcome_class']} | {r['reference_class']} | {'yes' if r['agrees'] else 'NO'} | "
              f"{r['t_end_s']:.3f} | {r['peak_xdd_g'][2]:.1f} |" for r in rows]
    write_atomic(files[2], "\n".join(lines) + "\n")
    return files


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m alightsize.study", description=__doc__.splitlines()[0])
    ap.add_argument("study")
    ap.add_argument("--out", required=True)
    a = ap.parse_args(argv)
    try:
        study = read_study(a.study)
        rows = run_study(study, progress=lambda m: print(m, flush=True))
    except InputError as exc:
        print(f"alightsize: {exc}", file=sys.stderr)
        return 2
    files = write_study(study, rows, Path(a.out))
    print("wrote " + ", ".join(str(f) for f in files))
    return 0


if __name__ == "__main__":
    sys.exit(main())
