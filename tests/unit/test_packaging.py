"""Packaging: the simulator ships under the project's own name and imports nothing of the toolkit; the
documents the README and docs name are in the repository; the sources are ruff-clean and the packages a verdict
is computed in pass mypy."""

import ast
import importlib.util
import os
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest
from conftest import ROOT



def test_the_simulator_imports_nothing_of_the_toolkit():
    code = ("import sys, alightsize_sim.landing, alightsize_sim.articulated_statics; "
            "print(sorted({m.split('.')[0] for m in sys.modules if m.startswith(('alightsize', 'sim'))}))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "['alightsize_sim']"


def test_no_top_level_package_borrows_a_common_name():
    wheel = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["hatch"]["build"]["targets"]["wheel"]
    assert all(p.startswith("alightsize") for p in wheel["packages"])
    assert not (ROOT / "sim").exists()


def test_the_license_pyproject_states_is_in_the_repository():
    meta = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    assert meta["license"]["text"] == "MIT" and "MIT License" in (ROOT / "LICENSE").read_text()


def test_every_document_the_readme_and_docs_name_exists():
    """Markdown links, and `NAME.md` / `docs/...md` names (output files such as `report.md` aside), in
    README.md and docs/ point at files of the repository."""
    missing = []
    for doc in [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]:
        text = doc.read_text()
        for target in re.findall(r"\]\(([^)#]+\.md)\)", text):
            if not (doc.parent / target).exists():
                missing.append(f"{doc.name}: {target}")
        for name in re.findall(r"`((?:docs/[\w/.-]+|[A-Z][A-Z_-]+)\.md)`", text):
            if not any((base / name).exists() for base in (doc.parent, ROOT, ROOT / "docs")):
                missing.append(f"{doc.name}: {name}")
    assert not missing, missing


def test_ci_runs_the_readme_test_command_verbatim():
    """The README opens with two commands; .ci/run's last line is the second, character for character."""
    commands = [line for line in (ROOT / "README.md").read_text().split("```sh\n", 1)[1].split("```")[0].splitlines()
                if line.strip()]
    assert len(commands) == 2
    assert (ROOT / ".ci" / "run").read_text().strip().splitlines()[-1] == commands[1]


def _files(*folders: Path) -> dict[str, int]:
    """Every file and folder in the folders with its modification time (ns): a folder's changes when an entry is
    made or removed in it."""
    return {str(p): p.stat().st_mtime_ns for folder in folders for p in [folder, *folder.rglob("*")]}


def test_importing_the_packages_writes_no_file(tmp_path):
    """`import alightsize, alightsize_sim` in a fresh process leaves the package folders and the numba cache
    folders as they were: no compiled-code cache, no folder made and removed. NUMBA_CACHE_DIR (set, then unset) and
    the user cache folder point at empty scratch folders, which stay empty; Python's own bytecode cache is off."""
    packages = [Path(importlib.util.find_spec(name).origin).parent for name in ("alightsize", "alightsize_sim")]
    numba_dir, user_cache = tmp_path / "numba", tmp_path / "xdg"
    numba_dir.mkdir()
    user_cache.mkdir()
    for numba_env in ({"NUMBA_CACHE_DIR": str(numba_dir)}, {}):
        env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
        env.update(numba_env, XDG_CACHE_HOME=str(user_cache), PYTHONDONTWRITEBYTECODE="1")
        before = _files(*packages)
        subprocess.run([sys.executable, "-c", "import alightsize, alightsize_sim"], env=env, check=True)
        assert _files(*packages) == before
        assert not any(numba_dir.iterdir()) and not any(user_cache.iterdir()), numba_env


def test_no_module_imports_pyplot():
    """Every module of both packages (but `python -m alightsize`) imported in one process: matplotlib.pyplot (a
    global figure state and a backend switch) is never loaded, and the backend a user chose is left alone."""
    code = ("import importlib, pkgutil, sys, matplotlib; matplotlib.use('svg')\n"
            "import alightsize, alightsize_sim\n"
            "for pkg in (alightsize, alightsize_sim):\n"
            "    for m in pkgutil.walk_packages(pkg.__path__, pkg.__name__ + '.'):\n"
            "        if not m.name.endswith('__main__'):\n"
            "            importlib.import_module(m.name)\n"
            "print(len(sys.modules), 'matplotlib.pyplot' in sys.modules, matplotlib.get_backend())")
    count, pyplot, backend = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                                            check=True).stdout.split()
    assert int(count) > 100 and pyplot == "False" and backend == "svg"


def test_the_packages_ship_type_information():
    """PEP 561 markers: both packages declare their type hints (the wheel takes every file of the packages)."""
    wheel = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["hatch"]["build"]["targets"]["wheel"]
    assert all((ROOT / p / "py.typed").is_file() for p in wheel["packages"])


def test_the_sources_are_ruff_clean():
    """pyproject.toml's ruff rules (pyflakes, pycodestyle, 120 columns) find nothing in the packages, tests and
    benchmarks."""
    run = subprocess.run([sys.executable, "-m", "ruff", "check", "--no-cache", "alightsize", "alightsize_sim", "tests",
                          "benchmarks"], cwd=ROOT, capture_output=True, text=True)
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]


MAX_POSITIONAL = 8


def test_no_function_takes_more_than_eight_positional_parameters():
    """Every function and lambda of both packages takes at most MAX_POSITIONAL positional parameters (the project's
    code standard); values that travel together go as one named group (a tuple such as the capsule's motion
    (r, R, v, w), or a bundle: alightsize_sim/bundle.py), with no exception."""
    wide = {}
    for package in ("alightsize", "alightsize_sim"):
        for path in sorted((ROOT / package).rglob("*.py")):
            for node in ast.walk(ast.parse(path.read_text(), str(path))):
                if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
                    n = len(node.args.posonlyargs) + len(node.args.args)
                    name = getattr(node, "name", "<lambda>")
                    if n > MAX_POSITIONAL:
                        wide[f"{path.relative_to(ROOT).as_posix()}:{node.lineno} {name}"] = n
    assert not wide, wide


TYPED_PACKAGES = ("alightsize/checks", "alightsize/weights", "alightsize/model", "alightsize/loads",
                  "alightsize/pipeline")


def test_the_typed_packages_pass_mypy(tmp_path):
    """pyproject.toml's mypy settings find no error in the packages held to their type hints (those a
    verdict is computed in: checks, weights, model, loads, pipeline). The modules they import are read for their
    types but their own errors are not counted here (`--follow-imports=silent`): how mypy resolves them differs
    between an editable and a regular install."""
    if importlib.util.find_spec("mypy") is None:
        pytest.skip("mypy is not installed (the test extra installs it)")
    run = subprocess.run([sys.executable, "-m", "mypy", "--cache-dir", str(tmp_path / "mypy_cache"),
                          "--follow-imports=silent", *TYPED_PACKAGES],
                         cwd=ROOT, capture_output=True, text=True)
    assert run.returncode == 0 and "Success: no issues found" in run.stdout, run.stdout[-3000:] + run.stderr[-3000:]
