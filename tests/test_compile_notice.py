"""The one line a first run prints while numba compiles, and nothing once compiled."""

import io

from numba import njit

from alightsize.common.compile_notice import compile_notice


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
