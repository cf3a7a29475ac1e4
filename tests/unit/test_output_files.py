"""Output files: written whole (temp file, then rename) with the permissions a new file gets under the
user's umask (0666 & ~umask), so a report on a shared drive is as readable as any other file there; a
command's files appear together or not at all."""

import json
import os
import stat
from pathlib import Path

import pytest

from alightsize.common.atomic import write_atomic
from alightsize.cli import main
from conftest import EXAMPLES


@pytest.fixture(params=[0o022, 0o027])
def umask(request):
    old = os.umask(request.param)
    yield request.param
    os.umask(old)


def _mode(path) -> int:
    return stat.S_IMODE(os.stat(path).st_mode)


def test_atomic_write_respects_the_umask(tmp_path, umask):
    plain = tmp_path / "plain.txt"
    plain.write_text("x")                              # what open() gives any new file here
    for data in ("text", b"bytes", lambda p: p.write_text("via a writer")):
        out = write_atomic(tmp_path / "a" / "file.txt", data)
        assert _mode(out) == _mode(plain) == 0o666 & ~umask
    assert not list(tmp_path.glob("a/.*.tmp"))


def test_every_design_output_is_readable_as_the_umask_allows(tmp_path, umask):
    out = tmp_path / "design"
    assert main(["design", str(EXAMPLES / "telescoping.toml"), "--out", str(out)]) == 0
    files = [p for p in out.rglob("*") if p.is_file()]
    assert len(files) >= 6                             # summary.json, report.html/.md, design.xlsx, two charts
    assert {p.name: _mode(p) for p in files} == {p.name: 0o666 & ~umask for p in files}


# A command's outputs appear together (docs/contracts.md): staged in --out/.staging-PID/, moved in on exit 0 or 1.
DESIGN_FILES = {"summary.json", "report.html", "report.md", "design.xlsx", "design_factors.png", "weights.png"}
LOADS_FILES = {"max_member_loads.json", "max_member_loads.xlsx", "loads.md", "loads.html"}   # docs/contracts.md


def _snapshot(folder) -> dict[str, bytes]:
    """Every file under `folder`, hidden ones included, by relative path, with its bytes."""
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


@pytest.mark.parametrize("stop, code", [(RuntimeError("disk gone"), 3), (KeyboardInterrupt(), 130)])
def test_a_design_stopped_while_writing_leaves_the_old_outputs_whole(tmp_path, monkeypatch, stop, code):
    """The App IV telescoping design (no landings) written, then a different design (articulated 68, other
    bytes in every file) stopped after three of its files: the folder holds exactly the first design's files."""
    from alightsize.reports import design_report
    out = tmp_path / "d"
    assert main(["design", str(EXAMPLES / "telescoping.toml"), "--out", str(out)]) == 0
    before = _snapshot(out)
    assert set(before) == DESIGN_FILES
    written = []

    def dying(path, data):
        if len(written) == 3:
            raise stop
        written.append(write_atomic(path, data))
        return written[-1]
    monkeypatch.setattr(design_report, "write_atomic", dying)
    assert main(["design", str(EXAMPLES / "articulated_68.toml"), "--out", str(out)]) == code
    assert len(written) == 3 and all(p.parent.name.startswith(".staging-") for p in written)
    assert _snapshot(out) == before                    # byte for byte, and no staged file left behind


def test_the_next_command_settles_what_a_killed_one_left(tmp_path):
    """A staging folder (killed while writing) is removed; a publication begun (killed while moving in) is
    finished; then the command's own outputs are moved in."""
    out = tmp_path / "l"
    (out / ".staging-4242" / "chosen").mkdir(parents=True)
    (out / ".staging-4242" / "max_member_loads.json").write_text("half a new set")
    (out / ".staging-4242" / "chosen" / "summary.json").write_text("{}")
    (out / ".publishing-4343" / "sub").mkdir(parents=True)
    (out / ".publishing-4343" / "sub" / "note.txt").write_text("a whole set, half moved in")
    assert main(["loads", str(EXAMPLES / "loads" / "telescoping.toml"), "--out", str(out)]) == 0
    assert sorted(p.name for p in out.iterdir()) == sorted(LOADS_FILES | {"sub"})
    assert (out / "sub" / "note.txt").read_text() == "a whole set, half moved in"
    assert json.loads((out / "max_member_loads.json").read_text())["schema"].startswith("alightsize.loads/")


@pytest.mark.parametrize("command, path, code, names", [
    ("design", EXAMPLES / "telescoping.toml", 0, DESIGN_FILES),
    ("design", EXAMPLES / "articulated_68.toml", 1, DESIGN_FILES),           # a failed check publishes too
    ("loads", EXAMPLES / "loads" / "telescoping.toml", 0, LOADS_FILES)])
def test_a_finished_command_publishes_its_files_and_nothing_else(tmp_path, command, path, code, names, capsys):
    """The files docs/contracts.md lists, at their published paths, with no staging folder left."""
    out = tmp_path / "o"
    assert main([command, str(path), "--out", str(out)]) == code
    assert {p.name for p in out.iterdir()} == names
    wrote = capsys.readouterr().out.split("wrote ")[-1].strip().split(", ")
    assert {Path(w) for w in wrote} == {out / n for n in names}


def test_bad_input_publishes_nothing_and_leaves_the_old_outputs(tmp_path):
    out = tmp_path / "o"
    assert main(["loads", str(EXAMPLES / "loads" / "telescoping.toml"), "--out", str(out)]) == 0
    before = _snapshot(out)
    bad = tmp_path / "bad.toml"
    bad.write_text((EXAMPLES / "loads" / "telescoping.toml").read_text() + "\n[nonsense]\nx = 1\n")
    assert main(["loads", str(bad), "--out", str(out)]) == 2
    assert _snapshot(out) == before
