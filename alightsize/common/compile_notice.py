"""One line on stderr while numba compiles the simulator (a fresh install's first run), and its time after.

Compiled kernels are cached on disk (numba `cache=True`); numba reports a compilation only on a cache miss, so
later runs print nothing. Worker processes forked from the announcing one stay silent.
"""

from __future__ import annotations

import os
import sys
import time
from contextlib import contextmanager
from typing import TextIO

from numba.core import event


class _Notice(event.Listener):
    """Prints when the first top-level compilation starts; counts the seconds spent compiling."""

    def __init__(self, stream: TextIO):
        self.stream, self.depth, self.started, self.seconds = stream, 0, None, 0.0
        self.pid = os.getpid()

    def on_start(self, ev: event.Event) -> None:
        if os.getpid() != self.pid:
            return
        if self.depth == 0:
            if self.started is None:
                print("alightsize: compiling the landing simulator for this machine (first run only; cached after)...",
                      file=self.stream, flush=True)
            self.started = time.perf_counter()
        self.depth += 1

    def on_end(self, ev: event.Event) -> None:
        if os.getpid() != self.pid:
            return
        self.depth -= 1
        if self.depth == 0:
            self.seconds += time.perf_counter() - self.started


@contextmanager
def compile_notice(stream: TextIO = sys.stderr):
    """Within the block, announce numba's first compilation on `stream` and report its total time at the end."""
    notice = _Notice(stream)
    event.register("numba:compile", notice)
    try:
        yield notice
    finally:
        event.unregister("numba:compile", notice)
        if notice.started is not None:
            print(f"alightsize: compiled in {notice.seconds:.0f} s", file=stream, flush=True)
