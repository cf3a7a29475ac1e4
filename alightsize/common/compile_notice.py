"""A line on stderr when numba starts compiling something new (the simulator's variant for a scene, on a fresh
install's first run), and its time as soon as it is compiled.

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


def _what(ev: event.Event) -> str:
    """What a top-level compilation is for: the landing simulator's variant (alightsize_sim.landing.variant of the
    landing being set up), or the compiled function's module."""
    module = getattr(getattr(ev.data.get("dispatcher"), "py_func", None), "__module__", "") or ""
    if module.startswith("alightsize_sim"):
        variant = getattr(sys.modules.get("alightsize_sim.landing"), "compiling_for", "")
        return f"the landing simulator for {variant}" if variant else "the landing simulator"
    return module.rsplit(".", 1)[-1].replace("_", " ") or "a compiled function"


class _Notice(event.Listener):
    """Announces each new thing compiled (the first top-level compilation for it) and its time once done; counts
    the seconds spent compiling."""

    def __init__(self, stream: TextIO):
        self.stream, self.depth, self.started, self.seconds = stream, 0, None, 0.0
        self.pid, self.announced, self.current = os.getpid(), set(), None

    def on_start(self, ev: event.Event) -> None:
        if os.getpid() != self.pid:
            return
        if self.depth == 0:
            what = _what(ev)
            self.current = what if what not in self.announced else None
            if self.current:
                self.announced.add(what)
                print(f"alightsize: compiling {what} (once per machine; cached after)...", file=self.stream,
                      flush=True)
            self.started = time.perf_counter()
        self.depth += 1

    def on_end(self, ev: event.Event) -> None:
        if os.getpid() != self.pid:
            return
        self.depth -= 1
        if self.depth == 0:
            took = time.perf_counter() - self.started
            self.seconds += took
            if self.current:
                print(f"alightsize: compiled in {took:.0f} s", file=self.stream, flush=True)


@contextmanager
def compile_notice(stream: TextIO = sys.stderr):
    """Within the block, announce numba's first compilation on `stream` and report its total time at the end."""
    notice = _Notice(stream)
    event.register("numba:compile", notice)
    try:
        yield notice
    finally:
        event.unregister("numba:compile", notice)
