"""One command per output folder: an exclusive lock on the folder itself while a command writes into it."""

from __future__ import annotations

import fcntl
import os
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from alightsize.common.errors import InputError


@contextmanager
def output_folder(path: Path) -> Iterator[Path]:
    """Hold `path` (made if missing) for this process while the command runs: a second command on the same
    folder is refused at once (flock on the folder, released when the process ends, even by kill -9); the
    temp files an interrupted write left (`.NAME.*.tmp`, alightsize.common.atomic) are removed first. A folder
    made here and left empty (the command refused its input) is removed again."""
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
        yield path
    finally:
        os.close(fd)
        if made and not any(path.iterdir()):
            path.rmdir()
