"""Output files: written whole (temp file, then rename) with the permissions a new file gets under the
user's umask (0666 & ~umask), so a report on a shared drive is as readable as any other file there."""

import os
import stat

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
