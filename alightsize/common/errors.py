"""Typed input errors and warnings: each names the file and the key path; an error also what was expected
and what was found."""

from __future__ import annotations

import warnings


class InputError(Exception):
    """Bad user input (exit status 2)."""

    def __init__(self, file: str, key: str, expected: str, found: str):
        self.file, self.key, self.expected, self.found = str(file), key, expected, found
        super().__init__(f"{self.file}: {key or '(top level)'}: expected {expected}, found {found}")


class InputWarning(UserWarning):
    """Legal but suspicious user input: run as given, the user told (the CLI prints it on stderr)."""

    def __init__(self, file: str, key: str, message: str):
        self.file, self.key, self.message = str(file), key, message
        super().__init__(f"{self.file}: {key or '(top level)'}: {message}")


def warn_input(file: str, key: str, message: str) -> None:
    """Issue an InputWarning (as a Python warning, so the API's caller may filter or raise it)."""
    warnings.warn(InputWarning(file, key, message), stacklevel=3)
