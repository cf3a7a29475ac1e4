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
from typing import Annotated, Any

import numpy as np
from pydantic import PlainValidator, model_validator

from alightsize.common.version import __version__
from alightsize.common.config import SEED_MAX, Node, _describe, is_file, key_name, load_toml
from alightsize.common.typed import Integer, Table, refuse, validate
from alightsize.landings.dispersions import Dispersion, DispersionTable, SpeedRegion, dispersion
from alightsize.common.errors import InputError, InputWarning
from alightsize.landings.criteria import Criteria, CriteriaTable
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


class StudyHead(Table):
    """`[study]`: name and title (default: the file's name), the Monte Carlo seed and samples."""

    name: str | None = None
    title: str | None = None
    seed: Annotated[int, Integer(0, SEED_MAX)] | None = None
    samples: Annotated[int, Integer(1)] | None = None
    history: bool = False
    note: str = ""


class RunsTable(Table):
    """`[runs]`: a CSV run table, its id and scene columns, the scene keys set from its columns (`set`, templates
    "{column}") and chosen by a column's value (`choose.COLUMN.VALUE`)."""

    table: str
    id: str = "run"
    scene: str = "scene"
    set: dict[str, Any] = {}
    choose: dict[str, dict[str, dict[str, Any]]] = {}


class Compare(Table):
    """`[compare]`: the run table's column of printed outcome classes."""

    column: str


class Matrix(Table):
    """`[matrix]`: the outcome matrix's rows and column, the boundary plot's two axes."""

    rows: list[str] | None = None
    columns: str | None = None
    plot: list[str] | None = None


def _grid(value: Any) -> dict[str, list]:
    """`[grid]`: `scene` (an array of [scenes] keys) and scene keys, each with a non-empty array of distinct
    values."""
    if not isinstance(value, dict):
        raise refuse("a table")
    for k, values in value.items():
        if k == "scene":
            if not isinstance(values, list) or not all(isinstance(v, str) for v in values):
                raise refuse("an array of [scenes] keys", _describe(values), k)
            continue
        if not isinstance(values, list) or not values:
            raise refuse("a non-empty array of values for this scene key", repr(values), k)
        seen: dict[str, int] = {}
        for i, v in enumerate(values):
            first = seen.setdefault(json.dumps(v, sort_keys=True, default=str), i)
            if first != i:                    # the key quoted, as TOML writes a dotted key
                raise refuse(f"distinct values (each grid point once; [{first}] is the same)", repr(v),
                             f"{json.dumps(k)}[{i}]")
    return value


class StudyFile(Table):
    """A study file (docs/reference/study.md)."""

    study: StudyHead
    scenes: dict[str, str]
    runs: RunsTable | None = None
    grid: Annotated[dict[str, list], PlainValidator(_grid)] | None = None
    dispersions: dict[str, DispersionTable] = {}
    criteria: CriteriaTable | None = None
    compare: Compare | None = None
    matrix: Matrix | None = None

    @model_validator(mode="after")
    def _consistent(self):
        head = self.study
        if self.runs and self.grid is not None:
            raise refuse("either a run table [runs] or a [grid]", "both", "grid")
        if self.compare and not self.runs:
            raise refuse("[compare] only with a run table [runs] (it names a column of the table)",
                         "a [grid]" if self.grid is not None else "no [runs]", "compare")
        if self.dispersions:
            if head.seed is None:
                raise refuse("an integer seed for the Monte Carlo dispersions", "nothing", "study.seed")
            if head.samples is None:
                raise refuse("the number of Monte Carlo samples (an integer >= 1)", "nothing", "study.samples")
        else:
            if head.seed is not None:
                raise refuse("seed only with [dispersions] (without them nothing is drawn)", str(head.seed),
                             "study.seed")
            if head.samples is not None and head.samples > 1:
                raise refuse("samples only with [dispersions] (without them every sample is the same run)",
                             str(head.samples), "study.samples")
        plot = self.matrix.plot if self.matrix else None
        if plot is not None and len(plot) != 2:
            raise refuse("two parameter names (x, y) for the boundary plot", repr(plot), "matrix.plot")
        return self


def _fill(template, row: dict, file: str, key: str):
    """A TOML value with "{column}" placeholders filled from the row (lists element by element)."""
    if isinstance(template, list):
        return [_fill(t, row, file, key) for t in template]
    if not isinstance(template, str):
        return template
    try:
        return template.format(**row)
    except (KeyError, IndexError, ValueError) as exc:
        raise InputError(file, f"runs.set.{key_name(key)}", "a template naming columns of the run table",
                         f"{template!r} ({exc})") from None


def _template_columns(value) -> list[str]:
    """The run-table columns a [runs.set] template names, in order."""
    if isinstance(value, list):
        return [c for v in value for c in _template_columns(v)]
    return [f for _, f, _, _ in string.Formatter().parse(value) if f] if isinstance(value, str) else []


def _table_points(path: Path, runs: RunsTable, scenes: dict, compare: Compare | None) -> list[tuple]:
    """(id, scene key, overrides, params, reference) per row of the CSV run table."""
    table = path.parent / runs.table
    if not is_file(table):
        raise InputError(str(path), "runs.table", "a CSV run table (relative to the study)",
                         f"{str(table)!r}: no such file")
    ref_col = compare.column if compare else None
    try:
        with open(table, newline="", encoding="utf-8") as fh:
            rows = list(csv.DictReader(fh))
    except UnicodeDecodeError as exc:
        raise InputError(str(path), "runs.table", "a CSV run table in UTF-8",
                         f"{str(table)!r}: {exc.reason} at byte {exc.start}") from None
    points = []
    for n, row in enumerate(rows, start=2):
        where = f"{table.name} line {n}"
        for col in (runs.id, runs.scene) + ((ref_col,) if ref_col else ()):
            if col not in row:
                raise InputError(str(table), where, f"a column {col!r}", f"columns {list(row)}")
        if row[runs.scene] not in scenes:
            raise InputError(str(table), f"{where}, {runs.scene}", f"one of {sorted(scenes)}", repr(row[runs.scene]))
        over = {k: _fill(v, row, str(path), k) for k, v in runs.set.items()}
        for col, options in runs.choose.items():
            if row.get(col) not in options:
                raise InputError(str(table), f"{where}, {col}", f"one of {sorted(options)}", repr(row.get(col)))
            over.update(options[row[col]])
        if not RUN_ID.fullmatch(row[runs.id]):
            raise InputError(str(table), f"{where}, {runs.id}", RUN_ID_RULE, repr(row[runs.id]))
        points.append((row[runs.id], row[runs.scene], over, dict(row), row[ref_col] if ref_col else None))
    return points


def _grid_points(path: Path, grid: dict[str, list], scenes: dict) -> list[tuple]:
    """The cartesian product of the grid's values (declared order, scenes outermost)."""
    keys = [k for k in grid if k != "scene"]
    chosen = grid.get("scene", list(scenes))
    for s in chosen:
        if s not in scenes:
            raise InputError(str(path), "grid.scene", f"keys of [scenes] ({', '.join(sorted(scenes))})", repr(s))
    combos = list(itertools.product(chosen, *(grid[k] for k in keys)))
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


def _check_scene_values(path: Path, grid: dict[str, list] | None, dispersions: list[Dispersion],
                        points: list[tuple], scenes: dict) -> None:
    """Each grid value, and each dispersion at its centre, read by the scene reader at the key it sets on every
    scene it is set on, alone and in the scene's first run (its first grid point or table row, the dispersions
    at their centres): one refused there both ways (a word or true where a speed is asked, a length where an
    angle is, an angle of 1e30 deg) is refused before any run, as the runs it sets would fail. A value refused
    only beside other values (a dynamic friction above one static friction of the grid) is left to fail its
    runs."""
    axes = {k: v for k, v in (grid or {}).items() if k != "scene"}
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


def _sampled(points: list[tuple], dispersions: list[Dispersion | SpeedRegion], samples: int, seed: int,
             scenes: dict) -> list[tuple]:
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
                drawn |= d.draws(rng, shapes.get(skey))
            run_id = f"{pid}-{k:0{width}d}" if pid else f"{k:0{width}d}"
            out.append((run_id, skey, {**over, **drawn}, {**params, **drawn, "sample": k}, ref))
    return out


def read_study(path: str | Path) -> Study:
    """Read a study (StudyFile), then its scenes and run table and the runs they make; problems are InputErrors
    naming the file and key path."""
    path = Path(path)
    t = validate(StudyFile, load_toml(path).data, str(path))
    head = t.study
    scenes = {k: path.parent / v for k, v in t.scenes.items()}
    for k, f in scenes.items():
        if not RUN_ID.fullmatch(k):
            raise InputError(str(path), f"scenes.{json.dumps(k)}", "a scene key of " + RUN_ID_RULE, repr(k))
        if not is_file(f):
            raise InputError(str(path), f"scenes.{k}", "the path of a scene TOML (relative to the study)",
                             f"{str(f)!r}: no such file")
    documents = {k: scene_document(f) for k, f in scenes.items()}
    if t.runs:
        points = _table_points(path, t.runs, scenes, t.compare)
    elif t.grid is not None:
        points = _grid_points(path, t.grid, scenes)
    else:
        points = [("" if len(scenes) == 1 else k, k, {}, {"scene": k}, None) for k in scenes]
    if not points:
        raise InputError(str(path), "runs" if t.runs else "scenes",
                         "at least one run (a scene, a grid point or a table row)", "none")
    dispersions = [dispersion(str(path), k, d) for k, d in t.dispersions.items()]
    samples = head.samples or 1
    if len(points) * samples > MAX_RUNS:
        raise InputError(str(path), "study.samples", f"at most {MAX_RUNS:,} runs in all", f"{len(points) * samples:,}")
    _check_scene_values(path, t.grid, dispersions, points, scenes)
    if dispersions:
        assert head.seed is not None                       # StudyFile requires it with dispersions
        points = _sampled(points, dispersions, samples, head.seed, documents)
    ids = [p[0] for p in points]
    if len(set(ids)) != len(ids):
        dup = next(i for i in ids if ids.count(i) > 1)
        raise InputError(str(path), "runs.id", "a unique run id per run", f"{dup!r} more than once")
    runs = tuple(Run(pid, skey, documents[skey], over, params, ref) for pid, skey, over, params, ref in points)
    mat = t.matrix or Matrix()
    default_col = "scene" if len(scenes) > 1 else (list(points[0][3])[-1] if points[0][3] else "scene")
    column = mat.columns or default_col
    rows = tuple(mat.rows) if mat.rows is not None else tuple(
        k for k in points[0][3] if k not in (column, "sample") and k not in (d.key for d in dispersions))
    if t.runs:
        candidates = [c for v in t.runs.set.values() for c in _template_columns(v)]
    else:
        candidates = list(t.grid or ()) + [d.key for d in dispersions if not d.per_cell]
    plot = tuple(mat.plot) if mat.plot is not None else tuple(dict.fromkeys(candidates))
    return Study(path, head.name or path.stem, head.title or path.stem, runs,
                 t.criteria.criteria() if t.criteria else None, rows, column, head.history, head.seed, plot)


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
