"""The toolkit's folders read as the pipeline and import each other in one direction: no module imports
itself back through others, and no folder does (imports under `if TYPE_CHECKING:` are annotations only)."""

from __future__ import annotations

import ast
from graphlib import CycleError, TopologicalSorter

import pytest

from conftest import ROOT

PACKAGE = ROOT / "alightsize"
PIPELINE = ["common", "model", "landings", "loads", "checks", "weights", "pipeline", "reports"]


def _module(path) -> str:
    parts = path.relative_to(ROOT).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _imports(path) -> set[str]:
    """Modules of alightsize that `path` imports anywhere (top level or inside functions)."""
    tree, here = ast.parse(path.read_text()), _module(path)
    skip = {id(n) for node in ast.walk(tree) if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test)
            for n in ast.walk(node)}
    out = set()
    for node in ast.walk(tree):
        if id(node) in skip:
            continue
        if isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                pkg = here.split(".")[: len(here.split(".")) - node.level + (path.name == "__init__.py")]
                base = ".".join(pkg + ([node.module] if node.module else []))
            for alias in node.names:
                out.add(f"{base}.{alias.name}" if (PACKAGE / (f"{base}.{alias.name}".replace(".", "/")[11:] + ".py"))
                        .exists() else base)
        elif isinstance(node, ast.Import):
            out |= {a.name for a in node.names}
    return {m for m in out if m.startswith("alightsize.") and m != here}


def _graph() -> dict[str, set[str]]:
    return {_module(p): _imports(p) for p in PACKAGE.rglob("*.py")}


def test_no_module_imports_itself_back():
    graph = _graph()
    try:
        tuple(TopologicalSorter(graph).static_order())
    except CycleError as exc:
        pytest.fail(f"import circle: {' -> '.join(exc.args[1])}")


def test_folders_import_only_folders_before_them_in_the_pipeline():
    """common -> model -> landings -> loads -> checks -> weights -> pipeline -> reports -> cli."""
    rank = {name: k for k, name in enumerate(PIPELINE)}
    for module, deps in _graph().items():
        folder = module.split(".")[1] if module.count(".") >= 2 else None
        if folder not in rank:
            continue
        for dep in deps:
            target = dep.split(".")[1] if dep.count(".") >= 1 else None
            if target in rank:
                assert rank[target] <= rank[folder], f"{module} imports {dep}: {target} comes after {folder}"
