"""Typed input errors: every bad input names the file, the key path, what was expected and what was found."""

from __future__ import annotations


class InputError(Exception):
    """Bad user input (exit status 2)."""

    def __init__(self, file: str, key: str, expected: str, found: str):
        self.file, self.key, self.expected, self.found = str(file), key, expected, found
        super().__init__(f"{self.file}: {key or '(top level)'}: expected {expected}, found {found}")
