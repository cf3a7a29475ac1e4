"""Packaging: the simulator ships under the project's own name and imports nothing of the toolkit; the
documents the README and docs name are in the repository."""

import re
import subprocess
import sys
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


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
