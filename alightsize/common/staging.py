"""A command's outputs appear together: it writes them into a hidden staging folder inside its output folder
and moves them in only once it has written them all; a command that stops short leaves the old outputs as
they were. Run stores (`runs.sqlite`, `history/`, `landings/`) are not staged: they are written in place, each
landing in its own transaction, so that a stopped sweep resumes."""

from __future__ import annotations

import os
import shutil
from dataclasses import dataclass
from pathlib import Path

STAGING = ".staging-"            # + pid: a command writing its outputs
PUBLISHING = ".publishing-"      # + pid: a command done writing, its outputs being moved in


@dataclass(frozen=True)
class Stage:
    """Where a command writes its outputs (`path`) until they are moved into the output folder (`root`)."""
    root: Path
    path: Path

    def final(self, staged: Path) -> Path:
        """The path a staged file has once published."""
        return self.root / Path(staged).relative_to(self.path)

    def publish(self) -> None:
        """Move every staged file into the output folder: one rename marks the set complete, then each file
        replaces its old version (os.replace) at its path, subfolders included; then the stage is gone. Until
        the first rename the old outputs stand whole; a process killed while moving leaves the rest for the
        next command on the folder to move in (settle)."""
        if not self.path.exists():                    # nothing written
            return
        ready = self.root / f"{PUBLISHING}{os.getpid()}"
        os.replace(self.path, ready)
        _move_in(ready, self.root)

    def discard(self) -> None:
        """Remove the stage and whatever was written into it (nothing when published)."""
        shutil.rmtree(self.path, ignore_errors=True)


def open_stage(root: Path) -> Stage:
    """This process's staging folder in `root`, made by the first file written into it."""
    path = root / f"{STAGING}{os.getpid()}"
    shutil.rmtree(path, ignore_errors=True)
    return Stage(root, path)


def settle(root: Path) -> None:
    """What an interrupted command left in `root`: its staging folder is removed (its outputs were not all
    written), a publication it had begun is finished (they were)."""
    for ready in sorted(root.glob(f"{PUBLISHING}*")):
        try:
            _move_in(ready, root)
        except OSError:                    # a file's place taken by a folder since: the old outputs stand
            shutil.rmtree(ready, ignore_errors=True)
    for stage in root.glob(f"{STAGING}*"):
        shutil.rmtree(stage, ignore_errors=True)


def _move_in(ready: Path, root: Path) -> None:
    for src in sorted(p for p in ready.rglob("*") if not p.is_dir()):
        dst = root / src.relative_to(ready)
        dst.parent.mkdir(parents=True, exist_ok=True)
        os.replace(src, dst)
    shutil.rmtree(ready)
