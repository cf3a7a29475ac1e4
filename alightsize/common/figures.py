"""What figures share: user text drawn as written."""

from __future__ import annotations


def literal(text: str) -> str:
    """User text (an item, a title, a parameter) as matplotlib draws it literally: each `$` escaped, so no name is
    read as mathtext (an unbalanced `$\\foo{$` would raise while drawing). matplotlib shows `\\$` as `$`."""
    return str(text).replace("$", r"\$")
