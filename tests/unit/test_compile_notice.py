"""The one line a first run prints while numba compiles, and nothing once compiled."""

import io
import os
import subprocess
import sys
import time

import pytest
from numba import njit

from alightsize.common.compile_notice import compile_notice
from alightsize_sim.cache import STALE


def test_a_compilation_is_announced_once_and_timed():
    @njit
    def twice(x):
        return 2.0 * x

    out = io.StringIO()
    with compile_notice(out) as notice:
        assert twice(1.5) == 3.0
        assert twice(2.5) == 5.0                     # same signature: compiled once
    lines = out.getvalue().splitlines()
    assert len(lines) == 2 and lines[0].startswith("alightsize: compiling") and "compiled in" in lines[1]
    assert notice.seconds > 0.0
    quiet = io.StringIO()
    with compile_notice(quiet):
        assert twice(4.0) == 8.0                     # already compiled: no compilation event
    assert quiet.getvalue() == ""


KERNEL = '''from numba import njit

from alightsize_sim.cache import register

register(__file__)


@njit(cache=True)
def twice(x):
    return {factor} * x
'''

RUN = ("import sys; sys.path.insert(0, sys.argv[1]); from alightsize.common.compile_notice import compile_notice\n"
       "with compile_notice():\n"
       "    import kernel; print(kernel.twice(1.5))")


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="platformdirs follows XDG_CACHE_HOME on Linux only")
def test_a_cached_kernel_is_announced_on_its_first_run_only_and_cached_outside_the_package(tmp_path):
    """A registered module's kernel compiles once (the notice) and loads silently from the user cache folder
    after; nothing lands beside the module; new sources compile again into a folder of their own, beside the
    earlier sources' (a run of those may still be compiling into it), which goes once idle for STALE."""
    src, cache = tmp_path / "src", tmp_path / "cache"
    src.mkdir()
    env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    env.update(XDG_CACHE_HOME=str(cache), PYTHONDONTWRITEBYTECODE="1")

    def run():
        out = subprocess.run([sys.executable, "-c", RUN, str(src)], env=env, capture_output=True, text=True, check=True)
        return out.stdout.strip(), out.stderr

    (src / "kernel.py").write_text(KERNEL.format(factor="2.0"))
    first, second = run(), run()
    assert first[0] == second[0] == "3.0"
    assert "compiling" in first[1] and second[1] == ""           # the second run loads the first's machine code
    assert [p.name for p in src.iterdir()] == ["kernel.py"]
    digests = list((cache / "alightsize").glob("numba-*/src-*/*"))
    assert len(digests) == 1 and any(digests[0].glob("kernel.twice-*.nbi"))
    (src / "kernel.py").write_text(KERNEL.format(factor="3.0"))
    third = run()
    assert third[0] == "4.5" and "compiling" in third[1]
    now = list((cache / "alightsize").glob("numba-*/src-*/*"))
    assert len(now) == 2 and digests[0] in now                   # the earlier sources' cache kept: recently written
    (src / "kernel.py").write_text(KERNEL.format(factor="4.0"))
    idle = time.time() - STALE - 60.0
    for p in [digests[0], *digests[0].rglob("*")]:
        os.utime(p, (idle, idle))
    assert run()[0] == "6.0"
    last = list((cache / "alightsize").glob("numba-*/src-*/*"))
    assert len(last) == 2 and digests[0] not in last             # idle for STALE: removed; the 3.0 one kept


def test_a_user_numba_cache_dir_wins(tmp_path):
    """With NUMBA_CACHE_DIR set, numba caches there as it documents, and the user cache folder is not used."""
    src, numba_dir, cache = tmp_path / "src", tmp_path / "numba", tmp_path / "cache"
    src.mkdir()
    (src / "kernel.py").write_text(KERNEL.format(factor="2.0"))
    env = {**os.environ, "NUMBA_CACHE_DIR": str(numba_dir), "XDG_CACHE_HOME": str(cache),
           "PYTHONDONTWRITEBYTECODE": "1"}
    subprocess.run([sys.executable, "-c", RUN, str(src)], env=env, capture_output=True, check=True)
    assert any(numba_dir.rglob("kernel.twice-*.nbi")) and not cache.exists()


def test_the_notice_names_the_simulator_variant_it_compiles(monkeypatch):
    """A compilation of the simulator is announced with the variant of the landing being set up (leg kinds and
    footpad model, alightsize_sim.landing.variant), once per variant, with its time as soon as it ends."""
    import dataclasses
    from types import SimpleNamespace
    from numba.core import event
    import alightsize_sim.landing as landing
    from alightsize.common.compile_notice import _Notice
    from alightsize.model.scene_config import read_scene
    from conftest import EXAMPLES
    scene = read_scene(EXAMPLES / "scenes" / "telescoping_config2.toml").scene
    assert landing.variant(scene) == "telescoping legs, footpads that hold"
    sliding = dataclasses.replace(scene, mu_static=0.5, mu_dynamic=0.4)
    assert landing.variant(sliding) == "telescoping legs, sliding footpads"
    assert landing.variant(dataclasses.replace(scene, footpad_mass=5.0)) == "telescoping legs, footpads with mass"
    kernel = SimpleNamespace(py_func=SimpleNamespace(__module__="alightsize_sim.landing_kernel"))
    out = io.StringIO()
    notice = _Notice(out)
    monkeypatch.setattr(landing, "compiling_for", "telescoping legs, sliding footpads")
    for _ in range(2):                                   # the second compilation of the same variant: silent
        notice.on_start(event.Event("numba:compile", event.EventStatus.START, {"dispatcher": kernel}))
        notice.on_end(event.Event("numba:compile", event.EventStatus.END, {"dispatcher": kernel}))
    lines = out.getvalue().splitlines()
    assert lines[0] == ("alightsize: compiling the landing simulator for telescoping legs, sliding footpads "
                        "(once per machine; cached after)...")
    assert len(lines) == 2 and lines[1].startswith("alightsize: compiled in ")
