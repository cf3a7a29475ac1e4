"""One command per output folder: an exclusive lock on the folder itself while a command writes into it, and the
staging folder its outputs are written into (alightsize.common.staging)."""

from __future__ import annotations

import fcntl
import os
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from alightsize.common.errors import InputError
from alightsize.common.staging import Stage, open_stage, settle


@contextmanager
def output_folder(path: Path) -> Iterator[Stage]:
    """Hold `path` (made if missing) for this process while the command runs and yield the stage its outputs
    are written into (published by the command when it has written them all, else removed on leaving): a
    second command on the same folder is refused at once (flock on the folder, released when the process ends,
    even by kill -9); what an interrupted command left is settled first (its temp files `.NAME.*.tmp`,
    alightsize.common.atomic, removed; its staging folder removed or its publication finished,
    alightsize.common.staging). A folder made here and left empty (the command refused its input) is removed
    again."""
    made = not path.exists()
    path.mkdir(parents=True, exist_ok=True)
    fd = os.open(path, os.O_RDONLY)
    try:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            raise InputError("(command line)", "--out", "an output folder no other alightsize command is writing",
                             f"{str(path)!r}, in use by another alightsize process") from None
        for leftover in path.rglob(".*.tmp"):
            leftover.unlink(missing_ok=True)
        settle(path)
        stage = open_stage(path)
        try:
            yield stage
        finally:
            stage.discard()
    finally:
        os.close(fd)
        if made and not any(path.iterdir()):
            path.rmdir()
