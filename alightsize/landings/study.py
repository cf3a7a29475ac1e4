"""Study configs for `alightsize sweep`: base scenes, then runs from a CSV run table, a grid over scene keys
and/or Monte Carlo dispersions, with study criteria and the layout of the outcome matrix.

```
[study]        name, title, seed (Monte Carlo), samples (per table row / grid point), history (bool)
[scenes]       KEY = "scene.toml" (relative to the study)
[runs]         table = "runs.csv", id, scene, set = {scene key = "{column} unit"}, choose.COLUMN = {...}
[grid]         scene = [KEYS], "scene.key" = [values] ...   (cartesian product, declared order)
[dispersions]  "scene.key" = {dist = "normal"|"uniform"|"truncated_normal", ...}   (alightsize.landings.dispersions)
[criteria]     preset = "human"|"instrument", max_xdd_g, max_onset_g_s, no_bottoming, ...
[compare]      column = "outcome_class"   (the run table's printed class, compared run by run)
[matrix]       rows = [parameters], columns = parameter (the layout of Tables 1-4), plot = [x, y]
```
Scene keys may index an array element: "initial.velocity[1]". A run is fully described by its scene and
overrides; its inputs hash (`scene_hash`) covers the merged scene TOML, the overrides and the version.
"""

from __future__ import annotations

import copy
import csv
import hashlib
import itertools
import json
import re
import string
import warnings
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numpy as np

from alightsize.common.version import __version__
from alightsize.common.config import SEED_MAX, Node, is_file, load_toml
from alightsize.landings.dispersions import Dispersion, read_dispersion
from alightsize.common.errors import InputError, InputWarning
from alightsize.landings.criteria import Criteria, read_criteria
from alightsize.landings.output import outcome
from alightsize.model.scene_config import SceneConfig, SceneDocument, read_scene, scene_document
from alightsize.common.units import registry

BOTTOMED_KIND = {"axial": "axial", "rot": "rotational_pad", "upper": "psi", "lower": "alpha",
                 "primary": "primary_strut", "secondary": "secondary_strut"}     # cell names by prefix
# The printed legends have one symbol for both: "+ FLIGHT TIME OUT, CAPSULE 'WALKING'" (Tables 3-4,
# their legends; Sec. II.B: every run stopped by the time limit was called walking).
PRINTED_AS = {"time_out": "walking"}
MAX_RUNS = 1_000_000
# run ids and scene keys name history files in the output folder: no separators, no leading dot
RUN_ID = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.-]{0,63}")
RUN_ID_RULE = "1-64 letters, digits, '_', '.' or '-', not starting with '.' or '-' (it names files)"


@dataclass(frozen=True)
class Run:
    run_id: str
    scene_key: str
    scene: SceneDocument       # the scene as read (its file's path: scene.path)
    overrides: dict
    params: dict               # what the user reads: table columns, grid values, samples (as written)
    reference: str | None


@dataclass(frozen=True)
class Study:
    path: Path
    name: str
    title: str
    runs: tuple[Run, ...]
    criteria: Criteria | None
    matrix_rows: tuple[str, ...]
    matrix_column: str
    history: bool
    seed: int | None
    plot_params: tuple[str, ...]   # candidates for the boundary plot's axes, in order


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


def _template_columns(value) -> list[str]:
    """The run-table columns a [runs.set] template names, in order."""
    if isinstance(value, list):
        return [c for v in value for c in _template_columns(v)]
    return [f for _, f, _, _ in string.Formatter().parse(value) if f] if isinstance(value, str) else []


def _table_points(path: Path, runs_node: Node, scenes: dict, compare: Node | None) -> list[tuple]:
    """(id, scene key, overrides, params, reference) per row of the CSV run table."""
    runs_node.allow(("table", "id", "scene", "set", "choose"))
    table = path.parent / runs_node.string("table")
    if not is_file(table):
        raise runs_node.error("table", "a CSV run table (relative to the study)", f"{str(table)!r}: no such file")
    id_col, scene_col = runs_node.string("id", "run"), runs_node.string("scene", "scene")
    setters = runs_node.table("set", optional=True)
    choose = runs_node.table("choose", optional=True)
    chooser = {col: {o: opts.table(o).data for o in opts.data}       # column -> its value -> scene overrides
               for col, opts in ((c, choose.table(c)) for c in (choose.data if choose else ()))}
    ref_col = compare.string("column") if compare else None
    try:
        with open(table, newline="", encoding="utf-8") as fh:
            rows = list(csv.DictReader(fh))
    except UnicodeDecodeError as exc:
        raise runs_node.error("table", "a CSV run table in UTF-8",
                              f"{str(table)!r}: {exc.reason} at byte {exc.start}") from None
    points = []
    for n, row in enumerate(rows, start=2):
        where = f"{table.name} line {n}"
        for col in (id_col, scene_col) + ((ref_col,) if ref_col else ()):
            if col not in row:
                raise InputError(str(table), where, f"a column {col!r}", f"columns {list(row)}")
        if row[scene_col] not in scenes:
            raise InputError(str(table), f"{where}, {scene_col}", f"one of {sorted(scenes)}", repr(row[scene_col]))
        over = {k: _fill(v, row, setters, k) for k, v in (setters.data.items() if setters else ())}
        for col, options in chooser.items():
            if row.get(col) not in options:
                raise InputError(str(table), f"{where}, {col}", f"one of {sorted(options)}", repr(row.get(col)))
            over.update(options[row[col]])
        if not RUN_ID.fullmatch(row[id_col]):
            raise InputError(str(table), f"{where}, {id_col}", RUN_ID_RULE, repr(row[id_col]))
        points.append((row[id_col], row[scene_col], over, dict(row), row[ref_col] if ref_col else None))
    return points


def _grid_points(grid: Node, scenes: dict) -> list[tuple]:
    """The cartesian product of the grid's values (declared order, scenes outermost)."""
    keys = [k for k in grid.data if k != "scene"]
    chosen = [str(s) for s in grid.raw("scene", list(scenes))]
    for s in chosen:
        if s not in scenes:
            raise grid.error("scene", f"keys of [scenes] ({', '.join(sorted(scenes))})", repr(s))
    axes = []
    for k in keys:
        values = grid.raw(k)
        if not isinstance(values, list) or not values:
            raise grid.error(k, "a non-empty array of values for this scene key", repr(values))
        seen: dict[str, int] = {}
        for i, v in enumerate(values):
            first = seen.setdefault(json.dumps(v, sort_keys=True, default=str), i)
            if first != i:
                raise InputError(str(grid.file), f"grid.{json.dumps(k)}[{i}]",
                                 f"distinct values (each grid point once; [{first}] is the same)", repr(v))
        axes.append(values)
    grid.finish()
    combos = list(itertools.product(chosen, *axes))
    width = len(str(len(combos)))
    return [(f"{c[0]}-{n + 1:0{width}d}", c[0], dict(zip(keys, c[1:])), {"scene": c[0], **dict(zip(keys, c[1:]))},
             None) for n, c in enumerate(combos)]


def _scene_key(key: str) -> str:
    """A dotted scene key as the scene's errors name it (a blank name quoted, as Node.key writes it)."""
    return ".".join(k if k.strip() else json.dumps(k) for k in key.split("."))


def _about(error_key: str, key: str) -> bool:
    """Whether a scene error at `error_key` concerns the scene key `key` (the key, an element or a part of
    it, or the array or table it indexes into)."""
    inner, outer = sorted((error_key, _scene_key(key)), key=len)
    return outer == inner or outer.startswith((inner + ".", inner + "["))


def _refusal(scene: Path, runs: list[dict], key: str, value) -> InputError | None:
    """The scene reader's error about `key` when `value` is set there in every run of `runs` (the other
    overrides of each), None when one of them takes it."""
    found = None
    for run in runs:
        try:
            with warnings.catch_warnings():           # a check, not a run: the runs warn
                warnings.simplefilter("ignore", InputWarning)
                read_scene(scene, {**run, key: value})
        except InputError as exc:
            if not _about(exc.key, key):
                return None
            found = found or exc
        else:
            return None
    return found


def _check_scene_values(path: Path, grid: Node | None, dispersions: list[Dispersion], points: list[tuple],
                        scenes: dict) -> None:
    """Each grid value, and each dispersion at its centre, read by the scene reader at the key it sets on every
    scene it is set on, alone and in the scene's first run (its first grid point or table row, the dispersions
    at their centres): one refused there both ways (a word or true where a speed is asked, a length where an
    angle is, an angle of 1e30 deg) is refused before any run, as the runs it sets would fail. A value refused
    only beside other values (a dynamic friction above one static friction of the grid) is left to fail its
    runs."""
    axes = {k: v for k, v in (grid.data.items() if grid else ()) if k != "scene"}
    for skey, first in {p[1]: p[2] for p in reversed(points)}.items():
        scene = scenes[skey]
        centres = {d.key: d.centre(_cell_shape(scene) if d.per_cell else None) for d in dispersions}
        runs = [{}, {**first, **centres}]
        for k, values in axes.items():
            for i, v in enumerate(values):
                if exc := _refusal(scene, runs, k, v):
                    raise _as_written(path, f"grid.{json.dumps(k)}[{i}]", scene, k, exc, repr(v))
        for d in dispersions:
            if exc := _refusal(scene, runs, d.key, centres[d.key]):
                raise _as_written(path, f"dispersions.{json.dumps(d.key)}", scene, d.key, exc,
                                  f"a {d.dist} distribution in {d.unit or 'plain numbers'} centred on "
                                  f"{centres[d.key]!r}")


def _as_written(path: Path, where: str, scene: Path, key: str, exc: InputError, found: str) -> InputError:
    """A scene's refusal of a value a study sets, as the study's error at the key path written there."""
    return InputError(str(path), where, f"what the scene key {_scene_key(key)} of {scene.name} takes: {exc.expected}",
                      found)


def _cell_shape(scene: SceneDocument | Path) -> tuple[int, int]:
    cfg = read_scene(scene)
    return len(cfg.cell_names), len(cfg.cell_names[0])


def _sampled(points: list[tuple], dispersions: list[Dispersion], samples: int, seed: int, scenes: dict) -> list[tuple]:
    """Each point times `samples` Monte Carlo draws; sample k uses default_rng([seed, k]) at every point."""
    shapes = {}
    out = []
    width = len(str(samples - 1))
    for pid, skey, over, params, ref in points:
        for k in range(samples):
            rng = np.random.default_rng([seed, k])
            drawn = {}
            for d in dispersions:
                if d.per_cell and skey not in shapes:
                    shapes[skey] = _cell_shape(scenes[skey])
                drawn[d.key] = d.value(rng, shapes.get(skey))
            run_id = f"{pid}-{k:0{width}d}" if pid else f"{k:0{width}d}"
            out.append((run_id, skey, {**over, **drawn}, {**params, **drawn, "sample": k}, ref))
    return out


def read_study(path: str | Path) -> Study:
    """Read a study; problems are InputErrors naming the file and key path."""
    path = Path(path)
    root = load_toml(path)
    root.allow(("study", "scenes", "runs", "grid", "dispersions", "criteria", "compare", "matrix"))
    head = root.table("study")
    head.allow(("name", "title", "seed", "samples", "history", "note"))
    name, title = head.string("name", path.stem), head.string("title", path.stem)
    history = head.boolean("history", False)
    head.string("note", "")
    scenes_node = root.table("scenes")
    scenes = {str(k): path.parent / str(v) for k, v in scenes_node.data.items()}
    for k in scenes:
        if not RUN_ID.fullmatch(k):
            raise InputError(str(path), f"scenes.{json.dumps(k)}", "a scene key of " + RUN_ID_RULE, repr(k))
    for k, f in scenes.items():
        if not is_file(f):
            raise scenes_node.error(k, "the path of a scene TOML (relative to the study)", f"{str(f)!r}: no such file")
    scenes_node.allow(tuple(scenes))
    documents = {k: scene_document(f) for k, f in scenes.items()}
    runs_node, grid = root.table("runs", optional=True), root.table("grid", optional=True)
    if runs_node and grid:
        raise root.error("grid", "either a run table [runs] or a [grid]", "both")
    compare = root.table("compare", optional=True)
    if runs_node:
        points = _table_points(path, runs_node, scenes, compare)
    elif grid:
        points = _grid_points(grid, scenes)
    else:
        points = [("" if len(scenes) == 1 else k, k, {}, {"scene": k}, None) for k in scenes]
    if not points:
        raise root.error("runs" if runs_node else "scenes", "at least one run (a scene, a grid point or a table row)",
                         "none")
    if compare:
        compare.finish()
    disp_node = root.table("dispersions", optional=True)
    dispersions = [read_dispersion(disp_node, k) for k in disp_node.data] if disp_node else []
    seed = head.integer("seed", None, minimum=0, maximum=SEED_MAX) if dispersions else None
    if dispersions and seed is None:
        raise head.error("seed", "an integer seed for the Monte Carlo dispersions", "nothing")
    if dispersions and not head.has("samples"):
        raise head.error("samples", "the number of Monte Carlo samples (an integer >= 1)", "nothing")
    samples = head.integer("samples", 1)
    if samples > 1 and not dispersions:
        raise head.error("samples", "samples only with [dispersions] (without them every sample is the same run)",
                         str(samples))
    if len(points) * samples > MAX_RUNS:
        raise head.error("samples", f"at most {MAX_RUNS:,} runs in all", f"{len(points) * samples:,}")
    head.finish()
    _check_scene_values(path, grid, dispersions, points, scenes)
    if dispersions:
        points = _sampled(points, dispersions, samples, seed, documents)
    ids = [p[0] for p in points]
    if len(set(ids)) != len(ids):
        dup = next(i for i in ids if ids.count(i) > 1)
        raise root.error("runs.id", "a unique run id per run", f"{dup!r} more than once")
    runs = tuple(Run(pid, skey, documents[skey], over, params, ref) for pid, skey, over, params, ref in points)
    criteria = read_criteria(root.table("criteria", optional=True))
    mat = root.table("matrix", optional=True)
    default_col = "scene" if len(scenes) > 1 else (list(points[0][3])[-1] if points[0][3] else "scene")
    column = mat.string("columns", default_col) if mat else default_col
    rows = tuple(mat.strings("rows")) if mat and mat.has("rows") else tuple(
        k for k in points[0][3] if k not in (column, "sample") and k not in (d.key for d in dispersions))
    if runs_node:
        candidates = [c for v in (runs_node.data.get("set") or {}).values() for c in _template_columns(v)]
    else:
        candidates = list(grid.data if grid else ()) + [d.key for d in dispersions if not d.per_cell]
    plot = tuple(mat.strings("plot")) if mat and mat.has("plot") else tuple(dict.fromkeys(candidates))
    if mat and mat.has("plot") and len(plot) != 2:
        raise mat.error("plot", "two parameter names (x, y) for the boundary plot", repr(list(plot)))
    if mat:
        mat.finish()
    root.finish()
    return Study(path, name, title, runs, criteria, rows, column, history, seed, plot)


def scene_hash(run: Run) -> str:
    """SHA-256 of the run's inputs: the merged scene TOML with the overrides applied, and the version."""
    data = copy.deepcopy(run.scene.data)
    node = Node(run.scene.path, "", data)
    for k, v in run.overrides.items():
        node.set_path(k, v)
    text = json.dumps({"scene": data, "version": __version__}, sort_keys=True, default=str)
    return hashlib.sha256(text.encode()).hexdigest()


_SUFFIX = {(0, 1, 0): ("m", "m"), (0, 1, -1): ("m_s", "m/s"), (0, 0, -1): ("rad_s", "rad/s"),
           (1, 1, -2): ("N", "N"), (1, 0, 0): ("kg", "kg"), (0, 0, 1): ("s", "s"), (0, 1, -2): ("m_s2", "m/s^2"),
           (1, 2, -2): ("J", "J")}


@lru_cache(maxsize=4096)
def _si(value) -> tuple[str, float | str]:
    """(unit suffix, value): quantities in SI (angles in deg, the contract's _deg), numbers as they are,
    other text as text."""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return "", float(value)
    try:
        q = registry().Quantity(str(value))
    except Exception:                                  # noqa: BLE001 - not a quantity: keep the text
        return "", str(value)
    if not hasattr(q, "dimensionality"):
        return "", float(q)
    if q.dimensionless:
        return ("deg", float(q.to("deg").magnitude)) if str(q.units) != "dimensionless" else ("", float(q.magnitude))
    d = q.dimensionality
    dims = (int(d.get("[mass]", 0)), int(d.get("[length]", 0)), int(d.get("[time]", 0)))
    if dims in _SUFFIX:
        return _SUFFIX[dims][0], float(q.to(_SUFFIX[dims][1]).magnitude)
    return "", str(value)


def parameter_columns(overrides: dict) -> dict:
    """Scene overrides as SQL columns named by key path and SI unit ("terrain.slope" -> terrain_slope_deg);
    arrays become one column per element."""
    out = {}

    def put(name: str, value) -> None:
        if isinstance(value, list):
            for i, v in enumerate(value):
                put(f"{name}_{i}", v)
            return
        if isinstance(value, dict):
            out[name] = json.dumps(value, sort_keys=True)
            return
        suffix, v = _si(value)
        out[f"{name}_{suffix}" if suffix else name] = v

    for key, value in overrides.items():
        put(key.replace(".", "_").replace("[", "_").replace("]", ""), value)
    return out


def agrees(outcome_class: str, printed: str) -> bool:
    """Whether a simulated outcome class reads as the printed one (time-out and walking share a symbol)."""
    return PRINTED_AS.get(outcome_class, outcome_class) == PRINTED_AS.get(printed, printed)


def outcome_class(cfg: SceneConfig, res) -> str:
    """The outcome as the report's tables class it: bottomed is split by the cell (axial, rotational pad,
    psi, alpha)."""
    out, _ = outcome(cfg, res)
    if out != "bottomed":
        return out
    cell = cfg.cell_names[res.bottomed[1]][res.bottomed[2]]
    return "bottomed_" + next(v for k, v in BOTTOMED_KIND.items() if cell.startswith(k))
