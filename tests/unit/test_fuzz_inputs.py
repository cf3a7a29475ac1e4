"""Property: an input reader given one mutation of a shipped input file (benchmarks/fuzz_inputs.py: type, sign,
magnitude, unit, nesting, names, deletion, misspelling) returns a result without a NaN or infinity its
unmutated file lacks, or raises an InputError naming a key (or the file, for a file-level error); never
another exception (the CLI's exit 3, a bug)."""

import importlib.util
import shutil
import tomllib
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from conftest import ROOT

_spec = importlib.util.spec_from_file_location("fuzz_inputs", ROOT / "benchmarks" / "fuzz_inputs.py")
fuzz = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(fuzz)

EXAMPLES_PER_KIND = 300      # 7 kinds: about 2,100 mutated reads, 20 s serially (the benchmark runs 10,000+)


class Tree(dict):
    def __repr__(self) -> str:           # a failing example prints the case, not the parsed sources
        return f"Tree({self['root']})"


@pytest.fixture(scope="module")
def tree(tmp_path_factory) -> Tree:
    """A copy of examples/ and materials/ (mutants are written beside the files whose relative paths they
    name), the parsed sources and each file's unmutated non-finite values (inf design factors of unloaded
    checks are by design)."""
    root = tmp_path_factory.mktemp("fuzz")
    for folder in ("examples", "materials"):
        shutil.copytree(ROOT / folder, root / folder)
    sources = {rel: tomllib.loads((ROOT / rel).read_text(encoding="utf-8"))
               for k in fuzz.KINDS for rel in fuzz.files(k)}
    return Tree(root=root, sources=sources, baseline={})


def _target(tree: Tree, rel: str) -> Path:
    return (tree["root"] / rel).with_name(Path(rel).stem + ".fuzz.toml")


@pytest.mark.parametrize("kind", sorted(fuzz.KINDS))
@settings(max_examples=EXAMPLES_PER_KIND, suppress_health_check=[HealthCheck.function_scoped_fixture,
                                                                 HealthCheck.too_slow, HealthCheck.data_too_large])
@given(data=st.data())
def test_reader_refuses_bad_input_by_key(kind, tree, data):
    rel = data.draw(st.sampled_from(fuzz.files(kind)), label="file")
    if rel not in tree["baseline"]:
        clean = fuzz.run_case(kind, _target(tree, rel), fuzz.dumps(tree["sources"][rel]))
        assert clean["outcome"] == "ok", clean
        tree["baseline"][rel] = set(clean["nonfinite"])
    mutated, key, desc = fuzz.mutate(tree["sources"][rel], lambda options: data.draw(st.sampled_from(options)))
    res = fuzz.run_case(kind, _target(tree, rel), fuzz.dumps(mutated))
    assert res["outcome"] in ("ok", "input_error"), (rel, key, desc, res)
    if res["outcome"] == "ok":
        assert not set(res["nonfinite"]) - tree["baseline"][rel], (rel, key, desc, res["nonfinite"])


# End to end: the command line on one mutation of a short landing scene or of a study of 2 runs on it.
E2E_EXAMPLES = 15          # per command; most stop at exit 2, a few land (10 ms) and draw their plots (2-3 s)


@pytest.fixture(scope="module")
def case_folder(tmp_path_factory) -> Path:
    return tmp_path_factory.mktemp("e2e") / "case"


@pytest.mark.parametrize("kind", sorted(fuzz.LANDINGS))
@settings(max_examples=E2E_EXAMPLES, suppress_health_check=[HealthCheck.function_scoped_fixture,
                                                            HealthCheck.too_slow, HealthCheck.data_too_large])
@given(data=st.data())
def test_the_command_line_on_a_mutated_landing_exits_0_1_or_2_and_writes_only_into_out(kind, case_folder, data):
    """`alightsize simulate` / `sweep --serial` exits 0 or 1 with finite JSON outputs, every run that fails
    failing on bad input, nothing made or changed beside --out and no staging left in it; or exits 2 naming
    a key (or the file, for a file-level error). Never exit 3."""
    rel = fuzz.LANDINGS[kind]
    mutated, key, desc = fuzz.mutate(fuzz.landing_sources()[rel], lambda options: data.draw(st.sampled_from(options)))
    res = fuzz.run_cli(kind, case_folder, fuzz.dumps(mutated))
    assert res["outcome"] in ("exit0", "exit1", "exit2"), (key, desc, res)
