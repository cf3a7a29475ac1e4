"""Mutation fuzzer of the input readers: every bad input must end in an InputError naming the file and key.

Each case takes one shipped input file (lander, design config, scene, study, loads config, soil, material),
picks one key path in its parsed TOML and mutates it once (type, sign, magnitude, unit, nesting, names,
deletion, misspelling, arrays), writes it into a temporary copy of examples/ and materials/ (so the relative
paths it names still resolve) and runs only that kind's READ step in a worker process: read_lander,
read_design (+ prepare and audit when the config has no landings), read_scene, read_study, read_loads,
read_soil, read_material. Outcomes: ok; InputError (keyless when it names no key and is no file-level error);
internal (any other exception: a bug); nonfinite (a NaN or inf in the result that the unmutated file does
not have); hang (over --timeout s; the worker is restarted). Prints counts per kind and the distinct bugs,
deduplicated by exception type and the innermost alightsize frame.

With --landings the cases run the command line end to end instead (kinds `simulate` and `sweep`): one
mutation of a short landing scene (telescoping configuration 2, t_final 0.3 s) or of a study of 2 runs on
it, then `alightsize simulate SCENE --out out` or `alightsize sweep STUDY --out out --serial` in a worker
process (cli.main, the folder of the case as working directory). Outcomes: exit0, exit1, exit2 (bad input
naming a key); keyless (exit 2 naming none); internal (exit 3, or a sweep run stored failed by an exception
other than bad input); nonfinite (NaN or inf in summary.json / outcomes.json); outside (a file made or changed
in the case folder outside --out); hang.
Usage: python benchmarks/fuzz_inputs.py [-n 10000] [--seed 1] [--kind KIND ...] [--landings] [--json FILE]
       [--show CASE]
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import math
import multiprocessing as mp
import random
import re
import shutil
import sys
import tempfile
import time
import traceback
import warnings
from collections import Counter
from collections.abc import Callable
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
_E = "examples/affdl-tr-66-33/"
KINDS = {
    "lander": ["examples/lunar_lander.toml", "examples/capsule_3000lb.toml", "examples/lunar_tripod.toml",
               "examples/mars_tripod.toml", _E + "landers/*.toml"],
    "design": [_E + "*.toml"],
    "scene": [_E + "scenes/*.toml", "examples/terrain/lunar_regolith.toml", "examples/terrain/lunar_rock.toml",
              "examples/terrain/lunar_rock_under_leg.toml"],
    "study": [_E + "studies/*.toml", "examples/terrain/lunar_rocks_monte_carlo.toml"],
    "loads": [_E + "loads/*.toml"],
    "soil": ["materials/soils/*.toml"],
    "material": ["materials/*.toml"],
}
# What a file-level InputError (key "") expects: common/config.py load_toml.
FILE_ERRORS = ("an existing TOML file", "a readable UTF-8 TOML file", "valid TOML",
               "TOML nested less deeply than Python's recursion limit")
OUTCOMES = ("ok", "input_error", "keyless", "internal", "nonfinite", "hang")
PASSING = ("ok", "input_error", "exit0", "exit1", "exit2")
# End to end (--landings): the file each command kind mutates, beside the other, in the case folder.
LANDINGS = {"simulate": "scene.toml", "sweep": "study.toml"}
LANDING_OUTCOMES = ("exit0", "exit1", "exit2", "keyless", "internal", "nonfinite", "outside", "hang")
LANDING_SCENE = _E + "scenes/telescoping_config2.toml"
T_FINAL = "0.3 s"        # the impact (35 ft/s on 0.7 ft of stroke, over in about 0.05 s) and the settling after


def files(kind: str) -> list[str]:
    """The shipped files of `kind`, relative to the repository root (the case file of an end-to-end kind)."""
    if kind in LANDINGS:
        return [LANDINGS[kind]]
    out: list[str] = []
    for pattern in KINDS[kind]:
        out += [str(p.relative_to(ROOT)) for p in sorted(ROOT.glob(pattern)) if str(p.relative_to(ROOT)) not in out]
    return out


# ---------------------------------------------------------------------------------------------------- TOML out

_BARE = re.compile(r"[A-Za-z0-9_-]+")


def _string(s: str) -> str:
    out = []
    for ch in s:
        if ch in '"\\':
            out.append("\\" + ch)
        elif ord(ch) < 0x20 or ord(ch) == 0x7F:
            out.append(f"\\u{ord(ch):04x}")
        else:
            out.append(ch)
    return '"' + "".join(out) + '"'


def _key(k: str) -> str:
    return k if _BARE.fullmatch(k) else _string(k)


def _value(v: Any) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return "nan" if math.isnan(v) else ("inf" if v > 0 else "-inf") if math.isinf(v) else repr(v)
    if isinstance(v, str):
        return _string(v)
    if isinstance(v, list):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{_key(k)} = {_value(x)}" for k, x in v.items()) + "}"
    raise TypeError(type(v))


def dumps(data: dict) -> str:
    """TOML text of `data` (every top-level key one line; tables inline)."""
    return "".join(f"{_key(k)} = {_value(v)}\n" for k, v in data.items())


# ---------------------------------------------------------------------------------------------------- mutations

_QTY = re.compile(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*)")
NAMES = ["", " ", '"', "'", "`", "``` x", "$\\foo{$", "a/b", "../../x", "/etc/passwd", "C:\\x\\y", "x" * 5000,
         "\u0000", "\t\n", "é😀", "nan", "inf", "-1", "1e999", "true", "{}", "[0]", "a.b", "*", "con"]
NUMBERS = [0, 0.0, -0.0, 1e-30, 1e30, 1e308, -1e308, 5e-324, 1e-310, 2**63, 2**64, 10**400, -(10**400),
           float("inf"), float("-inf"), float("nan"), 1, -1, 0.5, 1e6]
MAG_TEXT = ["0", "-0", "1e-30", "1e30", "1e308", "1e999", "5e-324", "1e-400", "123456789012345678901234567890",
            "-1e30", ".5", "1e+300", "0.0000000000000000000001"]
UNITS = ["kg", "in", "lbf", "psi", "deg", "m/s", "in^4", "lb/in^3", "furlongz", "", "%", "g_0", "s", "rad/s",
         "lbf*in", "in in", "m^-1", "dimensionless", "(in", "kPa", "N/m^2"]
SPECIAL = ["1e999 in", "nan in", "inf m", "0x10 in", "1_000 in", "  3 in  ", "3in", "3 in in", "- 3 in", "3 in^99",
           "3 in**2**2", "3 m/0", "3 1/in", "3 ()", "3 deg/deg"]
OTHER = ["text", 1, 1.5, True, {}, {"a": 1}, [], [1, 2], ["a"], [{}], "1 in", "15 deg"]


def key_paths(data: Any, path: tuple = ()) -> list[tuple]:
    """Every key path below `data` (table keys and array indices), parents before children."""
    out = []
    items = data.items() if isinstance(data, dict) else enumerate(data) if isinstance(data, list) else ()
    for k, v in items:
        out.append(path + (k,))
        out += key_paths(v, path + (k,))
    return out


def written(path: tuple) -> str:
    """A key path as a user writes it: `item[2].check[0].load`, `grid."terrain.slope"`."""
    text = ""
    for k in path:
        text += f"[{k}]" if isinstance(k, int) else ("." if text else "") + _key(k)
    return text


def _mutations(value: Any, in_table: bool) -> dict[str, Callable[[Callable], Any]]:
    """The applicable mutations of `value`: name -> function of a chooser returning the new value (or _DELETE,
    or a (_RENAME, new key) pair)."""
    muts: dict[str, Callable[[Callable], Any]] = {
        "type": lambda pick: pick([o for o in OTHER if type(o) is not type(value) or o != value]),
        "nesting": lambda pick: pick([[value], {"x": value}, [[value]], [value, value], {"": value}]),
        "delete": lambda pick: _DELETE,
    }
    if in_table:
        muts["misspell"] = lambda pick: (_RENAME, pick(["typo", "upper", "extra", "drop"]))
        muts["key name"] = lambda pick: (_RENAME, pick(NAMES))
    if isinstance(value, bool):
        muts["type"] = lambda pick: pick([0, 1, "true", "yes", [], {}])
    elif isinstance(value, (int, float)):
        muts["sign"] = lambda pick: -value if value else pick([-1, -1e-9])
        muts["magnitude"] = lambda pick: pick([value * 1e-30, value * 1e30] + NUMBERS)
        muts["unit"] = lambda pick: f"{value} {pick(UNITS)}".strip()
    elif isinstance(value, str):
        m = _QTY.fullmatch(value)
        muts["name"] = lambda pick: pick(NAMES + [value + pick(NAMES), value * 100])
        muts["special"] = lambda pick: pick(SPECIAL)
        if m:
            number, unit = m.groups()
            muts["sign"] = lambda pick: number[1:] + " " + unit if number[0] == "-" else "-" + value.strip()
            muts["magnitude"] = lambda pick: f"{pick(MAG_TEXT + [repr(float(number) * 1e30)])} {unit}"
            muts["unit"] = lambda pick: f"{number} {pick(UNITS)}".strip()
            muts["to number"] = lambda pick: pick([float(number),
                                                   int(float(number)) if abs(float(number)) < 1e18 else 0])
    elif isinstance(value, list):
        muts["array"] = lambda pick: pick([[], value + value, value[1:], value[::-1], value[:1] * 100,
                                           value + [pick(OTHER)]])
    elif isinstance(value, dict):
        muts["table"] = lambda pick: pick([{}, {**value, pick(["x", "name", "", "a.b"]): pick(OTHER)},
                                           dict(list(value.items())[1:])])
    return muts


_DELETE, _RENAME = object(), object()


def _misspell(key: str, how: str) -> str:
    if how == "upper":
        return key.upper() if key.upper() != key else key + "S"
    if how == "extra":
        return key + "_x"
    if how == "drop" and len(key) > 1:
        return key[:-1]
    return key[1] + key[0] + key[2:] if len(key) > 1 and key[0] != key[1] else key + key[-1:] + "e"


def mutate(data: dict, pick: Callable[[list], Any]) -> tuple[dict, str, str]:
    """A mutated deep copy of `data`: (copy, key path as written, description). `pick` chooses from a list
    (random.Random.choice, or a hypothesis draw)."""
    data = json.loads(json.dumps(data, default=str))   # deep copy (TOML dates become strings)
    path = pick(key_paths(data))
    parent = data
    for k in path[:-1]:
        parent = parent[k]
    last = path[-1]
    value = parent[last]
    muts = _mutations(value, isinstance(parent, dict))
    name = pick(sorted(muts))
    new = muts[name](pick)
    if new is _DELETE:
        del parent[last]
        return data, written(path), "delete"
    if isinstance(new, tuple) and len(new) == 2 and new[0] is _RENAME:
        key = _misspell(last, new[1]) if name == "misspell" else new[1]
        items = [(key if k == last else k, v) for k, v in parent.items()]
        parent.clear()
        parent.update(items)
        return data, written(path), f"{name} -> {_short(key)}"
    parent[last] = new
    return data, written(path), f"{name}: {_short(value)} -> {_short(new)}"


def _short(v: Any) -> str:
    text = repr(v)
    return text if len(text) <= 60 else text[:57] + "..."


# ---------------------------------------------------------------------------------------------------- reading


def read(kind: str, path: Path) -> Any:
    """The READ step of `kind` on `path` (design configs without landings also prepared and audited)."""
    if kind == "lander":
        from alightsize.pipeline.lander import read_lander
        return read_lander(path)
    if kind == "design":
        from alightsize.pipeline.config import prepare, read_design
        from alightsize.pipeline.design import audit
        spec = read_design(path)
        return spec if spec.landings is not None else audit(prepare(spec))
    if kind == "scene":
        from alightsize.model.scene_config import read_scene
        return read_scene(path)
    if kind == "study":
        from alightsize.landings.study import read_study
        return read_study(path)
    if kind == "loads":
        from alightsize.loads.config import read_loads
        return read_loads(path)
    if kind == "soil":
        from alightsize.model.soils import read_soil
        return read_soil(path)
    if kind == "material":
        from alightsize.model.materials import read_material
        return read_material(path)
    raise ValueError(kind)


# Infinities a result may hold by design: a check without stress has design factor and margin inf
# (pipeline/audit.py). A study's run overrides and parameters are its values as written, read with the scene.
INFINITE_OK = {"factor", "margin"}
RAW = {"overrides", "params"}


def nonfinite(obj: Any, where: str = "", seen: set | None = None, depth: int = 0) -> list[str]:
    """Attribute paths of the NaN or infinite numbers in a reader's result (raw TOML kept in Nodes and scene
    documents skipped)."""
    import numpy as np

    from alightsize.common.config import Node
    from alightsize.model.scene_config import SceneDocument
    seen = set() if seen is None else seen
    if depth > 14 or id(obj) in seen or isinstance(obj, (str, bytes, Path, Node, SceneDocument, type)) or \
            callable(obj) and not dataclasses.is_dataclass(obj):
        return []
    if isinstance(obj, (float, np.floating)):
        ok = math.isfinite(obj) or obj == math.inf and where.rpartition(".")[2] in INFINITE_OK
        return [] if ok else [where or "."]
    if isinstance(obj, np.ndarray):
        return [where] if obj.dtype.kind in "fc" and not np.isfinite(obj).all() else []
    seen.add(id(obj))
    if dataclasses.is_dataclass(obj):
        items = [(f.name, getattr(obj, f.name)) for f in dataclasses.fields(obj)]
    elif isinstance(obj, dict):
        items = [(str(k), v) for k, v in obj.items()]
    elif isinstance(obj, (list, tuple)):
        items = [(f"[{i}]", v) for i, v in enumerate(obj)]
    else:
        return []
    out = []
    for name, v in items:
        if name in RAW:
            continue
        out += nonfinite(v, f"{where}.{name}" if not name.startswith("[") else where + name, seen, depth + 1)
    return out


def run_case(kind: str, path: Path, text: str) -> dict:
    """Write `text` to `path`, read it (or run the command, for an end-to-end kind); the outcome as a dict."""
    from alightsize.common.errors import InputError
    if kind in LANDINGS:
        return run_cli(kind, path.parent, text)
    path.write_text(text, encoding="utf-8")
    t0 = time.perf_counter()
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            result = read(kind, path)
    except InputError as exc:
        named = exc.key or exc.expected in FILE_ERRORS      # a file-level error names the file alone
        return {"outcome": "input_error" if named else "keyless", "message": str(exc)[:300], "file": exc.file,
                "error_key": exc.key, "s": time.perf_counter() - t0}
    except Exception as exc:  # noqa: BLE001 - every other exception is the bug being looked for
        return _internal(exc, t0)
    return {"outcome": "ok", "nonfinite": nonfinite(result), "s": time.perf_counter() - t0}


# ---------------------------------------------------------------------------------------------------- end to end


def landing_sources() -> dict[str, dict]:
    """The parsed files of the end-to-end cases: the scene (t_final short) and a study of 2 runs on it (a grid
    value, a dispersion, criteria, histories)."""
    import tomllib
    scene = tomllib.loads((ROOT / LANDING_SCENE).read_text(encoding="utf-8"))
    scene["controls"]["t_final"] = T_FINAL
    study = {"study": {"name": "fuzz", "seed": 3, "samples": 2, "history": True},
             "scenes": {"c2": LANDINGS["simulate"]},
             "grid": {"terrain.slope": ["5 deg"]},
             "dispersions": {"initial.heading": {"dist": "uniform", "low": "-30 deg", "high": "30 deg"}},
             "criteria": {"preset": "instrument"}}
    return {LANDINGS["simulate"]: scene, LANDINGS["sweep"]: study}


_ERROR = re.compile(r"alightsize: error: (?P<file>.+?): (?P<key>.+?): expected (?P<expected>.*), found ", re.DOTALL)


def _strict_json(path: Path) -> list[str]:
    """The NaN/Infinity tokens of a JSON file, by the path of the value holding them."""
    bad: list[str] = []

    def walk(v: Any, where: str) -> None:
        if isinstance(v, float) and not math.isfinite(v):
            bad.append(where or ".")
        items = v.items() if isinstance(v, dict) else enumerate(v) if isinstance(v, list) else ()
        for k, x in items:
            walk(x, f"{where}[{k}]" if isinstance(k, int) else f"{where}.{k}")
    walk(json.loads(path.read_text(encoding="utf-8")), "")
    return [f"{path.name}:{w}" for w in bad]


def _tree(folder: Path, skip: Path) -> dict[str, bytes]:
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*"))
            if p.is_file() and skip not in p.parents}


def run_cli(kind: str, folder: Path, text: str) -> dict:
    """A fresh `folder` holding the case file (`text`) and the other, unmutated; the command run there by
    cli.main; the outcome as a dict."""
    import contextlib
    import io
    import os
    import sqlite3

    from alightsize.cli import main
    shutil.rmtree(folder, ignore_errors=True)
    folder.mkdir(parents=True)
    for name, data in landing_sources().items():
        (folder / name).write_text(text if name == LANDINGS[kind] else dumps(data), encoding="utf-8")
    out = folder / "out"
    before = _tree(folder, out)
    argv = ["simulate", LANDINGS[kind], "--out", "out"] if kind == "simulate" else \
        ["sweep", LANDINGS[kind], "--out", "out", "--serial", "--quiet"]
    err, cwd, t0 = io.StringIO(), os.getcwd(), time.perf_counter()
    try:
        os.chdir(folder)
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
            code = main(argv)
    finally:
        os.chdir(cwd)
    res: dict[str, Any] = {"outcome": f"exit{code}", "s": time.perf_counter() - t0}
    message = err.getvalue()
    if code == 2:
        m = _ERROR.search(message)
        named = m is not None and (m["key"] != "(top level)" or m["expected"] in FILE_ERRORS)
        res.update(outcome="exit2" if named else "keyless", message=message.strip()[-300:],
                   **({"error_file": m["file"], "error_key": m["key"]} if m else {}))
    elif code not in (0, 1):
        frames = re.findall(r'File "([^"]*alightsize[^"]*)", line (\d+), in (\S+)', message)
        where = f"{Path(frames[-1][0]).name}:{frames[-1][1]} {frames[-1][2]}" if frames else "(no frame)"
        return {**res, "outcome": "internal", "type": f"exit {code}", "where": where, "message": message[-600:]}
    else:
        reports = [out / n for n in ("summary.json", "outcomes.json") if (out / n).exists()]
        res["values"] = [v for f in reports for v in _strict_json(f)]
        if res["values"]:
            res["outcome"] = "nonfinite"
        if (out / "runs.sqlite").exists():
            con = sqlite3.connect(out / "runs.sqlite")
            failed = con.execute("SELECT message FROM runs WHERE status = 'failed'").fetchall()
            con.close()
            raised = [m for (m,) in failed if not m.startswith("bad input: ")]
            res["runs_failed"] = len(failed)
            if raised:
                return {**res, "outcome": "internal", "type": "run raised", "where": raised[0].split(":")[0],
                        "message": raised[0][:300]}
    after = _tree(folder, out)
    moved = sorted(k for k in set(before) | set(after) if before.get(k) != after.get(k))
    moved += [str(p.relative_to(folder)) for p in out.rglob(".*") if p.name.startswith((".staging-", ".publishing-"))
              or p.name.endswith(".tmp")] if out.exists() else []     # what a finished command leaves behind
    if moved:
        res.update(outcome="outside", files=moved[:5])
    return res


def _internal(exc: BaseException, t0: float) -> dict:
    frames = traceback.extract_tb(exc.__traceback__)
    ours = [f for f in frames if "/alightsize" in f.filename]
    loc = ours[-1] if ours else frames[-1]
    where = f"{Path(loc.filename).parent.name}/{Path(loc.filename).name}:{loc.lineno} {loc.name}"
    return {"outcome": "internal", "type": type(exc).__name__, "message": str(exc)[:300], "where": where,
            "traceback": "".join(traceback.format_exception(exc)[-6:])[-2000:], "s": time.perf_counter() - t0}


def _worker(conn) -> None:
    while True:
        job = conn.recv()
        if job is None:
            return
        try:
            conn.send(run_case(job[0], Path(job[1]), job[2]))
        except BaseException as exc:  # noqa: BLE001 - e.g. SystemExit from a reader
            conn.send(_internal(exc, time.perf_counter()))


class Worker:
    """One reader process; restarted after a hang or a crash."""

    def __init__(self):
        self.proc = None
        self.start()

    def start(self) -> None:
        ctx = mp.get_context("fork")
        self.conn, child = ctx.Pipe()
        self.proc = ctx.Process(target=_worker, args=(child,), daemon=True)
        self.proc.start()

    def run(self, kind: str, path: Path, text: str, timeout: float) -> dict:
        self.conn.send((kind, str(path), text))
        try:
            if self.conn.poll(timeout):
                return self.conn.recv()
            outcome = {"outcome": "hang", "s": timeout}
        except EOFError:
            outcome = {"outcome": "internal", "type": "WorkerDied", "message": f"exit code {self.proc.exitcode}",
                       "where": "(process)", "traceback": ""}
        self.proc.kill()
        self.proc.join()
        self.start()
        return outcome

    def stop(self) -> None:
        self.conn.send(None)
        self.proc.join(5)


# ---------------------------------------------------------------------------------------------------- driver


def target(tmp: Path, kind: str, rel: str) -> Path:
    """Where case files of `kind` are written: beside the file they mutate, or in their own case folder."""
    return tmp / "cases" / kind / rel if kind in LANDINGS else (tmp / rel).with_name(Path(rel).stem + ".fuzz.toml")


def case(seed: int, i: int, kinds: list[str], sources: dict[str, dict]) -> tuple[str, str, dict, str, str]:
    """Case `i` of run `seed`: (kind, file, mutated data, key path, mutation); reproducible on its own."""
    rng = random.Random(f"{seed}:{i}")
    kind = rng.choice(kinds)
    rel = rng.choice(files(kind))
    data, key, desc = mutate(sources[rel], rng.choice)
    return kind, rel, data, key, desc


def fuzz(n: int, seed: int, kinds: list[str], timeout: float, progress: bool = True) -> dict:
    import tomllib

    for kind in kinds:      # import the readers before forking, so every (re)started worker starts warm
        try:
            read(kind, ROOT / "missing.toml")
        except Exception:  # noqa: BLE001,S110 - only the imports matter
            pass
    tmp = Path(tempfile.mkdtemp(prefix="alightsize-fuzz-"))
    try:
        for folder in ("examples", "materials"):
            shutil.copytree(ROOT / folder, tmp / folder)
        sources = {rel: tomllib.loads((ROOT / rel).read_text(encoding="utf-8"))
                   for k in kinds if k not in LANDINGS for rel in files(k)}
        if any(k in LANDINGS for k in kinds):
            sources.update(landing_sources())
            run_cli("simulate", tmp / "warm", dumps(sources[LANDINGS["simulate"]]))   # compiled before forking
        worker = Worker()
        baseline = {}
        for kind in kinds:
            for rel in files(kind):
                res = worker.run(kind, target(tmp, kind, rel), dumps(sources[rel]), 120.0)
                if res["outcome"] != ("exit0" if kind in LANDINGS else "ok"):
                    raise SystemExit(f"{rel} unmutated: {res}")
                baseline[rel] = set(res.get("nonfinite", ()))
        counts = {k: Counter() for k in kinds}
        findings, t0 = [], time.perf_counter()
        for i in range(n):
            kind, rel, data, key, desc = case(seed, i, kinds, sources)
            res = worker.run(kind, target(tmp, kind, rel), dumps(data), timeout)
            if res["outcome"] == "ok" and set(res["nonfinite"]) - baseline[rel]:
                res = {**res, "outcome": "nonfinite", "values": sorted(set(res["nonfinite"]) - baseline[rel])[:5]}
            counts[kind][res["outcome"]] += 1
            counts[kind]["cases"] += 1
            if kind in LANDINGS:       # how many errors name the mutated file; how many sweep runs failed on input
                counts[kind]["exit2 naming the case file"] += str(res.get("error_file", "")).endswith(rel)
                counts[kind]["runs failed on input"] += res.get("runs_failed", 0)
            if res["outcome"] not in PASSING:
                res.pop("nonfinite", None)
                findings.append({"case": i, "kind": kind, "file": rel, "key": key, "mutation": desc, **res})
            if progress and (i + 1) % (25 if kinds[0] in LANDINGS else 500) == 0:
                print(f"  {i + 1} cases, {time.perf_counter() - t0:.0f} s", file=sys.stderr)
        worker.stop()
        return {"seed": seed, "n": n, "wall_s": time.perf_counter() - t0,
                "counts": {k: dict(c) for k, c in counts.items()}, "findings": findings, "bugs": bugs(findings)}
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def bugs(findings: list[dict]) -> list[dict]:
    """Distinct bugs: internal errors by (type, innermost alightsize frame); the others by (outcome, kind, key
    path without indices); each with its first case and count."""
    out: dict[tuple, dict] = {}
    for f in findings:
        if f["outcome"] == "internal":
            sig = ("internal", f["type"], f["where"])
        else:
            sig = (f["outcome"], f["kind"], re.sub(r"\[[^\]]*\]", "[]", f["key"]))
        if sig in out:
            out[sig]["count"] += 1
        else:
            out[sig] = {"signature": " | ".join(sig), "count": 1, "first": f}
    return sorted(out.values(), key=lambda b: (b["signature"]))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-n", type=int, default=10000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--kind", action="append", choices=sorted(KINDS), help="a file kind (repeatable; default all)")
    ap.add_argument("--landings", action="store_true", help="run the command line end to end on a mutated landing "
                    "scene or study (kinds simulate and sweep) instead of the readers")
    ap.add_argument("--timeout", type=float,
                    help="seconds after which a case counts as a hang (5; 120 with --landings)")
    ap.add_argument("--json", type=Path)
    ap.add_argument("--show", type=int, metavar="CASE", help="print case CASE's mutated file and stop")
    args = ap.parse_args()
    kinds = list(LANDINGS) if args.landings else args.kind or list(KINDS)
    timeout = args.timeout or (120.0 if args.landings else 5.0)
    columns = LANDING_OUTCOMES if args.landings else OUTCOMES
    if args.show is not None:
        import tomllib
        sources = landing_sources() if args.landings else \
            {rel: tomllib.loads((ROOT / rel).read_text(encoding="utf-8")) for k in kinds for rel in files(k)}
        kind, rel, data, key, desc = case(args.seed, args.show, kinds, sources)
        print(f"# {kind} {rel}: {key}: {desc}\n{dumps(data)}")
        return
    out = fuzz(args.n, args.seed, kinds, timeout)
    print(f"{out['n']} cases, seed {out['seed']}, {out['wall_s']:.0f} s")
    print(f"{'kind':10}{'cases':>7}" + "".join(f"{o:>13}" for o in columns))
    for kind, c in out["counts"].items():
        print(f"{kind:10}{c.get('cases', 0):7d}" + "".join(f"{c.get(o, 0):13d}" for o in columns))
    for kind, c in out["counts"].items() if args.landings else ():
        print(f"{kind}: {c.get('exit2 naming the case file', 0)} of {c.get('exit2', 0) + c.get('keyless', 0)} exit-2 "
              f"errors name the mutated file; {c.get('runs failed on input', 0)} sweep runs stored failed on bad input")
    print(f"\n{len(out['bugs'])} distinct findings:")
    for b in out["bugs"]:
        f = b["first"]
        print(f"- {b['signature']} (x{b['count']}; case {f['case']}: {f['file']}: {f['key']}: {f['mutation']})")
        if f.get("message"):
            print(f"    {f['message'][:200]}")
        if f.get("values"):
            print(f"    non-finite: {', '.join(f['values'])}")
    if args.json:
        args.json.write_text(json.dumps(out, indent=1, default=str), encoding="utf-8")


if __name__ == "__main__":
    main()
