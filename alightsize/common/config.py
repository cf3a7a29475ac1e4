"""Reading TOML configs: tables by key path, unknown keys rejected (values are typed in alightsize.common.typed)."""

from __future__ import annotations

import difflib
import json
import re
import tomllib
from pathlib import Path
from typing import Any, Literal, overload

from alightsize.common.errors import InputError, warn_input

_MISSING = object()
SEED_MAX = 2**32 - 1      # seeds are 32-bit unsigned integers (numpy.random.default_rng takes them whole)
_INDEXED = re.compile(r"(\w+)\[(\d+)\]")


def _close(name: str, candidates) -> str | None:
    """The candidate `name` is most likely a misspelling of (or of which it is one), if any is close (difflib
    ratio >= 0.75: 'lenght'/'length' 0.83, 'laod'/'load' 0.75, but 'moment_arm'/'moment_force' 0.73)."""
    found = difflib.get_close_matches(name, sorted(candidates), n=1, cutoff=0.75)
    return found[0] if found else None


def key_name(name: str) -> str:
    """A key as an error names it: as written, an empty or blank one as TOML writes it ("")."""
    return name if name.strip() else json.dumps(name)


def _describe(value: Any) -> str:
    if isinstance(value, dict):
        return "a table"
    if isinstance(value, list):
        return "an array"
    return f"{type(value).__name__} {value!r}"


class Node:
    """A TOML table being read: every key read is recorded so `finish` can reject unknown keys."""

    def __init__(self, file: str | Path, path: str, data: dict):
        self.file, self.path, self.data = str(file), path, data
        self._read: set[str] = set()

    def key(self, name: str) -> str:
        return f"{self.path}.{key_name(name)}" if self.path else key_name(name)

    def set_path(self, dotted: str, value: Any) -> None:
        """Set the value at a dotted key path below this table (creating tables on the way); a last key
        with an index, `initial.velocity[2]`, sets that element of an existing array, and an indexed table on
        the way, `terrain.rocks[0].x`, is that element of an existing array of tables."""
        *tables, last = dotted.split(".")
        data = self.data
        for k, name in enumerate(tables):
            m = _INDEXED.fullmatch(name)
            if m:
                array, index = data.get(m.group(1)), int(m.group(2))
                data = array[index] if isinstance(array, list) and index < len(array) else None
            else:
                data = data.setdefault(name, {})
            if not isinstance(data, dict):
                raise self.error(".".join(tables[:k + 1]), "a table to set " + dotted + " in", _describe(data))
        m = _INDEXED.fullmatch(last)
        if m is None:
            data[last] = value
            return
        name, index = m.group(1), int(m.group(2))
        array = data.get(name)
        if not isinstance(array, list) or index >= len(array):
            where = ".".join(tables + [name])
            raise self.error(where, f"an array with an element [{index}] to set", _describe(array))
        data[name] = array[:index] + [value] + array[index + 1:]

    def error(self, name: str, expected: str, found: str) -> InputError:
        return InputError(self.file, self.key(name), expected, found)

    def warn(self, name: str, message: str) -> None:
        """Warn about a legal but suspicious value at key `name` (an InputWarning naming file and key path)."""
        warn_input(self.file, self.key(name), message)

    def has(self, name: str) -> bool:
        return name in self.data

    def raw(self, name: str, default: Any = _MISSING) -> Any:
        self._read.add(name)
        if name not in self.data:
            if default is _MISSING:
                written = _close(name, set(self.data) - self._read)
                if written is not None:       # named as written, so the user finds it
                    raise self.error(written, f"the required key {name!r}", f"{written!r} (did you mean {name!r}?)")
                raise self.error(name, "this key to be present", "nothing")
            return default
        return self.data[name]

    def string(self, name: str, default: Any = _MISSING, choices: tuple[str, ...] | None = None) -> str:
        value = self.raw(name, default)
        if value is default and default is not _MISSING:
            return default
        if not isinstance(value, str):
            raise self.error(name, "a string", _describe(value))
        if choices is not None and value not in choices:
            raise self.error(name, "one of " + ", ".join(repr(c) for c in choices), repr(value))
        return value

    @overload
    def table(self, name: str, optional: Literal[False] = False) -> Node: ...

    @overload
    def table(self, name: str, optional: bool) -> Node | None: ...

    def table(self, name: str, optional: bool = False) -> Node | None:
        """The sub-table `name`; None when `optional` and absent (a required one missing raises InputError)."""
        value = self.raw(name, None if optional else _MISSING)
        if value is None:
            return None
        if not isinstance(value, dict):
            raise self.error(name, "a table", _describe(value))
        return Node(self.file, self.key(name), value)

    def tables(self, name: str, optional: bool = False, label: str | None = None) -> list[Node]:
        """An array of tables. With `label`, an element whose string under that key is unique in the array is
        named by it in key paths, `item["Upper Truss"]`, the others by index, `item[0]`."""
        value = self.raw(name, [] if optional else _MISSING)
        if not isinstance(value, list) or not all(isinstance(v, dict) for v in value):
            raise self.error(name, "an array of tables", _describe(value))
        labels = [v.get(label) for v in value] if label else []

        def element(i: int) -> str:
            text = labels[i] if labels else None
            return json.dumps(text, ensure_ascii=False) if isinstance(text, str) and labels.count(text) == 1 else str(i)
        return [Node(self.file, f"{self.key(name)}[{element(i)}]", v) for i, v in enumerate(value)]

    def allow(self, names) -> None:
        """Reject keys outside `names` before reading, so a typo is reported rather than a missing key."""
        unknown = sorted(set(self.data) - set(names))
        if unknown:
            raise self.error(unknown[0], "one of the known keys (" + ", ".join(sorted(names)) + ")",
                             _unknown(unknown[0], names))

    def finish(self) -> None:
        """Reject keys nobody read: a typo must never pass silently."""
        unknown = sorted(set(self.data) - self._read)
        if unknown:
            known = ", ".join(sorted(self._read)) or "no keys"
            raise self.error(unknown[0], f"one of the known keys ({known})", _unknown(unknown[0], self._read))


def _unknown(key: str, known) -> str:
    close = _close(key, known)
    return f"unknown key {key!r}" + (f" (did you mean {close!r}?)" if close else "")


def is_file(path: Path) -> bool:
    """Whether `path` is an existing file; False also for a path the system refuses (too long, a NUL byte)."""
    try:
        return path.is_file()
    except (OSError, ValueError):
        return False


def is_dir(path: Path) -> bool:
    """Whether `path` is an existing folder; False also for a path the system refuses."""
    try:
        return path.is_dir()
    except (OSError, ValueError):
        return False


def load_toml(path: str | Path) -> Node:
    """Read a TOML file into a root Node; a missing or malformed file is an InputError."""
    path = Path(path)
    try:
        text = path.read_bytes().decode("utf-8")
    except FileNotFoundError:
        raise InputError(str(path), "", "an existing TOML file", "no such file") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(str(path), "", "a readable UTF-8 TOML file", str(exc)) from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(str(path), "", "valid TOML", f"a syntax error: {exc}") from None
    except ValueError as exc:         # an integer of more than 4300 digits (Python's int-from-text limit)
        raise InputError(str(path), "", "valid TOML", f"a value Python cannot read: {exc}") from None
    except RecursionError:
        raise InputError(str(path), "", "TOML nested less deeply than Python's recursion limit",
                         "arrays or inline tables nested deeper") from None
    return Node(path, "", data)
